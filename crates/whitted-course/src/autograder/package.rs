//! The package each platform takes, written from the instructor's project by `whitted
//! autograder --platform P --out DIR`:
//!
//! - **Gradescope**: `autograder.zip` with, at its root, `setup.sh` (installs what is missing —
//!   the Rust toolchain, cargo-nextest, bubblewrap — builds `whitted`, then builds once the
//!   dependencies and the instructor's code with a handout whose every exercise is `todo!()`,
//!   so that each submission compiles only its own crate), `run_autograder` (grades
//!   `/autograder/submission` into `/autograder/results/results.json`, and writes a results
//!   file saying why even when `whitted` itself fails), the project in `whitted/` and the
//!   hidden tests in `hidden/`. Both scripts take their root from `AUTOGRADER_ROOT`
//!   (default `/autograder`), so they run anywhere.
//! - **PrairieLearn**: a `Dockerfile` for the grading image (the project prebuilt in it), the
//!   entry point `run.sh` (`/grade/student` → `/grade/results/results.json`; root
//!   `GRADE_ROOT`, default `/grade`), the question's `tests/hidden/` and the `info.json` lines
//!   that name them.
//! - **CodeGrade**: `setup.sh` (as Gradescope's) and `run.sh`, which writes JUnit XML where
//!   CodeGrade's JUnit step reads it.
//! - **GitHub Classroom**: `.github/workflows/classroom.yml` for the handout's repository (one
//!   step grades, then one step per exercise scores it, and the reporter sums them) and the
//!   course tool's sources in `.github/whitted/`, built by the workflow.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::io::Write;
use std::path::{Path, PathBuf};

use super::Platform;
pub use super::options::{NEXTEST_VERSION, Options};
use crate::grade::Judging;
use crate::grade::sandbox::Level;
use crate::manifest::Manifest;
use crate::{ToolError, files};

/// A file of a package: its path in the package, its text, whether it is executable.
struct Item {
    path: PathBuf,
    bytes: Vec<u8>,
    executable: bool,
}

fn item(path: &str, text: String, executable: bool) -> Item {
    Item {
        path: PathBuf::from(path),
        bytes: text.into_bytes(),
        executable,
    }
}

/// The arguments every grading of the package gets.
fn grade_args(options: &Options) -> String {
    format!(
        "{} --hidden-visibility {}",
        prebuild_args(options).trim_start(),
        options.settings.hidden_visibility
    )
}

/// The arguments of the package's prebuild: the grading's own but the hidden tests'
/// visibility, which no build needs.
fn prebuild_args(options: &Options) -> String {
    let mut a = format!(" --timeout {}", options.timeout);
    if let Some(c) = options.chapter {
        a += &format!(" --chapter {c}");
    }
    if options.settings.leaderboard {
        a += " --leaderboard";
    }
    if options.judging == Judging::WholeRoad {
        a += " --whole-road";
    }
    match options.sandbox {
        Some(Level::Namespaces) => {}
        Some(Level::User) => a += " --sandbox user",
        None | Some(Level::Off) => a += " --unsandboxed",
    }
    a
}

/// The Rust version the project is built with here (`rustc --version`), for the platform
/// to install the same.
fn rust_version() -> String {
    std::process::Command::new("rustc")
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| {
            String::from_utf8_lossy(&o.stdout)
                .split_whitespace()
                .nth(1)
                .map(str::to_string)
        })
        .unwrap_or_else(|| "stable".into())
}

/// The setup script of an image: installs what is missing, builds `whitted`, prebuilds.
/// `$ROOT` is set by the caller's first lines; `src` is where the package's files are.
fn setup_script(
    platform: Platform,
    root_var: &str,
    root_default: &str,
    src: &str,
    options: &Options,
) -> String {
    let hidden = hidden_arg(options);
    format!(
        r#"#!/usr/bin/env bash
# Written by `whitted autograder --platform {platform}`: run once, when the grading image is
# built. Installs what is missing (each install is skipped when the tool is there, so with the
# toolchain present nothing is downloaded), builds `whitted`, then builds once what every
# submission reuses. {root_var} (default {root_default}) is the root of the platform's layout.
set -euo pipefail
ROOT="${{{root_var}:-{root_default}}}"
SRC="{src}"
{TOOLCHAIN_PATH}sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
missing=()
command -v bwrap >/dev/null || missing+=(bubblewrap)
command -v cc >/dev/null || missing+=(build-essential)
command -v git >/dev/null || missing+=(git)
command -v curl >/dev/null || command -v cargo >/dev/null || missing+=(curl ca-certificates)
if [ ${{#missing[@]}} -gt 0 ]; then
  echo "setup: installing ${{missing[*]}}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${{missing[@]}}" >/dev/null
fi
if ! command -v cargo >/dev/null; then
  echo "setup: installing Rust {rust}"
  curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal --default-toolchain {rust}
fi
if ! cargo nextest --version >/dev/null 2>&1; then
  echo "setup: installing cargo-nextest {nextest}"
  cargo install --locked cargo-nextest --version {nextest}
fi
if [ -n "${{WHITTED_BIN:-}}" ]; then
  echo "setup: using the whitted program $WHITTED_BIN"
else
  echo "setup: building whitted"
  (cd "$SRC/whitted" && cargo build --release --locked --bin whitted)
fi
WHITTED="${{WHITTED_BIN:-$SRC/whitted/target/release/whitted}}"
{close}echo "setup: building the dependencies and the instructor's code once"
"$WHITTED" autograder prebuild --root "$SRC/whitted" --target-dir "${{WHITTED_BUILD_DIR:-$ROOT/build}}"{hidden}{args}
"#,
        platform = platform.name(),
        rust = rust_version(),
        nextest = NEXTEST_VERSION,
        args = prebuild_args(options),
        close = if options.sandbox == Some(Level::User) {
            "# the tests run as a user of their own: the project and the hidden tests are closed to it\nchmod 0700 \"$SRC/whitted\"\n[ -d \"$SRC/hidden\" ] && chmod 0700 \"$SRC/hidden\"\n"
        } else {
            ""
        },
    )
}

/// ` --hidden "$SRC/hidden"` when the package has hidden tests.
fn hidden_arg(options: &Options) -> &'static str {
    if options.hidden.is_some() {
        " --hidden \"$SRC/hidden\""
    } else {
        ""
    }
}

/// Gradescope's `run_autograder`.
fn gradescope_run(options: &Options) -> String {
    let hidden = hidden_arg(options);
    format!(
        r#"#!/usr/bin/env bash
# Written by `whitted autograder --platform gradescope`: grades $ROOT/submission into
# $ROOT/results/results.json. It always leaves a results file: when whitted cannot grade the
# submission its file says why, and when whitted itself fails this script writes one.
ROOT="${{AUTOGRADER_ROOT:-/autograder}}"
SRC="$ROOT/source"
RESULTS="$ROOT/results/results.json"
mkdir -p "$ROOT/results"
rm -f "$RESULTS"
{TOOLCHAIN_PATH}WHITTED="${{WHITTED_BIN:-$SRC/whitted/target/release/whitted}}"
"$WHITTED" autograder grade --platform gradescope --root "$SRC/whitted" \
    --submission "$ROOT/submission" --results "$RESULTS" \
    --target-dir "${{WHITTED_BUILD_DIR:-$ROOT/build}}"{hidden} {args}
{fallback}"#,
        args = grade_args(options),
        fallback = fallback(
            r#"{"score": 0, "output": "The autograder failed before it could grade this submission (exit status %s). Your instructor has its log.", "tests": []}"#
        )
    )
}

/// The lines that put cargo's programs on the `PATH`.
const TOOLCHAIN_PATH: &str =
    "export CARGO_HOME=\"${CARGO_HOME:-$HOME/.cargo}\"\nexport PATH=\"$CARGO_HOME/bin:$PATH\"\n";

/// A grading script's last lines: when `whitted` wrote no results file, `json` (a `printf`
/// format with `%s` for the exit status) is written instead; the script succeeds either way.
fn fallback(json: &str) -> String {
    format!(
        "status=$?\nif [ ! -s \"$RESULTS\" ]; then\n  printf '{json}\\n' \"$status\" > \"$RESULTS\"\nfi\nexit 0\n"
    )
}

/// PrairieLearn's entry point.
fn prairielearn_run(options: &Options) -> String {
    format!(
        r#"#!/usr/bin/env bash
# Written by `whitted autograder --platform prairielearn`: the external grader's entry point.
# Grades $GRADE/student into $GRADE/results/results.json; a submission that is not a copy of
# the handout is `gradable: false` (it costs no attempt). The question's hidden tests are its
# tests/hidden/*.rs, mounted at $GRADE/tests/hidden.
GRADE="${{GRADE_ROOT:-/grade}}"
RESULTS="$GRADE/results/results.json"
mkdir -p "$GRADE/results"
rm -f "$RESULTS"
{TOOLCHAIN_PATH}PROJECT="${{WHITTED_ROOT:-/whitted/whitted}}"
WHITTED="${{WHITTED_BIN:-$PROJECT/target/release/whitted}}"
hidden=()
if compgen -G "$GRADE/tests/hidden/*.rs" >/dev/null; then
  hidden=(--hidden "$GRADE/tests/hidden")
fi
"$WHITTED" autograder grade --platform prairielearn --root "$PROJECT" \
    --submission "$GRADE/student" --results "$RESULTS" \
    --target-dir "${{WHITTED_BUILD_DIR:-/whitted/build}}" "${{hidden[@]}}" {args}
{fallback}"#,
        args = grade_args(options),
        fallback = fallback(
            r#"{"gradable": false, "format_errors": ["the autograder failed (exit status %s)"]}"#
        )
    )
}

/// PrairieLearn's image.
fn prairielearn_dockerfile() -> String {
    format!(
        r#"# Written by `whitted autograder --platform prairielearn`: the external grader's image, with
# the toolchain, cargo-nextest and bubblewrap, and the project built once in /whitted.
FROM rust:{rust}-bookworm
RUN apt-get update -qq && apt-get install -y -qq bubblewrap && rm -rf /var/lib/apt/lists/*
RUN cargo install --locked cargo-nextest --version {nextest}
COPY whitted /whitted/whitted
COPY setup.sh /whitted/setup.sh
COPY run.sh /whitted/run.sh
RUN chmod +x /whitted/setup.sh /whitted/run.sh && AUTOGRADER_ROOT=/whitted /whitted/setup.sh
"#,
        rust = rust_version(),
        nextest = NEXTEST_VERSION
    )
}

/// CodeGrade's run script.
fn codegrade_run(options: &Options) -> String {
    let hidden = hidden_arg(options);
    format!(
        r#"#!/usr/bin/env bash
# Written by `whitted autograder --platform codegrade`: grades the student's files (the
# current directory, or $1) and writes JUnit XML to $CG_JUNIT_XML_LOCATION (or $2), which
# CodeGrade's JUnit step reads.
ROOT="${{WHITTED_HOME:-$HOME/whitted}}"
SRC="$ROOT"
OUT="${{2:-${{CG_JUNIT_XML_LOCATION:-junit.xml}}}}"
{TOOLCHAIN_PATH}WHITTED="${{WHITTED_BIN:-$SRC/whitted/target/release/whitted}}"
"$WHITTED" autograder grade --platform codegrade --root "$SRC/whitted" \
    --submission "${{1:-.}}" --results "$OUT" \
    --target-dir "${{WHITTED_BUILD_DIR:-$ROOT/build}}"{hidden} {args}
"#,
        args = grade_args(options)
    )
}

/// The project's files for a package (under `whitted/`), without the hidden tests when they
/// sit inside the project, and the hidden tests (under `hidden/`).
fn project_items(root: &Path, options: &Options) -> Result<Vec<Item>, ToolError> {
    let hidden_rel = options.hidden.as_ref().and_then(|h| {
        let h = h.canonicalize().ok()?;
        let r = root.canonicalize().ok()?;
        h.strip_prefix(&r).ok().map(Path::to_path_buf)
    });
    let mut items = Vec::new();
    for f in files::project_files(root)? {
        if hidden_rel.as_ref().is_some_and(|h| f.starts_with(h)) {
            continue;
        }
        let path = root.join(&f);
        let bytes = match &options.handout {
            // the handout's own list travels in the package's manifest
            Some(names) if f == Path::new(crate::manifest::DEFAULT_PATH) => {
                crate::handout::later::listed_manifest(root, names)?
                    .0
                    .into_bytes()
            }
            _ => std::fs::read(&path).map_err(|e| ToolError::io(&path, e))?,
        };
        items.push(Item {
            path: Path::new("whitted").join(&f),
            bytes,
            executable: is_executable(&path),
        });
    }
    if let Some(dir) = &options.hidden {
        for p in crate::grade::hidden_files(dir)? {
            let bytes = std::fs::read(&p).map_err(|e| ToolError::io(&p, e))?;
            let name = p.file_name().map(PathBuf::from).unwrap_or_default();
            items.push(Item {
                path: Path::new("hidden").join(name),
                bytes,
                executable: false,
            });
        }
    }
    Ok(items)
}

fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    std::fs::metadata(path).is_ok_and(|m| m.permissions().mode() & 0o111 != 0)
}

/// Writes `items` under `dir`.
fn write_items(dir: &Path, items: &[Item]) -> Result<(), ToolError> {
    use std::os::unix::fs::PermissionsExt;
    for i in items {
        let path = dir.join(&i.path);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).map_err(|e| ToolError::io(parent, e))?;
        }
        std::fs::write(&path, &i.bytes).map_err(|e| ToolError::io(&path, e))?;
        let mode = if i.executable { 0o755 } else { 0o644 };
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode))
            .map_err(|e| ToolError::io(&path, e))?;
    }
    Ok(())
}

/// Writes `items` into the zip file `path`, each at its path, with its mode.
fn write_zip(path: &Path, items: &[Item]) -> Result<(), ToolError> {
    let io = |e: std::io::Error| ToolError::io(path, e);
    let file = std::fs::File::create(path).map_err(io)?;
    let mut zip = zip::ZipWriter::new(file);
    for i in items {
        let options = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated)
            .unix_permissions(if i.executable { 0o755 } else { 0o644 });
        let name = i.path.to_string_lossy().replace('\\', "/");
        zip.start_file(name, options)
            .map_err(|e| ToolError::Usage(format!("{}: {e}", path.display())))?;
        zip.write_all(&i.bytes).map_err(io)?;
    }
    zip.finish()
        .map_err(|e| ToolError::Usage(format!("{}: {e}", path.display())))?;
    Ok(())
}

/// Writes `platform`'s package into `out`; returns the files written (relative to `out`).
pub fn write(
    root: &Path,
    manifest: &Manifest,
    platform: Platform,
    options: &Options,
    out: &Path,
) -> Result<Vec<PathBuf>, ToolError> {
    // a hidden test named after no exercise is refused now, not on the platform's machine
    if let Some(dir) = &options.hidden {
        crate::grade::hidden::check(manifest, dir)?;
    }
    std::fs::create_dir_all(out).map_err(|e| ToolError::io(out, e))?;
    let mut written = Vec::new();
    match platform {
        Platform::Gradescope => {
            let mut items = vec![
                item(
                    "setup.sh",
                    setup_script(
                        platform,
                        "AUTOGRADER_ROOT",
                        "/autograder",
                        "$ROOT/source",
                        options,
                    ),
                    true,
                ),
                item("run_autograder", gradescope_run(options), true),
            ];
            items.extend(project_items(root, options)?);
            write_zip(&out.join("autograder.zip"), &items)?;
            written.push(PathBuf::from("autograder.zip"));
        }
        Platform::Prairielearn => {
            let mut items = vec![
                item("Dockerfile", prairielearn_dockerfile(), false),
                // the hidden tests are the question's, mounted with each submission: the
                // image is built without them
                item(
                    "setup.sh",
                    setup_script(
                        platform,
                        "AUTOGRADER_ROOT",
                        "/whitted",
                        "$ROOT",
                        &Options {
                            hidden: None,
                            ..options.clone()
                        },
                    ),
                    true,
                ),
                item("run.sh", prairielearn_run(options), true),
                item("info.json", prairielearn_info(options), false),
            ];
            let mut project = project_items(root, options)?;
            // the question's tests: PrairieLearn mounts them at /grade/tests
            for i in &mut project {
                if i.path.starts_with("hidden") {
                    i.path = Path::new("tests").join(&i.path);
                }
            }
            items.extend(project);
            write_items(out, &items)?;
            written.extend(
                items
                    .into_iter()
                    .map(|i| i.path)
                    .filter(|p| !p.starts_with("whitted")),
            );
        }
        Platform::Codegrade => {
            let mut items = vec![
                item(
                    "setup.sh",
                    setup_script(platform, "WHITTED_HOME", "$HOME/whitted", "$ROOT", options),
                    true,
                ),
                item("run.sh", codegrade_run(options), true),
            ];
            items.extend(project_items(root, options)?);
            write_items(out, &items)?;
            written.extend(
                items
                    .into_iter()
                    .map(|i| i.path)
                    .filter(|p| !p.starts_with("whitted") && !p.starts_with("hidden")),
            );
        }
        Platform::Classroom => {
            // the repository is the handout: when it lists its own exercises, those are what
            // its workflow grades and scores, a step each (the grading reads the same list
            // from the handout's first commit)
            let own = crate::manifest::load(&out.join(crate::manifest::DEFAULT_PATH))
                .ok()
                .filter(|h| h.handout.exercises.is_some());
            let manifest = own.as_ref().unwrap_or(manifest);
            let items = super::classroom::items(root, manifest, options)?
                .into_iter()
                .map(|(path, text)| Item {
                    path,
                    bytes: text.into_bytes(),
                    executable: false,
                })
                .collect::<Vec<_>>();
            write_items(out, &items)?;
            written.extend(
                items
                    .into_iter()
                    .map(|i| i.path)
                    .filter(|p| !p.starts_with(".github/whitted/whitted-course/src")),
            );
        }
    }
    Ok(written)
}

/// The `externalGradingOptions` of the question's `info.json`.
fn prairielearn_info(options: &Options) -> String {
    let info = serde_json::json!({
        "externalGradingOptions": {
            "enabled": true,
            "image": "YOUR-REGISTRY/whitted-grader",
            "entrypoint": "/whitted/run.sh",
            "timeout": (options.timeout * 12).clamp(60, 600),
        }
    });
    super::json_text(&info)
}
