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
//! name = "half_height"      # the exercise's name; its displayed id (1.2) is its place
//! title = "Half the near plane's height"
//! task = "Return H = N·tan(θ/2) …"
//! hints = ["the idea", "the formula"]
//! points = 1
//! ```
//!
//! The parts that read it:
//!
//! - [`manifest`] reads and checks the file; a mistake is reported as `file:line:col: …`;
//! - [`source`] finds each function in `src/` (following `pub use` re-exports) and the exact
//!   bytes of its body;
//! - [`poison`] makes a copy of the project with every function behind a switch that makes
//!   it panic, builds its tests once and runs them with one function poisoned at a time;
//! - [`prove`] checks on it that every render path of a function's chapter fails with the
//!   function poisoned. A function that a render path can avoid is not the only place its
//!   formula is computed, or not a place that matters;
//! - [`handout`] writes a student's copy, each chosen exercise's solution region
//!   (`// BEGIN SOLUTION sphere_coefficients` … `// END SOLUTION`) replaced by its `todo!()`;
//! - [`deps`] measures which tests each exercise's absence fails, and keeps the result in
//!   `chapters/exercise-tests.toml`: what a handout fails, exactly;
//! - [`learn`] is the student's loop: progress, the next exercise, hints, rerun on save (with
//!   the manifest, the map, the files and the cargo runner it is the crate `whitted-learn`,
//!   which a handout holds instead of this one);
//! - [`readme`] writes each chapter README's exercises from the manifest;
//! - [`grade`] grades a student's copy, or a class, with the instructor's tests (public and
//!   hidden), each test in its own process under a time limit, the student's code built and
//!   run in a sandbox; [`report`] writes the table, Gradescope's `results.json`, JUnit XML
//!   and a submission's CSV row, and [`gradebook`] a class's `class.csv`;
//! - [`autograder`] fits grading to Gradescope, GitHub Classroom, PrairieLearn and CodeGrade:
//!   the package each one takes, and each one's results file from one report;
//! - [`figures`] renders the course book's figures and compares them; [`book`] checks the
//!   built book;
//! - [`trees`] keeps the reference's ray trees at a few pixels of each chapter scene, and
//!   [`mistakes`] the course's known mistakes (the hand-written mutants) with their
//!   fingerprints, for `cargo learn`'s first wrong number.
//!
//! The binary `whitted` exposes them: `whitted formulas [list | prove | deps [--write] |
//! readmes]` ([`formulas`]), `whitted handout`, `whitted learn [list | hint | watch]`,
//! `whitted grade`, `whitted autograder`, `whitted figures [--check]`, `whitted trees
//! [--check]`, `whitted book`.
//!
//! Course book: [The instructor's guide](../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub mod autograder;
pub mod book;
pub mod deps;
pub mod figures;
pub mod formulas;
pub mod grade;
pub mod gradebook;
pub mod handout;
pub mod mistakes;
pub mod parallel;
pub mod poison;
pub mod project;
pub mod prove;
pub mod readme;
pub mod report;
pub mod source;
pub mod trees;

pub use whitted_learn::{
    ToolError, args, cargo, cli, files, layout, learn, manifest, map, picture, syllabus,
};
