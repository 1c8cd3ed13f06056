//! The course tools: the exercises (which function holds which formula of the notes), the
//! proof that the renderer computes each formula there, a student's handout, and the
//! student's loop.
//!
//! The design asks that every formula of the course notes be computed in exactly one small
//! function, and that every render path (scalar or packets, with or without an acceleration
//! structure) go through that function. Each such function is an exercise. One file lists
//! them, the manifest `chapters/formulas.toml`:
//!
//! ```toml
//! [prove]
//! test = "render_paths"     # the integration test whose tests are the render paths
//! filter = "ch{chapter}_"   # the tests of one chapter
//!
//! [handout]
//! tests = ["ch01_camera_rays", "render_paths"]   # the test targets a student's copy keeps
//!
//! [[formula]]
//! function = "camera::near_plane_half_height"
//! chapter = 1
//! section = "Principles of Ray Tracing"
//! formula = "H = N·tan(θ/2)"
//! id = "1.2"                # the exercise: chapter.k in the file's order
//! title = "Half the near plane's height"
//! task = "Return H = N·tan(θ/2) …"
//! hints = ["a nudge", "nearly the answer"]
//! points = 1
//! ```
//!
//! The parts that read it:
//!
//! - [`manifest`] reads and checks the file; a mistake is reported as `file:line:col: …`;
//! - [`source`] finds each function in `src/` (following `pub use` re-exports) and the exact
//!   bytes of its body;
//! - [`prove`] poisons one function at a time in a copy of the project and checks that every
//!   render path of the function's chapter then fails. A function that a render path can avoid
//!   is not the only place its formula is computed, or not a place that matters;
//! - [`handout`] writes a student's copy, each chosen exercise's solution region
//!   (`// BEGIN SOLUTION 2.3` … `// END SOLUTION`) replaced by its `todo!()`;
//! - [`deps`] measures which tests each exercise's absence fails, and keeps the result in
//!   `chapters/exercise-tests.toml`: what a handout fails, exactly;
//! - [`learn`] is the student's loop: progress, the next exercise, hints, rerun on save;
//! - [`readme`] writes each chapter README's exercises from the manifest;
//! - [`grade`] grades a student's copy, or a class, with the instructor's tests (public and
//!   hidden), each test in its own process under a time limit; [`report`] writes the table,
//!   Gradescope's `results.json`, JUnit XML and gradebook CSV.
//!
//! The binary `whitted` exposes them: `whitted formulas [--prove | --deps [--write] |
//! --readmes]`, `whitted handout`, `whitted learn [list | hint | watch]`, `whitted grade`.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub mod book;
pub mod deps;
pub mod grade;
pub mod handout;
pub mod learn;
pub mod manifest;
pub mod prove;
pub mod readme;
pub mod report;
pub mod source;

use std::path::PathBuf;

/// The chapters, as the binaries name them (index 0 is chapter 1).
pub const CHAPTERS: [&str; 5] = [
    "camera rays",
    "generic objects",
    "shading",
    "shadows",
    "reflection and refraction",
];

/// The section titles of the course notes, the only values a manifest's `section` may take.
pub const SECTIONS: [&str; 14] = [
    "Principles of Ray Tracing",
    "Ray Tracing Process",
    "Generic Objects",
    "Generic Sphere",
    "Generic Plane",
    "Generic Cylinder",
    "Generic Cone",
    "Convex Polyhedra",
    "Computational Aspects",
    "Shading",
    "Surface Normals at Intersections",
    "Shadowing",
    "Reflection and Refraction",
    "Lighting Equations",
];

/// What can go wrong in the course tools, each worded for the person running them.
#[derive(Debug, thiserror::Error)]
pub enum Error {
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
    /// The proof could not be carried out (the build failed, the baseline is red …).
    #[error("{0}")]
    Proof(String),
    /// A command-line value makes no sense (an `--only` that names no entry …).
    #[error("{0}")]
    Usage(String),
}

impl Error {
    /// An I/O error on `path`.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Error::Io {
            path: path.into(),
            source,
        }
    }
}
