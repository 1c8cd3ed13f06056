//! Speed: the notes' "Computational Aspects", and a modern hierarchy beside them.
//!
//! The notes observe that the computation a ray tracer must do "is often times staggering",
//! and name the simplest remedies: bounding boxes, projection extents, and space subdivision
//! into cubes until each holds a preset number of surfaces. This module builds each of them,
//! selectable per render with [`Accel`] (`--accel` on the chapter binaries 2–5):
//!
//! | `--accel` | what a ray tests |
//! |---|---|
//! | `none` | every object, as the notes' step 4 says (brute force) |
//! | `boxes` | every object's world box ([`aabb`]); the object only if its box is hit |
//! | `extents` | camera rays: only the objects whose screen rectangle holds the pixel ([`extents`]); other rays as `boxes` |
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
//! rays of a 4 × 4 block of pixels, or their feelers towards one light): the structure is
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
//! How much each one saves can be counted: a build with the `counters` feature ([`counters`])
//! adds the queries, node visits, box tests and object tests to `--stats`.

pub mod aabb;
pub mod bvh;
pub mod counters;
pub mod extents;
pub mod octree;
pub mod scatter;

use std::time::Instant;

use arrayvec::ArrayVec;

pub use aabb::Aabb;
use aabb::{RayBox, Span, first_meeting};
pub use bvh::Bvh;
pub use extents::Extents;
pub use octree::Octree;

use crate::camera::Camera;
use crate::material::Material;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::render::Nearest;
use crate::shapes::{Formula, Hit, Object};

/// Which acceleration technique answers the ray queries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum)]
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
pub const PACKET: usize = 16;

/// The octree's k: a cube holding more objects than this is subdivided.
pub const OCTREE_K: usize = 4;

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
    /// sequence, and a third of what a whole [`Object`] would take.
    local: Vec<Local>,
    /// Objects without a box, increasing: tested against every ray.
    unbounded: Vec<u32>,
    index: Index,
    extents: Option<Extents>,
    /// Seconds spent building.
    pub build_seconds: f64,
}

/// The part of an object a ray test needs: the columns of M⁻¹ (without its last row) and
/// the generic shape.
#[derive(Clone, Debug)]
struct Local {
    inv: [Vec3; 4],
    shape: crate::shapes::Shape,
}

impl Local {
    fn new(o: &Object) -> Self {
        let m = &o.placement.inv;
        Self {
            inv: [
                m.x_axis.truncate(),
                m.y_axis.truncate(),
                m.z_axis.truncate(),
                m.w_axis.truncate(),
            ],
            shape: o.shape.clone(),
        }
    }

    /// The same as [`Object::intersect_object_space`], bit for bit: M⁻¹e and M⁻¹d summed in
    /// the order `Mat4::transform_point3` sums them.
    #[inline]
    fn intersect_object_space(&self, ray: &Ray, formula: Formula) -> crate::shapes::Hits {
        let [c0, c1, c2, c3] = self.inv;
        let (e, d) = (ray.origin, ray.dir);
        let dir = c2 * d.z + (c1 * d.y + c0 * d.x);
        let origin = c3 + (c2 * e.z + (c1 * e.y + c0 * e.x));
        self.shape.intersect_local(&Ray::new(origin, dir), formula)
    }
}

/// Anything a ray can be tested against in object space.
trait ObjectSpace {
    fn hits(&self, ray: &Ray, formula: Formula) -> crate::shapes::Hits;
}

impl ObjectSpace for Object {
    #[inline]
    fn hits(&self, ray: &Ray, formula: Formula) -> crate::shapes::Hits {
        counters::object();
        self.intersect_object_space(ray, formula)
    }
}

impl ObjectSpace for Local {
    #[inline]
    fn hits(&self, ray: &Ray, formula: Formula) -> crate::shapes::Hits {
        counters::object();
        self.intersect_object_space(ray, formula)
    }
}

/// The nearest hit so far: (t, object), with the hit in object space.
struct Best {
    t: Real,
    object: usize,
    hit: Option<Hit>,
}

impl Best {
    /// No hit yet.
    #[inline]
    fn new() -> Self {
        Self {
            t: Real::INFINITY,
            object: usize::MAX,
            hit: None,
        }
    }

    /// The nearest hit found, its normal carried to the world.
    #[inline]
    fn nearest(self, objects: &[Object]) -> Option<Nearest> {
        self.hit.map(|mut hit| {
            hit.normal = objects[self.object].placement.normal_to_world(hit.normal);
            Nearest {
                hit,
                object: self.object,
            }
        })
    }

    /// Tests object `i` and keeps its first hit after `t_min` if it comes before the best so
    /// far (equal t: the lower index wins, as in a scan in scene order).
    #[inline]
    fn consider(
        &mut self,
        object: &impl ObjectSpace,
        i: usize,
        ray: &Ray,
        t_min: Real,
        formula: Formula,
    ) {
        if let Some(h) = object.hits(ray, formula).first_after(t_min)
            && (h.t < self.t || (h.t == self.t && i < self.object))
        {
            self.t = h.t;
            self.object = i;
            self.hit = Some(h);
        }
    }
}

/// Translucent objects met by a feeler, kept to multiply their transmissions in scene order.
struct Blockers {
    inline: [u32; 8],
    len: usize,
    spill: Vec<u32>,
}

impl Blockers {
    fn new() -> Self {
        Self {
            inline: [0; 8],
            len: 0,
            spill: Vec::new(),
        }
    }

    fn push(&mut self, i: u32) {
        if self.len < self.inline.len() {
            self.inline[self.len] = i;
            self.len += 1;
        } else {
            if self.spill.is_empty() {
                self.spill.extend_from_slice(&self.inline);
            }
            self.spill.push(i);
        }
    }

    /// Takes note of object `i`, whose hits with a feeler are `hits`: false when it blocks
    /// the feeler and is opaque (the share is then 0, nothing more to learn); a translucent
    /// object that blocks it is kept for [`Blockers::share`].
    fn meet(
        &mut self,
        hits: &crate::shapes::Hits,
        i: u32,
        u_min: Real,
        objects: &[Object],
        materials: &[Material],
    ) -> bool {
        if crate::shadow::blocks(hits, u_min) {
            if materials[objects[i as usize].material].transmission == 0.0 {
                return false;
            }
            self.push(i);
        }
        true
    }

    /// The product of the transmissions, in increasing object index, each object once.
    fn share(mut self, objects: &[Object], materials: &[Material]) -> Real {
        let list: &mut [u32] = if self.spill.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spill
        };
        list.sort_unstable();
        let mut share: Real = 1.0;
        let mut last = None;
        for &i in list.iter() {
            if last == Some(i) {
                continue;
            }
            last = Some(i);
            share *= materials[objects[i as usize].material].transmission;
            if share == 0.0 {
                break;
            }
        }
        share
    }
}

/// The last few candidates an octree walk of a packet has been through, each with the first
/// ray it was done for: an object that straddles several cubes sits in several leaves, and a
/// packet crossing two of them would test it twice (classic "mailboxing"). Testing it again
/// cannot change an answer (the same object gives the same hit, which does not beat itself,
/// and a feeler's blockers are counted once), so skipping it changes nothing but the work.
struct Mailbox {
    ids: [u32; Mailbox::SIZE],
    from: [u32; Mailbox::SIZE],
    next: usize,
}

impl Mailbox {
    /// How many candidates it remembers (the oldest is forgotten first).
    const SIZE: usize = 8;

    fn new() -> Self {
        Self {
            ids: [u32::MAX; Self::SIZE],
            from: [0; Self::SIZE],
            next: 0,
        }
    }

    /// True when candidate `c` has been done for every ray from `from` on.
    #[inline]
    fn holds(&self, c: u32, from: usize) -> bool {
        // every slot is compared, without stopping at the first match: no branch per slot
        self.ids
            .iter()
            .zip(&self.from)
            .fold(false, |seen, (&id, &f)| {
                seen | (id == c && f as usize <= from)
            })
    }

    /// Remembers that candidate `c` has been done for every ray from `from` on.
    #[inline]
    fn note(&mut self, c: u32, from: usize) {
        self.ids[self.next] = c;
        self.from[self.next] = from as u32;
        self.next = (self.next + 1) % Self::SIZE;
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
        let local = bounded
            .iter()
            .map(|&i| Local::new(&objects[i as usize]))
            .collect();
        Self {
            kind,
            bounded,
            boxes,
            local,
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

    /// The nearest hit with t > `t_min` (world normal), exactly as a scan over every object
    /// finds it. `pixel` names the image pixel of a camera ray, which lets projection extents
    /// narrow the candidates; pass `None` for any other ray.
    #[must_use]
    pub fn nearest(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: Real,
        formula: Formula,
        pixel: Option<(u32, u32)>,
    ) -> Option<Nearest> {
        counters::query();
        let mut best = Best::new();
        self.consider_unbounded(objects, ray, t_min, formula, &mut best);
        if !self.bounded.is_empty() {
            let rb = RayBox::new(ray);
            let test = |c: u32, best: &mut Best| {
                self.consider_candidate(c as usize, &rb, ray, t_min, formula, best);
            };
            match &self.index {
                Index::List => match (&self.extents, pixel) {
                    (Some(e), Some((x, y))) => {
                        let (here, everywhere) = e.candidates(x, y);
                        for &c in here.iter().chain(everywhere) {
                            test(c, &mut best);
                        }
                    }
                    _ => {
                        for c in 0..self.bounded.len() as u32 {
                            test(c, &mut best);
                        }
                    }
                },
                Index::Bvh(bvh) => {
                    let mut limit = best.t;
                    bvh.walk(&rb, t_min, &mut limit, |c, limit| {
                        test(c, &mut best);
                        *limit = best.t;
                        true
                    });
                }
                Index::Octree(tree) => {
                    let mut limit = best.t;
                    tree.walk(&rb, t_min, &mut limit, |c, limit| {
                        test(c, &mut best);
                        *limit = best.t;
                        true
                    });
                }
            }
        }
        best.nearest(objects)
    }

    /// Tests the objects without a box, which every ray is tested against.
    #[inline]
    fn consider_unbounded(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: Real,
        formula: Formula,
        best: &mut Best,
    ) {
        for &i in &self.unbounded {
            best.consider(&objects[i as usize], i as usize, ray, t_min, formula);
        }
    }

    /// Tests bounded candidate `c` (a position in [`Accelerator::local`]) if the ray meets its
    /// box before the best hit so far.
    #[inline]
    fn consider_candidate(
        &self,
        c: usize,
        rb: &RayBox,
        ray: &Ray,
        t_min: Real,
        formula: Formula,
        best: &mut Best,
    ) {
        if self.boxes[c].hit_between(rb, t_min, best.t) {
            best.consider(
                &self.local[c],
                self.bounded[c] as usize,
                ray,
                t_min,
                formula,
            );
        }
    }

    /// Takes note of the objects without a box for a feeler, as [`Blockers::meet`] does:
    /// false as soon as an opaque one blocks it.
    #[inline(always)]
    fn meet_unbounded(
        &self,
        feeler: &Ray,
        u_min: Real,
        formula: Formula,
        blockers: &mut Blockers,
        (objects, materials): (&[Object], &[Material]),
    ) -> bool {
        // (inlined by force: called, rather than written out in its two callers, it took the
        // shapes' intersection routines out of line and cost the field's render 4% more
        // instructions at N = 10)
        for &i in &self.unbounded {
            let hits = objects[i as usize].hits(feeler, formula);
            if !blockers.meet(&hits, i, u_min, objects, materials) {
                return false;
            }
        }
        true
    }

    /// Takes note of bounded candidate `c` for a feeler that meets its box: false when it
    /// blocks the feeler and is opaque (see [`Blockers::meet`]).
    #[inline]
    fn meet_candidate(
        &self,
        c: usize,
        feeler: &Ray,
        u_min: Real,
        formula: Formula,
        blockers: &mut Blockers,
        (objects, materials): (&[Object], &[Material]),
    ) -> bool {
        blockers.meet(
            &self.local[c].hits(feeler, formula),
            self.bounded[c],
            u_min,
            objects,
            materials,
        )
    }

    /// The packet walk of the hierarchy (see [`Bvh::walk_packet`]); nothing for a list.
    /// `visit(c, from, limits)` is called for each candidate c whose box some ray from `from`
    /// on meets (ray `from` does). Where a leaf holds several candidates, each is screened
    /// first: the packet's span may turn its box down for every ray in one test, and the
    /// rays before the first that meets it are dropped (an octree leaf holds candidates
    /// far from most of the packet's rays).
    fn walk_packet(
        &self,
        rays: &[RayBox],
        t_min: &[Real],
        limits: &mut [Real],
        mut visit: impl FnMut(u32, usize, &mut [Real]),
    ) {
        let all = Span::of(rays, t_min, limits);
        let all = all.as_ref();
        let mut screened = |c: u32, from, limits: &mut [Real], alone| {
            let from = if alone {
                from
            } else {
                let b = &self.boxes[c as usize];
                match first_meeting(b, rays, t_min, limits, all, from) {
                    Some(f) => f,
                    None => return,
                }
            };
            visit(c, from, limits);
        };
        match &self.index {
            Index::Bvh(bvh) => bvh.walk_packet(rays, t_min, limits, all, screened),
            Index::Octree(tree) => {
                // a BVH names each object once; an octree's leaves share the objects that
                // straddle their cubes, so its walk remembers what it has done
                let mut done = Mailbox::new();
                tree.walk_packet(rays, t_min, limits, all, |c, from, limits, alone| {
                    if !done.holds(c, from) {
                        // (the rays before the first that meets c's box, which screening
                        // drops, cannot meet it later: their limits only come nearer)
                        screened(c, from, limits, alone);
                        done.note(c, from);
                    }
                });
            }
            Index::List => {}
        }
    }

    /// [`Accelerator::nearest`] for a packet of at most [`PACKET`] rays with the same
    /// `t_min` (camera rays of neighbouring pixels): the same answers, ray by ray, with the
    /// BVH or the octree walked once for all of them. Lists answer ray by ray.
    ///
    /// # Panics
    /// If there are more than [`PACKET`] rays, or `out` is not as long as `rays`.
    pub fn nearest_packet(
        &self,
        objects: &[Object],
        rays: &[Ray],
        t_min: Real,
        formula: Formula,
        out: &mut [Option<Nearest>],
    ) {
        assert!(rays.len() <= PACKET && out.len() == rays.len());
        if matches!(self.index, Index::List) {
            for (ray, out) in rays.iter().zip(out.iter_mut()) {
                *out = self.nearest(objects, ray, t_min, formula, None);
            }
            return;
        }
        let n = rays.len();
        let mut best: [Best; PACKET] = std::array::from_fn(|_| Best::new());
        for (ray, best) in rays.iter().zip(best.iter_mut()) {
            counters::query();
            self.consider_unbounded(objects, ray, t_min, formula, best);
        }
        if !self.bounded.is_empty() {
            let boxes: ArrayVec<RayBox, PACKET> = rays.iter().map(RayBox::new).collect();
            let mut limits = [Real::INFINITY; PACKET];
            for r in 0..n {
                limits[r] = best[r].t;
            }
            let t_mins = [t_min; PACKET];
            self.walk_packet(&boxes, &t_mins[..n], &mut limits[..n], |c, from, limits| {
                let c = c as usize;
                for r in from..n {
                    self.consider_candidate(c, &boxes[r], &rays[r], t_min, formula, &mut best[r]);
                    limits[r] = best[r].t;
                }
            });
        }
        for (out, best) in out.iter_mut().zip(best) {
            *out = best.nearest(objects);
        }
    }

    /// [`Accelerator::transmittance`] for a packet of at most [`PACKET`] feelers towards
    /// one light (from the hits of neighbouring pixels): `out[r]` is the share reaching
    /// `origins[r]`, the same as that function gives, with the BVH or the octree walked once
    /// for all of them. Lists answer feeler by feeler.
    ///
    /// # Panics
    /// If there are more than [`PACKET`] feelers, or `u_min` and `out` are not as long as
    /// `origins`.
    #[allow(clippy::too_many_arguments)] // the arguments of `transmittance`, and `out`
    pub fn transmittance_packet(
        &self,
        objects: &[Object],
        materials: &[Material],
        origins: &[Vec3],
        light: Vec3,
        u_min: &[Real],
        formula: Formula,
        out: &mut [Real],
    ) {
        let n = origins.len();
        assert!(n <= PACKET && u_min.len() == n && out.len() == n);
        if matches!(self.index, Index::List) {
            for r in 0..n {
                out[r] =
                    self.transmittance(objects, materials, origins[r], light, u_min[r], formula);
            }
            return;
        }
        let feelers: ArrayVec<Ray, PACKET> =
            origins.iter().map(|&o| Ray::new(o, light - o)).collect();
        let mut blockers: [Blockers; PACKET] = std::array::from_fn(|_| Blockers::new());
        // while a feeler is open, where the walk from the light ends (1 − u_min, see below);
        // NaN once an opaque object blocks it (see `walk_packet`)
        let mut limits = [0.0; PACKET];
        let scene = (objects, materials);
        for r in 0..n {
            counters::query();
            limits[r] =
                if self.meet_unbounded(&feelers[r], u_min[r], formula, &mut blockers[r], scene) {
                    1.0 - u_min[r]
                } else {
                    Real::NAN
                };
        }
        if !self.bounded.is_empty() {
            // The structure is walked from the light: the feelers reversed, L + (e − L)·v with
            // v = 1 − u ∈ [0, 1 − u_min], all start at L, so the packet's span is as narrow
            // as the camera rays' (the feelers' own origins lie far apart where a block of
            // pixels sees a distant patch of the scene). Only the box tests use them; each
            // object is tested with the feeler itself, so the answers do not change.
            let back: ArrayVec<RayBox, PACKET> = feelers
                .iter()
                .map(|f| RayBox::new(&Ray::new(light, -f.dir)))
                .collect();
            let from_light = [0.0; PACKET];
            self.walk_packet(
                &back,
                &from_light[..n],
                &mut limits[..n],
                |c, from, limits| {
                    let c = c as usize;
                    for r in from..n {
                        if self.boxes[c].hit_between(&back[r], 0.0, limits[r])
                            && !self.meet_candidate(
                                c,
                                &feelers[r],
                                u_min[r],
                                formula,
                                &mut blockers[r],
                                scene,
                            )
                        {
                            limits[r] = Real::NAN;
                        }
                    }
                },
            );
        }
        for (r, blockers) in blockers.into_iter().take(n).enumerate() {
            out[r] = if limits[r].is_nan() {
                0.0
            } else {
                blockers.share(objects, materials)
            };
        }
    }

    /// The share of a light reaching `origin` along the feeler S(u) = origin + (L − origin)·u,
    /// exactly as [`crate::shadow::transmittance`] computes it: the product, in scene order, of
    /// the transmissions of the objects met with u ∈ ]u_min, 1].
    #[must_use]
    pub fn transmittance(
        &self,
        objects: &[Object],
        materials: &[Material],
        origin: Vec3,
        light: Vec3,
        u_min: Real,
        formula: Formula,
    ) -> Real {
        counters::query();
        let feeler = Ray::new(origin, light - origin);
        let mut blockers = Blockers::new();
        let scene = (objects, materials);
        if !self.meet_unbounded(&feeler, u_min, formula, &mut blockers, scene) {
            return 0.0;
        }
        if !self.bounded.is_empty() {
            let rb = RayBox::new(&feeler);
            let mut blocked = false;
            let mut test = |c: u32, blockers: &mut Blockers| -> bool {
                let c = c as usize;
                let open = !self.boxes[c].hit_between(&rb, u_min, 1.0)
                    || self.meet_candidate(c, &feeler, u_min, formula, blockers, scene);
                blocked |= !open;
                open
            };
            match &self.index {
                Index::List => {
                    for c in 0..self.bounded.len() as u32 {
                        if !test(c, &mut blockers) {
                            break;
                        }
                    }
                }
                Index::Bvh(bvh) => {
                    let mut limit = 1.0;
                    bvh.walk(&rb, u_min, &mut limit, |c, _| test(c, &mut blockers));
                }
                Index::Octree(tree) => {
                    let mut limit = 1.0;
                    tree.walk(&rb, u_min, &mut limit, |c, _| test(c, &mut blockers));
                }
            }
            if blocked {
                return 0.0;
            }
        }
        blockers.share(objects, materials)
    }
}
