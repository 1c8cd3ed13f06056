//! Rendering: the road of one pixel, and the machinery that runs it over a whole image.
//!
//! | module | what it holds |
//! |---|---|
//! | [`tracer`] | **the road of one pixel**: camera ray → nearest hit → local light → feelers → mirror and transmitted rays, and what it asks of the objects ([`Query`]; the notes' own answer, [`EveryObject`]). Start reading here. |
//! | [`accelerated`] | the acceleration structure as the road's [`Query`] ([`Accelerated`]) |
//! | [`options`] | the chapter ([`Chapter`]), the [`View`] and the settings of a render ([`Options`]) |
//! | [`tiles`] | the image in parallel tiles: [`render`], [`render_with`]; a [`Rect`] of it, cancellable between tiles, for the live window: [`render_rect`] |
//! | [`packets`] | a block of pixels whose first rays are traced together, then each pixel down the road: the same image bit for bit |
//! | [`sampling`] | where the samples of a pixel go |
//! | [`framebuffer`] | the image in linear RGB ([`Framebuffer`]) and the bytes of its PNG ([`framebuffer::Encoding`]) |
//! | [`stats`] | rays cast by kind ([`Stats`]) |
//! | [`recorder`] | what the road tells as it goes ([`Recorder`]): [`Stats`] counts, the inspector keeps the tree |
//! | [`inspect`] | the ray tree of one pixel (`--inspect X,Y`): its types, the recorder that builds it, its text; JSON via serde |
//! | [`views`] | the shadow mask, and the scales and palettes of the depth, shadow-mask and rays-per-pixel views |
//! | [`stages`] | the pictures of single exercises of chapters 3 and 5 (`--view diffuse` …), drawn while a chapter is written |
//!
//! The road calls one small function per formula of the notes, and the speed machinery
//! (tiles, packets, the acceleration structures of [`crate::accel`]) answers the road's
//! [`Query`] with the same functions: it changes the time, never a bit of the image.
//!
//! Course book: [Chapter 1, camera rays](../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

pub mod accelerated;
pub mod framebuffer;
pub mod inspect;
pub mod options;
pub mod packets;
pub mod recorder;
pub mod sampling;
pub mod stages;
pub mod stats;
pub mod tiles;
pub mod tracer;
pub mod views;

pub use accelerated::Accelerated;
pub use framebuffer::{Framebuffer, MAX_FRAMEBUFFER_BYTES, check_size};
pub use inspect::RayTree;
pub use options::{Chapter, Options, View};
pub use recorder::{RayKind, Recorder, Stop};
pub use stats::Stats;
pub use tiles::{BLOCK, Finished, Rect, TILE, build_accel, render, render_rect, render_with};
pub use tracer::{EveryObject, Feeler, Query, ShadingPoint, Tracer};
