//! Errors for people: every failure a user can cause (a bad scene, flag or path) becomes one
//! of these, printed by the binaries as a single line `error: …` with exit status 2.

use std::path::PathBuf;

/// Everything that can go wrong between reading a scene and writing an image.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A scene file is malformed; `line` and `col` count from 1.
    #[error("{file}:{line}:{col}: {message}")]
    Scene {
        /// The file as the user named it.
        file: String,
        /// Line of the offending value.
        line: usize,
        /// Column of the offending value (in characters).
        col: usize,
        /// What was expected.
        message: String,
    },
    /// A file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The path.
        path: PathBuf,
        /// The reason.
        source: std::io::Error,
    },
    /// An output could not be written.
    #[error("cannot write {}: {message}", path.display())]
    Write {
        /// The path.
        path: PathBuf,
        /// The reason.
        message: String,
    },
    /// A command-line value is out of range (clap catches the rest).
    #[error("{0}")]
    Usage(String),
}

/// The 1-based line and column (in characters) of a byte offset in `text`.
#[must_use]
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}
