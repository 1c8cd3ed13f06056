//! # whitted-learn — the student's loop
//!
//! What a student's handout needs to run `cargo learn`, and nothing more: the manifest of the
//! exercises (`chapters/formulas.toml`, read by [`manifest`]) and the measured map of which
//! tests need which exercise ([`map`]), one runner for cargo and the test executables it
//! builds ([`cargo`]), one for the chapter binaries that draw a figure ([`chapter_binary`]),
//! where things are in a project ([`layout`]), the body a handout gives an exercise to write
//! ([`mod@todo`]), and the loop itself ([`learn`]): the verdict on
//! the next exercise, the progress, hints and the chapter's picture ([`picture`]), after every
//! save with `watch`.
//!
//! It does not depend on the renderer: it runs cargo on the student's project, so an edit of
//! the renderer never rebuilds it and a compile error never stops it. The instructor's tools
//! (`whitted formulas`, `handout`, `grade`, `figures`, `book`) are the crate `whitted-course`,
//! built on this one and left out of handouts.
//!
//! Course book: [The student's guide](../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

pub mod args;
pub mod cargo;
pub mod changes;
pub mod chapter_binary;
pub mod cli;
pub mod figures;
pub mod files;
pub mod known;
pub mod layout;
pub mod learn;
pub mod manifest;
pub mod map;
pub mod picture;
pub mod screen;
pub mod todo;
pub mod trees;
pub mod week;

/// The course's outline: the chapters (and the notes' sections, the todo!() message), read from
/// the one table every crate of whitted reads.
pub use whitted_syllabus as syllabus;

use std::path::PathBuf;

/// What can go wrong in the course tools (the loop, the proof, handouts, grading, the book),
/// each worded for the person running them. (The renderer's own errors are `whitted::Error`.)
#[derive(Debug, thiserror::Error)]
pub enum ToolError {
    /// A mistake in the manifest; `line` and `col` count from 1.
    #[error("{file}:{line}:{col}: {message}")]
    Manifest {
        /// The manifest file as named on the command line.
        file: String,
        /// Line of the offending value.
        line: usize,
        /// Column of the offending value (in characters).
        col: usize,
        /// What is wrong.
        message: String,
    },
    /// A manifest entry names a function that cannot be found, or is not unique.
    #[error("{manifest}:{line}: {function}: {message}")]
    Function {
        /// The manifest file.
        manifest: String,
        /// The entry's line in the manifest.
        line: usize,
        /// The entry's function path.
        function: String,
        /// What went wrong, naming the source file.
        message: String,
    },
    /// A source file does not parse as Rust.
    #[error("{file}:{line}:{col}: cannot parse the Rust source: {message}")]
    Parse {
        /// The source file.
        file: String,
        /// Line of the error.
        line: usize,
        /// Column of the error (in characters).
        col: usize,
        /// The parser's message.
        message: String,
    },
    /// A file or directory could not be read, written or copied.
    #[error("{}: {source}", path.display())]
    Io {
        /// The path.
        path: PathBuf,
        /// The reason.
        source: std::io::Error,
    },
    /// An exercise's solution markers are missing, misplaced or name another exercise.
    #[error("{0}")]
    Markers(String),
    /// The tests fail before anything is taken out or poisoned: nothing can be measured on
    /// them.
    #[error("{0}")]
    Baseline(String),
    /// A copy of the project (poisoned, or graded) does not build.
    #[error("{0}")]
    Build(String),
    /// A file of the project is not as the tools need it (the workspace's members, cargo's
    /// aliases, a book page's include).
    #[error("{0}")]
    Project(String),
    /// A figure of the course book could not be rendered.
    #[error("{0}")]
    Figure(String),
    /// Cargo or a test executable could not be run, or did not do its work.
    #[error("{0}")]
    Cargo(String),
    /// A command-line value makes no sense (an `--only` that names no entry …).
    #[error("{0}")]
    Usage(String),
}

impl ToolError {
    /// An I/O error on `path`.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        ToolError::Io {
            path: path.into(),
            source,
        }
    }
}
