//! Reading and checking the manifest `chapters/formulas.toml`, the one list of the functions
//! that compute the notes' formulas.
//!
//! Every key is checked: unknown keys, a chapter the syllabus does not have, a section the
//! notes do not have, a malformed function path, a function listed twice or a name that is not
//! unique are errors that name the file, line and column of the offending value, e.g.
//! `chapters/formulas.toml:12:12: chapter: expected 1 to 5, found 7`.
//!
//! An exercise is known by its **name** (`sphere_coefficients`): its solution region's marker
//! (`// BEGIN SOLUTION sphere_coefficients`), its tests' prefix (`ex_sphere_coefficients_`),
//! its entries in the measured map and the state `cargo learn` keeps all say the name, so
//! inserting an exercise changes nothing of the others. What a student reads is its displayed
//! id, `chapter.k` by the manifest's order (`2.6`), which is derived, never written.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use super::ToolError;
use crate::files::line_col;
use whitted_syllabus::SECTIONS;

pub mod handout;

/// Where the manifest lives, relative to the project's root.
pub const DEFAULT_PATH: &str = "chapters/formulas.toml";

/// The placeholder that [`Prove::filter`] replaces with a chapter's number.
pub const CHAPTER_PLACEHOLDER: &str = "{chapter}";

/// The checked manifest.
#[derive(Clone, Debug, PartialEq)]
pub struct Manifest {
    /// The file's name, as given to [`load`] or [`parse`], for messages.
    pub file: String,
    /// How the proof finds the render paths.
    pub prove: Prove,
    /// What a handout holds.
    pub handout: HandoutTable,
    /// The formula functions, in the file's order; an entry's index is its number in the proof.
    pub entries: Vec<Entry>,
}

/// The `[prove]` table: which tests are the render paths.
#[derive(Clone, Debug, PartialEq)]
pub struct Prove {
    /// The integration test target (a file in `tests/`) whose tests are the render paths.
    pub test: String,
    /// The libtest filter that selects one chapter's tests; `{chapter}` stands for its number.
    pub filter: String,
}

impl Prove {
    /// The filter for chapter `chapter`: [`Prove::filter`] with `{chapter}` replaced.
    #[must_use]
    pub fn filter_for(&self, chapter: u8) -> String {
        self.filter
            .replace(CHAPTER_PLACEHOLDER, &chapter.to_string())
    }
}

/// The `[handout]` table: which test targets a student's copy keeps, and in a handout of some
/// chapters, which exercises are the student's.
#[derive(Clone, Debug, PartialEq)]
pub struct HandoutTable {
    /// The test targets (files of `tests/` without `.rs`, or directories with a `main.rs`)
    /// that go into a handout; the others are the instructor's.
    pub tests: Vec<String>,
    /// The exercises of a handout of some of them, by name (`exercises = [...]`); `None` (no
    /// key) for all. [`Manifest::entries`] holds only these (see [`handout`]).
    pub exercises: Option<Vec<String>>,
    /// The names of the exercises [`HandoutTable::exercises`] leaves out: given earlier
    /// chapters' and later chapters' (empty without the key). The map reads past them.
    pub others: Vec<String>,
}

/// One `[[formula]]` entry: a function and the formula of the notes it computes.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The function's path in the crate: `module::fn` or `module::Type::method`.
    pub function: String,
    /// The chapter (1–5) whose render paths must all call the function.
    pub chapter: u8,
    /// The section of the notes where the formula is given.
    pub section: String,
    /// The formula, in the notes' symbols.
    pub formula: String,
    /// The line of the entry's `function` key in the manifest (from 1).
    pub line: usize,
    /// The exercise the function is: its name, displayed id, title, task, hints and points.
    pub exercise: Exercise,
}

/// The exercise a formula function is, for the handout, `whitted learn` and grading.
#[derive(Clone, Debug, PartialEq)]
pub struct Exercise {
    /// Its name, which never changes (`sphere_coefficients`): see the module's documentation.
    pub name: String,
    /// Its displayed id, `chapter.k`: the k-th exercise of its chapter in the manifest (`2.6`).
    pub id: String,
    /// A few words naming it ("The sphere's discriminant").
    pub title: String,
    /// What to write: the contract the function must keep (its signature is in the source).
    pub task: String,
    /// Two or three hints, from the idea to the formula (never the code).
    pub hints: Vec<String>,
    /// What the exercise is worth.
    pub points: u32,
    /// The test that tells most about a wrong body, shown first when several fail: the rest of
    /// its name after [`Exercise::test_prefix`] (`viewing_angle_is_converted_from_degrees`).
    pub first_check: Option<String>,
    /// The course book's figure (a file of `docs/figures.toml`) that shows what this exercise
    /// adds, drawn while its chapter is written (`ch03-diffuse.png`); `None` for the chapter's
    /// own figure. `cargo learn` draws it with the student's code beside the book's.
    pub picture: Option<String>,
}

/// What the names of an exercise's own tests begin with, before its name.
pub const TEST_PREFIX: &str = "ex_";

impl Exercise {
    /// The prefix of the names of the exercise's own tests: `ex_sphere_coefficients_` for the
    /// exercise `sphere_coefficients`. No name followed by `_` begins another name (the
    /// manifest is refused otherwise), so a test belongs to one exercise at most.
    #[must_use]
    pub fn test_prefix(&self) -> String {
        format!("{TEST_PREFIX}{}_", self.name)
    }
}

impl Manifest {
    /// The entry (its index) of the exercise named `key`, or whose displayed id is `key`: a
    /// student may type either.
    #[must_use]
    pub fn find(&self, key: &str) -> Option<usize> {
        let key = key.trim();
        self.entries
            .iter()
            .position(|e| e.exercise.name == key || e.exercise.id == key)
    }

    /// The entry of the exercise named `name`.
    #[must_use]
    pub fn by_name(&self, name: &str) -> Option<usize> {
        self.entries.iter().position(|e| e.exercise.name == name)
    }

    /// The displayed id of the exercise named `name`, or the name itself when no exercise has
    /// it (a message from an older handout).
    #[must_use]
    pub fn display<'a>(&'a self, name: &'a str) -> &'a str {
        self.by_name(name)
            .map_or(name, |i| self.entries[i].exercise.id.as_str())
    }

    /// The entry whose tests' prefix the test `name` (a test's own name, without its target
    /// or module) begins with.
    #[must_use]
    pub fn exercise_of_test(&self, name: &str) -> Option<usize> {
        self.entries
            .iter()
            .position(|e| name.starts_with(&e.exercise.test_prefix()))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawManifest {
    prove: Spanned<RawProve>,
    handout: Spanned<RawHandout>,
    #[serde(default)]
    formula: Vec<Spanned<RawEntry>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawProve {
    test: Spanned<String>,
    filter: Spanned<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHandout {
    tests: Spanned<Vec<String>>,
    exercises: Option<Spanned<Vec<String>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEntry {
    function: Spanned<String>,
    name: Option<Spanned<String>>,
    chapter: Spanned<i64>,
    section: Spanned<String>,
    formula: Spanned<String>,
    title: Option<Spanned<String>>,
    task: Option<Spanned<String>>,
    hints: Option<Spanned<Vec<String>>>,
    points: Option<Spanned<i64>>,
    first_check: Option<Spanned<String>>,
    picture: Option<Spanned<String>>,
    /// The quantities of the ray tree the function computes: the renderer reads them to say
    /// which functions computed a number (`render::inspect::provenance`) and checks them;
    /// the loop only lets them through.
    #[serde(rename = "computes")]
    _computes: Option<Vec<String>>,
}

/// Reads and checks the manifest at `path`; messages name the path as given.
pub fn load(path: &Path) -> Result<Manifest, ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    parse(&text, &path.display().to_string())
}

/// A mistake at byte range `span` of the TOML text `text` of `file`, reported as
/// `file:line:col: message`.
pub fn error_at(text: &str, file: &str, span: Range<usize>, message: String) -> ToolError {
    let (line, col) = line_col(text, span.start);
    ToolError::Manifest {
        file: file.to_string(),
        line,
        col,
        message,
    }
}

/// Reads TOML text into `T`; a syntax error, a missing or unknown key or a wrong type is
/// reported where it is, in one line ([`error_at`]).
pub fn from_toml<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, ToolError> {
    toml::from_str(text).map_err(|e| {
        let message = e.message().trim().replace('\n', " ");
        error_at(text, file, e.span().unwrap_or(0..0), message)
    })
}

/// Checks the manifest text `text`; `file` names it in messages.
pub fn parse(text: &str, file: &str) -> Result<Manifest, ToolError> {
    let err = |span: Range<usize>, message: String| error_at(text, file, span, message);
    let raw: RawManifest = from_toml(text, file)?;

    let (test, filter) = (&raw.prove.get_ref().test, &raw.prove.get_ref().filter);
    if test.get_ref().is_empty() || test.get_ref().contains(char::is_whitespace) {
        return Err(err(
            test.span(),
            format!(
                "prove.test: expected the name of a test target (a file in tests/ without .rs), found {:?}",
                test.get_ref()
            ),
        ));
    }
    if filter.get_ref().trim().is_empty() {
        return Err(err(
            filter.span(),
            "prove.filter: expected a test-name filter such as \"ch{chapter}_\", found an empty one"
                .into(),
        ));
    }
    let prove = Prove {
        test: test.get_ref().clone(),
        filter: filter.get_ref().clone(),
    };

    let tests = &raw.handout.get_ref().tests;
    if tests.get_ref().is_empty()
        || tests
            .get_ref()
            .iter()
            .any(|t| t.is_empty() || t.contains(['/', '\\', ' ']) || t.ends_with(".rs"))
    {
        return Err(err(
            tests.span(),
            format!(
                "handout.tests: expected the names of test targets (files of tests/ without .rs), found {:?}",
                tests.get_ref()
            ),
        ));
    }
    if !tests.get_ref().contains(&prove.test) {
        return Err(err(
            tests.span(),
            format!(
                "handout.tests: the render paths `{}` of [prove] must go into the handout too",
                prove.test
            ),
        ));
    }
    let mut handout = HandoutTable {
        tests: tests.get_ref().clone(),
        exercises: None,
        others: Vec::new(),
    };

    if raw.formula.is_empty() {
        return Err(err(
            raw.prove.span(),
            "the manifest lists no function: expected at least one [[formula]] table".into(),
        ));
    }

    let mut entries = Vec::with_capacity(raw.formula.len());
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut names: Vec<(String, usize)> = Vec::new();
    let mut per_chapter = [0usize; whitted_syllabus::CHAPTERS.len()];
    for spanned in &raw.formula {
        let raw = spanned.get_ref();
        let function = raw.function.get_ref().trim();
        if !is_function_path(function) {
            return Err(err(
                raw.function.span(),
                format!(
                    "function: expected a path in the crate such as \"camera::viewing_basis\" or \"ray::Ray::at\", found {:?}",
                    raw.function.get_ref()
                ),
            ));
        }
        let (line, _) = line_col(text, raw.function.span().start);
        if let Some(first) = seen.insert(function.to_string(), line) {
            return Err(err(
                raw.function.span(),
                format!("function {function} is listed twice (first on line {first})"),
            ));
        }
        let chapter = *raw.chapter.get_ref();
        let chapter = u8::try_from(chapter)
            .ok()
            .filter(|&c| whitted_syllabus::chapter(c).is_some())
            .ok_or_else(|| {
                err(
                    raw.chapter.span(),
                    format!(
                        "chapter: expected {} to {}, found {chapter}",
                        whitted_syllabus::FIRST,
                        whitted_syllabus::LAST
                    ),
                )
            })?;
        let section = raw.section.get_ref();
        if !SECTIONS.contains(&section.as_str()) {
            return Err(err(
                raw.section.span(),
                format!(
                    "section: {section:?} is not a section of the course notes; expected one of: {}",
                    SECTIONS.join(", ")
                ),
            ));
        }
        let formula = raw.formula.get_ref().trim();
        if formula.is_empty() {
            return Err(err(
                raw.formula.span(),
                "formula: expected the formula in the notes' symbols, found an empty string".into(),
            ));
        }
        per_chapter[usize::from(chapter) - 1] += 1;
        let id = format!("{chapter}.{}", per_chapter[usize::from(chapter) - 1]);
        let exercise = exercise(raw, id, spanned.span(), &err)?;
        let name_span = raw.name.as_ref().map_or(0..0, Spanned::span);
        for (other, other_line) in &names {
            let clash = if *other == exercise.name {
                Some(format!(
                    "name {other:?} is taken (by the exercise on line {other_line})"
                ))
            } else if exercise.name.starts_with(&format!("{other}_"))
                || other.starts_with(&format!("{}_", exercise.name))
            {
                let (short, long) = if exercise.name.len() < other.len() {
                    (exercise.name.as_str(), other.as_str())
                } else {
                    (other.as_str(), exercise.name.as_str())
                };
                Some(format!(
                    "name {:?}: `{short}_` begins `{long}` (line {other_line} has the other), so a test named `{TEST_PREFIX}{long}_…` would be both exercises'",
                    exercise.name
                ))
            } else {
                None
            };
            if let Some(message) = clash {
                return Err(err(name_span, message));
            }
        }
        names.push((exercise.name.clone(), line));
        entries.push(Entry {
            function: function.to_string(),
            chapter,
            section: section.clone(),
            formula: formula.to_string(),
            line,
            exercise,
        });
    }

    let listed = raw.handout.get_ref().exercises.as_ref();
    let (entries, split) = handout::only_listed(listed, entries, |e| e.exercise.name.as_str())
        .map_err(|(span, message)| error_at(text, file, span, message))?;
    (handout.exercises, handout.others) = split.map_or((None, Vec::new()), |(h, o)| (Some(h), o));
    Ok(Manifest {
        file: file.to_string(),
        prove,
        handout,
        entries,
    })
}

/// The shortest way to show the entries `set` to a reader: displayed ids, ranges (`2.1-2.12`)
/// and whole chapters (`3.*`).
#[must_use]
pub fn compress_ids(entries: &[Entry], set: &[usize]) -> Vec<String> {
    let mut sorted = set.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    let mut out = Vec::new();
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i;
        while j + 1 < sorted.len()
            && sorted[j + 1] == sorted[j] + 1
            && entries[sorted[j + 1]].chapter == entries[sorted[i]].chapter
        {
            j += 1;
        }
        let chapter = entries[sorted[i]].chapter;
        let whole = entries.iter().filter(|e| e.chapter == chapter).count();
        let (a, b) = (
            &entries[sorted[i]].exercise.id,
            &entries[sorted[j]].exercise.id,
        );
        out.push(if j - i + 1 == whole {
            format!("{chapter}.*")
        } else if i == j {
            a.clone()
        } else {
            format!("{a}-{b}")
        });
        i = j + 1;
    }
    out
}

/// The most points one exercise may be worth.
pub const MAX_POINTS: u32 = 100;

/// Checks an entry's exercise keys. `id` is the displayed id its place gives (`chapter.k`).
fn exercise(
    raw: &RawEntry,
    id: String,
    table: Range<usize>,
    err: &impl Fn(Range<usize>, String) -> ToolError,
) -> Result<Exercise, ToolError> {
    let missing = |key: &str| {
        err(
            table.clone(),
            format!(
                "[[formula]] for {}: the exercise key `{key}` is missing",
                raw.function.get_ref()
            ),
        )
    };
    let given = raw.name.as_ref().ok_or_else(|| missing("name"))?;
    let name = given.get_ref().trim();
    if !is_exercise_name(name) {
        return Err(err(
            given.span(),
            format!(
                "name: expected a snake_case name such as \"sphere_coefficients\" (a-z, 0-9 and single `_`, from a letter), found {name:?}"
            ),
        ));
    }
    let text = |key: &str, value: &Option<Spanned<String>>| -> Result<String, ToolError> {
        let value = value.as_ref().ok_or_else(|| missing(key))?;
        let t = value.get_ref().trim();
        if t.is_empty() {
            return Err(err(
                value.span(),
                format!("{key}: expected some text, found an empty string"),
            ));
        }
        Ok(t.to_string())
    };
    let title = text("title", &raw.title)?;
    let task = text("task", &raw.task)?;
    let hints = raw.hints.as_ref().ok_or_else(|| missing("hints"))?;
    let list: Vec<String> = hints
        .get_ref()
        .iter()
        .map(|h| h.trim().to_string())
        .collect();
    if !(2..=3).contains(&list.len()) || list.iter().any(String::is_empty) {
        return Err(err(
            hints.span(),
            format!(
                "hints: expected two or three hints (the idea first, the formula last), found {} ({} empty)",
                list.len(),
                list.iter().filter(|h| h.is_empty()).count()
            ),
        ));
    }
    let points = raw.points.as_ref().ok_or_else(|| missing("points"))?;
    let value = u32::try_from(*points.get_ref())
        .ok()
        .filter(|p| (1..=MAX_POINTS).contains(p))
        .ok_or_else(|| {
            err(
                points.span(),
                format!(
                    "points: expected 1 to {MAX_POINTS}, found {}",
                    points.get_ref()
                ),
            )
        })?;
    let first_check = match &raw.first_check {
        None => None,
        Some(check) => {
            let rest = check.get_ref().trim();
            if !is_test_rest(rest) {
                return Err(err(
                    check.span(),
                    format!(
                        "first_check: expected the rest of a test's name after `{TEST_PREFIX}{name}_` (snake_case), found {rest:?}"
                    ),
                ));
            }
            Some(rest.to_string())
        }
    };
    let picture = match &raw.picture {
        None => None,
        Some(file) => {
            let file_name = file.get_ref().trim();
            let plain = file_name.len() > 4
                && file_name.ends_with(".png")
                && !file_name.contains(['/', '\\']);
            if !plain {
                return Err(err(
                    file.span(),
                    format!(
                        "picture: expected a figure's file name ending in .png, without a directory, found {file_name:?}"
                    ),
                ));
            }
            Some(file_name.to_string())
        }
    };
    Ok(Exercise {
        name: name.to_string(),
        id,
        title,
        task,
        hints: list,
        points: value,
        first_check,
        picture,
    })
}

/// Whether `rest` can end a test's name: ASCII letters, digits and `_`, not empty.
fn is_test_rest(rest: &str) -> bool {
    !rest.is_empty()
        && rest
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

/// Whether `name` is a snake_case exercise name: lower-case ASCII letters, digits and single
/// underscores, from a letter, not ending in `_` (it goes into test function names).
#[must_use]
pub fn is_exercise_name(name: &str) -> bool {
    name.starts_with(|c: char| c.is_ascii_lowercase())
        && !name.ends_with('_')
        && !name.contains("__")
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

/// Whether `path` is two or more Rust identifiers joined by `::`.
fn is_function_path(path: &str) -> bool {
    let segments: Vec<&str> = path.split("::").collect();
    segments.len() >= 2 && segments.iter().all(|s| is_identifier(s))
}

/// Whether `s` is a plain (ASCII) Rust identifier.
fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && s != "_"
}
