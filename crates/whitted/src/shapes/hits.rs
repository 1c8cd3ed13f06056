//! What an intersection reports: each [`Hit`] (its t, normal, [`Part`] and side), the [`Hits`]
//! of one ray with one shape in increasing t, and the two helpers the convex shapes build
//! them with: `entering_leaving` for the two roots of a quadratic (the sphere, the cylinder's
//! wall) or a polyhedron's two facets, and `Span`, a stretch of the line clipped by slabs (the
//! cylinder, the cone).
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use crate::real::{Real, Vec3};

/// Which part of a shape a ray hit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Part {
    /// The one surface of a sphere or a plane.
    #[default]
    Surface,
    /// The curved wall of a cylinder or cone.
    Wall,
    /// The cylinder's cap at z = +1.
    TopCap,
    /// The cylinder's cap at z = −1.
    BottomCap,
    /// The cone's base at z = −1.
    Base,
    /// The cone's apex (0, 0, 1), where the wall normal (x, y, 1 − z) vanishes.
    Apex,
    /// Facet number i of a polyhedron, in the order the facets were given.
    Facet(u32),
}

// ANCHOR: ch2_hit
/// One point where a ray meets a surface.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Hit {
    /// The ray parameter: the point is r(t) = e + d·t.
    pub t: Real,
    /// The unit normal pointing out of the object (for a plane: its +z side), in world space
    /// once [`Object::intersect`](super::Object::intersect) returns it. In object space it need
    /// not be unit length.
    pub normal: Vec3,
    /// The part of the shape that was hit.
    pub part: Part,
    /// True where the ray goes from outside to inside (for a plane: hits its front, +z side).
    pub entering: bool,
}
// ANCHOR_END: ch2_hit

/// The hits of one ray with one object, in increasing t (at most two: the shapes are convex).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Hits {
    len: u8,
    items: [Hit; 2],
}

impl Hits {
    /// No hit: the ray misses.
    #[must_use]
    pub const fn none() -> Self {
        Self {
            len: 0,
            items: [
                Hit {
                    t: 0.0,
                    normal: Vec3::ZERO,
                    part: Part::Surface,
                    entering: false,
                },
                Hit {
                    t: 0.0,
                    normal: Vec3::ZERO,
                    part: Part::Surface,
                    entering: false,
                },
            ],
        }
    }

    /// One hit.
    #[must_use]
    pub fn one(hit: Hit) -> Self {
        let mut h = Self::none();
        h.items[0] = hit;
        h.len = 1;
        h
    }

    /// Two hits, entering then leaving; `near.t` must not exceed `far.t`.
    #[must_use]
    pub fn two(near: Hit, far: Hit) -> Self {
        debug_assert!(near.t <= far.t);
        Self {
            len: 2,
            items: [near, far],
        }
    }

    /// The hits as a slice, in increasing t.
    #[must_use]
    pub fn as_slice(&self) -> &[Hit] {
        &self.items[..self.len as usize]
    }

    /// The hits as a mutable slice.
    pub fn as_mut_slice(&mut self) -> &mut [Hit] {
        &mut self.items[..self.len as usize]
    }

    /// How many hits.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len as usize
    }

    /// True when the ray misses.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The first hit with t > `t_min`: the visible one for a ray that starts at t_min (the
    /// hits come in increasing t).
    #[must_use]
    pub fn first_after(&self, t_min: Real) -> Option<Hit> {
        // BEGIN SOLUTION visible_hit
        self.as_slice().iter().copied().find(|h| h.t > t_min)
        // END SOLUTION
    }
}

/// Orders two candidate hits of a convex shape into (entering, leaving), or one hit if they
/// coincide.
pub(crate) fn entering_leaving(mut near: Hit, mut far: Hit) -> Hits {
    if near.t > far.t {
        std::mem::swap(&mut near, &mut far);
    }
    near.entering = true;
    far.entering = false;
    if near.t == far.t {
        Hits::one(near)
    } else {
        Hits::two(near, far)
    }
}

/// A stretch [lo, hi] of the line inside a convex solid, remembering which part of the
/// surface bounds it at each end. Finite shapes are intersections of such stretches (the
/// cylinder: inside the infinite tube *and* between the cap planes), which is how the
/// polyhedron is clipped in the notes and how the robust cylinder and cone are clipped here.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Span {
    pub lo: Real,
    pub lo_part: Part,
    pub hi: Real,
    pub hi_part: Part,
}

impl Span {
    /// The whole line.
    pub const ALL: Span = Span {
        lo: Real::NEG_INFINITY,
        lo_part: Part::Surface,
        hi: Real::INFINITY,
        hi_part: Part::Surface,
    };

    /// The part of the line e_z + d_z·t with z ∈ [z0, z1]: between the plane z = z0 (part `p0`)
    /// and the plane z = z1 (part `p1`). A ray parallel to them is inside for every t or never.
    pub fn slab(ez: Real, dz: Real, z0: Real, p0: Part, z1: Real, p1: Part) -> Option<Span> {
        if dz == 0.0 {
            return (z0 <= ez && ez <= z1).then_some(Span::ALL);
        }
        let t0 = (z0 - ez) / dz;
        let t1 = (z1 - ez) / dz;
        // a tiny d_z may give ±∞ here: still a correct (unbounded) stretch of the line
        Some(if t0 <= t1 {
            Span {
                lo: t0,
                lo_part: p0,
                hi: t1,
                hi_part: p1,
            }
        } else {
            Span {
                lo: t1,
                lo_part: p1,
                hi: t0,
                hi_part: p0,
            }
        })
    }

    /// The common part of two stretches; at equal bounds the second one's part wins.
    pub fn clip(self, other: Span) -> Option<Span> {
        let (lo, lo_part) = if other.lo >= self.lo {
            (other.lo, other.lo_part)
        } else {
            (self.lo, self.lo_part)
        };
        let (hi, hi_part) = if other.hi <= self.hi {
            (other.hi, other.hi_part)
        } else {
            (self.hi, self.hi_part)
        };
        (lo <= hi).then_some(Span {
            lo,
            lo_part,
            hi,
            hi_part,
        })
    }

    /// Its finite ends as hits, with normals computed by `normal(part, t)`.
    pub fn hits(self, normal: impl Fn(Part, Real) -> Vec3) -> Hits {
        let mk = |t: Real, part: Part, entering: bool| Hit {
            t,
            normal: normal(part, t),
            part,
            entering,
        };
        match (self.lo.is_finite(), self.hi.is_finite()) {
            (true, true) if self.lo == self.hi => Hits::one(mk(self.lo, self.lo_part, true)),
            (true, true) => Hits::two(
                mk(self.lo, self.lo_part, true),
                mk(self.hi, self.hi_part, false),
            ),
            (true, false) => Hits::one(mk(self.lo, self.lo_part, true)),
            (false, true) => Hits::one(mk(self.hi, self.hi_part, false)),
            (false, false) => Hits::none(),
        }
    }
}
