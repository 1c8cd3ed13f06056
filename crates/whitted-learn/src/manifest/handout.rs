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

use std::ops::Range;

use toml::Spanned;

/// The names a handout's list holds and the names it leaves out, in the manifest's order.
pub(super) type Split = (Vec<String>, Vec<String>);

/// An error in the list: its span in the manifest's text, and what is wrong.
pub(super) type ListError = (Range<usize>, String);

/// Which of `entries` (in the manifest's order, each named by `name`) a handout holds by its
/// `[handout] exercises` list `listed`: those it lists, then the names it holds and the names
/// it leaves out; all of them, and no names, when the key is absent. An empty list or a name
/// that is no exercise's is an error: the span of the list in the manifest's text, and what is
/// wrong.
pub(super) fn only_listed<E>(
    listed: Option<&Spanned<Vec<String>>>,
    entries: Vec<E>,
    name: impl Fn(&E) -> &str,
) -> Result<(Vec<E>, Option<Split>), ListError> {
    let Some(listed) = listed else {
        return Ok((entries, None));
    };
    let names = listed.get_ref();
    if names.is_empty() {
        return Err((
            listed.span(),
            "handout.exercises: expected the names of the exercises this handout holds, found none (leave the key out for all of them)".into(),
        ));
    }
    if let Some(unknown) = names
        .iter()
        .find(|n| !entries.iter().any(|e| name(e) == n.as_str()))
    {
        return Err((
            listed.span(),
            format!(
                "handout.exercises: {unknown:?} names no exercise of the manifest (the exercises' `name`s, such as \"viewing_basis\")"
            ),
        ));
    }
    let (kept, others): (Vec<E>, Vec<E>) = entries
        .into_iter()
        .partition(|e| names.iter().any(|n| n == name(e)));
    let held = kept.iter().map(|e| name(e).to_string()).collect();
    let left = others.iter().map(|e| name(e).to_string()).collect();
    Ok((kept, Some((held, left))))
}
