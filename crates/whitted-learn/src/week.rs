//! What the manifest of a week's handout says of the exercises it does not hold: the last
//! chapter its exercises reach, whether an exercise is one it leaves out, and the line a
//! student reads when asking for one ([`crate::manifest::HandoutTable::others`]).
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use crate::manifest::Manifest;

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
    /// out (see [`crate::manifest::HandoutTable::others`]).
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

/// The project's manifest with every exercise, in a week's handout too (its `exercises = [...]`
/// line left out): for the tests that name exercises of every chapter.
#[cfg(test)]
pub(crate) fn every_exercise() -> Manifest {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join(crate::manifest::DEFAULT_PATH)).unwrap();
    let all: String = text
        .split_inclusive('\n')
        .filter(|l| !l.starts_with("exercises = ["))
        .collect();
    crate::manifest::parse(&all, crate::manifest::DEFAULT_PATH).unwrap()
}
