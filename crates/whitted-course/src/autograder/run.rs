//! What a platform's package runs: `whitted autograder grade` grades one submission and
//! always writes the platform's results file, a submission that cannot be graded included (its
//! file says why); `whitted autograder prebuild` builds, once, what every grading reuses;
//! `whitted autograder check` tells a GitHub Classroom step whether one exercise got all its
//! points.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use super::codegrade::Audience;
use super::{Platform, Report, Settings, json_text, write};
use crate::ToolError;
use crate::grade::{self, GradeSetup};
use crate::manifest::Manifest;

/// One submission to grade for a platform.
#[derive(Clone, Debug)]
pub struct Submission<'a> {
    /// The platform whose results file is written.
    pub platform: Platform,
    /// What the platform handed over ([`super::locate`] finds the copy in it).
    pub dir: &'a Path,
    /// Where the results go.
    pub results: &'a Path,
    /// How the results are shown.
    pub settings: Settings,
}

/// Grades `submission` and writes its results file; `Err` only when that file cannot be
/// written. Whatever stops the grading (not a copy of the handout, the sandbox missing, a
/// tool missing) becomes the reason in the file.
pub fn grade_submission(
    root: &Path,
    manifest: &Manifest,
    setup: &GradeSetup,
    submission: &Submission<'_>,
) -> Result<Report, ToolError> {
    let start = Instant::now();
    let student = submission
        .dir
        .file_name()
        .map_or_else(|| "submission".into(), |n| n.to_string_lossy().into_owned());
    let chapters = crate::grade::Chapters::or_all(setup.chapter);
    let max: f64 = manifest
        .entries
        .iter()
        .filter(|e| chapters.contains(&e.chapter))
        .map(|e| f64::from(e.exercise.points))
        .sum();
    let scratch = tempfile::Builder::new()
        .prefix("whitted-submission-")
        .tempdir()
        .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
    let graded = super::locate(root, manifest, submission.dir, scratch.path()).and_then(|dir| {
        grade::grade(root, manifest, &dir, setup).map_err(|e| {
            format!("the autograder could not grade it ({e}); your instructor has the log")
        })
    });
    let mut report = match graded {
        Ok(mut g) => {
            g.student.clone_from(&student);
            eprint!("{}", crate::report::table(&g, manifest));
            Report::new(&g, manifest, &submission.settings)
        }
        Err(why) => {
            eprintln!("not graded: {why}");
            let mut r = Report::ungradable(&student, &why, max, start.elapsed().as_secs_f64());
            r.settings = submission.settings.clone();
            r
        }
    };
    report.execution_time = start.elapsed().as_secs_f64();
    write(
        submission.results,
        &results_text(&report, &chapters, submission.platform),
    )?;
    Ok(report)
}

/// The platform's results file for `report`.
#[must_use]
pub fn results_text(report: &Report, chapters: &[u8], platform: Platform) -> String {
    match platform {
        // Classroom's steps read Gradescope's file: one result per test, tagged by exercise
        Platform::Gradescope | Platform::Classroom => {
            json_text(&super::gradescope::results(report))
        }
        Platform::Prairielearn => json_text(&super::prairielearn::results(report)),
        Platform::Codegrade => super::codegrade::junit(report, chapters, Audience::Student),
    }
}

/// Builds once what every grading in `setup.target_dir` reuses: the dependencies, the
/// instructor's crate and tests, the hidden tests, by grading a handout whose every exercise
/// is `todo!()` (no solution is compiled into the build directory). Prints what it took.
pub fn prebuild(
    root: &Path,
    manifest: &Manifest,
    setup: &GradeSetup,
) -> Result<ExitCode, ToolError> {
    let start = Instant::now();
    let dir = tempfile::Builder::new()
        .prefix("whitted-prebuild-")
        .tempdir()
        .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
    let handout = dir.path().join("handout");
    let all: Vec<usize> = (0..manifest.entries.len()).collect();
    crate::handout::write(root, manifest, &all, &handout)?;
    let g = grade::grade(root, manifest, &handout, setup)?;
    if let Some(note) = g.notes.first() {
        return Err(ToolError::Cargo(format!(
            "the empty handout does not build: {note}"
        )));
    }
    println!(
        "prebuilt in {:.0} s: {} tests ran on the empty handout ({} passed), {}",
        start.elapsed().as_secs_f64(),
        g.tests.len(),
        g.tests
            .iter()
            .filter(|t| t.status == grade::Status::Passed)
            .count(),
        if setup
            .sandbox
            .as_ref()
            .is_some_and(|s| s.level != grade::sandbox::Level::Off)
        {
            "built and run in the sandbox"
        } else {
            "without a sandbox"
        }
    );
    Ok(ExitCode::SUCCESS)
}

/// Whether exercise `exercise` (its name or id) got all its points in the Gradescope-style
/// `results` file: exit status 0 when it did, 1 when not, with one line saying which.
pub fn check(results: &Path, exercise: &str) -> Result<ExitCode, ToolError> {
    let text = std::fs::read_to_string(results).map_err(|e| ToolError::io(results, e))?;
    let json: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| ToolError::Usage(format!("{}: {e}", results.display())))?;
    let tests: Vec<&serde_json::Value> = json["tests"]
        .as_array()
        .map(|t| {
            t.iter()
                .filter(|t| {
                    t["number"] == exercise
                        || t["tags"]
                            .as_array()
                            .is_some_and(|tags| tags.iter().any(|g| g == exercise))
                })
                .collect()
        })
        .unwrap_or_default();
    let sum = |key: &str| -> f64 { tests.iter().filter_map(|t| t[key].as_f64()).sum() };
    let (score, max) = (sum("score"), sum("max_score"));
    let full = !tests.is_empty() && score + 1e-6 >= max;
    println!(
        "exercise {exercise}: {} / {} points over {} tests",
        crate::report::points(score),
        crate::report::points(max),
        tests.len()
    );
    // what the grader noted about the whole submission, or about this exercise
    let number = tests
        .first()
        .and_then(|t| t["number"].as_str())
        .unwrap_or("");
    for line in json["output"].as_str().unwrap_or("").lines().filter(|l| {
        !l.starts_with("exercise ")
            || (!number.is_empty() && l.starts_with(&format!("exercise {number}:")))
    }) {
        println!("{line}");
    }
    for t in tests.iter().filter(|t| t["status"] != "passed") {
        println!(
            "  failed: {}{}",
            t["name"].as_str().unwrap_or(""),
            t["output"]
                .as_str()
                .filter(|o| !o.is_empty())
                .map(|o| format!(": {o}"))
                .unwrap_or_default()
        );
    }
    Ok(if full {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The grading setup of a package's command line (`render`: measure the leaderboard's
/// render).
#[must_use]
pub fn setup(
    chapter: Option<crate::grade::Chapters>,
    hidden: Option<PathBuf>,
    timeout: u64,
    target_dir: PathBuf,
    sandbox: Option<grade::SandboxSetup>,
    render: bool,
) -> GradeSetup {
    GradeSetup {
        chapter,
        hidden,
        timeout: std::time::Duration::from_secs(timeout),
        target_dir: Some(target_dir),
        keep: false,
        sandbox,
        render,
        feedback: true,
        screen: true,
        judging: grade::Judging::default(),
        judge: None,
        compile: grade::sandbox::watch::CompileLimits::default(),
    }
}
