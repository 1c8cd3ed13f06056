//! The verdict on one exercise, in words: its state, the notes' formula, its failing tests
//! (the most telling first) with their messages, and the file and line to write it at; or, when
//! the code does not compile, the compiler's first error.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::{Path, PathBuf};

use super::say::COMMAND;
use super::state::{State, message_lines};
use super::style::Style;
use crate::cargo::{TestOutcome, TestRun, test_name};
use crate::layout;
use crate::manifest::Manifest;

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
            "its tests call exercise {} ({name}), which is not done: that one first",
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
    // a known mistake, told by the values its tests print
    if matches!(state, State::Failing(_))
        && let Some(root) = root
    {
        let mistakes = crate::trees::load_mistakes(root);
        let failing = crate::known::failing_values(run, &prefix);
        if let Some(m) = crate::known::recognise(&mistakes, &x.name, &failing) {
            out += &style.bad(&crate::known::line(m));
        }
    }
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

/// The report of a project that does not build: the first compiler error, whole.
pub(super) fn build_failure(run: &TestRun, style: Style) -> String {
    let Some((line, rendered)) = &run.build_error else {
        return String::new();
    };
    format!(
        "{} your code does not compile yet, so no test ran: {line}\n\n{}\n(`{COMMAND} hint` gives hints and `{COMMAND} list` lists the exercises, even now)\n",
        style.bad("✗"),
        rendered.trim_end()
    )
}
