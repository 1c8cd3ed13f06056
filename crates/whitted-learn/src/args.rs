//! The `whitted` and `cargo learn` command lines' errors in one line: the syllabus's
//! [`words`](whitted_syllabus::words), which the chapter binaries use too.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub use whitted_syllabus::words::{one_line, parse_args};
