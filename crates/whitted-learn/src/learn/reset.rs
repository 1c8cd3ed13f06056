//! `cargo learn reset EXERCISE`: an exercise's body put back to the handout's `todo!()`
//! ([`mod@crate::todo`]), the body that stood there kept in `.whitted/reset/NAME-N.rs`, as
//! rustlings' `reset` does.
//!
//! Only the lines between `// BEGIN SOLUTION NAME` and `// END SOLUTION` change; the marker
//! lines and the rest of the file stay as they are. The kept copy is written first and never
//! over an earlier one (`NAME-1.rs`, then `NAME-2.rs` …), and the source file is written
//! atomically, so a failure at any point loses no text. Nothing is built: the next check
//! sees the region changed and checks that exercise first.
//!
//! Only the exercises of the manifest can be reset: in a handout of some chapters, those it
//! asks the student to write (its `[handout] exercises`); an exercise it gives written, or
//! leaves to a later chapter's handout, is named as such ([`Manifest::not_found`]). In the
//! project and a full handout, every exercise can be, and its body is kept like any other.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::ops::Range;
use std::path::{Path, PathBuf};

use super::say::COMMAND;
use super::state::STATE_DIR;
use crate::layout::{BEGIN, END};
use crate::manifest::Manifest;
use crate::{ToolError, files};

/// The directory, under [`STATE_DIR`], where reset keeps the bodies it replaced.
pub const RESET_DIR: &str = "reset";

/// What a reset did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reset {
    /// The exercise (its manifest index).
    pub index: usize,
    /// The source file, relative to the project.
    pub file: PathBuf,
    /// The line of the body in the file (the line after BEGIN), from 1.
    pub line: usize,
    /// Where the old body is kept, relative to the project.
    pub kept: PathBuf,
}

impl Reset {
    /// The one line `cargo learn reset` prints.
    #[must_use]
    pub fn said(&self, manifest: &Manifest) -> String {
        let x = &manifest.entries[self.index].exercise;
        format!(
            "exercise {} ({}) is the handout's todo!() again at {}:{}; your body is kept in {}",
            x.id,
            x.name,
            self.file.display(),
            self.line,
            self.kept.display()
        )
    }
}

/// An exercise's region in one source text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Body {
    /// The bytes between the end of the BEGIN line and the start of the END line.
    pub bytes: Range<usize>,
    /// The BEGIN line's indentation.
    pub indent: String,
    /// The BEGIN line's ending (`"\n"`, or `"\r\n"` in a file saved so).
    pub eol: String,
    /// The line of the body's first line, from 1.
    pub line: usize,
}

/// The region of the exercise `name` in `text`, or why there is none: a BEGIN line not closed
/// by END before the next BEGIN or the end, or no BEGIN line (`Ok(None)`).
pub fn find_body(text: &str, name: &str) -> Result<Option<Body>, String> {
    let mut open: Option<(usize, String, String, usize)> = None;
    let mut offset = 0;
    for (n, line) in text.split_inclusive('\n').enumerate() {
        let trimmed = line.trim();
        if let Some((start, indent, eol, first)) = &open {
            if trimmed == END {
                return Ok(Some(Body {
                    bytes: *start..offset,
                    indent: indent.clone(),
                    eol: eol.clone(),
                    line: *first,
                }));
            }
            if trimmed.starts_with(BEGIN) {
                return Err(format!(
                    "line {}: `{BEGIN} {name}` is not closed by `{END}` before the next `{BEGIN}`",
                    first - 1
                ));
            }
        } else if trimmed
            .strip_prefix(BEGIN)
            .is_some_and(|rest| rest.trim() == name)
        {
            let indent = line[..line.len() - line.trim_start().len()].to_string();
            let eol = if line.ends_with("\r\n") { "\r\n" } else { "\n" };
            open = Some((offset + line.len(), indent, eol.to_string(), n + 2));
        }
        offset += line.len();
    }
    match open {
        Some((_, _, _, first)) => Err(format!(
            "line {}: `{BEGIN} {name}` is not closed by `{END}`",
            first - 1
        )),
        None => Ok(None),
    }
}

/// Resets the exercise `key` (its displayed id or its name) of the project at `root`: its body
/// becomes the handout's `todo!()`, the old body is kept under `.whitted/reset/`. An unknown
/// exercise, markers not found (or found twice), or a body that is the handout's already are
/// [`ToolError::Usage`] or [`ToolError::Markers`] errors, one line each, and change nothing.
pub fn reset(root: &Path, manifest: &Manifest, key: &str) -> Result<Reset, ToolError> {
    let index = manifest
        .find(key)
        .ok_or_else(|| ToolError::Usage(manifest.not_found(key)))?;
    let e = &manifest.entries[index];
    let x = &e.exercise;
    let who = format!("exercise {} ({})", x.id, x.name);
    let mut found: Vec<(PathBuf, String, Body)> = Vec::new();
    for path in crate::changes::sources(root) {
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let file = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
        match find_body(&text, &x.name) {
            Ok(Some(body)) => found.push((file, text, body)),
            Ok(None) => {}
            Err(why) => {
                return Err(ToolError::Markers(format!(
                    "{who}: {}: {why}: put the marker lines back as the handout had them",
                    file.display()
                )));
            }
        }
    }
    let (file, text, body) = match found.len() {
        1 => found.remove(0),
        0 => {
            return Err(ToolError::Markers(format!(
                "{who}: no `{BEGIN} {}` … `{END}` lines in {}: put the two lines back around \
                 its body (`{COMMAND}` says where the exercise is)",
                x.name,
                crate::layout::core_src().display()
            )));
        }
        _ => {
            let places: Vec<String> = found
                .iter()
                .map(|(f, _, b)| format!("{}:{}", f.display(), b.line - 1))
                .collect();
            return Err(ToolError::Markers(format!(
                "{who}: `{BEGIN} {}` stands more than once ({}): keep only the exercise's own",
                x.name,
                places.join(", ")
            )));
        }
    };
    let old = &text[body.bytes.clone()];
    if old.trim() == crate::todo::todo_statement(e) {
        return Err(ToolError::Usage(format!(
            "{who} at {}:{} is the handout's todo!() already: nothing to reset",
            file.display(),
            body.line
        )));
    }
    let kept = keep(
        root,
        &x.name,
        &format!(
            "// {who}: the body `{COMMAND} reset` took out of {}:{}{}{old}",
            file.display(),
            body.line,
            body.eol
        ),
    )?;
    let new = format!(
        "{}{}{}",
        &text[..body.bytes.start],
        crate::todo::todo_body(e, &body.indent, &body.eol),
        &text[body.bytes.end..]
    );
    files::write_file(&root.join(&file), new.as_bytes())?;
    Ok(Reset {
        index,
        file,
        line: body.line,
        kept,
    })
}

/// Writes `text` to `.whitted/reset/NAME-N.rs` with the first N from 1 that names no file
/// yet (checked by the rename itself, so an earlier copy is never overwritten); returns the
/// path relative to `root`.
fn keep(root: &Path, name: &str, text: &str) -> Result<PathBuf, ToolError> {
    use std::io::Write;
    let dir = Path::new(STATE_DIR).join(RESET_DIR);
    let full = root.join(&dir);
    std::fs::create_dir_all(&full).map_err(|e| ToolError::io(&full, e))?;
    let mut tmp = tempfile::Builder::new()
        .prefix(".whitted-")
        .tempfile_in(&full)
        .map_err(|e| ToolError::io(&full, e))?;
    tmp.write_all(text.as_bytes())
        .and_then(|()| tmp.as_file().sync_all())
        .map_err(|e| ToolError::io(tmp.path(), e))?;
    let mut n = 1;
    loop {
        let relative = dir.join(format!("{name}-{n}.rs"));
        match tmp.persist_noclobber(root.join(&relative)) {
            Ok(_) => return Ok(relative),
            Err(e) if e.error.kind() == std::io::ErrorKind::AlreadyExists => tmp = e.file,
            Err(e) => return Err(ToolError::io(root.join(&relative), e.error)),
        }
        n += 1;
    }
}
