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
//! file, [`render::tracer`]; [`render::Chapter`] decides how far along it a chapter goes.
//!
//! Around the road: [`render`] (tiles in parallel, packets, the framebuffer, statistics),
//! [`numeric`], [`error`] and [`output`] (sRGB-encoded PNGs, written atomically). Everything
//! computes with [`real::Real`], `f64` by default and `f32` under the `f32` feature.
//!
//! This crate is the renderer and nothing else: what a student writes and what it runs in. The
//! programs around it are other crates of the workspace: `whitted-app` holds the chapter
//! binaries, the command line they share and the live window; `whitted-learn` (the student's
//! loop, `cargo learn`) and `whitted-course` (the instructor's tools, `whitted grade` …) run
//! cargo on a project and do not depend on this crate.
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
pub mod error;
pub mod judge;
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
