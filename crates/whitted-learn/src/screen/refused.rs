//! The screen run over a student's project, as `cargo learn` runs it at every save: each
//! exercise body the grader would refuse, with its file and line.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::{Path, PathBuf};

use super::{Refusal, screen};
use crate::manifest::Manifest;

/// A body of a student's project that the grader would refuse, where it stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refused {
    /// The manifest entry.
    pub entry: usize,
    /// The source file, relative to the project.
    pub file: PathBuf,
    /// The refused line in that file, from 1.
    pub line: usize,
    /// What is refused, why, and what to write instead.
    pub refusal: Refusal,
}

impl Refused {
    /// The loop's line: the exercise, the file and line, what is refused and how to write it.
    #[must_use]
    pub fn line(&self, manifest: &Manifest) -> String {
        let x = &manifest.entries[self.entry].exercise;
        let r = &self.refusal;
        format!(
            "✗ the grader would grade exercise {} ({}) as not written: {}:{}: {} {}; {}",
            x.id,
            x.name,
            self.file.display(),
            self.line,
            r.what,
            r.why,
            r.instead
        )
    }
}

/// Every exercise body of the project at `root` that the screen refuses, in manifest order.
#[must_use]
pub fn refused(root: &Path, manifest: &Manifest) -> Vec<Refused> {
    let mut out: Vec<Refused> = crate::changes::located(root)
        .into_iter()
        .filter_map(|r| {
            let entry = manifest.by_name(&r.name)?;
            let refusal = screen(&r.body)?;
            Some(Refused {
                entry,
                line: r.line + refusal.line - 1,
                file: r.file,
                refusal,
            })
        })
        .collect();
    out.sort_by_key(|r| r.entry);
    out
}
