//! The progress of every chapter (a bar each) and the list of every exercise with its state and
//! points: what `cargo learn` prints after the verdict, and `cargo learn list`.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use super::state::State;
use super::style::Style;
use crate::manifest::{Entry, Manifest};

/// A bar of `width` cells, `done` of `total` filled.
#[must_use]
pub fn bar(done: usize, total: usize, width: usize) -> String {
    let filled = (done * width).checked_div(total).unwrap_or(0);
    format!("[{}{}]", "#".repeat(filled), "-".repeat(width - filled))
}

/// The progress of every chapter: exercises done with a bar, and a summary line.
#[must_use]
pub fn progress(manifest: &Manifest, states: &[State], style: Style) -> String {
    let total = states.len();
    let done = states.iter().filter(|s| **s == State::Done).count();
    let mut out = format!(
        "{} — {done} of {total} exercises done\n",
        style.strong("progress")
    );
    // the widest title, in characters: the bars line up whatever the titles
    let title_w = whitted_syllabus::CHAPTERS
        .iter()
        .map(|c| c.title.chars().count())
        .max()
        .unwrap_or(0);
    for chapter in &whitted_syllabus::CHAPTERS {
        let (number, title) = (chapter.number, chapter.title);
        let of: Vec<usize> = (0..total)
            .filter(|&i| manifest.entries[i].chapter == number)
            .collect();
        if of.is_empty() {
            continue;
        }
        let d = of.iter().filter(|&&i| states[i] == State::Done).count();
        let line = format!(
            "  chapter {number}  {title:<title_w$}  {} {d:>2}/{}",
            bar(d, of.len(), 20),
            of.len()
        );
        out += &if d == of.len() {
            style.good(&line)
        } else {
            line
        };
        out.push('\n');
    }
    out
}

/// What a check whose every exercise passes says is written: the whole road of one pixel, or
/// in a handout that ends before the last chapter, the road up to its last chapter.
#[must_use]
pub fn written_road(manifest: &Manifest) -> String {
    let last = manifest.last_chapter();
    if last >= whitted_syllabus::LAST {
        "the whole road of one pixel is written".into()
    } else {
        format!("the road of one pixel is written up to chapter {last}, the last of this handout")
    }
}

/// The list of every exercise with its state and points, aligned, and a summary line.
#[must_use]
pub fn list(manifest: &Manifest, states: &[State], style: Style) -> String {
    let width = |f: &dyn Fn(&Entry) -> usize| manifest.entries.iter().map(f).max().unwrap_or(0);
    let id_w = width(&|e| e.exercise.id.chars().count());
    let title_w = width(&|e| e.exercise.title.chars().count());
    let fn_w = width(&|e| e.function.chars().count());
    let words: Vec<String> = states
        .iter()
        .map(|s| match s {
            State::Waiting(name) => format!("waits for {}", manifest.display(name)),
            s => s.word(),
        })
        .collect();
    let state_w = words.iter().map(|w| w.chars().count()).max().unwrap_or(0);
    let mut out = String::new();
    let mut chapter = 0;
    for ((e, s), word) in manifest.entries.iter().zip(states).zip(&words) {
        if e.chapter != chapter {
            chapter = e.chapter;
            out += &format!(
                "chapter {chapter} — {}\n",
                whitted_syllabus::chapter(chapter).map_or("", |c| c.title)
            );
        }
        let word = format!("{word:<state_w$}");
        let word = match s {
            State::Done => style.good(&word),
            State::Failing(_) | State::NoTests => style.bad(&word),
            _ => word,
        };
        out += &format!(
            "  {:<id_w$}  {word}  {:<title_w$}  {:<fn_w$}  {:>2} pt\n",
            e.exercise.id, e.exercise.title, e.function, e.exercise.points
        );
    }
    let count = |f: &dyn Fn(&State) -> bool| states.iter().filter(|s| f(s)).count();
    let points: u32 = manifest
        .entries
        .iter()
        .zip(states)
        .filter(|(_, s)| **s == State::Done)
        .map(|(e, _)| e.exercise.points)
        .sum();
    let all: u32 = manifest.entries.iter().map(|e| e.exercise.points).sum();
    out += &format!(
        "{} done, {} to do, {} failing, {} waiting for an earlier one; {points} of {all} points\n",
        count(&|s| *s == State::Done),
        count(&|s| *s == State::ToDo),
        count(&|s| matches!(s, State::Failing(_))),
        count(&|s| matches!(s, State::Waiting(_))),
    );
    out
}
