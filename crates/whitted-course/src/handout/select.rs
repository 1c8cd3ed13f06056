//! Which exercises a handout takes out: by chapter, by name or id, or all.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use crate::ToolError;
use crate::manifest::Manifest;

/// Which exercises a handout takes out: those of `chapters` (inclusive range), or those given
/// in `exercises` (names or displayed ids), or all when both are empty. An unknown exercise or
/// chapter is an error.
pub fn select(
    manifest: &Manifest,
    chapters: Option<(u8, u8)>,
    exercises: &[String],
) -> Result<Vec<usize>, ToolError> {
    if let Some((lo, hi)) = chapters {
        let known = |c: u8| crate::syllabus::chapter(c).is_some();
        if !known(lo) || !known(hi) || lo > hi {
            let given = if lo == hi {
                lo.to_string()
            } else {
                format!("{lo}-{hi}")
            };
            return Err(ToolError::Usage(format!(
                "--chapters {given}: expected chapters from {} to {}, the first not after the last",
                crate::syllabus::FIRST,
                crate::syllabus::LAST
            )));
        }
        return Ok((0..manifest.entries.len())
            .filter(|&i| (lo..=hi).contains(&manifest.entries[i].chapter))
            .collect());
    }
    if exercises.is_empty() {
        return Ok((0..manifest.entries.len()).collect());
    }
    let mut out = Vec::new();
    for id in exercises {
        let i = manifest.find(id).ok_or_else(|| {
                ToolError::Usage(format!(
                    "--exercises: there is no exercise {id} in {} (a name such as sphere_coefficients, or an id such as 2.6; `cargo learn list` shows them)",
                    manifest.file
                ))
            })?;
        if !out.contains(&i) {
            out.push(i);
        }
    }
    out.sort_unstable();
    Ok(out)
}

/// Reads `1-3` or `4` as an inclusive range of chapters.
pub fn parse_chapters(text: &str) -> Result<(u8, u8), String> {
    let bad =
        || format!("expected a chapter or a range of chapters such as 4 or 1-3, found `{text}`");
    let (lo, hi) = match text.split_once('-') {
        Some((a, b)) => (a.trim(), b.trim()),
        None => (text.trim(), text.trim()),
    };
    let lo: u8 = lo.parse().map_err(|_| bad())?;
    let hi: u8 = hi.parse().map_err(|_| bad())?;
    Ok((lo, hi))
}
