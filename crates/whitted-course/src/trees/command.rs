//! `whitted trees [--check]` as the command line asks: the steps that write the trees files
//! and the known mistakes, or the check of the committed ones.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::check::check_all;
use super::choose::Chosen;
use super::file::{rel, tree_file, write_file};
use super::grid::grid;
use super::run::{figure_of, reference_binary};
use super::switched::Switched;
use crate::figures::{self, Figure};
use crate::manifest::Manifest;
use crate::syllabus;
use crate::{ToolError, mistakes};
use whitted_learn::trees::trees_file;

/// The arguments of `whitted trees`.
#[derive(clap::Args)]
pub struct TreesArgs {
    /// Compare the committed trees with the reference's instead of writing them.
    #[arg(long)]
    check: bool,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

impl TreesArgs {
    /// Runs `whitted trees` on the project the arguments name.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        let manifest = crate::cli::read_manifest(&root)?;
        command(&root, &manifest, self.check)
    }
}

/// `whitted trees [--check]` on the project at `root` (see the module's documentation).
pub fn command(root: &Path, manifest: &Manifest, check: bool) -> Result<ExitCode, ToolError> {
    let figures = figures::read_figures(&root.join("docs/figures.toml"))?;
    if check {
        return check_all(root, &figures);
    }
    let scratch = tempfile::Builder::new()
        .prefix("whitted-trees-")
        .tempdir()
        .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
    // 1. each chapter's grid, and the pixels its features need
    let mut chosen = choose_all(root, &figures)?;
    // 2. the known mistakes, one build for all, and a pixel for each one no pixel kept shows
    let mutants = mistakes::load(root)?;
    let switched = Switched::build(root, scratch.path(), &figures, manifest, &mutants)?;
    switched.add_pixels(&mut chosen)?;
    // 3. the trees files
    write_all(root, &chosen)?;
    // 4. the mistakes' fingerprints
    switched.fingerprints()?;
    Ok(ExitCode::SUCCESS)
}

/// Each chapter's grid, traced by its reference binary, and the pixels kept for its features
/// (in chapter order), said as they are chosen.
fn choose_all(root: &Path, figures: &[Figure]) -> Result<Vec<Chosen>, ToolError> {
    let mut all = Vec::new();
    for chapter in &syllabus::CHAPTERS {
        let figure = figure_of(figures, chapter)?;
        let (chosen, unsteady) = Chosen::from(grid(&reference_binary(chapter)?, figure, root)?);
        println!(
            "chapter {}: {} pixels show the {} features of its steady trees",
            chapter.number,
            chosen.picks.len(),
            chosen.features()
        );
        if !unsteady.is_empty() {
            println!("  only near edges, not kept: {}", unsteady.join("; "));
        }
        all.push(chosen);
    }
    Ok(all)
}

/// Writes each chapter's trees file from its pixels kept.
fn write_all(root: &Path, chosen: &[Chosen]) -> Result<(), ToolError> {
    for (chapter, c) in syllabus::CHAPTERS.iter().zip(chosen) {
        let pixels: Vec<_> = c
            .picks
            .iter()
            .map(|(i, covers)| (c.grid.trees[*i].clone(), covers.clone()))
            .collect();
        let count = pixels.len();
        let path = root.join(trees_file(chapter.number).unwrap_or_default());
        write_file(&path, &tree_file(chapter, &c.grid.settings, pixels), true)?;
        println!("wrote {} ({count} pixels)", rel(root, &path));
    }
    Ok(())
}
