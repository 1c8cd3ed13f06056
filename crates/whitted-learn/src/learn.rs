//! `whitted learn` (`cargo learn` in a handout): the student's loop — the verdict on the next
//! exercise first, then the progress of every chapter, hints, the chapter's picture, and all of
//! it again after every save.
//!
//! An exercise is **done** when its own tests (those named `ex_sphere_coefficients_…` for the
//! exercise `sphere_coefficients`, in the test targets of the manifest's `[handout] tests`)
//! all pass. A check goes in two steps, so
//! that the answer a student waits for comes first:
//!
//! 0. **What changed.** The exercises whose body changed since the last complete check
//!    ([`crate::changes`]) are checked first: one that now passes says so at once, and one
//!    that fails gets its verdict before anything else, though it was finished before.
//! 1. **The verdict.** The exercise to look at is the first one that was not done at the last
//!    check (`.whitted/progress.json`, by exercise name), or the first. Only the test target that holds its
//!    tests (by the measured map, `chapters/exercise-tests.toml`) is built and run; if all of
//!    that target's exercises pass, the next target is, until one is not done. That verdict is
//!    printed: the exercise, the notes' formula, every failing test of it with its message,
//!    where to write it.
//! 2. **The picture.** What the student's code draws of the chapter being written, beside the
//!    book's picture of the same stage ([`crate::picture`]).
//! 3. **The progress.** The other targets are built and run at once, and each chapter's count
//!    is printed; should the first exercise not done be another than the verdict's, its
//!    verdict follows.
//!
//! When the code does not compile, the first compiler error is shown at the student's
//! file:line:col, and nothing runs; `learn hint` and `learn list` answer all the same, since
//! this tool does not depend on the student's code. A build that lasts more than a moment (the
//! first one compiles the renderer's dependencies) shows cargo's lines as it goes.
//!
//! Every build selects both the renderer's and the binaries' packages, so cargo resolves their
//! dependencies alike and the renderer is compiled once per save for the tests and the picture.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::cargo::{self, Build, Built, Stderr, TestOutcome, TestRun, test_name};
use crate::manifest::{Entry, Manifest};
use crate::map::{self, Group};
use crate::{ToolError, layout};

/// Where `whitted learn` keeps its state and the images it renders, in the project.
pub const STATE_DIR: &str = ".whitted";

/// The command a student types; every message that names a command names this one (a handout's
/// `.cargo/config.toml` defines it).
pub const COMMAND: &str = "cargo learn";

/// The packages every build of the loop selects (see the module's documentation).
pub const PACKAGES: [&str; 2] = [layout::CORE_PACKAGE, layout::APP_PACKAGE];

/// How long a build may run before its cargo lines are shown.
const QUIET_BUILD: Duration = Duration::from_millis(1500);

/// The time limit of one test target's run: a loop that never ends stops there.
pub const TEST_TIME_LIMIT: Duration = Duration::from_secs(60);

/// Where an exercise stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum State {
    /// All its own tests pass.
    Done,
    /// A test stopped at its `todo!()`: not written yet.
    ToDo,
    /// Written, but these of its own tests fail.
    Failing(Vec<String>),
    /// Its tests stop at the `todo!()` of this other exercise (its name), which comes first.
    Waiting(String),
    /// It has no test in the handout's targets (a mistake of the course, not the student's).
    NoTests,
    /// Not checked (its tests did not run, or the project does not build).
    Unknown,
}

impl State {
    /// A word for the list.
    #[must_use]
    pub fn word(&self) -> String {
        match self {
            State::Done => "done".into(),
            State::ToDo => "to do".into(),
            State::Failing(_) => "failing".into(),
            State::Waiting(name) => format!("waits for {name}"),
            State::NoTests => "no tests".into(),
            State::Unknown => "?".into(),
        }
    }

    /// The state a word of [`State::word`] names, as `.whitted/progress.json` keeps it (the
    /// failing tests are not kept).
    #[must_use]
    pub fn from_word(word: &str) -> State {
        match word {
            "done" => State::Done,
            "to do" => State::ToDo,
            "failing" => State::Failing(Vec::new()),
            "no tests" => State::NoTests,
            w => match w.strip_prefix("waits for ") {
                Some(name) => State::Waiting(name.to_string()),
                None => State::Unknown,
            },
        }
    }
}

/// The name of the exercise whose `todo!()` a test's output `text` stopped at.
#[must_use]
pub fn todo_name(text: &str) -> Option<&str> {
    whitted_syllabus::todo::find(text).map(|t| t.name)
}

/// The state of every exercise of `manifest` (in its order) after the test run `run`: those
/// whose tests did not run are [`State::Unknown`].
#[must_use]
pub fn states(manifest: &Manifest, run: &TestRun) -> Vec<State> {
    manifest
        .entries
        .iter()
        .map(|e| {
            if run.build_error.is_some() {
                return State::Unknown;
            }
            let prefix = e.exercise.test_prefix();
            let own: Vec<(&String, &TestOutcome)> = run
                .outcomes
                .iter()
                .filter(|(name, _)| test_name(name).starts_with(&prefix))
                .collect();
            if own.is_empty() {
                return if run.targets.len() == manifest.handout.tests.len() {
                    State::NoTests
                } else {
                    State::Unknown
                };
            }
            let failed: Vec<String> = own
                .iter()
                .filter(|(_, o)| **o == TestOutcome::Failed)
                .map(|(n, _)| (*n).clone())
                .collect();
            if failed.is_empty() {
                return State::Done;
            }
            let stopped_at: Vec<&str> = failed
                .iter()
                .filter_map(|n| run.failures.get(n).and_then(|t| todo_name(t)))
                .collect();
            // a failure that printed nothing says nothing of where it stopped (a panic on a
            // thread that another test spawned prints in that test's output)
            let telling = failed
                .iter()
                .filter(|n| {
                    run.failures
                        .get(*n)
                        .is_some_and(|t| !message_lines(t).is_empty())
                })
                .count();
            if stopped_at.contains(&e.exercise.name.as_str()) {
                State::ToDo
            } else if !stopped_at.is_empty() && stopped_at.len() == telling {
                // every failing test that tells stopped at another exercise's todo!(): that
                // one comes first
                State::Waiting(stopped_at[0].to_string())
            } else {
                State::Failing(failed)
            }
        })
        .collect()
}

/// The test target that holds each exercise's own tests (by manifest index): the map's, or
/// else the handout target named after its chapter (`ch02_…`).
#[must_use]
pub fn targets_of(manifest: &Manifest, map: &[Group]) -> Vec<Option<String>> {
    manifest
        .entries
        .iter()
        .map(|e| {
            let prefix = e.exercise.test_prefix();
            map.iter()
                .flat_map(|g| &g.tests)
                .filter_map(|t| t.split_once("::"))
                .find(|(_, name)| test_name(name).starts_with(&prefix))
                .map(|(target, _)| target.to_string())
                .or_else(|| {
                    let binary = whitted_syllabus::chapter(e.chapter)?.binary;
                    manifest
                        .handout
                        .tests
                        .iter()
                        .find(|t| *t == binary)
                        .cloned()
                })
        })
        .collect()
}

/// The exercises' states at the last check, kept by exercise name (`.whitted/progress.json`).
#[must_use]
pub fn saved_states(root: &Path, manifest: &Manifest) -> Vec<State> {
    let saved: BTreeMap<String, String> =
        std::fs::read_to_string(root.join(STATE_DIR).join("progress.json"))
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok())
            .unwrap_or_default();
    manifest
        .entries
        .iter()
        .map(|e| {
            saved
                .get(&e.exercise.name)
                .map_or(State::Unknown, |w| State::from_word(w))
        })
        .collect()
}

/// Keeps the states of a complete check for the next one.
pub fn save_states(root: &Path, manifest: &Manifest, states: &[State]) -> Result<(), ToolError> {
    let saved: BTreeMap<&str, String> = manifest
        .entries
        .iter()
        .zip(states)
        .filter(|(_, s)| **s != State::Unknown)
        .map(|(e, s)| (e.exercise.name.as_str(), s.word()))
        .collect();
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = serde_json::to_string_pretty(&saved)
        .map_err(|e| ToolError::Cargo(format!("cannot write the progress: {e}")))?;
    crate::files::write_file(&dir.join("progress.json"), text.as_bytes())
}

/// Colours for a terminal: none when stdout is not one, or `NO_COLOR` is set.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    on: bool,
}

impl Style {
    /// Colour when stdout is a terminal and `NO_COLOR` is unset or empty.
    #[must_use]
    pub fn detect() -> Self {
        Self::choose(
            std::io::stdout().is_terminal(),
            std::env::var_os("NO_COLOR").as_deref(),
        )
    }

    /// Colour on a terminal, unless `NO_COLOR` holds something (<https://no-color.org>).
    #[must_use]
    pub fn choose(terminal: bool, no_color: Option<&std::ffi::OsStr>) -> Self {
        Self {
            on: terminal && no_color.is_none_or(|v| v.is_empty()),
        }
    }

    /// No colour at all.
    #[must_use]
    pub fn plain() -> Self {
        Self { on: false }
    }

    fn paint(self, code: &str, text: &str) -> String {
        if self.on {
            format!("\x1b[{code}m{text}\x1b[0m")
        } else {
            text.to_string()
        }
    }

    /// Green.
    #[must_use]
    pub fn good(self, text: &str) -> String {
        self.paint("32", text)
    }

    /// Red.
    #[must_use]
    pub fn bad(self, text: &str) -> String {
        self.paint("31", text)
    }

    /// Bold.
    #[must_use]
    pub fn strong(self, text: &str) -> String {
        self.paint("1", text)
    }
}

/// A bar of `width` cells, `done` of `total` filled.
#[must_use]
pub fn bar(done: usize, total: usize, width: usize) -> String {
    let filled = (done * width).checked_div(total).unwrap_or(0);
    format!("[{}{}]", "#".repeat(filled), "-".repeat(width - filled))
}

/// The progress of every chapter: exercises done with a bar, and a summary line.
#[must_use]
pub fn progress(manifest: &Manifest, states: &[State], style: Style) -> String {
    let total = states.len();
    let done = states.iter().filter(|s| **s == State::Done).count();
    let mut out = format!(
        "{} — {done} of {total} exercises done\n",
        style.strong("progress")
    );
    // the widest title, in characters: the bars line up whatever the titles
    let title_w = whitted_syllabus::CHAPTERS
        .iter()
        .map(|c| c.title.chars().count())
        .max()
        .unwrap_or(0);
    for chapter in &whitted_syllabus::CHAPTERS {
        let (number, title) = (chapter.number, chapter.title);
        let of: Vec<usize> = (0..total)
            .filter(|&i| manifest.entries[i].chapter == number)
            .collect();
        if of.is_empty() {
            continue;
        }
        let d = of.iter().filter(|&&i| states[i] == State::Done).count();
        let line = format!(
            "  chapter {number}  {title:<title_w$}  {} {d:>2}/{}",
            bar(d, of.len(), 20),
            of.len()
        );
        out += &if d == of.len() {
            style.good(&line)
        } else {
            line
        };
        out.push('\n');
    }
    out
}

/// The verdict on exercise `index`: its state, the notes' formula, each of its failing tests
/// with its message, and where to write it.
#[must_use]
pub fn verdict(
    manifest: &Manifest,
    run: &TestRun,
    states: &[State],
    index: usize,
    style: Style,
    root: Option<&Path>,
) -> String {
    let e = &manifest.entries[index];
    let x = &e.exercise;
    let state = &states[index];
    let mark = match state {
        State::Done => style.good("✓"),
        _ => style.bad("✗"),
    };
    let how = match state {
        State::ToDo => "not written yet".to_string(),
        State::Failing(f) => {
            let own = run
                .outcomes
                .keys()
                .filter(|n| test_name(n).starts_with(&x.test_prefix()))
                .count();
            format!("{} of its {own} tests fail", f.len())
        }
        State::Waiting(name) => format!(
            "its tests wait for exercise {} ({name})",
            manifest.display(name)
        ),
        State::NoTests => "it has no test in the handout: tell your instructor".into(),
        State::Done => "done".into(),
        State::Unknown => "not checked".into(),
    };
    let mut out = format!(
        "{mark} {} — {} ({}, {} point{}): {how}\n",
        style.strong(&format!("exercise {}", x.id)),
        x.title,
        e.function,
        x.points,
        if x.points == 1 { "" } else { "s" }
    );
    out += &format!("  the notes, \"{}\": {}\n", e.section, e.formula);
    let prefix = x.test_prefix();
    let failing = telling_order(x, run);
    // a body not written fails every test the same way: one of them says so
    let shown = if *state == State::ToDo {
        1
    } else {
        failing.len()
    };
    for name in failing.iter().take(shown) {
        out += &format!("  {} {}\n", style.bad("failing:"), test_name(name));
        let text = run.failures.get(*name).map_or("", String::as_str);
        for line in message_lines(text).into_iter().take(10) {
            out += &format!("    {line}\n");
        }
    }
    if failing.len() > shown {
        out += &format!(
            "  … and {} more of its tests (`cargo test -p {} {prefix}` runs them all)\n",
            failing.len() - shown,
            layout::CORE_PACKAGE
        );
    }
    out += &format!(
        "  write it in {}; `{COMMAND} hint` gives a hint\n",
        match root.and_then(|r| place(r, &x.name)) {
            Some((file, line)) => format!("{}:{line} ({})", file.display(), e.function),
            None => e.function.clone(),
        }
    );
    out
}

/// The failing tests of exercise `x` in `run`, the most telling first: the manifest's
/// `first_check`, then those whose message shows a value (a digit: what was computed and what
/// was expected), then the others, each group in name order.
#[must_use]
pub fn telling_order<'r>(x: &crate::manifest::Exercise, run: &'r TestRun) -> Vec<&'r String> {
    let prefix = x.test_prefix();
    let mut failing: Vec<&String> = run
        .outcomes
        .iter()
        .filter(|(n, o)| test_name(n).starts_with(&prefix) && **o == TestOutcome::Failed)
        .map(|(n, _)| n)
        .collect();
    let rank = |name: &String| {
        let first = x
            .first_check
            .as_ref()
            .is_some_and(|c| test_name(name).strip_prefix(&prefix) == Some(c.as_str()));
        let message = run.failures.get(name).map_or("", String::as_str);
        let valued = message_lines(message)
            .iter()
            .skip(1) // the panic's place, whose line number is not a value
            .any(|l| l.chars().any(|c| c.is_ascii_digit()));
        (!first, !valued)
    };
    failing.sort_by_key(|name| rank(name));
    failing
}

/// Where the student writes the exercise named `name`: the file (relative to `root`) and line
/// of its `// BEGIN SOLUTION name` marker, searched in the renderer's sources.
#[must_use]
pub fn place(root: &Path, name: &str) -> Option<(PathBuf, usize)> {
    let marker = format!("{} {name}", layout::BEGIN);
    let mut stack = vec![root.join(layout::core_src())];
    while let Some(dir) = stack.pop() {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(&dir)
            .ok()?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs")
                && let Ok(text) = std::fs::read_to_string(&path)
                && let Some(n) = text.lines().position(|l| l.trim() == marker)
            {
                let file = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
                return Some((file, n + 1));
            }
        }
    }
    None
}

/// The lines of a failed test's output worth showing: the panic's place and message, without
/// the notes on backtraces (the first panic of a test process prints `note: run with
/// RUST_BACKTRACE=1 …`, in whichever test panicked first: it would come and go).
#[must_use]
pub fn message_lines(text: &str) -> Vec<&str> {
    text.lines()
        .filter(|l| {
            let backtrace_note = l.starts_with("note: ") && l.contains("RUST_BACKTRACE");
            !l.trim().is_empty() && !backtrace_note
        })
        .collect()
}

/// The hint levels shown so far, by exercise name (`.whitted/hints.json`).
pub fn hints_shown(root: &Path) -> BTreeMap<String, usize> {
    std::fs::read_to_string(root.join(STATE_DIR).join("hints.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_default()
}

/// Shows the next hint of exercise `index` and remembers it; once all are shown, shows them
/// all again.
pub fn next_hint(root: &Path, manifest: &Manifest, index: usize) -> Result<String, ToolError> {
    let e: &Entry = &manifest.entries[index];
    let hints = &e.exercise.hints;
    let mut shown = hints_shown(root);
    let level = shown.get(&e.exercise.name).copied().unwrap_or(0);
    let now = (level + 1).min(hints.len());
    shown.insert(e.exercise.name.clone(), now);
    let mut out = format!(
        "exercise {} — {} ({}):\n",
        e.exercise.id, e.exercise.title, e.function
    );
    for (i, h) in hints.iter().take(now).enumerate() {
        out += &format!("  hint {} of {}: {h}\n", i + 1, hints.len());
    }
    if now < hints.len() {
        out += "  (ask again for the next one)\n";
    }
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = serde_json::to_string_pretty(&shown)
        .map_err(|e| ToolError::Cargo(format!("cannot write the hints' state: {e}")))?;
    crate::files::write_file(&dir.join("hints.json"), text.as_bytes())?;
    Ok(out)
}

/// The list of every exercise with its state and points, aligned, and a summary line.
#[must_use]
pub fn list(manifest: &Manifest, states: &[State], style: Style) -> String {
    let width = |f: &dyn Fn(&Entry) -> usize| manifest.entries.iter().map(f).max().unwrap_or(0);
    let id_w = width(&|e| e.exercise.id.chars().count());
    let title_w = width(&|e| e.exercise.title.chars().count());
    let fn_w = width(&|e| e.function.chars().count());
    let words: Vec<String> = states
        .iter()
        .map(|s| match s {
            State::Waiting(name) => format!("waits for {}", manifest.display(name)),
            s => s.word(),
        })
        .collect();
    let state_w = words.iter().map(|w| w.chars().count()).max().unwrap_or(0);
    let mut out = String::new();
    let mut chapter = 0;
    for ((e, s), word) in manifest.entries.iter().zip(states).zip(&words) {
        if e.chapter != chapter {
            chapter = e.chapter;
            out += &format!(
                "chapter {chapter} — {}\n",
                whitted_syllabus::chapter(chapter).map_or("", |c| c.title)
            );
        }
        let word = format!("{word:<state_w$}");
        let word = match s {
            State::Done => style.good(&word),
            State::Failing(_) | State::NoTests => style.bad(&word),
            _ => word,
        };
        out += &format!(
            "  {:<id_w$}  {word}  {:<title_w$}  {:<fn_w$}  {:>2} pt\n",
            e.exercise.id, e.exercise.title, e.function, e.exercise.points
        );
    }
    let count = |f: &dyn Fn(&State) -> bool| states.iter().filter(|s| f(s)).count();
    let points: u32 = manifest
        .entries
        .iter()
        .zip(states)
        .filter(|(_, s)| **s == State::Done)
        .map(|(e, _)| e.exercise.points)
        .sum();
    let all: u32 = manifest.entries.iter().map(|e| e.exercise.points).sum();
    out += &format!(
        "{} done, {} to do, {} failing, {} waiting for an earlier one; {points} of {all} points\n",
        count(&|s| *s == State::Done),
        count(&|s| *s == State::ToDo),
        count(&|s| matches!(s, State::Failing(_))),
        count(&|s| matches!(s, State::Waiting(_))),
    );
    out
}

/// The exercises that are done in `now` but were not in `before`.
#[must_use]
pub fn newly_done(before: &[State], now: &[State]) -> BTreeSet<usize> {
    (0..now.len())
        .filter(|&i| now[i] == State::Done && before.get(i) != Some(&State::Done))
        .collect()
}

/// A build of the loop: the packages of [`PACKAGES`], cargo's lines shown once it is slow.
pub(crate) fn build(
    root: &Path,
    tests: &[String],
    bins: &[String],
    say: &Say,
) -> Result<Built, ToolError> {
    let started = Instant::now();
    let held: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let showing = AtomicBool::new(false);
    let relay = |line: &str| {
        let line = line.trim_end();
        let worth = [
            "Compiling",
            "Downloading",
            "Downloaded",
            "Updating",
            "Blocking",
        ]
        .iter()
        .any(|w| line.trim_start().starts_with(w));
        if !worth {
            return;
        }
        if showing.load(Ordering::Relaxed) {
            say.status(line);
            return;
        }
        let mut held = held.lock().unwrap_or_else(|p| p.into_inner());
        held.push(line.to_string());
        if started.elapsed() > QUIET_BUILD {
            showing.store(true, Ordering::Relaxed);
            say.status(
                "  compiling (a fresh handout's first build compiles the renderer's dependencies \
                 too: a minute or two; after that a save takes seconds)",
            );
            for l in held.drain(..) {
                say.status(&l);
            }
        }
    };
    Build {
        project: root,
        packages: &PACKAGES,
        tests,
        bins,
        // the test profile for binaries too: cargo compiles the derive macros once per
        // profile, and the tests use this one
        profile: Some("test"),
        features: &[],
        target_dir: None,
        debug_info: true,
        locked: false,
        stderr: Stderr::Lines(&relay),
        wrapper: None,
    }
    .run()
}

/// Where `learn` writes what it is doing: the report on stdout (when it is wanted), progress
/// lines on stderr.
pub(crate) struct Say {
    /// Whether the report is printed.
    pub(crate) report: bool,
}

impl Say {
    /// Writes a progress line on stderr.
    fn status(&self, line: &str) {
        let mut err = std::io::stderr().lock();
        let _ = writeln!(err, "{line}");
    }

    /// Writes part of the report on stdout, now.
    fn report(&self, text: &str) {
        if !self.report {
            return;
        }
        let mut out = std::io::stdout().lock();
        let _ = out.write_all(text.as_bytes());
        let _ = out.flush();
    }
}

/// Runs the test executable `exe` of the test target `target` in `dir` as every check does:
/// all its tests, within [`TEST_TIME_LIMIT`], without `WHITTED_BLESS` (no golden image is
/// rewritten) and with RUST_BACKTRACE=0 (the runner's: a student's RUST_BACKTRACE=1 would put
/// a stack in every message).
pub fn run_tests(target: &str, exe: &Path, dir: &Path) -> Result<TestRun, ToolError> {
    cargo::Run {
        target,
        exe,
        dir,
        args: &[],
        env: &[],
        env_remove: &["WHITTED_BLESS"],
        log: None,
        timeout: TEST_TIME_LIMIT,
    }
    .run()
}

/// What one check found.
pub struct Checked {
    /// The test runs.
    pub run: TestRun,
    /// Every exercise's state.
    pub states: Vec<State>,
}

/// Builds and runs the test targets `targets` into `run`; `false` when they did not build (the
/// error is in `run`).
fn check_targets(
    root: &Path,
    targets: &[String],
    run: &mut TestRun,
    say: &Say,
) -> Result<bool, ToolError> {
    let built = build(root, targets, &[], say)?;
    if !built.success {
        let rendered = built
            .errors
            .first()
            .map_or_else(|| built.stderr.clone(), |d| d.rendered.clone());
        run.build_error = Some((built.first_error(), rendered));
        return Ok(false);
    }
    for target in targets {
        let exe = built.executables.get(target).ok_or_else(|| {
            ToolError::Cargo(format!(
                "cargo built no test executable for {}",
                layout::core_test_target(root, target).display()
            ))
        })?;
        let result = run_tests(target, exe, &root.join(layout::CORE))?;
        if let Some(why) = &result.unfinished {
            return Err(ToolError::Cargo(format!(
                "the tests of {} did not finish: {why}",
                layout::core_test_target(root, target).display()
            )));
        }
        run.merge(result);
    }
    Ok(true)
}

/// One check (see the module's documentation): the verdict, printed as soon as it is known,
/// then (with `draw`) the picture of the newest chapter the code can draw, then the progress.
/// The report is printed only with `report`; the lines saying what is being checked go to
/// stderr either way. `known` holds the states of the last check.
pub fn check(
    root: &Path,
    manifest: &Manifest,
    known: &[State],
    style: Style,
    report: bool,
    draw: bool,
) -> Result<Checked, ToolError> {
    let say = Say { report };
    let map = map::load_map(root, manifest).unwrap_or_default();
    let target_of = targets_of(manifest, &map);
    let mut run = TestRun::default();
    let state_now = |run: &TestRun, i: usize| -> State {
        let fresh = states(manifest, run);
        match &fresh[i] {
            State::Unknown => known.get(i).cloned().unwrap_or(State::Unknown),
            s => s.clone(),
        }
    };
    // 0. what was saved since the last check comes first: its targets, then its verdict
    let regions = crate::changes::regions(root);
    let touched = crate::changes::touched(manifest, &crate::changes::saved(root), &regions);
    let mut first_targets: Vec<String> = touched
        .iter()
        .filter_map(|&i| target_of[i].clone())
        .collect();
    first_targets.sort();
    first_targets.dedup();
    first_targets.retain(|t| manifest.handout.tests.contains(t));
    if !first_targets.is_empty() {
        let ids: Vec<&str> = touched
            .iter()
            .map(|&i| manifest.entries[i].exercise.id.as_str())
            .collect();
        say.status(&format!(
            "checking what you changed: exercise {} …",
            ids.join(", ")
        ));
        if !check_targets(root, &first_targets, &mut run, &say)? {
            say.report(&build_failure(&run, style));
            return Ok(Checked {
                states: states(manifest, &run),
                run,
            });
        }
    }
    let mut shown: Option<usize> = None;
    let fresh = states(manifest, &run);
    for &i in &touched {
        let x = &manifest.entries[i].exercise;
        if fresh[i] == State::Done && known.get(i) != Some(&State::Done) {
            say.report(&style.good(&format!(
                "✓ exercise {} — {} ({}) passes: all its tests pass\n",
                x.id, x.title, manifest.entries[i].function
            )));
        }
    }
    // a changed exercise that fails: its verdict now, whatever comes before it
    if let Some(&i) = touched
        .iter()
        .find(|&&i| matches!(fresh[i], State::Failing(_)))
    {
        say.report(&verdict(manifest, &run, &fresh, i, style, Some(root)));
        shown = Some(i);
    }
    // 1. the verdict: the targets of the first exercises not done, one at a time
    while shown.is_none() {
        let next = (0..manifest.entries.len()).find(|&i| state_now(&run, i) != State::Done);
        let Some(next) = next else { break };
        let target = target_of[next].clone();
        match target {
            Some(t) if !run.targets.contains(&t) => {
                say.status(&format!(
                    "checking exercise {} ({}) …",
                    manifest.entries[next].exercise.id,
                    layout::core_test_target(root, &t).display()
                ));
                if !check_targets(root, &[t], &mut run, &say)? {
                    say.report(&build_failure(&run, style));
                    return Ok(Checked {
                        states: states(manifest, &run),
                        run,
                    });
                }
            }
            _ => {
                let fresh = states(manifest, &run);
                say.report(&verdict(manifest, &run, &fresh, next, style, Some(root)));
                shown = Some(next);
                break;
            }
        }
    }
    // the picture, before the other chapters' tests: what the student looks at next
    if draw {
        let now: Vec<State> = (0..manifest.entries.len())
            .map(|i| state_now(&run, i))
            .collect();
        say.report(&crate::picture::report(
            root, manifest, known, &now, shown, style,
        ));
    }
    // 2. the progress: every target not run yet
    let rest: Vec<String> = manifest
        .handout
        .tests
        .iter()
        .filter(|t| !run.targets.contains(*t))
        .cloned()
        .collect();
    if !rest.is_empty() {
        say.status(&format!("checking the other tests ({}) …", rest.join(", ")));
        if !check_targets(root, &rest, &mut run, &say)? {
            say.report(&build_failure(&run, style));
            return Ok(Checked {
                states: states(manifest, &run),
                run,
            });
        }
    }
    let all = states(manifest, &run);
    let next = all.iter().position(|s| *s != State::Done);
    let mut out = String::new();
    match (next, shown) {
        (None, _) => {
            out += &style.good(&format!(
                "✓ all {} exercises pass: the whole road of one pixel is written\n",
                all.len()
            ));
        }
        (Some(n), Some(s)) if n == s => {}
        (Some(n), _) => {
            if shown.is_some() {
                let why = if known.get(n) == Some(&State::Done) {
                    "passed at the last check and fails now, so it comes first"
                } else {
                    "is the first exercise not done"
                };
                out += &format!(
                    "\nnote: exercise {} {why}:\n",
                    manifest.entries[n].exercise.id
                );
            }
            out += &verdict(manifest, &run, &all, n, style, Some(root));
        }
    }
    out.push('\n');
    out += &progress(manifest, &all, style);
    say.report(&out);
    save_states(root, manifest, &all)?;
    crate::changes::save(root, &regions)?;
    Ok(Checked { run, states: all })
}

/// The report of a project that does not build: the first compiler error, whole.
fn build_failure(run: &TestRun, style: Style) -> String {
    let Some((line, rendered)) = &run.build_error else {
        return String::new();
    };
    format!(
        "{} your code does not compile yet, so no test ran: {line}\n\n{}\n(`{COMMAND} hint` gives hints and `{COMMAND} list` lists the exercises, even now)\n",
        style.bad("✗"),
        rendered.trim_end()
    )
}

/// Whether a changed file matters to the tests: not an editor's backup or swap file.
#[must_use]
pub fn is_source_change(path: &Path) -> bool {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    !(name.ends_with('~')
        || name.starts_with(".#")
        || name.ends_with(".swp")
        || name.ends_with(".swx")
        || name == "4913") // vim's probe file
}

/// The directories `watch` watches, relative to the project's root.
#[must_use]
pub fn watched() -> [PathBuf; 4] {
    [
        layout::core_src(),
        layout::core_tests(),
        PathBuf::from("chapters"),
        PathBuf::from("scenes"),
    ]
}

/// Each file under the watched directories with its modification time and size: what a save
/// changes. (The file watcher also reports files being read, as the compiler reads them; a
/// rerun happens only when this snapshot differs.)
#[must_use]
pub fn snapshot(root: &Path) -> BTreeMap<PathBuf, (std::time::SystemTime, u64)> {
    let mut out = BTreeMap::new();
    let mut stack: Vec<PathBuf> = watched().iter().map(|d| root.join(d)).collect();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let Ok(meta) = entry.metadata() else { continue };
            if meta.is_dir() {
                stack.push(path);
            } else if is_source_change(&path)
                && let Ok(modified) = meta.modified()
            {
                out.insert(path, (modified, meta.len()));
            }
        }
    }
    out
}

/// `learn` itself: one check with its picture; `false` when the code does not compile.
pub fn once(root: &Path, manifest: &Manifest, style: Style) -> Result<bool, ToolError> {
    let known = saved_states(root, manifest);
    let checked = check(root, manifest, &known, style, true, true)?;
    Ok(checked.run.build_error.is_none())
}

/// `whitted learn watch`: a check with its picture, then another after every save (changes
/// under [`watched`], debounced by 300 ms). Stops after `cycles` reruns when
/// given (for scripts and tests), else runs until interrupted.
pub fn watch(
    root: &Path,
    manifest: &Manifest,
    style: Style,
    cycles: Option<usize>,
) -> Result<(), ToolError> {
    use notify_debouncer_mini::notify::RecursiveMode;
    let (tx, rx) = std::sync::mpsc::channel();
    let fail = |e: notify_debouncer_mini::notify::Error| {
        ToolError::Cargo(format!("cannot watch the project's files: {e}"))
    };
    let mut debouncer =
        notify_debouncer_mini::new_debouncer(std::time::Duration::from_millis(300), tx)
            .map_err(fail)?;
    for dir in watched() {
        let path = root.join(dir);
        if path.is_dir() {
            debouncer
                .watcher()
                .watch(&path, RecursiveMode::Recursive)
                .map_err(fail)?;
        }
    }
    let mut files = snapshot(root);
    let mut known = saved_states(root, manifest);
    let mut reruns = 0;
    loop {
        let checked = check(root, manifest, &known, style, true, true)?;
        if checked.run.build_error.is_none() {
            known = checked.states;
        }
        if cycles.is_some_and(|c| reruns >= c) {
            return Ok(());
        }
        println!(
            "\nwatching {} for changes (Ctrl-C to stop)",
            watched()
                .iter()
                .map(|d| format!("{}/", d.display()))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let mut changed = false;
        while !changed {
            match rx.recv() {
                Ok(Ok(events)) if events.iter().any(|e| is_source_change(&e.path)) => {
                    while rx.try_recv().is_ok() {} // one rerun for a burst of saves
                    let now = snapshot(root);
                    changed = now != files; // a save, not a read
                    files = now;
                }
                Ok(Ok(_)) => {}
                Ok(Err(e)) => eprintln!("warning: while watching: {e}"),
                Err(_) => return Ok(()), // the watcher is gone
            }
        }
        reruns += 1;
        println!();
    }
}
