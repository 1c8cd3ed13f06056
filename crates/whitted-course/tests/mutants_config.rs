//! cargo-mutants' configuration (`.cargo/mutants.toml`) mutates exactly the exercise functions
//! of `chapters/formulas.toml` and runs exactly the student's suite (the manifest's [handout]
//! tests): a function added to the manifest, moved to another file or renamed fails here, and
//! the message gives the lines to paste.

mod common;

use common::root;

use whitted_course::{manifest, source};

/// The regex that picks the mutants of one function out of cargo-mutants' names
/// (`src/shapes/sphere.rs:30:24: replace - with + in discriminant`, `… replace
/// Tracer<'a>::feeler -> Option<Feeler> with None`).
fn examine_re(file: &str, function: &str) -> String {
    let segments: Vec<&str> = function.split("::").collect();
    let name = segments[segments.len() - 1];
    let owner = segments
        .len()
        .checked_sub(2)
        .map(|i| segments[i])
        .filter(|s| s.starts_with(char::is_uppercase));
    let function = match owner {
        Some(ty) => format!("{ty}(<[^>]*>)?::{name}"),
        None => name.to_string(),
    };
    format!(
        "{}:\\d+:\\d+: (replace {function} -> |.* in {function}$)",
        file.replace('.', "\\.")
    )
}

#[derive(serde::Deserialize)]
struct Config {
    test_tool: String,
    additional_cargo_test_args: Vec<String>,
    examine_globs: Vec<String>,
    examine_re: Vec<String>,
    #[serde(default)]
    exclude_re: Vec<String>,
}

fn config() -> Config {
    let path = root().join(".cargo/mutants.toml");
    toml::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

#[test]
fn cargo_mutants_examines_exactly_the_exercise_functions() {
    let root = root();
    let manifest = manifest::load(&root.join("chapters/formulas.toml")).unwrap();
    let mut globs: Vec<String> = Vec::new();
    let mut regexes = Vec::new();
    for entry in &manifest.entries {
        let location = source::locate(&root, &entry.function).unwrap();
        let file = location.file.display().to_string();
        if !globs.contains(&file) {
            globs.push(file.clone());
        }
        regexes.push(examine_re(&file, &entry.function));
    }
    let config = config();
    let paste = |items: &[String]| {
        items
            .iter()
            .map(|r| format!("    {},", toml::Value::String(r.clone())))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(
        config.examine_globs,
        globs,
        "examine_globs should be the files of the manifest's functions:\n{}",
        paste(&globs)
    );
    let named: Vec<String> = manifest
        .entries
        .iter()
        .zip(&regexes)
        .map(|(e, r)| format!("    # {}\n    {r:?},", e.exercise.name))
        .collect();
    assert_eq!(
        config.examine_re,
        regexes,
        "examine_re should be, in the manifest's order:\n{}",
        named.join("\n")
    );
    // each regex under its exercise's name, so that the list reads by exercise
    let text = std::fs::read_to_string(root.join(".cargo/mutants.toml")).unwrap();
    for line in &named {
        assert!(
            text.contains(line.as_str()),
            "examine_re should hold, as written:\n{line}"
        );
    }
}

#[test]
fn cargo_mutants_runs_the_students_suite_each_test_in_its_own_process() {
    let manifest = manifest::load(&root().join("chapters/formulas.toml")).unwrap();
    let config = config();
    assert_eq!(config.test_tool, "nextest");
    let expected: Vec<String> = manifest
        .handout
        .tests
        .iter()
        .flat_map(|t| ["--test".to_string(), t.clone()])
        .collect();
    assert_eq!(config.additional_cargo_test_args, expected);
}

/// Every mutant left alone is justified where it is excluded: a comment right above its
/// regex says why no test can or should catch it.
#[test]
fn every_excluded_mutant_has_its_reason_written_above_it() {
    let text = std::fs::read_to_string(root().join(".cargo/mutants.toml")).unwrap();
    let config = config();
    for regex in &config.exclude_re {
        let quoted = format!("\"{}\"", regex.replace('\\', "\\\\").replace('"', "\\\""));
        let at = text
            .find(&quoted)
            .unwrap_or_else(|| panic!("{quoted} not found as written"));
        let before: Vec<&str> = text[..at].lines().collect();
        let above = before[before.len() - 2].trim();
        assert!(
            above.starts_with('#') && above.len() > 20,
            "exclude_re {quoted} has no reason in a comment on the line above it"
        );
    }
}

#[test]
fn the_regex_of_a_method_and_of_a_free_function() {
    assert_eq!(
        examine_re("src/render/tracer.rs", "render::tracer::Tracer::feeler"),
        "src/render/tracer\\.rs:\\d+:\\d+: (replace Tracer(<[^>]*>)?::feeler -> |.* in Tracer(<[^>]*>)?::feeler$)"
    );
    assert_eq!(
        examine_re("src/shapes/sphere.rs", "shapes::sphere::normal"),
        "src/shapes/sphere\\.rs:\\d+:\\d+: (replace normal -> |.* in normal$)"
    );
}
