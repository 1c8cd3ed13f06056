//! The course's known mistakes: the hand-written mutants of
//! `crates/whitted-course/tests/mutants/hand-written.toml`, each a small wrong change to one
//! exercise's reference body (the text `find` in its solution region becomes `replace`), with
//! the words that say what it is (`why`).
//!
//! `whitted trees` applies each to the reference, renders its chapter and compares the trees,
//! and keeps its fingerprint in `chapters/mistakes.json` for `cargo learn` (the words and the
//! numbers only: never `find` or `replace`). To build once for all of them, a copy of the
//! project holds every mutant behind a switch ([`switch`]): each solution region that has
//! mutants becomes
//!
//! ```text
//! // BEGIN SOLUTION normal_to_world
//! if crate::__mutant::on("normals-by-m") {
//!     …the body with `find` replaced…
//! } else {
//!     …the reference body…
//! }
//! // END SOLUTION
//! ```
//!
//! and the renderer's `lib.rs` gets the hidden module `__mutant`, whose `on(name)` is true when
//! the environment variable [`SWITCH_VAR`] holds that name. The mutated code is exactly the
//! mutant's; a solution region is always the tail of its function's body, so both branches
//! are that body.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::handout::{self, Region};
use crate::manifest::Manifest;
use crate::{ToolError, layout};

/// Where the hand-written mutants are listed, relative to the project's root.
pub const MUTANTS: &str = "crates/whitted-course/tests/mutants/hand-written.toml";

/// The environment variable that names the mutant switched on in a copy made by [`switch`].
pub const SWITCH_VAR: &str = "WHITTED_MUTANT";

/// The module appended to the copy's `src/lib.rs`.
pub const SWITCH_MODULE: &str = r#"
/// The mutant switch of `whitted trees`; it exists only in the copy that holds the mutants.
#[doc(hidden)]
pub mod __mutant {
    /// Whether the mutant `name` is switched on: `WHITTED_MUTANT` names it (read once).
    pub fn on(name: &str) -> bool {
        static ON: std::sync::OnceLock<String> = std::sync::OnceLock::new();
        ON.get_or_init(|| std::env::var("WHITTED_MUTANT").unwrap_or_default()) == name
    }
}
"#;

/// One hand-written mutant.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mutant {
    /// Its name (`normals-by-m`).
    pub name: String,
    /// The exercise it changes, by name.
    pub exercise: String,
    /// What the mistake is, in words.
    pub why: String,
    /// The text of the reference body it replaces.
    pub find: String,
    /// What it puts there.
    pub replace: String,
    /// Why its chapter's scene cannot show it, when it cannot: then no kept number and no
    /// pixel of the chapter's picture moves, its own tests alone catch it, and `whitted trees
    /// --check` accepts that it has no fingerprint. Every other mutant must have one.
    #[serde(default)]
    pub unseen: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MutantsFile {
    mutant: Vec<Mutant>,
}

/// The hand-written mutants of the project at `root` ([`MUTANTS`]).
pub fn load(root: &Path) -> Result<Vec<Mutant>, ToolError> {
    let path = root.join(MUTANTS);
    let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    Ok(crate::manifest::from_toml::<MutantsFile>(&text, MUTANTS)?.mutant)
}

/// The body of `region` with `mutant` applied; an error when its `find` is not in the body.
pub fn mutated(region: &Region, mutant: &Mutant) -> Result<String, ToolError> {
    if !region.solution.contains(&mutant.find) {
        return Err(ToolError::Markers(format!(
            "{MUTANTS}: mutant {}: `{}` is not in exercise {}'s body ({})",
            mutant.name,
            mutant.find,
            mutant.exercise,
            region.file.display()
        )));
    }
    Ok(region.solution.replacen(&mutant.find, &mutant.replace, 1))
}

/// The text of each source file of the project at `project` that holds a mutated exercise,
/// every mutant of `mutants` behind its switch (see the module's documentation). The regions
/// are found in `project` itself, so a copy whose functions are poisoned (`whitted formulas
/// prove`'s switch) takes the mutants too.
pub fn switched_sources(
    project: &Path,
    manifest: &Manifest,
    mutants: &[Mutant],
) -> Result<BTreeMap<PathBuf, String>, ToolError> {
    let regions = handout::regions(project, manifest)?;
    let mut by_region: BTreeMap<usize, Vec<&Mutant>> = BTreeMap::new();
    for m in mutants {
        let entry = manifest.by_name(&m.exercise).ok_or_else(|| {
            ToolError::Usage(format!(
                "{MUTANTS}: mutant {}: no exercise is named {}",
                m.name, m.exercise
            ))
        })?;
        by_region.entry(entry).or_default().push(m);
    }
    let mut files: BTreeMap<PathBuf, String> = BTreeMap::new();
    // from the last region of each file to the first, so that the offsets before stay right
    let mut order: Vec<(&Region, Vec<&Mutant>)> = by_region
        .into_iter()
        .map(|(entry, ms)| (&regions[entry], ms))
        .collect();
    order.sort_by_key(|(r, _)| (r.file.clone(), std::cmp::Reverse(r.bytes.start)));
    for (region, ms) in order {
        let text = match files.get(&region.file) {
            Some(t) => t.clone(),
            None => {
                let path = project.join(&region.file);
                std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?
            }
        };
        let start = region.bytes.start + text[region.bytes.start..].find('\n').map_or(0, |i| i + 1);
        let end = start + region.solution.len();
        let tail = text[region.bytes.end..].trim_start();
        if text.get(start..end) != Some(region.solution.as_str()) || !tail.starts_with('}') {
            return Err(ToolError::Markers(format!(
                "{}: exercise {}'s solution region is not the tail of its function's body: its mutants cannot be switched",
                region.file.display(),
                ms[0].exercise
            )));
        }
        let indent = &region.indent;
        let mut switched = String::new();
        for (k, m) in ms.iter().enumerate() {
            let keyword = if k == 0 { "if" } else { "} else if" };
            switched += &format!(
                "{indent}{keyword} crate::__mutant::on({:?}) {{\n{}",
                m.name,
                mutated(region, m)?
            );
        }
        switched += &format!("{indent}}} else {{\n{}{indent}}}\n", region.solution);
        let mut edited = text;
        edited.replace_range(start..end, &switched);
        files.insert(region.file.clone(), edited);
    }
    Ok(files)
}

/// Puts every mutant of `mutants` behind its switch in the copy of the project at `project`
/// (its sources are edited in place, and the switch module appended to the renderer's
/// `lib.rs`). Nothing changes until [`SWITCH_VAR`] names a mutant.
pub fn switch(project: &Path, manifest: &Manifest, mutants: &[Mutant]) -> Result<(), ToolError> {
    for (file, text) in switched_sources(project, manifest, mutants)? {
        let path = project.join(file);
        std::fs::write(&path, text).map_err(|e| ToolError::io(&path, e))?;
    }
    let lib = project.join(layout::core_lib());
    let mut text = std::fs::read_to_string(&lib).map_err(|e| ToolError::io(&lib, e))?;
    text.push_str(SWITCH_MODULE);
    std::fs::write(&lib, text).map_err(|e| ToolError::io(&lib, e))
}
