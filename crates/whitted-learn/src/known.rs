//! Known mistakes told at the save, from the exercise's own tests: what `cargo learn` adds to
//! the verdict on a failing exercise.
//!
//! `whitted trees` applies each of the course's known mistakes (the hand-written mutants) to
//! the reference one at a time, runs the tests of the mistake's exercise, and keeps in
//! `chapters/mistakes.json` what each failing test printed ([`Mistake::tests`]): the values
//! it computed and expected, as the trees keep pixels. When a student's exercise fails exactly
//! those tests, each with the same words and the same numbers (within a tolerance that lets
//! a formula written in another correct order, or in `f32`, agree), [`recognise`] names the
//! mistake, with the verdict of the exercise where it is, on the save that made it: no hint
//! and no finished chapter needed. The file holds numbers and words, never code.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;

use crate::cargo::{TestOutcome, TestRun, test_name};
use crate::learn::message_lines;
use crate::trees::Mistake;

/// The relative tolerance two numbers of a test's message agree within (and the absolute one
/// near zero): the messages print computed values, which another correct order of the same
/// operations, or `f32`, changes in the last digits only.
pub const TOLERANCE: f64 = 1e-3;

/// What of a failed test's output is compared: its message without the panic's place (whose
/// line number moves as the student writes), one line each, joined by `\n`.
#[must_use]
pub fn values_of(output: &str) -> String {
    message_lines(output)
        .into_iter()
        .filter(|l| !(l.starts_with("thread '") && l.contains("panicked at")))
        .map(str::trim_end)
        .collect::<Vec<_>>()
        .join("\n")
}

/// The failing tests of the exercise whose test names start with `prefix` in `run`, by name
/// (without the target), each with [`values_of`] its output.
#[must_use]
pub fn failing_values(run: &TestRun, prefix: &str) -> BTreeMap<String, String> {
    run.outcomes
        .iter()
        .filter(|(n, o)| test_name(n).starts_with(prefix) && **o == TestOutcome::Failed)
        .map(|(n, _)| {
            let output = run.failures.get(n).map_or("", String::as_str);
            (test_name(n).to_string(), values_of(output))
        })
        .collect()
}

/// A message cut into its words and its numbers: `(text before each number, the number)`,
/// then the text after the last.
fn tokens(text: &str) -> (Vec<(&str, f64)>, &str) {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let (mut from, mut i) = (0, 0);
    while i < bytes.len() {
        let sign = bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit);
        let starts = bytes[i].is_ascii_digit() || sign;
        // a digit inside a word (`ch03`, `x2`) is part of the word
        let in_word = i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        if !starts || in_word {
            i += 1;
            continue;
        }
        let mut j = i + usize::from(sign);
        let digits = |j: &mut usize| {
            while *j < bytes.len() && bytes[*j].is_ascii_digit() {
                *j += 1;
            }
        };
        digits(&mut j);
        if j + 1 < bytes.len() && bytes[j] == b'.' && bytes[j + 1].is_ascii_digit() {
            j += 1;
            digits(&mut j);
        }
        if j < bytes.len() && (bytes[j] == b'e' || bytes[j] == b'E') {
            let mut k = j + 1;
            if k < bytes.len() && (bytes[k] == b'-' || bytes[k] == b'+') {
                k += 1;
            }
            if k < bytes.len() && bytes[k].is_ascii_digit() {
                digits(&mut k);
                j = k;
            }
        }
        if let Ok(value) = text[i..j].parse::<f64>() {
            out.push((&text[from..i], value));
            from = j;
        }
        i = j.max(i + 1);
    }
    (out, &text[from..])
}

/// Whether the message `seen` says what `recorded` says: the same words, and numbers that
/// agree within [`TOLERANCE`].
#[must_use]
pub fn same_values(recorded: &str, seen: &str) -> bool {
    let ((a, a_tail), (b, b_tail)) = (tokens(recorded), tokens(seen));
    a.len() == b.len()
        && a_tail == b_tail
        && a.iter().zip(&b).all(|((wa, x), (wb, y))| {
            let scale = x.abs().max(y.abs()).max(1.0);
            wa == wb && ((x - y).abs() <= TOLERANCE * scale || x.is_nan() && y.is_nan())
        })
}

/// The known mistake of the exercise named `exercise` whose recorded tests the student's
/// failing tests `failing` ([`failing_values`]) match: the same tests fail, each with the
/// same values. `None` when no known mistake of it does.
#[must_use]
pub fn recognise<'m>(
    mistakes: &'m [Mistake],
    exercise: &str,
    failing: &BTreeMap<String, String>,
) -> Option<&'m Mistake> {
    mistakes.iter().find(|m| {
        m.exercise == exercise
            && !m.tests.is_empty()
            && m.tests.len() == failing.len()
            && m.tests.iter().all(|(name, recorded)| {
                failing
                    .get(name)
                    .is_some_and(|seen| same_values(recorded, seen))
            })
    })
}

/// The verdict's line naming the known mistake `m`.
#[must_use]
pub fn line(m: &Mistake) -> String {
    format!(
        "  a known mistake: this looks like {} (its tests fail with these very values)\n",
        m.looks_like
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mistake(name: &str, tests: &[(&str, &str)]) -> Mistake {
        Mistake {
            name: name.into(),
            exercise: "mirror_direction".into(),
            chapter: 3,
            looks_like: format!("{name} in words"),
            first: String::new(),
            fingerprint: None,
            tests: tests
                .iter()
                .map(|(n, v)| (n.to_string(), v.to_string()))
                .collect(),
        }
    }

    fn failing(tests: &[(&str, &str)]) -> BTreeMap<String, String> {
        tests
            .iter()
            .map(|(n, v)| (n.to_string(), v.to_string()))
            .collect()
    }

    #[test]
    fn the_place_of_the_panic_is_not_a_value() {
        let output = "thread 'ex_a' panicked at crates/whitted/tests/ch03.rs:120:5:\n\
                      r = (0.6, 0.8, 0) (expected (-0.6, 0.8, 0))\n\
                      note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n";
        let got = values_of(output);
        assert_eq!(
            got, "r = (0.6, 0.8, 0) (expected (-0.6, 0.8, 0))",
            "values_of kept {got:?}"
        );
    }

    #[test]
    fn numbers_agree_within_the_tolerance_and_words_exactly() {
        let recorded = "r = (0.6000, -0.8, 1e-3) expected (0.6, 0.8, 0)";
        for (seen, same) in [
            ("r = (0.6000004, -0.8, 0.001) expected (0.6, 0.8, 0)", true),
            ("r = (0.6100, -0.8, 1e-3) expected (0.6, 0.8, 0)", false),
            ("r = (0.6000, 0.8, 1e-3) expected (0.6, 0.8, 0)", false),
            ("s = (0.6000, -0.8, 1e-3) expected (0.6, 0.8, 0)", false),
            ("r = (0.6000, -0.8, 1e-3) expected (0.6, 0.8, 0) !", false),
            ("r = (0.6000, -0.8) expected (0.6, 0.8, 0)", false),
        ] {
            assert_eq!(
                same_values(recorded, seen),
                same,
                "same_values({recorded:?}, {seen:?}) should be {same}"
            );
        }
        // digits inside a word are the word's
        assert!(!same_values("in ch03 at x2", "in ch04 at x2"));
        assert!(same_values("NaN: NaN", "NaN: NaN"));
    }

    #[test]
    fn a_mistake_is_recognised_by_the_same_failing_tests_with_the_same_values() {
        let mistakes = [
            mistake("dy-upwards", &[("ex_t_one", "y = 1.5 (expected -1.5)")]),
            mistake(
                "rows-from-the-top",
                &[
                    ("ex_t_one", "y = 1.5 (expected -1.5)"),
                    ("ex_t_two", "row 3 (expected 5)"),
                ],
            ),
        ];
        let name = |f: &[(&str, &str)]| {
            recognise(&mistakes, "mirror_direction", &failing(f)).map(|m| m.name.clone())
        };
        assert_eq!(
            name(&[("ex_t_one", "y = 1.50000001 (expected -1.5)")]),
            Some("dy-upwards".into())
        );
        assert_eq!(
            name(&[
                ("ex_t_one", "y = 1.5 (expected -1.5)"),
                ("ex_t_two", "row 3 (expected 5)")
            ]),
            Some("rows-from-the-top".into())
        );
        // another value, another set of tests, another exercise: not these mistakes
        assert_eq!(name(&[("ex_t_one", "y = 2.5 (expected -1.5)")]), None);
        assert_eq!(name(&[("ex_t_two", "row 3 (expected 5)")]), None);
        assert_eq!(
            recognise(
                &mistakes,
                "highlight",
                &failing(&[("ex_t_one", "y = 1.5 (expected -1.5)")])
            )
            .map(|m| m.name.clone()),
            None
        );
    }
}
