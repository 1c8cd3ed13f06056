//! The command line of the student's loop: `whitted-learn` (`cargo learn` in a handout) and
//! `whitted learn`, one definition for both.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Subcommand;

use crate::ToolError;
use crate::manifest::{self, Manifest};

/// The arguments of `learn`.
#[derive(clap::Args)]
pub struct LearnArgs {
    #[command(subcommand)]
    /// What to show [default: the verdict on the next exercise, the progress, the picture].
    pub what: Option<LearnCommand>,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR", global = true)]
    pub root: Option<PathBuf>,
}

/// What `learn` shows.
#[derive(Subcommand)]
pub enum LearnCommand {
    /// Every exercise, by chapter, with its state (done, to do, failing) and points.
    List,
    /// The next hint of an exercise (the next unfinished one without EXERCISE); ask again for
    /// more.
    Hint {
        /// The exercise: its id as `list` shows it (2.6) or its name (sphere_coefficients).
        #[arg(value_name = "EXERCISE")]
        id: Option<String>,
    },
    /// Puts an exercise's body back to the handout's todo!(), keeping yours in
    /// .whitted/reset/.
    ///
    /// The lines between `// BEGIN SOLUTION NAME` and `// END SOLUTION` become the one line the
    /// handout gave, `todo!("exercise NAME (ID): …")`; the marker lines and the rest of the file
    /// stay. What stood there is kept in .whitted/reset/NAME-1.rs (then NAME-2.rs …: an earlier
    /// copy is never overwritten), and the line printed says where. Only this handout's own
    /// exercises (`list` shows them) can be reset. Nothing is built; the next `cargo learn` checks this exercise first. A body that is
    /// the handout's already, an unknown exercise or missing marker lines are an error (exit
    /// status 2) that changes nothing.
    Reset {
        /// The exercise: its id as `list` shows it (1.1) or its name (viewing_basis).
        #[arg(value_name = "EXERCISE")]
        id: String,
    },
    /// Checks again after every save: the verdict, the progress, and the picture of the
    /// newest chapter your code draws (.whitted/chNN_….png).
    Watch {
        /// Stop after this many reruns (for scripts); without it, run until Ctrl-C.
        #[arg(long, value_name = "N")]
        cycles: Option<usize>,
    },
}

/// Runs `learn` as the command line asks: 0 when all went well (whatever the exercises' state),
/// 1 when the code does not compile, an error otherwise.
pub fn learn(args: &LearnArgs) -> Result<ExitCode, ToolError> {
    use crate::learn::{self, State, Style};
    let root = match &args.root {
        Some(root) => root.clone(),
        None => find_root()?,
    };
    let manifest = read_manifest(&root)?;
    let style = Style::detect();
    match &args.what {
        None => Ok(if learn::once(&root, &manifest, style)? {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        }),
        Some(LearnCommand::List) => {
            let known = learn::saved_states(&root, &manifest);
            let checked = learn::check(&root, &manifest, &known, style, false, false)?;
            let states = if let Some((line, _)) = &checked.run.build_error {
                println!("your code does not compile yet ({line}); the states of the last check:");
                known
            } else {
                checked.states
            };
            print!("{}", learn::list(&manifest, &states, style));
            Ok(ExitCode::SUCCESS)
        }
        Some(LearnCommand::Hint { id }) => {
            let index = match id {
                Some(id) => manifest
                    .find(id)
                    .ok_or_else(|| ToolError::Usage(manifest.not_found(id)))?,
                // the first not done at the last check: no build, so a hint comes even while
                // the code does not compile
                None => match learn::saved_states(&root, &manifest)
                    .iter()
                    .position(|s| *s != State::Done)
                {
                    Some(i) => i,
                    None => {
                        println!("every exercise passed at the last check: no hint needed");
                        return Ok(ExitCode::SUCCESS);
                    }
                },
            };
            print!("{}", learn::next_hint(&root, &manifest, index)?);
            Ok(ExitCode::SUCCESS)
        }
        Some(LearnCommand::Reset { id }) => {
            let done = learn::reset(&root, &manifest, id)?;
            println!("{}", done.said(&manifest));
            Ok(ExitCode::SUCCESS)
        }
        Some(LearnCommand::Watch { cycles }) => {
            learn::watch(&root, &manifest, style, *cycles)?;
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// The project around the current directory: the nearest whitted workspace at or above it.
pub fn find_root() -> Result<PathBuf, ToolError> {
    let here = std::env::current_dir().map_err(|e| ToolError::io(".", e))?;
    crate::layout::find_root(&here).ok_or_else(|| {
        ToolError::Usage(format!(
            "no Cargo.toml in {} or above: run whitted in the project, or give --root DIR",
            here.display()
        ))
    })
}

/// Reads the manifest of the project at `root`, named in messages relative to the current
/// directory when the project is in it.
pub fn read_manifest(root: &Path) -> Result<Manifest, ToolError> {
    let path = root.join(manifest::DEFAULT_PATH);
    let here = std::env::current_dir().ok();
    let name = match path.strip_prefix(here.as_deref().unwrap_or(Path::new("/nowhere"))) {
        Ok(relative) => relative.display().to_string(),
        Err(_) => path.display().to_string(),
    };
    let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
    manifest::parse(&text, &name)
}
