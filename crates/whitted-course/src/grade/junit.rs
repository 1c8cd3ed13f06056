//! Reading nextest's JUnit report: each test's status, the exercise its name says, and why it
//! failed in a line.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::{Status, TestResult};
use crate::ToolError;
use crate::cargo::test_name;
use crate::manifest::Manifest;

/// The results in a JUnit report of nextest.
pub fn parse_junit(
    text: &str,
    manifest: &Manifest,
    hidden: &[String],
) -> Result<Vec<TestResult>, ToolError> {
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
                    (Status::Failed, panic_message(body))
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
            message,
        });
    }
    out.sort_by(|a, b| (&a.target, &a.name).cmp(&(&b.target, &b.name)));
    Ok(out)
}

/// The longest message a report quotes, in characters.
pub const MESSAGE_CHARS: usize = 400;

/// The message of a panic in a test's output: the lines after `panicked at …:`, up to the
/// backtrace note, at most three, at most [`MESSAGE_CHARS`] characters.
#[must_use]
pub fn panic_message(output: &str) -> String {
    let mut lines = output.lines();
    if !lines.by_ref().any(|l| l.contains("panicked at")) {
        let first = output.lines().next().unwrap_or("failed").trim();
        return first.chars().take(MESSAGE_CHARS).collect();
    }
    let message: Vec<&str> = lines
        .take_while(|l| !l.starts_with("note:") && !l.starts_with("stack backtrace"))
        .filter(|l| !l.trim().is_empty())
        .take(3)
        .collect();
    let mut text = message.join(" / ");
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
