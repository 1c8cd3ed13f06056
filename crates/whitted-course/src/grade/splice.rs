//! The graded copy's sources: the student's body of each graded exercise, taken from between
//! its markers and put into the instructor's file with the wire of the judge outside
//! ([`super::outside`]), and the instructor's hidden tests beside the public ones (in the
//! judge's copy).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::alone;
use super::outside::{FileWire, Wire};
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
    /// The wire's stubs (at bytes of `reference`, none inside a region) and answers.
    pub(super) wire: FileWire,
    /// For each region whose body is the student's, the line of the student's file (from 1)
    /// where it begins: a compiler error is reported at the student's own line.
    pub(super) student_at: BTreeMap<usize, usize>,
}

impl Spliced {
    /// The text with every region's body in place, and for each region the lines (from 1,
    /// inclusive) an error in its body may be reported on: from its BEGIN line to the line
    /// after its END line.
    pub(super) fn text(&self) -> (String, Vec<BodyLines>) {
        // a body's leading inner attributes (`#![allow(…)]`) go just before the wire's stub,
        // which opens the function's block: an inner attribute must come first in its block
        let mut hoisted: BTreeMap<usize, String> = BTreeMap::new();
        let bodies: Vec<String> = self
            .regions
            .iter()
            .map(|(r, body)| {
                let stub = self
                    .wire
                    .stubs
                    .iter()
                    .rposition(|(at, _)| *at <= r.bytes.start);
                match (inner_attributes(body), stub) {
                    (Some((attributes, rest)), Some(k)) => {
                        hoisted.entry(k).or_default().push_str(&attributes);
                        rest
                    }
                    _ => body.clone(),
                }
            })
            .collect();
        let mut out = String::new();
        let mut lines = Vec::new();
        let mut at = 0;
        for ((r, _), body) in self.regions.iter().zip(&bodies) {
            let head_end = self.reference[r.bytes.start..]
                .find('\n')
                .map_or(r.bytes.end, |i| r.bytes.start + i + 1);
            self.copy(&mut out, at..head_end, &hoisted);
            // the BEGIN line, the body, the END line and the line after it: a syntax error
            // in a body is often reported at the token that follows it
            let first = out.lines().count();
            // the body's first line here, and in the student's file
            let shift = |starts: usize| {
                self.student_at
                    .get(&r.entry)
                    .map_or(0, |&at| at as i64 - starts as i64)
            };
            let mut body = body.clone();
            if !body.is_empty() && !body.ends_with('\n') {
                body.push('\n');
            }
            out.push_str(&body);
            let last = out.lines().count() + 2;
            lines.push((r.entry, first, last, shift(first + 1)));
            out.push_str(&r.indent);
            out.push_str(END);
            out.push('\n');
            at = r.bytes.end;
        }
        self.copy(&mut out, at..self.reference.len(), &hoisted);
        out.push_str(&self.wire.answers);
        (out, lines)
    }

    /// Copies the reference's bytes `range` to `out`, with the wire's stubs that fall in it
    /// (each on its function's `{` line: no line moves), each after the inner attributes
    /// `hoisted` to it.
    fn copy(
        &self,
        out: &mut String,
        range: std::ops::Range<usize>,
        hoisted: &BTreeMap<usize, String>,
    ) {
        let mut from = range.start;
        for (k, (stub_at, stub)) in self.wire.stubs.iter().enumerate() {
            if range.contains(stub_at) {
                out.push_str(&self.reference[from..*stub_at]);
                out.push_str(hoisted.get(&k).map_or("", String::as_str));
                out.push_str(stub);
                from = *stub_at;
            }
        }
        out.push_str(&self.reference[from..range.end]);
    }
}

/// The inner attributes a body opens with (lines `#![…]`, among blank and comment lines), on
/// one line, and the body with their lines left empty (so no line moves); `None` when it
/// opens with none.
fn inner_attributes(body: &str) -> Option<(String, String)> {
    let mut attributes = String::new();
    let mut rest = String::with_capacity(body.len());
    let mut opening = true;
    for line in body.split_inclusive('\n') {
        let t = line.trim();
        if opening && t.starts_with("#![") && t.ends_with(']') {
            attributes.push_str(t);
            attributes.push(' ');
            rest.push_str(if line.ends_with('\n') { "\n" } else { "" });
            continue;
        }
        opening &= t.is_empty() || t.starts_with("//");
        rest.push_str(line);
    }
    (!attributes.is_empty()).then_some((attributes, rest))
}

/// The graded copy's source files with the student's bodies in the regions of `chapters`
/// (the other regions keep the reference code) and the `wire` in: the copy holds no reference
/// body of a graded exercise, whose calls the judge makes from outside. A body that cannot be found is noted and replaced by
/// the exercise's `todo!()`; so is, when `screen` (always, but for a test of the runner's lock
/// alone), a body that does more than compute ([`super::screen::screen`]), and a body that is
/// not whole on its own ([`alone::whole_on_its_own`]): it is never compiled.
pub(super) fn splice(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    chapters: &[u8],
    screen: bool,
    wire: &Wire,
    notes: &mut BTreeMap<usize, String>,
) -> Result<Vec<Spliced>, ToolError> {
    let mut by_file: BTreeMap<PathBuf, Vec<(Region, String)>> = BTreeMap::new();
    let mut student_at = BTreeMap::new();
    for r in handout::regions(root, manifest)? {
        let e = &manifest.entries[r.entry];
        let body = if chapters.contains(&e.chapter) {
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
    // a file the wire changes is written even where it holds no region
    for file in wire.files.keys() {
        by_file.entry(file.clone()).or_default();
    }
    by_file
        .into_iter()
        .map(|(file, mut regions)| {
            regions.sort_by_key(|(r, _)| r.bytes.start);
            let path = root.join(&file);
            let reference = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
            let wire = wire.files.get(&file).cloned().unwrap_or_default();
            Ok(Spliced {
                file,
                reference,
                regions,
                wire,
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

/// The test target a hidden test file becomes in a copy: `hidden_STEM`, each character of its
/// name that is not an ASCII letter or digit made `_`.
pub(crate) fn hidden_target(file: &Path) -> String {
    let stem: String = file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    format!("hidden_{stem}")
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
        let target = hidden_target(&f);
        let to = project.join(layout::core_test_file(&target));
        let bytes = std::fs::read(&f).map_err(|e| ToolError::io(&f, e))?;
        files::write_if_changed(&to, &bytes)?;
        targets.push(target);
    }
    Ok(targets)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The student's body takes the region's place and the wire's stub goes right after the
    /// function's `{`, on its line: every line keeps its number, so a compiler error in the
    /// body is placed at the student's own line; the answers follow the file.
    #[test]
    fn the_wire_goes_in_without_moving_a_line() {
        let reference =
            "fn f(x: f64) -> f64 {\n    // BEGIN SOLUTION f\n    x + 1.0\n    // END SOLUTION\n}\n";
        let begin = reference.find("    // BEGIN").unwrap();
        let end = reference.find("}\n").unwrap();
        let region = Region {
            entry: 0,
            file: PathBuf::from("f.rs"),
            bytes: begin..end,
            indent: "    ".into(),
            solution: "    x + 1.0\n".into(),
        };
        let spliced = Spliced {
            file: PathBuf::from("f.rs"),
            reference: reference.into(),
            regions: vec![(region, "    x * 2.0\n".into())],
            wire: FileWire {
                stubs: vec![(reference.find('{').unwrap() + 1, "STUB;".into())],
                answers: "\nfn answer() {}\n".into(),
            },
            student_at: BTreeMap::from([(0, 7)]),
        };
        let (text, lines) = spliced.text();
        assert_eq!(
            text,
            "fn f(x: f64) -> f64 {STUB;\n    // BEGIN SOLUTION f\n    x * 2.0\n    // END SOLUTION\n}\n\nfn answer() {}\n"
        );
        // the body's lines (BEGIN to the line after END) and the shift to the student's line 7
        assert_eq!(lines, vec![(0, 2, 5, 4)]);
        // a body's opening inner attribute goes before the stub, on the `{` line
        let mut attributed = spliced.clone();
        attributed.regions[0].1 =
            "    // why\n    #![allow(unused_variables)]\n    let y = 1.0;\n    x * 2.0\n".into();
        let (text, _) = attributed.text();
        assert_eq!(
            text.lines().take(6).collect::<Vec<_>>(),
            [
                "fn f(x: f64) -> f64 {#![allow(unused_variables)] STUB;",
                "    // BEGIN SOLUTION f",
                "    // why",
                "",
                "    let y = 1.0;",
                "    x * 2.0",
            ]
        );
    }
}
