//! GitHub Classroom: a workflow for the handout's repository, which Classroom copies for each
//! student and runs on every push. One step grades the student's copy against the handout
//! as it was given (the repository's first commit: its tests, manifest and code around the
//! exercises), then one `autograding-command-grader` step per exercise passes when the
//! exercise got all its points (`whitted autograder check`), worth the exercise's points; the
//! `autograding-grading-reporter` step sums them (`runners` lists the steps, each step's
//! result in `<ID>_RESULTS`). A command step scores all or nothing, so an exercise half right
//! scores 0 here. The course tool itself travels in the repository, in `.github/whitted/`,
//! built by the workflow: the handout holds no solution, and neither does the tool.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

use super::options::{NEXTEST_VERSION, Options};
use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// Where the workflow sits in the repository.
pub const WORKFLOW: &str = ".github/workflows/classroom.yml";

/// Where the course tool's sources sit in the repository.
pub const GRADER: &str = ".github/whitted";

/// The step id of an exercise (`ex-2-3`).
#[must_use]
pub fn step_id(id: &str) -> String {
    format!("ex-{}", id.replace('.', "-"))
}

/// A YAML double-quoted string.
fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The workflow file.
#[must_use]
pub fn workflow(manifest: &Manifest, options: &Options) -> String {
    let whitted = format!("{GRADER}/target/release/whitted");
    let mut args = format!("--timeout {}", options.timeout);
    if let Some(c) = options.chapter {
        args += &format!(" --chapter {c}");
    }
    if options.judging == crate::grade::Judging::WholeRoad {
        args += " --whole-road";
    }
    let mut out = format!(
        r#"# Written by `whitted autograder --platform classroom`. GitHub Classroom runs it in each
# student's repository on every push: one step grades, one step per exercise scores it, and
# the reporter sums the exercises' points.
name: Autograding Tests
'on':
- push
- repository_dispatch
permissions:
  checks: write
  actions: read
  contents: read
jobs:
  run-autograding-tests:
    runs-on: ubuntu-latest
    if: github.actor != 'github-classroom[bot]'
    steps:
    - name: Checkout code
      uses: actions/checkout@v4
      with:
        fetch-depth: 0
    - name: Grade against the handout as it was given
      run: |
        sudo apt-get update -qq
        sudo apt-get install -y -qq bubblewrap
        cargo nextest --version || cargo install --locked cargo-nextest --version {NEXTEST_VERSION}
        cargo build --release --manifest-path {GRADER}/Cargo.toml --bin whitted
        git worktree add --detach ../handout "$(git rev-list --max-parents=0 HEAD | tail -n 1)"
        # as root: bubblewrap's namespaces without unprivileged user namespaces
        sudo -E env "PATH=$PATH" {whitted} autograder grade --platform classroom --root ../handout --submission . --results ../results.json --target-dir ../build {args}
"#
    );
    let mut ids = Vec::new();
    for e in manifest.entries.iter().filter(|e| {
        options
            .chapter
            .is_none_or(|c| c.list().contains(&e.chapter))
    }) {
        let id = step_id(&e.exercise.id);
        let name = format!("{} {}", e.exercise.id, e.exercise.title);
        out += &format!(
            "    - name: {}\n      id: {id}\n      uses: classroom-resources/autograding-command-grader@v1\n      with:\n        test-name: {}\n        command: {}\n        timeout: 1\n        max-score: {}\n",
            quoted(&name),
            quoted(&name),
            quoted(&format!(
                "{whitted} autograder check --results ../results.json --exercise {}",
                e.exercise.name
            )),
            e.exercise.points
        );
        ids.push(id);
    }
    out += "    - name: Autograding Reporter\n      uses: classroom-resources/autograding-grading-reporter@v1\n      env:\n";
    for id in &ids {
        out += &format!(
            "        {}_RESULTS: \"${{{{steps.{id}.outputs.result}}}}\"\n",
            id.to_uppercase()
        );
    }
    out += &format!("      with:\n        runners: {}\n", ids.join(","));
    out
}

/// The files of the Classroom package, relative to the handout repository's root: the
/// workflow, and the course tool as a workspace of its own over the handout's crates.
pub fn items(
    root: &Path,
    manifest: &Manifest,
    options: &Options,
) -> Result<Vec<(PathBuf, String)>, ToolError> {
    let mut items = vec![(PathBuf::from(WORKFLOW), workflow(manifest, options))];
    let path = root.join("Cargo.toml");
    let reference = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    items.push((
        Path::new(GRADER).join("Cargo.toml"),
        grader_manifest(&reference),
    ));
    let lock = root.join("Cargo.lock");
    if let Ok(text) = std::fs::read_to_string(&lock) {
        items.push((Path::new(GRADER).join("Cargo.lock"), text));
    }
    for f in files::project_files(root)? {
        let Ok(rest) = f.strip_prefix(layout::COURSE) else {
            continue;
        };
        if rest == Path::new("Cargo.toml") || rest.starts_with("src") {
            let p = root.join(&f);
            let text = std::fs::read_to_string(&p).map_err(|e| ToolError::io(&p, e))?;
            items.push((Path::new(GRADER).join("whitted-course").join(rest), text));
        }
    }
    Ok(items)
}

/// The course tool's workspace manifest: the project's, with `whitted-course` its only
/// member and every other crate found two levels up (in the handout).
#[must_use]
pub fn grader_manifest(reference: &str) -> String {
    let mut out = String::from(
        "# Written by `whitted autograder --platform classroom`: the course tool (`whitted`),\n\
         # built by the Classroom workflow against the handout's crates.\n",
    );
    // the project's own header describes the project, not this workspace
    let body = reference.trim_start_matches(|c: char| c.is_whitespace());
    let mut lines = body.lines().peekable();
    while lines.next_if(|l| l.starts_with('#')).is_some() {}
    for line in lines {
        let line = if line.trim_start().starts_with("members = [") {
            "members = [\"whitted-course\"]".to_string()
        } else if line.contains(&format!("path = \"{}\"", layout::COURSE)) {
            line.replace(layout::COURSE, "whitted-course")
        } else {
            line.replace("path = \"crates/", "path = \"../../crates/")
        };
        out += &line;
        out.push('\n');
    }
    out
}
