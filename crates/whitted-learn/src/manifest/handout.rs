//! A handout's own list of exercises: `[handout] exercises = [...]`.
//!
//! A handout of some chapters (`whitted handout --chapters 3-4`) or of some exercises holds
//! the whole manifest, every exercise's text and hints, but only some exercises are the
//! student's: the others are earlier chapters' given code, or later chapters' bodies that come
//! with a later handout. `whitted handout` writes their names into the handout's manifest, and
//! [`parse`](super::parse) keeps only those entries: the loop (`cargo learn`, its list, its
//! hints, its progress and its pictures) then knows nothing of the others. Their displayed ids
//! are the manifest's (`3.1` stays `3.1`). Without the key (the project, a full handout) every
//! exercise is kept.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use toml::Spanned;

use super::{Entry, HandoutTable, Manifest, error_at};
use crate::ToolError;

/// The entries of `listed` (the `[handout] exercises` value of the manifest text `text`, read
/// from `file`), in the manifest's order, with the table's [`HandoutTable::exercises`] and
/// [`HandoutTable::others`] filled in; all of `entries` when the key is absent. An empty list
/// or a name that is no exercise's is an error at its place.
pub(super) fn only_listed(
    text: &str,
    file: &str,
    listed: Option<&Spanned<Vec<String>>>,
    entries: Vec<Entry>,
    table: &mut HandoutTable,
) -> Result<Vec<Entry>, ToolError> {
    let Some(listed) = listed else {
        return Ok(entries);
    };
    let names = listed.get_ref();
    let err = |message: String| error_at(text, file, listed.span(), message);
    if names.is_empty() {
        return Err(err(
            "handout.exercises: expected the names of the exercises this handout holds, found none (leave the key out for all of them)".into(),
        ));
    }
    if let Some(unknown) = names
        .iter()
        .find(|n| !entries.iter().any(|e| e.exercise.name == **n))
    {
        return Err(err(format!(
            "handout.exercises: {unknown:?} names no exercise of the manifest (the exercises' `name`s, such as \"viewing_basis\")"
        )));
    }
    let (kept, others): (Vec<Entry>, Vec<Entry>) = entries
        .into_iter()
        .partition(|e| names.contains(&e.exercise.name));
    table.exercises = Some(kept.iter().map(|e| e.exercise.name.clone()).collect());
    table.others = others.into_iter().map(|e| e.exercise.name).collect();
    Ok(kept)
}

impl Manifest {
    /// The last chapter the manifest's exercises reach: the handout's last chapter when it
    /// lists its own exercises, else the syllabus's last. A chapter after it has no exercise
    /// in this handout, and no picture the loop draws.
    #[must_use]
    pub fn last_chapter(&self) -> u8 {
        self.entries
            .iter()
            .map(|e| e.chapter)
            .max()
            .unwrap_or(whitted_syllabus::LAST)
    }

    /// Whether the exercise named `name` is one the manifest knows but this handout leaves
    /// out (see [`HandoutTable::others`]).
    #[must_use]
    pub fn is_left_out(&self, name: &str) -> bool {
        self.handout.others.iter().any(|n| n == name)
    }
}

impl Manifest {
    /// The one line a student reads when `key` names no exercise of this manifest: a handout
    /// of some chapters says when the name is one of the exercises it leaves out.
    #[must_use]
    pub fn not_found(&self, key: &str) -> String {
        let key = key.trim();
        // an id names its chapter before the dot: a chapter this handout has no exercise of
        let chapter = key
            .split_once('.')
            .and_then(|(c, _)| c.parse::<u8>().ok())
            .filter(|c| whitted_syllabus::chapter(*c).is_some());
        let left_out = self.handout.exercises.is_some()
            && chapter.is_some_and(|c| !self.entries.iter().any(|e| e.chapter == c));
        if left_out || self.handout.others.iter().any(|n| n == key) {
            format!(
                "exercise {key} is not one of this handout's: it is given, or it comes with a \
                 later chapter's handout (`{} list` shows this handout's)",
                crate::learn::COMMAND
            )
        } else {
            format!(
                "there is no exercise {key}: `{} list` shows the ids",
                crate::learn::COMMAND
            )
        }
    }
}
