//! The hints of an exercise, one more each time a student asks (`cargo learn hint`), with how
//! many were shown kept in `.whitted/hints.json`.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::path::Path;

use super::state::STATE_DIR;
use crate::ToolError;
use crate::manifest::{Entry, Manifest};

/// The hint levels shown so far, by exercise name (`.whitted/hints.json`).
pub fn hints_shown(root: &Path) -> BTreeMap<String, usize> {
    std::fs::read_to_string(root.join(STATE_DIR).join("hints.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_default()
}

/// Shows the next hint of exercise `index` and remembers it; once all are shown, shows them
/// all again.
pub fn next_hint(root: &Path, manifest: &Manifest, index: usize) -> Result<String, ToolError> {
    let e: &Entry = &manifest.entries[index];
    let hints = &e.exercise.hints;
    let mut shown = hints_shown(root);
    let level = shown.get(&e.exercise.name).copied().unwrap_or(0);
    let now = (level + 1).min(hints.len());
    shown.insert(e.exercise.name.clone(), now);
    let mut out = format!(
        "exercise {} — {} ({}):\n",
        e.exercise.id, e.exercise.title, e.function
    );
    for (i, h) in hints.iter().take(now).enumerate() {
        out += &format!("  hint {} of {}: {h}\n", i + 1, hints.len());
    }
    if now < hints.len() {
        out += "  (ask again for the next one)\n";
    }
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = serde_json::to_string_pretty(&shown)
        .map_err(|e| ToolError::Cargo(format!("cannot write the hints' state: {e}")))?;
    crate::files::write_file(&dir.join("hints.json"), text.as_bytes())?;
    Ok(out)
}
