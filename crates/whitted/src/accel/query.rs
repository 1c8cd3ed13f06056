//! One ray at a time: the nearest hit of a ray, and the share of a light a feeler lets through.
//!
//! Both answer exactly what testing every object in turn answers
//! ([`EveryObject`](crate::render::tracer::EveryObject), the notes' step 4); the road asks
//! them through [`Accelerated`](crate::render::accelerated::Accelerated). The structures only choose
//! which objects to test; each test, and what is made of its hits, is the road's own function:
//! [`Shape::intersect_placed`](crate::shapes::Shape::intersect_placed),
//! [`Hits::first_after`], [`nearer`], [`shadow::blocks`] and [`shadow::transmittance`].
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use super::aabb::RayBox;
use super::{Accelerator, Index, ObjectSpace, counters};
use crate::material::Material;
use crate::ray::Ray;
use crate::real::Real;
use crate::shadow;
use crate::shapes::{Hit, Hits, Nearest, Numerics, Object, nearer};

/// The nearest hit so far: (t, object), with the hit in object space.
pub(super) struct Best {
    pub(super) t: Real,
    object: usize,
    hit: Option<Hit>,
}

impl Best {
    /// No hit yet.
    #[inline]
    pub(super) fn new() -> Self {
        Self {
            t: Real::INFINITY,
            object: usize::MAX,
            hit: None,
        }
    }

    /// The nearest hit found for `ray`, its normal carried to the world (and its t refined,
    /// in the f32 build: see [`Object::refine`]).
    #[inline(always)]
    pub(super) fn nearest(
        self,
        objects: &[Object],
        ray: &Ray,
        numerics: Numerics,
    ) -> Option<Nearest> {
        let hit = self.hit?;
        let object = &objects[self.object];
        let mut hit = object.refine(ray, hit, numerics);
        hit.normal = object.placement.normal_to_world(hit.normal);
        Some(Nearest {
            hit,
            object: self.object,
        })
    }

    /// Tests object `i` and keeps its first hit after `t_min` if it comes before the best so
    /// far (see [`nearer`]).
    #[inline]
    pub(super) fn consider(
        &mut self,
        object: &impl ObjectSpace,
        i: usize,
        ray: &Ray,
        t_min: Real,
        numerics: Numerics,
    ) {
        if let Some(h) = object.hits(ray, numerics).first_after(t_min)
            && nearer(h.t, i, self.t, self.object)
        {
            self.t = h.t;
            self.object = i;
            self.hit = Some(h);
        }
    }
}

/// What a feeler has met so far: whether an opaque object blocks it, and the translucent
/// objects it crosses, kept to multiply their transmissions in scene order.
pub(super) struct Blockers {
    opaque: bool,
    inline: [u32; 8],
    len: usize,
    spill: Vec<u32>,
}

impl Blockers {
    pub(super) fn new() -> Self {
        Self {
            opaque: false,
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

    /// Takes note of object `i`, whose hits with a feeler are `hits`: false when it blocks the
    /// feeler ([`shadow::blocks`]) and is opaque, after which nothing more can change the
    /// share; a translucent object that blocks it is kept for [`Blockers::share`].
    pub(super) fn meet(
        &mut self,
        hits: &Hits,
        i: u32,
        u_min: Real,
        (objects, materials): (&[Object], &[Material]),
    ) -> bool {
        if shadow::blocks(hits, u_min) {
            if materials[objects[i as usize].material].transmission == 0.0 {
                self.opaque = true;
                return false;
            }
            self.push(i);
        }
        true
    }

    /// The share of the light: [`shadow::transmittance`] of the objects met, an opaque one
    /// first (if any), then the translucent ones in increasing object index, each once.
    pub(super) fn share(mut self, objects: &[Object], materials: &[Material]) -> Real {
        let list: &mut [u32] = if self.spill.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spill
        };
        list.sort_unstable();
        let mut last = None;
        let translucent = list.iter().filter(move |&&i| {
            let new = last != Some(i);
            last = Some(i);
            new
        });
        let k_t = |i: &u32| materials[objects[*i as usize].material].transmission;
        let opaque = self.opaque.then_some(0.0);
        shadow::transmittance(opaque.into_iter().chain(translucent.map(k_t)))
    }
}

impl Accelerator {
    /// The nearest hit with t > `t_min` (world normal), exactly as a scan over every object
    /// finds it.
    #[must_use]
    pub fn nearest(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: Real,
        numerics: Numerics,
    ) -> Option<Nearest> {
        self.nearest_among(objects, ray, t_min, numerics, None)
    }

    /// [`Accelerator::nearest`] of a camera ray (t > 0): projection extents test only the
    /// objects whose rectangle holds the image point the ray passes through.
    #[must_use]
    pub fn nearest_camera(
        &self,
        objects: &[Object],
        ray: &Ray,
        numerics: Numerics,
    ) -> Option<Nearest> {
        let pixel = self.extents.as_ref().map(|e| e.pixel_of(ray.dir));
        self.nearest_among(objects, ray, 0.0, numerics, pixel)
    }

    /// The nearest hit; `pixel` names an image pixel whose tile's projection extents hold
    /// every object the ray can hit.
    fn nearest_among(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: Real,
        numerics: Numerics,
        pixel: Option<(u32, u32)>,
    ) -> Option<Nearest> {
        counters::query();
        let mut best = Best::new();
        self.consider_unbounded(objects, ray, t_min, numerics, &mut best);
        if !self.bounded.is_empty() {
            let rb = RayBox::new(ray);
            let test = |c: u32, best: &mut Best| {
                self.consider_candidate(c as usize, &rb, ray, t_min, numerics, best);
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
        best.nearest(objects, ray, numerics)
    }

    /// Tests the objects without a box, which every ray is tested against.
    #[inline]
    pub(super) fn consider_unbounded(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: Real,
        numerics: Numerics,
        best: &mut Best,
    ) {
        for &i in &self.unbounded {
            best.consider(&objects[i as usize], i as usize, ray, t_min, numerics);
        }
    }

    /// Tests bounded candidate `c` (a position in the structure's order) if the ray meets its
    /// box before the best hit so far.
    #[inline]
    pub(super) fn consider_candidate(
        &self,
        c: usize,
        rb: &RayBox,
        ray: &Ray,
        t_min: Real,
        numerics: Numerics,
        best: &mut Best,
    ) {
        if self.boxes[c].hit_between(rb, t_min, best.t) {
            best.consider(
                &self.candidates[c],
                self.bounded[c] as usize,
                ray,
                t_min,
                numerics,
            );
        }
    }

    /// Takes note of the objects without a box for a feeler, as [`Blockers::meet`] does:
    /// false as soon as an opaque one blocks it.
    #[inline(always)]
    pub(super) fn meet_unbounded(
        &self,
        feeler: &Ray,
        u_min: Real,
        numerics: Numerics,
        blockers: &mut Blockers,
        scene: (&[Object], &[Material]),
    ) -> bool {
        // (inlined by force: called, rather than written out in its two callers, it took the
        // shapes' intersection routines out of line and cost the field's render 4% more
        // instructions at N = 10)
        for &i in &self.unbounded {
            let hits = scene.0[i as usize].hits(feeler, numerics);
            if !blockers.meet(&hits, i, u_min, scene) {
                return false;
            }
        }
        true
    }

    /// Takes note of bounded candidate `c` for a feeler that meets its box: false when it
    /// blocks the feeler and is opaque (see [`Blockers::meet`]).
    #[inline]
    pub(super) fn meet_candidate(
        &self,
        c: usize,
        feeler: &Ray,
        u_min: Real,
        numerics: Numerics,
        blockers: &mut Blockers,
        scene: (&[Object], &[Material]),
    ) -> bool {
        let hits = self.candidates[c].hits(feeler, numerics);
        blockers.meet(&hits, self.bounded[c], u_min, scene)
    }

    /// The share of a light that the feeler S(u) = P + (L − P)·u ([`shadow::feeler`]) lets
    /// through to P: [`shadow::transmittance`] of the objects it crosses with u ∈ ]u_min, 1],
    /// in scene order, exactly as testing every object in turn finds them.
    #[must_use]
    pub fn transmittance(
        &self,
        objects: &[Object],
        materials: &[Material],
        feeler: &Ray,
        u_min: Real,
        numerics: Numerics,
    ) -> Real {
        counters::query();
        let mut blockers = Blockers::new();
        let scene = (objects, materials);
        if self.meet_unbounded(feeler, u_min, numerics, &mut blockers, scene)
            && !self.bounded.is_empty()
        {
            let rb = RayBox::new(feeler);
            let test = |c: u32, blockers: &mut Blockers| -> bool {
                let c = c as usize;
                !self.boxes[c].hit_between(&rb, u_min, 1.0)
                    || self.meet_candidate(c, feeler, u_min, numerics, blockers, scene)
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
        }
        blockers.share(objects, materials)
    }
}
