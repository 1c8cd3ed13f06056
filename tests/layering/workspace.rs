//! The workspace as the checks see it: its root, the root file of every crate its members build
//! (libraries, binaries, tests, benchmarks, examples: those their manifests name and those cargo
//! finds by convention), every Rust source file, and which files are test files.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::modules::normalize;
use crate::syntax::only_in_tests;

/// The workspace's root: this package is its `tests/`.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ sits in the workspace's root")
        .to_path_buf()
}

/// A file's text, from the disk.
pub fn disk(path: &Path) -> Option<String> {
    std::fs::read_to_string(path).ok()
}

/// A TOML file, parsed.
fn manifest(path: &Path) -> toml::Table {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.parse()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The root file of every crate the workspace's members build.
pub fn crate_roots(root: &Path) -> Vec<PathBuf> {
    let workspace = manifest(&root.join("Cargo.toml"));
    let members = workspace["workspace"]["members"]
        .as_array()
        .expect("the workspace lists its members");
    let mut roots = BTreeSet::new();
    for member in members {
        let dir = root.join(member.as_str().expect("a member is a path"));
        roots.extend(member_roots(&dir, &manifest(&dir.join("Cargo.toml"))));
    }
    roots.into_iter().map(|p| normalize(&p)).collect()
}

/// The root files of one member's crates (`dir` holds its manifest, `package`).
fn member_roots(dir: &Path, package: &toml::Table) -> Vec<PathBuf> {
    let mut roots = Vec::new();
    let auto = |key: &str| {
        package
            .get("package")
            .and_then(|p| p.get(key))
            .and_then(toml::Value::as_bool)
            != Some(false)
    };
    // what the manifest names
    if let Some(path) = package
        .get("lib")
        .and_then(|l| l.get("path"))
        .and_then(toml::Value::as_str)
    {
        roots.push(dir.join(path));
    } else if dir.join("src/lib.rs").is_file() {
        roots.push(dir.join("src/lib.rs"));
    }
    for (kind, default_dir) in [
        ("bin", "src/bin"),
        ("test", "tests"),
        ("bench", "benches"),
        ("example", "examples"),
    ] {
        for target in package
            .get(kind)
            .and_then(toml::Value::as_array)
            .into_iter()
            .flatten()
        {
            match (
                target.get("path").and_then(toml::Value::as_str),
                target.get("name").and_then(toml::Value::as_str),
            ) {
                (Some(path), _) => roots.push(dir.join(path)),
                (None, Some(name)) => roots.push(dir.join(default_dir).join(format!("{name}.rs"))),
                (None, None) => {}
            }
        }
    }
    // what cargo finds by convention
    if auto("autobins") {
        if dir.join("src/main.rs").is_file() {
            roots.push(dir.join("src/main.rs"));
        }
        roots.extend(conventional(&dir.join("src/bin")));
    }
    for (key, sub) in [
        ("autotests", "tests"),
        ("autobenches", "benches"),
        ("autoexamples", "examples"),
    ] {
        if auto(key) {
            roots.extend(conventional(&dir.join(sub)));
        }
    }
    roots
}

/// The targets cargo finds in a directory by convention: `name.rs` and `name/main.rs`.
fn conventional(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for entry in entries {
        let path = entry.expect("a readable directory").path();
        if path.is_dir() && path.join("main.rs").is_file() {
            out.push(path.join("main.rs"));
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
    out
}

/// Every `.rs` file under `dir`, recursively, build output (`target/`) and hidden directories
/// left out.
pub fn rust_sources(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("a readable directory") {
        let path = entry.expect("a readable entry").path();
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        if path.is_dir() {
            if name != "target" && !name.starts_with('.') {
                out.extend(rust_sources(&path));
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
    out.sort();
    out
}

/// Whether a file, by its path inside the workspace, is a test file: it sits under a `tests/`
/// directory.
pub fn under_tests(relative: &Path) -> bool {
    relative
        .parent()
        .is_some_and(|p| p.components().any(|c| c.as_os_str() == "tests"))
}

/// Whether a file's text holds test code only: it opens with `#![cfg(test)]`, or every item in
/// it is `#[cfg(test)]` (a `tests.rs` holding one `#[cfg(test)] mod tests { … }`).
pub fn only_test_code(text: &str) -> bool {
    let Ok(file) = syn::parse_file(text) else {
        return false;
    };
    only_in_tests(&file.attrs)
        || (!file.items.is_empty()
            && file
                .items
                .iter()
                .all(|item| only_in_tests(crate::modules::attrs(item))))
}
