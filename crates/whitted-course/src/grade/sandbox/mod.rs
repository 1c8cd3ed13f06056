//! The sandbox a submission is built and run in (Linux, bubblewrap): the student's code never
//! runs, nor is compiled, with the grader's view of the machine.
//!
//! - **Build.** cargo runs in a bubblewrap sandbox that sees the system (`/usr`, and of `/etc`
//!   what the linker needs), the toolchain and the registry read-only, the graded copy
//!   read-only, the build directory writable, and nothing else: not the instructor's project,
//!   not the hidden tests, not the results, not the machine's own files. A body's
//!   `include_str!`, `include_bytes!` or `#[path]` can read only what the sandbox shows: no
//!   hidden test while the student's crate compiles, and of the instructor's files only the
//!   graded copy, whose regions hold the reference's bodies beside the student's (each exercise
//!   is judged alone, [`super::alone`]). Those macros and attributes are the screen's to refuse
//!   ([`super::screen()`]: a body may call only a short list of macros and carry only lint
//!   attributes), which it does at every level.
//! - **The compiler under limits** ([`watch`]): each process of the build has a CPU time and a
//!   memory limit, so a body that stalls the compiler costs its own exercise.
//! - **Run.** nextest stays outside and writes its report; each test binary it starts goes
//!   through [`super::runner::run_test`] (nextest's target runner, `CARGO_TARGET_<TRIPLE>_RUNNER`): a new
//!   root that holds only the system's libraries, the test binary read-only, the files the
//!   tests read and a small private `/tmp`; namespaces of its own (network, processes, IPC,
//!   host name, and users when the grader is not root); an empty environment; an
//!   unprivileged user (as root, a user id of its own per worker, so that its limit on
//!   processes counts only its own); limits on memory,
//!   processes, file size and open files (`prlimit`). The runner cuts its output at a size
//!   (a test that prints megabytes costs the grader nothing), cleans it, passes a test only
//!   when libtest reported it `ok`, and ends it a moment before nextest's time limit: the
//!   sandbox ends with it (`--die-with-parent`, and the PID namespace ends with its first
//!   process).
//!
//! When bubblewrap is missing or cannot make namespaces, [`Sandbox::probe`] says why in one
//! line; the grader then refuses unless told to grade at [`Level::User`] (as root, in a
//! container that makes no namespace: the same user, limits and environment without the new
//! root, the secrets closed by their permissions, what the test's user leaves swept) or
//! unsandboxed ([`Level::Off`]: the runner's verdict, limits and cleaning only).
//!
//! Its files, one job each: `policy.rs` (the levels, the limits and the command of a test
//! run), `bwrap.rs` (bubblewrap's arguments), `worker.rs` (a worker's sandbox, found and
//! tried), `compile.rs` (the build's sandbox), `watch.rs` (the build's limits), `protect.rs`
//! (the secrets at the user level) and `sweep.rs` (what a test's user leaves behind).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

mod bwrap;
mod compile;
mod policy;
mod protect;
mod sweep;
pub mod watch;
mod worker;

pub(crate) use policy::SLOT_VAR;
pub use policy::{FIRST_UID, Level, Limits, POLICY_VAR, Policy, RUNNER_COMMAND, SLOTS};
pub use sweep::{SHARED_TEMPORARY, processes_of, remove_left_files};
pub use worker::{BLOCKS, Lease, Sandbox};
