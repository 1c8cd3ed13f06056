//! `whitted grade` as the command line asks: one submission, its table on stdout and the
//! reports asked for, or a class, a directory of reports per student and the gradebook.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;
use std::process::ExitCode;

use super::class::grade_class;
use super::grading::grade;
use super::outcome::Grade;
use super::setup::GradeSetup;
use crate::manifest::Manifest;
use crate::{ToolError, files};

/// The reports of one submission, each written where it says (atomically).
#[derive(Clone, Copy, Debug, Default)]
pub struct Reports<'a> {
    /// Gradescope's `results.json`.
    pub json: Option<&'a Path>,
    /// A JUnit XML report.
    pub junit: Option<&'a Path>,
    /// The gradebook's header and this submission's row (CSV).
    pub csv: Option<&'a Path>,
}

/// A class to grade: every subdirectory of `dir`, reports into `out`, `jobs` at a time (the
/// cores when `None`).
#[derive(Clone, Copy, Debug)]
pub struct Class<'a> {
    /// The directory of submissions.
    pub dir: &'a Path,
    /// Where the reports go (one directory per student, and class.csv).
    pub out: &'a Path,
    /// Submissions graded at a time.
    pub jobs: Option<usize>,
    /// The roster that fills the gradebook's id and e-mail columns.
    pub roster: Option<&'a Path>,
    /// Write the gradebook anew rather than update the one in `out`.
    pub new_gradebook: bool,
}

/// Grades `submission` (the instructor's project `root` when `None`) or, with `class`, a
/// whole class, and writes the reports.
pub fn command(
    root: &Path,
    manifest: &Manifest,
    setup: &GradeSetup,
    submission: Option<&Path>,
    class: Option<Class<'_>>,
    reports: Reports<'_>,
) -> Result<ExitCode, ToolError> {
    if let Some(hidden) = &setup.hidden
        && !hidden.is_dir()
    {
        return Err(ToolError::Usage(format!(
            "--hidden {}: not a directory",
            hidden.display()
        )));
    }
    if let Some(class) = class {
        return grade_a_class(root, manifest, setup, class);
    }
    let submission = submission.unwrap_or(root);
    let g = grade(root, manifest, submission, setup)?;
    print!("{}", crate::report::table(&g, manifest));
    write_reports(&g, manifest, None, reports.json, reports.junit, reports.csv)?;
    Ok(ExitCode::SUCCESS)
}

/// Grades every submission of `class`, writes each one's reports in a directory of its own
/// and the class's gradebook, and says how long the submissions took.
fn grade_a_class(
    root: &Path,
    manifest: &Manifest,
    setup: &GradeSetup,
    class: Class<'_>,
) -> Result<ExitCode, ToolError> {
    let Class {
        dir: class,
        out,
        jobs,
        roster,
        new_gradebook,
    } = class;
    let roster = roster
        .map(crate::gradebook::read_roster)
        .transpose()?
        .unwrap_or_default();
    std::fs::create_dir_all(out).map_err(|e| ToolError::io(out, e))?;
    // a gradebook of other columns is refused before anything is graded
    let book = out.join(crate::gradebook::FILE);
    let chapters = super::Chapters::or_all(setup.chapter);
    let header = crate::gradebook::header(manifest, &chapters);
    let existing = match std::fs::read_to_string(&book) {
        Ok(text) => Some(text),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(ToolError::io(&book, e)),
    };
    let possible = crate::gradebook::possible(manifest, &chapters);
    let merge = |fresh: &[(String, String)]| {
        crate::gradebook::merged(
            existing.as_deref(),
            &header,
            &possible,
            fresh,
            new_gradebook,
        )
        .map_err(|why| ToolError::Usage(format!("{}: {why}", book.display())))
    };
    merge(&[])?;
    let out = out.canonicalize().map_err(|e| ToolError::io(out, e))?;
    let jobs = jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from));
    let count = std::fs::read_dir(class).map_or(0, |d| {
        d.filter_map(Result::ok)
            .filter(|e| e.path().is_dir())
            .count()
    });
    let jobs = jobs.min(count.max(1));
    let start = std::time::Instant::now();
    // each student's reports as soon as they are graded: a stalled submission holds back no
    // other student's
    let written = |student: &str, g: &Grade| -> Result<(), ToolError> {
        let dir = out.join(student);
        std::fs::create_dir_all(&dir).map_err(|err| ToolError::io(&dir, err))?;
        write_reports(
            g,
            manifest,
            Some(&dir.join("report.txt")),
            Some(&dir.join("results.json")),
            Some(&dir.join("junit.xml")),
            None,
        )
    };
    let entries = grade_class(root, manifest, class, setup, jobs, &|e| match &e.grade {
        Ok(g) => {
            eprintln!(
                "graded {}: {} / {} points in {:.0} s",
                e.student,
                crate::report::points(g.score()),
                crate::report::points(g.max()),
                g.elapsed.as_secs_f64()
            );
            if let Err(why) = written(&e.student, g) {
                eprintln!("could not write {}'s reports: {why}", e.student);
            }
        }
        Err(why) => eprintln!("could not grade {}: {why}", e.student),
    })?;
    let mut rows = Vec::new();
    for e in &entries {
        match &e.grade {
            Ok(g) => {
                rows.push((
                    e.student.clone(),
                    crate::gradebook::graded(&e.student, g, manifest, &roster),
                ));
            }
            Err(why) => rows.push((
                e.student.clone(),
                crate::gradebook::ungraded(&e.student, why, manifest, &chapters, &roster),
            )),
        }
    }
    files::write_file(&book, merge(&rows)?.as_bytes())?;
    let graded: Vec<&Grade> = entries
        .iter()
        .filter_map(|e| e.grade.as_ref().ok())
        .collect();
    // the first grading of each worker builds the dependencies: the median is of the rest
    let later = if graded.len() > jobs {
        &graded[jobs..]
    } else {
        &graded[..]
    };
    let median = |f: &dyn Fn(&Grade) -> std::time::Duration| {
        let mut t: Vec<f64> = later.iter().map(|g| f(g).as_secs_f64()).collect();
        t.sort_by(f64::total_cmp);
        t.get(t.len() / 2).copied().unwrap_or(0.0)
    };
    println!(
        "graded {} of {} submissions in {:.0} s ({jobs} at a time); after each worker's first, the median submission took {:.1} s: splice {:.1} s, build {:.1} s, test run {:.1} s; reports in {}, the gradebook in {}",
        graded.len(),
        entries.len(),
        start.elapsed().as_secs_f64(),
        median(&|g| g.elapsed),
        median(&|g| g.timings.splice),
        median(&|g| g.timings.build),
        median(&|g| g.timings.run),
        out.display(),
        book.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Writes the reports asked for, each atomically.
fn write_reports(
    g: &Grade,
    manifest: &Manifest,
    text: Option<&Path>,
    json: Option<&Path>,
    junit: Option<&Path>,
    csv: Option<&Path>,
) -> Result<(), ToolError> {
    if let Some(path) = text {
        files::write_file(path, crate::report::table(g, manifest).as_bytes())?;
    }
    if let Some(path) = json {
        let value = crate::report::gradescope(g, manifest);
        let text = serde_json::to_string_pretty(&value)
            .map_err(|e| ToolError::Usage(format!("cannot write JSON: {e}")))?;
        files::write_file(path, (text + "\n").as_bytes())?;
    }
    if let Some(path) = junit {
        files::write_file(path, crate::report::junit(g, manifest).as_bytes())?;
    }
    if let Some(path) = csv {
        let text = format!(
            "{}\n{}\n",
            crate::report::csv_header(manifest, &g.chapters),
            crate::report::csv_row(g, manifest)
        );
        files::write_file(path, text.as_bytes())?;
    }
    Ok(())
}
