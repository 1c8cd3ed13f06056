//! The submission's own pictures: its code renders the book's figure of a chapter (the
//! chapter binary built from the graded copy, in the build sandbox; the render in the run
//! sandbox) with `--compare` against the committed figure, run as `cargo learn` runs it
//! ([`whitted_learn::chapter_binary`]).
//!
//! - **Feedback** ([`feedback`]): for each graded chapter that lost points, the render also
//!   traces the pixels of the chapter's reference ray trees (`--against
//!   chapters/chNN_name/trees.json`), so that a report can say, as `cargo learn` does, how many
//!   pixels differ from the book's figure and the first wrong number of the trees with the
//!   exercise that computed it, and show the three pictures side by side (the student's, the
//!   book's, their difference). A chapter that cannot render says why (the exercise it waits
//!   for).
//! - **The leaderboard** ([`measure`]): the last graded chapter's figure drawn alone (no
//!   `--compare`: the render is shown nothing of the book's), its speed in millions of the
//!   figure's pixels a second on the grader's clock, from the binary's start to its end, and
//!   its error, the share of its pixels that differ from the book's figure as the grader
//!   compares them. Nothing the binary prints is read, so a body that prints a speed or a
//!   comparison changes neither.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use super::sandbox::{Policy, Sandbox};
use crate::cargo::Wrapper;
use crate::figures;
use crate::layout;
use whitted_learn::chapter_binary::{self, Render, RunError};
use whitted_learn::trees::{self as learn_trees, Against};

/// The figures' manifest, in the project.
pub(super) use whitted_learn::figures::FIGURES;

/// How a submission's code renders.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderScore {
    /// The figure rendered (`ch05_reflection_refraction.png`).
    pub figure: String,
    /// Millions of the figure's pixels a second, on the grader's clock.
    pub pixels_per_second: f64,
    /// The share of pixels that differ from the committed figure, in percent, as the grader
    /// compares them.
    pub differing: f64,
}

/// By how many 8-bit levels a channel may differ from the book's figure and count as the
/// same, as the chapter binaries' `--compare` counts.
const SAME_WITHIN: u8 = 2;

/// The files the renders need in the graded copy: the figures' manifest, the figures and the
/// reference's ray trees (public data: every handout holds them).
pub(super) fn needs(file: &Path) -> bool {
    file == Path::new(FIGURES)
        || file.starts_with("docs/src/figures")
        || (file.starts_with("chapters") && file.file_name().is_some_and(|n| n == "trees.json"))
}

/// The largest picture a report carries: the three side by side of a chapter's figure take
/// about 100 kB, and PrairieLearn takes a results file of 1 MB at the most.
pub const PICTURE_BYTES: u64 = 400_000;

/// The most of a render's stdout, and of its stderr, that is read back.
const OUTPUT_BYTES: u64 = 1 << 20;

/// What the submission's code shows of one chapter, beside the reference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChapterFeedback {
    /// The chapter.
    pub chapter: u8,
    /// The binary's `compare:` line: how many pixels differ from the book's figure, and the
    /// first one.
    pub compare: Option<String>,
    /// The trees compared with the reference's, one a pixel.
    pub against: Vec<Against>,
    /// The PNG of the render, the figure and their difference side by side.
    pub picture: Option<Vec<u8>>,
    /// Why the chapter could not be drawn: the binary's one-line error (the exercise it
    /// waits for, a panic), or what failed around it.
    pub trouble: Option<String>,
}

/// A chapter binary's run on its figure's scene.
struct Ran {
    figure: String,
    success: bool,
    stdout: String,
    stderr: String,
    picture: Option<Vec<u8>>,
    /// From the binary's start to its end, on the grader's clock.
    took: Duration,
    /// The book's figure of the chapter.
    book: PathBuf,
}

/// The binaries of `chapters`, built from the graded copy in one build (in the build
/// sandbox, through `wrapper`).
fn build_binaries(
    project: &Path,
    target_dir: &Path,
    chapters: &[u8],
    wrapper: Option<&Wrapper>,
) -> Result<BTreeMap<u8, PathBuf>, String> {
    let names: Vec<String> = chapters
        .iter()
        .filter_map(|&c| crate::syllabus::chapter(c).map(|c| c.binary.to_string()))
        .collect();
    let built = super::blame::cargo_build(
        project,
        target_dir,
        layout::APP_PACKAGE,
        &[],
        (&names, &[]),
        wrapper,
    );
    let executables = chapter_binary::executables(built).map_err(|e| e.to_string())?;
    // their dependencies are built for these manifests now
    let _ = std::fs::write(target_dir.join(BUILT_FOR), manifests(project));
    Ok(chapters
        .iter()
        .filter_map(|&c| {
            let name = crate::syllabus::chapter(c)?.binary;
            executables.get(name).map(|exe| (c, exe.clone()))
        })
        .collect())
}

/// The file in a build directory that records for which manifests (the project's
/// `Cargo.lock` and `Cargo.toml` files, as text) the chapter binaries' dependencies are built.
const BUILT_FOR: &str = "feedback-built-for";

/// The project's manifests as one text: what decides which dependencies the chapter binaries
/// need, and how they are built.
fn manifests(project: &Path) -> String {
    let mut files = vec![project.join("Cargo.lock"), project.join("Cargo.toml")];
    if let Ok(crates) = std::fs::read_dir(project.join("crates")) {
        let mut each: Vec<PathBuf> = crates
            .filter_map(Result::ok)
            .map(|e| e.path().join("Cargo.toml"))
            .collect();
        each.sort();
        files.extend(each);
    }
    files
        .iter()
        .map(|f| format!("{}\n{}\n", f.display(), read_capped(f, 1 << 20)))
        .collect()
}

/// Builds every chapter binary when the build directory's were not built for the project's
/// manifests as they are, so that the first grading after a change of them, even one that
/// lost no point, pays for what a later one's feedback needs (the programs' own
/// dependencies) and no later grading does. A failure is not reported here: the feedback
/// that needs the binaries says why they are missing.
pub(super) fn warm(project: &Path, target_dir: &Path, wrapper: Option<&Wrapper>) {
    let now = manifests(project);
    if std::fs::read_to_string(target_dir.join(BUILT_FOR)).is_ok_and(|was| was == now) {
        return;
    }
    let all: Vec<u8> = crate::syllabus::CHAPTERS.iter().map(|c| c.number).collect();
    let _ = build_binaries(project, target_dir, &all, wrapper);
}

/// Reads at most `limit` bytes of the file at `path` as clean text ([`super::clean`]: the
/// student's code printed it); empty when it cannot.
fn read_capped(path: &Path, limit: u64) -> String {
    let mut bytes = Vec::new();
    if let Ok(f) = std::fs::File::open(path) {
        let _ = std::io::Read::read_to_end(&mut std::io::Read::take(f, limit), &mut bytes);
    }
    super::clean::clean(&String::from_utf8_lossy(&bytes))
}

/// Runs chapter `chapter`'s binary `exe` on its figure's scene at the figure's settings, in
/// the run sandbox when there is one, under `timeout`: for `feedback`, with `--compare` and
/// `--against` its trees; else alone, shown nothing of the book's. The picture goes to a
/// directory made for this run alone, and is taken back only when it is a PNG of at most
/// [`PICTURE_BYTES`].
fn run_figure(
    project: &Path,
    target_dir: &Path,
    (chapter, exe): (u8, &Path),
    sandbox: Option<&Sandbox>,
    timeout: Duration,
    feedback: bool,
) -> Result<Ran, String> {
    let about = crate::syllabus::chapter(chapter).ok_or_else(|| format!("no chapter {chapter}"))?;
    let binary = about.binary;
    let figures = figures::read_figures(&project.join(FIGURES)).map_err(|e| e.to_string())?;
    let figure = chapter_binary::chapter_figure(&figures, chapter)
        .ok_or_else(|| format!("{FIGURES} lists no figure of {binary}"))?;
    let reference = project.join(figure.path());
    let trees = chapter_binary::chapter_trees(project, chapter).filter(|_| feedback);
    let out_dir = target_dir.join("feedback").join(binary);
    if out_dir.exists() {
        std::fs::remove_dir_all(&out_dir).map_err(|e| format!("{}: {e}", out_dir.display()))?;
    }
    let out_png = out_dir.join("picture.png");
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
        .collect();
    let policy = match sandbox {
        Some(s) => {
            let mut policy = s.policy.clone();
            if feedback {
                policy.read.push(reference.clone());
            }
            policy.read.extend(trees.clone());
            policy
                .writable(&out_dir)
                .map_err(|e| format!("{}: {e}", out_dir.display()))?;
            Some(policy)
        }
        None => {
            std::fs::create_dir_all(&out_dir).map_err(|e| format!("{}: {e}", out_dir.display()))?;
            None
        }
    };
    let command = policy
        .as_ref()
        .map_or_else(|| Command::new(exe), |p| p.command(exe, project));
    let started = std::time::Instant::now();
    let rendered = Render {
        args: &args,
        compare: feedback.then_some(reference.as_path()),
        against: trees.as_deref(),
        out: Some(&out_png),
        timeout: Some(timeout),
        output_limit: Some(OUTPUT_BYTES),
        ..Render::new(exe, project)
    }
    .run_in(command)
    .map_err(|e| match e {
        RunError::Start(e) => format!("cannot run {binary}: {e}"),
        RunError::Output(e) => e.to_string(),
    })?;
    let took = started.elapsed();
    policy.iter().for_each(Policy::sweep);
    if rendered.status.is_none() {
        let _ = std::fs::remove_dir_all(&out_dir);
        return Err(format!("{binary} ran past {} s", timeout.as_secs()));
    }
    let picture = chapter_binary::read_picture(&out_png, PICTURE_BYTES);
    let _ = std::fs::remove_dir_all(&out_dir);
    Ok(Ran {
        figure: figure.file.clone(),
        success: rendered.success(),
        stdout: super::clean::clean(&rendered.stdout),
        stderr: super::clean::clean(&rendered.stderr),
        picture,
        took,
        book: reference,
    })
}

/// The one line a chapter binary's failed run says: its `error: …` line (an exercise not
/// written yet says which), else the panic's message.
fn one_line_error(stderr: &str) -> String {
    chapter_binary::error_line(stderr)
        .map_or_else(|| super::junit::panic_message(stderr), str::to_string)
}

/// The feedback of `chapters` (those that lost points): the chapter binaries built from the
/// graded copy in one build, each run on its figure with `--compare` and `--against`.
pub(super) fn feedback(
    project: &Path,
    target_dir: &Path,
    chapters: &[u8],
    wrapper: Option<&Wrapper>,
    sandbox: Option<&Sandbox>,
    timeout: Duration,
) -> Vec<ChapterFeedback> {
    let trouble = |chapter: u8, why: String| ChapterFeedback {
        chapter,
        compare: None,
        against: Vec::new(),
        picture: None,
        trouble: Some(why),
    };
    let exes = match build_binaries(project, target_dir, chapters, wrapper) {
        Ok(e) => e,
        Err(why) => return chapters.iter().map(|&c| trouble(c, why.clone())).collect(),
    };
    chapters
        .iter()
        .map(|&c| {
            let Some(exe) = exes.get(&c) else {
                return trouble(c, format!("cargo built no binary for chapter {c}"));
            };
            match run_figure(project, target_dir, (c, exe), sandbox, timeout, true) {
                Ok(ran) if ran.success => {
                    let (compare, against) = learn_trees::read_output(&ran.stdout);
                    ChapterFeedback {
                        chapter: c,
                        compare,
                        against,
                        picture: ran.picture,
                        trouble: None,
                    }
                }
                Ok(ran) => trouble(c, one_line_error(&ran.stderr)),
                Err(why) => trouble(c, why),
            }
        })
        .collect()
}

/// Builds the binary of `chapter`'s figure from the graded copy `project` and renders it for
/// the leaderboard, alone; `Err` says why there is no score (the code panics, the figure is
/// not listed …).
pub(super) fn measure(
    project: &Path,
    target_dir: &Path,
    chapter: u8,
    wrapper: Option<&Wrapper>,
    sandbox: Option<&Sandbox>,
    timeout: Duration,
) -> Result<RenderScore, String> {
    let exes = build_binaries(project, target_dir, &[chapter], wrapper)?;
    let exe = exes
        .get(&chapter)
        .ok_or_else(|| format!("cargo built no binary for chapter {chapter}"))?;
    let ran = run_figure(project, target_dir, (chapter, exe), sandbox, timeout, false)?;
    if !ran.success {
        return Err(format!(
            "the render failed: {}",
            one_line_error(&ran.stderr)
        ));
    }
    let picture = ran
        .picture
        .as_deref()
        .ok_or("the render wrote no picture".to_string())?;
    let book = figures::read_rgba(&ran.book).map_err(|e| e.to_string())?;
    judged(&ran.figure, picture, &book, ran.took)
}

/// The leaderboard's score of a render that wrote `picture` (a PNG) in `took`, against the
/// book's figure `book`: the speed in millions of its pixels a second, and the share of its
/// pixels off by more than [`SAME_WITHIN`], both the grader's own figures.
pub(super) fn judged(
    figure: &str,
    picture: &[u8],
    book: &figures::Rgba,
    took: Duration,
) -> Result<RenderScore, String> {
    let (width, height, rgba) = whitted_syllabus::words::decode_rgba(std::io::Cursor::new(picture))
        .map_err(|e| format!("the render's picture: {e}"))?;
    let pixels = f64::from(width) * f64::from(height);
    let differing = match figures::compare_rgba(book, &((width, height), rgba), SAME_WITHIN) {
        figures::Difference::Same => 0.0,
        figures::Difference::Pixels { pixels: off, .. } => 100.0 * off as f64 / pixels,
        figures::Difference::Size(want, got) => {
            return Err(format!(
                "the render is {}×{}, the book's figure {}×{}",
                got.0, got.1, want.0, want.1
            ));
        }
    };
    Ok(RenderScore {
        figure: figure.to_string(),
        pixels_per_second: pixels / took.as_secs_f64().max(1e-6) / 1e6,
        differing,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2×2 RGB PNG of `pixels`, row by row.
    fn png_of(pixels: [[u8; 3]; 4]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, 2, 2);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(pixels.as_flattened()).unwrap();
        writer.finish().unwrap();
        out
    }

    /// The leaderboard's figures are the grader's: the pixels of the picture over the time it
    /// measured, and the share of pixels off the book's figure by more than two levels (one
    /// of four here; one off by two levels counts as the same).
    #[test]
    fn the_leaderboard_counts_the_pictures_pixels_on_the_graders_clock() {
        let grey = [100, 100, 100];
        let book = (
            (2, 2),
            [grey; 4]
                .iter()
                .flat_map(|p| [p[0], p[1], p[2], 255])
                .collect(),
        );
        let picture = png_of([grey, [102, 100, 98], [0, 0, 0], grey]);
        let took = Duration::from_millis(2);
        let score = judged("f.png", &picture, &book, took).unwrap();
        assert!(
            (score.differing - 25.0).abs() < 1e-9,
            "{} % of pixels off, expected 25 %",
            score.differing
        );
        let expected = 4.0 / 0.002 / 1e6;
        assert!(
            (score.pixels_per_second - expected).abs() < 1e-12,
            "{} M pixels/s, expected {expected}",
            score.pixels_per_second
        );
        let wide = ((4, 1), vec![0; 16]);
        let err = judged("f.png", &picture, &wide, took).unwrap_err();
        assert_eq!(err, "the render is 2×2, the book's figure 4×1");
    }
}
