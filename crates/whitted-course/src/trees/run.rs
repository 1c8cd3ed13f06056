//! Running a chapter binary for `whitted trees`: which binary and which figure's settings,
//! the run itself, and the `--against` comparison it prints.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::{Path, PathBuf};

use crate::ToolError;
use crate::figures::Figure;
use crate::mistakes;
use crate::syllabus::Chapter;
use whitted_learn::chapter_binary::{self, Render};
use whitted_learn::trees::{Against, read_output};

/// The chapter's figure in `docs/figures.toml`: `chNN_name.png`. Its arguments are the
/// settings the trees are traced with.
pub(super) fn figure_of<'f>(
    figures: &'f [Figure],
    chapter: &Chapter,
) -> Result<&'f Figure, ToolError> {
    chapter_binary::chapter_figure(figures, chapter.number).ok_or_else(|| {
        ToolError::Usage(format!(
            "docs/figures.toml has no figure {}.png: the trees are traced with the figure's settings",
            chapter.binary
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

/// Runs `render` quietly (with `mutant` switched on, if any): its stdout, or its stderr's last
/// line as the error.
pub(super) fn run(render: Render<'_>, mutant: Option<&str>) -> Result<String, ToolError> {
    let switch: Vec<(&str, &str)> = mutant
        .map(|m| (mistakes::SWITCH_VAR, m))
        .into_iter()
        .collect();
    let render = Render {
        quiet: true,
        env_remove: &[mistakes::SWITCH_VAR],
        env: &switch,
        ..render
    };
    let rendered = render
        .run()
        .map_err(|e| ToolError::io(render.exe, e.into_io()))?;
    if !rendered.success() {
        // the arguments as given, without the `--quiet` every run has
        let args: Vec<String> = render
            .arguments()
            .iter()
            .filter(|a| *a != "--quiet")
            .map(|a| a.to_string_lossy().into_owned())
            .collect();
        return Err(ToolError::Figure(format!(
            "{} {}{}: {}",
            render.exe.display(),
            args.join(" "),
            mutant.map_or(String::new(), |m| format!(" (mutant {m})")),
            rendered.stderr.lines().last().unwrap_or("failed")
        )));
    }
    Ok(rendered.stdout)
}

/// The comparison `--against FILE --json` prints, one [`Against`] a pixel, with the picture
/// `(book, png)` compared and written when given, and `mutant` switched on.
pub(super) fn against(
    exe: &Path,
    figure: &Figure,
    root: &Path,
    file: &Path,
    picture: Option<(&Path, &Path)>,
    mutant: Option<&str>,
) -> Result<(Option<String>, Vec<Against>), ToolError> {
    let render = Render {
        args: &figure.args,
        compare: picture.map(|(book, _)| book),
        against: Some(file),
        out: picture.map(|(_, png)| png),
        ..Render::new(exe, root)
    };
    Ok(read_output(&run(render, mutant)?))
}
