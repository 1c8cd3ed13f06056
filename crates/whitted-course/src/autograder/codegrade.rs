//! JUnit XML from a [`Report`]: what CodeGrade's JUnit step reads, and the instructor's
//! `junit.xml` of `whitted grade`. A test suite per chapter, a test case per test with its
//! `time` and its points (`properties`: `points` earned and `max_points`, whose sum over the
//! report is the course's points exactly), and a `failure` (its status, its message, the first wrong number of the ray trees
//! where they point at its exercise, the formula) for each that did not pass.
//! For the student ([`Audience::Student`]) a hidden test is named as in Gradescope and says
//! only whether it passed; for the instructor it is named and quoted in full.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::Report;
use crate::grade::Status;

/// Who reads the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Audience {
    /// The instructor: every test by name, with its message.
    Instructor,
    /// The student: hidden tests without their names or messages.
    Student,
}

/// XML text with `& < > " '` escaped.
fn xml(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&apos;")
}

/// The `properties` of a test case or a suite (indented by `indent`): the points it earned
/// and the most it carries, in the hundredths every platform shows, so that the maxima of a
/// report add up to the course's points exactly ([`super::share`]).
fn points(indent: &str, earned: f64, max: f64) -> String {
    format!(
        "{indent}<properties>\n{indent}  <property name=\"points\" value=\"{earned:.2}\"/>\n{indent}  <property name=\"max_points\" value=\"{max:.2}\"/>\n{indent}</properties>\n"
    )
}

/// The JUnit XML of `report` for `audience`, its suites the graded `chapters`.
#[must_use]
pub fn junit(report: &Report, chapters: &[u8], audience: Audience) -> String {
    let failures = report
        .tests
        .iter()
        .filter(|t| t.status != Status::Passed)
        .count();
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"whitted grade {}\" tests=\"{}\" failures=\"{failures}\" time=\"{:.3}\">\n",
        xml(&report.student),
        report.tests.len(),
        report.execution_time
    );
    if let Some(why) = &report.ungradable {
        out += &format!(
            "  <testsuite name=\"submission\" tests=\"1\" failures=\"0\" errors=\"1\">\n    <testcase name=\"the submission is graded\" classname=\"submission\">\n      <error type=\"not graded\" message=\"{}\"/>\n    </testcase>\n  </testsuite>\n",
            xml(why)
        );
    }
    for &c in chapters {
        let tests: Vec<_> = report.tests.iter().filter(|t| t.chapter == c).collect();
        let failed = tests.iter().filter(|t| t.status != Status::Passed).count();
        let time: f64 = tests.iter().map(|t| t.time).sum();
        out += &format!(
            "  <testsuite name=\"chapter {c} {}\" tests=\"{}\" failures=\"{failed}\" time=\"{time:.3}\">\n{}",
            crate::syllabus::chapter(c).map_or("", |c| c.title),
            tests.len(),
            points(
                "    ",
                tests.iter().map(|t| t.score).sum(),
                tests.iter().map(|t| t.max).sum()
            )
        );
        for t in tests {
            let secret = t.hidden && audience == Audience::Student;
            let name = if secret { &t.name } else { &t.test };
            out += &format!(
                "    <testcase name=\"{}\" classname=\"exercise {}\" time=\"{:.3}\">\n{}",
                xml(name),
                xml(&t.number),
                t.time,
                points("      ", t.score, t.max)
            );
            if t.status == Status::Passed {
                out += "    </testcase>\n";
                continue;
            }
            let (message, text) = if secret {
                (t.status.word().to_string(), t.status.word().to_string())
            } else {
                let wrong: String = [&t.first_wrong, &t.known]
                    .iter()
                    .filter(|s| !s.is_empty())
                    .map(|s| format!("\n{s}"))
                    .collect();
                (
                    t.message.clone(),
                    format!("{}{wrong}\n— formula: {}", t.message, t.formula),
                )
            };
            out += &format!(
                "      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>\n",
                t.status.word(),
                xml(&message),
                xml(&text)
            );
        }
        out += "  </testsuite>\n";
    }
    out += "</testsuites>\n";
    out
}
