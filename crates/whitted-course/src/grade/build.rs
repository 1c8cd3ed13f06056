//! The build of the graded copy, the student's server: each body that does not compile put
//! back to its `todo!()` and the build tried again, so that a compile error costs only the
//! exercise it is in.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;

use super::blame::{blame, blame_files, build, stalled};
use super::clean::clean;
use super::copy::GradedCopy;
use super::splice::Spliced;
use crate::handout::todo_statement;
use crate::manifest::Manifest;
use crate::{ToolError, cargo, files};

/// Builds the graded copy's server (the program `examples` name) with the student's bodies in
/// `files` (the bodies of `chapters`): an exercise whose body does not compile is noted in `notes` and
/// put back to its `todo!()`, and the build is tried again, so that a compile error costs
/// only the exercise it is in. Returns what concerns the whole submission: that it does not
/// build, when no body can be blamed (none when it builds).
pub(super) fn build_bodies(
    copy: &GradedCopy,
    manifest: &Manifest,
    chapters: &[u8],
    files: &mut [Spliced],
    examples: &[String],
    wrapper: Option<&cargo::Wrapper>,
    notes: &mut BTreeMap<usize, String>,
) -> Result<Vec<String>, ToolError> {
    loop {
        // each file's body lines, as written, for placing the compiler's errors
        let mut placed = Vec::with_capacity(files.len());
        for f in files.iter() {
            let (text, lines) = f.text();
            files::write_if_changed(&copy.project.join(&f.file), text.as_bytes())?;
            placed.push((f.file.clone(), lines));
        }
        let errors = build(&copy.project, &copy.target_dir, examples, wrapper)?;
        if errors.is_empty() {
            return Ok(Vec::new());
        }
        if let Some(why) = stalled(&errors) {
            let why = why.to_string();
            let students: Vec<usize> = files
                .iter()
                .flat_map(|f| f.regions.iter().map(|(r, _)| r.entry))
                .filter(|&e| {
                    chapters.contains(&manifest.entries[e].chapter) && !notes.contains_key(&e)
                })
                .collect::<std::collections::BTreeSet<usize>>()
                .into_iter()
                .collect();
            let Some(entry) = stalling_body(copy, manifest, files, &students, examples, wrapper)?
            else {
                return Ok(vec![clean(&format!(
                    "the submission's build was stopped at the compiler's limit ({why}), and not because of one exercise's body"
                ))]);
            };
            notes.insert(
                entry,
                clean(&format!(
                    "stops the compiler ({why}): graded as not written; a formula compiles in moments"
                )),
            );
            put_back(manifest, files, entry);
            continue;
        }
        let mut broken = blame(&placed, &errors);
        if broken.is_empty() {
            // not on a body's lines (an unclosed brace is reported at the end of the file):
            // every student body of the files with errors goes back to its todo!()
            broken = blame_files(files, &errors, |e| {
                chapters.contains(&manifest.entries[e].chapter) && !notes.contains_key(&e)
            });
        }
        if broken.is_empty() {
            return Ok(vec![clean(&format!(
                "the submission does not build, and not because of an exercise's body: {}",
                errors[0].1
            ))]);
        }
        for (entry, message) in broken {
            notes.insert(
                entry,
                clean(&format!(
                    "does not compile, graded as not written: {message}"
                )),
            );
            put_back(manifest, files, entry);
        }
    }
}

/// Puts the body of exercise `entry` back to its `todo!()` in `files`.
fn put_back(manifest: &Manifest, files: &mut [Spliced], entry: usize) {
    let e = &manifest.entries[entry];
    for f in files.iter_mut() {
        for (r, body) in &mut f.regions {
            if r.entry == entry {
                *body = format!("{}{}\n", r.indent, todo_statement(e));
            }
        }
    }
}

/// The student's body that stops the compiler at its limits, among `students` (manifest entries,
/// in order), when one does: the last of the shortest run of them, from the first, whose build
/// (of the same `targets`, every later one of them put back to its `todo!()`) is stopped. A
/// binary search from the build that was stopped with all of them: about log₂ n builds more,
/// each stopped at the limit or done sooner. `None` when the build is stopped with none of them
/// (the limit is too low for the build itself): no body is blamed then. The copy's files are
/// left as the search's last build wrote them; the caller writes them again.
fn stalling_body(
    copy: &GradedCopy,
    manifest: &Manifest,
    files: &[Spliced],
    students: &[usize],
    targets: &[String],
    wrapper: Option<&cargo::Wrapper>,
) -> Result<Option<usize>, ToolError> {
    let stalls = |first: usize| -> Result<bool, ToolError> {
        let mut probe: Vec<Spliced> = files.to_vec();
        for &e in &students[first..] {
            put_back(manifest, &mut probe, e);
        }
        for f in &probe {
            let (text, _) = f.text();
            files::write_if_changed(&copy.project.join(&f.file), text.as_bytes())?;
        }
        let errors = build(&copy.project, &copy.target_dir, targets, wrapper)?;
        Ok(stalled(&errors).is_some())
    };
    // invariant: the first `lo` do not stall the build, the first `hi` do (all of them did)
    let (mut lo, mut hi) = (0, students.len());
    if hi == 0 || stalls(0)? {
        return Ok(None);
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if stalls(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(Some(students[hi - 1]))
}
