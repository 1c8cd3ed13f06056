//! `whitted handout` as the command line asks.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::select::{parse_chapters, select};
use super::write::write;
use crate::ToolError;
use crate::manifest::Manifest;

/// The arguments of `whitted handout`.
#[derive(clap::Args)]
pub struct HandoutArgs {
    /// The directory to write the student's copy into (it must not exist, or be empty).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Take out the exercises of these chapters only: 4, or a range such as 1-3.
    #[arg(long, value_name = "N|A-B", value_parser = parse_chapters,
          conflicts_with = "exercises")]
    chapters: Option<(u8, u8)>,
    /// Take out these exercises only, by name or id (comma-separated): sphere_coefficients,2.7.
    #[arg(long, value_name = "IDS", value_delimiter = ',')]
    exercises: Vec<String>,
    /// The project to copy [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

impl HandoutArgs {
    /// Runs `whitted handout` on the project the arguments name.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        let manifest = crate::cli::read_manifest(&root)?;
        command(&root, &manifest, self.chapters, &self.exercises, &self.out)
    }
}

/// `whitted handout`: writes the handout of the exercises chosen (see [`select`]) into `out`
/// and says what it holds.
pub fn command(
    root: &Path,
    manifest: &Manifest,
    chapters: Option<(u8, u8)>,
    exercises: &[String],
    out: &Path,
) -> Result<ExitCode, ToolError> {
    let selected = select(manifest, chapters, exercises)?;
    let made = write(root, manifest, &selected, out)?;
    let ids: Vec<&str> = made
        .stripped
        .iter()
        .map(|&i| manifest.entries[i].exercise.id.as_str())
        .collect();
    println!(
        "wrote {} ({} files): {} exercise{} to write ({}); in it, run `cargo learn`",
        out.display(),
        made.files,
        ids.len(),
        if ids.len() == 1 { "" } else { "s" },
        if ids.len() == manifest.entries.len() {
            "all".to_string()
        } else {
            ids.join(", ")
        }
    );
    Ok(ExitCode::SUCCESS)
}
