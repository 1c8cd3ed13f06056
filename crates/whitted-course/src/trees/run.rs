//! Running a chapter binary for `whitted trees`: which binary and which figure's settings,
//! the run itself, and the `--against` comparison it prints.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::{Path, PathBuf};

use crate::ToolError;
use crate::figures::Figure;
use crate::mistakes;
use crate::syllabus::Chapter;
use whitted_learn::trees::{Against, read_output};

/// The chapter's figure in `docs/figures.toml`: `chNN_name.png`. Its arguments are the
/// settings the trees are traced with.
pub(super) fn figure_of<'f>(
    figures: &'f [Figure],
    chapter: &Chapter,
) -> Result<&'f Figure, ToolError> {
    let file = format!("{}.png", chapter.binary);
    figures.iter().find(|f| f.file == file).ok_or_else(|| {
        ToolError::Usage(format!(
            "docs/figures.toml has no figure {file}: the trees are traced with the figure's settings"
        ))
    })
}

/// The chapter binary built next to this program.
pub(super) fn reference_binary(chapter: &Chapter) -> Result<PathBuf, ToolError> {
    let exe = std::env::current_exe().map_err(|e| ToolError::io("whitted", e))?;
    let bin = exe.parent().unwrap_or(Path::new(".")).join(format!(
        "{}{}",
        chapter.binary,
        std::env::consts::EXE_SUFFIX
    ));
    if bin.is_file() {
        Ok(bin)
    } else {
        Err(ToolError::Usage(format!(
            "{} is not built: run `cargo build --bins` (or --release) first",
            bin.display()
        )))
    }
}

/// Runs `exe ARGS` from `root` (with `mutant` switched on, if any): its stdout, or its
/// stderr's last line as the error.
pub(super) fn run(
    exe: &Path,
    args: &[String],
    root: &Path,
    mutant: Option<&str>,
) -> Result<String, ToolError> {
    let mut command = std::process::Command::new(exe);
    command
        .args(args)
        .arg("--quiet")
        .current_dir(root)
        .env_remove(mistakes::SWITCH_VAR)
        .stdin(std::process::Stdio::null());
    if let Some(m) = mutant {
        command.env(mistakes::SWITCH_VAR, m);
    }
    let out = command.output().map_err(|e| ToolError::io(exe, e))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(ToolError::Figure(format!(
            "{} {}{}: {}",
            exe.display(),
            args.join(" "),
            mutant.map_or(String::new(), |m| format!(" (mutant {m})")),
            err.lines().last().unwrap_or("failed")
        )));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The comparison `--against FILE --json` prints, one [`Against`] a pixel, and the
/// `compare:` line when `extra` asks for one (`extra` arguments go first; `mutant` is
/// switched on).
pub(super) fn against(
    exe: &Path,
    figure: &Figure,
    root: &Path,
    file: &Path,
    extra: &[String],
    mutant: Option<&str>,
) -> Result<(Option<String>, Vec<Against>), ToolError> {
    let mut args = figure.args.clone();
    args.extend(extra.iter().cloned());
    args.extend([
        "--against".to_string(),
        file.display().to_string(),
        "--json".to_string(),
    ]);
    Ok(read_output(&run(exe, &args, root, mutant)?))
}
