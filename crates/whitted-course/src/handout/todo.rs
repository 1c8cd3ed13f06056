//! What a handed-out exercise becomes: its region's body replaced by a `todo!()` that names
//! the exercise (the text [`mod@whitted_learn::todo`] writes, which `cargo learn reset` puts back
//! too), and the renderer's `lib.rs` allowing what is unused until the student writes it.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use super::regions::Region;
use crate::layout::{BEGIN, END};
use crate::manifest::Manifest;
pub use whitted_learn::todo::todo_statement;

/// The line the handout adds at the top of the renderer's `lib.rs`, after the crate's
/// documentation.
pub const LIB_ALLOW: &str = "// handout: the parameters of the exercises still to write are unused until you write them\n#![allow(unused_variables, unused_imports, unused_mut, dead_code)]\n";

/// `text` with each region's body replaced by its statement (an exercise's `todo!()`,
/// [`todo_statement`], or a later chapter's, [`super::later::later_statement`]), between the
/// same marker lines.
pub(super) fn strip(text: &str, regions: &[(&Region, String)], manifest: &Manifest) -> String {
    let mut sorted: Vec<&(&Region, String)> = regions.iter().collect();
    sorted.sort_by_key(|(r, _)| r.bytes.start);
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for (r, statement) in sorted {
        let e = &manifest.entries[r.entry];
        out.push_str(&text[at..r.bytes.start]);
        // the markers stay: the student writes between them, and `whitted grade` takes
        // exactly what is there
        out.push_str(&format!("{}{BEGIN} {}\n", r.indent, e.exercise.name));
        out.push_str(&format!("{}{statement}\n", r.indent));
        out.push_str(&format!("{}{END}\n", r.indent));
        at = r.bytes.end;
    }
    out.push_str(&text[at..]);
    out
}

/// The renderer's `lib.rs` with [`LIB_ALLOW`] after its leading `//!` documentation.
pub(super) fn allow_unused(lib: &str) -> String {
    let mut at = 0;
    for line in lib.split_inclusive('\n') {
        if line.trim_start().starts_with("//!") || line.trim().is_empty() && at == 0 {
            at += line.len();
        } else {
            break;
        }
    }
    format!("{}{LIB_ALLOW}{}", &lib[..at], &lib[at..])
}
