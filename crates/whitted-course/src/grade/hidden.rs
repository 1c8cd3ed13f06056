//! The instructor's hidden tests, read before anything is graded: every `#[test]` function of
//! a hidden file must be an exercise's (`ex_NAME_…`, NAME an exercise of the manifest), since
//! a test of no exercise would count for nothing without a word. A file that does not parse,
//! or a test named after no exercise, stops the grading with its file, line and column: an
//! instructor's mistake never changes a grade silently, and nothing of it reaches a student.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use crate::ToolError;
use crate::manifest::Manifest;

/// Checks every hidden test file of the directory `dir` against the manifest (see the
/// module's documentation); the first problem is a [`ToolError::Usage`] at its place.
pub fn check(manifest: &Manifest, dir: &Path) -> Result<(), ToolError> {
    for file in super::splice::hidden_files(dir)? {
        let text = std::fs::read_to_string(&file).map_err(|e| ToolError::io(&file, e))?;
        let name = file.display().to_string();
        let parsed = crate::source::parse(&text, &name).map_err(ToolError::Usage)?;
        let mut tests = Vec::new();
        tests_of(&parsed.items, &mut tests);
        for (test, line, col) in tests {
            if !manifest
                .entries
                .iter()
                .any(|e| test.starts_with(&e.exercise.test_prefix()))
            {
                return Err(ToolError::Usage(format!(
                    "{name}:{line}:{col}: hidden test `{test}` is named after no exercise, so \
                     its points would count for nothing: name it ex_EXERCISE_… after one of \
                     the exercises of {} (ex_sphere_discriminant_…)",
                    manifest.file
                )));
            }
        }
    }
    Ok(())
}

/// The `#[test]` functions of `items` and of the modules they hold: name, line, column (from 1).
fn tests_of(items: &[syn::Item], out: &mut Vec<(String, usize, usize)>) {
    for item in items {
        match item {
            syn::Item::Fn(f) if f.attrs.iter().any(|a| a.path().is_ident("test")) => {
                let at = f.sig.ident.span().start();
                out.push((f.sig.ident.to_string(), at.line, at.column + 1));
            }
            syn::Item::Mod(m) => {
                if let Some((_, inner)) = &m.content {
                    tests_of(inner, out);
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_test_of_no_exercise_is_refused_at_its_place() {
        let m = whitted_learn::manifest::load(
            &Path::new(env!("CARGO_MANIFEST_DIR")).join("../../chapters/formulas.toml"),
        )
        .unwrap();
        let dir = tempfile::tempdir().unwrap();
        let good = "#[test]\nfn ex_sphere_discriminant_hidden_one() {}\nmod more {\n    #[test]\n    fn ex_ambient_hidden() {}\n}\nfn helper() {}\n";
        std::fs::write(dir.path().join("a.rs"), good).unwrap();
        check(&m, dir.path()).unwrap();
        let bad = "mod more {\n    #[test]\n    fn sphere_discriminant_forgot_the_prefix() {}\n}\n";
        std::fs::write(dir.path().join("b.rs"), bad).unwrap();
        let err = check(&m, dir.path()).unwrap_err().to_string();
        let at = format!(
            "{}:3:8: hidden test `sphere_discriminant_forgot_the_prefix` is named after no exercise",
            dir.path().join("b.rs").display()
        );
        assert!(
            err.starts_with(&at),
            "computed {err:?}, expected it to start with {at:?}"
        );
        std::fs::write(dir.path().join("b.rs"), "fn (").unwrap();
        let err = check(&m, dir.path()).unwrap_err().to_string();
        assert!(
            err.contains("b.rs:1:") && err.contains("cannot parse"),
            "{err}"
        );
    }
}
