//! `whitted` — the course tools: the formula functions of the notes (the exercises), a
//! student's handout, and the student's loop.
//!
//! ```text
//! whitted formulas                                  the manifest, by chapter, with file:line
//! whitted formulas --prove [--only PATH]... [--keep] [--features f32]
//!                                                   poison each function, run the render paths
//! whitted handout --out DIR [--chapters 1-3 | --exercises 2.3,2.4]
//!                                                   a student's copy, the exercises as todo!()
//! whitted learn [list | hint [ID] | watch]          progress, the next exercise, hints, rerun on save
//! whitted grade [DIR] [--chapter N] [--hidden DIR] [--json F] [--junit F] [--csv F]
//!                                                   a student's copy graded with the instructor's tests
//! whitted grade --class DIR --out REPORTS           every submission of a class
//! ```
//!
//! Exit status: 0 when everything asked for is fine, 1 when some function is not proven,
//! 2 on an error (a bad manifest, a function not found, a build that fails …), printed as
//! one line `error: …`.

#![deny(missing_docs)]

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use whitted_course::cli::{find_root, read_manifest};
use whitted_course::manifest::Manifest;
use whitted_course::prove::{self, PoisonedRuns};
use whitted_course::{ToolError, syllabus};

/// The course tools of whitted, the toolkit for learning classic ray tracing.
#[derive(Parser)]
#[command(name = "whitted", version)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// The functions that compute the course notes' formulas (chapters/formulas.toml).
    ///
    /// Without options, lists them by chapter, each with its file:line, the formula and the
    /// notes' section. With --prove, shows that each one is on every render path of its
    /// chapter: in a copy of the project, one function at a time is made to panic
    /// ("poisoned"), and every test of tests/render_paths.rs for its chapter must then fail.
    /// Exit status: 0 all proven, 1 some not, 2 on an error.
    Formulas(Formulas),
    /// Writes a student's copy of the project, with exercises taken out.
    ///
    /// Each chosen exercise's reference body (between `// BEGIN SOLUTION ID` and
    /// `// END SOLUTION` in src/) becomes `todo!("exercise ID: … — see chapters/…/README.md")`;
    /// the others keep their reference code. Of tests/, only the targets of the manifest's
    /// [handout] tests go along; .ci/ stays behind. Without --chapters or --exercises, every
    /// exercise is taken out. DIR must not exist (or be empty).
    Handout(HandoutArgs),
    /// The student's loop: progress, the next exercise and its failing test, hints.
    ///
    /// Runs the exercise tests (`cargo test` on the manifest's [handout] tests) and shows, per
    /// chapter, how many exercises pass, then the next one to write with its first failing
    /// test, the formula it checks and the notes' section. Colour only on a terminal, and not
    /// with NO_COLOR set.
    Learn(whitted_course::cli::LearnArgs),
    /// Grades a student's copy (DIR, default the current project) with this project's tests.
    ///
    /// Only the student's exercise bodies (between `// BEGIN SOLUTION ID` and `// END
    /// SOLUTION` in DIR's src/) are taken; they go into a fresh copy of this project, so the
    /// tests, the manifest and the code around the exercises are the instructor's. A body that
    /// does not compile is graded as not written, and the others still count. Each test runs in
    /// its own process under --timeout (cargo-nextest), so a panic, a stack overflow or an
    /// endless loop costs only its own tests. An exercise's points (chapters/formulas.toml) are
    /// shared by its tests. Exit status 0 once graded, whatever the score; 2 on an error.
    Grade(GradeArgs),
    /// Renders the course book's figures (docs/figures.toml), or checks them with --check.
    ///
    /// Each figure is `BINARY ARGS -o docs/src/figures/FILE`, run from the project's root
    /// with the chapter binaries built next to this one (target/debug or target/release).
    /// With --check, each is rendered to a temporary directory and compared with the
    /// committed PNG: a channel may differ by at most 1/255. Exit status: 0 all written or all
    /// the same, 1 some differ, 2 on an error.
    Figures(FiguresArgs),
    /// Builds the course book (docs/, mdBook with mdbook-katex) and checks it.
    ///
    /// Before the build, every {{#include file:anchor}} must give something; during it,
    /// mdBook and mdbook-katex must log no warning or error (a formula KaTeX cannot parse is
    /// only logged by them); after it, every internal link and image must resolve, nothing
    /// may load from the network, and each chapter page must show typeset math and a figure.
    /// The book is written to docs/book (open docs/book/index.html). Exit status: 0 clean,
    /// 1 problems found (each printed as file:line: …), 2 on an error (mdbook missing …).
    Book(BookArgs),
}

#[derive(clap::Args)]
struct FiguresArgs {
    /// Compare fresh renders with the committed figures instead of writing them.
    #[arg(long)]
    check: bool,
    /// Only the figures whose file names contain this text.
    #[arg(long, value_name = "TEXT")]
    only: Option<String>,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct BookArgs {
    /// The mdbook program to run.
    #[arg(long, value_name = "PATH", default_value = "mdbook")]
    mdbook: PathBuf,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct GradeArgs {
    /// The student's copy of the project [default: the current project].
    #[arg(value_name = "DIR", conflicts_with = "class")]
    submission: Option<PathBuf>,
    /// Grade only this chapter's exercises (1-5).
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u8).range(i64::from(syllabus::FIRST)..=i64::from(syllabus::LAST)))]
    chapter: Option<u8>,
    /// The instructor's hidden tests: a directory of .rs test files, each added as a test
    /// target; their tests are named after the exercise they check (ex2_3_…), like the public
    /// ones. Students' reports show their points, not their names.
    #[arg(long, value_name = "DIR")]
    hidden: Option<PathBuf>,
    /// Write Gradescope's results.json here.
    #[arg(long, value_name = "FILE")]
    json: Option<PathBuf>,
    /// Write a JUnit XML report here.
    #[arg(long, value_name = "FILE")]
    junit: Option<PathBuf>,
    /// Write the gradebook's header and this submission's row here (CSV).
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// The time limit of one test, in seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
    /// Grade every submission of a class: each subdirectory of DIR.
    #[arg(long, value_name = "DIR", requires = "out")]
    class: Option<PathBuf>,
    /// With --class: where the reports go (one directory per student, and class.csv).
    #[arg(long, value_name = "DIR", requires = "class")]
    out: Option<PathBuf>,
    /// With --class: submissions graded at a time [default: the cores].
    #[arg(long, value_name = "N", requires = "class",
          value_parser = clap::value_parser!(u64).range(1..=64))]
    jobs: Option<u64>,
    /// Where cargo builds, kept between gradings so the dependencies are built once (a class
    /// gives each of its --jobs its own directory in it) [default: target/grade in the
    /// instructor's project].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    /// Keep each graded copy (its path is printed).
    #[arg(long)]
    keep: bool,
    /// The instructor's project, whose tests and manifest grade [default: the nearest
    /// Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct HandoutArgs {
    /// The directory to write the student's copy into (it must not exist, or be empty).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Take out the exercises of these chapters only: 4, or a range such as 1-3.
    #[arg(long, value_name = "N|A-B", value_parser = whitted_course::handout::parse_chapters,
          conflicts_with = "exercises")]
    chapters: Option<(u8, u8)>,
    /// Take out these exercises only, by name or id (comma-separated): sphere_coefficients,2.7.
    #[arg(long, value_name = "IDS", value_delimiter = ',')]
    exercises: Vec<String>,
    /// The project to copy [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct Formulas {
    /// Run the proof: build a poisoned copy of the project once (into target/prove), check
    /// that the render paths pass unpoisoned, then poison each function in turn.
    #[arg(long, conflicts_with = "deps")]
    prove: bool,
    /// Measure which tests of a handout depend on which exercise (poison each in turn and run
    /// the manifest's [handout] tests), and check chapters/exercise-tests.toml against it.
    /// Exit status 1 when it is out of date.
    #[arg(long)]
    deps: bool,
    /// With --deps: write chapters/exercise-tests.toml from the measurements.
    #[arg(long, requires = "deps")]
    write: bool,
    /// Rewrite the "## Exercises" section of each chapter's README from the manifest.
    #[arg(long, conflicts_with_all = ["prove", "deps"])]
    readmes: bool,
    /// Prove only this function (a path as in the manifest, e.g. camera::viewing_basis);
    /// may be repeated.
    #[arg(long, value_name = "PATH", requires = "prove")]
    only: Vec<String>,
    /// Keep the temporary copy of the project and the test runs' output, for debugging; its
    /// path is printed.
    #[arg(long, requires = "prove")]
    keep: bool,
    /// The time limit of one test run, in seconds: a poisoned function that makes a render
    /// loop forever counts as not proven instead of hanging the proof.
    #[arg(long, value_name = "SECONDS", default_value_t = 120, requires = "prove",
          value_parser = clap::value_parser!(u64).range(1..=86_400))]
    timeout: u64,
    /// Cargo features to build the poisoned copy with, comma-separated (`--features f32`
    /// proves the single-precision build).
    #[arg(long, value_name = "LIST", value_delimiter = ',', requires = "prove")]
    features: Vec<String>,
    /// The project's root (the directory of Cargo.toml) [default: the nearest one at or
    /// above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

fn main() -> ExitCode {
    let args: Args = whitted_course::args::parse_args();
    let result = match args.command {
        Command::Formulas(f) => formulas(&f),
        Command::Handout(h) => handout(&h),
        Command::Learn(l) => whitted_course::cli::learn(&l),
        Command::Grade(g) => grade(&g),
        Command::Figures(f) => figures(&f),
        Command::Book(b) => book(&b),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn formulas(args: &Formulas) -> Result<ExitCode, ToolError> {
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let manifest = read_manifest(&root)?;
    if args.deps {
        return deps(&root, &manifest, args);
    }
    if args.readmes {
        let changed = whitted_course::readme::write_all(&root, &manifest)?;
        println!(
            "{}",
            if changed.is_empty() {
                "the chapter READMEs' exercises are current".to_string()
            } else {
                format!("rewrote the exercises of {}", changed.join(", "))
            }
        );
        return Ok(ExitCode::SUCCESS);
    }
    if !args.prove {
        list(&root, &manifest)?;
        return Ok(ExitCode::SUCCESS);
    }
    let options = PoisonedRuns {
        only: args.only.clone(),
        keep: args.keep,
        timeout: std::time::Duration::from_secs(args.timeout),
        features: args.features.clone(),
        ..PoisonedRuns::default()
    };
    let report = prove::prove(&root, &manifest, &options)?;
    eprintln!(
        "proof: build {:.1} s, test runs {:.1} s",
        report.build_time.as_secs_f64(),
        report.run_time.as_secs_f64()
    );
    if let Some(kept) = &report.kept {
        eprintln!(
            "proof: the poisoned copy and the runs' output are kept in {}",
            kept.display()
        );
    }
    let mut out = std::io::stdout().lock();
    report
        .write_table(&manifest, &mut out)
        .map_err(|e| ToolError::io("stdout", e))?;
    Ok(if report.proven() == report.rows.len() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn handout(args: &HandoutArgs) -> Result<ExitCode, ToolError> {
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let manifest = read_manifest(&root)?;
    let selected = whitted_course::handout::select(&manifest, args.chapters, &args.exercises)?;
    let made = whitted_course::handout::write(&root, &manifest, &selected, &args.out)?;
    let ids: Vec<&str> = made
        .stripped
        .iter()
        .map(|&i| manifest.entries[i].exercise.id.as_str())
        .collect();
    println!(
        "wrote {} ({} files): {} exercise{} to write ({}); in it, run `cargo learn`",
        args.out.display(),
        made.files,
        ids.len(),
        if ids.len() == 1 { "" } else { "s" },
        if ids.len() == manifest.entries.len() {
            "all".to_string()
        } else {
            ids.join(", ")
        }
    );
    Ok(ExitCode::SUCCESS)
}

/// `whitted formulas --deps [--write]`: the measured dependencies, checked against the map
/// (or written to it).
fn deps(root: &Path, manifest: &Manifest, args: &Formulas) -> Result<ExitCode, ToolError> {
    use whitted_course::deps;
    let options = PoisonedRuns {
        keep: args.keep,
        timeout: std::time::Duration::from_secs(args.timeout),
        features: args.features.clone(),
        ..PoisonedRuns::default()
    };
    let measured = deps::measure(root, manifest, &options)?;
    for (e, failing) in manifest.entries.iter().zip(&measured.failing) {
        println!(
            "{:<5} {:<44} {:>3} of {} tests fail without it",
            e.exercise.id,
            e.function,
            failing.len(),
            measured.tests.len()
        );
    }
    if args.write {
        let path = root.join(deps::MAP_PATH);
        whitted_course::files::write_file(&path, deps::map_text(manifest, &measured).as_bytes())?;
        println!("wrote {}", deps::MAP_PATH);
        return Ok(ExitCode::SUCCESS);
    }
    let map = deps::load_map(root, manifest)?;
    let problems = deps::check(manifest, &map, &measured);
    if problems.is_empty() {
        println!(
            "{} says what the {} tests measure",
            deps::MAP_PATH,
            measured.tests.len()
        );
        return Ok(ExitCode::SUCCESS);
    }
    for p in &problems {
        println!("{p}");
    }
    println!(
        "\n{} is out of date: `cargo run --release --bin whitted -- formulas --deps --write` rewrites it",
        deps::MAP_PATH
    );
    Ok(ExitCode::from(1))
}

/// `whitted figures [--check]`: the book's renders, from their manifest.
fn figures(args: &FiguresArgs) -> Result<ExitCode, ToolError> {
    use whitted_course::book::{self, Difference};
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let manifest = root.join("docs/figures.toml");
    let mut figures = book::read_figures(&manifest)?;
    if let Some(only) = &args.only {
        figures.retain(|f| f.file.contains(only.as_str()));
        if figures.is_empty() {
            return Err(ToolError::Usage(format!(
                "--only {only}: no figure of {} has it in its name",
                manifest.display()
            )));
        }
    }
    let exe = std::env::current_exe().map_err(|e| ToolError::io("whitted", e))?;
    let bin_dir = exe.parent().unwrap_or(Path::new("."));
    let dir = root.join("docs/src/figures");
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let scratch = tempfile::Builder::new()
        .prefix(".figures-")
        .tempdir_in(&dir)
        .map_err(|e| ToolError::io(&dir, e))?;
    let mut differ = 0;
    for (k, figure) in figures.iter().enumerate() {
        let fresh = scratch.path().join(&figure.file);
        let committed = dir.join(&figure.file);
        let started = std::time::Instant::now();
        book::render(figure, bin_dir, &root, &fresh)?;
        let ms = started.elapsed().as_millis();
        let n = figures.len();
        if !args.check {
            std::fs::rename(&fresh, &committed).map_err(|e| ToolError::io(&committed, e))?;
            println!(
                "[{}/{n}] wrote docs/src/figures/{} ({ms} ms)",
                k + 1,
                figure.file
            );
            continue;
        }
        if !committed.is_file() {
            differ += 1;
            println!(
                "[{}/{n}] docs/src/figures/{}: missing (docs/figures.toml:{}): run `whitted figures`",
                k + 1,
                figure.file,
                figure.line
            );
            continue;
        }
        let verdict = match book::compare(&committed, &fresh, book::TOLERANCE)? {
            Difference::Same => "the same".to_string(),
            Difference::Size(a, b) => {
                differ += 1;
                format!(
                    "DIFFERS: {}×{} committed, {}×{} rendered",
                    a.0, a.1, b.0, b.1
                )
            }
            Difference::Pixels {
                pixels,
                largest,
                first,
            } => {
                differ += 1;
                format!(
                    "DIFFERS: {pixels} pixel{} off by up to {largest}/255, the first at ({}, {})",
                    if pixels == 1 { "" } else { "s" },
                    first.0,
                    first.1
                )
            }
        };
        println!(
            "[{}/{n}] docs/src/figures/{} (docs/figures.toml:{}): {verdict} ({ms} ms)",
            k + 1,
            figure.file,
            figure.line
        );
    }
    if differ > 0 {
        println!(
            "{differ} of {} figures differ from a fresh render: if the change is meant, run `whitted figures` and commit them",
            figures.len()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// `whitted book`: checks the includes, builds the book, checks the log and the HTML.
fn book(args: &BookArgs) -> Result<ExitCode, ToolError> {
    use whitted_course::book;
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let docs = root.join("docs");
    let mut problems: Vec<String> = book::check_includes(&docs.join("src"))?
        .iter()
        .map(ToString::to_string)
        .collect();
    let out = std::process::Command::new(&args.mdbook)
        .arg("build")
        .arg(&docs)
        .env("NO_COLOR", "1")
        .output()
        .map_err(|e| {
            ToolError::Usage(format!(
                "cannot run `{}`: {e}: install the book's tools as docs/README.md says (`.ci/run` does)",
                args.mdbook.display()
            ))
        })?;
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    problems.extend(
        book::log_problems(&log)
            .into_iter()
            .map(|l| format!("mdbook: {l}")),
    );
    if !out.status.success() {
        problems.push(format!("mdbook build failed ({})", out.status));
    } else {
        let chapters = [
            "ch01-camera-rays.html",
            "ch02-generic-objects.html",
            "ch03-shading.html",
            "ch04-shadows.html",
            "ch05-reflection-refraction.html",
        ];
        let built = docs.join("book");
        for chapter in chapters {
            if !built.join(chapter).is_file() {
                problems.push(format!(
                    "docs/book/{chapter}: the chapter page was not built"
                ));
            }
        }
        problems.extend(
            book::check_html(&built, &chapters)?
                .iter()
                .map(ToString::to_string),
        );
    }
    for p in &problems {
        println!("{p}");
    }
    if problems.is_empty() {
        println!(
            "the book is built and clean: {}",
            docs.join("book/index.html").display()
        );
        Ok(ExitCode::SUCCESS)
    } else {
        println!("{} problems in the book", problems.len());
        Ok(ExitCode::from(1))
    }
}

/// `whitted grade`: one submission, or a class.
fn grade(args: &GradeArgs) -> Result<ExitCode, ToolError> {
    use whitted_course::{grade, report};
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let manifest = read_manifest(&root)?;
    let options = grade::GradeSetup {
        chapter: args.chapter,
        hidden: args.hidden.clone(),
        timeout: std::time::Duration::from_secs(args.timeout),
        // kept between gradings: the dependencies are built once
        target_dir: Some(
            args.target_dir
                .clone()
                .unwrap_or_else(|| root.join("target").join("grade")),
        ),
        keep: args.keep,
    };
    if let Some(hidden) = &args.hidden
        && !hidden.is_dir()
    {
        return Err(ToolError::Usage(format!(
            "--hidden {}: not a directory",
            hidden.display()
        )));
    }
    if let (Some(class), Some(out)) = (&args.class, &args.out) {
        std::fs::create_dir_all(out).map_err(|e| ToolError::io(out, e))?;
        let out = out.canonicalize().map_err(|e| ToolError::io(out, e))?;
        let jobs = args.jobs.map_or_else(
            || std::thread::available_parallelism().map_or(1, usize::from),
            |j| j as usize,
        );
        let start = std::time::Instant::now();
        let entries = grade::grade_class(&root, &manifest, class, &options, jobs, &|e| match &e
            .grade
        {
            Ok(g) => eprintln!(
                "graded {}: {} / {} points in {:.0} s",
                e.student,
                report::points(g.score()),
                report::points(g.max()),
                g.elapsed.as_secs_f64()
            ),
            Err(why) => eprintln!("could not grade {}: {why}", e.student),
        })?;
        let chapters: Vec<u8> = args.chapter.map_or_else(
            || syllabus::CHAPTERS.iter().map(|c| c.number).collect(),
            |c| vec![c],
        );
        let mut csv = report::csv_header(&manifest, &chapters) + "\n";
        for e in &entries {
            match &e.grade {
                Ok(g) => {
                    let dir = out.join(&e.student);
                    std::fs::create_dir_all(&dir).map_err(|err| ToolError::io(&dir, err))?;
                    write_reports(
                        g,
                        &manifest,
                        Some(&dir.join("report.txt")),
                        Some(&dir.join("results.json")),
                        Some(&dir.join("junit.xml")),
                        None,
                    )?;
                    csv += &report::csv_row(g, &manifest);
                }
                Err(why) => {
                    csv += &format!("{},0,,\"not graded: {}\"", e.student, why.replace('"', "'"))
                }
            }
            csv.push('\n');
        }
        write(&out.join("class.csv"), csv.as_bytes())?;
        let graded = entries.iter().filter(|e| e.grade.is_ok()).count();
        let mut times: Vec<f64> = entries
            .iter()
            .filter_map(|e| e.grade.as_ref().ok().map(|g| g.elapsed.as_secs_f64()))
            .collect();
        times.sort_by(f64::total_cmp);
        let median = times.get(times.len() / 2).copied().unwrap_or(0.0);
        println!(
            "graded {graded} of {} submissions in {:.0} s ({jobs} at a time; median {:.0} s each); reports in {}, the gradebook in {}",
            entries.len(),
            start.elapsed().as_secs_f64(),
            median,
            out.display(),
            out.join("class.csv").display()
        );
        return Ok(ExitCode::SUCCESS);
    }
    let submission = args.submission.clone().unwrap_or_else(|| root.clone());
    let g = grade::grade(&root, &manifest, &submission, &options)?;
    print!("{}", report::table(&g, &manifest));
    write_reports(
        &g,
        &manifest,
        None,
        args.json.as_deref(),
        args.junit.as_deref(),
        args.csv.as_deref(),
    )?;
    Ok(ExitCode::SUCCESS)
}

/// Writes the reports asked for, each atomically.
fn write_reports(
    g: &whitted_course::grade::Grade,
    manifest: &Manifest,
    text: Option<&Path>,
    json: Option<&Path>,
    junit: Option<&Path>,
    csv: Option<&Path>,
) -> Result<(), ToolError> {
    use whitted_course::report;
    if let Some(path) = text {
        write(path, report::table(g, manifest).as_bytes())?;
    }
    if let Some(path) = json {
        let value = report::gradescope(g, manifest);
        let text = serde_json::to_string_pretty(&value)
            .map_err(|e| ToolError::Usage(format!("cannot write JSON: {e}")))?;
        write(path, (text + "\n").as_bytes())?;
    }
    if let Some(path) = junit {
        write(path, report::junit(g, manifest).as_bytes())?;
    }
    if let Some(path) = csv {
        let text = format!(
            "{}\n{}\n",
            report::csv_header(manifest, &g.chapters),
            report::csv_row(g, manifest)
        );
        write(path, text.as_bytes())?;
    }
    Ok(())
}

/// Writes a file atomically (a temporary file renamed into place).
fn write(path: &Path, bytes: &[u8]) -> Result<(), ToolError> {
    whitted_course::files::write_file(path, bytes)
}

/// Prints the manifest by chapter: function, file:line, formula, section.
fn list(root: &Path, manifest: &Manifest) -> Result<(), ToolError> {
    let locations = prove::locate_all(root, manifest)?;
    let places: Vec<String> = locations
        .iter()
        .map(|l| format!("{}:{}", l.file.display(), l.line))
        .collect();
    let fn_width = manifest
        .entries
        .iter()
        .map(|e| e.function.chars().count())
        .max()
        .unwrap_or(0);
    let at_width = places.iter().map(|p| p.chars().count()).max().unwrap_or(0);
    for chapter in &syllabus::CHAPTERS {
        let (number, title) = (chapter.number, chapter.title);
        let entries: Vec<usize> = (0..manifest.entries.len())
            .filter(|&i| manifest.entries[i].chapter == number)
            .collect();
        if entries.is_empty() {
            continue;
        }
        println!("chapter {number} — {title}");
        for i in entries {
            let e = &manifest.entries[i];
            println!(
                "  {:<fn_width$}  {:<at_width$}  {}   ({})",
                e.function, places[i], e.formula, e.section
            );
        }
    }
    println!(
        "{} formula functions in {}; `whitted formulas --prove` shows they are on every render path",
        manifest.entries.len(),
        manifest.file
    );
    Ok(())
}
