//! The handout's own cargo files: its workspace manifest, with only the crates a student
//! gets, and its `.cargo/config.toml`, with only the student's alias.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use crate::{ToolError, layout};

/// The handout's workspace manifest: the project's, with only the crates a handout holds as
/// members (tools and benchmarks stay with the instructor) and a header of its own.
pub fn workspace_manifest(reference: &str) -> Result<String, ToolError> {
    let members = format!(
        "members = [{}]",
        [layout::SYLLABUS, layout::CORE, layout::APP, layout::LEARN]
            .map(|m| format!("{m:?}"))
            .join(", ")
    );
    let mut out = String::from(
        "# The workspace of your copy of whitted: the renderer you write (crates/whitted), the\n\
         # chapter binaries (crates/whitted-app), the loop behind `cargo learn`\n\
         # (crates/whitted-learn) and the course's outline they share (crates/whitted-syllabus).\n",
    );
    let mut replaced = false;
    let mut header = true;
    for line in reference.lines() {
        if header && line.starts_with('#') {
            continue; // the reference's header describes the whole project
        }
        header = false;
        if line.trim_start().starts_with("members = [") && !replaced {
            out += &members;
            replaced = true;
        } else if LEFT_PACKAGES
            .iter()
            .any(|p| line.trim_start().starts_with(&format!("{p} ")))
        {
            continue; // a dependency or profile setting of a crate the handout does not hold
        } else {
            out += line;
        }
        out.push('\n');
    }
    if !replaced {
        return Err(ToolError::Project(
            "Cargo.toml: no `members = [...]` line to write the handout's members into".into(),
        ));
    }
    out += HANDOUT_PROFILE;
    Ok(out)
}

/// What a handout's workspace manifest adds to the project's profiles: the renderer at
/// opt-level 0 in dev and test builds. Writing an exercise's first body then recompiles a few
/// functions instead of half the crate (measured on `cylinder::intersect`: 9 s at opt-level 1,
/// 2 s at 0), while a chapter's tests still run in milliseconds and its picture renders in
/// under a second. (The instructor's project keeps opt-level 1: its own tests are heavier.)
pub const HANDOUT_PROFILE: &str = "\n# In a handout the renderer compiles at opt-level 0 in dev and test builds: writing an\n\
     # exercise recompiles a few functions, not half the crate, and its tests still take a\n\
     # moment. Release builds (`cargo run --release`) are as fast as ever.\n\
     [profile.dev.package.whitted]\nopt-level = 0\n";

/// Packages of the project that no crate of a handout uses: their lines in the workspace's
/// manifest (a path dependency, a profile setting) are left out, since cargo warns at every
/// build about a profile setting that names no package.
pub const LEFT_PACKAGES: [&str; 6] = [
    "whitted-course",
    "whitted-tools",
    "whitted-benches",
    "whitted-tests",
    "roxmltree",
    "plotters",
];

/// The handout's `.cargo/config.toml`: the project's `learn` alias (the one command of the
/// student's README) and nothing of the instructor's.
pub fn cargo_config(reference: &str) -> Result<String, ToolError> {
    let learn = reference
        .lines()
        .find(|l| l.trim_start().starts_with("learn ="))
        .ok_or_else(|| {
            ToolError::Project(".cargo/config.toml: no `learn = …` alias for the handout".into())
        })?;
    Ok(format!(
        "# `cargo learn`: the loop of this handout (crates/whitted-learn), built once, at the test\n\
         # profile, which its own builds of the renderer's tests and binaries use too.\n\
         [alias]\n{learn}\n"
    ))
}
