//! `whitted` — the course tools: the formula functions of the notes (the exercises), a
//! student's handout, the student's loop, grading and the course book. This file is the
//! command line and nothing else: each command's arguments and code are the library's.
//!
//! ```text
//! whitted formulas [list]                           the manifest, by chapter, with file:line
//! whitted formulas prove [--only PATH]... [--keep] [--features f32]
//!                                                   poison each function, run the render paths
//! whitted formulas deps [--write]                   which tests need which exercise (the map)
//! whitted formulas readmes                          each chapter README's exercises
//! whitted handout --out DIR [--chapters 1-3 | --exercises NAME,2.4]
//!                                                   a student's copy, the exercises as todo!()
//! whitted learn [list | hint [EXERCISE] | reset EXERCISE | watch]
//!                                                   progress, the next exercise, hints, a fresh start, rerun on save
//! whitted grade [DIR] [--chapter N|A-B] [--hidden DIR] [--json F] [--junit F] [--csv F]
//!                                                   a student's copy graded with the instructor's tests
//! whitted grade --class DIR --out REPORTS [--roster F] [--new-gradebook]
//!                                                   every submission of a class, and its class.csv
//! whitted autograder --platform P --out DIR         a grading platform's package (gradescope,
//!                                                   classroom, prairielearn, codegrade)
//! whitted autograder grade|prebuild|check           what those packages run
//! whitted figures [--check]                         the book's figures, rendered or compared
//! whitted trees [--check]                           the reference's ray trees and the known
//!                                                   mistakes, written or compared
//! whitted book                                      the book, built and checked
//! ```
//!
//! Exit status: 0 when everything asked for is fine, 1 when some function is not proven (or
//! the map, a figure or the book is out of date), 2 on an error (a bad manifest, a function
//! not found, a build that fails …), printed as one line `error: …`.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use whitted_course::{autograder, book, cli, figures, formulas, grade, handout, trees};

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
    /// `list` (the default) lists them by chapter, each with its file:line; `prove` shows that
    /// each one is on every render path of its chapter (in a copy of the project, one function
    /// at a time is made to panic, "poisoned", and every test of tests/render_paths.rs for its
    /// chapter must then fail); `deps` measures which tests need which exercise; `readmes`
    /// writes the chapter READMEs' exercises. Exit status: 0 fine, 1 something is not
    /// (unproven, out of date), 2 on an error.
    Formulas(formulas::FormulasArgs),
    /// Writes a student's copy of the project, with exercises taken out.
    ///
    /// Each chosen exercise's reference body (between `// BEGIN SOLUTION NAME` and
    /// `// END SOLUTION` in src/) becomes `todo!("exercise NAME (ID): … — see chapters/…/README.md")`;
    /// earlier chapters' exercises keep their reference code, and a chapter after the last
    /// chosen one is not part of the handout: its bodies say so, its tests and golden images
    /// stay behind. Of tests/, only the targets of the manifest's [handout] tests go along;
    /// .ci/ stays behind. The handout's manifest lists the chosen exercises, the only ones its
    /// `cargo learn` counts. Without --chapters or --exercises, every exercise is taken out.
    /// DIR must not exist (or be empty).
    Handout(handout::HandoutArgs),
    /// The student's loop: progress, the next exercise and its failing test, hints.
    ///
    /// Runs the exercise tests (`cargo test` on the manifest's [handout] tests) and shows, per
    /// chapter, how many exercises pass, then the next one to write with its first failing
    /// test, the formula it checks and the notes' section. Colour only on a terminal, and not
    /// with NO_COLOR set.
    Learn(cli::LearnArgs),
    /// Grades a student's copy (DIR, default the current project) with this project's tests.
    ///
    /// Only the student's exercise bodies (between `// BEGIN SOLUTION NAME` and `// END
    /// SOLUTION` in DIR's src/) are taken; they go into a fresh copy of this project, so the
    /// tests, the manifest and the code around the exercises are the instructor's. Each
    /// exercise is judged alone: its tests run with the student's body for it and this
    /// project's for every other exercise, so a mistake costs only its own exercise
    /// (--whole-road judges with all of the student's bodies together). The tests run in a
    /// build of this project (the judge, built once, beside --target-dir); only the values of
    /// the student's functions cross to it from their build (the server, in the sandbox), so
    /// nothing the student's code prints, writes or exits with decides a test. A body that does not
    /// compile, or that stops the compiler at its limits (--compile-cpu, --compile-memory), is
    /// graded as not written; so is a body the screen refuses (`cargo learn` runs the same
    /// screen at every save: a formula's grammar passes, whatever its names; `unsafe`, items,
    /// lifetimes, most macros and paths into the process, files, the network or the
    /// environment do not), which is never compiled. Each test runs in its own process under
    /// --timeout of CPU time (cargo-nextest), so a panic, a stack overflow or an endless loop costs only
    /// its own tests, and a test passes only when the judge's assertions all held on the
    /// values the student's code returned. An exercise's points (chapters/formulas.toml) are shared by its tests.
    /// Exit status 0 once graded, whatever the score; 2 on an error.
    Grade(grade::GradeArgs),
    /// Writes what a grading platform takes (Gradescope's zip, PrairieLearn's image and entry
    /// point, CodeGrade's scripts, GitHub Classroom's workflow) into --out; its subcommands are
    /// what those packages run.
    Autograder(autograder::command::AutograderArgs),
    /// Runs a program of the student's in the grader's sandbox: with `--serve` first, the
    /// student's server of the judge outside their process (how grading uses it); else a test
    /// binary, as nextest's target runner.
    #[command(name = "sandbox-run", hide = true)]
    SandboxRun {
        /// The test binary and its arguments, or `--serve`, the server and its arguments.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, required = true)]
        command: Vec<std::ffi::OsString>,
    },
    /// Runs a graded copy's build with each of its processes under a CPU time and a memory
    /// limit: the grader's wrapper around cargo.
    #[command(name = "compile-watch", hide = true)]
    CompileWatch {
        /// `--cpu-ms N --memory BYTES -- PROGRAM ARGS…`
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, required = true)]
        args: Vec<std::ffi::OsString>,
    },
    /// Runs one of the judge's tests under its limit of CPU time: the grader's target runner
    /// for nextest.
    #[command(name = "test-clock", hide = true)]
    TestClock {
        /// `--cpu-ms N --road-times K TEST-BINARY ARGS…`
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, required = true)]
        args: Vec<std::ffi::OsString>,
    },
    /// Renders the course book's figures (docs/figures.toml), or checks them with --check.
    ///
    /// Each figure is `BINARY ARGS -o docs/src/figures/FILE`, run from the project's root
    /// with the chapter binaries built next to this one (target/debug or target/release).
    /// With --check, each is rendered to a temporary directory and compared with the
    /// committed PNG: a channel may differ by at most 1/255. Exit status: 0 all written or all
    /// the same, 1 some differ, 2 on an error.
    Figures(figures::FiguresArgs),
    /// Writes the reference's ray trees at a few pixels of each chapter scene
    /// (chapters/chNN_name/trees.json) and the known mistakes' fingerprints
    /// (chapters/mistakes.json), or checks the trees with --check.
    ///
    /// The pixels are chosen so that their trees show every object and part, each light lit
    /// and shadowed, every kind of branch and stop, and every hand-written mutant of
    /// crates/whitted-course/tests/mutants/hand-written.toml (built once, each behind a switch,
    /// into target/mistakes). With --check, the committed pixels are traced again by the
    /// chapter binaries built next to this one and compared. Exit status: 0 written or the same,
    /// 1 some differ, 2 on an error.
    Trees(trees::TreesArgs),
    /// Builds the course book (docs/, mdBook with mdbook-katex) and checks it.
    ///
    /// Before the build, every {{#include file:anchor}} must give something; during it,
    /// mdBook and mdbook-katex must log no warning or error (a formula KaTeX cannot parse is
    /// only logged by them); after it, every internal link and image must resolve, nothing
    /// may load from the network, and each chapter page must show typeset math and a figure.
    /// The book is written to docs/book (open docs/book/index.html). Exit status: 0 clean,
    /// 1 problems found (each printed as file:line: …), 2 on an error (mdbook missing …).
    Book(book::BookArgs),
}

fn main() -> ExitCode {
    let args: Args = whitted_course::args::parse_args();
    let result = match args.command {
        Command::Formulas(f) => f.run(),
        Command::Handout(h) => h.run(),
        Command::Learn(l) => cli::learn(&l),
        Command::Grade(g) => g.run(),
        Command::Autograder(a) => a.run(),
        Command::SandboxRun { command } => return grade::runner::run_test(&command),
        Command::CompileWatch { args } => return grade::sandbox::watch::run(&args),
        Command::TestClock { args } => return grade::clock::run(&args),
        Command::Figures(f) => f.run(),
        Command::Trees(t) => t.run(),
        Command::Book(b) => b.run(),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
