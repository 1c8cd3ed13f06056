//! `cargo learn watch`: a check, then another after every save of the student's sources,
//! tests, chapters or scenes (what an editor's backup files and the compiler's reads do not
//! count as).
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::check::check;
use super::state::saved_states;
use super::style::Style;
use crate::manifest::Manifest;
use crate::{ToolError, layout};

/// Whether a changed file matters to the tests: not an editor's backup or swap file.
#[must_use]
pub fn is_source_change(path: &Path) -> bool {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    !(name.ends_with('~')
        || name.starts_with(".#")
        || name.ends_with(".swp")
        || name.ends_with(".swx")
        || name == "4913") // vim's probe file
}

/// The directories `watch` watches, relative to the project's root.
#[must_use]
pub fn watched() -> [PathBuf; 4] {
    [
        layout::core_src(),
        layout::core_tests(),
        PathBuf::from("chapters"),
        PathBuf::from("scenes"),
    ]
}

/// Each file under the watched directories with its modification time and size: what a save
/// changes. (The file watcher also reports files being read, as the compiler reads them; a
/// rerun happens only when this snapshot differs.)
#[must_use]
pub fn snapshot(root: &Path) -> BTreeMap<PathBuf, (std::time::SystemTime, u64)> {
    let mut out = BTreeMap::new();
    let mut stack: Vec<PathBuf> = watched().iter().map(|d| root.join(d)).collect();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let Ok(meta) = entry.metadata() else { continue };
            if meta.is_dir() {
                stack.push(path);
            } else if is_source_change(&path)
                && let Ok(modified) = meta.modified()
            {
                out.insert(path, (modified, meta.len()));
            }
        }
    }
    out
}

/// `whitted learn watch`: a check with its picture, then another after every save (changes
/// under [`watched`], debounced by 300 ms). Stops after `cycles` reruns when
/// given (for scripts and tests), else runs until interrupted.
pub fn watch(
    root: &Path,
    manifest: &Manifest,
    style: Style,
    cycles: Option<usize>,
) -> Result<(), ToolError> {
    use notify_debouncer_mini::notify::RecursiveMode;
    let (tx, rx) = std::sync::mpsc::channel();
    let fail = |e: notify_debouncer_mini::notify::Error| {
        ToolError::Cargo(format!("cannot watch the project's files: {e}"))
    };
    let mut debouncer =
        notify_debouncer_mini::new_debouncer(std::time::Duration::from_millis(300), tx)
            .map_err(fail)?;
    for dir in watched() {
        let path = root.join(dir);
        if path.is_dir() {
            debouncer
                .watcher()
                .watch(&path, RecursiveMode::Recursive)
                .map_err(fail)?;
        }
    }
    let mut files = snapshot(root);
    let mut known = saved_states(root, manifest);
    let mut reruns = 0;
    loop {
        let checked = check(root, manifest, &known, style, true, true)?;
        if checked.run.build_error.is_none() {
            known = checked.states;
        }
        if cycles.is_some_and(|c| reruns >= c) {
            return Ok(());
        }
        println!(
            "\nwatching {} for changes (Ctrl-C to stop)",
            watched()
                .iter()
                .map(|d| format!("{}/", d.display()))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let mut changed = false;
        while !changed {
            match rx.recv() {
                Ok(Ok(events)) if events.iter().any(|e| is_source_change(&e.path)) => {
                    while rx.try_recv().is_ok() {} // one rerun for a burst of saves
                    let now = snapshot(root);
                    changed = now != files; // a save, not a read
                    files = now;
                }
                Ok(Ok(_)) => {}
                Ok(Err(e)) => eprintln!("warning: while watching: {e}"),
                Err(_) => return Ok(()), // the watcher is gone
            }
        }
        reruns += 1;
        println!();
    }
}
