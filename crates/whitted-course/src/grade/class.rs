//! Grading a class: every submission of a directory, a few at a time, each worker with a build
//! directory of its own.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

use super::grading::grade;
use super::outcome::Grade;
use super::setup::GradeSetup;
use crate::ToolError;
use crate::manifest::Manifest;

/// One submission of a class and how its grading went.
#[derive(Clone, Debug)]
pub struct ClassEntry {
    /// The submission's directory name.
    pub student: String,
    /// Its grade, or why it could not be graded (not a copy of the project …).
    pub grade: Result<Grade, String>,
}

/// Grades every submission of a class: each subdirectory of `dir`, in name order, `jobs` at
/// a time, each in its own copy. With `options.target_dir` set, each of the `jobs` workers
/// builds into its own directory under it (`slot-0`, `slot-1` …), kept from one submission
/// to the next; the first worker grades the first submission alone, and the others' start as
/// copies of its directory, so the dependencies are built once for the class. (One shared directory would
/// not do: every copy of the crate builds its tests to the same file names, and one
/// submission's tests would run another's code.) A submission that cannot be graded is
/// reported and the others go on.
pub fn grade_class(
    root: &Path,
    manifest: &Manifest,
    dir: &Path,
    options: &GradeSetup,
    jobs: usize,
    done: &(dyn Fn(&ClassEntry) + Sync),
) -> Result<Vec<ClassEntry>, ToolError> {
    let mut submissions: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| ToolError::io(dir, e))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.is_dir()
                && !p
                    .file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    submissions.sort();
    if submissions.is_empty() {
        return Err(ToolError::Usage(format!(
            "--class {}: no submission directory in it",
            dir.display()
        )));
    }
    let jobs = jobs.max(1).min(submissions.len());
    // the judge, built once for the class, beside the workers' build directories
    let mut options = options.clone();
    if options.judge.is_none() {
        super::grading::check_sandbox(&options)?;
        let chapters = super::grading::chapters_asked(manifest, options.chapter);
        eprintln!(
            "building the judge: your project with the grader's wire{} (the first time, a few minutes) …",
            if options.hidden.is_some() {
                " and your hidden tests"
            } else {
                ""
            }
        );
        let judge = super::grading::judge_for(
            root,
            manifest,
            &chapters,
            &options,
            options
                .target_dir
                .as_ref()
                .map(|d| d.join("judge"))
                .as_deref(),
        )?;
        options.judge = Some(std::sync::Arc::new(judge));
    }
    let options = &options;
    preflight(root, manifest, options)?;
    let progress = Progress::new(submissions.len(), jobs);
    // the first submission on the first worker alone, then every other worker's build
    // directory starts as a copy of the first's: the dependencies and the instructor's code are
    // compiled once for the class, not once per worker
    let mut first = Vec::new();
    if jobs > 1
        && let Some(dir) = &options.target_dir
    {
        let mut own = options.clone();
        own.target_dir = Some(dir.join("slot-0"));
        if let Some(s) = &mut own.sandbox {
            s.worker = 0;
        }
        let path = &submissions[0];
        let entry = ClassEntry {
            student: student_name(path),
            grade: grade(root, manifest, path, &own).map_err(|e| e.to_string()),
        };
        done(&entry);
        progress.step(&entry);
        first.push(entry);
        for i in 1..jobs {
            let to = dir.join(format!("slot-{i}"));
            if !to.join("debug").is_dir() {
                seed(&dir.join("slot-0").join("debug"), &to.join("debug"))?;
            }
        }
    }
    let items: Vec<usize> = (first.len()..submissions.len()).collect();
    // one build directory per worker: two copies of the crate build to the same file names,
    // so two submissions must never share one at the same time
    let slots: std::sync::Mutex<Vec<(usize, Option<PathBuf>)>> = std::sync::Mutex::new(
        (0..jobs)
            .map(|i| {
                let dir = options
                    .target_dir
                    .as_ref()
                    .map(|t| t.join(format!("slot-{i}")));
                (i, dir)
            })
            .collect(),
    );
    crate::parallel::in_parallel(&items, jobs, |i| {
        let path = &submissions[i];
        let slot = slots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .pop()
            .unwrap_or((0, None));
        let mut own = options.clone();
        own.target_dir.clone_from(&slot.1);
        // each worker's tests run as a user of their own: one submission's processes never
        // count against another's limit
        if let Some(s) = &mut own.sandbox {
            s.worker = slot.0;
        }
        let entry = ClassEntry {
            student: student_name(path),
            grade: grade(root, manifest, path, &own).map_err(|e| e.to_string()),
        };
        slots.lock().unwrap_or_else(|p| p.into_inner()).push(slot);
        done(&entry);
        progress.step(&entry);
        Ok(entry)
    })
    .map(|rest| first.into_iter().chain(rest).collect())
}

/// A class's progress, said after each submission: how many are graded, the median time of
/// one, and about how long the rest will take at `jobs` at a time.
struct Progress {
    total: usize,
    jobs: usize,
    times: std::sync::Mutex<Vec<f64>>,
}

impl Progress {
    fn new(total: usize, jobs: usize) -> Self {
        Self {
            total,
            jobs,
            times: std::sync::Mutex::new(Vec::new()),
        }
    }

    /// Counts `entry` and says where the class stands.
    fn step(&self, entry: &ClassEntry) {
        let mut times = self.times.lock().unwrap_or_else(|p| p.into_inner());
        times.push(
            entry
                .grade
                .as_ref()
                .map_or(0.0, |g| g.elapsed.as_secs_f64()),
        );
        let mut sorted = times.clone();
        sorted.sort_by(f64::total_cmp);
        let median = sorted[sorted.len() / 2];
        let left = self.total - times.len();
        let eta = median * left.div_ceil(self.jobs) as f64;
        eprintln!(
            "  [{} / {}] the median submission {median:.0} s; about {} left",
            times.len(),
            self.total,
            if left == 0 {
                "nothing".to_string()
            } else if eta < 90.0 {
                format!("{eta:.0} s")
            } else {
                format!("{:.0} min", eta / 60.0)
            }
        );
    }
}

/// The preflight of a class: your project graded as a submission, with your tests, hidden
/// ones included, on the first worker's build directory (which it leaves built for the
/// class). Anything short of full marks is your mistake, not a student's, and stops the class
/// before the first submission, naming the tests that failed.
fn preflight(root: &Path, manifest: &Manifest, options: &GradeSetup) -> Result<(), ToolError> {
    eprintln!("preflight: grading your own project with your tests …");
    let mut own = options.clone();
    own.target_dir = options.target_dir.as_ref().map(|d| d.join("slot-0"));
    if let Some(s) = &mut own.sandbox {
        s.worker = 0;
    }
    let g = grade(root, manifest, root, &own)?;
    let failed: Vec<String> = g
        .tests
        .iter()
        .filter(|t| t.status != super::Status::Passed)
        .map(|t| {
            let why = t.message.lines().next().unwrap_or("");
            format!("{} ({}: {why})", t.name, t.status.word())
        })
        .collect();
    if g.score() + 1e-9 < g.max() || !failed.is_empty() {
        return Err(ToolError::Usage(format!(
            "preflight: your own project scores {} / {} with your tests, so no submission is \
             graded; {} test{} failed: {}",
            crate::report::points(g.score()),
            crate::report::points(g.max()),
            failed.len(),
            if failed.len() == 1 { "" } else { "s" },
            failed
                .iter()
                .take(5)
                .cloned()
                .collect::<Vec<_>>()
                .join("; ")
        )));
    }
    eprintln!(
        "preflight: your own project scores {} / {}, all {} of its tests passed, in {:.0} s",
        crate::report::points(g.score()),
        crate::report::points(g.max()),
        g.tests.len(),
        g.elapsed.as_secs_f64()
    );
    Ok(())
}

/// A submission's name: its directory's, cleaned ([`super::clean`]).
fn student_name(path: &Path) -> String {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    super::clean::clean(&name)
}

/// Copies the build directory `from` to `to`, every file with its modification time (cargo
/// decides what is fresh by them), so that a worker starts with what another built.
fn seed(from: &Path, to: &Path) -> Result<(), ToolError> {
    let entries = std::fs::read_dir(from).map_err(|e| ToolError::io(from, e))?;
    std::fs::create_dir_all(to).map_err(|e| ToolError::io(to, e))?;
    for entry in entries {
        let entry = entry.map_err(|e| ToolError::io(from, e))?;
        let (src, dest) = (entry.path(), to.join(entry.file_name()));
        let meta = entry.metadata().map_err(|e| ToolError::io(&src, e))?;
        if meta.is_dir() {
            seed(&src, &dest)?;
        } else if meta.is_file() {
            std::fs::copy(&src, &dest).map_err(|e| ToolError::io(&src, e))?;
            let modified = meta.modified().map_err(|e| ToolError::io(&src, e))?;
            std::fs::File::options()
                .write(true)
                .open(&dest)
                .and_then(|f| f.set_modified(modified))
                .map_err(|e| ToolError::io(&dest, e))?;
        }
    }
    Ok(())
}
