//! The grid of trees to choose from: the chapter binary traces every [`STEP`]-th pixel of
//! every [`STEP`]-th row of its figure (`--inspect-grid STEP`), one line of JSON a tree after a
//! first line of settings; each line is read once, as the tree's types.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::BTreeSet;
use std::path::Path;

use serde_json::error::Category;
use whitted_learn::chapter_binary::Render;
use whitted_syllabus::tree::{Document, GridHeader, Plain, Settings};

use super::run::run;
use super::shape::{features, signature};
use crate::ToolError;
use crate::figures::Figure;

/// The distance in pixels between the pixels whose trees are traced to choose from: every
/// pixel, so that a steady pixel's neighbours are the pixels next to it.
pub const STEP: u32 = 1;

/// The trees traced at every [`STEP`]-th pixel of a chapter's scene, row by row, each with
/// its shape ([`signature`]) and what it shows ([`features`]).
#[derive(Debug)]
pub(super) struct Grid {
    /// What the trees were traced with: the settings line `--inspect-grid` prints first.
    pub(super) settings: Settings<Plain>,
    /// The trees, row by row.
    pub(super) trees: Vec<Document<Plain>>,
    /// Each tree's shape.
    pub(super) shapes: Vec<String>,
    /// What each tree shows.
    pub(super) shows: Vec<BTreeSet<String>>,
    /// Pixels a row.
    pub(super) columns: usize,
}

impl Grid {
    /// Rows of trees.
    pub(super) fn rows(&self) -> usize {
        self.trees.len() / self.columns.max(1)
    }

    /// The pixel of tree `i`.
    pub(super) fn pixel(&self, i: usize) -> (u32, u32) {
        let (c, r) = ((i % self.columns) as u32, (i / self.columns) as u32);
        (STEP / 2 + c * STEP, STEP / 2 + r * STEP)
    }

    /// The index of the tree of pixel `p`, one of the grid's.
    pub(super) fn index(&self, p: (u32, u32)) -> usize {
        ((p.1 - STEP / 2) / STEP) as usize * self.columns + ((p.0 - STEP / 2) / STEP) as usize
    }
}

/// The trees of every [`STEP`]-th pixel of `figure`'s render, by `exe`.
pub(super) fn grid(exe: &Path, figure: &Figure, root: &Path) -> Result<Grid, ToolError> {
    let mut args = figure.args.clone();
    args.extend(["--inspect-grid".to_string(), STEP.to_string()]);
    let render = Render {
        args: &args,
        ..Render::new(exe, root)
    };
    let text = run(render, None)?;
    read(&text).map_err(|why| ToolError::Figure(format!("{} --inspect-grid: {why}", exe.display())))
}

/// Reads what `--inspect-grid` printed: a line that is not a tree, or trees that do not fill
/// the grid, is an error that says so in a sentence.
fn read(text: &str) -> Result<Grid, String> {
    let mut lines = text.lines();
    let header: GridHeader<Plain> = match lines.next().map(serde_json::from_str) {
        Some(Ok(header)) => header,
        Some(Err(e)) if e.classify() == Category::Data => {
            return Err(format!("the settings line is not a grid's header: {e}"));
        }
        None | Some(Err(_)) => return Err("no settings line".into()),
    };
    let settings = header.settings;
    let size = (settings.width, settings.height);
    let (mut trees, mut shapes, mut shows) = (Vec::new(), Vec::new(), Vec::new());
    for (n, line) in lines.enumerate() {
        let tree: Document<Plain> = serde_json::from_str(line).map_err(|e| match e.classify() {
            // the settings are line 1
            Category::Data => format!("the tree of line {} is not a ray tree: {e}", n + 2),
            _ => format!("a tree is not JSON: {e}"),
        })?;
        shapes.push(signature(&tree.tree));
        shows.push(features(&tree.tree, size));
        trees.push(tree);
    }
    let columns = size.0.saturating_sub(STEP / 2).div_ceil(STEP) as usize;
    if columns == 0 || trees.len() % columns != 0 {
        return Err("the trees do not fill the grid".into());
    }
    Ok(Grid {
        settings,
        trees,
        shapes,
        shows,
        columns,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The settings line of a grid of 2 × 1 pixels.
    const HEADER: &str = r#"{"version": 1, "settings": {"chapter": 1, "view": "color",
        "width": 2, "height": 1, "samples": 1, "max_depth": 5, "min_weight": 0.001,
        "numerics": "plain", "offset": "normal", "seed": 0}}"#;

    /// The tree of pixel (`x`, 0), whose camera ray misses.
    fn tree(x: u32) -> String {
        format!(
            r#"{{"version": 2, "pixel": [{x}, 0], "chapter": 1, "view": "color",
            "colour": [0.0, 0.0, 0.0], "encoding": "srgb", "rays": 1, "samples": [{{"index": 0,
            "position": [0.5, 0.5], "ray": {{"kind": "camera", "origin": [0.0, 0.0, 0.0],
            "direction": [0.0, 0.0, -1.0], "t_min": 0.0, "depth": 0, "weight": 1.0, "k": 1.0,
            "colour": [0.0, 0.0, 0.0], "hit": null}}}}], "bytes": [0, 0, 0]}}"#
        )
        .replace('\n', " ")
    }

    /// A grid of whole trees is read as the tree's types, each with its shape and features.
    #[test]
    fn a_grid_is_read_line_by_line_as_trees() {
        let text = format!("{}\n{}\n{}\n", HEADER.replace('\n', " "), tree(0), tree(1));
        let grid = read(&text).unwrap();
        assert_eq!((grid.columns, grid.rows()), (2, 1));
        assert_eq!(grid.trees[1].tree.pixel, (1, 0));
        assert_eq!(grid.shapes[0], "camera:miss;");
        assert!(grid.shows[1].contains("a camera ray misses every object"));
    }

    /// A line that is JSON but not a ray tree, one that is not JSON, or a missing settings
    /// line, is refused in one line that says which and why; nothing panics.
    #[test]
    fn a_line_that_is_not_a_tree_is_named() {
        let header = HEADER.replace('\n', " ");
        let no_rays = tree(1).replace(r#""rays": 1,"#, "");
        let e = read(&format!("{header}\n{}\n{no_rays}\n", tree(0))).unwrap_err();
        assert!(
            e.starts_with("the tree of line 3 is not a ray tree: missing field `rays`"),
            "{e}"
        );
        let e = read(&format!("{header}\n{}\n{{\n", tree(0))).unwrap_err();
        assert!(e.starts_with("a tree is not JSON: "), "{e}");
        assert!(!e.contains('\n'), "{e}");
        assert_eq!(read("").unwrap_err(), "no settings line");
        let e = read(r#"{"version": 1}"#).unwrap_err();
        assert!(
            e.starts_with("the settings line is not a grid's header: "),
            "{e}"
        );
        let e = read(&format!("{header}\n{}\n", tree(0))).unwrap_err();
        assert_eq!(e, "the trees do not fill the grid");
    }
}
