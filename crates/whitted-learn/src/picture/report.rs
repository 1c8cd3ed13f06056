//! The lines a check prints of its pictures: what each shows and where it is, how it differs
//! from the book's, and for a chapter's picture the first wrong number of its ray trees.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::Path;

use super::draw::{NoPicture, Picture, draw};
use super::stage::{Stage, choose};
use crate::learn::{State, Style};
use crate::manifest::Manifest;

/// After a check: the pictures [`choose`] picks for the verdict on exercise `on`, drawn, and
/// what each shows.
pub fn report(
    root: &Path,
    manifest: &Manifest,
    before: &[State],
    states: &[State],
    on: Option<usize>,
    style: Style,
) -> String {
    let chosen = choose(manifest, before, states, on);
    let mut drawn = draw(root, manifest, &chosen);
    // none could be drawn yet (the chapter's scene meets an exercise not written): the
    // chapter's scene through the chapter before, which can
    let none = drawn
        .iter()
        .all(|(_, d)| matches!(d, Err(NoPicture::Render(_))));
    let chapter = chosen.first().map(|s| match *s {
        Stage::Exercise(i) => manifest.entries[i].chapter,
        Stage::Chapter(c) | Stage::Before(c) => c,
    });
    if let Some(c) = chapter.filter(|&c| none && c > 1 && !chosen.contains(&Stage::Before(c))) {
        drawn = draw(root, manifest, &[Stage::Before(c)]);
    }
    let mut out = String::new();
    for (stage, drawn) in drawn {
        out += &describe(root, manifest, states, stage, drawn, style);
    }
    out
}

/// The lines of one picture: what it shows and where it is, how it differs from the book's,
/// and for a chapter's picture the first wrong number of its trees.
fn describe(
    root: &Path,
    manifest: &Manifest,
    states: &[State],
    stage: Stage,
    drawn: Result<Picture, NoPicture>,
    style: Style,
) -> String {
    let what = match stage {
        Stage::Exercise(i) => {
            let x = &manifest.entries[i].exercise;
            format!(
                "exercise {}'s quantity ({}) over its chapter's scene",
                x.id, x.title
            )
        }
        Stage::Chapter(c) => format!("chapter {c}'s scene"),
        Stage::Before(c) => format!(
            "chapter {c}'s scene through chapter {}'s road (before chapter {c}'s exercises)",
            c - 1
        ),
    };
    let picture = match drawn {
        Ok(p) => p,
        Err(NoPicture::Render(why)) => {
            return format!("picture: {what} cannot be drawn yet: {why}\n");
        }
        Err(NoPicture::Tool(e)) => return format!("picture: none yet ({e})\n"),
    };
    let path = picture.path.strip_prefix(root).unwrap_or(&picture.path);
    let feedback = match stage {
        Stage::Chapter(_) => crate::trees::feedback(
            root,
            manifest,
            states,
            &picture.against,
            picture.compare.as_deref(),
        ),
        _ => String::new(),
    };
    match &picture.compare {
        Some(compare) => {
            let same = compare.contains("the same as the reference");
            format!(
                "{} picture: {what} as your code draws it, beside the book's and their difference: {}\n  {compare}\n{feedback}",
                if same {
                    style.good("✓")
                } else {
                    style.bad("✗")
                },
                path.display(),
            )
        }
        None => format!(
            "{} picture: {what} as your code draws it: {}\n{feedback}",
            style.good("✓"),
            path.display(),
        ),
    }
}
