//! Building the graded copy (the student's server), and blaming each compiler error on the exercise whose body holds
//! it: that body goes back to its `todo!()` and the build is tried again.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::sandbox::watch;
use super::splice::{BodyLines, Spliced};
use crate::{ToolError, cargo, layout};

/// A compiler error: the file and line of its primary span, and its message with its place.
pub(super) type CompileError = ((PathBuf, usize), String);

/// How the one error of a build stopped at a limit begins ([`watch`]).
pub(super) const STALLED: &str = "the compiler was stopped: ";

/// The limit a build was stopped at, when it was.
pub(super) fn stalled(errors: &[CompileError]) -> Option<&str> {
    errors.first().and_then(|(_, m)| m.strip_prefix(STALLED))
}

/// Builds `tests` (test targets) or else `bins` and `examples` of `package` in a copy of the
/// project, inside `wrapper` (the build sandbox) when there is one, without debug information.
pub(super) fn cargo_build(
    project: &Path,
    target_dir: &Path,
    package: &str,
    tests: &[String],
    (bins, examples): (&[String], &[String]),
    wrapper: Option<&cargo::Wrapper>,
) -> Result<cargo::Built, ToolError> {
    cargo::Build {
        project,
        packages: &[package],
        tests,
        bins,
        examples,
        profile: None,
        features: &[],
        target_dir: Some(target_dir),
        debug_info: false,
        locked: true,
        stderr: cargo::Stderr::Keep,
        wrapper,
    }
    .run()
}

/// Builds the graded copy's `examples` (the server of the judge outside, and with it the
/// student's crate) inside `wrapper`, the build sandbox, when there is one; returns
/// the compiler's errors, each as the primary span's file and line, and the error's first line
/// with its place (empty when the build succeeded); a build stopped at the compiler's limits
/// has one error, [`STALLED`] and the limit.
pub(super) fn build(
    project: &Path,
    target_dir: &Path,
    examples: &[String],
    wrapper: Option<&cargo::Wrapper>,
) -> Result<Vec<CompileError>, ToolError> {
    let built = cargo_build(
        project,
        target_dir,
        layout::CORE_PACKAGE,
        &[],
        (&[], examples),
        wrapper,
    )?;
    if built.success {
        return Ok(Vec::new());
    }
    if let Some(why) = watch::stopped(&built.stderr) {
        return Ok(vec![((PathBuf::new(), 0), format!("{STALLED}{why}"))]);
    }
    let mut errors: Vec<CompileError> = built
        .errors
        .iter()
        .map(|d| {
            (
                (d.file.clone(), d.line),
                format!("{}:{}: {}", d.file.display(), d.line, d.message),
            )
        })
        .collect();
    if errors.is_empty() {
        errors.push(((PathBuf::new(), 0), built.first_error()));
    }
    Ok(errors)
}

/// The exercises whose bodies hold the errors, each with its first error; `placed` gives
/// each file's body lines as [`Spliced::text`] wrote them.
pub(super) fn blame(
    placed: &[(PathBuf, Vec<BodyLines>)],
    errors: &[CompileError],
) -> BTreeMap<usize, String> {
    let mut out = BTreeMap::new();
    for ((file, line), message) in errors {
        for (_, lines) in placed.iter().filter(|(f, _)| f == file) {
            for &(entry, first, last, shift) in lines {
                if (first..=last).contains(line) {
                    // the place as the student's own file numbers it
                    let copy = format!("{}:{line}: ", file.display());
                    let own = usize::try_from(*line as i64 + shift).unwrap_or(*line);
                    let told = message.strip_prefix(&copy).map_or_else(
                        || message.clone(),
                        |m| format!("{}:{own}: {m}", file.display()),
                    );
                    out.entry(entry).or_insert(told);
                }
            }
        }
    }
    out
}

/// Every region of the files the errors are in whose entry passes `graded` (still the
/// student's), each with the file's first error.
pub(super) fn blame_files(
    files: &[Spliced],
    errors: &[CompileError],
    graded: impl Fn(usize) -> bool,
) -> BTreeMap<usize, String> {
    let mut out = BTreeMap::new();
    for ((file, _), message) in errors {
        for f in files.iter().filter(|f| &f.file == file) {
            for (r, _) in &f.regions {
                if graded(r.entry) {
                    out.entry(r.entry).or_insert_with(|| {
                        format!("{message} (the error could not be placed in one body of this file, so each is graded as not written)")
                    });
                }
            }
        }
    }
    out
}
