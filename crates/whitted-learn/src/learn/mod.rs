//! `whitted learn` (`cargo learn` in a handout): the student's loop — the verdict on the next
//! exercise first, then the progress of every chapter, hints, the chapter's picture, and all of
//! it again after every save.
//!
//! An exercise is **done** when its own tests (those named `ex_sphere_coefficients_…` for the
//! exercise `sphere_coefficients`, in the test targets of the manifest's `[handout] tests`)
//! all pass. A check goes in two steps, so
//! that the answer a student waits for comes first:
//!
//! 0. **What changed.** The exercises whose body changed since the last complete check
//!    ([`crate::changes`]) are checked first: one that now passes says so at once, and one
//!    that fails gets its verdict before anything else, though it was finished before.
//! 1. **The verdict.** An exercise whose tests fail while an exercise they call (by the map)
//!    is not done waits for that one ([`rooted`]): the verdict is always on the root of a
//!    failure, and names a known mistake from the values its tests print
//!    ([`crate::known`]). The exercise to look at is the first one that was not done at the last
//!    check (`.whitted/progress.json`, by exercise name), or the first. Only the test target that holds its
//!    tests (by the measured map, `chapters/exercise-tests.toml`) is built and run; if all of
//!    that target's exercises pass, the next target is, until one is not done. That verdict is
//!    printed: the exercise, the notes' formula, every failing test of it with its message,
//!    where to write it.
//! 2. **The picture.** What the student's code draws of the chapter being written, beside the
//!    book's picture of the same stage ([`crate::picture`]).
//! 3. **The progress.** The other targets are built and run at once, and each chapter's count
//!    is printed; should the first exercise not done be another than the verdict's, its
//!    verdict follows.
//!
//! When the code does not compile, the first compiler error is shown at the student's
//! file:line:col, and nothing runs; `learn hint` and `learn list` answer all the same, since
//! this tool does not depend on the student's code. A build that lasts more than a moment (the
//! first one compiles the renderer's dependencies) shows cargo's lines as it goes.
//!
//! Every build selects both the renderer's and the binaries' packages, so cargo resolves their
//! dependencies alike and the renderer is compiled once per save for the tests and the picture.
//!
//! | file | its job |
//! |---|---|
//! | `state.rs` | where each exercise stands ([`State`]), kept between checks |
//! | `style.rs` | colours on a terminal ([`Style`]) |
//! | `say.rs` | the report on stdout, progress lines on stderr, the [`COMMAND`] messages name |
//! | `verdict.rs` | the verdict on one exercise in words ([`verdict`]) |
//! | `progress.rs` | every chapter's progress and the list of exercises ([`progress`], [`list`]) |
//! | `hints.rs` | the next hint of an exercise ([`next_hint`]) |
//! | `run.rs` | which target decides an exercise, the builds, the test runs ([`run_tests`]) |
//! | `check.rs` | one check, steps 0 to 3 above ([`check`], [`once`]) |
//! | `watch.rs` | a check after every save, the screen redrawn for each ([`watch`]) |
//! | `reset.rs` | an exercise's body put back to the handout's `todo!()` ([`reset()`]) |
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

mod check;
mod hints;
mod progress;
mod reset;
mod run;
mod say;
mod state;
mod style;
mod verdict;
mod watch;

pub use check::{Checked, check, once};
pub use hints::{hints_shown, next_hint};
pub use progress::{bar, list, progress, written_road};
pub use reset::{Body, RESET_DIR, Reset, find_body, reset};
pub(crate) use run::build;
pub use run::{PACKAGES, TEST_TIME_LIMIT, run_tests, targets_of};
pub use say::COMMAND;
pub(crate) use say::Say;
pub use state::{
    STATE_DIR, State, calls, message_lines, newly_done, rooted, save_states, saved_states, states,
    todo_name,
};
pub use style::Style;
pub use verdict::{place, telling_order, verdict};
pub use watch::{Between, CLEAR_SCREEN, is_source_change, snapshot, watch, watched};
