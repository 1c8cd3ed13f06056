//! The leaderboard's measure of a submission: its code renders the book's figure of the last
//! graded chapter (the chapter binary built from the graded copy, in the build sandbox) and
//! the render runs in the run sandbox with `--compare` against the committed figure. Its
//! speed is the binary's `M rays/s` (stderr), its error the share of pixels the `compare:`
//! line (stdout) says differ.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::sandbox::Sandbox;
use crate::cargo::Wrapper;
use crate::figures;
use crate::layout;

/// The figures' manifest, in the project.
pub(super) const FIGURES: &str = "docs/figures.toml";

/// How a submission's code renders.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderScore {
    /// The figure rendered (`ch05_reflection_refraction.png`).
    pub figure: String,
    /// Millions of rays a second.
    pub rays_per_second: f64,
    /// The share of pixels that differ from the committed figure, in percent.
    pub differing: f64,
}

/// The files the render needs in the graded copy: the figures' manifest and the figures.
pub(super) fn needs(file: &Path) -> bool {
    file == Path::new(FIGURES) || file.starts_with("docs/src/figures")
}

/// Builds the binary of `chapter`'s figure from the graded copy `project` and renders it;
/// `Err` says why there is no score (the code panics, the figure is not listed …).
pub(super) fn measure(
    project: &Path,
    target_dir: &Path,
    chapter: u8,
    wrapper: Option<&Wrapper>,
    sandbox: Option<&Sandbox>,
    timeout: Duration,
) -> Result<RenderScore, String> {
    let binary = crate::syllabus::chapter(chapter)
        .map(|c| c.binary)
        .ok_or_else(|| format!("no chapter {chapter}"))?;
    let figure = figures::read_figures(&project.join(FIGURES))
        .map_err(|e| e.to_string())?
        .into_iter()
        .find(|f| f.binary == binary)
        .ok_or_else(|| format!("{FIGURES} lists no figure of {binary}"))?;
    let built = super::blame::cargo_build(
        project,
        target_dir,
        layout::APP_PACKAGE,
        &[],
        &[binary.to_string()],
        wrapper,
    )
    .map_err(|e| e.to_string())?;
    let exe = built
        .executables
        .get(binary)
        .filter(|_| built.success)
        .ok_or_else(|| format!("{binary} does not build: {}", built.first_error()))?;
    let reference = project.join("docs/src/figures").join(&figure.file);
    let args: Vec<String> = figure
        .args
        .iter()
        .map(|a| {
            // the scene and other paths are relative to the project
            if project.join(a).exists() {
                project.join(a).display().to_string()
            } else {
                a.clone()
            }
        })
        .chain([
            "--compare".into(),
            reference.display().to_string(),
            "-o".into(),
            "/tmp/render.png".into(),
        ])
        .collect();
    let mut command = match sandbox {
        Some(s) => {
            let mut policy = s.policy.clone();
            policy.read.push(reference.clone());
            policy.command(exe, project)
        }
        None => Command::new(exe),
    };
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let (out, err) = (dir.path().join("out"), dir.path().join("err"));
    let file = |p: &PathBuf| std::fs::File::create(p).map_err(|e| e.to_string());
    let mut child = command
        .args(&args)
        .current_dir(project)
        .stdin(Stdio::null())
        .stdout(file(&out)?)
        .stderr(file(&err)?)
        .spawn()
        .map_err(|e| format!("cannot run {binary}: {e}"))?;
    let started = Instant::now();
    let status = loop {
        match child.try_wait().map_err(|e| e.to_string())? {
            Some(s) => break s,
            None if started.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!("{binary} ran past {} s", timeout.as_secs()));
            }
            None => std::thread::sleep(Duration::from_millis(20)),
        }
    };
    let read = |p: &PathBuf| std::fs::read_to_string(p).unwrap_or_default();
    let (stdout, stderr) = (read(&out), read(&err));
    if !status.success() {
        return Err(format!(
            "{binary} failed: {}",
            super::junit::panic_message(&stderr)
        ));
    }
    parse(&figure.file, &stdout, &stderr)
}

/// The score in a chapter binary's output: `… M rays/s` on stderr, the `compare:` line on
/// stdout.
pub(super) fn parse(figure: &str, stdout: &str, stderr: &str) -> Result<RenderScore, String> {
    let rays = stderr
        .lines()
        .rev()
        .find_map(|l| {
            let before = l.strip_suffix(" M rays/s")?;
            before.rsplit(' ').next()?.parse::<f64>().ok()
        })
        .ok_or("no `M rays/s` in the render's output".to_string())?;
    let compare = stdout
        .lines()
        .find(|l| l.starts_with("compare:"))
        .ok_or("no `compare:` line in the render's output".to_string())?;
    let differing = if compare.contains("the same as the reference") {
        0.0
    } else {
        compare
            .split('(')
            .nth(1)
            .and_then(|r| r.split('%').next())
            .and_then(|p| p.parse::<f64>().ok())
            .ok_or_else(|| format!("cannot read `{compare}`"))?
    };
    Ok(RenderScore {
        figure: figure.to_string(),
        rays_per_second: rays,
        differing,
    })
}
