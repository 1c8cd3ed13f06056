//! Which pictures a check draws ([`choose`]), from the exercises' states before and after it,
//! and which of the book's figures shows each ([`figure_of`]).
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use crate::chapter_binary::chapter_figure;
use crate::figures::Figure;
use crate::learn::State;
use crate::manifest::Manifest;

/// A picture a check draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// The picture of one exercise (its manifest index): its `picture` figure.
    Exercise(usize),
    /// A chapter's own picture, with its ray trees.
    Chapter(u8),
    /// A chapter's scene drawn by the chapter before it.
    Before(u8),
}

/// The newest chapter whose exercises, and all earlier chapters', are done: the one whose
/// picture the student's code can draw whole (never after the handout's last chapter, whose
/// later chapters' bodies it does not hold).
#[must_use]
pub fn drawable_chapter(manifest: &Manifest, states: &[State]) -> Option<u8> {
    let mut out = None;
    for chapter in whitted_syllabus::FIRST..=manifest.last_chapter() {
        if of_chapter(manifest, chapter).all(|i| states[i] == State::Done) {
            out = Some(chapter);
        } else {
            break;
        }
    }
    out
}

/// The chapter whose picture a check is about: a chapter that turned green at this check (the
/// first of them: when one exercise turns several green, as the first of chapter 3 may turn
/// chapters 3 to 5, the one the student was working in), else the chapter of the next exercise
/// (the one the student works on, whose picture shows what is still wrong), else the last.
#[must_use]
pub fn picture_chapter(manifest: &Manifest, before: &[State], now: &[State]) -> u8 {
    turned_green(manifest, before, now)
        .or_else(|| next(now).map(|i| manifest.entries[i].chapter))
        .unwrap_or(manifest.last_chapter())
}

/// The pictures a check draws, in the order they are shown (see [`crate::picture`]):
/// `before` holds the states of the last check, `now` this one's, and `on` the exercise the
/// verdict is on (by default the first not done).
#[must_use]
pub fn choose(
    manifest: &Manifest,
    before: &[State],
    now: &[State],
    on: Option<usize>,
) -> Vec<Stage> {
    // a chapter that turned green is the picture, unless the verdict is on an exercise that
    // fails (one save may finish a chapter and break another): the picture follows that one
    let verdict_fails = on.is_some_and(|x| matches!(now[x], State::Failing(_) | State::Waiting(_)));
    if let Some(chapter) = turned_green(manifest, before, now).filter(|_| !verdict_fails) {
        return vec![Stage::Chapter(chapter)];
    }
    let Some(x) = on.or_else(|| next(now)) else {
        return vec![Stage::Chapter(manifest.last_chapter())];
    };
    let chapter = manifest.entries[x].chapter;
    // written: done, failing, or waiting for a written exercise that fails (its tests call it)
    let written = |i: usize| match &now[i] {
        State::Done | State::Failing(_) => true,
        State::Waiting(name) => manifest
            .by_name(name)
            .is_some_and(|j| matches!(now[j], State::Failing(_))),
        _ => false,
    };
    let has_picture = |i: usize| manifest.entries[i].exercise.picture.is_some();
    let mut out = Vec::new();
    let stage = if written(x) && has_picture(x) {
        Some(x)
    } else {
        of_chapter(manifest, chapter)
            .filter(|&i| i < x && written(i) && has_picture(i))
            .last()
    };
    out.extend(stage.map(Stage::Exercise));
    if of_chapter(manifest, chapter).all(written) {
        out.push(Stage::Chapter(chapter));
    }
    if out.is_empty() {
        out.push(if chapter > 1 {
            Stage::Before(chapter)
        } else {
            Stage::Chapter(chapter)
        });
    }
    out
}

/// The first exercise not done.
fn next(states: &[State]) -> Option<usize> {
    states.iter().position(|s| *s != State::Done)
}

/// The manifest indices of chapter `chapter`'s exercises.
fn of_chapter(manifest: &Manifest, chapter: u8) -> impl Iterator<Item = usize> + '_ {
    (0..manifest.entries.len()).filter(move |&i| manifest.entries[i].chapter == chapter)
}

/// The first chapter that is drawable now and was known not to be at the last check (one of
/// its exercises was not done then; a first check knows nothing of before, and turns nothing).
fn turned_green(manifest: &Manifest, before: &[State], now: &[State]) -> Option<u8> {
    let was_not_done = |i: usize| {
        before
            .get(i)
            .is_some_and(|s| !matches!(s, State::Done | State::Unknown))
    };
    drawable_chapter(manifest, now)
        .and_then(|drawable| (1..=drawable).find(|&c| of_chapter(manifest, c).any(was_not_done)))
}

/// The book's figure that shows `stage`, from the figures' list `figures`: `None` when the
/// handout has none (a chapter's picture is then drawn alone, [`PICTURE_WIDTH`](super::PICTURE_WIDTH)
/// wide).
#[must_use]
pub fn figure_of<'f>(
    manifest: &Manifest,
    figures: &'f [Figure],
    stage: Stage,
) -> Option<&'f Figure> {
    match stage {
        Stage::Exercise(i) => {
            let file = manifest.entries.get(i)?.exercise.picture.as_deref()?;
            figures.iter().find(|f| f.file == file)
        }
        Stage::Chapter(c) => chapter_figure(figures, c),
        Stage::Before(c) => {
            let scene = whitted_syllabus::chapter(c)?.scene();
            let road = whitted_syllabus::chapter(c.checked_sub(1)?)?.binary;
            figures
                .iter()
                .find(|f| f.binary == road && f.scene() == Some(scene.as_str()))
        }
    }
}
