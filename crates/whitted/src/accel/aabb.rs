//! Bounding boxes (notes: "Computational Aspects", item 1).
//!
//! Every generic shape but the plane fits in a known box in its own space: the sphere and the
//! cylinder in [−1, 1]³, the cone x² + y² = (1 − z)², z ∈ [−1, 1] in [−2, 2]² × [−1, 1], a
//! polyhedron in the box of its vertices. Placing the
//! object by M carries that box into the world; the world box of the placed object is the box
//! around the eight carried corners (for a sphere, the exact box of the ellipsoid). A ray that
//! misses the box cannot hit the object, and a slab test costs a few multiplications where an
//! object test costs a transform and a square root.
//!
//! The boxes are *conservative*: they are padded by more than the rounding error of any hit
//! the object test can report, so skipping an object whose box is missed never changes an
//! image (the tests compare every accelerated image with the brute-force one, bit for bit).
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use crate::ray::Ray;
use crate::real::{Mat4, Real, Vec3};
use crate::shapes::{Object, Polyhedron, Shape};

/// An axis-aligned box [min, max].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The lower corner.
    pub min: Vec3,
    /// The upper corner.
    pub max: Vec3,
}

/// Relative padding of a box, in units of its size: covers the error of the square root in a
/// grazing hit (about √ε of the object's size).
const PAD_SIZE: Real = 64.0
    * if cfg!(feature = "f32") {
        3.5e-4
    } else {
        1.5e-8
    };
/// Padding in units of the coordinates' magnitude: covers rounding in M⁻¹ and in r(t).
const PAD_MAGNITUDE: Real = 1024.0 * Real::EPSILON;
/// Relative slack of a slab test's interval (pbrt's 1 + 2γ₃, generously): a computed
/// crossing (bound − e)·(1/d) is within three roundings, 3ε relative, of the exact one.
pub(crate) const SLACK: Real = 16.0 * Real::EPSILON;

/// A ray prepared for slab tests: origin and reciprocal direction.
#[derive(Clone, Copy, Debug)]
pub struct RayBox {
    /// The origin e.
    pub(crate) origin: Vec3,
    /// 1/d, componentwise, held within ±[`Real::MAX`]: where d has a zero component it is
    /// ±MAX (the sign of the zero) instead of ±∞, so that (bound − e)·(1/d) is never 0·∞.
    pub(crate) inv_dir: Vec3,
    /// Per axis: the ray moves down it (1/d < 0), so it meets a box's upper side first.
    pub(crate) down: [bool; 3],
}

impl RayBox {
    /// 1/d, componentwise, held within ±[`Real::MAX`] (see the field).
    #[must_use]
    pub fn inv_dir(&self) -> Vec3 {
        self.inv_dir
    }

    /// Prepares `ray` for slab tests.
    #[inline]
    #[must_use]
    pub fn new(ray: &Ray) -> Self {
        let r = ray.dir.recip();
        let big = Vec3::splat(Real::MAX);
        let inv_dir = r.max(-big).min(big);
        Self {
            origin: ray.origin,
            inv_dir,
            down: [inv_dir.x < 0.0, inv_dir.y < 0.0, inv_dir.z < 0.0],
        }
    }
}

/// The smaller of two numbers that are never NaN: one `minsd`, where `Real::min` also has
/// to look for a NaN.
#[inline(always)]
pub(crate) fn lesser(a: Real, b: Real) -> Real {
    if a < b { a } else { b }
}

/// The larger of two numbers that are never NaN.
#[inline(always)]
pub(crate) fn greater(a: Real, b: Real) -> Real {
    if a > b { a } else { b }
}

/// Widens t a little towards +∞: the bound used when comparing an entry parameter with the
/// nearest hit found so far.
#[inline]
#[must_use]
pub(crate) fn widen(t: Real) -> Real {
    t + t.abs() * SLACK
}

impl Aabb {
    /// The empty box (min = +∞, max = −∞): the neutral element of [`Aabb::union`].
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::splat(Real::INFINITY),
        max: Vec3::splat(Real::NEG_INFINITY),
    };

    /// The generic box [−1, 1]³ of the sphere and the cylinder (the cone's is wider:
    /// [−2, 2]² × [−1, 1], see [`generic_bounds`]).
    pub const GENERIC: Aabb = Aabb {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };

    /// The smallest box holding both.
    #[inline]
    #[must_use]
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    /// The box grown to hold the point p.
    #[inline]
    #[must_use]
    pub fn with_point(&self, p: Vec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// True when min ≤ max on every axis and every bound is finite.
    #[must_use]
    pub fn is_finite_nonempty(&self) -> bool {
        self.min.is_finite() && self.max.is_finite() && self.min.cmple(self.max).all()
    }

    /// The centre of the box.
    #[inline]
    #[must_use]
    pub fn centre(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Half the surface area, the measure the SAH weighs children by (0 for an empty box).
    #[must_use]
    pub fn half_area(&self) -> Real {
        let e = (self.max - self.min).max(Vec3::ZERO);
        e.x * e.y + e.y * e.z + e.z * e.x
    }

    /// True when the two closed boxes share a point.
    #[inline]
    #[must_use]
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.min.cmple(o.max).all() && o.min.cmple(self.max).all()
    }

    /// The box grown on every side by a margin covering rounding error (see the module docs).
    #[must_use]
    pub fn padded(&self) -> Aabb {
        let size = (self.max - self.min).max_element();
        let magnitude = self.min.abs().max(self.max.abs()).max_element();
        let pad = Vec3::splat(size * PAD_SIZE + magnitude * PAD_MAGNITUDE + Real::MIN_POSITIVE);
        Aabb {
            min: self.min - pad,
            max: self.max + pad,
        }
    }

    /// The box around the eight corners of this (object-space) box carried by M.
    #[must_use]
    pub fn transformed(&self, m: &Mat4) -> Aabb {
        let mut out = Aabb::EMPTY;
        for i in 0..8 {
            let corner = Vec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            out = out.with_point(m.transform_point3(corner));
        }
        out
    }

    /// The parameters (t_enter, t_exit) where the ray crosses the box, by the slab method:
    /// on each axis t = (bound − e)/d, the entry is the largest near crossing and the exit the
    /// smallest far one; the interval is empty (t_enter > t_exit) when the ray misses.
    ///
    /// Rounding is allowed for on the exit only, which is moved towards +∞ by a relative
    /// slack (16ε). The entry is left as computed, within 3ε of the exact one: a caller
    /// compares it with a *widened* limit (`widen`), and the widened exit is at least the
    /// computed entry whenever the exact entry is at most the exact exit. So a box the exact
    /// ray meets is always met.
    #[inline]
    #[must_use]
    pub fn slabs(&self, ray: &RayBox) -> (Real, Real) {
        super::counters::box_test();
        // No NaN can arise: 1/d is finite (see [`RayBox`]) and the bounds are finite, so a
        // product is 0·finite or finite·finite (at worst ±∞ by overflow, never 0·∞).
        let (o, inv) = (ray.origin, ray.inv_dir);
        // The crossings of the lower and the upper side of each axis; the near one is the
        // smaller (the lower side's, or the upper one's going down). Rounding is monotone, so
        // the smaller of the two is exactly the near side's crossing, with one `minsd`.
        let lo = (self.min - o) * inv;
        let hi = (self.max - o) * inv;
        let enter = greater(
            greater(lesser(lo.x, hi.x), lesser(lo.y, hi.y)),
            lesser(lo.z, hi.z),
        );
        let exit = lesser(
            lesser(greater(lo.x, hi.x), greater(lo.y, hi.y)),
            greater(lo.z, hi.z),
        );
        (enter, exit + exit.abs() * SLACK)
    }

    /// True when the ray meets the box somewhere in [lo, hi] (hi widened by the slack).
    #[inline]
    #[must_use]
    pub fn hit_between(&self, ray: &RayBox, lo: Real, hi: Real) -> bool {
        let (enter, exit) = self.slabs(ray);
        enter <= exit && exit >= lo && enter <= widen(hi)
    }
}

/// The rays of a packet taken together (Wald, Boulos and Shirley's interval test): per
/// axis, the range of their origins and of their 1/d, when all go the same way along it.
/// A box that no ray of these ranges could meet is missed by every ray of the packet, and
/// one test says so instead of one a ray.
pub(crate) struct Span {
    origin: [(Real, Real); 3],
    inv_dir: [(Real, Real); 3],
    down: [bool; 3],
    /// The smallest t_min and the largest widened limit of the packet.
    t_min: Real,
    limit: Real,
}

impl Span {
    /// The span of `rays`, or `None` if they do not all go the same way along every axis.
    #[must_use]
    pub(crate) fn of(rays: &[RayBox], t_min: &[Real], limits: &[Real]) -> Option<Self> {
        let first = rays.first()?;
        let mut span = Span {
            origin: [(Real::INFINITY, Real::NEG_INFINITY); 3],
            inv_dir: [(Real::INFINITY, Real::NEG_INFINITY); 3],
            down: first.down,
            t_min: Real::INFINITY,
            limit: Real::NEG_INFINITY,
        };
        for (r, ray) in rays.iter().enumerate() {
            if ray.down != span.down {
                return None;
            }
            let o = [ray.origin.x, ray.origin.y, ray.origin.z];
            let i = [ray.inv_dir.x, ray.inv_dir.y, ray.inv_dir.z];
            for a in 0..3 {
                span.origin[a] = (
                    lesser(span.origin[a].0, o[a]),
                    greater(span.origin[a].1, o[a]),
                );
                span.inv_dir[a] = (
                    lesser(span.inv_dir[a].0, i[a]),
                    greater(span.inv_dir[a].1, i[a]),
                );
            }
            span.t_min = lesser(span.t_min, t_min[r]);
            // a NaN limit (a finished ray) meets nothing: it leaves the span's limit as it is
            if limits[r] >= Real::NEG_INFINITY {
                span.limit = greater(span.limit, widen(limits[r]));
            }
        }
        Some(span)
    }

    /// True when no ray of the span can meet `b` between t_min and the limit. Each bound is
    /// computed as [`Aabb::slabs`] computes a crossing, then moved outwards by the slack, so
    /// the test errs only towards opening the box.
    #[inline]
    #[must_use]
    pub(crate) fn misses(&self, b: &Aabb) -> bool {
        super::counters::box_test();
        let (lo, hi) = ([b.min.x, b.min.y, b.min.z], [b.max.x, b.max.y, b.max.z]);
        let mut enter = Real::NEG_INFINITY;
        let mut exit = Real::INFINITY;
        for a in 0..3 {
            let (near, far) = if self.down[a] {
                (hi[a], lo[a])
            } else {
                (lo[a], hi[a])
            };
            let (olo, ohi) = self.origin[a];
            // (bound − e)·(1/d) over e and 1/d in their ranges: the smallest near crossing
            // and the largest far one (1/d has one sign along the axis)
            let (ilo, ihi) = self.inv_dir[a];
            let (n, f) = if self.down[a] {
                // 1/d < 0: the product falls as (bound − e) grows
                let dn = near - olo;
                let df = far - ohi;
                (
                    dn * if dn >= 0.0 { ilo } else { ihi },
                    df * if df >= 0.0 { ihi } else { ilo },
                )
            } else {
                let dn = near - ohi;
                let df = far - olo;
                (
                    dn * if dn >= 0.0 { ilo } else { ihi },
                    df * if df >= 0.0 { ihi } else { ilo },
                )
            };
            enter = greater(enter, n);
            exit = lesser(exit, f);
        }
        let enter = enter - enter.abs() * SLACK;
        let exit = exit + exit.abs() * SLACK;
        enter > exit || exit < self.t_min || enter > self.limit
    }
}

/// The first ray of a packet, from index `from` on, that meets `b` after its t_min and not
/// beyond its limit. The packet's [`Span`] may turn the box down for every ray at once;
/// otherwise the rays are tried one by one. (Trying ray `from` before the span, since it
/// met the parent, was measured: no faster with the BVH, and slower with the octree, whose
/// rays miss most of a cell's eight octants.)
#[inline]
pub(crate) fn first_meeting(
    b: &Aabb,
    rays: &[RayBox],
    t_min: &[Real],
    limits: &[Real],
    span: Option<&Span>,
    from: usize,
) -> Option<usize> {
    if span.is_some_and(|s| s.misses(b)) {
        return None;
    }
    (from..rays.len()).find(|&r| b.hit_between(&rays[r], t_min[r], limits[r]))
}

/// The generic (object-space) bounds of a shape, or `None` for a shape without finite bounds
/// (the plane, or a polyhedron whose facets leave it open).
#[must_use]
pub fn generic_bounds(shape: &Shape) -> Option<Aabb> {
    match shape {
        Shape::Plane => None,
        Shape::Sphere | Shape::Cylinder => Some(Aabb::GENERIC),
        // the wall x² + y² = (1 − z)² reaches radius 2 at z = −1: the box must hold what the
        // intersection routine can return, whatever the base disc's radius
        Shape::Cone => Some(Aabb {
            min: Vec3::new(-2.0, -2.0, -1.0),
            max: Vec3::new(2.0, 2.0, 1.0),
        }),
        Shape::Polyhedron(p) => polyhedron_bounds(p),
    }
}

/// The padded world box of a placed object, or `None` if it is unbounded (it is then tested
/// against every ray, outside any hierarchy).
#[must_use]
pub fn world_bounds(object: &Object) -> Option<Aabb> {
    let m = &object.placement.m();
    let b = match object.shape {
        // the exact box of the ellipsoid M·(unit sphere): half-extent on axis k is |row k of M|
        Shape::Sphere => {
            let c = m.transform_point3(Vec3::ZERO);
            let rows = m.transpose();
            let half = Vec3::new(
                rows.x_axis.truncate().length(),
                rows.y_axis.truncate().length(),
                rows.z_axis.truncate().length(),
            );
            Aabb {
                min: c - half,
                max: c + half,
            }
        }
        _ => generic_bounds(&object.shape)?.transformed(m),
    };
    let b = b.padded();
    b.is_finite_nonempty().then_some(b)
}

/// The box of a convex polyhedron's vertices ([`Polyhedron::vertices`]). Returns `None` when
/// the facets do not close a bounded solid with an inside ([`Polyhedron::check`]): such a
/// polyhedron is treated as unbounded, which is always safe.
#[must_use]
pub fn polyhedron_bounds(p: &Polyhedron) -> Option<Aabb> {
    p.check().ok()?;
    let b = p
        .vertices()
        .into_iter()
        .fold(Aabb::EMPTY, |b, v| b.with_point(v));
    b.is_finite_nonempty().then_some(b)
}
