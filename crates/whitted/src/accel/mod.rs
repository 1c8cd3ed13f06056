//! Speed: the notes' "Computational Aspects", and a modern hierarchy beside them.
//!
//! The notes observe that the computation a ray tracer must do "is often times staggering",
//! and name the simplest remedies: bounding boxes, projection extents, and space subdivision
//! into cubes until each holds a preset number of surfaces. This module builds each of them,
//! selectable per render with [`Accel`] (`--accel` on the chapter binaries 2–5):
//!
//! | `--accel` | what a ray tests |
//! |---|---|
//! | `none` | every object, as the notes' step 4 says (brute force, as the road's own [`EveryObject`](crate::render::EveryObject)) |
//! | `boxes` | every object's world box ([`aabb`]); the object only if its box is hit |
//! | `extents` | camera rays: only the objects whose screen rectangle holds the image point the ray passes through ([`extents`]); other rays as `boxes` |
//! | `octree` | the objects of the cubes of an octree the ray crosses, front to back ([`octree`]) |
//! | `bvh` (default) | the leaves of a bounding volume hierarchy built by the binned SAH ([`bvh`]) |
//!
//! Infinite planes (and polyhedra whose facets leave them open) have no box: they live outside
//! every structure and are tested against every ray.
//!
//! Every option returns exactly what brute force returns: the hit with the smallest t, and
//! among equal t the object listed first in the scene, and for a feeler ray the product of the
//! transmissions of the objects in between, taken in scene order. So the images are identical,
//! bit for bit, whichever option renders them.
//!
//! ```text
//! ch05_reflection_refraction scene.toml --accel octree
//! ```
//!
//! The BVH and the octree also answer *packets* of up to [`PACKET`] rays at once (the camera
//! rays of an 8 × 8 block of pixels, or their feelers towards one light): the structure is
//! walked once for all of them, a node opened when some ray of the packet meets its box.
//! Two classic devices keep that cheap: the rays before the first one that meets a box are
//! dropped for all of its subtree (Wald's "first active ray"), and a box that the span of the
//! packet's origins and directions cannot meet is turned down with one interval test
//! (`Span` in [`aabb`]), which also screens each object of a leaf that holds several. A packet
//! of feelers, which start far apart when a block of pixels sees a distant patch, walks the
//! structure from the light, where they all start. An octree leaf shares the objects that
//! straddle its cube with its neighbours, so the octree's packet walk also keeps a small
//! mailbox of the objects it has already tested. Each ray still gets exactly its own answer.
//!
//! Every ray–object test, in every structure and in the packets, is the same call,
//! [`crate::shapes::Shape::intersect_placed`] (M⁻¹ onto the generic shape); the nearest hit is
//! chosen by [`crate::shapes::Hits::first_after`] and [`crate::shapes::nearer`], and a feeler's
//! share by [`crate::shadow::blocks`] and [`crate::shadow::transmittance`]: the structures
//! decide only which objects to test. [`query`] answers one ray at a time, [`packet`] a packet;
//! the road of one pixel asks them through its `Query` trait
//! ([`crate::render::Accelerated`]).
//!
//! How much each one saves can be counted: a build with the `counters` feature ([`counters`])
//! adds the queries, node visits, box tests and object tests to `--stats`.
//!
//! Course book: [Performance](../../../../docs/book/performance.html) (`docs/src/performance.md`).

pub mod aabb;
pub mod bvh;
pub mod counters;
pub mod extents;
pub mod octree;
pub mod packet;
pub mod query;

use std::time::Instant;

pub use aabb::Aabb;
pub use bvh::Bvh;
pub use extents::Extents;
pub use octree::Octree;

use crate::camera::Camera;
use crate::ray::Ray;
use crate::real::Mat4;
use crate::shapes::{Hits, Numerics, Object, Shape};

/// Which acceleration technique answers the ray queries.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum Accel {
    /// Brute force: every ray against every object.
    None,
    /// A bounding box per object, tested before the object.
    Boxes,
    /// Boxes, and screen rectangles that limit the objects a camera ray tests.
    Extents,
    /// An octree: cubes subdivided until each holds at most k objects.
    Octree,
    /// A bounding volume hierarchy (binned SAH).
    #[default]
    Bvh,
}

impl Accel {
    /// Every option, in the order of the notes and then the modern one.
    pub const ALL: [Accel; 5] = [
        Accel::None,
        Accel::Boxes,
        Accel::Extents,
        Accel::Octree,
        Accel::Bvh,
    ];

    /// The option's name as `--accel` writes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Accel::None => "none",
            Accel::Boxes => "boxes",
            Accel::Extents => "extents",
            Accel::Octree => "octree",
            Accel::Bvh => "bvh",
        }
    }
}

/// The most rays [`Accelerator::nearest_packet`] takes at once.
pub const PACKET: usize = 64;

/// The octree's k: a cube holding more objects than this is subdivided. With packets of
/// 64 rays, 8 measured faster than 4 on the 100 000-sphere field (and 12 or 16 no better).
pub const OCTREE_K: usize = 8;

#[derive(Clone, Debug)]
enum Index {
    /// Test the candidates one by one (none, boxes, extents).
    List,
    Octree(Octree),
    Bvh(Bvh),
}

/// An acceleration structure built for one scene, camera and [`Accel`].
#[derive(Clone, Debug)]
pub struct Accelerator {
    kind: Accel,
    /// Object index of each bounded candidate, in the order the structure walks them (BVH:
    /// leaf order; otherwise increasing).
    bounded: Vec<u32>,
    /// The world box of each bounded candidate, same order.
    boxes: Vec<Aabb>,
    /// What intersecting each bounded candidate needs, same order: a walk reads memory in
    /// sequence, and less than half of what a whole [`Object`] would take.
    candidates: Vec<Candidate>,
    /// Objects without a box, increasing: tested against every ray.
    unbounded: Vec<u32>,
    index: Index,
    extents: Option<Extents>,
    /// Seconds spent building.
    build_seconds: f64,
}

/// The part of an object a ray test needs: M⁻¹ and the generic shape.
#[derive(Clone, Debug)]
struct Candidate {
    inv: Mat4,
    shape: Shape,
}

/// Anything a world ray can be tested against, normals left in object space.
trait ObjectSpace {
    fn hits(&self, ray: &Ray, numerics: Numerics) -> Hits;
}

impl ObjectSpace for Object {
    #[inline]
    fn hits(&self, ray: &Ray, numerics: Numerics) -> Hits {
        counters::object();
        self.intersect_object_space(ray, numerics)
    }
}

impl ObjectSpace for Candidate {
    #[inline]
    fn hits(&self, ray: &Ray, numerics: Numerics) -> Hits {
        counters::object();
        self.shape.intersect_placed(&self.inv, ray, numerics)
    }
}

impl Accelerator {
    /// Builds the structure `kind` over the scene's objects; `camera` gives the image size and
    /// the viewpoint for projection extents, tiles of `tile` pixels.
    #[must_use]
    pub fn build(objects: &[Object], camera: &Camera, kind: Accel, tile: u32) -> Self {
        let start = Instant::now();
        let mut bounded = Vec::new();
        let mut boxes = Vec::new();
        let mut unbounded = Vec::new();
        for (i, o) in objects.iter().enumerate() {
            match aabb::world_bounds(o) {
                Some(b) if kind != Accel::None => {
                    bounded.push(i as u32);
                    boxes.push(b);
                }
                _ => unbounded.push(i as u32),
            }
        }
        let index = match kind {
            Accel::Octree => {
                let mut tree = Octree::build(&boxes, OCTREE_K);
                // store the candidates in the order the leaves name them
                let order = tree.renumber(boxes.len());
                bounded = order.iter().map(|&k| bounded[k as usize]).collect();
                boxes = order.iter().map(|&k| boxes[k as usize]).collect();
                Index::Octree(tree)
            }
            Accel::Bvh => {
                let bvh = Bvh::build(&boxes);
                // store the candidates in leaf order
                bounded = bvh.order().iter().map(|&k| bounded[k as usize]).collect();
                boxes = bvh.order().iter().map(|&k| boxes[k as usize]).collect();
                Index::Bvh(bvh)
            }
            _ => Index::List,
        };
        let extents = (kind == Accel::Extents).then(|| Extents::build(&boxes, camera, tile));
        let candidates = bounded
            .iter()
            .map(|&i| {
                let o = &objects[i as usize];
                Candidate {
                    inv: *o.placement.inv(),
                    shape: o.shape.clone(),
                }
            })
            .collect();
        Self {
            kind,
            bounded,
            boxes,
            candidates,
            unbounded,
            index,
            extents,
            build_seconds: start.elapsed().as_secs_f64(),
        }
    }

    /// The technique in use.
    #[must_use]
    pub fn kind(&self) -> Accel {
        self.kind
    }

    /// Seconds the build took.
    #[must_use]
    pub fn build_seconds(&self) -> f64 {
        self.build_seconds
    }

    /// A one-line description of the structure (objects in and out of it, nodes).
    #[must_use]
    pub fn describe(&self) -> String {
        let detail = match &self.index {
            Index::Octree(o) => format!(", {} cells (k = {OCTREE_K})", o.cell_count()),
            Index::Bvh(b) => format!(", {} nodes", b.node_count()),
            Index::List => String::new(),
        };
        format!(
            "accel {}: {} bounded, {} unbounded objects{detail}, built in {:.3} s",
            self.kind.name(),
            self.bounded.len(),
            self.unbounded.len(),
            self.build_seconds
        )
    }
}
