//! The student's loop, measured as a student lives it: on a fresh handout in a temporary
//! directory, the time to the first verdict (cold `target/`, crates already downloaded), then,
//! putting the reference bodies back one exercise at a time (each a save), the time from the
//! save to the verdict and to the chapter's picture, the size of `target/` at the end, and the
//! time to grade one submission after the first (the finished handout is graded first, then
//! the same student's sources as they were once chapter 2 was written).
//!
//! ```text
//! cargo bench -p whitted-benches --bench student_loop                    # this project
//! cargo bench -p whitted-benches --bench student_loop -- --project DIR   # another build of it
//!     [--runs N]    first verdicts on N fresh handouts (median), default 1
//!     [--saves N]   put back N exercises spread over the chapters, default all
//!     [--no-grade]  skip the grading
//!     [--load N]    keep N threads busy beside it the whole time (a loaded machine: load N)
//! ```
//!
//! The verdict is the first line of `cargo learn`'s report, the picture the `✓ picture:` or
//! `✗ picture:` line after it (the student's render beside the book's figure and their
//! difference). Every cargo it runs is the course tools' one runner ([`whitted_learn::cargo::command`]),
//! every exercise is found by its name's markers, and copies are [`whitted_learn::files`]'.
//! Times are wall-clock, medians and 90th percentiles of the saves; the machine should be
//! otherwise idle, or loaded on purpose with `--load`: N threads of this process that spin at
//! the normal priority from before the first handout to the end, as a student's browser, editor
//! and other builds would (`--load 2` on two cores: a load average of 2 besides the loop).

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use whitted_learn::layout::{BEGIN, END};
use whitted_learn::manifest;

/// The reference project's `whitted` tool, as cargo's arguments.
const TOOL: [&str; 8] = [
    "run",
    "--release",
    "-q",
    "-p",
    "whitted-course",
    "--bin",
    "whitted",
    "--",
];

/// The command a student runs for a verdict, in the handout.
const VERDICT: [&str; 1] = ["learn"];

struct Args {
    project: PathBuf,
    runs: usize,
    saves: Option<usize>,
    grade: bool,
    load: usize,
}

fn args() -> Result<Args, String> {
    let mut out = Args {
        project: PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/..")),
        runs: 1,
        saves: None,
        grade: true,
        load: 0,
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().ok_or(format!("{name} needs a value"));
        match a.as_str() {
            "--project" => out.project = PathBuf::from(value("--project")?),
            "--runs" => {
                out.runs = value("--runs")?
                    .parse()
                    .map_err(|e| format!("--runs: {e}"))?
            }
            "--saves" => {
                out.saves = Some(
                    value("--saves")?
                        .parse()
                        .map_err(|e| format!("--saves: {e}"))?,
                )
            }
            "--no-grade" => out.grade = false,
            "--load" => {
                out.load = value("--load")?
                    .parse()
                    .map_err(|e| format!("--load: {e}"))?;
            }
            "--bench" => {} // what `cargo bench` adds
            other => {
                return Err(format!(
                    "unknown argument `{other}` (see the file's header)"
                ));
            }
        }
    }
    out.project = out
        .project
        .canonicalize()
        .map_err(|e| format!("{}: {e}", out.project.display()))?;
    Ok(out)
}

/// `cargo ARGS` in `dir`, building into `dir`'s own `target/`, without colour.
fn cargo(dir: &Path, args: &[&str]) -> Command {
    let mut c = whitted_learn::cargo::command(dir, Some(&dir.join("target")), true);
    c.args(args).env("NO_COLOR", "1");
    c
}

/// Runs `command`; returns when its stdout showed a line starting with one of `verdict`
/// (or the end, when `verdict` is empty) and when it showed a line starting with one of
/// `picture`, and the whole output.
fn timed(
    mut command: Command,
    verdict: &[&str],
    picture: &[&str],
) -> (Duration, Option<Duration>, String) {
    let started = Instant::now();
    let mut child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("cargo runs");
    let mut seen_verdict = None;
    let mut seen_picture = None;
    let mut text = String::new();
    if let Some(out) = child.stdout.take() {
        for line in BufReader::new(out).lines().map_while(Result::ok) {
            if seen_verdict.is_none() && verdict.iter().any(|v| line.starts_with(v)) {
                seen_verdict = Some(started.elapsed());
            }
            if seen_picture.is_none() && picture.iter().any(|p| line.starts_with(p)) {
                seen_picture = Some(started.elapsed());
            }
            text += &line;
            text.push('\n');
        }
    }
    let _ = child.wait();
    let end = started.elapsed();
    (seen_verdict.unwrap_or(end), seen_picture, text)
}

/// Writes a fresh handout of every exercise of `project` into `dir`.
fn handout(project: &Path, dir: &Path) {
    let out = dir.to_str().expect("a UTF-8 path");
    let mut args = TOOL.to_vec();
    args.extend(["handout", "--out", out]);
    let status = cargo(project, &args).status().expect("cargo runs");
    assert!(status.success(), "the handout could not be written");
}

/// The body of the exercise named `name` in `text`: the bytes between its markers.
fn region(text: &str, name: &str) -> Option<(usize, usize)> {
    let begin = format!("{BEGIN} {name}");
    let mut offset = 0;
    let mut start = None;
    for line in text.split_inclusive('\n') {
        if start.is_none() && line.trim() == begin {
            start = Some(offset + line.len());
        } else if let Some(s) = start
            && line.trim() == END
        {
            return Some((s, offset));
        }
        offset += line.len();
    }
    None
}

/// The file of the handout (relative) that holds the markers of the exercise named `name`.
fn file_of(dir: &Path, name: &str) -> Option<PathBuf> {
    let begin = format!("{BEGIN} {name}");
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).ok()?.flatten() {
            let p = entry.path();
            let name = p
                .file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            if p.is_dir() && name != "target" && !name.starts_with('.') {
                stack.push(p);
            } else if name.ends_with(".rs")
                && std::fs::read_to_string(&p).is_ok_and(|t| t.lines().any(|l| l.trim() == begin))
            {
                return p.strip_prefix(dir).ok().map(Path::to_path_buf);
            }
        }
    }
    None
}

/// Puts the reference body of the exercise named `name` back into the handout: one save.
fn put_back(project: &Path, dir: &Path, name: &str) {
    let file =
        file_of(dir, name).unwrap_or_else(|| panic!("exercise {name}: no markers in the handout"));
    let reference = std::fs::read_to_string(project.join(&file)).expect("the reference file");
    let mine = std::fs::read_to_string(dir.join(&file)).expect("the handout's file");
    let (a, b) = region(&reference, name).expect("the reference region");
    let (c, d) = region(&mine, name).expect("the handout's region");
    let text = format!("{}{}{}", &mine[..c], &reference[a..b], &mine[d..]);
    std::fs::write(dir.join(&file), text).expect("the save");
}

fn size(dir: &Path) -> u64 {
    let mut total = 0;
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            match e.metadata() {
                Ok(m) if m.is_dir() => stack.push(e.path()),
                Ok(m) => total += m.len(),
                Err(_) => {}
            }
        }
    }
    total
}

fn quantile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    // the nearest rank
    let rank = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len());
    v[rank - 1]
}

fn main() {
    let args = match args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    let m = manifest::load(&args.project.join(manifest::DEFAULT_PATH)).expect("the manifest");
    eprintln!("student's loop of {}", args.project.display());
    // the reference's own tool, built before anything is timed
    let mut warm = TOOL.to_vec();
    warm.push("--version");
    let _ = cargo(&args.project, &warm).output();
    let _load = Load::start(args.load);

    let verdict_marks: &[&str] = &["✗", "✓"];
    // a picture drawn, the same as the book's or not (a chapter that cannot render yet is none)
    let picture_mark: &[&str] = &["✓ picture:", "✗ picture:"];
    let temp = tempfile::tempdir().expect("a temporary directory");
    let mut firsts = Vec::new();
    let mut dir = PathBuf::new();
    for run in 0..args.runs.max(1) {
        dir = temp.path().join(format!("handout-{run}"));
        handout(&args.project, &dir);
        let (verdict, _, _) = timed(cargo(&dir, &VERDICT), verdict_marks, &[]);
        eprintln!(
            "first verdict on a fresh handout: {:.1} s",
            verdict.as_secs_f64()
        );
        firsts.push(verdict.as_secs_f64());
    }

    // the saves: every exercise in order, or N of them spread evenly
    let n = m.entries.len();
    let chosen: Vec<usize> = match args.saves {
        Some(k) if k < n => (0..k).map(|i| (i * n) / k.max(1)).collect(),
        _ => (0..n).collect(),
    };
    let mut to_verdict = Vec::new();
    let mut to_picture = Vec::new();
    // a second submission for the grading: this student half-way, chapters 1 and 2 written
    let halfway = temp.path().join("halfway");
    let sources = whitted_learn::layout::core_src();
    for (i, e) in m.entries.iter().enumerate() {
        put_back(&args.project, &dir, &e.exercise.name);
        let written = i + 1;
        if m.entries.get(written).is_some_and(|next| next.chapter == 3) && e.chapter == 2 {
            whitted_learn::files::copy_tree(&dir.join(&sources), &halfway.join(&sources))
                .expect("a copy of the sources");
        }
        if !chosen.contains(&i) {
            continue;
        }
        let (verdict, picture, _) = timed(cargo(&dir, &VERDICT), verdict_marks, picture_mark);
        eprintln!(
            "save {} (exercise {} {}): verdict {:.2} s{}",
            to_verdict.len() + 1,
            e.exercise.id,
            e.exercise.name,
            verdict.as_secs_f64(),
            picture.map_or(String::new(), |p| format!(
                ", picture {:.2} s",
                p.as_secs_f64()
            ))
        );
        to_verdict.push(verdict.as_secs_f64());
        if let Some(p) = picture {
            to_picture.push(p.as_secs_f64());
        }
    }
    let target = size(&dir.join("target"));

    // grading: the finished handout first (it builds what is shared), then the half-way one:
    // what a class pays for each submission after the first
    let mut grade = None;
    if args.grade {
        let graded = |submission: &Path| {
            let mut g = TOOL.to_vec();
            g.extend(["grade", submission.to_str().expect("UTF-8")]);
            let started = Instant::now();
            let out = cargo(&args.project, &g).output().expect("cargo runs");
            if !out.status.success() {
                eprintln!("grading failed: {}", String::from_utf8_lossy(&out.stderr));
            }
            let text = String::from_utf8_lossy(&out.stdout).into_owned();
            (started.elapsed().as_secs_f64(), text)
        };
        let (first, _) = graded(&dir);
        eprintln!("grading the finished handout, the first: {first:.1} s");
        let (second, report) = graded(&halfway);
        eprintln!("grading the half-way one after it: {second:.1} s");
        if let Some(total) = report.lines().find(|l| l.contains(" points (")) {
            eprintln!("  {}", total.trim());
        }
        grade = Some(second);
    }

    if args.load > 0 {
        println!("(with {} busy threads beside the loop)", args.load);
    }
    println!("| measure | this project |");
    println!("|---|---:|");
    println!(
        "| first verdict on a fresh handout (median of {}) | {:.1} s |",
        firsts.len(),
        quantile(&firsts, 0.5)
    );
    println!(
        "| save → verdict, median / 90th percentile ({} saves) | {:.2} s / {:.2} s |",
        to_verdict.len(),
        quantile(&to_verdict, 0.5),
        quantile(&to_verdict, 0.9)
    );
    println!(
        "| save → picture, median / 90th percentile ({} saves) | {:.2} s / {:.2} s |",
        to_picture.len(),
        quantile(&to_picture, 0.5),
        quantile(&to_picture, 0.9)
    );
    println!(
        "| `target/` of the handout at the end | {:.2} GB |",
        target as f64 / 1e9
    );
    if let Some(g) = grade {
        println!("| grading one submission, after the first | {g:.1} s |");
    }
}

/// Threads that keep the cores busy until dropped (`--load`).
struct Load {
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    threads: Vec<std::thread::JoinHandle<()>>,
}

impl Load {
    /// Starts `n` spinning threads.
    fn start(n: usize) -> Self {
        use std::sync::atomic::{AtomicBool, Ordering};
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let threads = (0..n)
            .map(|_| {
                let stop = stop.clone();
                std::thread::spawn(move || {
                    let mut x = 0u64;
                    while !stop.load(Ordering::Relaxed) {
                        x = std::hint::black_box(
                            x.wrapping_mul(6364136223846793005).wrapping_add(1),
                        );
                    }
                })
            })
            .collect();
        if n > 0 {
            eprintln!("{n} busy threads beside the loop");
        }
        Self { stop, threads }
    }
}

impl Drop for Load {
    fn drop(&mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        for t in self.threads.drain(..) {
            let _ = t.join();
        }
    }
}
