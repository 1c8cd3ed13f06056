//! How a chapter binary's run ends: [`guard`] turns an error, or the panic of an exercise not
//! written yet, into one line on stderr and exit status 2.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::process::ExitCode;

use whitted::error::{Error, handout_stub, missing_exercise, panic_text};

/// Runs `work` and returns the exit status: 0 when it succeeds; 2 after one line on stderr,
/// `error: …`, when it fails or panics on an exercise not written yet, or on a later chapter's
/// body in a handout that ends before it (from any thread: the line names the exercise, or the
/// chapter, as [`missing_exercise`] writes it). Any other panic goes on as a panic.
pub fn guard(work: impl FnOnce() -> Result<(), Error>) -> ExitCode {
    quiet_missing_exercises();
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)) {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
        Err(payload) => match missing_exercise(payload.as_ref()) {
            Some(line) => {
                eprintln!("error: {line}");
                ExitCode::from(2)
            }
            None => std::panic::resume_unwind(payload),
        },
    }
}

/// Keeps the panics of exercises not written yet (and of later chapters' bodies) quiet (no message, no backtrace, on any
/// thread): [`guard`] turns the first into one line. Other panics are reported as usual.
fn quiet_missing_exercises() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if panic_text(info.payload()).is_none_or(|t| handout_stub(t).is_none()) {
            default(info);
        }
    }));
}
