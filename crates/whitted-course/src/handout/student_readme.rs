//! The student's README of a handout, from its template.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use crate::ToolError;
use crate::manifest::Manifest;

/// Where the student's README of a handout comes from, in the course tools' crate.
pub const README_TEMPLATE: &str = "crates/whitted-course/handout/README.md";

/// The student's README: the template [`README_TEMPLATE`] with `{exercises}` (which exercises
/// the handout takes out, and which chapters come with a later handout) and `{chapters}` (the
/// chapters' list) filled in.
pub fn student_readme(
    root: &Path,
    manifest: &Manifest,
    selected: &[usize],
) -> Result<String, ToolError> {
    let path = root.join(README_TEMPLATE);
    let template = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    let ids: Vec<String> = crate::manifest::compress_ids(&manifest.entries, selected);
    let exercises = if selected.len() == manifest.entries.len() {
        format!("all {} exercises of the five chapters", selected.len())
    } else if selected.is_empty() {
        "no exercise: every function keeps its reference code".into()
    } else {
        format!(
            "{} exercise{} ({})",
            selected.len(),
            if selected.len() == 1 { "" } else { "s" },
            ids.join(", ")
        )
    };
    let last = super::later::last_chapter(manifest, selected);
    let exercises = match last {
        Some(last) => format!(
            "{exercises}; the chapters after chapter {last} are not part of it (their exercises \
             come with a later handout, and until then their functions and chapter binaries stop \
             with a message that says so)"
        ),
        None => exercises,
    };
    let mut chapters = String::new();
    for chapter in &crate::syllabus::CHAPTERS {
        let (n, title, dir) = (chapter.number, chapter.title, chapter.binary);
        let count = selected
            .iter()
            .filter(|&&i| manifest.entries[i].chapter == n)
            .count();
        let count = match last {
            Some(last) if n > last => "a later handout".to_string(),
            _ => count.to_string(),
        };
        chapters += &format!(
            "| {n} | {title} | `{dir}` | [chapters/{dir}/README.md](chapters/{dir}/README.md) | {count} |\n"
        );
    }
    Ok(template
        .replace("{exercises}", &exercises)
        .replace("{chapters}", chapters.trim_end()))
}
