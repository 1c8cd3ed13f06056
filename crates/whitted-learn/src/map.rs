//! The map of which tests of a handout need which exercises, `chapters/exercise-tests.toml`:
//! measured by the instructor's tools (`whitted formulas deps --write`, see the course crate's
//! `deps`), read here. `learn` finds in it the test target that decides each exercise.
//!
//! Each `[[tests]]` table names tests (as `target::name`, or a prefix of it) and the exercises
//! they run, by name: without any one of those, each of the tests fails. Names, not displayed
//! ids, so that inserting an exercise leaves every table as it is.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeSet;
use std::path::Path;

use crate::ToolError;
use crate::manifest::Manifest;

pub use crate::cargo::TestId;

/// Where the map of tests to exercises lives, relative to the project's root.
pub const MAP_PATH: &str = "chapters/exercise-tests.toml";

/// One `[[tests]]` table of the map: tests and the exercises (manifest indices) they run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Group {
    /// The tests, as `target::name` or prefixes of it (`render_paths::ch3_`).
    pub tests: Vec<String>,
    /// The exercises they need, as manifest indices.
    pub needs: Vec<usize>,
}

impl Group {
    /// Whether the test `target::name` is one of these.
    #[must_use]
    pub fn matches(&self, test: &str) -> bool {
        self.tests.iter().any(|t| test.starts_with(t.as_str()))
    }
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMap {
    #[serde(default)]
    tests: Vec<toml::Spanned<RawGroup>>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGroup {
    tests: toml::Spanned<Vec<String>>,
    needs: toml::Spanned<Vec<String>>,
}

/// Reads the map text `text` (`file` names it in messages) against the manifest's exercises;
/// in a handout of some chapters, the exercises it leaves out are no test's needs.
pub fn parse_map(text: &str, file: &str, manifest: &Manifest) -> Result<Vec<Group>, ToolError> {
    let err = |span: std::ops::Range<usize>, message: String| {
        crate::manifest::error_at(text, file, span, message)
    };
    let raw: RawMap = crate::manifest::from_toml(text, file)?;
    let mut groups = Vec::new();
    for g in &raw.tests {
        let g = g.get_ref();
        if g.tests.get_ref().is_empty() || g.tests.get_ref().iter().any(|t| !t.contains("::")) {
            return Err(err(
                g.tests.span(),
                "tests: expected tests as target::name or prefixes of it (render_paths::ch3_)"
                    .into(),
            ));
        }
        let mut needs = Vec::new();
        for name in g.needs.get_ref() {
            // an exercise the handout leaves out is never missing: earlier chapters' code is
            // given, and no test of a later chapter is in the handout
            if manifest.is_left_out(name.trim()) {
                continue;
            }
            let found = manifest.by_name(name.trim()).ok_or_else(|| {
                err(
                    g.needs.span(),
                    format!(
                        "needs: {name:?} names no exercise of {} (the exercises' `name`s, such as \"viewing_basis\")",
                        manifest.file
                    ),
                )
            })?;
            needs.push(found);
        }
        needs.sort_unstable();
        needs.dedup();
        groups.push(Group {
            tests: g.tests.get_ref().clone(),
            needs,
        });
    }
    Ok(groups)
}

/// Reads [`MAP_PATH`] under `root`.
pub fn load_map(root: &Path, manifest: &Manifest) -> Result<Vec<Group>, ToolError> {
    let path = root.join(MAP_PATH);
    let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    parse_map(&text, MAP_PATH, manifest)
}

/// The exercises the test `target::name` needs, by the map.
#[must_use]
pub fn needs_of(map: &[Group], test: &str) -> BTreeSet<usize> {
    map.iter()
        .filter(|g| g.matches(test))
        .flat_map(|g| g.needs.iter().copied())
        .collect()
}

/// Of `tests`, those the map says fail when the exercises `stripped` (manifest indices) are
/// missing.
#[must_use]
pub fn expected(map: &[Group], tests: &BTreeSet<TestId>, stripped: &[usize]) -> BTreeSet<TestId> {
    tests
        .iter()
        .filter(|t| needs_of(map, t).iter().any(|i| stripped.contains(i)))
        .cloned()
        .collect()
}
