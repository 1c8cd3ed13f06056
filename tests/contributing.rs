//! CONTRIBUTING.md's recipes list the files to touch to add a shape, a grading platform or a
//! tree quantity; this keeps those lists true. Each list sits between two HTML comments,
//!
//! ```text
//! <!-- shape: sphere spheres | plane planes | cylinder cylinders | cone cones | polyhedron polyhedra -->
//! - `crates/whitted/src/shapes/mod.rs` …
//! <!-- end shape -->
//! ```
//!
//! the first naming the things the list is about (each with its forms, `|` between things),
//! and its files are the bullets that open with a path in backticks. The rule: the files of
//! the repository, outside its `tests/` directories, that name every one of those things
//! are exactly the files listed. A file names a thing when one of its forms appears in the
//! file, case ignored, with no letter or digit right before or after it (`Shape::Sphere`
//! and `sphere_discriminant` name the sphere; `spherical` does not). A file that names every
//! shape lists them, matches on them or describes each: a new shape belongs there too, or
//! the list says why not.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The workspace's root: this package is its `tests/`.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ sits in the workspace's root")
        .to_path_buf()
}

/// The recipes whose lists CONTRIBUTING.md must hold, by the key of their markers.
const RECIPES: [&str; 3] = ["shape", "platform", "quantity"];

/// One list of CONTRIBUTING.md.
#[derive(Debug, PartialEq)]
struct List {
    /// The key of its markers (`shape`).
    key: String,
    /// The things it is about, each as its forms (`["sphere", "spheres"]`).
    names: Vec<Vec<String>>,
    /// The files listed, as written (paths from the repository's root), with their lines.
    files: Vec<(String, usize)>,
}

/// The lists of a Markdown text, in order. A malformed list (an end without a start, a start
/// without an end, a list inside another) is an error naming its line.
fn lists(doc: &str) -> Result<Vec<List>, String> {
    let mut out: Vec<List> = Vec::new();
    let mut open: Option<List> = None;
    for (i, line) in doc.lines().enumerate() {
        let number = i + 1;
        let trimmed = line.trim();
        if let Some(inner) = trimmed
            .strip_prefix("<!--")
            .and_then(|l| l.strip_suffix("-->"))
            .map(str::trim)
        {
            if let Some(key) = inner.strip_prefix("end ") {
                match open.take() {
                    Some(list) if list.key == key.trim() => out.push(list),
                    _ => return Err(format!("line {number}: `end {key}` closes no open list")),
                }
            } else if let Some((key, names)) = inner.split_once(':')
                && RECIPES.contains(&key.trim())
            {
                if let Some(list) = &open {
                    return Err(format!(
                        "line {number}: a list opens inside the list `{}`",
                        list.key
                    ));
                }
                open = Some(List {
                    key: key.trim().to_string(),
                    names: names
                        .split('|')
                        .map(|thing| thing.split_whitespace().map(str::to_lowercase).collect())
                        .filter(|forms: &Vec<String>| !forms.is_empty())
                        .collect(),
                    files: Vec::new(),
                });
            }
        } else if let Some(list) = &mut open
            && let Some(rest) = trimmed.strip_prefix("- `")
            && let Some((path, _)) = rest.split_once('`')
        {
            list.files.push((path.to_string(), number));
        }
    }
    match open {
        Some(list) => Err(format!("the list `{}` is never ended", list.key)),
        None => Ok(out),
    }
}

/// Whether `form` (lower case) appears in `text` (lower case) with no ASCII letter or digit
/// right before or after it.
fn names(text: &str, form: &str) -> bool {
    text.match_indices(form).any(|(at, _)| {
        let before = text[..at].chars().next_back();
        let after = text[at + form.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphanumeric())
            && !after.is_some_and(|c| c.is_ascii_alphanumeric())
    })
}

/// The things of `list` that `text` does not name (by their first form).
fn unnamed(text: &str, list: &List) -> Vec<String> {
    let lower = text.to_lowercase();
    list.names
        .iter()
        .filter(|forms| !forms.iter().any(|f| names(&lower, f)))
        .map(|forms| forms[0].clone())
        .collect()
}

/// The repository's text files outside its `tests/` directories, as paths from the root:
/// build output (`target/`, the built book `docs/book/`, cargo-mutants' `mutants.out*`),
/// `.git/`, the student's loop's state (`.whitted/`), CONTRIBUTING.md itself and files that
/// are not UTF-8 (images) left out.
fn files(root: &Path) -> BTreeMap<String, String> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, String>) {
        for entry in std::fs::read_dir(dir).expect("a readable directory") {
            let path = entry.expect("a readable entry").path();
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            let relative = path
                .strip_prefix(root)
                .expect("inside the root")
                .to_string_lossy()
                .replace('\\', "/");
            if path.is_dir() {
                let skipped = ["target", ".git", ".whitted", "tests"].contains(&name.as_ref())
                    || name.starts_with("mutants.out")
                    || relative == "docs/book";
                if !skipped {
                    walk(root, &path, out);
                }
            } else if relative != "CONTRIBUTING.md"
                && let Ok(text) = std::fs::read_to_string(&path)
            {
                out.insert(relative, text);
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(root, root, &mut out);
    out
}

/// Each list of CONTRIBUTING.md holds exactly the files that name every one of its things:
/// each file listed exists, none is listed twice, none that names them all is missing, and
/// none listed fails to name one of them.
#[test]
fn each_recipe_lists_exactly_the_files_that_name_every_one_of_its_things() {
    let root = root();
    let doc = std::fs::read_to_string(root.join("CONTRIBUTING.md"))
        .expect("CONTRIBUTING.md at the repository's root");
    let lists = lists(&doc).unwrap_or_else(|e| panic!("CONTRIBUTING.md: {e}"));
    let keys: Vec<&str> = lists.iter().map(|l| l.key.as_str()).collect();
    assert_eq!(keys, RECIPES, "CONTRIBUTING.md's lists, in order");
    let files = files(&root);
    let mut wrong = Vec::new();
    for list in &lists {
        let things: Vec<&str> = list.names.iter().map(|f| f[0].as_str()).collect();
        let things = things.join(", ");
        assert!(
            list.names.len() >= 2,
            "the list `{}` names {things}",
            list.key
        );
        let mut listed = BTreeSet::new();
        for (path, line) in &list.files {
            if !listed.insert(path.as_str()) {
                wrong.push(format!(
                    "CONTRIBUTING.md:{line}: `{path}` is listed twice under `{}`",
                    list.key
                ));
            }
            match files.get(path) {
                None if root.join(path).is_file() => wrong.push(format!(
                    "CONTRIBUTING.md:{line}: `{path}` is listed under `{}`, but the rule \
                     reads no such file (a test file, or build output)",
                    list.key
                )),
                None => wrong.push(format!(
                    "CONTRIBUTING.md:{line}: `{path}` is listed under `{}`, but there is no such file",
                    list.key
                )),
                Some(text) => {
                    let missing = unnamed(text, list);
                    if !missing.is_empty() {
                        wrong.push(format!(
                            "CONTRIBUTING.md:{line}: `{path}` is listed under `{}`, but it does not \
                             name {} (the list holds the files that name every one of {things})",
                            list.key,
                            missing.join(", ")
                        ));
                    }
                }
            }
        }
        for (path, text) in &files {
            if !listed.contains(path.as_str()) && unnamed(text, list).is_empty() {
                wrong.push(format!(
                    "CONTRIBUTING.md: `{path}` names every one of {things}, but the list `{}` \
                     misses it (add it, under what to edit, regenerate or leave)",
                    list.key
                ));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "CONTRIBUTING.md's lists of files are not true:\n{}",
        wrong.join("\n")
    );
}

/// The list reader: markers with their things and forms, bullets that open with a path,
/// other lines skipped; a list left open or closed twice is an error.
#[test]
fn the_lists_are_read_from_their_markers() {
    let doc = "# Title\n- `outside.rs` not in a list\n\
               <!-- shape: sphere spheres | Cone cones -->\nEdit:\n- `a.rs` — why\n  - `nested.rs`\n\
               some text with `b.rs`\n<!-- end shape -->\n";
    let read = lists(doc).unwrap();
    assert_eq!(
        read,
        [List {
            key: "shape".into(),
            names: vec![
                vec!["sphere".into(), "spheres".into()],
                vec!["cone".into(), "cones".into()]
            ],
            files: vec![("a.rs".into(), 5), ("nested.rs".into(), 6)],
        }]
    );
    assert!(lists("<!-- shape: a | b -->\n").is_err());
    assert!(lists("<!-- end shape -->\n").is_err());
    assert!(lists("<!-- shape: a | b -->\n<!-- platform: c | d -->\n").is_err());
}

/// A form names a thing only as a whole word, case ignored, `_` and `::` counting as
/// separators: `Shape::Cone` and `cone_normal` name the cone, `cones` is its plural, and
/// `icon`, `coned` and `cone2` do not.
#[test]
fn a_form_names_a_thing_only_as_a_whole_word() {
    let list = List {
        key: "shape".into(),
        names: vec![vec!["cone".into(), "cones".into()]],
        files: vec![],
    };
    for text in [
        "Shape::Cone",
        "cone_normal",
        "two cones",
        "\"cone\"",
        "cone",
    ] {
        assert!(unnamed(text, &list).is_empty(), "{text}");
    }
    for text in ["icon", "coned", "cone2", "c one"] {
        assert_eq!(unnamed(text, &list), ["cone"], "{text}");
    }
}
