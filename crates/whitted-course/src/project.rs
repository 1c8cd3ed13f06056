//! The project a command of `whitted` works on: the one `--root DIR` names, or the nearest
//! one at or above the current directory.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::PathBuf;

use crate::ToolError;
use crate::cli::find_root;

/// The project's root: `root` when given (`--root DIR`), else the directory of the nearest
/// `Cargo.toml` at or above the current directory.
pub fn root(root: Option<&PathBuf>) -> Result<PathBuf, ToolError> {
    root.map_or_else(find_root, |r| Ok(r.clone()))
}
