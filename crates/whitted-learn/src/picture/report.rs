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
    let map = crate::map::load_map(root, manifest).unwrap_or_default();
    let chosen = choose(manifest, before, states, on);
    // a picture whose road meets an exercise not written cannot be drawn: said, not built
    let (blocked, drawable): (Vec<Stage>, Vec<Stage>) = chosen
        .iter()
        .partition(|&&s| unwritten_need(manifest, &map, states, s).is_some());
    let mut drawn = draw(root, manifest, &drawable);
    // none could be drawn (the chapter's scene meets an exercise not written): the
    // chapter's scene through the chapter before, which can
    let none = drawn
        .iter()
        .all(|(_, d)| matches!(d, Err(NoPicture::Render(_))));
    let chapter = chosen.first().map(|s| match *s {
        Stage::Exercise(i) => manifest.entries[i].chapter,
        Stage::Chapter(c) | Stage::Before(c) => c,
    });
    let before_stage = chapter
        .filter(|&c| none && c > 1 && !chosen.contains(&Stage::Before(c)))
        .map(Stage::Before)
        .filter(|&s| unwritten_need(manifest, &map, states, s).is_none());
    let mut out = String::new();
    match before_stage {
        Some(stage) => drawn = draw(root, manifest, &[stage]),
        None => {
            for stage in blocked {
                if let Some(why) = unwritten_need(manifest, &map, states, stage) {
                    out += &format!(
                        "picture: {} cannot be drawn yet: {why}\n",
                        what(manifest, stage)
                    );
                }
            }
        }
    }
    // the verdict's exercise when it is written and fails: a picture the same as the book's
    // says it cannot show that exercise, and takes no ✓ beside the verdict's ✗ (beside a
    // verdict on an exercise not written yet, a ✓ says what is written draws right)
    let open = on.filter(|&x| matches!(states[x], State::Failing(_)));
    for (stage, drawn) in drawn {
        out += &describe(root, manifest, states, stage, drawn, open, style);
    }
    out
}

/// What `stage` shows, in words.
fn what(manifest: &Manifest, stage: Stage) -> String {
    match stage {
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
    }
}

/// Why `stage` cannot be drawn yet, when its road needs an exercise not written: the first
/// exercise the render tests of its chapter's road call (`render_paths::chN_…`, by the map
/// `map`) that stops at its `todo!()`. `None` when all are written, or the map says nothing.
fn unwritten_need(
    manifest: &Manifest,
    map: &[crate::map::Group],
    states: &[State],
    stage: Stage,
) -> Option<String> {
    let road = match stage {
        Stage::Chapter(c) => c,
        Stage::Before(c) => c.checked_sub(1)?,
        Stage::Exercise(_) => return None,
    };
    let prefix = format!("render_paths::ch{road}_");
    let unwritten = |i: usize| match &states[i] {
        State::ToDo => true,
        State::Waiting(name) => manifest
            .by_name(name)
            .is_some_and(|j| states[j] == State::ToDo),
        _ => false,
    };
    let i = map
        .iter()
        .filter(|g| g.tests.iter().any(|t| t.starts_with(&prefix)))
        .flat_map(|g| g.needs.iter().copied())
        .filter(|&i| i < states.len() && unwritten(i))
        .min()?;
    let e = &manifest.entries[i];
    Some(format!(
        "chapter {road}'s road calls exercise {} ({}), which is not written yet",
        e.exercise.id, e.function
    ))
}

/// The lines of one picture: what it shows and where it is, how it differs from the book's,
/// and for a chapter's picture the first wrong number of its trees.
fn describe(
    root: &Path,
    manifest: &Manifest,
    states: &[State],
    stage: Stage,
    drawn: Result<Picture, NoPicture>,
    open: Option<usize>,
    style: Style,
) -> String {
    let what = what(manifest, stage);
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
    let same = picture
        .compare
        .as_deref()
        .is_none_or(|c| c.contains("the same as the reference"));
    let compare = picture
        .compare
        .as_deref()
        .map_or(String::new(), |c| format!("\n  {c}"));
    let beside = if compare.is_empty() {
        ""
    } else {
        ", beside the book's and their difference"
    };
    let line = format!(
        "picture: {what} as your code draws it{beside}: {}{compare}\n",
        path.display()
    );
    match (same, open) {
        (true, Some(x)) => {
            let id = &manifest.entries[x].exercise.id;
            let why = match stage {
                Stage::Before(c) => format!(
                    "it is drawn before chapter {c}'s exercises, so it cannot show exercise {id} yet"
                ),
                _ => format!(
                    "it does not show exercise {id}: what is wrong there does not reach this \
                     picture yet; the tests above tell it"
                ),
            };
            format!("{line}  {why}\n{feedback}")
        }
        (true, None) => format!("{} {line}{feedback}", style.good("✓")),
        (false, _) => format!("{} {line}{feedback}", style.bad("✗")),
    }
}
