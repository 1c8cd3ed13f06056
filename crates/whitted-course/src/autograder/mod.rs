//! `whitted autograder`: whitted's grading on the platforms courses grade on — Gradescope,
//! GitHub Classroom, PrairieLearn and CodeGrade — each given what it asks for by an adapter
//! over one report.
//!
//! A grading ([`crate::grade::Grade`]) becomes one [`Report`]: the score, the time it took, what
//! the student is told about the whole submission, and per test the points, its exercise's
//! displayed id (`number`), tags (chapter, exercise name), whether it is hidden and how long it
//! ran; or, when the submission could not be graded, why. Each platform's file is written
//! from it: [`gradescope`] (`results.json`), [`prairielearn`] (`results.json` with a 0–1 score
//! and `gradable`), [`codegrade`] (JUnit XML, which the instructor's reports use too) and
//! [`classroom`] (one workflow step per exercise, each reading the report). [`package`] writes
//! what an instructor uploads or commits to each platform, and [`run`] is what those packages
//! run for each submission.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub mod classroom;
pub mod codegrade;
pub mod command;
pub mod gradescope;
mod options;
pub mod package;
pub mod prairielearn;
pub mod run;

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::grade::{Grade, Status};
use crate::manifest::Manifest;
use crate::{ToolError, layout};

/// The platforms [`package`] writes for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Platform {
    /// Gradescope: a zip with `setup.sh` and `run_autograder`, `results.json`.
    Gradescope,
    /// GitHub Classroom: a workflow in the student's repository, a step per exercise.
    Classroom,
    /// PrairieLearn's external grader: `/grade/{student,tests,data}` in, `results.json` out.
    Prairielearn,
    /// CodeGrade: JUnit XML from a command.
    Codegrade,
}

impl Platform {
    /// Its name on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Platform::Gradescope => "gradescope",
            Platform::Classroom => "classroom",
            Platform::Prairielearn => "prairielearn",
            Platform::Codegrade => "codegrade",
        }
    }
}

/// How a course shows its results: the settings a package carries to each grading.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Settings {
    /// When students see the hidden tests' points (Gradescope's `visibility`:
    /// `hidden`, `after_due_date`, `after_published` or `visible`).
    pub hidden_visibility: String,
    /// Whether the leaderboard (the render's speed and its error against the reference) is
    /// measured and posted.
    pub leaderboard: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            hidden_visibility: "after_due_date".into(),
            leaderboard: false,
        }
    }
}

/// One test as every platform shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct TestLine {
    /// Its name for the student: the exercise, its title and formula, then the test's name;
    /// for a hidden test only "exercise 2.3, hidden test 1".
    pub name: String,
    /// Its real name within its test target (`sphere::ex_sphere_discriminant_…`), for the
    /// instructor's reports only.
    pub test: String,
    /// The displayed id of its exercise (`2.3`), or `-` when its name says none.
    pub number: String,
    /// The exercise's formula, or empty.
    pub formula: String,
    /// `chapter N` and the exercise's stable name.
    pub tags: Vec<String>,
    /// Its share of its exercise's points, earned.
    pub score: f64,
    /// Its share of its exercise's points.
    pub max: f64,
    /// How it ended.
    pub status: Status,
    /// Why it failed, for the student (empty when it passed, its status alone when hidden).
    pub output: String,
    /// Why it failed, as the test said it (the instructor's).
    pub message: String,
    /// For a failed public test of the exercise a chapter's ray trees point at, the first
    /// wrong number (learn's lines); empty otherwise.
    pub first_wrong: String,
    /// For a failed public test of an exercise that looks like a known mistake, the line that
    /// names it (`a known mistake: this looks like …`); empty otherwise.
    pub known: String,
    /// Whether it is one of the instructor's hidden tests.
    pub hidden: bool,
    /// The chapter it counts for (0 when its name says no exercise).
    pub chapter: u8,
    /// How long it ran, in seconds.
    pub time: f64,
}

/// An entry of Gradescope's leaderboard.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Board {
    /// What is measured (`M pixels/s`).
    pub name: String,
    /// The value.
    pub value: f64,
    /// `desc` when more is better, `asc` when less is.
    pub order: String,
}

/// The most pictures a report carries (each about 100 kB; PrairieLearn's results file takes
/// 1 MB at the most).
pub const MAX_IMAGES: usize = 2;

/// A picture for the student (PrairieLearn's `images`): the student's render beside the
/// book's figure and their difference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// What it shows.
    pub label: String,
    /// The PNG file's bytes.
    pub png: Vec<u8>,
}

/// A submission's results, as every platform's file is written from them.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The submission's name.
    pub student: String,
    /// Points earned.
    pub score: f64,
    /// Points possible.
    pub max: f64,
    /// How long grading took, in seconds.
    pub execution_time: f64,
    /// What the student is told about the whole submission: what did not compile, which
    /// markers are missing.
    pub output: String,
    /// Every test.
    pub tests: Vec<TestLine>,
    /// The leaderboard's entries (empty unless asked for).
    pub leaderboard: Vec<Board>,
    /// Pictures for the student: of the first chapters that lost points (at most
    /// [`MAX_IMAGES`]), the student's render, the book's figure and their difference side by
    /// side; every adapter that can show pictures (PrairieLearn) shows them.
    pub images: Vec<Image>,
    /// Why the submission could not be graded (not a copy of the handout …); `None` when
    /// it was.
    pub ungradable: Option<String>,
    /// The settings it is shown with.
    pub settings: Settings,
}

impl TestLine {
    /// Whether a student's report lists it: a test of no exercise carries no points, and the
    /// whole road's lines of the report's output say what such tests found.
    #[must_use]
    pub fn listed(&self) -> bool {
        !self.tags.is_empty()
    }
}

/// Points rounded to hundredths, as the platforms show them.
#[must_use]
pub fn round2(x: f64) -> f64 {
    (x * 100.0).round() / 100.0
}

/// The share of an exercise's `points` that its `k`-th test of `total` (from 1) carries, in
/// hundredths, as the platforms show points: each test the hundredths of `points / total`
/// rounded down, the last the remainder, so the shares add up to `points` exactly (2 points
/// over 6 tests: five of 0.33 and one of 0.35), whatever a platform sums.
#[must_use]
pub fn share(points: u32, total: usize, k: usize) -> f64 {
    let cents = u64::from(points) * 100;
    let total = total.max(1) as u64;
    let each = cents / total;
    let mine = if k as u64 >= total {
        cents - each * (total - 1)
    } else {
        each
    };
    mine as f64 / 100.0
}

impl Report {
    /// The report of a grading.
    #[must_use]
    pub fn new(grade: &Grade, manifest: &Manifest, settings: &Settings) -> Self {
        let explained = grade.explained(manifest);
        // the first wrong number of each exercise the ray trees point at
        let first_wrong = |entry: usize| {
            explained.iter().find_map(|x| match &x.first_wrong {
                Some((Some(at), lines)) if *at == entry => Some(lines.as_str()),
                _ => None,
            })
        };
        // the known mistake each exercise looks like, told by its tests' values
        let known_of = |entry: usize| {
            grade
                .exercises
                .iter()
                .find(|e| e.entry == entry)
                .and_then(|e| e.known.as_deref())
        };
        let mut hidden_seen: std::collections::BTreeMap<usize, usize> = Default::default();
        let mut seen: std::collections::BTreeMap<usize, usize> = Default::default();
        let mut tests = Vec::new();
        for t in &grade.tests {
            let entry = t.exercise.map(|e| &manifest.entries[e]);
            let (score, max) = match t.exercise {
                Some(e) => {
                    let total = grade.tests.iter().filter(|u| u.exercise == Some(e)).count();
                    let k = seen.entry(e).or_default();
                    *k += 1;
                    let max = share(manifest.entries[e].exercise.points, total, *k);
                    (if t.status == Status::Passed { max } else { 0.0 }, max)
                }
                None => (0.0, 0.0),
            };
            let number = entry.map_or("-".to_string(), |e| e.exercise.id.clone());
            let (name, output) = if t.hidden {
                let n = hidden_seen
                    .entry(t.exercise.unwrap_or(usize::MAX))
                    .or_default();
                *n += 1;
                (
                    format!("exercise {number}, hidden test {n}"),
                    t.status.word().to_string(),
                )
            } else {
                let title = entry.map_or(String::new(), |e| {
                    format!("{} {} ({}): ", e.exercise.id, e.exercise.title, e.formula)
                });
                let output = if t.status == Status::Passed {
                    String::new()
                } else {
                    format!("{}: {}", t.status.word(), t.message)
                };
                (format!("{title}{}", t.name), output)
            };
            let wrong = match t.exercise.and_then(first_wrong) {
                Some(lines) if !t.hidden && t.status != Status::Passed => {
                    lines.trim_end().to_string()
                }
                _ => String::new(),
            };
            let output = if wrong.is_empty() {
                output
            } else {
                format!("{output}\n{wrong}")
            };
            let known = match t.exercise.and_then(&known_of) {
                Some(k) if !t.hidden && t.status != Status::Passed => {
                    format!("a known mistake: this looks like {k}")
                }
                _ => String::new(),
            };
            let output = if known.is_empty() {
                output
            } else {
                format!("{output}\n{known}")
            };
            let mut tags = Vec::new();
            if let Some(e) = entry {
                tags.push(format!("chapter {}", e.chapter));
                tags.push(e.exercise.name.clone());
            }
            tests.push(TestLine {
                name,
                test: t.name.clone(),
                number,
                formula: entry.map_or(String::new(), |e| e.formula.clone()),
                tags,
                score,
                max,
                status: t.status.clone(),
                output,
                message: t.message.clone(),
                first_wrong: wrong,
                known,
                hidden: t.hidden,
                chapter: entry.map_or(0, |e| e.chapter),
                time: t.time,
            });
        }
        let mut output = format!("{}\n", grade.judging.line());
        for note in &grade.notes {
            output += &format!("{note}\n");
        }
        for road in grade
            .chapters
            .iter()
            .filter_map(|&c| grade.road(manifest, c))
            .filter(|r| r.passed < r.total)
        {
            output += &format!("{}\n", road.line());
        }
        let mut images = Vec::new();
        for x in &explained {
            output += &format!("chapter {} picture: {}\n", x.chapter, x.picture_line);
            if let Some((None, lines)) = &x.first_wrong {
                output += lines;
            }
            // two pictures at the most: a platform's results file has a size limit
            if let Some(png) = x.picture.filter(|_| images.len() < MAX_IMAGES) {
                images.push(Image {
                    label: format!(
                        "chapter {}: your render, the book's figure and their difference",
                        x.chapter
                    ),
                    png: png.to_vec(),
                });
            }
        }
        for e in &grade.exercises {
            if let Some(note) = &e.note {
                output += &format!(
                    "exercise {}: {note}\n",
                    manifest.entries[e.entry].exercise.id
                );
            }
            if let Some(known) = &e.known {
                output += &format!(
                    "exercise {}: a known mistake: this looks like {known}\n",
                    manifest.entries[e.entry].exercise.id
                );
            }
        }
        let mut leaderboard = Vec::new();
        if settings.leaderboard {
            match &grade.render {
                Some(Ok(r)) => {
                    leaderboard.push(Board {
                        name: "M pixels/s".into(),
                        value: r.pixels_per_second,
                        order: "desc".into(),
                    });
                    leaderboard.push(Board {
                        name: "pixels off (%)".into(),
                        value: r.differing,
                        order: "asc".into(),
                    });
                }
                Some(Err(why)) => output += &format!("leaderboard: no render ({why})\n"),
                None => {}
            }
        }
        Self {
            student: grade.student.clone(),
            score: grade.score(),
            max: grade.max(),
            execution_time: grade.elapsed.as_secs_f64(),
            output,
            tests,
            leaderboard,
            images,
            ungradable: None,
            settings: settings.clone(),
        }
    }

    /// The report of a submission that could not be graded, and why.
    #[must_use]
    pub fn ungradable(student: &str, why: &str, max: f64, seconds: f64) -> Self {
        Self {
            student: student.to_string(),
            score: 0.0,
            max,
            execution_time: seconds,
            output: format!("This submission could not be graded: {why}\n"),
            tests: Vec::new(),
            leaderboard: Vec::new(),
            images: Vec::new(),
            ungradable: Some(why.to_string()),
            settings: Settings::default(),
        }
    }
}

/// Where the student's copy is in what a platform handed over: the directory itself when it
/// holds `crates/whitted/src/`, its one subdirectory that does (an upload of the folder), or a
/// copy laid out in `scratch` from exercise files uploaded one by one (`camera.rs`,
/// `shapes/sphere.rs`: each put where the file of the same name is in the project). `Err` says
/// why it is not a copy of the handout.
pub fn locate(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    scratch: &Path,
) -> Result<PathBuf, String> {
    if submission.join(layout::core_src()).is_dir() {
        return Ok(submission.to_path_buf());
    }
    let entries: Vec<PathBuf> = std::fs::read_dir(submission)
        .map_err(|e| format!("cannot read the submission {}: {e}", submission.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    let inner: Vec<&PathBuf> = entries
        .iter()
        .filter(|p| p.join(layout::core_src()).is_dir())
        .collect();
    if let [one] = inner.as_slice() {
        return Ok((*one).clone());
    }
    // exercise files one by one: each to the project file whose path ends with it
    let regions = crate::handout::regions(root, manifest).map_err(|e| e.to_string())?;
    let mut wanted: Vec<PathBuf> = regions.iter().map(|r| r.file.clone()).collect();
    wanted.sort();
    wanted.dedup();
    let mut uploaded = Vec::new();
    crate::files::project_files(submission)
        .map_err(|e| e.to_string())?
        .into_iter()
        .filter(|f| f.extension().is_some_and(|x| x == "rs"))
        .for_each(|f| uploaded.push(f));
    let mut placed = 0;
    for f in &uploaded {
        let matches: Vec<&PathBuf> = wanted.iter().filter(|w| w.ends_with(f)).collect();
        if let [to] = matches.as_slice() {
            let dest = scratch.join(to);
            if let Some(parent) = dest.parent() {
                std::fs::create_dir_all(parent).map_err(|e| e.to_string())?;
            }
            std::fs::copy(submission.join(f), &dest).map_err(|e| e.to_string())?;
            placed += 1;
        }
    }
    if placed == 0 {
        let names: Vec<String> = wanted
            .iter()
            .map(|w| {
                w.file_name()
                    .map_or(String::new(), |n| n.to_string_lossy().into())
            })
            .collect();
        return Err(format!(
            "it is not a copy of the handout: no {}/ directory, and none of the exercise files ({}) was uploaded",
            layout::core_src().display(),
            names.join(", ")
        ));
    }
    Ok(scratch.to_path_buf())
}

/// Writes `text` to `path` atomically, making its directory.
pub fn write(path: &Path, text: &str) -> Result<(), ToolError> {
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| ToolError::io(parent, e))?;
    }
    crate::files::write_file(path, text.as_bytes())
}

/// JSON text, pretty, with a final newline.
#[must_use]
pub fn json_text(value: &serde_json::Value) -> String {
    serde_json::to_string_pretty(value).unwrap_or_else(|_| value.to_string()) + "\n"
}

#[cfg(test)]
mod tests {
    use super::share;

    #[test]
    fn the_shares_of_an_exercise_add_up_to_its_points() {
        for (points, total) in [(2, 6), (1, 3), (8, 7), (4, 1), (3, 200), (0, 4)] {
            let shares: Vec<f64> = (1..=total).map(|k| share(points, total, k)).collect();
            let cents: i64 = shares.iter().map(|s| (s * 100.0).round() as i64).sum();
            assert_eq!(
                cents,
                i64::from(points) * 100,
                "{points} points over {total} tests: shares {shares:?}"
            );
            assert!(shares.iter().all(|s| *s >= 0.0), "{shares:?}");
        }
        assert_eq!(
            (share(2, 6, 1), share(2, 6, 6)),
            (0.33, 0.35),
            "2 points over 6 tests"
        );
    }
}
