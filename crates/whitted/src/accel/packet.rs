//! Packets of up to [`PACKET`] rays walked through the BVH or the octree together: the camera
//! rays of a block of pixels, or their feelers towards one light. Each ray gets exactly its own
//! answer, the one [`Accelerator::nearest`] or [`Accelerator::transmittance`] gives it: the
//! objects are tested, and their hits judged, by the same functions.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use arrayvec::ArrayVec;

use super::aabb::{RayBox, Span, first_meeting};
use super::query::{Best, Blockers};
use super::{Accelerator, Index, PACKET, counters};
use crate::material::Material;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::{Nearest, Numerics, Object};

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
        numerics: Numerics,
        out: &mut [Option<Nearest>],
    ) {
        assert!(rays.len() <= PACKET && out.len() == rays.len());
        if matches!(self.index, Index::List) {
            for (ray, out) in rays.iter().zip(out.iter_mut()) {
                *out = self.nearest(objects, ray, t_min, numerics);
            }
            return;
        }
        let n = rays.len();
        let mut best: [Best; PACKET] = std::array::from_fn(|_| Best::new());
        for (ray, best) in rays.iter().zip(best.iter_mut()) {
            counters::query();
            self.consider_unbounded(objects, ray, t_min, numerics, best);
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
                    self.consider_candidate(c, &boxes[r], &rays[r], t_min, numerics, &mut best[r]);
                    limits[r] = best[r].t;
                }
            });
        }
        for ((out, best), ray) in out.iter_mut().zip(best).zip(rays) {
            *out = best.nearest(objects, ray, numerics);
        }
    }

    /// [`Accelerator::transmittance`] for a packet of at most [`PACKET`] feelers towards the
    /// light at `light` (from the hits of neighbouring pixels, each made by
    /// [`crate::shadow::feeler`]): `out[r]` is the share feeler r lets through, the same as
    /// that function gives, with the BVH or the octree walked once for all of them. Lists
    /// answer feeler by feeler.
    ///
    /// # Panics
    /// If there are more than [`PACKET`] feelers, or `u_min` and `out` are not as long as
    /// `feelers`.
    #[allow(clippy::too_many_arguments)] // the arguments of `transmittance`, the light and `out`
    pub fn transmittance_packet(
        &self,
        objects: &[Object],
        materials: &[Material],
        light: Vec3,
        feelers: &[Ray],
        u_min: &[Real],
        numerics: Numerics,
        out: &mut [Real],
    ) {
        let n = feelers.len();
        assert!(n <= PACKET && u_min.len() == n && out.len() == n);
        if matches!(self.index, Index::List) {
            for r in 0..n {
                out[r] = self.transmittance(objects, materials, &feelers[r], u_min[r], numerics);
            }
            return;
        }
        let mut blockers: [Blockers; PACKET] = std::array::from_fn(|_| Blockers::new());
        // while a feeler is open, where the walk from the light ends (1 − u_min, see below);
        // NaN once an opaque object blocks it (see `walk_packet`)
        let mut limits = [0.0; PACKET];
        let scene = (objects, materials);
        for r in 0..n {
            counters::query();
            limits[r] =
                if self.meet_unbounded(&feelers[r], u_min[r], numerics, &mut blockers[r], scene) {
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
                                numerics,
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
        for (out, blockers) in out.iter_mut().zip(blockers) {
            *out = blockers.share(objects, materials);
        }
    }
}
