//! The reports of `whitted grade`: a table per chapter for the terminal, Gradescope's
//! `results.json`, JUnit XML, and gradebook CSV rows.
//!
//! Every point is explained: each exercise's line gives its tests passed and, for each failed
//! one, its first message and the formula it checks. Hidden tests show in the instructor's
//! reports (the table, JUnit, CSV) by name; in Gradescope's file, which students read, a
//! hidden test is only "exercise 2.3, hidden test 1" with its points and whether it passed —
//! never its name, message or code.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::grade::{Grade, Status, TestResult};
use super::manifest::Manifest;

/// Points with at most two decimals, without trailing zeros.
#[must_use]
pub fn points(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// The terminal report: per chapter, the points, the tests passed and failed, and each
/// exercise that lost points with its failures.
#[must_use]
pub fn table(grade: &Grade, manifest: &Manifest) -> String {
    let mut out = format!(
        "{}: {} / {} points ({:.0}%), graded in {:.0} s\n",
        grade.student,
        points(grade.score()),
        points(grade.max()),
        100.0 * grade.score() / grade.max().max(1e-9),
        grade.elapsed.as_secs_f64()
    );
    for note in &grade.notes {
        out += &format!("  ! {note}\n");
    }
    for &c in &grade.chapters {
        let (s, m) = grade.chapter(manifest, c);
        let tests: Vec<&TestResult> = grade
            .tests
            .iter()
            .filter(|t| t.exercise.is_some_and(|e| manifest.entries[e].chapter == c))
            .collect();
        let passed = tests.iter().filter(|t| t.status == Status::Passed).count();
        out += &format!(
            "chapter {c}  {:<26} {:>6} / {:<4} points   {passed} passed, {} failed\n",
            crate::syllabus::chapter(c).map_or("", |c| c.title),
            points(s),
            points(m),
            tests.len() - passed
        );
        for e in grade
            .exercises
            .iter()
            .filter(|e| manifest.entries[e.entry].chapter == c)
        {
            if e.score >= e.max && e.note.is_none() {
                continue;
            }
            let entry = &manifest.entries[e.entry];
            out += &format!(
                "  {} {:<40} {:>5} / {:<3} {} of {} tests   {}\n",
                entry.exercise.id,
                entry.exercise.title,
                points(e.score),
                points(e.max),
                e.passed,
                e.total,
                entry.formula
            );
            if let Some(note) = &e.note {
                out += &format!("      note: {note}\n");
            }
            for t in grade
                .tests
                .iter()
                .filter(|t| t.exercise == Some(e.entry) && t.status != Status::Passed)
            {
                let hidden = if t.hidden { " (hidden)" } else { "" };
                out += &format!(
                    "      ✗ {}{hidden}: {}: {}\n",
                    t.name,
                    t.status.word(),
                    t.message
                );
            }
        }
    }
    out
}

/// Each test's share of its exercise's points.
fn test_points(grade: &Grade, manifest: &Manifest, t: &TestResult) -> (f64, f64) {
    let Some(e) = t.exercise else {
        return (0.0, 0.0);
    };
    let total = grade.tests.iter().filter(|u| u.exercise == Some(e)).count();
    let max = f64::from(manifest.entries[e].exercise.points) / total.max(1) as f64;
    let score = if t.status == Status::Passed { max } else { 0.0 };
    (score, max)
}

/// Gradescope's `results.json`: the total `score`, an `output` for the student, and one entry
/// per test with `name`, `score`, `max_score`, `status`, `output` and `visibility`.
#[must_use]
pub fn gradescope(grade: &Grade, manifest: &Manifest) -> serde_json::Value {
    let mut hidden_seen: std::collections::BTreeMap<usize, usize> = Default::default();
    let mut tests = Vec::new();
    for t in &grade.tests {
        let (score, max) = test_points(grade, manifest, t);
        let exercise = t.exercise.map(|e| &manifest.entries[e]);
        let (name, output) = if t.hidden {
            let n = hidden_seen
                .entry(t.exercise.unwrap_or(usize::MAX))
                .or_default();
            *n += 1;
            let id = exercise.map_or("-", |e| e.exercise.id.as_str());
            (
                format!("exercise {id}, hidden test {n}"),
                t.status.word().to_string(),
            )
        } else {
            let title = exercise.map_or(String::new(), |e| {
                format!("{} {} ({}): ", e.exercise.id, e.exercise.title, e.formula)
            });
            let output = if t.status == Status::Passed {
                String::new()
            } else {
                format!("{}: {}", t.status.word(), t.message)
            };
            (format!("{title}{}", t.name), output)
        };
        tests.push(serde_json::json!({
            "name": name,
            "score": round2(score),
            "max_score": round2(max),
            "status": if t.status == Status::Passed { "passed" } else { "failed" },
            "output": output,
            "visibility": "visible",
        }));
    }
    let mut output = String::new();
    for note in &grade.notes {
        output += &format!("{note}\n");
    }
    for e in &grade.exercises {
        if let Some(note) = &e.note {
            output += &format!(
                "exercise {}: {note}\n",
                manifest.entries[e.entry].exercise.id
            );
        }
    }
    serde_json::json!({
        "score": round2(grade.score()),
        "output": output,
        "tests": tests,
    })
}

fn round2(x: f64) -> f64 {
    (x * 100.0).round() / 100.0
}

/// XML text with `& < > " '` escaped.
fn xml(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&apos;")
}

/// JUnit XML: a test suite per chapter, a test case per test (named by its exercise), its
/// failure with the message.
#[must_use]
pub fn junit(grade: &Grade, manifest: &Manifest) -> String {
    let failures = grade
        .tests
        .iter()
        .filter(|t| t.status != Status::Passed)
        .count();
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"whitted grade {}\" tests=\"{}\" failures=\"{failures}\">\n",
        xml(&grade.student),
        grade.tests.len()
    );
    for &c in &grade.chapters {
        let tests: Vec<&TestResult> = grade
            .tests
            .iter()
            .filter(|t| t.exercise.is_some_and(|e| manifest.entries[e].chapter == c))
            .collect();
        let failed = tests.iter().filter(|t| t.status != Status::Passed).count();
        out += &format!(
            "  <testsuite name=\"chapter {c} {}\" tests=\"{}\" failures=\"{failed}\">\n",
            crate::syllabus::chapter(c).map_or("", |c| c.title),
            tests.len()
        );
        for t in tests {
            let e = &manifest.entries[t.exercise.unwrap_or_default()];
            out += &format!(
                "    <testcase name=\"{}\" classname=\"exercise {}\"",
                xml(&t.name),
                xml(&e.exercise.id)
            );
            if t.status == Status::Passed {
                out += "/>\n";
            } else {
                out += &format!(
                    ">\n      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>\n",
                    t.status.word(),
                    xml(&t.message),
                    xml(&format!("{} — formula: {}", t.message, e.formula))
                );
            }
        }
        out += "  </testsuite>\n";
    }
    out += "</testsuites>\n";
    out
}

/// The gradebook's header: student, total, maximum, each graded chapter, each exercise.
#[must_use]
pub fn csv_header(manifest: &Manifest, chapters: &[u8]) -> String {
    let mut cols = vec!["student".to_string(), "total".into(), "max".into()];
    cols.extend(chapters.iter().map(|c| format!("chapter {c}")));
    cols.extend(
        manifest
            .entries
            .iter()
            .filter(|e| chapters.contains(&e.chapter))
            .map(|e| format!("ex {}", e.exercise.id)),
    );
    cols.join(",")
}

/// One gradebook row, in the columns of [`csv_header`].
#[must_use]
pub fn csv_row(grade: &Grade, manifest: &Manifest) -> String {
    let quoted = if grade.student.contains([',', '"', '\n']) {
        format!("\"{}\"", grade.student.replace('"', "\"\""))
    } else {
        grade.student.clone()
    };
    let mut cols = vec![quoted, points(grade.score()), points(grade.max())];
    cols.extend(
        grade
            .chapters
            .iter()
            .map(|&c| points(grade.chapter(manifest, c).0)),
    );
    cols.extend(grade.exercises.iter().map(|e| points(e.score)));
    cols.join(",")
}
