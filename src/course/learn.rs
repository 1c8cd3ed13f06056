//! `whitted learn`: the student's loop — which exercises pass, the next one to write, its
//! failing test and hints, and, while watching, the chapter's image each time an exercise
//! turns green.
//!
//! An exercise is **done** when its own tests (those named `ex2_3_…` for exercise 2.3, in the
//! test targets of the manifest's `[handout] tests`) all pass. The state of every exercise
//! comes from one run of those targets (`cargo test --no-fail-fast`), read from libtest's
//! output: `done`, `to do` (a test stopped at the exercise's `todo!()`), or `failing`.
//! The hints a student has asked for are kept in `.whitted/hints.json` in the project.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use super::manifest::{Entry, Manifest};
use super::prove::{TestOutcome, parse_libtest};
use super::{CHAPTERS, Error};

/// Where `whitted learn` keeps its state and the images it renders, in the project.
pub const STATE_DIR: &str = ".whitted";

/// What one run of the handout's tests said.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TestRun {
    /// Every test's outcome, by name.
    pub outcomes: BTreeMap<String, TestOutcome>,
    /// The output of each failed test (libtest's `---- NAME stdout ----` block).
    pub failures: BTreeMap<String, String>,
    /// The compiler's errors, when the project did not build.
    pub build_errors: Option<String>,
}

/// Where an exercise stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum State {
    /// All its own tests pass.
    Done,
    /// A test stopped at its `todo!()`: not written yet.
    ToDo,
    /// Written, but these of its own tests fail.
    Failing(Vec<String>),
    /// It has no test in the handout's targets (a mistake of the course, not the student's).
    NoTests,
    /// The project does not build, so nothing can be said.
    Unknown,
}

impl State {
    /// A word for the list.
    #[must_use]
    pub fn word(&self) -> &'static str {
        match self {
            State::Done => "done",
            State::ToDo => "to do",
            State::Failing(_) => "failing",
            State::NoTests => "no tests",
            State::Unknown => "?",
        }
    }
}

/// The state of every exercise of `manifest` (in its order) after the test run `run`.
#[must_use]
pub fn states(manifest: &Manifest, run: &TestRun) -> Vec<State> {
    manifest
        .entries
        .iter()
        .map(|e| {
            if run.build_errors.is_some() {
                return State::Unknown;
            }
            let prefix = e.exercise.test_prefix();
            let own: Vec<(&String, &TestOutcome)> = run
                .outcomes
                .iter()
                .filter(|(name, _)| test_name(name).starts_with(&prefix))
                .collect();
            if own.is_empty() {
                return State::NoTests;
            }
            let failed: Vec<String> = own
                .iter()
                .filter(|(_, o)| **o == TestOutcome::Failed)
                .map(|(n, _)| (*n).clone())
                .collect();
            if failed.is_empty() {
                return State::Done;
            }
            let todo = format!("not yet implemented: exercise {}:", e.exercise.id);
            if failed
                .iter()
                .any(|n| run.failures.get(n).is_some_and(|out| out.contains(&todo)))
            {
                State::ToDo
            } else {
                State::Failing(failed)
            }
        })
        .collect()
}

/// A test's own name, without the module path libtest puts before it.
#[must_use]
pub fn test_name(full: &str) -> &str {
    full.rsplit("::").next().unwrap_or(full)
}

/// Runs the handout's test targets of the project at `root` once.
pub fn run_tests(root: &Path, manifest: &Manifest) -> Result<TestRun, Error> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.args(["test", "--no-fail-fast", "--color", "never"]);
    for t in &manifest.handout.tests {
        command.args(["--test", t]);
    }
    let out = command
        .current_dir(root)
        .env_remove("WHITTED_BLESS")
        .env("RUST_BACKTRACE", "0") // the failing line, not the stack, is what a student needs
        .stdin(Stdio::null())
        .output()
        .map_err(|e| Error::Proof(format!("cannot run cargo test: {e}")))?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let outcomes: BTreeMap<String, TestOutcome> = parse_libtest(&stdout).into_iter().collect();
    let build_errors = (outcomes.is_empty() && !out.status.success()).then(|| {
        let errors: Vec<&str> = stderr
            .split("\n\n")
            .filter(|block| block.trim_start().starts_with("error"))
            .take(3)
            .collect();
        if errors.is_empty() {
            stderr.trim().to_string()
        } else {
            errors.join("\n\n")
        }
    });
    Ok(TestRun {
        failures: failure_blocks(&stdout),
        outcomes,
        build_errors,
    })
}

/// libtest's `---- NAME stdout ----` blocks, by test name.
#[must_use]
pub fn failure_blocks(stdout: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    let mut current: Option<(String, String)> = None;
    for line in stdout.lines() {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|l| l.strip_suffix(" stdout ----"))
        {
            if let Some((n, text)) = current.take() {
                out.insert(n, text);
            }
            current = Some((name.to_string(), String::new()));
        } else if line == "failures:" || line.starts_with("test result:") {
            if let Some((n, text)) = current.take() {
                out.insert(n, text);
            }
        } else if let Some((_, text)) = current.as_mut() {
            text.push_str(line);
            text.push('\n');
        }
    }
    if let Some((n, text)) = current {
        out.insert(n, text);
    }
    out
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

/// The progress report: exercises done per chapter with a bar, then the next exercise to
/// write with its first failing test (and, given the project's `root`, its file:line), or the
/// end.
#[must_use]
pub fn report(
    manifest: &Manifest,
    run: &TestRun,
    states: &[State],
    style: Style,
    root: Option<&Path>,
) -> String {
    let mut out = String::new();
    let total = states.len();
    let done = states.iter().filter(|s| **s == State::Done).count();
    if let Some(errors) = &run.build_errors {
        out += &format!(
            "{} the project does not build, so no test ran. The compiler says:\n\n{errors}\n",
            style.bad("✗")
        );
        return out;
    }
    out += &format!(
        "{} — {done} of {total} exercises done\n",
        style.strong("whitted learn")
    );
    for (number, title) in (1u8..).zip(CHAPTERS) {
        let of: Vec<usize> = (0..total)
            .filter(|&i| manifest.entries[i].chapter == number)
            .collect();
        if of.is_empty() {
            continue;
        }
        let d = of.iter().filter(|&&i| states[i] == State::Done).count();
        let line = format!(
            "  chapter {number}  {title:<26} {} {d:>2}/{}",
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
    match states.iter().position(|s| *s != State::Done) {
        None => {
            out += &style.good(&format!(
                "all {total} exercises pass: the whole road of one pixel is written\n"
            ));
        }
        Some(next) => out += &next_exercise(manifest, run, &states[next], next, style, root),
    }
    out
}

/// What to do next: the exercise, where it is, its formula and its first failing test.
fn next_exercise(
    manifest: &Manifest,
    run: &TestRun,
    state: &State,
    index: usize,
    style: Style,
    root: Option<&Path>,
) -> String {
    let e = &manifest.entries[index];
    let x = &e.exercise;
    let mut out = format!(
        "\nnext: {} — {} ({}, {} point{})\n",
        style.strong(&format!("exercise {}", x.id)),
        x.title,
        e.function,
        x.points,
        if x.points == 1 { "" } else { "s" }
    );
    out += &format!("  the notes, \"{}\": {}\n", e.section, e.formula);
    let prefix = x.test_prefix();
    let first_failed = run
        .outcomes
        .iter()
        .filter(|(n, o)| test_name(n).starts_with(&prefix) && **o == TestOutcome::Failed)
        .map(|(n, _)| n)
        .next();
    match (state, first_failed) {
        (State::NoTests, _) => {
            out += &format!(
                "  it has no test named {prefix}… in the handout's tests: tell your instructor\n"
            );
        }
        (_, Some(name)) => {
            out += &format!("  {} {name}\n", style.bad("failing:"));
            let text = run.failures.get(name).map_or("", String::as_str);
            for line in text.lines().filter(|l| !l.trim().is_empty()).take(12) {
                out += &format!("    {line}\n");
            }
        }
        (_, None) => {}
    }
    out += &format!(
        "  write it in {}; `whitted learn hint` gives a hint\n",
        match root.map(|r| super::source::locate(r, &e.function)) {
            Some(Ok(at)) => format!("{}, {}:{}", e.function, at.file.display(), at.line),
            _ => e.function.clone(),
        }
    );
    out
}

/// The hint levels shown so far, by exercise id (`.whitted/hints.json`).
pub fn hints_shown(root: &Path) -> BTreeMap<String, usize> {
    std::fs::read_to_string(root.join(STATE_DIR).join("hints.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_default()
}

/// Shows the next hint of exercise `index` and remembers it; once all are shown, shows them
/// all again.
pub fn next_hint(root: &Path, manifest: &Manifest, index: usize) -> Result<String, Error> {
    let e: &Entry = &manifest.entries[index];
    let hints = &e.exercise.hints;
    let mut shown = hints_shown(root);
    let level = shown.get(&e.exercise.id).copied().unwrap_or(0);
    let now = (level + 1).min(hints.len());
    shown.insert(e.exercise.id.clone(), now);
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
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    let text = serde_json::to_string_pretty(&shown)
        .map_err(|e| Error::Proof(format!("cannot write the hints' state: {e}")))?;
    crate::output::write_file(&dir.join("hints.json"), text.as_bytes())
        .map_err(|e| Error::Proof(e.to_string()))?;
    Ok(out)
}

/// The list of every exercise with its state and points.
#[must_use]
pub fn list(manifest: &Manifest, states: &[State], style: Style) -> String {
    let mut out = String::new();
    let mut chapter = 0;
    for (e, s) in manifest.entries.iter().zip(states) {
        if e.chapter != chapter {
            chapter = e.chapter;
            out += &format!(
                "chapter {chapter} — {}\n",
                CHAPTERS[usize::from(chapter) - 1]
            );
        }
        let word = format!("{:<8}", s.word());
        let word = match s {
            State::Done => style.good(&word),
            State::Failing(_) | State::NoTests => style.bad(&word),
            _ => word,
        };
        out += &format!(
            "  {:<5} {word} {:<40} {:<44} {:>2} pt\n",
            e.exercise.id, e.exercise.title, e.function, e.exercise.points
        );
    }
    out
}

/// The exercises that are done in `now` but were not in `before`.
#[must_use]
pub fn newly_done(before: &[State], now: &[State]) -> BTreeSet<usize> {
    (0..now.len())
        .filter(|&i| now[i] == State::Done && before.get(i) != Some(&State::Done))
        .collect()
}

/// Renders chapter `chapter`'s scene with the project's own chapter binary (built by cargo)
/// into `.whitted/chNN_name.png`; returns the image's path.
pub fn render_chapter(root: &Path, chapter: u8) -> Result<PathBuf, Error> {
    let name = super::handout::chapter_dir(root, chapter);
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    let png = dir.join(format!("{name}.png"));
    let scene = root.join("scenes").join(format!("{name}.toml"));
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.args(["run", "--quiet", "--bin", &name, "--"]);
    if scene.is_file() {
        command.arg(&scene);
    }
    let out = command
        .args(["--quiet", "-o"])
        .arg(&png)
        .current_dir(root)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| Error::Proof(format!("cannot run cargo run --bin {name}: {e}")))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let line = err
            .lines()
            .rev()
            .find(|l| l.starts_with("error"))
            .unwrap_or("the render failed");
        return Err(Error::Proof(format!("chapter {chapter}'s image: {line}")));
    }
    Ok(png)
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

/// The directories `watch` watches.
pub const WATCHED: [&str; 4] = ["src", "tests", "chapters", "scenes"];

/// Each file under the watched directories with its modification time and size: what a save
/// changes. (The file watcher also reports files being read, as the compiler reads them; a
/// rerun happens only when this snapshot differs.)
#[must_use]
pub fn snapshot(root: &Path) -> BTreeMap<PathBuf, (std::time::SystemTime, u64)> {
    let mut out = BTreeMap::new();
    let mut stack: Vec<PathBuf> = WATCHED.iter().map(|d| root.join(d)).collect();
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

/// `whitted learn watch`: reports, then reruns the tests after every save (changes in
/// [`WATCHED`], debounced by 300 ms), and renders the chapter of each exercise that turns
/// green. Stops after `cycles` reruns when given (for scripts and tests), else runs until
/// interrupted.
pub fn watch(
    root: &Path,
    manifest: &Manifest,
    style: Style,
    cycles: Option<usize>,
) -> Result<(), Error> {
    use notify_debouncer_mini::notify::RecursiveMode;
    let (tx, rx) = std::sync::mpsc::channel();
    let fail = |e: notify_debouncer_mini::notify::Error| {
        Error::Proof(format!("cannot watch the project's files: {e}"))
    };
    let mut debouncer =
        notify_debouncer_mini::new_debouncer(std::time::Duration::from_millis(300), tx)
            .map_err(fail)?;
    for dir in WATCHED {
        let path = root.join(dir);
        if path.is_dir() {
            debouncer
                .watcher()
                .watch(&path, RecursiveMode::Recursive)
                .map_err(fail)?;
        }
    }
    let mut files = snapshot(root);
    let run = run_tests(root, manifest)?;
    let mut before = states(manifest, &run);
    print!("{}", report(manifest, &run, &before, style, Some(root)));
    let mut reruns = 0;
    while cycles.is_none_or(|c| reruns < c) {
        println!(
            "\nwatching {} for changes (Ctrl-C to stop)",
            WATCHED.map(|d| format!("{d}/")).join(", ")
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
        let run = run_tests(root, manifest)?;
        let now = states(manifest, &run);
        print!("\n{}", report(manifest, &run, &now, style, Some(root)));
        let chapters: BTreeSet<u8> = newly_done(&before, &now)
            .into_iter()
            .map(|i| manifest.entries[i].chapter)
            .collect();
        for chapter in chapters {
            match render_chapter(root, chapter) {
                Ok(png) => println!(
                    "{} chapter {chapter}'s scene, as your code draws it now: {}",
                    style.good("✓"),
                    png.display()
                ),
                Err(e) => println!("  (no image yet: {e})"),
            }
        }
        before = now;
    }
    Ok(())
}
