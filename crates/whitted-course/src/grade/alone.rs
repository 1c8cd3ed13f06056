//! Each exercise judged alone: an exercise's tests run with the student's body for that
//! exercise and the reference's for every other one, so that a mistake, a compile error or a
//! marker slip costs its own exercise and nothing else.
//!
//! The two sides never share a process ([`super::outside`], the renderer's `judge` module).
//! The **judge** is the instructor's crate with its tests, public and hidden, built once for a
//! class; the **server** is the graded copy, built once per submission, which holds the
//! student's bodies and no reference body of a graded exercise. A test named after an exercise
//! (`ex_NAME_…`) runs in the judge: that exercise's calls cross to the server, which runs the
//! student's body, and every other exercise runs in the judge, the reference's. A test of no
//! exercise (the render paths) sends every exercise to the server: the student's whole road,
//! judged by the judge. `--whole-road` ([`Judging::WholeRoad`]) judges every test that way,
//! so that an exercise's tests fail too when an exercise they call is wrong.
//!
//! A student's body goes in only when it is whole on its own (its brackets, braces, quotes and
//! comments close inside it: [`whole_on_its_own`]), so it can never close its function and
//! reach the code around it.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use crate::manifest::Manifest;

/// The environment variable in which the test runner names the test a process runs (its libtest
/// name, module path and all): the judge reads it (the renderer's `judge::TEST_VAR`).
pub const GRADED_TEST_VAR: &str = "WHITTED_GRADED_TEST";

/// How the graded copy judges the tests of an exercise.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Judging {
    /// Each exercise alone: its tests run with the student's body for it (across the wire) and
    /// the reference's for every other exercise (in the judge).
    #[default]
    Alone,
    /// The whole road: every test runs with all of the student's bodies together (every call
    /// across the wire), so that an exercise's tests fail too when an exercise they call is
    /// wrong (`--whole-road`).
    WholeRoad,
}

impl Judging {
    /// The line a report gives: how the tests were judged.
    #[must_use]
    pub fn line(self) -> &'static str {
        match self {
            Self::Alone => {
                "each exercise judged alone: its tests ran with your body for it and the reference's for every other exercise"
            }
            Self::WholeRoad => {
                "the whole road judged (--whole-road): every test ran with all of your bodies together, so a mistake also costs the exercises that call it"
            }
        }
    }
}

/// Whether `body` is whole on its own: it lexes as Rust tokens whose brackets and braces all
/// close inside it, and none of its strings or comments is left open.
#[must_use]
pub fn whole_on_its_own(body: &str) -> bool {
    body.parse::<proc_macro2::TokenStream>().is_ok()
}

/// Each exercise's test prefix (`ex_NAME_`) as a Rust string literal, in the manifest's order:
/// what the code written into a graded copy names the exercises by.
pub(super) fn quoted_prefixes(manifest: &Manifest) -> Vec<String> {
    manifest
        .entries
        .iter()
        .map(|e| format!("{:?}", e.exercise.test_prefix()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body is whole when its delimiters, strings and comments close inside it: one that
    /// would close its function and reach the code around it is not.
    #[test]
    fn a_body_that_could_close_its_block_is_not_whole() {
        for (body, whole) in [
            ("    let a = 1.0;\n    a * 2.0\n", true),
            ("    x // a comment } else {\n", true),
            ("    \"} else {\"\n", true),
            ("    } else { } if false {\n", false),
            ("    todo!() }\n", false),
            ("    /* open comment\n", false),
            ("    r#\"open raw string\n", false),
        ] {
            assert_eq!(whole_on_its_own(body), whole, "{body:?}");
        }
    }
}
