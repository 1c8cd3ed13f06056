//! The pictures of `cargo learn`: after each check, what the student's own code draws of the
//! chapter being written, beside the course book's figure of the same stage and their
//! difference.
//!
//! A chapter's own picture needs every exercise of the chapter, so while a chapter is written
//! the picture is one of the book's stages ([`choose`]):
//!
//! - **the exercise's own picture**, when the exercise the verdict is on is written (and
//!   fails): its manifest `picture`, a figure that shows the quantity it computes (the
//!   normals for a normal, each light's max(n·s, 0) for the cosine law), so that its mistake
//!   is in sight; otherwise the picture of the newest exercise of the chapter written before
//!   it: what the student has written so far;
//! - **the chapter's picture**, with the first wrong number of its ray trees ([`crate::trees`]),
//!   once every exercise of the chapter is written, and when a chapter turns green;
//! - **the chapter before's road over this chapter's scene** (the book's figure drawn by the
//!   previous chapter's binary: no objects yet, no shadows yet, no mirror rays yet), when
//!   nothing of the chapter that it can draw is written, or when what is chosen cannot be
//!   drawn yet (chapter 2's scene holds every shape: its pictures need all of them).
//!
//! A stage whose road calls an exercise not written yet (by the map's render tests of its
//! chapter) is not built: its line says which exercise it waits for. A picture the same as the
//! book's beside a verdict on a written exercise that fails takes no ✓: its line says that it
//! cannot show that exercise yet. When a save finishes a chapter and breaks another exercise,
//! the picture follows the one that fails.
//!
//! Each is the book's figure as `docs/figures.toml` lists it ([`crate::figures`]), drawn by
//! the project's own build of that figure's binary with the figure's arguments and
//! `--compare` with the book's PNG ([`crate::chapter_binary`]), into `.whitted/FILE`. Nothing of the reference's code is
//! needed: the figures are pictures, the trees numbers.
//!
//! | file | its job |
//! |---|---|
//! | `stage.rs` | which pictures a check draws, and the figure of each ([`choose`], [`figure_of`]) |
//! | `draw.rs` | drawing them with the chapter binaries ([`draw`]) |
//! | `report.rs` | the lines printed of each ([`report`]) |
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

mod draw;
mod report;
mod stage;

pub use draw::{NoPicture, PICTURE_WIDTH, Picture, draw};
pub use report::report;
pub use stage::{Stage, choose, drawable_chapter, figure_of, picture_chapter};
