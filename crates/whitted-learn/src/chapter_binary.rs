//! A chapter binary run for a picture: the one place the course tools do it — `cargo learn`'s
//! picture of the student's code, `whitted grade`'s feedback and leaderboard, `whitted figures`'
//! renders of the book and `whitted trees`' traces of the reference.
//!
//! - **Which binary, with which arguments.** A figure of `docs/figures.toml`
//!   ([`crate::figures`]) names both. A chapter's own picture is its figure `chNN_name.png`,
//!   drawn by `chNN_name` ([`chapter_figure`]), and the reference's ray trees of its scene are
//!   `chapters/chNN_name/trees.json` ([`chapter_trees`]).
//! - **Built** by the project's cargo runner, a [`Build`](crate::cargo::Build) of the
//!   binaries; [`executables`] takes what it built, or says in one line why nothing can run.
//! - **Run** ([`Render::run`], or [`Render::run_in`] the command a sandbox starts it with) from
//!   the project's root, reading no input, within a time limit when one is given:
//!
//!   ```text
//!   BINARY ARGS [--compare BOOK.png] [--against TREES.json --json] [--quiet] [-o PICTURE.png]
//!   ```
//! - **Read back** ([`Rendered`]): the `compare:` line and each pixel's tree compared
//!   ([`Rendered::compared`]), the one-line error of a render that stopped ([`error_line`]),
//!   and the picture itself ([`read_picture`]).
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

use crate::ToolError;
use crate::cargo::Built;
use crate::figures::Figure;
use crate::trees::{Against, read_output, trees_file};

/// The figure that is chapter `chapter`'s own picture: `chNN_name.png`, drawn by the chapter's
/// binary `chNN_name` (`None` when `figures` lists none).
#[must_use]
pub fn chapter_figure(figures: &[Figure], chapter: u8) -> Option<&Figure> {
    let binary = whitted_syllabus::chapter(chapter)?.binary;
    let file = format!("{binary}.png");
    figures
        .iter()
        .find(|f| f.file == file && f.binary == binary)
}

/// The reference's ray trees of chapter `chapter`'s scene in the project at `root`
/// (`chapters/chNN_name/trees.json`), when the project holds them.
#[must_use]
pub fn chapter_trees(root: &Path, chapter: u8) -> Option<PathBuf> {
    trees_file(chapter)
        .map(|t| root.join(t))
        .filter(|t| t.is_file())
}

/// The chapter binaries' executables by name, from cargo's build of them: `Err` says in one
/// line why none can run (cargo could not be started, or the binaries do not build).
pub fn executables(
    built: Result<Built, ToolError>,
) -> Result<BTreeMap<String, PathBuf>, ToolError> {
    let built = built?;
    if !built.success {
        return Err(ToolError::Cargo(format!(
            "the chapter binaries do not build: {}",
            built.first_error()
        )));
    }
    Ok(built.executables)
}

/// One run of a chapter binary. [`Render::new`] gives the plainest (no argument, no time
/// limit); a caller sets what it needs with struct update syntax:
///
/// ```no_run
/// # use std::path::Path;
/// # use whitted_learn::chapter_binary::Render;
/// # let (exe, root) = (Path::new("ch04_shadows"), Path::new("."));
/// let args = ["scenes/ch04_shadows.toml".to_string()];
/// let book = Path::new("docs/src/figures/ch04_shadows.png");
/// let rendered = Render {
///     args: &args,
///     compare: Some(book),
///     out: Some(Path::new(".whitted/ch04_shadows.png")),
///     quiet: true,
///     ..Render::new(exe, root)
/// }
/// .run()?;
/// # Ok::<(), whitted_learn::chapter_binary::RunError>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Render<'a> {
    /// The chapter binary's executable, as cargo built it.
    pub exe: &'a Path,
    /// Its arguments before the ones below: a figure's (the scene, `--view`, `--width` …), or
    /// others (`--inspect-grid N`).
    pub args: &'a [String],
    /// Where it runs: the project's root, against which relative paths in `args` resolve.
    pub dir: &'a Path,
    /// `--compare BOOK.png`: the picture it is compared with, pixel by pixel (its `compare:`
    /// line on stdout, and the two side by side with their difference in `out`).
    pub compare: Option<&'a Path>,
    /// `--against TREES.json --json`: the reference's trees it traces again and compares,
    /// one JSON line a pixel on stdout.
    pub against: Option<&'a Path>,
    /// `--quiet`: nothing on stderr but an error (no progress, no speed).
    pub quiet: bool,
    /// `-o PICTURE.png`: where the picture goes.
    pub out: Option<&'a Path>,
    /// Environment variables removed before the run.
    pub env_remove: &'a [&'a str],
    /// Environment variables set, after those removed (a known mistake's switch).
    pub env: &'a [(&'a str, &'a str)],
    /// The time limit: past it, the binary is killed ([`Rendered::status`] is `None`). It runs
    /// to its end when `None`.
    pub timeout: Option<Duration>,
    /// At most this many bytes of its stdout, and of its stderr, are read back; all of them
    /// when `None`.
    pub output_limit: Option<u64>,
}

/// Why a chapter binary could not be run.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// It could not be started.
    #[error("{0}")]
    Start(std::io::Error),
    /// Its output could not be kept, or it could not be waited for.
    #[error("{0}")]
    Output(std::io::Error),
}

impl RunError {
    /// The I/O error underneath.
    #[must_use]
    pub fn into_io(self) -> std::io::Error {
        match self {
            RunError::Start(e) | RunError::Output(e) => e,
        }
    }
}

/// What a chapter binary's run said.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// How it ended; `None` when it was killed at its time limit.
    pub status: Option<ExitStatus>,
    /// Its stdout (as UTF-8, lossily; up to the run's output limit).
    pub stdout: String,
    /// Its stderr, likewise.
    pub stderr: String,
}

impl<'a> Render<'a> {
    /// `exe` run from `dir`, with no argument, no time limit, and all its output read back.
    #[must_use]
    pub fn new(exe: &'a Path, dir: &'a Path) -> Self {
        Self {
            exe,
            args: &[],
            dir,
            compare: None,
            against: None,
            quiet: false,
            out: None,
            env_remove: &[],
            env: &[],
            timeout: None,
            output_limit: None,
        }
    }

    /// The arguments the binary gets, in the order the module's documentation shows.
    #[must_use]
    pub fn arguments(&self) -> Vec<OsString> {
        let mut out: Vec<OsString> = self.args.iter().map(OsString::from).collect();
        if let Some(book) = self.compare {
            out.extend(["--compare".into(), book.into()]);
        }
        if let Some(trees) = self.against {
            out.extend(["--against".into(), trees.into(), "--json".into()]);
        }
        if self.quiet {
            out.push("--quiet".into());
        }
        if let Some(png) = self.out {
            out.extend(["-o".into(), png.into()]);
        }
        out
    }

    /// Runs the binary itself.
    pub fn run(&self) -> Result<Rendered, RunError> {
        self.run_in(Command::new(self.exe))
    }

    /// Runs the binary as `command` starts it (a sandbox's command for it, which the
    /// arguments follow): its output goes to files of a directory made for this run, read
    /// back once it ends.
    pub fn run_in(&self, mut command: Command) -> Result<Rendered, RunError> {
        for name in self.env_remove {
            command.env_remove(name);
        }
        for (name, value) in self.env {
            command.env(name, value);
        }
        let dir = tempfile::tempdir().map_err(RunError::Output)?;
        let (out, err) = (dir.path().join("out"), dir.path().join("err"));
        let file = |p: &Path| std::fs::File::create(p).map_err(RunError::Output);
        let mut child = command
            .args(self.arguments())
            .current_dir(self.dir)
            .stdin(Stdio::null())
            .stdout(file(&out)?)
            .stderr(file(&err)?)
            .spawn()
            .map_err(RunError::Start)?;
        let status = match self.timeout {
            None => Some(child.wait().map_err(RunError::Output)?),
            Some(limit) => wait_within(&mut child, limit).map_err(RunError::Output)?,
        };
        Ok(Rendered {
            status,
            stdout: read_text(&out, self.output_limit),
            stderr: read_text(&err, self.output_limit),
        })
    }
}

/// Waits for `child` until `limit` has passed, then kills it (`None`).
fn wait_within(child: &mut Child, limit: Duration) -> std::io::Result<Option<ExitStatus>> {
    let started = Instant::now();
    loop {
        match child.try_wait()? {
            Some(status) => return Ok(Some(status)),
            None if started.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Ok(None);
            }
            None => std::thread::sleep(Duration::from_millis(20)),
        }
    }
}

/// The text of the file at `path`, at most `limit` bytes of it (empty when it cannot be read).
fn read_text(path: &Path, limit: Option<u64>) -> String {
    let mut bytes = Vec::new();
    if let Ok(f) = std::fs::File::open(path) {
        let _ = f.take(limit.unwrap_or(u64::MAX)).read_to_end(&mut bytes);
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

impl Rendered {
    /// Whether it ended, and with success.
    #[must_use]
    pub fn success(&self) -> bool {
        self.status.is_some_and(|s| s.success())
    }

    /// Its `compare:` line (with `--compare`) and each pixel's tree compared (with
    /// `--against`), in order.
    #[must_use]
    pub fn compared(&self) -> (Option<String>, Vec<Against>) {
        read_output(&self.stdout)
    }

    /// The one line it stopped with ([`error_line`] of its stderr).
    #[must_use]
    pub fn error_line(&self) -> Option<&str> {
        error_line(&self.stderr)
    }
}

/// The one line a chapter binary that stopped says on `stderr`: its last `error: …` line,
/// without `error: ` (an exercise not written yet says which).
#[must_use]
pub fn error_line(stderr: &str) -> Option<&str> {
    stderr.lines().rev().find_map(|l| l.strip_prefix("error: "))
}

/// The picture a chapter binary wrote at `path`, when it is a plain file of at most
/// `max_bytes` that starts as a PNG does (the bytes are not decoded: they are passed on as
/// they are).
#[must_use]
pub fn read_picture(path: &Path, max_bytes: u64) -> Option<Vec<u8>> {
    std::fs::symlink_metadata(path)
        .ok()
        .filter(|m| m.is_file() && m.len() <= max_bytes)
        .and_then(|_| std::fs::read(path).ok())
        .filter(|bytes| bytes.starts_with(b"\x89PNG\r\n\x1a\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn figure(file: &str, binary: &str) -> Figure {
        Figure {
            file: file.into(),
            binary: binary.into(),
            args: vec![format!("scenes/{binary}.toml")],
            line: 1,
        }
    }

    /// A chapter's own figure is `chNN_name.png` drawn by `chNN_name`, wherever the list
    /// puts it, and not another figure its binary draws.
    #[test]
    fn a_chapters_figure_is_the_one_named_after_its_binary() {
        let figures = [
            figure("ch02-normals.png", "ch02_generic_objects"),
            figure("ch02_generic_objects.png", "ch02_generic_objects"),
        ];
        let found = chapter_figure(&figures, 2).map(|f| f.file.as_str());
        assert_eq!(found, Some("ch02_generic_objects.png"));
        assert_eq!(chapter_figure(&figures, 3), None);
        assert_eq!(chapter_figure(&figures, 9), None);
    }

    /// The arguments come in one order: the figure's, then what is compared, then where
    /// the picture goes.
    #[test]
    fn the_arguments_follow_the_figures() {
        let args = ["scene.toml".to_string(), "--width".into(), "40".into()];
        let render = Render {
            args: &args,
            compare: Some(Path::new("book.png")),
            against: Some(Path::new("trees.json")),
            quiet: true,
            out: Some(Path::new("out.png")),
            ..Render::new(Path::new("ch05"), Path::new("."))
        };
        let words: Vec<String> = render
            .arguments()
            .iter()
            .map(|a| a.to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            words.join(" "),
            "scene.toml --width 40 --compare book.png --against trees.json --json --quiet -o out.png"
        );
        let plain = Render::new(Path::new("ch05"), Path::new(".")).arguments();
        assert!(plain.is_empty(), "{plain:?}");
    }

    /// A build that failed says so in one line, with the compiler's first error.
    #[test]
    fn binaries_that_do_not_build_say_why_in_one_line() {
        let failed = Built {
            stderr: "error: could not compile `whitted`\n".into(),
            ..Built::default()
        };
        let why = executables(Ok(failed)).unwrap_err().to_string();
        assert_eq!(
            why,
            "the chapter binaries do not build: error: could not compile `whitted`"
        );
    }

    /// The last `error: ` line is the one a render stopped with.
    #[test]
    fn a_render_stops_with_its_last_error_line() {
        let stderr = "rendering …\nerror: first\nerror: exercise sphere_coefficients (2.6) is not written yet\n";
        assert_eq!(
            error_line(stderr),
            Some("exercise sphere_coefficients (2.6) is not written yet")
        );
        assert_eq!(error_line("thread 'main' panicked"), None);
    }

    /// A run reads back what the binary printed, in its directory, with its environment,
    /// within the output limit.
    #[cfg(unix)]
    #[test]
    fn a_run_reads_back_what_the_binary_printed() {
        let dir = tempfile::tempdir().unwrap();
        let args = [
            "-c".to_string(),
            "echo compare: the same as the reference; echo \"$WHO in $(basename \"$(pwd)\")\"; \
             echo error: stopped >&2; exit 3"
                .into(),
        ];
        let rendered = Render {
            args: &args,
            env: &[("WHO", "sh")],
            ..Render::new(Path::new("/bin/sh"), dir.path())
        }
        .run()
        .unwrap();
        assert!(!rendered.success());
        assert_eq!(rendered.status.and_then(|s| s.code()), Some(3));
        let name = dir.path().file_name().unwrap().to_string_lossy();
        assert_eq!(
            rendered.stdout,
            format!("compare: the same as the reference\nsh in {name}\n")
        );
        assert_eq!(rendered.error_line(), Some("stopped"));
        let (compare, against) = rendered.compared();
        assert_eq!(
            compare.as_deref(),
            Some("compare: the same as the reference")
        );
        assert!(against.is_empty());
        let capped = Render {
            args: &args,
            output_limit: Some(7),
            ..Render::new(Path::new("/bin/sh"), dir.path())
        }
        .run()
        .unwrap();
        assert_eq!(capped.stdout, "compare");
    }

    /// A binary past its time limit is killed, and a binary that does not exist does not
    /// start.
    #[cfg(unix)]
    #[test]
    fn a_run_past_its_time_limit_is_stopped() {
        let args = ["-c".to_string(), "sleep 5".into()];
        let started = Instant::now();
        let rendered = Render {
            args: &args,
            timeout: Some(Duration::from_millis(100)),
            ..Render::new(Path::new("/bin/sh"), Path::new("."))
        }
        .run()
        .unwrap();
        assert_eq!(rendered.status, None);
        assert!(!rendered.success());
        assert!(started.elapsed() < Duration::from_secs(4));
        let missing = Render::new(Path::new("/nowhere/ch01_camera_rays"), Path::new(".")).run();
        assert!(matches!(missing, Err(RunError::Start(_))), "{missing:?}");
    }

    /// Only a plain file that starts as a PNG, and is small enough, is taken back.
    #[test]
    fn only_a_small_png_is_taken_back() {
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("picture.png");
        let bytes = b"\x89PNG\r\n\x1a\nrest".to_vec();
        std::fs::write(&png, &bytes).unwrap();
        assert_eq!(read_picture(&png, 100), Some(bytes));
        assert_eq!(read_picture(&png, 4), None);
        std::fs::write(&png, b"GIF89a").unwrap();
        assert_eq!(read_picture(&png, 100), None);
        assert_eq!(read_picture(&dir.path().join("none.png"), 100), None);
    }
}
