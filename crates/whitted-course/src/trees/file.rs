//! A chapter's trees file (`chapters/chNN_name/trees.json`, its shape in
//! `docs/src/inspect.md`), written and read as the tree's types: [`TreeFile`] and its
//! [`Kept`] pixels.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::Path;

use whitted_syllabus::tree::{Document, FILE_VERSION, Kept, Plain, Settings, TreeFile};

use crate::ToolError;
use crate::syllabus::Chapter;

/// The words the pixels a known mistake adds are kept for (the start of their `covers`).
pub(super) const MISTAKE_SHOWS: &str = "a known mistake of exercise";

/// The trees file of `chapter` keeping `pixels` (each tree with what it is kept for), traced
/// with `settings`.
pub(super) fn tree_file(
    chapter: &Chapter,
    settings: &Settings<Plain>,
    pixels: Vec<(Document<Plain>, Vec<String>)>,
) -> TreeFile<Plain> {
    TreeFile {
        version: FILE_VERSION,
        about: format!(
            "The reference's ray trees at {} pixels of {}, rendered as the book's figure {}.png; \
             written by `whitted trees`, compared by `{} --against` and `cargo learn`.",
            pixels.len(),
            chapter.scene(),
            chapter.binary,
            chapter.binary
        ),
        settings: settings.clone(),
        pixels: pixels
            .into_iter()
            .map(|(tree, covers)| Kept {
                pixel: tree.tree.pixel,
                covers,
                tree,
            })
            .collect(),
    }
}

/// Reads the trees file at `path`: a file that is not one is an error that says what is
/// wrong with it.
pub(super) fn read_file(path: &Path) -> Result<TreeFile<Plain>, ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    TreeFile::parse(&text).map_err(|why| ToolError::Usage(format!("{}: {why}", path.display())))
}

/// Writes `file` at `path`, `pretty` for a file people read.
pub(super) fn write_file(
    path: &Path,
    file: &TreeFile<Plain>,
    pretty: bool,
) -> Result<(), ToolError> {
    crate::files::write_file(path, file.text(pretty).as_bytes())
}

/// `path` relative to `root`, for messages.
pub(super) fn rel(root: &Path, path: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .display()
        .to_string()
}
