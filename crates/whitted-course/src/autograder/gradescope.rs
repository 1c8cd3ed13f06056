//! Gradescope's `results.json`, from a [`Report`]: the total `score`, `execution_time`, the
//! `output` students read (Markdown, `output_format: "md"`: what the tests and the grader said
//! stands verbatim in code blocks), `visibility` and `stdout_visibility` (the
//! grader's own output stays the instructor's), `extra_data`, the opt-in `leaderboard`, and
//! per test `name`, `number` (the exercise's id), `score`, `max_score`, `status`, `output`,
//! `tags` (chapter, exercise) and `visibility` (hidden tests: the course's setting, by default
//! after the due date). A submission that could not be graded gets a score of 0 and the
//! reason as its output.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use serde_json::{Value, json};

use super::{Report, round2};
use crate::grade::Status;

/// The `results.json` of `report`.
#[must_use]
pub fn results(report: &Report) -> Value {
    let tests: Vec<Value> = report
        .tests
        .iter()
        .filter(|t| t.listed())
        .map(|t| {
            json!({
                "name": t.name,
                "number": t.number,
                "score": round2(t.score),
                "max_score": round2(t.max),
                "status": if t.status == Status::Passed { "passed" } else { "failed" },
                "output": markdown(&t.output),
                "output_format": "md",
                "tags": t.tags,
                "visibility": if t.hidden {
                    report.settings.hidden_visibility.as_str()
                } else {
                    "visible"
                },
            })
        })
        .collect();
    let mut out = json!({
        "score": round2(report.score),
        "execution_time": report.execution_time.round() as u64,
        "output": markdown(&report.output),
        "output_format": "md",
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "extra_data": {
            "student": report.student,
            "max": round2(report.max),
            "graded": report.ungradable.is_none(),
        },
        "tests": tests,
    });
    if !report.leaderboard.is_empty() {
        out["leaderboard"] = report
            .leaderboard
            .iter()
            .map(|b| json!({"name": b.name, "value": b.value, "order": b.order}))
            .collect();
    }
    out
}

/// `text` for Gradescope's Markdown: verbatim, in a fenced code block whose fence no line of
/// the text can close (empty text stays empty).
#[must_use]
pub fn markdown(text: &str) -> String {
    let text = text.trim_end();
    if text.is_empty() {
        return String::new();
    }
    let longest = text
        .lines()
        .map(|l| l.trim_start().chars().take_while(|&c| c == '`').count())
        .max()
        .unwrap_or(0);
    let fence = "`".repeat(longest.max(2) + 1);
    format!("{fence}text\n{text}\n{fence}\n")
}
