//! Work on several items at once, a fixed number of threads at a time: the proof's poisoned
//! runs, the dependency measurement's, and the grading of a class.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::ToolError;

/// Runs `job` on every item, `jobs` at a time, and returns the results in the items' order.
/// The first error stops the workers (each finishes the job it is on) and is returned.
pub fn in_parallel<T: Send>(
    items: &[usize],
    jobs: usize,
    job: impl Fn(usize) -> Result<T, ToolError> + Sync,
) -> Result<Vec<T>, ToolError> {
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<(usize, T)>> = Mutex::new(Vec::new());
    let failure: Mutex<Option<ToolError>> = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..jobs.max(1) {
            scope.spawn(|| {
                while let Some(&item) = items.get(next.fetch_add(1, Ordering::SeqCst)) {
                    if failure.lock().unwrap_or_else(|p| p.into_inner()).is_some() {
                        break;
                    }
                    match job(item) {
                        Ok(t) => results
                            .lock()
                            .unwrap_or_else(|p| p.into_inner())
                            .push((item, t)),
                        Err(e) => {
                            failure
                                .lock()
                                .unwrap_or_else(|p| p.into_inner())
                                .get_or_insert(e);
                            break;
                        }
                    }
                }
            });
        }
    });
    if let Some(e) = failure.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    let mut results = results.into_inner().unwrap_or_else(|p| p.into_inner());
    results.sort_by_key(|(item, _)| items.iter().position(|i| i == item));
    Ok(results.into_iter().map(|(_, t)| t).collect())
}
