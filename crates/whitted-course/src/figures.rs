//! The course book's figures: every render in the book is made by a chapter binary from a
//! scene of the repository; the manifest `docs/figures.toml` lists them, one `[[figure]]`
//! table each:
//!
//! ```toml
//! [[figure]]
//! file = "ch02-normals.png"          # under docs/src/figures/
//! binary = "ch02_generic_objects"     # one of the chapter binaries
//! args = ["scenes/ch02_generic_objects.toml", "--view", "normals", "--width", "320"]
//! ```
//!
//! `whitted figures` renders them all (`BINARY ARGS -o docs/src/figures/FILE`, from the
//! project's root); `whitted figures --check` renders them to a temporary directory and
//! compares each with the committed PNG, pixel by pixel, within [`TOLERANCE`].
//!
//! Course book: [Introduction](../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::ToolError;
use whitted_learn::chapter_binary::Render;
pub use whitted_learn::figures::{FIGURES, Figure, parse_figures, read_figures};

/// The largest difference, in 8-bit levels, between a committed figure and a fresh render of
/// it that `whitted figures --check` accepts: floating point may round the last bit
/// differently on another machine, and one level is 1/255.
pub const TOLERANCE: u8 = 1;

/// Renders `figure` to `out` with the binary of that name in `bin_dir`, from `root` (so that
/// the scene paths of its arguments resolve). The binary's own message is the error.
pub fn render(figure: &Figure, bin_dir: &Path, root: &Path, out: &Path) -> Result<(), ToolError> {
    let binary = bin_dir.join(format!("{}{}", figure.binary, std::env::consts::EXE_SUFFIX));
    if !binary.is_file() {
        return Err(ToolError::Usage(format!(
            "{} is not built: run `cargo build --bins` (or --release) first",
            binary.display()
        )));
    }
    let rendered = Render {
        args: &figure.args,
        quiet: true,
        out: Some(out),
        ..Render::new(&binary, root)
    }
    .run()
    .map_err(|e| ToolError::io(&binary, e.into_io()))?;
    if rendered.success() {
        Ok(())
    } else {
        Err(ToolError::Figure(format!(
            "{} {}: {}",
            figure.binary,
            figure.args.join(" "),
            rendered.stderr.trim()
        )))
    }
}

/// How a fresh render differs from the committed figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Difference {
    /// Every channel of every pixel is within [`TOLERANCE`].
    Same,
    /// The two images do not have the same size: (committed, fresh), as (width, height).
    Size((u32, u32), (u32, u32)),
    /// `pixels` pixels have a channel off by more than the tolerance, at most by `largest`
    /// levels; `first` is the first such pixel, (x, y) from the top left.
    Pixels {
        /// How many pixels differ.
        pixels: usize,
        /// The largest difference of a channel, in 8-bit levels.
        largest: u8,
        /// The first pixel that differs.
        first: (u32, u32),
    },
}

/// Compares two PNGs channel by channel; a difference of at most `tolerance` levels counts as
/// the same.
pub fn compare(committed: &Path, fresh: &Path, tolerance: u8) -> Result<Difference, ToolError> {
    Ok(compare_rgba(
        &read_rgba(committed)?,
        &read_rgba(fresh)?,
        tolerance,
    ))
}

/// [`compare`] of two images already read: each its size and its 8-bit RGBA pixels.
#[must_use]
pub fn compare_rgba(a: &Rgba, b: &Rgba, tolerance: u8) -> Difference {
    if a.0 != b.0 {
        return Difference::Size(a.0, b.0);
    }
    let mut pixels = 0;
    let mut largest = 0;
    let mut first = None;
    let width = a.0.0 as usize;
    for (i, (p, q)) in a.1.chunks_exact(4).zip(b.1.chunks_exact(4)).enumerate() {
        let (x, y) = ((i % width) as u32, (i / width) as u32);
        let off = p
            .iter()
            .zip(q)
            .map(|(u, v)| u.abs_diff(*v))
            .max()
            .unwrap_or(0);
        if off > tolerance {
            pixels += 1;
            largest = largest.max(off);
            first.get_or_insert((x, y));
        }
    }
    match first {
        None => Difference::Same,
        Some(first) => Difference::Pixels {
            pixels,
            largest,
            first,
        },
    }
}

/// An image's size (width, height) and its pixels as 8-bit RGBA, row by row from the top.
pub type Rgba = ((u32, u32), Vec<u8>);

/// A PNG's size and its pixels as 8-bit RGBA, row by row from the top.
pub fn read_rgba(path: &Path) -> Result<Rgba, ToolError> {
    let (width, height, rgba) = whitted_syllabus::words::read_rgba(path)
        .map_err(|e| ToolError::Usage(format!("{}: cannot read the PNG: {e}", path.display())))?;
    Ok(((width, height), rgba))
}

/// `whitted figures [--check]`: renders the book's figures with the chapter binaries built
/// next to this program, or (`check`) compares fresh renders with the committed ones (status
/// 1 when some differ); `only` keeps the figures whose file names contain it.
pub fn command(root: &Path, check: bool, only: Option<&str>) -> Result<ExitCode, ToolError> {
    let manifest = root.join("docs/figures.toml");
    let mut figures = read_figures(&manifest)?;
    if let Some(only) = only {
        figures.retain(|f| f.file.contains(only));
        if figures.is_empty() {
            return Err(ToolError::Usage(format!(
                "--only {only}: no figure of {} has it in its name",
                manifest.display()
            )));
        }
    }
    let exe = std::env::current_exe().map_err(|e| ToolError::io("whitted", e))?;
    let bin_dir = exe.parent().unwrap_or(Path::new("."));
    let dir = root.join("docs/src/figures");
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let scratch = tempfile::Builder::new()
        .prefix(".figures-")
        .tempdir_in(&dir)
        .map_err(|e| ToolError::io(&dir, e))?;
    let mut differ = 0;
    for (k, figure) in figures.iter().enumerate() {
        let fresh = scratch.path().join(&figure.file);
        let committed = dir.join(&figure.file);
        let started = std::time::Instant::now();
        render(figure, bin_dir, root, &fresh)?;
        let ms = started.elapsed().as_millis();
        let n = figures.len();
        if !check {
            std::fs::rename(&fresh, &committed).map_err(|e| ToolError::io(&committed, e))?;
            println!(
                "[{}/{n}] wrote docs/src/figures/{} ({ms} ms)",
                k + 1,
                figure.file
            );
            continue;
        }
        if !committed.is_file() {
            differ += 1;
            println!(
                "[{}/{n}] docs/src/figures/{}: missing (docs/figures.toml:{}): run `whitted figures`",
                k + 1,
                figure.file,
                figure.line
            );
            continue;
        }
        let verdict = match compare(&committed, &fresh, TOLERANCE)? {
            Difference::Same => "the same".to_string(),
            Difference::Size(a, b) => {
                differ += 1;
                format!(
                    "DIFFERS: {}×{} committed, {}×{} rendered",
                    a.0, a.1, b.0, b.1
                )
            }
            Difference::Pixels {
                pixels,
                largest,
                first,
            } => {
                differ += 1;
                format!(
                    "DIFFERS: {pixels} pixel{} off by up to {largest}/255, the first at ({}, {})",
                    if pixels == 1 { "" } else { "s" },
                    first.0,
                    first.1
                )
            }
        };
        println!(
            "[{}/{n}] docs/src/figures/{} (docs/figures.toml:{}): {verdict} ({ms} ms)",
            k + 1,
            figure.file,
            figure.line
        );
    }
    if differ > 0 {
        println!(
            "{differ} of {} figures differ from a fresh render: if the change is meant, run `whitted figures` and commit them",
            figures.len()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// The arguments of `whitted figures`.
#[derive(clap::Args)]
pub struct FiguresArgs {
    /// Compare fresh renders with the committed figures instead of writing them.
    #[arg(long)]
    check: bool,
    /// Only the figures whose file names contain this text.
    #[arg(long, value_name = "TEXT")]
    only: Option<String>,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

impl FiguresArgs {
    /// Runs `whitted figures` on the project the arguments name.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        command(&root, self.check, self.only.as_deref())
    }
}
