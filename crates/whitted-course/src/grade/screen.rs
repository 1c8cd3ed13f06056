//! The screen a student's body passes before the grader compiles it: the one `cargo learn` runs
//! at every save ([`whitted_learn::screen`]), so that what the grader refuses, the student was
//! told at the save, with its line and a way to write it.
//!
//! A body the screen refuses is graded as not written and never compiled. With each exercise
//! judged alone, the screen is the first of the locks around a body, and a teacher's hint: a
//! formula's grammar (statements, expressions, closures, loops, `match`, a few macros, lint
//! attributes, comments) passes whatever its names; items, lifetimes, `unsafe`, `extern`,
//! macro definitions and paths into the process, files, the network or the environment do not.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub use whitted_learn::screen::{MACROS, REFUSED_OF_THE_PROJECT, Refusal};

/// What in `body` the screen refuses, as the body writes it (`` `std::env::var` (`env`) ``,
/// `` `unsafe` ``, `` `fn` ``); `None` when the body is a formula. The whole refusal, with its
/// line and a way to write it, is [`whitted_learn::screen::screen`]'s.
#[must_use]
pub fn screen(body: &str) -> Option<String> {
    whitted_learn::screen::screen(body).map(|r| r.what)
}
