//! PrairieLearn's external grader results (`/grade/results/results.json`), from a [`Report`]:
//! `gradable`, a `score` between 0 and 1, a `message` and `output` for the student, `images`
//! (data URLs of PNGs), and per test `name`, `description` (the formula it checks), `points`,
//! `max_points`, `message` and `output`. A submission that is not a copy of the handout is
//! `gradable: false` with its `format_errors`: it costs the student no attempt. Hidden tests
//! show as in Gradescope: their points, never their names or messages.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use serde_json::{Value, json};

use super::{Report, round2};
use crate::grade::Status;

/// The `results.json` of `report`.
#[must_use]
pub fn results(report: &Report) -> Value {
    if let Some(why) = &report.ungradable {
        return json!({
            "gradable": false,
            "format_errors": [why],
            "message": report.output,
        });
    }
    let score = if report.max > 0.0 {
        (report.score / report.max).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let tests: Vec<Value> = report
        .tests
        .iter()
        .filter(|t| t.listed())
        .map(|t| {
            json!({
                "name": t.name,
                "description": if t.hidden { String::new() } else { t.formula.clone() },
                "points": round2(t.score),
                "max_points": round2(t.max),
                "message": if t.status == Status::Passed { "passed" } else { t.status.word() },
                "output": t.output,
            })
        })
        .collect();
    json!({
        "gradable": true,
        "score": (score * 10_000.0).round() / 10_000.0,
        "message": format!(
            "{} / {} points",
            crate::report::points(report.score),
            crate::report::points(report.max)
        ),
        "output": report.output,
        "images": images(report),
        "tests": tests,
    })
}

/// The report's pictures as PrairieLearn's `images`: `{label, url}` with a PNG data URL.
fn images(report: &Report) -> Vec<Value> {
    report
        .images
        .iter()
        .map(|i| {
            json!({
                "label": i.label,
                "url": format!("data:image/png;base64,{}", base64(&i.png)),
            })
        })
        .collect()
}

/// Standard base64 with padding (RFC 4648), as a data URL carries it.
#[must_use]
pub fn base64(bytes: &[u8]) -> String {
    use base64::Engine;
    base64::engine::general_purpose::STANDARD.encode(bytes)
}
