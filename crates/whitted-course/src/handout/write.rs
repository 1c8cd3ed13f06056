//! Writing a handout: every file the handout holds, each as its [`Part`] says, into a
//! temporary directory renamed into place at the end.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::later::{
    cut_later_sections, handout_manifest, last_chapter, later_golden, later_statement, tests_up_to,
};
use super::parts::{Part, part_of};
use super::regions::{Region, regions};
use super::student_readme::student_readme;
use super::todo::{allow_unused, strip, todo_statement};
use super::workspace::{cargo_config, workspace_manifest};
use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// What [`write()`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Handout {
    /// The exercises taken out (manifest indices).
    pub stripped: Vec<usize>,
    /// How many files were written.
    pub files: usize,
}

/// Writes the handout of `root`'s project into `out`, which must not exist or be an empty
/// directory: the exercises `selected` (manifest indices) become `todo!()`. When they are not
/// all of them, the handout's manifest lists them as its own (`[handout] exercises`), and when
/// a chapter comes after the last of them, that chapter's bodies, test targets, tests and
/// golden images are taken out too ([`super::later`]).
pub fn write(
    root: &Path,
    manifest: &Manifest,
    selected: &[usize],
    out: &Path,
) -> Result<Handout, ToolError> {
    if out.exists() {
        let empty = std::fs::read_dir(out)
            .map(|mut d| d.next().is_none())
            .unwrap_or(false);
        if !empty {
            return Err(ToolError::Usage(format!(
                "{} exists and is not an empty directory: give a new directory for the handout",
                out.display()
            )));
        }
    }
    let regions = regions(root, manifest)?;
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&parent).map_err(|e| ToolError::io(&parent, e))?;
    let temp = tempfile::Builder::new()
        .prefix(".whitted-handout-")
        .tempdir_in(&parent)
        .map_err(|e| ToolError::io(&parent, e))?;
    let files = files::project_files(root)?;
    let mut selected = selected.to_vec();
    selected.sort_unstable();
    selected.dedup();
    let selected = &selected[..];
    let last = last_chapter(manifest, selected);
    let tests = &match last {
        Some(last) => tests_up_to(&manifest.handout.tests, last),
        None => manifest.handout.tests.clone(),
    };
    let later = |i: usize| last.is_some_and(|last| manifest.entries[i].chapter > last);
    let mut edits: BTreeMap<PathBuf, Vec<(&Region, String)>> = BTreeMap::new();
    for r in &regions {
        let e = &manifest.entries[r.entry];
        let statement = if selected.contains(&r.entry) {
            todo_statement(e)
        } else if later(r.entry) {
            later_statement(e)
        } else {
            continue;
        };
        edits
            .entry(r.file.clone())
            .or_default()
            .push((r, statement));
    }
    // a handout of some exercises says which are the student's: the loop counts those alone
    let own = (!selected.is_empty() && selected.len() < manifest.entries.len()).then(|| {
        selected
            .iter()
            .map(|&i| manifest.entries[i].exercise.name.as_str())
            .collect::<Vec<&str>>()
    });
    let manifest_file = Path::new(crate::manifest::DEFAULT_PATH);
    let test_dir = layout::core_tests();
    let lib = layout::core_lib();
    let mut written = 0;
    let mut pages = Vec::new();
    for file in &files {
        let part = part_of(file, tests, root);
        if part == Part::Left || last.is_some_and(|last| later_golden(file, last)) {
            continue;
        }
        let from = root.join(file);
        let to = temp.path().join(file);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).map_err(|e| ToolError::io(dir, e))?;
        }
        let read = || std::fs::read_to_string(&from).map_err(|e| ToolError::io(&from, e));
        let text = match part {
            Part::Workspace => Some(workspace_manifest(&read()?)?),
            Part::Readme => Some(student_readme(root, manifest, selected)?),
            Part::CargoConfig => Some(cargo_config(&read()?)?),
            Part::Page => {
                pages.push(file.clone());
                None
            }
            _ if file == manifest_file && own.is_some() => Some(handout_manifest(
                &read()?,
                crate::manifest::DEFAULT_PATH,
                tests,
                own.as_deref().unwrap_or_default(),
            )?),
            _ if file.starts_with(&test_dir) && file.extension().is_some_and(|x| x == "rs") => {
                match last {
                    Some(last) => Some(cut_later_sections(&read()?, file, last)?),
                    None => None,
                }
            }
            _ => match edits.get(file) {
                Some(rs) => Some(strip(&read()?, rs, manifest)),
                None if *file == lib && !selected.is_empty() => Some(read()?),
                None => None,
            },
        };
        match text {
            Some(mut t) => {
                if *file == lib && !selected.is_empty() {
                    t = allow_unused(&t);
                }
                std::fs::write(&to, t).map_err(|e| ToolError::io(&to, e))?;
            }
            None => {
                std::fs::copy(&from, &to).map_err(|e| ToolError::io(&from, e))?;
            }
        }
        written += 1;
    }
    // the book's pages last: what they include is the handout's own code, exercises taken out
    for page in &pages {
        let to = temp.path().join(page);
        let text = std::fs::read_to_string(root.join(page)).map_err(|e| ToolError::io(page, e))?;
        let dir = to.parent().unwrap_or(temp.path());
        let mut expanded = crate::book::expand_includes(&text, dir)
            .map_err(|why| ToolError::Project(format!("{}: {why}", page.display())))?;
        if page.file_name().is_some_and(|n| n == "SUMMARY.md") {
            expanded = without_instructors(&expanded);
        }
        std::fs::write(&to, expanded).map_err(|e| ToolError::io(&to, e))?;
    }
    prune_lock(temp.path());
    let kept = temp.keep();
    if out.exists() {
        std::fs::remove_dir(out).map_err(|e| ToolError::io(out, e))?;
    }
    std::fs::rename(&kept, out).map_err(|e| ToolError::io(out, e))?;
    Ok(Handout {
        stripped: selected.to_vec(),
        files: written,
    })
}

/// Lets cargo drop from the handout's `Cargo.lock` the packages that only the instructor's
/// crates use (`cargo metadata --offline`, which resolves from the lock without the network),
/// so that the student's first build leaves the lock as it is. Resolving reads every package's
/// manifest, the other platforms' too (Windows' and macOS' crates), so it needs them
/// downloaded; if cargo cannot, the lock stays as copied, and the first build prunes it.
fn prune_lock(project: &Path) {
    let pruned = crate::cargo::command(project, None, true)
        .args(["metadata", "--offline", "--format-version", "1"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status();
    if !pruned.is_ok_and(|s| s.success()) {
        eprintln!(
            "warning: cargo could not prune the handout's Cargo.lock offline (`cargo fetch` in \
             the project downloads every platform's packages); the student's first build prunes it"
        );
    }
}

/// `SUMMARY.md` without the section for instructors (a handout has no instructor's guide).
fn without_instructors(summary: &str) -> String {
    let mut out = String::new();
    let mut skipping = false;
    for line in summary.lines() {
        if line.starts_with("# ") {
            skipping = line.contains("nstructor");
        }
        if !skipping && !line.contains("instructor-guide.md") {
            out += line;
            out.push('\n');
        }
    }
    out
}
