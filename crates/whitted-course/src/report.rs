//! The reports of `whitted grade`: a table per chapter for the terminal, Gradescope's
//! `results.json` and JUnit XML (both written by the platforms' adapters of
//! [`crate::autograder`], from its one report), and gradebook CSV rows.
//!
//! Every point is explained: each exercise's line gives its tests passed and, for each failed
//! one, its first message and the formula it checks. Hidden tests show in the instructor's
//! reports (the table, JUnit, CSV) by name; in Gradescope's file, which students read, a
//! hidden test is only "exercise 2.3, hidden test 1" with its points and whether it passed —
//! never its name, message or code.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::autograder::codegrade::Audience;
use super::autograder::{Report, Settings};
use super::grade::{Grade, Status, TestResult};
use super::manifest::Manifest;

/// Points with at most two decimals, without trailing zeros.
#[must_use]
pub fn points(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// The terminal report: per chapter, the points, the tests passed and failed, how the
/// student's picture compares with the book's, and each exercise that lost points with its
/// failures and, for the one the chapter's ray trees point at, the first wrong number.
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
    out += &format!("  {}\n", grade.judging.line());
    for note in &grade.notes {
        out += &format!("  ! {note}\n");
    }
    let explained = grade.explained(manifest);
    let indented =
        |lines: &str, by: &str| -> String { lines.lines().map(|l| format!("{by}{l}\n")).collect() };
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
        if let Some(road) = grade.road(manifest, c) {
            out += &format!("  {}\n", road.line());
        }
        let told = explained.iter().find(|x| x.chapter == c);
        if let Some(x) = told {
            out += &format!("  picture: {}\n", x.picture_line);
            if let Some((None, lines)) = &x.first_wrong {
                out += &indented(lines, "");
            }
        }
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
            if let Some(known) = &e.known {
                out += &format!("      a known mistake: this looks like {known}\n");
            }
            if let Some((Some(at), lines)) = told.and_then(|x| x.first_wrong.as_ref())
                && *at == e.entry
            {
                out += &indented(lines, "    ");
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

/// Gradescope's `results.json` ([`crate::autograder::gradescope`]), shown with the default
/// settings.
#[must_use]
pub fn gradescope(grade: &Grade, manifest: &Manifest) -> serde_json::Value {
    let report = Report::new(grade, manifest, &Settings::default());
    crate::autograder::gradescope::results(&report)
}

/// The instructor's JUnit XML ([`crate::autograder::codegrade::junit`]): a test suite per
/// chapter, a test case per test (named by its exercise), its failure with the message.
#[must_use]
pub fn junit(grade: &Grade, manifest: &Manifest) -> String {
    let report = Report::new(grade, manifest, &Settings::default());
    crate::autograder::codegrade::junit(&report, &grade.chapters, Audience::Instructor)
}

/// The gradebook's header: student, then [`score_columns`].
#[must_use]
pub fn csv_header(manifest: &Manifest, chapters: &[u8]) -> String {
    let mut cols = vec!["student".to_string()];
    cols.extend(score_columns(manifest, chapters));
    cols.join(",")
}

/// The score's columns of a gradebook: total, maximum, each graded chapter, each exercise.
#[must_use]
pub fn score_columns(manifest: &Manifest, chapters: &[u8]) -> Vec<String> {
    let mut cols = vec!["total".to_string(), "max".into()];
    cols.extend(chapters.iter().map(|c| format!("chapter {c}")));
    cols.extend(
        manifest
            .entries
            .iter()
            .filter(|e| chapters.contains(&e.chapter))
            .map(|e| format!("ex {}", e.exercise.id)),
    );
    cols
}

/// One gradebook row, in the columns of [`csv_header`].
#[must_use]
pub fn csv_row(grade: &Grade, manifest: &Manifest) -> String {
    let quoted = if grade.student.contains([',', '"', '\n']) {
        format!("\"{}\"", grade.student.replace('"', "\"\""))
    } else {
        grade.student.clone()
    };
    let mut cols = vec![quoted];
    cols.extend(score_cells(grade, manifest));
    cols.join(",")
}

/// A grade's cells in the columns of [`score_columns`].
#[must_use]
pub fn score_cells(grade: &Grade, manifest: &Manifest) -> Vec<String> {
    let mut cols = vec![points(grade.score()), points(grade.max())];
    cols.extend(
        grade
            .chapters
            .iter()
            .map(|&c| points(grade.chapter(manifest, c).0)),
    );
    cols.extend(grade.exercises.iter().map(|e| points(e.score)));
    cols
}
