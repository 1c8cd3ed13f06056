//! The pictures of `cargo learn`: after each check, what the student's own code draws of the
//! chapter being written, beside the course book's figure of the same stage and their
//! difference.
//!
//! A chapter's own picture needs every exercise of the chapter, so while a chapter is written
//! the picture is one of the book's stages ([`choose`]):
//!
//! - **the exercise's own picture**, when the exercise the verdict is on is written (and
//!   fails): its manifest `picture`, a figure that shows the quantity it computes (the
//!   normals for a normal, each light's max(n·s, 0) for the cosine law), so that its mistake
//!   is in sight; otherwise the picture of the newest exercise of the chapter written before
//!   it: what the student has written so far;
//! - **the chapter's picture**, with the first wrong number of its ray trees ([`crate::trees`]),
//!   once every exercise of the chapter is written, and when a chapter turns green;
//! - **the chapter before's road over this chapter's scene** (the book's figure drawn by the
//!   previous chapter's binary: no objects yet, no shadows yet, no mirror rays yet), when
//!   nothing of the chapter that it can draw is written, or when what is chosen cannot be
//!   drawn yet (chapter 2's scene holds every shape: its pictures need all of them).
//!
//! Each is the book's figure as `docs/figures.toml` lists it ([`crate::figures`]), drawn by
//! the project's own build of that figure's binary with the figure's arguments and
//! `--compare` with the book's PNG, into `.whitted/FILE`. Nothing of the reference's code is
//! needed: the figures are pictures, the trees numbers.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::{Path, PathBuf};

use crate::ToolError;
use crate::figures::{self, Figure};
use crate::learn::{self, STATE_DIR, Say, State, Style};
use crate::manifest::Manifest;

/// The width of a chapter's picture when the handout has no figure of it to compare with (the
/// height follows the scene).
pub const PICTURE_WIDTH: u32 = 240;

/// A picture a check draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// The picture of one exercise (its manifest index): its `picture` figure.
    Exercise(usize),
    /// A chapter's own picture, with its ray trees.
    Chapter(u8),
    /// A chapter's scene drawn by the chapter before it.
    Before(u8),
}

/// The newest chapter whose exercises, and all earlier chapters', are done: the one whose
/// picture the student's code can draw whole.
#[must_use]
pub fn drawable_chapter(manifest: &Manifest, states: &[State]) -> Option<u8> {
    let mut out = None;
    for chapter in whitted_syllabus::CHAPTERS.iter().map(|c| c.number) {
        if of_chapter(manifest, chapter).all(|i| states[i] == State::Done) {
            out = Some(chapter);
        } else {
            break;
        }
    }
    out
}

/// The chapter whose picture a check is about: a chapter that turned green at this check (the
/// first of them: when one exercise turns several green, as the first of chapter 3 may turn
/// chapters 3 to 5, the one the student was working in), else the chapter of the next exercise
/// (the one the student works on, whose picture shows what is still wrong), else the last.
#[must_use]
pub fn picture_chapter(manifest: &Manifest, before: &[State], now: &[State]) -> u8 {
    turned_green(manifest, before, now)
        .or_else(|| next(now).map(|i| manifest.entries[i].chapter))
        .unwrap_or(whitted_syllabus::LAST)
}

/// The pictures a check draws, in the order they are shown (see the module's documentation):
/// `before` holds the states of the last check, `now` this one's, and `on` the exercise the
/// verdict is on (by default the first not done).
#[must_use]
pub fn choose(
    manifest: &Manifest,
    before: &[State],
    now: &[State],
    on: Option<usize>,
) -> Vec<Stage> {
    if let Some(chapter) = turned_green(manifest, before, now) {
        return vec![Stage::Chapter(chapter)];
    }
    let Some(x) = on.or_else(|| next(now)) else {
        return vec![Stage::Chapter(whitted_syllabus::LAST)];
    };
    let chapter = manifest.entries[x].chapter;
    let written = |i: usize| matches!(now[i], State::Done | State::Failing(_));
    let has_picture = |i: usize| manifest.entries[i].exercise.picture.is_some();
    let mut out = Vec::new();
    let stage = if written(x) && has_picture(x) {
        Some(x)
    } else {
        of_chapter(manifest, chapter)
            .filter(|&i| i < x && written(i) && has_picture(i))
            .last()
    };
    out.extend(stage.map(Stage::Exercise));
    if of_chapter(manifest, chapter).all(written) {
        out.push(Stage::Chapter(chapter));
    }
    if out.is_empty() {
        out.push(if chapter > 1 {
            Stage::Before(chapter)
        } else {
            Stage::Chapter(chapter)
        });
    }
    out
}

/// The first exercise not done.
fn next(states: &[State]) -> Option<usize> {
    states.iter().position(|s| *s != State::Done)
}

/// The manifest indices of chapter `chapter`'s exercises.
fn of_chapter(manifest: &Manifest, chapter: u8) -> impl Iterator<Item = usize> + '_ {
    (0..manifest.entries.len()).filter(move |&i| manifest.entries[i].chapter == chapter)
}

/// The first chapter that is drawable now and was known not to be at the last check (one of
/// its exercises was not done then; a first check knows nothing of before, and turns nothing).
fn turned_green(manifest: &Manifest, before: &[State], now: &[State]) -> Option<u8> {
    let was_not_done = |i: usize| {
        before
            .get(i)
            .is_some_and(|s| !matches!(s, State::Done | State::Unknown))
    };
    drawable_chapter(manifest, now)
        .and_then(|drawable| (1..=drawable).find(|&c| of_chapter(manifest, c).any(was_not_done)))
}

/// The book's figure that shows `stage`, from the figures' list `figures`: `None` when the
/// handout has none (a chapter's picture is then drawn alone, [`PICTURE_WIDTH`] wide).
#[must_use]
pub fn figure_of<'f>(
    manifest: &Manifest,
    figures: &'f [Figure],
    stage: Stage,
) -> Option<&'f Figure> {
    match stage {
        Stage::Exercise(i) => {
            let file = manifest.entries.get(i)?.exercise.picture.as_deref()?;
            figures.iter().find(|f| f.file == file)
        }
        Stage::Chapter(c) => {
            let binary = whitted_syllabus::chapter(c)?.binary;
            let file = format!("{binary}.png");
            figures
                .iter()
                .find(|f| f.file == file && f.binary == binary)
        }
        Stage::Before(c) => {
            let scene = whitted_syllabus::chapter(c)?.scene();
            let road = whitted_syllabus::chapter(c.checked_sub(1)?)?.binary;
            figures
                .iter()
                .find(|f| f.binary == road && f.scene() == Some(scene.as_str()))
        }
    }
}

/// A picture drawn by the student's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Picture {
    /// The PNG written: with a figure to compare with, the student's render, the figure and
    /// their difference side by side; else the render alone.
    pub path: PathBuf,
    /// The chapter binary's `compare:` line (how many pixels differ from the figure, and
    /// where the first one is), when there was a figure.
    pub compare: Option<String>,
    /// The student's ray trees compared with the reference's at the pixels of the chapter's
    /// trees file, for a chapter's own picture ([`crate::trees`]).
    pub against: Vec<crate::trees::Against>,
}

/// Why a picture could not be drawn.
#[derive(Debug)]
pub enum NoPicture {
    /// The render stopped: the chapter binary's one-line error (an exercise it needs is not
    /// written yet, or panics).
    Render(String),
    /// The chapter binary could not be built or run.
    Tool(ToolError),
}

/// What to run for one picture: the binary, its arguments, where the PNG goes, and the
/// chapter whose trees it compares (a chapter's own picture).
struct Job {
    binary: String,
    args: Vec<String>,
    png: PathBuf,
    compare: Option<PathBuf>,
    trees: Option<PathBuf>,
}

/// What to run to draw `stage` in the project at `root`, whose book lists `figures`.
fn job(root: &Path, manifest: &Manifest, figures: &[Figure], stage: Stage) -> Option<Job> {
    let dir = root.join(STATE_DIR);
    if let Some(figure) = figure_of(manifest, figures, stage) {
        let book = root.join(figure.path());
        let trees = match stage {
            Stage::Chapter(c) => crate::trees::trees_file(c)
                .map(|t| root.join(t))
                .filter(|t| t.is_file()),
            _ => None,
        };
        return Some(Job {
            binary: figure.binary.clone(),
            args: figure.args.clone(),
            png: dir.join(&figure.file),
            compare: book.is_file().then_some(book),
            trees,
        });
    }
    // a handout without the book's figures: the chapter's scene alone
    let Stage::Chapter(c) = stage else {
        return None;
    };
    let about = whitted_syllabus::chapter(c)?;
    let mut args = Vec::new();
    if root.join(about.scene()).is_file() {
        args.push(about.scene());
    }
    args.extend(["--width".to_string(), PICTURE_WIDTH.to_string()]);
    Some(Job {
        binary: about.binary.to_string(),
        args,
        png: dir.join(format!("{}.png", about.binary)),
        compare: None,
        trees: None,
    })
}

/// Draws each of `stages` with the project's own chapter binaries (built together, at the
/// loop's profile); a stage the handout has no figure of is left out.
pub fn draw(
    root: &Path,
    manifest: &Manifest,
    stages: &[Stage],
) -> Vec<(Stage, Result<Picture, NoPicture>)> {
    let figures = figures::read_figures(&root.join(figures::FIGURES)).unwrap_or_default();
    let jobs: Vec<(Stage, Job)> = stages
        .iter()
        .filter_map(|&s| job(root, manifest, &figures, s).map(|j| (s, j)))
        .collect();
    let mut bins: Vec<String> = jobs.iter().map(|(_, j)| j.binary.clone()).collect();
    bins.sort();
    bins.dedup();
    if bins.is_empty() {
        return Vec::new();
    }
    let built = learn::build(root, &[], &bins, &Say { report: false });
    let built = match built {
        Ok(b) if b.success => b,
        Ok(b) => {
            let why = format!("the chapter binaries do not build: {}", b.first_error());
            return jobs
                .into_iter()
                .map(|(s, _)| (s, Err(NoPicture::Tool(ToolError::Cargo(why.clone())))))
                .collect();
        }
        Err(e) => {
            let why = e.to_string();
            return jobs
                .into_iter()
                .map(|(s, _)| (s, Err(NoPicture::Tool(ToolError::Cargo(why.clone())))))
                .collect();
        }
    };
    jobs.into_iter()
        .map(|(s, job)| {
            let picture = match built.executables.get(&job.binary) {
                Some(exe) => run(root, exe, &job),
                None => Err(NoPicture::Tool(ToolError::Cargo(format!(
                    "cargo built no binary {}",
                    job.binary
                )))),
            };
            (s, picture)
        })
        .collect()
}

/// Runs the chapter binary `exe` for `job`, from `root`.
fn run(root: &Path, exe: &Path, job: &Job) -> Result<Picture, NoPicture> {
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| NoPicture::Tool(ToolError::io(&dir, e)))?;
    let mut command = std::process::Command::new(exe);
    command.args(&job.args);
    if let Some(book) = &job.compare {
        command.arg("--compare").arg(book);
    }
    // the first wrong number: the same pixels' trees, traced and compared
    if let Some(trees) = &job.trees {
        command.arg("--against").arg(trees).arg("--json");
    }
    let out = command
        .arg("--quiet")
        .arg("-o")
        .arg(&job.png)
        .current_dir(root)
        .stdin(std::process::Stdio::null())
        .output()
        .map_err(|e| {
            NoPicture::Tool(ToolError::Cargo(format!(
                "cannot run {}: {e}",
                exe.display()
            )))
        })?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let line = err
            .lines()
            .rev()
            .find_map(|l| l.strip_prefix("error: "))
            .unwrap_or("the render failed");
        return Err(NoPicture::Render(line.to_string()));
    }
    let (compare, against) = crate::trees::read_output(&String::from_utf8_lossy(&out.stdout));
    Ok(Picture {
        path: job.png.clone(),
        compare,
        against,
    })
}

/// After a check: the pictures [`choose`] picks for the verdict on exercise `on`, drawn, and
/// what each shows.
pub fn report(
    root: &Path,
    manifest: &Manifest,
    before: &[State],
    states: &[State],
    on: Option<usize>,
    style: Style,
) -> String {
    let chosen = choose(manifest, before, states, on);
    let mut drawn = draw(root, manifest, &chosen);
    // none could be drawn yet (the chapter's scene meets an exercise not written): the
    // chapter's scene through the chapter before, which can
    let none = drawn
        .iter()
        .all(|(_, d)| matches!(d, Err(NoPicture::Render(_))));
    let chapter = chosen.first().map(|s| match *s {
        Stage::Exercise(i) => manifest.entries[i].chapter,
        Stage::Chapter(c) | Stage::Before(c) => c,
    });
    if let Some(c) = chapter.filter(|&c| none && c > 1 && !chosen.contains(&Stage::Before(c))) {
        drawn = draw(root, manifest, &[Stage::Before(c)]);
    }
    let mut out = String::new();
    for (stage, drawn) in drawn {
        out += &describe(root, manifest, states, stage, drawn, style);
    }
    out
}

/// The lines of one picture: what it shows and where it is, how it differs from the book's,
/// and for a chapter's picture the first wrong number of its trees.
fn describe(
    root: &Path,
    manifest: &Manifest,
    states: &[State],
    stage: Stage,
    drawn: Result<Picture, NoPicture>,
    style: Style,
) -> String {
    let what = match stage {
        Stage::Exercise(i) => {
            let x = &manifest.entries[i].exercise;
            format!(
                "exercise {}'s quantity ({}) over its chapter's scene",
                x.id, x.title
            )
        }
        Stage::Chapter(c) => format!("chapter {c}'s scene"),
        Stage::Before(c) => format!(
            "chapter {c}'s scene through chapter {}'s road (before chapter {c}'s exercises)",
            c - 1
        ),
    };
    let picture = match drawn {
        Ok(p) => p,
        Err(NoPicture::Render(why)) => {
            return format!("picture: {what} cannot be drawn yet: {why}\n");
        }
        Err(NoPicture::Tool(e)) => return format!("picture: none yet ({e})\n"),
    };
    let path = picture.path.strip_prefix(root).unwrap_or(&picture.path);
    let feedback = match stage {
        Stage::Chapter(_) => crate::trees::feedback(
            root,
            manifest,
            states,
            &picture.against,
            picture.compare.as_deref(),
        ),
        _ => String::new(),
    };
    match &picture.compare {
        Some(compare) => {
            let same = compare.contains("the same as the reference");
            format!(
                "{} picture: {what} as your code draws it, beside the book's and their difference: {}\n  {compare}\n{feedback}",
                if same {
                    style.good("✓")
                } else {
                    style.bad("✗")
                },
                path.display(),
            )
        }
        None => format!(
            "{} picture: {what} as your code draws it: {}\n{feedback}",
            style.good("✓"),
            path.display(),
        ),
    }
}
