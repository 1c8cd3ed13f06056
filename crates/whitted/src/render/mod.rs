//! Rendering: the road of one pixel, and the machinery that runs it over a whole image.
//!
//! The files sit on floors, each using only those below it or beside it, never one above:
//!
//! | floor | module | what it holds |
//! |---|---|---|
//! | what the road asks and tells | [`query`] | what the road asks of the objects, the notes' step 4 ([`Query`]), and what shading needs to know of a hit ([`ShadingPoint`]) |
//! | | [`shortcuts`] | what a faster query may offer besides its answers ([`Shortcuts`]) |
//! | | [`recorder`] | what the road tells as it goes ([`Recorder`]): [`Stats`] counts, the inspector keeps the tree |
//! | | [`options`] | the chapter ([`Chapter`]), the [`View`] and the settings of a render ([`Options`]) |
//! | | [`scales`] | the scales and palettes of the depth, shadow-mask and rays-per-pixel views, fixed before the first pixel |
//! | | [`sampling`], [`stats`], [`framebuffer`] | where the samples of a pixel go; rays cast by kind ([`Stats`]); the image in linear RGB ([`Framebuffer`]) and its PNG's bytes ([`framebuffer::Encoding`]) |
//! | **the road** | [`tracer`] | **the road of one pixel**: camera ray → nearest hit → local light → feelers → mirror and transmitted rays, and the notes' own answer to its questions, [`EveryObject`]. Start reading here. |
//! | beside the road, calling it | [`pixel`] | a pixel: its samples, its colour in the options' view ([`Tracer::pixel`]), its ray tree ([`Tracer::inspect`]) |
//! | | [`views`] | what a hit shows in each view; the shadow mask |
//! | | [`stages`] | the pictures of single exercises of chapters 3 and 5 (`--view diffuse` …), drawn while a chapter is written |
//! | | [`inspect`] | the ray tree of one pixel (`--inspect X,Y`): its types, the recorder that builds it, its text; JSON via serde |
//! | | [`accelerated`] | the acceleration structure as the road's [`Query`] ([`Accelerated`]); for `--accel none`, [`EveryObject`] itself |
//! | | [`packets`] | a block of pixels whose first rays are traced together, then each pixel down the road: the same image bit for bit |
//! | | [`tiles`] | the image in parallel tiles: [`render`], [`render_with`]; a [`Rect`] of it, cancellable between tiles, for the live window: [`render_rect`] |
//!
//! The road calls one small function per formula of the notes, and the speed machinery
//! (tiles, packets, the acceleration structures of [`crate::accel`]) answers the road's
//! [`Query`] with the same functions: it changes the time, never a bit of the image.
//!
//! Course book: [Chapter 1, camera rays](../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

pub mod accelerated;
pub mod crossing;
pub mod framebuffer;
pub mod inspect;
pub mod options;
pub mod packets;
pub mod pixel;
pub mod query;
pub mod recorder;
pub mod sampling;
pub mod scales;
pub mod shortcuts;
pub mod stages;
pub mod stats;
pub mod tiles;
pub mod tracer;
pub mod views;

pub use crate::shadow::Feeler;
pub use accelerated::Accelerated;
pub use framebuffer::{Framebuffer, MAX_FRAMEBUFFER_BYTES, check_size};
pub use inspect::RayTree;
pub use options::{Chapter, Options, View};
pub use query::{Query, ShadingPoint};
pub use recorder::{RayKind, Recorder, Stop};
pub use shortcuts::Shortcuts;
pub use stats::Stats;
pub use tiles::{BLOCK, Finished, Rect, TILE, build_accel, render, render_rect, render_with};
pub use tracer::{EveryObject, Tracer};
