//! The course book's figures as `docs/figures.toml` lists them: each PNG under
//! `docs/src/figures/`, the chapter binary that renders it and its arguments. `cargo learn`
//! reads the list to draw the student's version of a figure beside the book's, and the course
//! tools (`whitted figures`) render and check them all.
//!
//! ```toml
//! [[figure]]
//! file = "ch02-normals.png"          # under docs/src/figures/
//! binary = "ch02_generic_objects"     # one of the chapter binaries
//! args = ["scenes/ch02_generic_objects.toml", "--view", "normals", "--width", "320"]
//! ```
//!
//! Course book: [Introduction](../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::collections::HashMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::ToolError;
use crate::files::line_col;
use crate::manifest::{error_at, from_toml};

/// The figures' list, relative to the project's root.
pub const FIGURES: &str = "docs/figures.toml";

/// The directory of the figures' PNG files, relative to the project's root.
pub const FIGURE_DIR: &str = "docs/src/figures";

/// One render of the book, as the manifest lists it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Figure {
    /// The PNG's name under `docs/src/figures/`.
    pub file: String,
    /// The chapter binary that renders it.
    pub binary: String,
    /// Its arguments, all but `-o`; paths are relative to the project's root.
    pub args: Vec<String>,
    /// The line of the manifest where its table starts.
    pub line: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFigures {
    #[serde(default)]
    figure: Vec<toml::Spanned<RawFigure>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFigure {
    file: toml::Spanned<String>,
    binary: toml::Spanned<String>,
    args: Vec<String>,
}

/// Reads the figures' manifest; a mistake is reported as `file:line:col: …`.
pub fn read_figures(path: &Path) -> Result<Vec<Figure>, ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    parse_figures(&text, &path.display().to_string())
}

/// Checks the manifest text `text`; `file` names it in messages. Each `file` must be a plain
/// `NAME.png` (no directory) named once, each `binary` a chapter binary of the syllabus, and `args` must
/// not say where to write (`-o`/`--output`): the manifest's `file` does.
pub fn parse_figures(text: &str, file: &str) -> Result<Vec<Figure>, ToolError> {
    let err = |span: Range<usize>, message: String| error_at(text, file, span, message);
    let raw: RawFigures = from_toml(text, file)?;
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut figures = Vec::new();
    for spanned in &raw.figure {
        let raw = spanned.get_ref();
        let name = raw.file.get_ref();
        let plain = !name.contains(['/', '\\']) && name.len() > 4 && name.ends_with(".png");
        if !plain {
            return Err(err(
                raw.file.span(),
                format!("file `{name}` must be a name ending in .png, without a directory"),
            ));
        }
        let (line, _) = line_col(text, spanned.span().start);
        if let Some(first) = seen.insert(name.clone(), line) {
            return Err(err(
                raw.file.span(),
                format!("file `{name}` is listed twice (first on line {first})"),
            ));
        }
        if crate::syllabus::by_binary(raw.binary.get_ref()).is_none() {
            return Err(err(
                raw.binary.span(),
                format!(
                    "binary `{}` is not a chapter binary (one of {})",
                    raw.binary.get_ref(),
                    crate::syllabus::CHAPTERS
                        .iter()
                        .map(|c| c.binary)
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ));
        }
        if let Some(o) = raw
            .args
            .iter()
            .find(|a| *a == "-o" || a.starts_with("--output"))
        {
            return Err(err(
                spanned.span(),
                format!("args must not contain `{o}`: the figure's `file` says where it goes"),
            ));
        }
        figures.push(Figure {
            file: name.clone(),
            binary: raw.binary.get_ref().clone(),
            args: raw.args.clone(),
            line,
        });
    }
    Ok(figures)
}

impl Figure {
    /// The PNG file of the figure, relative to the project's root.
    #[must_use]
    pub fn path(&self) -> PathBuf {
        Path::new(FIGURE_DIR).join(&self.file)
    }

    /// The scene it renders: the first argument ending in `.toml`.
    #[must_use]
    pub fn scene(&self) -> Option<&str> {
        self.args
            .iter()
            .map(String::as_str)
            .find(|a| a.ends_with(".toml"))
    }
}
