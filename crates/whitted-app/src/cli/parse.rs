//! A chapter's command line, built from the chapter alone: [`command`] offers [`Common`] and
//! each group the chapter reaches ([`super::offers`]), and [`ChapterArgs`] reads back what was
//! given. [`parsed_or_exit`] is the exit every whitted program makes when its command line
//! cannot be read (`--help` and `--version` too).
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use clap::{Args, FromArgMatches};

use whitted::render::Chapter;

use super::args::{Accuracy, Common, Objects, Tracing};
use super::offers::{ACCURACY_FROM, OBJECTS_FROM, TRACING_FROM};

/// What a chapter's binary was given: [`Common`], and each other group if the chapter offers
/// it.
#[derive(Debug, Clone)]
pub struct ChapterArgs {
    /// Every chapter's arguments.
    pub common: Common,
    /// From [`OBJECTS_FROM`] on.
    pub objects: Option<Objects>,
    /// From [`ACCURACY_FROM`] on.
    pub accuracy: Option<Accuracy>,
    /// From [`TRACING_FROM`] on.
    pub tracing: Option<Tracing>,
}

impl ChapterArgs {
    /// Reads the groups `chapter` offers from what [`command`] parsed.
    pub fn from_matches(chapter: Chapter, m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        Ok(Self {
            common: Common::from_arg_matches(m)?,
            objects: group(chapter, OBJECTS_FROM, m)?,
            accuracy: group(chapter, ACCURACY_FROM, m)?,
            tracing: group(chapter, TRACING_FROM, m)?,
        })
    }
}

/// Group `G`, offered from chapter `from`, as `chapter`'s binary was given it.
fn group<G: clap::FromArgMatches>(
    chapter: Chapter,
    from: Chapter,
    m: &clap::ArgMatches,
) -> Result<Option<G>, clap::Error> {
    (chapter >= from)
        .then(|| G::from_arg_matches(m))
        .transpose()
}

/// The command line of `chapter`'s binary: named after the chapter's binary, described as
/// "Chapter N of whitted, TITLE: `about`", with the argument groups the chapter offers.
#[must_use]
pub fn command(chapter: Chapter, about: &str) -> clap::Command {
    let offer = |cmd, from, add: fn(clap::Command) -> clap::Command| {
        if chapter >= from { add(cmd) } else { cmd }
    };
    let entry = chapter.about();
    let cmd = clap::Command::new(entry.binary).version(env!("CARGO_PKG_VERSION"));
    let cmd = Common::augment_args(cmd);
    let cmd = offer(cmd, OBJECTS_FROM, Objects::augment_args);
    let cmd = offer(cmd, ACCURACY_FROM, Accuracy::augment_args);
    // after the groups: each sets the command's description to its own
    offer(cmd, TRACING_FROM, Tracing::augment_args)
        .about(format!(
            "Chapter {} of whitted, {}: {about}",
            entry.number, entry.title
        ))
        .long_about(None)
}

/// Parses the command line of a program built with clap's derive (the chapter binaries use
/// [`main`](super::main)). `--help`, `--version` and errors as [`parsed_or_exit`] says.
#[must_use]
pub fn parse_args<T: clap::Parser>() -> T {
    parsed_or_exit(T::try_parse())
}

/// The parsed command line, or the exit every whitted program makes
/// ([`leave_after_args`](whitted_syllabus::words::leave_after_args)): `--help` and
/// `--version` exit 0, any other problem is one line `error: …` with exit status 2.
#[must_use]
pub fn parsed_or_exit<T>(parsed: Result<T, clap::Error>) -> T {
    parsed.unwrap_or_else(|e| {
        whitted_syllabus::words::leave_after_args(
            !e.use_stderr(),
            e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand,
            || drop(e.print()),
            || e.render().to_string(),
        )
    })
}
