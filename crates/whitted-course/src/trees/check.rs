//! `whitted trees --check`: the committed trees files are still what the reference traces,
//! and the committed known mistakes still what the hand-written mutants do.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::Path;
use std::process::ExitCode;

use super::choose::Chosen;
use super::file::{MISTAKE_SHOWS, read_file, rel};
use super::grid::grid;
use super::run::{against, figure_of, reference_binary};
use crate::ToolError;
use crate::figures::Figure;
use crate::mistakes::{self, Mutant};
use crate::syllabus;
use whitted_learn::trees::{Mistake, trees_file};

/// Each chapter's committed trees are still the reference's, and its features' pixels still
/// those a fresh choice makes; each known mistake is still told ([`mistakes_unseen`]).
/// Status 1 when one differs.
pub(super) fn check_all(root: &Path, figures: &[Figure]) -> Result<ExitCode, ToolError> {
    let mut differ = 0;
    let n = syllabus::CHAPTERS.len();
    for (k, chapter) in syllabus::CHAPTERS.iter().enumerate() {
        let started = std::time::Instant::now();
        let figure = figure_of(figures, chapter)?;
        let exe = reference_binary(chapter)?;
        let path = root.join(trees_file(chapter.number).unwrap_or_default());
        let name = rel(root, &path);
        if !path.is_file() {
            differ += 1;
            println!("[{}/{n}] {name}: missing: run `whitted trees`", k + 1);
            continue;
        }
        let committed = read_file(&path)?;
        let (fresh, _) = Chosen::from(grid(&exe, figure, root)?);
        let mut problems: Vec<String> = Vec::new();
        let kept: Vec<(u32, u32)> = committed
            .pixels
            .iter()
            .filter(|p| !p.covers.iter().any(|c| c.starts_with(MISTAKE_SHOWS)))
            .map(|p| p.tree.tree.pixel)
            .collect();
        let fresh = fresh.pixels();
        if kept != fresh {
            problems.push(format!(
                "the features' pixels are {} now, {} in the file",
                pixels_text(&fresh),
                pixels_text(&kept)
            ));
        }
        let (_, compared) = against(&exe, figure, root, &path, None, None)?;
        let count = committed.pixels.len();
        if compared.len() != count {
            problems.push(format!("{} of its {count} pixels compared", compared.len()));
        }
        problems.extend(
            compared
                .iter()
                .filter_map(|a| a.first.as_ref())
                .map(|p| p.text.clone()),
        );
        let ms = started.elapsed().as_millis();
        if problems.is_empty() {
            println!(
                "[{}/{n}] {name}: the same ({count} pixels) ({ms} ms)",
                k + 1
            );
        } else {
            differ += 1;
            println!("[{}/{n}] {name}: DIFFERS ({ms} ms)", k + 1);
            for p in problems {
                println!("  {p}");
            }
        }
    }
    let unseen = mistakes_unseen(
        &mistakes::load(root)?,
        &whitted_learn::trees::load_mistakes(root),
    );
    for problem in &unseen {
        println!("{problem}");
    }
    if differ > 0 || !unseen.is_empty() {
        println!(
            "{differ} of {n} trees files differ from the reference, {} mistakes are not told: if the change is meant, run `whitted trees` and commit them (and chapters/mistakes.json)",
            unseen.len()
        );
        return Ok(ExitCode::from(1));
    }
    println!(
        "each of the {} hand-written mistakes moves a kept number or a pixel of its chapter, or says why its scene cannot show it",
        mistakes::load(root)?.len()
    );
    Ok(ExitCode::SUCCESS)
}

/// What is wrong with the known mistakes' fingerprints `known` (`chapters/mistakes.json`) for
/// the hand-written mutants `mutants`: each mutant must move some kept number or some pixel of
/// its chapter's picture (a fingerprint with a differing tree or pixel), unless it says why its
/// chapter's scene cannot show it (`unseen`), and then it must have none; every fingerprint
/// must be a mutant's. One line a problem; none when all is well.
#[must_use]
pub fn mistakes_unseen(mutants: &[Mutant], known: &[Mistake]) -> Vec<String> {
    let mut out = Vec::new();
    for m in mutants {
        let found = known.iter().find(|k| k.name == m.name);
        let moves = found
            .and_then(|k| k.fingerprint.as_ref())
            .is_some_and(|f| !f.pixels.is_empty() || f.picture.0 > 0);
        match (&m.unseen, moves) {
            (None, false) => out.push(format!(
                "mistake {} ({}): no kept number and no pixel of its chapter moves",
                m.name, m.exercise
            )),
            (Some(why), true) => out.push(format!(
                "mistake {} ({}): its chapter shows it now, though `unseen` says \"{why}\"",
                m.name, m.exercise
            )),
            _ => {}
        }
    }
    for k in known {
        if !mutants.iter().any(|m| m.name == k.name) {
            out.push(format!(
                "mistake {} in chapters/mistakes.json is no hand-written mutant",
                k.name
            ));
        }
    }
    out
}

/// Pixels as `(x, y) (x, y) …`.
fn pixels_text(pixels: &[(u32, u32)]) -> String {
    pixels
        .iter()
        .map(|(x, y)| format!("({x}, {y})"))
        .collect::<Vec<_>>()
        .join(" ")
}
