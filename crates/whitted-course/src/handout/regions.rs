//! Where each exercise's reference body sits: its solution region, between the
//! `// BEGIN SOLUTION NAME` and `// END SOLUTION` lines inside the function's body.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use crate::layout::{BEGIN, END};
use crate::manifest::{Entry, Manifest};
use crate::source::Location;
use crate::{ToolError, layout};

/// A solution region of one exercise in its source file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Region {
    /// The manifest entry (its index).
    pub entry: usize,
    /// The source file, relative to the project's root.
    pub file: PathBuf,
    /// The bytes from the start of the BEGIN line to the end of the END line (newline
    /// included).
    pub bytes: Range<usize>,
    /// The BEGIN line's indentation.
    pub indent: String,
    /// The reference code between the two marker lines.
    pub solution: String,
}

/// Finds the solution region of every manifest entry (in manifest order): the BEGIN line with
/// the entry's exercise name and the END line after it, both inside the function's body. A
/// region missing, or misnumbered, or a BEGIN marker in `src/` that belongs to no entry, is an
/// error that names the file and line.
pub fn regions(root: &Path, manifest: &Manifest) -> Result<Vec<Region>, ToolError> {
    let locations = crate::source::locate_all(root, manifest)?;
    let mut out = Vec::with_capacity(locations.len());
    for (entry, (e, at)) in manifest.entries.iter().zip(&locations).enumerate() {
        let path = root.join(&at.file);
        let text = std::fs::read_to_string(&path).map_err(|err| ToolError::io(&path, err))?;
        out.push(region_in(&text, entry, e, at)?);
    }
    // every marker in src/ belongs to a region found above
    let mut known: BTreeMap<PathBuf, Vec<usize>> = BTreeMap::new();
    for r in &out {
        known.entry(r.file.clone()).or_default().push(r.bytes.start);
    }
    for file in crate::book::pages(&root.join(layout::core_src()), "rs")? {
        let text = std::fs::read_to_string(&file).map_err(|err| ToolError::io(&file, err))?;
        let relative = file.strip_prefix(root).unwrap_or(&file).to_path_buf();
        let mut offset = 0;
        for (n, line) in text.split_inclusive('\n').enumerate() {
            // a week's handout keeps the markers of the exercises it gives or leaves to a
            // later week (its manifest lists its own): those are not the student's regions
            let left_out = line
                .trim()
                .strip_prefix(BEGIN)
                .is_some_and(|name| manifest.is_left_out(name.trim()));
            if line.trim_start().starts_with(BEGIN)
                && !left_out
                && !known
                    .get(&relative)
                    .is_some_and(|starts| starts.contains(&offset))
            {
                return Err(ToolError::Markers(format!(
                    "{}:{}: `{}` belongs to no function of {} (or to another one than its id says)",
                    relative.display(),
                    n + 1,
                    line.trim(),
                    manifest.file
                )));
            }
            offset += line.len();
        }
    }
    Ok(out)
}

/// The region of entry `e` inside its function's body at `at` in `text`.
fn region_in(text: &str, entry: usize, e: &Entry, at: &Location) -> Result<Region, ToolError> {
    let id = &e.exercise.name;
    let body = &text[at.body.clone()];
    let fail = |what: String| {
        ToolError::Markers(format!(
            "{}:{}: {} (exercise {id}): {what}",
            at.file.display(),
            at.line,
            e.function
        ))
    };
    let mut begin: Option<(usize, String)> = None;
    let mut offset = at.body.start;
    for line in body.split_inclusive('\n') {
        let trimmed = line.trim();
        if let Some(rest) = trimmed.strip_prefix(BEGIN) {
            if begin.is_some() {
                return Err(fail("two BEGIN SOLUTION lines in one body".into()));
            }
            if rest.trim() != id {
                return Err(fail(format!(
                    "the body's marker says `{trimmed}`, expected `{BEGIN} {id}`"
                )));
            }
            let indent = line[..line.len() - line.trim_start().len()].to_string();
            begin = Some((offset, indent));
        } else if trimmed == END {
            let Some((start, indent)) = begin.take() else {
                return Err(fail(format!("`{END}` without a `{BEGIN} {id}` before it")));
            };
            let end = offset + line.len();
            let first = text[start..].find('\n').map_or(end, |i| start + i + 1);
            return Ok(Region {
                entry,
                file: at.file.clone(),
                bytes: start..end,
                indent,
                solution: text[first..offset].to_string(),
            });
        }
        offset += line.len();
    }
    Err(fail(match begin {
        Some(_) => format!("`{BEGIN} {id}` is not closed by `{END}`"),
        None => format!("the body has no `{BEGIN} {id}` … `{END}` region"),
    }))
}
