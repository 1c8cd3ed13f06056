//! Errors for people: every failure a user can cause (a bad scene, flag or path) becomes one
//! of these, printed by the binaries as a single line `error: …` with exit status 2. A
//! handout's exercise not written yet panics (`todo!`); [`missing_exercise`] turns that panic
//! into the same kind of line.
//!
//! Course book: [The scene file](../../../../docs/book/scene-format.html) (`docs/src/scene-format.md`).

use std::path::PathBuf;

/// Everything that can go wrong between reading a scene and writing an image.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A scene file is malformed; `line` and `col` count from 1.
    #[error("{file}:{line}:{col}: {message}")]
    Scene {
        /// The file as the user named it.
        file: String,
        /// Line of the offending value.
        line: usize,
        /// Column of the offending value (in characters).
        col: usize,
        /// What was expected.
        message: String,
    },
    /// A file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The path.
        path: PathBuf,
        /// The reason.
        source: std::io::Error,
    },
    /// An output could not be written.
    #[error("cannot write {}: {message}", path.display())]
    Write {
        /// The path.
        path: PathBuf,
        /// The reason.
        message: String,
    },
    /// A command-line value is out of range (clap catches the rest).
    #[error("{0}")]
    Usage(String),
    /// The live window could not open (no display, no X library).
    #[error("cannot open a window ({0}): render to a file with -o FILE instead")]
    Window(String),
}

pub use whitted_syllabus::words::line_col;

/// The prefix of the panic a handout's `todo!("exercise NAME (2.3): …")` raises (its format is
/// the syllabus's, [`whitted_syllabus::todo`](mod@whitted_syllabus::todo)).
pub const MISSING: &str = whitted_syllabus::todo::PANIC_START;

/// The message of a panic, when it is a string.
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> Option<&str> {
    payload
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| payload.downcast_ref::<&str>().copied())
}

/// The message of a panic, for a report: its text, or a note that it carried none.
#[must_use]
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> &str {
    panic_text(payload).unwrap_or("(no message)")
}

/// The prefix of the panic a later chapter's body raises in a handout that ends before it
/// ([`whitted_syllabus::todo::later_message`]).
pub const LATER: &str = whitted_syllabus::todo::LATER_START;

/// For the panic of an exercise not written yet (a handout's `todo!()`), the one line that
/// says which: `exercise 2.3 (sphere_coefficients) is not written yet: The sphere's quadratic
/// — see …`; for the panic of a later chapter's body in a handout that ends before it, the
/// line that says so (`chapter 5 (reflection and refraction) is not part of this handout: …`).
#[must_use]
pub fn missing_exercise(payload: &(dyn std::any::Any + Send)) -> Option<String> {
    handout_stub(panic_text(payload)?)
}

/// The one line of [`missing_exercise`] for a panic's text `text`, when it is a handout's stub.
#[must_use]
pub fn handout_stub(text: &str) -> Option<String> {
    if text.starts_with(MISSING) {
        whitted_syllabus::todo::find(text).map(|t| t.not_written())
    } else if text.starts_with(LATER) {
        whitted_syllabus::todo::find_later(text).map(str::to_string)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::missing_exercise;

    /// The panic of a handout's todo!() becomes one line naming the exercise.
    #[test]
    fn a_missing_exercise_is_one_line() {
        let payload: Box<dyn std::any::Any + Send> = Box::new(String::from(
            "not yet implemented: exercise sphere_discriminant (2.7): The sphere's discriminant — see chapters/ch02_generic_objects/README.md",
        ));
        assert_eq!(
            missing_exercise(payload.as_ref()).unwrap(),
            "exercise 2.7 (sphere_discriminant) is not written yet: The sphere's discriminant — see chapters/ch02_generic_objects/README.md"
        );
        let later: Box<dyn std::any::Any + Send> = Box::new(format!(
            "not yet implemented: {}",
            whitted_syllabus::todo::later_message("refract", "5.3", 5)
        ));
        assert_eq!(
            missing_exercise(later.as_ref()).unwrap(),
            "chapter 5 (reflection and refraction) is not part of this handout: exercise 5.3 (refract) comes with chapter 5's handout"
        );
        let other: Box<dyn std::any::Any + Send> = Box::new("index out of bounds");
        assert_eq!(missing_exercise(other.as_ref()), None);
    }
}
