//! The "Exercises" section of each chapter's README, written from the manifest so that the
//! README and the manifest cannot say different things: `whitted formulas readmes`
//! rewrites the sections, and a test checks they are current.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::Path;

use super::ToolError;
use super::manifest::Manifest;

/// The heading of the section.
pub const HEADING: &str = "## Exercises";

/// The lines around the section's text (its heading excepted): mdBook's anchors, so that the
/// course book's chapter page includes the section (`{{#include …/README.md:exercises}}`)
/// instead of saying it again.
pub const ANCHOR_START: &str = "<!-- ANCHOR: exercises -->";
/// The line that ends the anchored text.
pub const ANCHOR_END: &str = "<!-- ANCHOR_END: exercises -->";

/// The section for chapter `chapter`, heading included, ending with a newline.
#[must_use]
pub fn section(manifest: &Manifest, chapter: &crate::syllabus::Chapter) -> String {
    let (binary, number) = (chapter.binary, chapter.number);
    let first = manifest.entries.iter().find(|e| e.chapter == number);
    let example = first.map_or_else(String::new, |e| {
        format!(
            " (`{}…` for {}, the exercise `{}`)",
            e.exercise.test_prefix(),
            e.exercise.id,
            e.exercise.name
        )
    });
    let commands = [
        (
            "cargo learn".to_string(),
            "the verdict on the next exercise, its failing tests, the picture",
        ),
        (
            "cargo learn hint".to_string(),
            "a hint, then a stronger one",
        ),
        (
            format!(
                "cargo test -p whitted --test {binary} {}",
                crate::manifest::TEST_PREFIX
            ),
            "this chapter's exercise tests (--features f32: in single precision)",
        ),
    ];
    let width = commands.iter().map(|(c, _)| c.len()).max().unwrap_or(0);
    let lines: String = commands
        .iter()
        .map(|(c, what)| format!("{c:<width$}  # {what}\n"))
        .collect();
    let mut out = format!(
        "{HEADING}\n\n{ANCHOR_START}\n\
         Each exercise is one function of the renderer (`crates/whitted/src/`), the one it calls for\n\
         that formula.\n\
         In a handout (`whitted handout`, see `docs/src/student-guide.md`) its body is `todo!()`; write\n\
         it, then run\n\n\
         ```text\n{lines}```\n\n\
         An exercise's tests are named after it{example} and may use the exercises before it.\n"
    );
    for e in manifest.entries.iter().filter(|e| e.chapter == number) {
        let x = &e.exercise;
        out += &format!(
            "\n### {} {} ({} point{})\n\n`{}` (the exercise `{}`) — the notes, \"{}\": {}\n\n{}\n",
            x.id,
            x.title,
            x.points,
            if x.points == 1 { "" } else { "s" },
            e.function,
            x.name,
            e.section,
            e.formula,
            x.task
        );
    }
    out + ANCHOR_END + "\n"
}

/// `readme` with its exercises section replaced by `section` (the section runs from its
/// heading to the next `## ` heading or the end); the section is appended when missing.
#[must_use]
pub fn replace_section(readme: &str, section: &str) -> String {
    let start = readme
        .find(&format!("\n{HEADING}\n"))
        .map(|i| i + 1)
        .or_else(|| readme.starts_with(&format!("{HEADING}\n")).then_some(0));
    match start {
        None => format!("{}\n\n{section}", readme.trim_end()),
        Some(start) => {
            let after = &readme[start + HEADING.len()..];
            let end = after
                .find("\n## ")
                .map_or(readme.len(), |i| start + HEADING.len() + i + 1);
            format!(
                "{}{section}{}",
                &readme[..start],
                if end < readme.len() {
                    format!("\n{}", &readme[end..])
                } else {
                    String::new()
                }
            )
        }
    }
}

/// Rewrites the exercises section of every chapter's README under `root`; returns the
/// READMEs that changed.
pub fn write_all(root: &Path, manifest: &Manifest) -> Result<Vec<String>, ToolError> {
    let mut changed = Vec::new();
    for chapter in &crate::syllabus::CHAPTERS {
        let path = root.join(chapter.readme());
        let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
        let new = replace_section(&text, &section(manifest, chapter));
        if new != text {
            crate::files::write_file(&path, new.as_bytes())?;
            changed.push(chapter.readme());
        }
    }
    Ok(changed)
}
