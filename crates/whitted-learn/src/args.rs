//! The `whitted` and `cargo learn` command lines' errors in one line, as every whitted
//! program words them ([`leave_after_args`](whitted_syllabus::words::leave_after_args)).
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub use whitted_syllabus::words::one_line;

/// Parses the command line. `--help` and `--version` print and exit 0; any other problem is
/// printed as one line `error: …` (clap's own first line, with the list that follows it when
/// it ends in a colon, such as the arguments missing) with exit status 2.
#[must_use]
pub fn parse_args<T: clap::Parser>() -> T {
    T::try_parse().unwrap_or_else(|e| {
        whitted_syllabus::words::leave_after_args(
            !e.use_stderr(),
            e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand,
            || drop(e.print()),
            || e.render().to_string(),
        )
    })
}
