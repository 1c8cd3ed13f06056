//! The project's files as the course tools read, write and copy them: a place in a text as
//! `line:col`, files written atomically or only when they change, and the project's files
//! (what git lists) copied or kept in step with a copy, for the proof, the dependency
//! measurement, handouts, grading and the loop's benchmark.
//!
//! The course crates do not depend on the renderer (a student's edit must never rebuild
//! them), so they keep these small helpers of their own.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::ToolError;

pub use whitted_syllabus::words::line_col;

/// Writes `bytes` to `path` through a temporary file in the same directory, renamed into
/// place: a reader sees the old file or the whole new one, and a failure leaves the old one.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ToolError> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".whitted-")
        .tempfile_in(dir)
        .map_err(|e| ToolError::io(dir, e))?;
    tmp.write_all(bytes)
        .and_then(|()| tmp.as_file().sync_all())
        .map_err(|e| ToolError::io(path, e))?;
    #[cfg(unix)]
    {
        // a temporary file is private (0600); the result should be as readable as any new file
        use std::os::unix::fs::PermissionsExt;
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(0o644))
            .map_err(|e| ToolError::io(path, e))?;
    }
    tmp.persist(path)
        .map_err(|e| ToolError::io(path, e.error))?;
    Ok(())
}

/// The files to copy, relative to `root`: what git lists (tracked, or untracked and not
/// ignored), or else every file outside `target/` and `.git/`.
pub fn project_files(root: &Path) -> Result<Vec<PathBuf>, ToolError> {
    let listed = Command::new("git")
        .args([
            "ls-files",
            "-z",
            "--cached",
            "--others",
            "--exclude-standard",
        ])
        .current_dir(root)
        .stderr(Stdio::null())
        .output();
    if let Ok(out) = listed
        && out.status.success()
    {
        let text = String::from_utf8_lossy(&out.stdout);
        return Ok(text
            .split('\0')
            .filter(|p| !p.is_empty())
            .map(PathBuf::from)
            .filter(|p| root.join(p).is_file())
            .collect());
    }
    let mut files = Vec::new();
    walk(root, Path::new(""), &mut files)?;
    Ok(files)
}

/// Every file under `root.join(dir)`, outside `target/` and `.git/`, relative to `root`.
fn walk(root: &Path, dir: &Path, files: &mut Vec<PathBuf>) -> Result<(), ToolError> {
    let full = root.join(dir);
    for entry in std::fs::read_dir(&full).map_err(|e| ToolError::io(&full, e))? {
        let entry = entry.map_err(|e| ToolError::io(&full, e))?;
        let name = entry.file_name();
        let relative = dir.join(&name);
        let kind = entry.file_type().map_err(|e| ToolError::io(&relative, e))?;
        if kind.is_dir() {
            if name != "target" && name != ".git" {
                walk(root, &relative, files)?;
            }
        } else if root.join(&relative).is_file() {
            files.push(relative);
        }
    }
    Ok(())
}

/// Copies the project's files from `root` to `dest`; returns how many.
pub fn copy_project(root: &Path, dest: &Path) -> Result<usize, ToolError> {
    copy_files(root, dest, &project_files(root)?)
}

/// Copies every file under `from` to the same place under `to`; returns how many.
pub fn copy_tree(from: &Path, to: &Path) -> Result<usize, ToolError> {
    let mut files = Vec::new();
    walk(from, Path::new(""), &mut files)?;
    copy_files(from, to, &files)
}

/// Copies `files` (relative) from under `from` to the same places under `to`, creating the
/// directories; returns how many.
fn copy_files(from: &Path, to: &Path, files: &[PathBuf]) -> Result<usize, ToolError> {
    for file in files {
        let dest = to.join(file);
        if let Some(parent) = dest.parent() {
            std::fs::create_dir_all(parent).map_err(|e| ToolError::io(parent, e))?;
        }
        std::fs::copy(from.join(file), &dest).map_err(|e| ToolError::io(from.join(file), e))?;
    }
    Ok(files.len())
}

/// Makes `dest` a copy of the project's files at `root`, writing only the files that are
/// missing or differ, so that cargo (which goes by modification times) rebuilds only what
/// changed since the last copy, and removing the files the project no longer has (but those
/// under `keep`, relative to `dest`); returns how many files it wrote. A file for which
/// `whole` says no is copied empty: it exists (cargo wants every target a manifest names to
/// exist) and says nothing.
pub fn sync_project(
    root: &Path,
    dest: &Path,
    keep: &[&str],
    whole: &dyn Fn(&Path) -> bool,
) -> Result<usize, ToolError> {
    let files = project_files(root)?;
    let mut written = 0;
    for file in &files {
        let bytes = if whole(file) {
            std::fs::read(root.join(file)).map_err(|e| ToolError::io(root.join(file), e))?
        } else {
            Vec::new()
        };
        if write_if_changed(&dest.join(file), &bytes)? {
            written += 1;
        }
    }
    if dest.is_dir() {
        let mut present = Vec::new();
        walk(dest, Path::new(""), &mut present)?;
        for stale in present.iter().filter(|p| !files.contains(p)) {
            if !keep.iter().any(|k| stale.starts_with(k)) {
                let path = dest.join(stale);
                std::fs::remove_file(&path).map_err(|e| ToolError::io(&path, e))?;
            }
        }
    }
    Ok(written)
}

/// Writes `bytes` to `path` unless it holds them already (creating its directory); returns
/// whether it wrote.
pub fn write_if_changed(path: &Path, bytes: &[u8]) -> Result<bool, ToolError> {
    if std::fs::read(path).is_ok_and(|now| now == bytes) {
        return Ok(false);
    }
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| ToolError::io(parent, e))?;
    }
    std::fs::write(path, bytes).map_err(|e| ToolError::io(path, e))?;
    Ok(true)
}
