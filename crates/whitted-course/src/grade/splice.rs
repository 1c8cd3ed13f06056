//! The graded copy's sources: the student's body of each graded exercise, taken from between
//! its markers and put into the instructor's file, and the instructor's hidden tests beside the
//! public ones.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use super::alone::{self, Judging};
use crate::handout::{self, BEGIN, END, Region};
use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// The body a student wrote for the region `r` of the exercise named `name`: the lines between
/// the region's markers in the same file of the submission. `Err` says why there is none.
pub fn student_body(submission: &Path, r: &Region, name: &str) -> Result<String, String> {
    student_body_at(submission, r, name).map(|(body, _)| body)
}

/// [`student_body`], and the line of the student's file (from 1) where the body begins.
fn student_body_at(submission: &Path, r: &Region, name: &str) -> Result<(String, usize), String> {
    let path = submission.join(&r.file);
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", r.file.display()))?;
    let begin = format!("{BEGIN} {name}");
    let mut lines = text.split_inclusive('\n');
    let Some(at) = lines.by_ref().position(|l| l.trim() == begin) else {
        return Err(format!(
            "`{begin}` is missing from {}: graded as not written",
            r.file.display()
        ));
    };
    let mut body = String::new();
    for line in lines {
        let t = line.trim();
        if t == END {
            // `at` counts from 0 the BEGIN line: the body begins on the line after it
            return Ok((body, at + 2));
        }
        if t.starts_with(BEGIN) {
            break;
        }
        body.push_str(line);
    }
    Err(format!(
        "`{begin}` is not closed by `{END}` in {}: graded as not written",
        r.file.display()
    ))
}

/// An exercise's body in a spliced file: its manifest entry, the first and last line (from 1)
/// an error in it may be reported on, and what to add to such a line to find it in the student's
/// own file (0 when the body is not the student's).
pub(super) type BodyLines = (usize, usize, usize, i64);

/// A source file of the graded copy and the lines each exercise's body holds in it.
#[derive(Clone)]
pub(super) struct Spliced {
    /// The file, relative to the project.
    pub(super) file: PathBuf,
    /// The reference text.
    pub(super) reference: String,
    /// The regions in the file, in order, with the body each one now holds.
    pub(super) regions: Vec<(Region, String)>,
    /// The regions whose body is the student's (their manifest entries), when each exercise is
    /// judged alone: each holds the reference's body too, beside the student's
    /// ([`super::alone::both_bodies`]).
    pub(super) alone: BTreeSet<usize>,
    /// For each region whose body is the student's, the line of the student's file (from 1)
    /// where it begins: a compiler error is reported at the student's own line.
    pub(super) student_at: BTreeMap<usize, usize>,
}

impl Spliced {
    /// The text with every region's body in place, and for each region the lines (from 1,
    /// inclusive) an error in its body may be reported on: from its BEGIN line to the line
    /// after its END line.
    pub(super) fn text(&self) -> (String, Vec<BodyLines>) {
        let mut out = String::new();
        let mut lines = Vec::new();
        let mut at = 0;
        for (r, body) in &self.regions {
            let head_end = self.reference[r.bytes.start..]
                .find('\n')
                .map_or(r.bytes.end, |i| r.bytes.start + i + 1);
            out.push_str(&self.reference[at..head_end]);
            // the BEGIN line, the body, the END line and the line after it: a syntax error
            // in a body is often reported at the token that follows it
            let first = out.lines().count();
            // the body's first line here, and in the student's file
            let shift = |starts: usize| {
                self.student_at
                    .get(&r.entry)
                    .map_or(0, |&at| at as i64 - starts as i64)
            };
            if self.alone.contains(&r.entry) {
                // the student's body (after the `if` and its block's `{`), then the line after it
                let (both, end) = alone::both_bodies(r.entry, &r.indent, body, &r.solution);
                out.push_str(&both);
                lines.push((r.entry, first, first + end + 1, shift(first + 3)));
            } else {
                let mut body = body.clone();
                if !body.is_empty() && !body.ends_with('\n') {
                    body.push('\n');
                }
                out.push_str(&body);
                let last = out.lines().count() + 2;
                lines.push((r.entry, first, last, shift(first + 1)));
            }
            out.push_str(&r.indent);
            out.push_str(END);
            out.push('\n');
            at = r.bytes.end;
        }
        out.push_str(&self.reference[at..]);
        (out, lines)
    }
}

/// The graded copy's source files with the student's bodies in the regions of `chapters`
/// (the other regions keep the reference code), each beside the reference's when each exercise
/// is judged alone ([`Judging::Alone`]). A body that cannot be found is noted and replaced by
/// the exercise's `todo!()`; so is, when `screen` (always, but for a test of the runner's lock
/// alone), a body that does more than compute ([`super::screen::screen`]), and a body that is
/// not whole on its own ([`alone::whole_on_its_own`]): it is never compiled.
pub(super) fn splice(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    chapters: &[u8],
    (screen, judging): (bool, Judging),
    notes: &mut BTreeMap<usize, String>,
) -> Result<Vec<Spliced>, ToolError> {
    let mut by_file: BTreeMap<PathBuf, Vec<(Region, String)>> = BTreeMap::new();
    let mut alone = BTreeSet::new();
    let mut student_at = BTreeMap::new();
    for r in handout::regions(root, manifest)? {
        let e = &manifest.entries[r.entry];
        let body = if chapters.contains(&e.chapter) {
            if judging == Judging::Alone {
                alone.insert(r.entry);
            }
            student_body_at(submission, &r, &e.exercise.name)
                .map(|(body, at)| {
                    student_at.insert(r.entry, at);
                    body
                })
                .and_then(|body| match whitted_learn::screen::screen(&body).filter(|_| screen) {
                    Some(refused) => Err(format!(
                        "refused by the screen, {refused}; graded as not written (cargo learn says the same at the save)"
                    )),
                    None if !alone::whole_on_its_own(&body) => Err(
                        "its brackets, braces, quotes or comments do not close inside the body: graded as not written".to_string()
                    ),
                    None => Ok(body),
                })
                .unwrap_or_else(|why| {
                    student_at.remove(&r.entry);
                    notes.insert(r.entry, super::clean::clean(&why));
                    format!("{}{}\n", r.indent, handout::todo_statement(e))
                })
        } else {
            r.solution.clone()
        };
        by_file.entry(r.file.clone()).or_default().push((r, body));
    }
    by_file
        .into_iter()
        .map(|(file, mut regions)| {
            regions.sort_by_key(|(r, _)| r.bytes.start);
            let path = root.join(&file);
            let reference = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
            Ok(Spliced {
                file,
                reference,
                regions,
                alone: alone.clone(),
                student_at: student_at.clone(),
            })
        })
        .collect()
}

/// Removes the hidden tests from the copy (`tests/hidden_*`) and their binaries from the
/// build directory (`debug/deps/hidden_*`): what the student's crate is compiled next to, and
/// what a later build in the same directory could read, holds none of them.
pub(super) fn remove_hidden(project: &Path, target_dir: &Path) -> Result<(), ToolError> {
    for dir in [
        project.join(layout::core_tests()),
        target_dir.join("debug").join("deps"),
    ] {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for e in entries.flatten() {
            if e.file_name().to_string_lossy().starts_with("hidden_") {
                let path = e.path();
                std::fs::remove_file(&path).map_err(|err| ToolError::io(&path, err))?;
            }
        }
    }
    Ok(())
}

/// The hidden tests of the directory `dir`: its `*.rs` files, in name order.
pub(crate) fn hidden_files(dir: &Path) -> Result<Vec<PathBuf>, ToolError> {
    let entries = std::fs::read_dir(dir).map_err(|e| ToolError::io(dir, e))?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "rs"))
        .collect();
    files.sort();
    Ok(files)
}

/// Makes the hidden tests' binaries in the build directory executable and nothing else for
/// other users: a test running as one (the user sandbox) cannot read their names or
/// messages out of them.
pub(super) fn seal_hidden(target_dir: &Path) -> Result<(), ToolError> {
    use std::os::unix::fs::PermissionsExt;
    let deps = target_dir.join("debug").join("deps");
    let Ok(entries) = std::fs::read_dir(&deps) else {
        return Ok(());
    };
    for e in entries.flatten() {
        if e.file_name().to_string_lossy().starts_with("hidden_") {
            let path = e.path();
            let mode = if path.extension().is_none() {
                0o711
            } else {
                0o600
            };
            std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode))
                .map_err(|err| ToolError::io(&path, err))?;
        }
    }
    Ok(())
}

/// Once the hidden tests' binaries are built and listed, removes everything else of them
/// that a test could read while they run: their sources in the copy (a test's working
/// directory is inside the copy, so a relative path would reach them however the copy's root
/// is closed), their incremental caches and the compiler's messages cargo keeps with their
/// fingerprints (both quote their text). They are built again, from the hidden directory,
/// for the next submission.
pub(super) fn strip_hidden(project: &Path, target_dir: &Path) -> Result<(), ToolError> {
    let is_hidden = |name: &std::ffi::OsStr| name.to_string_lossy().contains("hidden_");
    let sources = project.join(layout::core_tests());
    for e in std::fs::read_dir(&sources).into_iter().flatten().flatten() {
        if e.file_name().to_string_lossy().starts_with("hidden_") {
            let path = e.path();
            std::fs::remove_file(&path).map_err(|err| ToolError::io(&path, err))?;
        }
    }
    let debug = target_dir.join("debug");
    for e in std::fs::read_dir(debug.join("incremental"))
        .into_iter()
        .flatten()
        .flatten()
    {
        if is_hidden(&e.file_name()) {
            let path = e.path();
            std::fs::remove_dir_all(&path).map_err(|err| ToolError::io(&path, err))?;
        }
    }
    for unit in std::fs::read_dir(debug.join(".fingerprint"))
        .into_iter()
        .flatten()
        .flatten()
    {
        for e in std::fs::read_dir(unit.path())
            .into_iter()
            .flatten()
            .flatten()
        {
            if is_hidden(&e.file_name()) {
                let path = e.path();
                std::fs::remove_file(&path).map_err(|err| ToolError::io(&path, err))?;
            }
        }
    }
    Ok(())
}

/// Copies each `*.rs` of the hidden directory into the copy's `tests/` as `hidden_NAME.rs`;
/// returns the test targets added.
pub(super) fn add_hidden(project: &Path, hidden: Option<&Path>) -> Result<Vec<String>, ToolError> {
    let Some(dir) = hidden else {
        return Ok(Vec::new());
    };
    let mut targets = Vec::new();
    let files = hidden_files(dir)?;
    if files.is_empty() {
        return Err(ToolError::Usage(format!(
            "--hidden {}: the directory holds no .rs test file",
            dir.display()
        )));
    }
    for f in files {
        let stem: String = f
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let target = format!("hidden_{stem}");
        let to = project.join(layout::core_test_file(&target));
        let bytes = std::fs::read(&f).map_err(|e| ToolError::io(&f, e))?;
        files::write_if_changed(&to, &bytes)?;
        targets.push(target);
    }
    Ok(targets)
}
