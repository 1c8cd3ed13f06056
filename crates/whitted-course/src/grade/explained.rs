//! The feedback of a graded submission worded for a report: each chapter that lost points,
//! its picture's line and the first wrong number of its ray trees, attributed to an exercise
//! as `cargo learn` attributes it.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::outcome::Grade;
use crate::manifest::Manifest;

/// What a report says of one chapter's feedback ([`Grade::explained`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Explained<'g> {
    /// The chapter.
    pub chapter: u8,
    /// How the student's picture compares with the book's (the binary's `compare:` line), or
    /// why there is no picture.
    pub picture_line: String,
    /// The first wrong number of the chapter's ray trees, in learn's words, and the exercise
    /// (manifest index) it points at, when a tree differs.
    pub first_wrong: Option<(Option<usize>, String)>,
    /// The PNG of the student's render, the book's figure and their difference side by side.
    pub picture: Option<&'g [u8]>,
}

impl Grade {
    /// The feedback of each chapter that lost points, worded for a report: the picture's
    /// line, and the first wrong number of its trees attributed to an exercise as `cargo
    /// learn` attributes it (the first of those that computed it whose tests did not all
    /// pass).
    #[must_use]
    pub fn explained(&self, manifest: &Manifest) -> Vec<Explained<'_>> {
        use whitted_learn::learn::State;
        use whitted_learn::trees as learn_trees;
        // an exercise not graded here has the reference's body in the graded copy
        let states: Vec<State> = (0..manifest.entries.len())
            .map(|i| match self.exercises.iter().find(|e| e.entry == i) {
                Some(e) if e.score < e.max || e.note.is_some() => State::Failing(Vec::new()),
                _ => State::Done,
            })
            .collect();
        self.feedback
            .iter()
            .map(|f| {
                let picture_line = match (&f.trouble, &f.compare) {
                    (Some(why), _) => format!("no picture: {why}"),
                    (None, Some(compare)) => compare.clone(),
                    (None, None) => "no picture".into(),
                };
                let differs = f
                    .compare
                    .as_deref()
                    .and_then(learn_trees::picture_counts)
                    .is_some_and(|(n, _)| n > 0);
                let first_wrong = learn_trees::attribute(manifest, &states, &f.against, differs)
                    .map(|w| (w.exercise, w.lines(manifest, f.against.len())));
                Explained {
                    chapter: f.chapter,
                    picture_line,
                    first_wrong,
                    picture: f.picture.as_deref(),
                }
            })
            .collect()
    }
}
