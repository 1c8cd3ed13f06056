//! Handouts: a student's copy of the project with some exercises taken out.
//!
//! In `src/`, the reference body of every exercise sits between two comment lines,
//!
//! ```text
//! pub fn discriminant(a: Real, b: Real, c: Real) -> Real {
//!     // BEGIN SOLUTION sphere_discriminant
//!     b * b - a * c
//!     // END SOLUTION
//! }
//! ```
//!
//! and [`write()`] copies the project with the chosen regions' bodies replaced by
//! `todo!("exercise sphere_discriminant (2.7): The sphere's discriminant — see chapters/ch02_generic_objects/README.md")`
//! (the message is the syllabus's, [`crate::syllabus::todo`]), between the same two marker lines: the student writes the body there, and `whitted grade`
//! takes what is between them.
//! Exercises not chosen keep their reference code, so a course can hand out one chapter alone
//! on top of working earlier chapters. The copy holds no solution of a chosen exercise, and
//! no instructor material: of `tests/`, only the targets the manifest's `[handout] tests`
//! lists (and the helper directories they use, such as `tests/common/` and `tests/golden/`),
//! and no `.ci/`. It is written into a temporary directory beside the destination and renamed
//! into place, so a failure leaves nothing half written.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use super::manifest::{Entry, Manifest};
use super::source::Location;
use super::{ToolError, files, layout};

pub use super::layout::{BEGIN, END};

/// The line the handout adds at the top of the renderer's `lib.rs`, after the crate's
/// documentation.
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
/// the entry's exercise name and the END line after it, both inside the function's body. A
/// region missing, or misnumbered, or a BEGIN marker in `src/` that belongs to no entry, is an
/// error that names the file and line.
pub fn regions(root: &Path, manifest: &Manifest) -> Result<Vec<Region>, ToolError> {
    let locations = super::source::locate_all(root, manifest)?;
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
    for file in super::book::pages(&root.join(layout::core_src()), "rs")? {
        let text = std::fs::read_to_string(&file).map_err(|err| ToolError::io(&file, err))?;
        let relative = file.strip_prefix(root).unwrap_or(&file).to_path_buf();
        let mut offset = 0;
        for (n, line) in text.split_inclusive('\n').enumerate() {
            if line.trim_start().starts_with(BEGIN)
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

/// The statement that replaces a handed-out exercise's region: `todo!` with the syllabus's
/// message, which names the exercise, its displayed id and its chapter's README.
#[must_use]
pub fn todo_statement(e: &Entry) -> String {
    let readme = crate::syllabus::chapter(e.chapter).map_or_else(String::new, |c| c.readme());
    let message = crate::syllabus::todo::message(
        &e.exercise.name,
        &e.exercise.id,
        &e.exercise.title,
        &readme,
    );
    format!("todo!({message:?})")
}

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

/// What becomes of a project file in a handout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// Left out: the instructor's (tools, benchmarks, CI, mutation and grading tests, hidden
    /// tests, the instructor's guide) or not needed without mdBook.
    Left,
    /// Copied as it is (or with its exercises' bodies taken out).
    Copied,
    /// A page of the course book, written with every `{{#include …}}` replaced by what it
    /// includes, so that it reads without mdBook.
    Page,
    /// The workspace's manifest, written with only the crates a handout holds.
    Workspace,
    /// Replaced by the student's README.
    Readme,
    /// Cargo's configuration, written with only the alias a student uses (`cargo learn`).
    CargoConfig,
}

/// What becomes of the project file `file` (relative to `root`) in a handout whose test
/// targets are `tests`: the renderer with the listed test targets (and the helper directories
/// of its `tests/` without a `main.rs`, such as `common/` and `golden/`), the chapter binaries,
/// the course tools without their tests, the chapters, the scenes and the book's pages.
#[must_use]
pub fn part_of(file: &Path, tests: &[String], root: &Path) -> Part {
    let path = file.to_string_lossy().replace('\\', "/");
    let under = |dir: &str| path.strip_prefix(dir).and_then(|r| r.strip_prefix('/'));
    if path == "Cargo.toml" {
        return Part::Workspace;
    }
    if path == "README.md" {
        return Part::Readme;
    }
    if path == ".cargo/config.toml" {
        return Part::CargoConfig;
    }
    if matches!(path.as_str(), "Cargo.lock" | ".gitignore") {
        return Part::Copied;
    }
    if let Some(rest) = under(&layout::core_tests().to_string_lossy()) {
        let (first, more) = match rest.split_once('/') {
            Some((a, b)) => (a, Some(b)),
            None => (rest, None),
        };
        let listed = |name: &str| tests.iter().any(|t| t == name);
        let keep = match more {
            // tests/NAME.rs is a test target
            None => first.strip_suffix(".rs").is_some_and(listed),
            // tests/NAME/…: a target when it has a main.rs, else helpers
            Some(_) => {
                !root
                    .join(layout::core_tests())
                    .join(first)
                    .join("main.rs")
                    .is_file()
                    || listed(first)
            }
        };
        return if keep { Part::Copied } else { Part::Left };
    }
    if under(layout::CORE).is_some() {
        return Part::Copied;
    }
    for krate in [layout::SYLLABUS, layout::APP, layout::LEARN] {
        if let Some(rest) = under(krate) {
            return if rest.starts_with("tests/") {
                Part::Left
            } else {
                Part::Copied
            };
        }
    }
    if under("chapters").is_some() || under("scenes").is_some() {
        return Part::Copied;
    }
    // the book's figures' list: `cargo learn` draws a figure as the student's code does
    if path == whitted_learn::figures::FIGURES {
        return Part::Copied;
    }
    if let Some(rest) = under("docs/src") {
        let instructor = rest == "instructor-guide.md";
        let unneeded = rest.starts_with("katex/") || rest.ends_with(".json");
        return match () {
            _ if instructor || unneeded => Part::Left,
            _ if rest.ends_with(".md") => Part::Page,
            _ => Part::Copied,
        };
    }
    Part::Left
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
) -> Result<Handout, ToolError> {
    if out.exists() {
        let empty = std::fs::read_dir(out)
            .map(|mut d| d.next().is_none())
            .unwrap_or(false);
        if !empty {
            return Err(ToolError::Usage(format!(
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
    std::fs::create_dir_all(&parent).map_err(|e| ToolError::io(&parent, e))?;
    let temp = tempfile::Builder::new()
        .prefix(".whitted-handout-")
        .tempdir_in(&parent)
        .map_err(|e| ToolError::io(&parent, e))?;
    let files = files::project_files(root)?;
    let tests = &manifest.handout.tests;
    let mut edits: BTreeMap<PathBuf, Vec<&Region>> = BTreeMap::new();
    for r in regions.iter().filter(|r| selected.contains(&r.entry)) {
        edits.entry(r.file.clone()).or_default().push(r);
    }
    let lib = layout::core_lib();
    let mut written = 0;
    let mut pages = Vec::new();
    for file in &files {
        let part = part_of(file, tests, root);
        if part == Part::Left {
            continue;
        }
        let from = root.join(file);
        let to = temp.path().join(file);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).map_err(|e| ToolError::io(dir, e))?;
        }
        let read = || std::fs::read_to_string(&from).map_err(|e| ToolError::io(&from, e));
        let text = match part {
            Part::Workspace => Some(workspace_manifest(&read()?)?),
            Part::Readme => Some(student_readme(root, manifest, selected)?),
            Part::CargoConfig => Some(cargo_config(&read()?)?),
            Part::Page => {
                pages.push(file.clone());
                None
            }
            _ => match edits.get(file) {
                Some(rs) => Some(strip(&read()?, rs, manifest)),
                None if *file == lib && !selected.is_empty() => Some(read()?),
                None => None,
            },
        };
        match text {
            Some(mut t) => {
                if *file == lib && !selected.is_empty() {
                    t = allow_unused(&t);
                }
                std::fs::write(&to, t).map_err(|e| ToolError::io(&to, e))?;
            }
            None => {
                std::fs::copy(&from, &to).map_err(|e| ToolError::io(&from, e))?;
            }
        }
        written += 1;
    }
    // the book's pages last: what they include is the handout's own code, exercises taken out
    for page in &pages {
        let to = temp.path().join(page);
        let text = std::fs::read_to_string(root.join(page)).map_err(|e| ToolError::io(page, e))?;
        let dir = to.parent().unwrap_or(temp.path());
        let mut expanded = super::book::expand_includes(&text, dir)
            .map_err(|why| ToolError::Project(format!("{}: {why}", page.display())))?;
        if page.file_name().is_some_and(|n| n == "SUMMARY.md") {
            expanded = without_instructors(&expanded);
        }
        std::fs::write(&to, expanded).map_err(|e| ToolError::io(&to, e))?;
    }
    prune_lock(temp.path());
    let kept = temp.keep();
    if out.exists() {
        std::fs::remove_dir(out).map_err(|e| ToolError::io(out, e))?;
    }
    std::fs::rename(&kept, out).map_err(|e| ToolError::io(out, e))?;
    Ok(Handout {
        stripped: selected.to_vec(),
        files: written,
    })
}

/// Lets cargo drop from the handout's `Cargo.lock` the packages that only the instructor's
/// crates use (`cargo metadata --offline`, which resolves from the lock without the network),
/// so that the student's first build leaves the lock as it is. If cargo cannot, the lock stays
/// as copied, and the first build prunes it.
fn prune_lock(project: &Path) {
    let pruned = super::cargo::command(project, None, true)
        .args(["metadata", "--offline", "--format-version", "1"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status();
    if !pruned.is_ok_and(|s| s.success()) {
        eprintln!("warning: cargo could not prune the handout's Cargo.lock; its first build will");
    }
}

/// The handout's workspace manifest: the project's, with only the crates a handout holds as
/// members (tools and benchmarks stay with the instructor) and a header of its own.
pub fn workspace_manifest(reference: &str) -> Result<String, ToolError> {
    let members = format!(
        "members = [{}]",
        [layout::SYLLABUS, layout::CORE, layout::APP, layout::LEARN]
            .map(|m| format!("{m:?}"))
            .join(", ")
    );
    let mut out = String::from(
        "# The workspace of your copy of whitted: the renderer you write (crates/whitted), the\n\
         # chapter binaries (crates/whitted-app), the loop behind `cargo learn`\n\
         # (crates/whitted-learn) and the course's outline they share (crates/whitted-syllabus).\n",
    );
    let mut replaced = false;
    let mut header = true;
    for line in reference.lines() {
        if header && line.starts_with('#') {
            continue; // the reference's header describes the whole project
        }
        header = false;
        if line.trim_start().starts_with("members = [") && !replaced {
            out += &members;
            replaced = true;
        } else if LEFT_PACKAGES
            .iter()
            .any(|p| line.trim_start().starts_with(&format!("{p} ")))
        {
            continue; // a dependency or profile setting of a crate the handout does not hold
        } else {
            out += line;
        }
        out.push('\n');
    }
    if !replaced {
        return Err(ToolError::Project(
            "Cargo.toml: no `members = [...]` line to write the handout's members into".into(),
        ));
    }
    out += HANDOUT_PROFILE;
    Ok(out)
}

/// What a handout's workspace manifest adds to the project's profiles: the renderer at
/// opt-level 0 in dev and test builds. Writing an exercise's first body then recompiles a few
/// functions instead of half the crate (measured on `cylinder::intersect`: 9 s at opt-level 1,
/// 2 s at 0), while a chapter's tests still run in milliseconds and its picture renders in
/// under a second. (The instructor's project keeps opt-level 1: its own tests are heavier.)
pub const HANDOUT_PROFILE: &str = "\n# In a handout the renderer compiles at opt-level 0 in dev and test builds: writing an\n\
     # exercise recompiles a few functions, not half the crate, and its tests still take a\n\
     # moment. Release builds (`cargo run --release`) are as fast as ever.\n\
     [profile.dev.package.whitted]\nopt-level = 0\n";

/// Packages of the project that no crate of a handout uses: their lines in the workspace's
/// manifest (a path dependency, a profile setting) are left out, since cargo warns at every
/// build about a profile setting that names no package.
pub const LEFT_PACKAGES: [&str; 6] = [
    "whitted-course",
    "whitted-tools",
    "whitted-benches",
    "whitted-tests",
    "roxmltree",
    "plotters",
];

/// The handout's `.cargo/config.toml`: the project's `learn` alias (the one command of the
/// student's README) and nothing of the instructor's.
pub fn cargo_config(reference: &str) -> Result<String, ToolError> {
    let learn = reference
        .lines()
        .find(|l| l.trim_start().starts_with("learn ="))
        .ok_or_else(|| {
            ToolError::Project(".cargo/config.toml: no `learn = …` alias for the handout".into())
        })?;
    Ok(format!(
        "# `cargo learn`: the loop of this handout (crates/whitted-learn), built once, at the test\n\
         # profile, which its own builds of the renderer's tests and binaries use too.\n\
         [alias]\n{learn}\n"
    ))
}

/// `SUMMARY.md` without the section for instructors (a handout has no instructor's guide).
fn without_instructors(summary: &str) -> String {
    let mut out = String::new();
    let mut skipping = false;
    for line in summary.lines() {
        if line.starts_with("# ") {
            skipping = line.contains("nstructor");
        }
        if !skipping && !line.contains("instructor-guide.md") {
            out += line;
            out.push('\n');
        }
    }
    out
}

/// Where the student's README of a handout comes from, in the course tools' crate.
pub const README_TEMPLATE: &str = "crates/whitted-course/handout/README.md";

/// The student's README: the template [`README_TEMPLATE`] with `{exercises}` (which exercises
/// the handout takes out) and `{chapters}` (the chapters' list) filled in.
pub fn student_readme(
    root: &Path,
    manifest: &Manifest,
    selected: &[usize],
) -> Result<String, ToolError> {
    let path = root.join(README_TEMPLATE);
    let template = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    let ids: Vec<String> = super::manifest::compress_ids(&manifest.entries, selected);
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
    let mut chapters = String::new();
    for chapter in &crate::syllabus::CHAPTERS {
        let (n, title, dir) = (chapter.number, chapter.title, chapter.binary);
        let count = selected
            .iter()
            .filter(|&&i| manifest.entries[i].chapter == n)
            .count();
        chapters += &format!(
            "| {n} | {title} | `{dir}` | [chapters/{dir}/README.md](chapters/{dir}/README.md) | {count} |\n"
        );
    }
    Ok(template
        .replace("{exercises}", &exercises)
        .replace("{chapters}", chapters.trim_end()))
}

/// `text` with each region's body replaced by its exercise's `todo!()`, between the same
/// marker lines.
fn strip(text: &str, regions: &[&Region], manifest: &Manifest) -> String {
    let mut sorted: Vec<&&Region> = regions.iter().collect();
    sorted.sort_by_key(|r| r.bytes.start);
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for r in sorted {
        let e = &manifest.entries[r.entry];
        out.push_str(&text[at..r.bytes.start]);
        // the markers stay: the student writes between them, and `whitted grade` takes
        // exactly what is there
        out.push_str(&format!("{}{BEGIN} {}\n", r.indent, e.exercise.name));
        out.push_str(&format!("{}{}\n", r.indent, todo_statement(e)));
        out.push_str(&format!("{}{END}\n", r.indent));
        at = r.bytes.end;
    }
    out.push_str(&text[at..]);
    out
}

/// The renderer's `lib.rs` with [`LIB_ALLOW`] after its leading `//!` documentation.
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

/// `whitted handout`: writes the handout of the exercises chosen (see [`select`]) into `out`
/// and says what it holds.
pub fn command(
    root: &Path,
    manifest: &Manifest,
    chapters: Option<(u8, u8)>,
    exercises: &[String],
    out: &Path,
) -> Result<std::process::ExitCode, ToolError> {
    let selected = select(manifest, chapters, exercises)?;
    let made = write(root, manifest, &selected, out)?;
    let ids: Vec<&str> = made
        .stripped
        .iter()
        .map(|&i| manifest.entries[i].exercise.id.as_str())
        .collect();
    println!(
        "wrote {} ({} files): {} exercise{} to write ({}); in it, run `cargo learn`",
        out.display(),
        made.files,
        ids.len(),
        if ids.len() == 1 { "" } else { "s" },
        if ids.len() == manifest.entries.len() {
            "all".to_string()
        } else {
            ids.join(", ")
        }
    );
    Ok(std::process::ExitCode::SUCCESS)
}
