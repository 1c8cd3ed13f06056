//! One test's result, as the test run reports it.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

/// How one test ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// It passed.
    Passed,
    /// It failed: an assertion, a panic, a `todo!()`.
    Failed,
    /// It ran past its time limit and was stopped.
    TimedOut,
    /// Its process died: a stack overflow, an abort, a signal.
    Crashed,
}

impl Status {
    /// The word for reports.
    #[must_use]
    pub fn word(&self) -> &'static str {
        match self {
            Status::Passed => "passed",
            Status::Failed => "failed",
            Status::TimedOut => "timed out",
            Status::Crashed => "crashed",
        }
    }
}

/// One test's result.
#[derive(Clone, Debug, PartialEq)]
pub struct TestResult {
    /// The test's name within its target, with its module path (`ex_near_plane_half_width_…`,
    /// `sphere::ex_sphere_discriminant_…`).
    pub name: String,
    /// Its test target (`ch02_generic_objects`, `hidden_extra`).
    pub target: String,
    /// The manifest entry of the exercise it belongs to, if its name says one.
    pub exercise: Option<usize>,
    /// Whether it is one of the instructor's hidden tests.
    pub hidden: bool,
    /// How it ended.
    pub status: Status,
    /// Why it failed, in a line or two (empty when it passed).
    pub message: String,
    /// How long it ran, in seconds.
    pub time: f64,
    /// What it printed when it failed, as `cargo learn` compares it with a known mistake's
    /// ([`whitted_learn::known::values_of`]); empty otherwise.
    pub values: String,
}
