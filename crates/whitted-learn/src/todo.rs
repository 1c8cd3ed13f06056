//! The body a handout gives an exercise to write: one `todo!()` line between its markers,
//! written here only, so that the handout (`whitted handout`), the grader and
//! `cargo learn reset` produce the same bytes.
//!
//! ```text
//!     // BEGIN SOLUTION sphere_coefficients
//!     todo!("exercise sphere_coefficients (2.6): The sphere's quadratic — see chapters/…/README.md")
//!     // END SOLUTION
//! ```
//!
//! The message (shortened above) is the syllabus's ([`crate::syllabus::todo`]), which the loop
//! and the grader read back.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use crate::manifest::Entry;

/// The statement that replaces a handed-out exercise's region: `todo!` with the syllabus's
/// message, which names the exercise, its displayed id and its chapter's README.
#[must_use]
pub fn todo_statement(e: &Entry) -> String {
    let readme = crate::syllabus::chapter(e.chapter).map_or_else(String::new, |c| c.readme());
    let message = crate::syllabus::todo::message(
        &e.exercise.name,
        &e.exercise.id,
        &e.exercise.title,
        &readme,
    );
    format!("todo!({message:?})")
}

/// The whole text between an exercise's two marker lines in a handout: [`todo_statement`] on
/// one line, indented as the `BEGIN` line (`indent`), ended by `eol` (`"\n"` in a handout).
#[must_use]
pub fn todo_body(e: &Entry, indent: &str, eol: &str) -> String {
    format!("{indent}{}{eol}", todo_statement(e))
}
