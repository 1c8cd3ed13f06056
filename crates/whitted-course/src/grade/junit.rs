//! Reading nextest's JUnit report: each test's status, the exercise its name says, and why it
//! failed in a line.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::test_result::{Status, TestResult};
use crate::ToolError;
use crate::cargo::test_name;
use crate::manifest::Manifest;

/// The results in a JUnit report of nextest.
pub fn parse_junit(
    text: &str,
    manifest: &Manifest,
    hidden: &[String],
) -> Result<Vec<TestResult>, ToolError> {
    // the runner cleans what a test prints; a report written without it may still hold a
    // character XML forbids (U+FFFE), which must not make a submission ungradable
    let safe;
    let text = if roxmltree::Document::parse(text).is_ok() {
        text
    } else {
        safe = super::clean::xml_safe(text);
        &safe
    };
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| ToolError::Cargo(format!("cannot read nextest's JUnit report: {e}")))?;
    let mut out = Vec::new();
    for case in doc.descendants().filter(|n| n.has_tag_name("testcase")) {
        // the name within its target, module path and all (`sphere::ex_hit_sphere_…`)
        let name = case.attribute("name").unwrap_or("").to_string();
        let class = case.attribute("classname").unwrap_or("");
        let target = class.rsplit("::").next().unwrap_or(class).to_string();
        let failure = case
            .children()
            .find(|n| n.has_tag_name("failure") || n.has_tag_name("error"));
        let mut values = String::new();
        let (status, message) = match failure {
            None => (Status::Passed, String::new()),
            Some(f) => {
                let kind = f.attribute("type").unwrap_or("");
                let body = f.text().unwrap_or("");
                if kind.contains("timeout") {
                    (
                        Status::TimedOut,
                        "stopped at the time limit: an endless loop, or far too slow".into(),
                    )
                } else if kind.contains("abort") || kind.contains("signal") {
                    let what = f.attribute("message").unwrap_or(kind);
                    (
                        Status::Crashed,
                        format!("the test's process died ({what}): a stack overflow or an abort"),
                    )
                } else {
                    // libtest captures the test's output (the runner asks it to) and prints
                    // the panic in its list of failures, on stdout: nextest keeps it in
                    // `system-out`
                    let kept = |tag: &str| {
                        case.children()
                            .find(|n| n.has_tag_name(tag))
                            .and_then(|n| n.text())
                            .unwrap_or("")
                    };
                    let all = format!("{body}\n{}\n{}", kept("system-out"), kept("system-err"));
                    let stopped = all
                        .lines()
                        .find_map(|l| l.strip_prefix(super::clock::STOPPED));
                    let died = all.lines().find_map(|l| l.strip_prefix(SERVER_DIED));
                    match (stopped, died) {
                        // the grader's clock stopped it at its limit
                        (Some(after), _) => (Status::TimedOut, format!("stopped after {after}")),
                        // the judge's word that the server died by a signal
                        (None, Some(what)) => (
                            Status::Crashed,
                            format!(
                                "the student's process died {}: a stack overflow or an abort",
                                what.split(": the test fails").next().unwrap_or(what).trim()
                            ),
                        ),
                        (None, None) => {
                            values = self::values(&all);
                            (Status::Failed, panic_message(&all))
                        }
                    }
                }
            }
        };
        let exercise = manifest.exercise_of_test(test_name(&name));
        let time = case
            .attribute("time")
            .and_then(|t| t.parse::<f64>().ok())
            .unwrap_or(0.0);
        out.push(TestResult {
            time,
            hidden: hidden.contains(&target),
            name,
            target,
            exercise,
            status,
            message: super::clean::clean(&message),
            values,
        });
    }
    out.sort_by(|a, b| (&a.target, &a.name).cmp(&(&b.target, &b.name)));
    Ok(out)
}

/// The longest message a report quotes, in characters.
pub const MESSAGE_CHARS: usize = 400;

/// How each line the judge adds to a test's output begins (the renderer's `judge` module).
const JUDGE_MARK: &str = "whitted judge: ";

/// How the judge's line begins when the student's process died by a signal: the test crashed.
const SERVER_DIED: &str = "whitted judge: the student's process died ";

/// The lines of the first panic's message in a test's output: after its `panicked at …:`
/// line, up to the backtrace's note (or libtest's list of failures), blank ones left out;
/// `None` when nothing panicked.
fn panic_lines(output: &str) -> Option<Vec<&str>> {
    let mut lines = output.lines();
    lines.by_ref().find(|l| l.contains("panicked at"))?;
    Some(
        lines
            .take_while(|l| {
                !l.starts_with("note:") && !l.starts_with("stack backtrace") && *l != "failures:"
            })
            .filter(|l| !l.trim().is_empty())
            .collect(),
    )
}

/// A failed test's message as a known mistake's values are recorded (`chapters/mistakes.json`,
/// [`whitted_learn::known::values_of`]): every line of its panic's message, each without its
/// trailing spaces, joined by `\n`; empty when nothing panicked.
#[must_use]
pub fn values(output: &str) -> String {
    panic_lines(output)
        .unwrap_or_default()
        .iter()
        .map(|l| l.trim_end())
        .collect::<Vec<_>>()
        .join("\n")
}

/// The message of a panic in a test's output: the lines after `panicked at …:`, up to the
/// backtrace note (or libtest's list of failures), at most three, at most [`MESSAGE_CHARS`]
/// characters; else the runner's or the judge's own line ([`super::runner::RUNNER_MARK`],
/// `whitted judge:`), else the first line.
#[must_use]
pub fn panic_message(output: &str) -> String {
    let Some(lines) = panic_lines(output) else {
        let first = output
            .lines()
            .find(|l| l.starts_with(super::runner::RUNNER_MARK) || l.starts_with(JUDGE_MARK))
            .or_else(|| output.lines().next())
            .unwrap_or("failed")
            .trim();
        return first.chars().take(MESSAGE_CHARS).collect();
    };
    let mut text = lines
        .iter()
        .take(3)
        .copied()
        .collect::<Vec<_>>()
        .join(" / ");
    // a report quotes a message, not a test's whole output
    if let Some((cut, _)) = text.char_indices().nth(MESSAGE_CHARS) {
        text.truncate(cut);
        text.push('…');
    }
    if text.starts_with("not yet implemented") {
        format!("not written ({text})")
    } else {
        text
    }
}
