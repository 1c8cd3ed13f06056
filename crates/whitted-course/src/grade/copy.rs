//! The graded copy of the instructor's project: where it lies and where cargo builds it, and
//! which of the project's files go into it whole.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

use super::render;
use super::setup::GradeSetup;
use crate::handout::{self, Part};
use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// The graded copy's directory, inside the build directory when grading has one.
const COPY: &str = "graded-copy";

/// Where one grading copies the project and builds it.
pub(super) struct GradedCopy {
    /// The copy of the project the student's bodies go into.
    pub(super) project: PathBuf,
    /// Where cargo builds it.
    pub(super) target_dir: PathBuf,
    /// The temporary directory that holds the copy when there is no build directory: the
    /// copy goes with it when the grading ends (unless it is kept).
    temp: Option<tempfile::TempDir>,
}

impl GradedCopy {
    /// The copy's place: beside the build directory when there is one, kept from one grading
    /// to the next and updated file by file, so that cargo recompiles only what differs from
    /// the last submission; else a fresh temporary directory, with its own `target/`.
    pub(super) fn place(options: &GradeSetup) -> Result<Self, ToolError> {
        // absolute: the sandbox binds the directories at their paths
        let build_dir = match &options.target_dir {
            Some(dir) => Some(std::path::absolute(dir).map_err(|e| ToolError::io(dir, e))?),
            None => None,
        };
        let mut temp = None;
        let project = match &build_dir {
            Some(dir) => dir.join(COPY),
            None => {
                let mut t = tempfile::Builder::new()
                    .prefix("whitted-grade-")
                    .tempdir()
                    .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
                t.disable_cleanup(options.keep);
                let project = t.path().join("project");
                temp = Some(t);
                project
            }
        };
        let target_dir = build_dir.unwrap_or_else(|| project.join("target"));
        Ok(Self {
            project,
            target_dir,
            temp,
        })
    }

    /// Brings the copy up to date with the project at `root` (each file whole, or empty:
    /// [`whole_in_copy`]) and makes the build directory; says where the copy is when it is
    /// `kept`.
    pub(super) fn sync(
        &self,
        root: &Path,
        manifest: &Manifest,
        kept: bool,
    ) -> Result<(), ToolError> {
        let whole = |f: &Path| whole_in_copy(root, manifest, f);
        files::sync_project(root, &self.project, &[], &whole)?;
        if kept {
            eprintln!("grade: the graded copy is {}", self.project.display());
        }
        std::fs::create_dir_all(&self.target_dir).map_err(|e| ToolError::io(&self.target_dir, e))
    }

    /// Ends the grading's use of the copy: a temporary copy is removed (unless it is kept).
    pub(super) fn close(self) {
        drop(self.temp);
    }
}

/// Whether the project file `file` goes whole into the graded copy: what the student's crate
/// and its tests are built from (every manifest, the exercises' manifest, the lock, cargo's
/// settings, the syllabus, the renderer with the handout's tests, the scenes), and the chapter binaries and the book's
/// figures for the leaderboard's render: all of it in the handout too. Every other file is
/// there empty, so that a body compiled in the copy cannot include the instructor's other
/// files (a mutant list, a guide, tools that quote the solutions).
fn whole_in_copy(root: &Path, manifest: &Manifest, file: &Path) -> bool {
    let name = file.file_name().map(|n| n.to_string_lossy().into_owned());
    if matches!(name.as_deref(), Some("Cargo.toml"))
        || file == Path::new("Cargo.lock")
        || file.starts_with(".cargo")
        || name
            .as_deref()
            .is_some_and(|n| n.starts_with("rust-toolchain"))
        || file.starts_with(layout::SYLLABUS)
        || file.starts_with(layout::APP)
        || file.starts_with("scenes")
        // the renderer builds the manifest in: it says which functions computed each
        // number of a ray tree (`render::inspect::provenance`), which the feedback names
        || file == Path::new(whitted_learn::manifest::DEFAULT_PATH)
        || render::needs(file)
    {
        return true;
    }
    if file.starts_with(layout::core_tests()) {
        return handout::part_of(file, &manifest.handout.tests, root) == Part::Copied;
    }
    file.starts_with(layout::CORE)
}

/// What the tests read at run time, shown to them read-only: the scenes and the golden
/// images.
pub(super) fn run_reads(project: &Path) -> Vec<PathBuf> {
    vec![
        project.join("scenes"),
        project.join(layout::core_tests()).join("golden"),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The graded copy holds whole what the renderer builds in (the exercises' manifest, which
    /// names the functions of a tree's numbers), and the instructor's other files empty.
    #[test]
    fn the_copy_holds_what_the_renderer_builds_in_and_no_more() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let manifest =
            whitted_learn::manifest::load(&root.join(whitted_learn::manifest::DEFAULT_PATH))
                .unwrap();
        for (file, whole) in [
            ("chapters/formulas.toml", true),
            ("crates/whitted/src/render/inspect/provenance.rs", true),
            ("chapters/ch02_generic_objects/trees.json", true),
            (
                "crates/whitted-course/tests/mutants/hand-written.toml",
                false,
            ),
            ("docs/src/instructor-guide.md", false),
        ] {
            assert_eq!(
                whole_in_copy(&root, &manifest, Path::new(file)),
                whole,
                "{file} whole in the graded copy"
            );
        }
    }
}
