//! # whitted — classic ray tracing, chapter by chapter
//!
//! whitted follows the course notes (`course-notes.md`) from camera rays to a complete
//! Whitted-style renderer. Each module belongs to the chapter that introduces it:
//!
//! | chapter | binary | modules |
//! |---|---|---|
//! | 1 camera rays | `ch01_camera_rays` | [`camera`], [`ray`], [`real`] |
//! | 2 generic objects | `ch02_generic_objects` | [`shapes`], [`transform`], [`scene`] |
//! | 3 shading | `ch03_shading` | [`shading`], [`light`], [`material`] |
//! | 4 shadows | `ch04_shadows` | [`shadow`], [`offset`] |
//! | 5 reflection and refraction | `ch05_reflection_refraction` | [`optics`] |
//!
//! Each formula of the notes is one small function in those modules, and the renderer calls
//! exactly that function (`chapters/formulas.toml` lists them). **The road of one pixel** —
//! camera ray, nearest hit, local light, feelers, mirror and transmitted rays — is one plain
//! file, [`render::tracer`]; [`render::Stage`] decides how far along it a chapter goes.
//!
//! Around the road: [`render`] (tiles in parallel, packets, the framebuffer, statistics),
//! [`numeric`], [`error`], [`output`] (sRGB-encoded PNGs, written atomically) and [`cli`] (the
//! arguments every binary shares). Everything computes with [`real::Real`], `f64` by default
//! and `f32` under the `f32` feature.
//!
//! The live window (`--window` on every chapter binary) lives in [`window`]: the image refined
//! coarse to fine as you watch, keys for the camera, stage, view and depth, and the ray tree of
//! a clicked pixel drawn over the image.
//!
//! The course tools live in [`course`]: the manifest of the functions that compute the notes'
//! formulas, and the proof that every render path calls them (`whitted formulas --prove`).
//!
//! Speed (the notes' "Computational Aspects") lives in [`accel`]: bounding boxes, projection
//! extents, an octree and a BVH, chosen with `--accel`. They decide which objects a ray is
//! tested against, never how, so no choice changes a pixel. Measurements:
//! `docs/src/performance.md`.
//!
//! Course book: [Introduction](../../../docs/book/introduction.html) (`docs/src/introduction.md`).

#![deny(missing_docs)]

pub mod accel;
pub mod camera;
pub mod cli;
pub mod course;
pub mod error;
pub mod light;
pub mod material;
pub mod numeric;
pub mod offset;
pub mod optics;
pub mod output;
pub mod ray;
pub mod real;
pub mod render;
pub mod scene;
pub mod shading;
pub mod shadow;
pub mod shapes;
pub mod transform;
pub mod window;
