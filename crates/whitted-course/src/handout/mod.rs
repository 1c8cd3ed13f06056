//! Handouts: a student's copy of the project with some exercises taken out.
//!
//! In `src/`, the reference body of every exercise sits between two comment lines,
//!
//! ```text
//! pub fn discriminant(a: Real, b: Real, c: Real) -> Real {
//!     // BEGIN SOLUTION sphere_discriminant
//!     b * b - a * c
//!     // END SOLUTION
//! }
//! ```
//!
//! and [`write()`] copies the project with the chosen regions' bodies replaced by
//! `todo!("exercise sphere_discriminant (2.7): The sphere's discriminant — see chapters/ch02_generic_objects/README.md")`
//! (the message is the syllabus's, [`crate::syllabus::todo`]), between the same two marker lines: the student writes the body there, and `whitted grade`
//! takes what is between them.
//! Exercises of earlier chapters keep their reference code, so a course can hand out one
//! chapter alone on top of working earlier chapters; a later chapter's bodies, tests and
//! golden images are taken out ([`later`]), so a course that releases its chapters week by
//! week hands out no answer of a week to come. A handout of some exercises lists them in its
//! manifest (`[handout] exercises`), and its `cargo learn` counts those alone. The copy holds
//! no solution of a chosen exercise, and
//! no instructor material: of `tests/`, only the targets the manifest's `[handout] tests`
//! lists (and the helper directories they use, such as `tests/common/` and `tests/golden/`),
//! and no `.ci/`. It is written into a temporary directory beside the destination and renamed
//! into place, so a failure leaves nothing half written.
//!
//! Its files, one job each: `regions.rs` finds the solution regions, `select.rs` which
//! exercises go, `todo.rs` what a handed-out body becomes, `later.rs` what becomes of the
//! chapters after the handout's last, `parts.rs` what becomes of each
//! file, `workspace.rs` and `student_readme.rs` the files a handout writes anew, `write.rs`
//! the copy, and `command.rs` the command line.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

mod command;
pub mod later;
mod parts;
mod regions;
mod select;
mod student_readme;
mod todo;
mod workspace;
mod write;

pub use command::{HandoutArgs, command};
pub use parts::{Part, part_of};
pub use regions::{Region, regions};
pub use select::{parse_chapters, select};
pub use student_readme::{README_TEMPLATE, student_readme};
pub use todo::{LIB_ALLOW, todo_statement};
pub use workspace::{HANDOUT_PROFILE, LEFT_PACKAGES, cargo_config, workspace_manifest};
pub use write::{Handout, write};

pub use crate::layout::{BEGIN, END};
