//! Drawing the pictures a check chose: each stage's figure (or, in a handout without the
//! book's figures, the chapter's scene alone), drawn by the project's own chapter binaries
//! through [`crate::chapter_binary`] into `.whitted/FILE`.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::{Path, PathBuf};

use super::stage::{Stage, figure_of};
use crate::ToolError;
use crate::chapter_binary::{self, Render};
use crate::figures::{self, Figure};
use crate::learn::{STATE_DIR, Say, build};
use crate::manifest::Manifest;
use crate::trees::Against;

/// The width of a chapter's picture when the handout has no figure of it to compare with (the
/// height follows the scene).
pub const PICTURE_WIDTH: u32 = 240;

/// A picture drawn by the student's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Picture {
    /// The PNG written: with a figure to compare with, the student's render, the figure and
    /// their difference side by side; else the render alone.
    pub path: PathBuf,
    /// The chapter binary's `compare:` line (how many pixels differ from the figure, and
    /// where the first one is), when there was a figure.
    pub compare: Option<String>,
    /// The student's ray trees compared with the reference's at the pixels of the chapter's
    /// trees file, for a chapter's own picture ([`crate::trees`]).
    pub against: Vec<Against>,
}

/// Why a picture could not be drawn.
#[derive(Debug)]
pub enum NoPicture {
    /// The render stopped: the chapter binary's one-line error (an exercise it needs is not
    /// written yet, or panics).
    Render(String),
    /// The chapter binary could not be built or run.
    Tool(ToolError),
}

/// What to run for one picture: the binary, its arguments, where the PNG goes, and the
/// chapter whose trees it compares (a chapter's own picture).
struct Job {
    binary: String,
    args: Vec<String>,
    png: PathBuf,
    compare: Option<PathBuf>,
    trees: Option<PathBuf>,
}

/// What to run to draw `stage` in the project at `root`, whose book lists `figures`.
fn job(root: &Path, manifest: &Manifest, figures: &[Figure], stage: Stage) -> Option<Job> {
    let dir = root.join(STATE_DIR);
    if let Some(figure) = figure_of(manifest, figures, stage) {
        let book = root.join(figure.path());
        let trees = match stage {
            Stage::Chapter(c) => chapter_binary::chapter_trees(root, c),
            _ => None,
        };
        return Some(Job {
            binary: figure.binary.clone(),
            args: figure.args.clone(),
            png: dir.join(&figure.file),
            compare: book.is_file().then_some(book),
            trees,
        });
    }
    // a handout without the book's figures: the chapter's scene alone
    let Stage::Chapter(c) = stage else {
        return None;
    };
    let about = whitted_syllabus::chapter(c)?;
    let mut args = Vec::new();
    if root.join(about.scene()).is_file() {
        args.push(about.scene());
    }
    args.extend(["--width".to_string(), PICTURE_WIDTH.to_string()]);
    Some(Job {
        binary: about.binary.to_string(),
        args,
        png: dir.join(format!("{}.png", about.binary)),
        compare: None,
        trees: None,
    })
}

/// Draws each of `stages` with the project's own chapter binaries (built together, at the
/// loop's profile); a stage the handout has no figure of is left out.
pub fn draw(
    root: &Path,
    manifest: &Manifest,
    stages: &[Stage],
) -> Vec<(Stage, Result<Picture, NoPicture>)> {
    let figures = figures::read_figures(&root.join(figures::FIGURES)).unwrap_or_default();
    let jobs: Vec<(Stage, Job)> = stages
        .iter()
        .filter_map(|&s| job(root, manifest, &figures, s).map(|j| (s, j)))
        .collect();
    let mut bins: Vec<String> = jobs.iter().map(|(_, j)| j.binary.clone()).collect();
    bins.sort();
    bins.dedup();
    if bins.is_empty() {
        return Vec::new();
    }
    let built = build(root, &[], &bins, &Say { report: false });
    let executables = match chapter_binary::executables(built) {
        Ok(e) => e,
        Err(e) => {
            let why = e.to_string();
            return jobs
                .into_iter()
                .map(|(s, _)| (s, Err(NoPicture::Tool(ToolError::Cargo(why.clone())))))
                .collect();
        }
    };
    jobs.into_iter()
        .map(|(s, job)| {
            let picture = match executables.get(&job.binary) {
                Some(exe) => run(root, exe, &job),
                None => Err(NoPicture::Tool(ToolError::Cargo(format!(
                    "cargo built no binary {}",
                    job.binary
                )))),
            };
            (s, picture)
        })
        .collect()
}

/// Runs the chapter binary `exe` for `job`, from `root`.
fn run(root: &Path, exe: &Path, job: &Job) -> Result<Picture, NoPicture> {
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| NoPicture::Tool(ToolError::io(&dir, e)))?;
    let rendered = Render {
        args: &job.args,
        compare: job.compare.as_deref(),
        // the first wrong number: the same pixels' trees, traced and compared
        against: job.trees.as_deref(),
        quiet: true,
        out: Some(&job.png),
        ..Render::new(exe, root)
    }
    .run()
    .map_err(|e| {
        NoPicture::Tool(ToolError::Cargo(format!(
            "cannot run {}: {e}",
            exe.display()
        )))
    })?;
    if !rendered.success() {
        let line = rendered.error_line().unwrap_or("the render failed");
        return Err(NoPicture::Render(line.to_string()));
    }
    let (compare, against) = rendered.compared();
    Ok(Picture {
        path: job.png.clone(),
        compare,
        against,
    })
}
