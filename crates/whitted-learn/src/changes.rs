//! What the student changed since the last check: the exercises whose text between
//! `// BEGIN SOLUTION NAME` and `// END SOLUTION` differs from the text the last complete check
//! saw (`.whitted/regions.json`). `cargo learn` checks those exercises first, so that the
//! verdict on what was just saved comes at once: a finished exercise that breaks, or one that
//! now passes.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::learn::STATE_DIR;
use crate::manifest::Manifest;
use crate::{ToolError, layout};

/// The file, under [`STATE_DIR`], that keeps the regions of the last complete check.
pub const REGIONS: &str = "regions.json";

/// The text of every exercise's region in the renderer's sources, by exercise name (the lines
/// between its markers, as they stand).
#[must_use]
pub fn regions(root: &Path) -> BTreeMap<String, String> {
    located(root)
        .into_iter()
        .map(|r| (r.name, r.body))
        .collect()
}

/// An exercise's region as it stands in the student's sources.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Located {
    /// The exercise's name.
    pub name: String,
    /// The source file, relative to the project.
    pub file: PathBuf,
    /// The line of the body's first line in the file (the line after BEGIN), from 1.
    pub line: usize,
    /// The lines between its markers, joined by newlines.
    pub body: String,
}

/// Every exercise's region in the renderer's sources, where it stands, in file order.
#[must_use]
pub fn located(root: &Path) -> Vec<Located> {
    let mut out = Vec::new();
    for path in sources(root) {
        if let Ok(text) = std::fs::read_to_string(&path) {
            let file = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
            read_regions(&text, &file, &mut out);
        }
    }
    out
}

/// The renderer's `.rs` sources, where the exercises' regions are, sorted; unreadable
/// directories are skipped.
#[must_use]
pub fn sources(root: &Path) -> Vec<PathBuf> {
    let mut stack: Vec<PathBuf> = vec![root.join(layout::core_src())];
    let mut files = Vec::new();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for path in entries.flatten().map(|e| e.path()) {
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// Adds the regions of the source `text` (of `file`) to `out`.
fn read_regions(text: &str, file: &Path, out: &mut Vec<Located>) {
    let mut open: Option<(String, usize, Vec<&str>)> = None;
    for (n, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if let Some(name) = trimmed.strip_prefix(layout::BEGIN) {
            open = Some((name.trim().to_string(), n + 2, Vec::new()));
        } else if trimmed == layout::END {
            if let Some((name, first, lines)) = open.take() {
                out.push(Located {
                    name,
                    file: file.to_path_buf(),
                    line: first,
                    body: lines.join("\n"),
                });
            }
        } else if let Some((_, _, lines)) = &mut open {
            lines.push(line);
        }
    }
}

/// The regions the last complete check saw (empty before the first).
#[must_use]
pub fn saved(root: &Path) -> BTreeMap<String, String> {
    std::fs::read_to_string(root.join(STATE_DIR).join(REGIONS))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_default()
}

/// Keeps `regions` for the next check.
pub fn save(root: &Path, regions: &BTreeMap<String, String>) -> Result<(), ToolError> {
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = serde_json::to_string(regions)
        .map_err(|e| ToolError::Cargo(format!("cannot write the regions: {e}")))?;
    crate::files::write_file(&dir.join(REGIONS), text.as_bytes())
}

/// The exercises (manifest indices, in order) whose region in `now` differs from `before`;
/// none when nothing was saved before (a first check has nothing to compare with).
#[must_use]
pub fn touched(
    manifest: &Manifest,
    before: &BTreeMap<String, String>,
    now: &BTreeMap<String, String>,
) -> Vec<usize> {
    if before.is_empty() {
        return Vec::new();
    }
    (0..manifest.entries.len())
        .filter(|&i| {
            let name = &manifest.entries[i].exercise.name;
            before.get(name) != now.get(name)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A manifest of two exercises, `first` and `second`.
    fn two() -> Manifest {
        let entry = |function: &str, name: &str| {
            format!(
                "[[formula]]\nfunction = \"{function}\"\nname = \"{name}\"\nchapter = 3\n\
                 section = \"Shading\"\nformula = \"x\"\ntitle = \"T\"\ntask = \"Do it.\"\n\
                 hints = [\"One.\", \"Two.\"]\npoints = 1\n"
            )
        };
        let text = format!(
            "[prove]\ntest = \"render_paths\"\nfilter = \"ch{{chapter}}_\"\n{}{}\
             [handout]\ntests = [\"ch03_shading\", \"render_paths\"]\n",
            entry("shading::a", "first"),
            entry("shading::b", "second")
        );
        crate::manifest::parse(&text, "m.toml").unwrap()
    }

    /// The exercises whose region differs from the last check's are touched, in the manifest's
    /// order; a first check (nothing saved) touches none, and an exercise whose region went
    /// missing is touched.
    #[test]
    fn the_exercises_whose_region_changed_are_touched() {
        let m = two();
        let map = |a: &str, b: &str| -> BTreeMap<String, String> {
            [("first", a), ("second", b)]
                .into_iter()
                .filter(|(_, v)| !v.is_empty())
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        };
        let before = map("todo!()", "todo!()");
        assert_eq!(touched(&m, &BTreeMap::new(), &before), Vec::<usize>::new());
        assert_eq!(touched(&m, &before, &before), Vec::<usize>::new());
        assert_eq!(touched(&m, &before, &map("todo!()", "x + 1")), vec![1]);
        assert_eq!(touched(&m, &before, &map("1.0", "x + 1")), vec![0, 1]);
        assert_eq!(touched(&m, &before, &map("todo!()", "")), vec![1]);
    }

    /// A region is the text between its markers, its first line the one after BEGIN; text
    /// outside any region is no exercise's.
    #[test]
    fn a_region_is_the_text_between_its_markers() {
        let text = "fn a() {\n    // BEGIN SOLUTION first\n    1 + 1\n    // END SOLUTION\n}\n\
                    fn b() {\n    let x = 2;\n    // BEGIN SOLUTION second\n    x\n    // END SOLUTION\n}\n";
        let mut out = Vec::new();
        read_regions(text, Path::new("f.rs"), &mut out);
        assert_eq!(
            out.into_iter()
                .map(|r| (r.name, r.line, r.body))
                .collect::<Vec<_>>(),
            vec![
                ("first".to_string(), 3, "    1 + 1".to_string()),
                ("second".to_string(), 9, "    x".to_string())
            ]
        );
    }
}
