//! What a handout of some chapters holds of the chapters after its last: nothing that gives
//! their answers away, and nothing that fails for want of them.
//!
//! A course that releases its chapters week by week hands out `--chapters 3-4` while chapter 5
//! is still to come. The handout's **last chapter** is that of its last exercise; of each
//! chapter after it,
//!
//! - every exercise's body becomes a panic that says the chapter is not part of this handout
//!   ([`later_statement`], worded by the syllabus's [`later_message`](crate::syllabus::todo::later_message)):
//!   not the `todo!()` of an exercise to write, so `cargo learn` never reads it as one, and the
//!   chapter binary says it in one line (`error: chapter 5 (reflection and refraction) is not
//!   part of this handout: …`), exit status 2;
//! - its test target (`tests/ch05_….rs`) is left out ([`tests_up_to`]): its tests cannot pass
//!   without the bodies;
//! - in the test targets it keeps that test several chapters (`render_paths`), the tests of a
//!   later chapter are cut: they sit between `// BEGIN CHAPTER 5` and `// END CHAPTER` lines,
//!   and the section goes ([`cut_later_sections`]); every test the handout keeps then needs only
//!   its own chapters (`chapters/exercise-tests.toml` says which a test needs, and a test of the
//!   handout proves it);
//! - its golden image (`tests/golden/ch05_….png`, and the showcase's, which draws every
//!   chapter) is left out ([`later_golden`]): no test left reads it.
//!
//! The chapter's README, scene and the book's pages stay: they teach, and what the pages
//! include of the code is the handout's own, later bodies taken out. The handout's manifest
//! lists its own exercises (`[handout] exercises`, [`handout_manifest`]) and its test targets,
//! so that the loop counts only those.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use crate::ToolError;
use crate::manifest::{Entry, Manifest};

/// The line that opens a later chapter's section of a shared test target, followed by the
/// chapter's number (and, after a space, anything that says why).
pub const BEGIN_CHAPTER: &str = "// BEGIN CHAPTER";

/// The line that closes a chapter's section of a shared test target.
pub const END_CHAPTER: &str = "// END CHAPTER";

/// The handout's last chapter, when a chapter of the syllabus comes after it: that of the last
/// of the `selected` exercises. `None` when the selection reaches the last chapter, or is empty
/// (a handout of no exercise keeps every body).
#[must_use]
pub fn last_chapter(manifest: &Manifest, selected: &[usize]) -> Option<u8> {
    selected
        .iter()
        .map(|&i| manifest.entries[i].chapter)
        .max()
        .filter(|&last| last < crate::syllabus::LAST)
}

/// The statement that replaces the body of a later chapter's exercise: a `todo!` whose message
/// says which chapter it belongs to, and that it is not part of this handout.
#[must_use]
pub fn later_statement(e: &Entry) -> String {
    let message = crate::syllabus::todo::later_message(&e.exercise.name, &e.exercise.id, e.chapter);
    format!("todo!({message:?})")
}

/// The chapter whose test target `target` is (the chapter binary it is named after), or
/// `None` for a target shared by the chapters (`render_paths`).
fn chapter_of_target(target: &str) -> Option<u8> {
    crate::syllabus::CHAPTERS
        .iter()
        .find(|c| c.binary == target)
        .map(|c| c.number)
}

/// Of the manifest's handout test targets `tests`, those a handout whose last chapter is `last`
/// keeps: the shared ones, and the chapters' up to `last`.
#[must_use]
pub fn tests_up_to(tests: &[String], last: u8) -> Vec<String> {
    tests
        .iter()
        .filter(|t| chapter_of_target(t).is_none_or(|c| c <= last))
        .cloned()
        .collect()
}

/// Whether `file` (relative to the project) is the golden image of a chapter after `last`:
/// `tests/golden/NAME.png` where NAME is a later chapter's binary, or no chapter's (the
/// showcase, whose scene uses every chapter).
#[must_use]
pub fn later_golden(file: &Path, last: u8) -> bool {
    let golden = crate::layout::core_tests().join("golden");
    let Ok(rest) = file.strip_prefix(&golden) else {
        return false;
    };
    let Some(name) = rest.to_str().and_then(|n| n.strip_suffix(".png")) else {
        return false;
    };
    chapter_of_target(name).unwrap_or(crate::syllabus::LAST) > last
}

/// `text` (the test target `file`) without its sections of chapters after `last`: each from a
/// `// BEGIN CHAPTER N` line with N > `last` to its `// END CHAPTER` line, both included. The
/// other sections keep their marker lines. A marker without its number or its end is an error
/// at its line.
pub fn cut_later_sections(text: &str, file: &Path, last: u8) -> Result<String, ToolError> {
    let err = |line: usize, why: &str| {
        ToolError::Project(format!("{}:{}: {why}", file.display(), line + 1))
    };
    let mut out = String::with_capacity(text.len());
    let mut open: Option<(usize, u8)> = None;
    for (n, line) in text.split_inclusive('\n').enumerate() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix(BEGIN_CHAPTER) {
            if let Some((at, _)) = open {
                return Err(err(
                    n,
                    &format!(
                        "a chapter's section opens inside the one of line {}",
                        at + 1
                    ),
                ));
            }
            let number = rest
                .split_whitespace()
                .next()
                .and_then(|w| w.parse::<u8>().ok());
            let chapter = number
                .filter(|&c| crate::syllabus::chapter(c).is_some())
                .ok_or_else(|| {
                    err(
                        n,
                        &format!("expected `{BEGIN_CHAPTER} N` with a chapter's number"),
                    )
                })?;
            open = Some((n, chapter));
        } else if t == END_CHAPTER {
            let Some((_, chapter)) = open.take() else {
                return Err(err(n, &format!("`{END_CHAPTER}` closes no section")));
            };
            if chapter > last {
                continue;
            }
        }
        if open.is_none_or(|(_, c)| c <= last) {
            out.push_str(line);
        }
    }
    match open {
        Some((at, _)) => Err(err(
            at,
            &format!("this chapter's section has no `{END_CHAPTER}` line"),
        )),
        None => Ok(out),
    }
}

#[derive(serde::Deserialize)]
struct Doc {
    handout: Table,
}

#[derive(serde::Deserialize)]
struct Table {
    tests: toml::Spanned<Vec<String>>,
}

/// The handout's manifest: the project's `text` with `[handout] tests` set to `tests` and, on
/// the line after it, `exercises = […]` listing the handout's own exercises by name; every
/// other line (and comment) as it is. The result is read back as the loop reads it, so a
/// manifest the loop would refuse is never written.
pub fn handout_manifest(
    text: &str,
    file: &str,
    tests: &[String],
    exercises: &[&str],
) -> Result<String, ToolError> {
    let doc: Doc = crate::manifest::from_toml(text, file)?;
    let span = doc.handout.tests.span();
    let end_of_line = text[span.end..]
        .find('\n')
        .map_or(text.len(), |i| span.end + i + 1);
    let quoted = |names: &mut dyn Iterator<Item = &str>| {
        names
            .map(|n| format!("{n:?}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut out = String::with_capacity(text.len() + 1024);
    out.push_str(&text[..span.start]);
    out.push_str(&format!(
        "[{}]",
        quoted(&mut tests.iter().map(String::as_str))
    ));
    out.push_str(&text[span.end..end_of_line]);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    out.push_str(
        "# the exercises of this handout, yours to write: `cargo learn` counts these alone (the\n\
         # others are earlier chapters' given code, or later chapters' that come with their own\n\
         # handout)\n",
    );
    out.push_str(&format!(
        "exercises = [{}]\n",
        quoted(&mut exercises.iter().copied())
    ));
    out.push_str(&text[end_of_line..]);
    let read = crate::manifest::parse(&out, file)?;
    let kept: Vec<&str> = read
        .entries
        .iter()
        .map(|e| e.exercise.name.as_str())
        .collect();
    if kept != exercises {
        return Err(ToolError::Project(format!(
            "{file}: the handout's manifest lists {kept:?}, not the handout's exercises {exercises:?}"
        )));
    }
    Ok(out)
}

/// The exercises the handout at `dir` gives its students to write: its manifest's `[handout]
/// exercises` list. A handout without the list (one of every exercise) is an error that says
/// so: grading it needs no list.
pub fn listed_in(dir: &Path) -> Result<Vec<String>, ToolError> {
    let path = dir.join(crate::manifest::DEFAULT_PATH);
    let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    let read = crate::manifest::parse(&text, &path.display().to_string())?;
    read.handout.exercises.ok_or_else(|| {
        ToolError::Usage(format!(
            "--handout {}: its manifest lists no exercises of its own (a handout of every exercise), so the grading needs no --handout",
            dir.display()
        ))
    })
}

/// The manifest of the project at `root` with the list `exercises` of a handout's own
/// (`[handout] exercises`), as its text and as read: what a grading of that handout counts,
/// and what a package of it carries.
pub fn listed_manifest(root: &Path, exercises: &[String]) -> Result<(String, Manifest), ToolError> {
    let path = root.join(crate::manifest::DEFAULT_PATH);
    let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    let file = crate::manifest::DEFAULT_PATH;
    let full = crate::manifest::parse(&text, file)?;
    let names: Vec<&str> = exercises.iter().map(String::as_str).collect();
    let listed = handout_manifest(&text, file, &full.handout.tests, &names)?;
    let read = crate::manifest::parse(&listed, file)?;
    Ok((listed, read))
}
