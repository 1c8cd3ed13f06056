//! The judge's copy: the instructor's project with the wire of the judge outside
//! ([`super::outside`]) and the hidden tests, built once for a class and run for each
//! submission against that submission's server.
//!
//! It holds what decides a test (the expected values, the comparisons, the hidden tests) and
//! never the student's code, so it is built and run with the grader's rights, outside the
//! sandbox; its directory is closed to other users and lies outside every directory the
//! sandbox shows a submission's code. A file of it is written only when its bytes change, so
//! that a class's later gradings find it built.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

use super::blame::cargo_build;
use super::nextest::{self, Listed};
use super::outside::{Wire, plan_wire};
use super::splice;
use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// The judge, built and its tests listed: what a grading runs against its server.
#[derive(Debug)]
pub struct Judge {
    /// Its directory (the project, its build and its runs' reports), closed to other users.
    pub dir: PathBuf,
    /// The copy of the project.
    pub project: PathBuf,
    /// Where cargo builds it.
    pub target_dir: PathBuf,
    /// Its test binaries, listed for nextest.
    pub listed: Listed,
    /// The test targets that run: the graded chapters' and the hidden tests'.
    pub targets: Vec<String>,
    /// The hidden tests' targets among them.
    pub hidden: Vec<String>,
    /// The wire, planned on the instructor's files: the same in the judge and in every
    /// submission's server.
    pub wire: Wire,
    /// The temporary directory that holds it when the grading has no build directory.
    _temp: Option<tempfile::TempDir>,
}

/// Where a grading's judge lies when none is given: beside its build directory `target_dir`
/// (`NAME-judge`), never inside it (the build sandbox shows that whole directory to the
/// submission's build).
#[must_use]
pub fn beside(target_dir: &Path) -> PathBuf {
    let name = target_dir
        .file_name()
        .map_or_else(|| "build".into(), |n| n.to_string_lossy().into_owned());
    target_dir.with_file_name(format!("{name}-judge"))
}

/// Makes and builds the judge of the project at `root` in `dir` (a fresh temporary directory
/// when `None`): the test targets `public` and the hidden tests of the directory `hidden`.
/// Before anything is graded, a hidden test named after no exercise ([`super::hidden`]), or
/// a public or hidden test that does not build, is an error at its file and line: the
/// project and the hidden tests are the instructor's, and a grade never silently goes
/// without them.
pub fn prepare(
    root: &Path,
    manifest: &Manifest,
    public: &[String],
    hidden: Option<&Path>,
    dir: Option<&Path>,
) -> Result<Judge, ToolError> {
    let (dir, temp) = match dir {
        Some(d) => (
            std::path::absolute(d).map_err(|e| ToolError::io(d, e))?,
            None,
        ),
        None => {
            let t = tempfile::Builder::new()
                .prefix("whitted-judge-")
                .tempdir()
                .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
            (t.path().to_path_buf(), Some(t))
        }
    };
    close(&dir)?;
    let project = dir.join("project");
    let target_dir = dir.join("target");
    if let Some(dir) = hidden {
        super::hidden::check(manifest, dir)?;
    }
    let wire = write_copy(root, manifest, &project)?;
    let hidden_targets = splice::add_hidden(&project, hidden)?;
    remove_stale_hidden(&project, &hidden_targets)?;
    let build = |targets: &[String]| -> Result<(), ToolError> {
        let built = cargo_build(
            &project,
            &target_dir,
            layout::CORE_PACKAGE,
            targets,
            (&[], &[]),
            None,
        )?;
        if built.success {
            Ok(())
        } else {
            Err(ToolError::Cargo(built.first_error()))
        }
    };
    let targets: Vec<String> = public.iter().chain(&hidden_targets).cloned().collect();
    if let Err(e) = build(&targets) {
        let why = e.to_string();
        let why = why.trim_start_matches("error: ");
        // a hidden file's error names its copy in the judge: the instructor's file instead
        let hidden_file = hidden.and_then(|dir| {
            hidden_targets
                .iter()
                .find_map(|t| {
                    let copy = layout::core_test_file(t).display().to_string();
                    why.contains(&copy).then(|| (copy, t.clone()))
                })
                .and_then(|(copy, t)| {
                    let original = splice::hidden_files(dir)
                        .ok()?
                        .into_iter()
                        .find(|f| splice::hidden_target(f) == t)?;
                    Some(why.replace(&copy, &original.display().to_string()))
                })
        });
        return Err(ToolError::Usage(match hidden_file {
            Some(why) => format!("the hidden tests do not build, so no grading starts: {why}"),
            None => format!(
                "the judge (the instructor's project with the grader's wire{}) does not build: {why}",
                if hidden_targets.is_empty() {
                    ""
                } else {
                    " and the hidden tests"
                }
            ),
        }));
    }
    let listed = nextest::list(&project, &target_dir, &targets, None, &dir.join("listed"))?;
    Ok(Judge {
        dir,
        project,
        target_dir,
        listed,
        targets,
        hidden: hidden_targets,
        wire,
        _temp: temp,
    })
}

/// Makes `dir` and closes it to every other user: the sandbox's user never reads the judge.
fn close(dir: &Path) -> Result<(), ToolError> {
    use std::os::unix::fs::PermissionsExt;
    std::fs::create_dir_all(dir).map_err(|e| ToolError::io(dir, e))?;
    std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o700))
        .map_err(|e| ToolError::io(dir, e))
}

/// Writes the copy of the project at `root` into `project` with the wire in: each file as the
/// project has it, or wired, written only when its bytes change; returns the wire.
fn write_copy(root: &Path, manifest: &Manifest, project: &Path) -> Result<Wire, ToolError> {
    let wire = plan_wire(root, manifest)?;
    let lib = layout::core_lib();
    for file in files::project_files(root)? {
        let from = root.join(&file);
        let bytes = std::fs::read(&from).map_err(|e| ToolError::io(&from, e))?;
        let bytes = match wire.files.get(&file) {
            Some(w) => {
                let text = String::from_utf8(bytes).map_err(|e| {
                    ToolError::io(
                        &from,
                        std::io::Error::new(std::io::ErrorKind::InvalidData, e),
                    )
                })?;
                w.apply(&text).into_bytes()
            }
            None if file == lib => {
                let mut b = bytes;
                b.extend_from_slice(wire.table.as_bytes());
                b
            }
            None => bytes,
        };
        files::write_if_changed(&project.join(&file), &bytes)?;
    }
    wire.write_server(project)?;
    Ok(wire)
}

/// Removes the copy's hidden tests (`tests/hidden_*.rs`) that are not of `targets`.
fn remove_stale_hidden(project: &Path, targets: &[String]) -> Result<(), ToolError> {
    let tests = project.join(layout::core_tests());
    for e in std::fs::read_dir(&tests).into_iter().flatten().flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let stem = name.strip_suffix(".rs").unwrap_or(&name);
        if name.starts_with("hidden_") && !targets.iter().any(|t| t == stem) {
            let path = e.path();
            std::fs::remove_file(&path).map_err(|err| ToolError::io(&path, err))?;
        }
    }
    Ok(())
}

/// The place of one run of the judge's tests: a directory of its own in the judge's, so that
/// gradings run beside each other against one judge; removed when dropped.
pub(super) fn run_dir(judge: &Judge) -> Result<tempfile::TempDir, ToolError> {
    let runs = judge.dir.join("runs");
    std::fs::create_dir_all(&runs).map_err(|e| ToolError::io(&runs, e))?;
    tempfile::Builder::new()
        .prefix("run-")
        .tempdir_in(&runs)
        .map_err(|e| ToolError::io(&runs, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A judge lies beside its build directory, never inside it.
    #[test]
    fn the_judge_lies_beside_the_build_directory() {
        assert_eq!(
            beside(Path::new("/srv/grading/slot-1")),
            Path::new("/srv/grading/slot-1-judge")
        );
        assert!(!beside(Path::new("/srv/build")).starts_with("/srv/build"));
    }
}
