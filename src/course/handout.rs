//! Handouts: a student's copy of the project with some exercises taken out.
//!
//! In `src/`, the reference body of every exercise sits between two comment lines,
//!
//! ```text
//! pub fn discriminant(a: Real, b: Real, c: Real) -> Real {
//!     // BEGIN SOLUTION 2.3
//!     b * b - a * c
//!     // END SOLUTION
//! }
//! ```
//!
//! and [`write()`] copies the project with the chosen regions' bodies replaced by
//! `todo!("exercise 2.3: The sphere's discriminant — see chapters/ch02_generic_objects/README.md")`,
//! between the same two marker lines: the student writes the body there, and `whitted grade`
//! takes what is between them.
//! Exercises not chosen keep their reference code, so a course can hand out one chapter alone
//! on top of working earlier chapters. The copy holds no solution of a chosen exercise, and
//! no instructor material: of `tests/`, only the targets the manifest's `[handout] tests`
//! lists (and the helper directories they use, such as `tests/common/` and `tests/golden/`),
//! and no `.ci/`. It is written into a temporary directory beside the destination and renamed
//! into place, so a failure leaves nothing half written.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use super::manifest::{Entry, Manifest};
use super::source::Location;
use super::{Error, prove};

/// The marker line that opens a solution region: `// BEGIN SOLUTION 2.3`.
pub const BEGIN: &str = "// BEGIN SOLUTION";
/// The marker line that closes it.
pub const END: &str = "// END SOLUTION";

/// The line the handout adds at the top of `src/lib.rs`, after the crate's documentation.
pub const LIB_ALLOW: &str = "// handout: the parameters of the exercises still to write are unused until you write them\n#![allow(unused_variables, unused_imports, unused_mut, dead_code)]\n";

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
/// the entry's exercise id and the END line after it, both inside the function's body. A
/// region missing, or misnumbered, or a BEGIN marker in `src/` that belongs to no entry, is an
/// error that names the file and line.
pub fn regions(root: &Path, manifest: &Manifest) -> Result<Vec<Region>, Error> {
    let locations = prove::locate_all(root, manifest)?;
    let mut out = Vec::with_capacity(locations.len());
    for (entry, (e, at)) in manifest.entries.iter().zip(&locations).enumerate() {
        let path = root.join(&at.file);
        let text = std::fs::read_to_string(&path).map_err(|err| Error::io(&path, err))?;
        out.push(region_in(&text, entry, e, at)?);
    }
    // every marker in src/ belongs to a region found above
    let mut known: BTreeMap<PathBuf, Vec<usize>> = BTreeMap::new();
    for r in &out {
        known.entry(r.file.clone()).or_default().push(r.bytes.start);
    }
    for file in super::book::pages(&root.join("src"), "rs")? {
        let text = std::fs::read_to_string(&file).map_err(|err| Error::io(&file, err))?;
        let relative = file.strip_prefix(root).unwrap_or(&file).to_path_buf();
        let mut offset = 0;
        for (n, line) in text.split_inclusive('\n').enumerate() {
            if line.trim_start().starts_with(BEGIN)
                && !known
                    .get(&relative)
                    .is_some_and(|starts| starts.contains(&offset))
            {
                return Err(Error::Proof(format!(
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
fn region_in(text: &str, entry: usize, e: &Entry, at: &Location) -> Result<Region, Error> {
    let id = &e.exercise.id;
    let body = &text[at.body.clone()];
    let fail = |what: String| {
        Error::Proof(format!(
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

/// The directory of chapter `chapter` under `chapters/` (`ch02_generic_objects`), or
/// `chNN` when there is none.
#[must_use]
pub fn chapter_dir(root: &Path, chapter: u8) -> String {
    let prefix = format!("ch{chapter:02}_");
    std::fs::read_dir(root.join("chapters"))
        .ok()
        .and_then(|dir| {
            let mut names: Vec<String> = dir
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.starts_with(&prefix))
                .collect();
            names.sort();
            names.into_iter().next()
        })
        .unwrap_or_else(|| format!("ch{chapter:02}"))
}

/// The statement that replaces a handed-out exercise's region.
#[must_use]
pub fn todo_statement(root: &Path, e: &Entry) -> String {
    let message = format!(
        "exercise {}: {} — see chapters/{}/README.md",
        e.exercise.id,
        e.exercise.title,
        chapter_dir(root, e.chapter)
    );
    format!("todo!({message:?})")
}

/// Which exercises a handout takes out: those of `chapters` (inclusive range), or those named
/// in `exercises` (ids), or all when both are empty. An unknown id or chapter is an error.
pub fn select(
    manifest: &Manifest,
    chapters: Option<(u8, u8)>,
    exercises: &[String],
) -> Result<Vec<usize>, Error> {
    if let Some((lo, hi)) = chapters {
        if !(1..=5).contains(&lo) || !(1..=5).contains(&hi) || lo > hi {
            let given = if lo == hi {
                lo.to_string()
            } else {
                format!("{lo}-{hi}")
            };
            return Err(Error::Usage(format!(
                "--chapters {given}: expected chapters from 1 to 5, the first not after the last"
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
        let i = manifest
            .entries
            .iter()
            .position(|e| e.exercise.id == id.trim())
            .ok_or_else(|| {
                Error::Usage(format!(
                    "--exercises: there is no exercise {id} in {} (ids look like 2.3; `whitted learn list` shows them)",
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

/// Whether the project file `file` (relative) goes into a handout whose test targets are
/// `tests`: everything but `.ci/`, `target/` and the test targets not listed. A directory of
/// `tests/` without a `main.rs` (helpers, golden images) goes along.
#[must_use]
pub fn in_handout(file: &Path, tests: &[String], root: &Path) -> bool {
    let mut parts = file.components().map(|c| c.as_os_str().to_string_lossy());
    match parts.next().as_deref() {
        Some(".ci") | Some("target") | Some(".git") => false,
        Some("tests") => {
            let Some(second) = parts.next() else {
                return false;
            };
            let is_file = parts.next().is_none();
            if is_file {
                // tests/NAME.rs is a test target
                let name = second.trim_end_matches(".rs");
                second.ends_with(".rs") && tests.iter().any(|t| t == name)
            } else {
                // tests/NAME/…: a target when it has a main.rs, else helpers
                let target = root.join("tests").join(second.as_ref()).join("main.rs");
                !target.is_file() || tests.iter().any(|t| t == second.as_ref())
            }
        }
        _ => true,
    }
}

/// What [`write()`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Handout {
    /// The exercises taken out (manifest indices).
    pub stripped: Vec<usize>,
    /// How many files were written.
    pub files: usize,
}

/// Writes the handout of `root`'s project into `out`, which must not exist or be an empty
/// directory: the exercises `selected` (manifest indices) become `todo!()`.
pub fn write(
    root: &Path,
    manifest: &Manifest,
    selected: &[usize],
    out: &Path,
) -> Result<Handout, Error> {
    if out.exists() {
        let empty = std::fs::read_dir(out)
            .map(|mut d| d.next().is_none())
            .unwrap_or(false);
        if !empty {
            return Err(Error::Usage(format!(
                "{} exists and is not an empty directory: give a new directory for the handout",
                out.display()
            )));
        }
    }
    let regions = regions(root, manifest)?;
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&parent).map_err(|e| Error::io(&parent, e))?;
    let temp = tempfile::Builder::new()
        .prefix(".whitted-handout-")
        .tempdir_in(&parent)
        .map_err(|e| Error::io(&parent, e))?;
    let files = prove::project_files(root)?;
    let tests = &manifest.handout.tests;
    let mut edits: BTreeMap<PathBuf, Vec<&Region>> = BTreeMap::new();
    for r in regions.iter().filter(|r| selected.contains(&r.entry)) {
        edits.entry(r.file.clone()).or_default().push(r);
    }
    let mut written = 0;
    for file in files.iter().filter(|f| in_handout(f, tests, root)) {
        let from = root.join(file);
        let to = temp.path().join(file);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
        }
        let mut text = None;
        if let Some(rs) = edits.get(file) {
            let original = std::fs::read_to_string(&from).map_err(|e| Error::io(&from, e))?;
            text = Some(strip(&original, rs, root, manifest));
        } else if file == Path::new("src/lib.rs") && !selected.is_empty() {
            text = Some(std::fs::read_to_string(&from).map_err(|e| Error::io(&from, e))?);
        }
        match text {
            Some(mut t) => {
                if file == Path::new("src/lib.rs") && !selected.is_empty() {
                    t = allow_unused(&t);
                }
                std::fs::write(&to, t).map_err(|e| Error::io(&to, e))?;
            }
            None => {
                std::fs::copy(&from, &to).map_err(|e| Error::io(&from, e))?;
            }
        }
        written += 1;
    }
    let kept = temp.keep();
    if out.exists() {
        std::fs::remove_dir(out).map_err(|e| Error::io(out, e))?;
    }
    std::fs::rename(&kept, out).map_err(|e| Error::io(out, e))?;
    Ok(Handout {
        stripped: selected.to_vec(),
        files: written,
    })
}

/// `text` with each region's body replaced by its exercise's `todo!()`, between the same
/// marker lines.
fn strip(text: &str, regions: &[&Region], root: &Path, manifest: &Manifest) -> String {
    let mut sorted: Vec<&&Region> = regions.iter().collect();
    sorted.sort_by_key(|r| r.bytes.start);
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for r in sorted {
        let e = &manifest.entries[r.entry];
        out.push_str(&text[at..r.bytes.start]);
        // the markers stay: the student writes between them, and `whitted grade` takes
        // exactly what is there
        out.push_str(&format!("{}{BEGIN} {}\n", r.indent, e.exercise.id));
        out.push_str(&format!("{}{}\n", r.indent, todo_statement(root, e)));
        out.push_str(&format!("{}{END}\n", r.indent));
        at = r.bytes.end;
    }
    out.push_str(&text[at..]);
    out
}

/// `src/lib.rs` with [`LIB_ALLOW`] after its leading `//!` documentation.
fn allow_unused(lib: &str) -> String {
    let mut at = 0;
    for line in lib.split_inclusive('\n') {
        if line.trim_start().starts_with("//!") || line.trim().is_empty() && at == 0 {
            at += line.len();
        } else {
            break;
        }
    }
    format!("{}{LIB_ALLOW}{}", &lib[..at], &lib[at..])
}
