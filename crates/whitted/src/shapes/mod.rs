//! Chapter 2 — generic objects (notes: "Generic Objects", "Surface Normals at Intersections").
//!
//! Every object is a *generic* shape in its own space, placed in the scene by a matrix M
//! (see [`crate::transform`]). To intersect a world ray r(t) = e + d·t with it, the ray is
//! carried into object space with M⁻¹, intersected there with the shape's simple implicit
//! equation, and each hit's normal n′ is carried back with (M⁻¹)ᵀ and renormalised. Because
//! M⁻¹d is not renormalised, the t found in object space is the t of the world ray.
//!
//! | shape | generic form | normal |
//! |---|---|---|
//! | [`Shape::Sphere`] | x² + y² + z² = 1 | (x, y, z) |
//! | [`Shape::Plane`] | z = 0 | (0, 0, 1) |
//! | [`Shape::Cylinder`] | x² + y² = 1, z ∈ [−1, 1], caps at z = ±1 | (x, y, 0); caps (0, 0, ±1) |
//! | [`Shape::Cone`] | x² + y² = (1 − z)², z ∈ [−1, 1], base at z = −1 | (x, y, 1 − z); base (0, 0, −1) |
//! | [`Shape::Polyhedron`] | facets n·P = d, n outward | the facet's n |
//!
//! An intersection reports *every* hit along the whole line, in increasing t, each with its
//! world-space unit normal pointing out of the object, the [`Part`] that was hit and whether
//! the ray enters or leaves there. The generic shapes are convex, so a line meets each at most
//! twice (the plane once).
//!
//! ```toml
//! [[objects]]
//! shape = "cylinder"
//! transform = [ { scale = [0.5, 0.5, 1.0] }, { rotate_x = -90.0 }, { translate = [2.0, 0.0, 0.0] } ]
//! ```
//!
//! Course book: [Chapter 2, generic objects](../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

pub mod cone;
pub mod cylinder;
pub mod plane;
pub mod polyhedron;
pub mod quadratic;
pub mod sphere;

pub use polyhedron::{Facet, Polyhedron};
pub use quadratic::Numerics;

use crate::ray::Ray;
use crate::real::{Mat4, Real, Vec3};
use crate::transform::Placement;

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
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hit {
    /// The ray parameter: the point is r(t) = e + d·t.
    pub t: Real,
    /// The unit normal pointing out of the object (for a plane: its +z side), in world space
    /// once [`Object::intersect`] returns it. In object space it need not be unit length.
    pub normal: Vec3,
    /// The part of the shape that was hit.
    pub part: Part,
    /// True where the ray goes from outside to inside (for a plane: hits its front, +z side).
    pub entering: bool,
}
// ANCHOR_END: ch2_hit

/// The hits of one ray with one object, in increasing t (at most two: the shapes are convex).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
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

/// The nearest hit of a ray over the objects of a scene: the hit (world normal) and the index
/// of the object hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearest {
    /// The hit.
    pub hit: Hit,
    /// Index of the object hit.
    pub object: usize,
}

/// Step 5 of the notes' process: of the hits found, the visible one has the smallest t. True
/// when a hit at `t` on object number `object` comes before the best so far, at `best_t` on
/// `best_object` (∞ and any index when there is none yet). Two hits at the same t go to the
/// object listed first in the scene, so the answer does not depend on the order in which the
/// objects were tested.
#[inline]
#[must_use]
pub fn nearer(t: Real, object: usize, best_t: Real, best_object: usize) -> bool {
    // BEGIN SOLUTION nearer_hit
    t < best_t || (t == best_t && object < best_object)
    // END SOLUTION
}

/// The closed set of generic shapes.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// The unit sphere x² + y² + z² = 1.
    Sphere,
    /// The plane z = 0, normal +z.
    Plane,
    /// The unit cylinder x² + y² = 1 for z ∈ [−1, 1], closed by caps at z = ±1.
    Cylinder,
    /// The cone x² + y² = (1 − z)² for z ∈ [−1, 1]: apex (0, 0, 1), base of radius 2 at z = −1.
    Cone,
    /// A convex polyhedron: the intersection of half-spaces n·P ≤ d.
    Polyhedron(Polyhedron),
}

impl Shape {
    // ANCHOR: ch2_intersect_placed_sig
    /// The hits of a world ray with the shape placed by a matrix M whose inverse is `inv`: the
    /// ray carried into object space, M⁻¹r(t) = M⁻¹e + M⁻¹d·t ([`Ray::transformed`]), and
    /// intersected with the generic shape. t is the world ray's; the normals stay in object
    /// space (carry them back with [`Placement::normal_to_world`]). Every ray–object test of
    /// every render path goes through here: [`Object::intersect`] and the acceleration
    /// structures, which keep M⁻¹ and the shape side by side for speed.
    #[inline]
    #[must_use]
    pub fn intersect_placed(&self, inv: &Mat4, ray: &Ray, numerics: Numerics) -> Hits {
        // ANCHOR_END: ch2_intersect_placed_sig
        // BEGIN SOLUTION hit_placed_shape
        self.intersect_local(&ray.transformed(inv), numerics)
        // END SOLUTION
    }

    // ANCHOR: ch2_intersect_local
    /// Intersects an object-space ray with the generic shape. Normals are in object space.
    #[must_use]
    pub fn intersect_local(&self, ray: &Ray, numerics: Numerics) -> Hits {
        match self {
            Shape::Sphere => sphere::intersect(ray, numerics),
            Shape::Plane => plane::intersect(ray),
            Shape::Cylinder => cylinder::intersect(ray, numerics),
            Shape::Cone => cone::intersect(ray, numerics),
            Shape::Polyhedron(p) => p.intersect(ray),
        }
    }
    // ANCHOR_END: ch2_intersect_local

    /// The shape's name as the scene file writes it.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Sphere => "sphere",
            Shape::Plane => "plane",
            Shape::Cylinder => "cylinder",
            Shape::Cone => "cone",
            Shape::Polyhedron(_) => "polyhedron",
        }
    }

    /// True for shapes that enclose a volume (everything but the plane).
    #[must_use]
    pub fn is_closed(&self) -> bool {
        !matches!(self, Shape::Plane)
    }
}

/// A generic shape placed in the scene, with the index of its material.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The generic shape.
    pub shape: Shape,
    /// Its placement M (with M⁻¹ and (M⁻¹)ᵀ cached).
    pub placement: Placement,
    /// Index into the scene's materials.
    pub material: usize,
}

impl Object {
    /// A shape placed by `placement` with material 0.
    #[must_use]
    pub fn new(shape: Shape, placement: Placement) -> Self {
        Self {
            shape,
            placement,
            material: 0,
        }
    }

    // ANCHOR: ch2_object_intersect
    /// Intersects a world ray: carries it into object space with M⁻¹ (direction not
    /// renormalised, so t is shared), intersects the generic shape, and carries each normal
    /// back with (M⁻¹)ᵀ, renormalised.
    #[must_use]
    pub fn intersect(&self, ray: &Ray, numerics: Numerics) -> Hits {
        let mut hits = self.intersect_object_space(ray, numerics);
        for hit in hits.as_mut_slice() {
            hit.normal = self.placement.normal_to_world(hit.normal);
        }
        hits
    }
    // ANCHOR_END: ch2_object_intersect

    /// The hits of a world ray with the object, normals left in object space: the first half
    /// of [`Object::intersect`] (see [`Shape::intersect_placed`]).
    #[inline]
    #[must_use]
    pub fn intersect_object_space(&self, ray: &Ray, numerics: Numerics) -> Hits {
        self.shape
            .intersect_placed(self.placement.inv(), ray, numerics)
    }
}

impl Object {
    /// The hit point `p` (computed as e + d·t, so off the surface by an error that grows with
    /// the distance the ray travelled) moved back onto the surface, with a componentwise bound
    /// on the error of the result.
    ///
    /// In object space the point is projected onto the part that was hit (the sphere: P/|P|;
    /// the plane and the caps: z set to its value; the cylinder wall: (x, y) scaled to radius 1;
    /// the cone wall: the nearest point of the generator through P; a facet: P − n·(n·P − d)),
    /// which costs a few roundings of the size of the object-space point. M then carries it
    /// back, adding γ₃·|M|·(|q|, 1). The bound also counts the round trip a spawned ray makes
    /// through M⁻¹ when it is intersected again: |M|·|M⁻¹|·(|P|, 1). Neither term depends on
    /// how far the ray came from, which is what lets a far camera keep its offsets small
    /// (compare Wächter & Binder, Ray Tracing Gems ch. 6, and pbrt-v4's reprojection of sphere
    /// hits).
    #[must_use]
    pub fn reproject(&self, p: Vec3, part: Part) -> (Vec3, Vec3) {
        let q = self
            .shape
            .project(self.placement.inv().transform_point3(p), part);
        if !q.is_finite() {
            return (p, Vec3::splat(Real::INFINITY));
        }
        let refined = self.placement.m().transform_point3(q);
        let m = abs_matrix(self.placement.m());
        let inv = abs_matrix(self.placement.inv());
        let carried = m.transform_point3(q.abs());
        let round_trip = m.transform_point3(inv.transform_point3(p.abs()));
        (refined, carried + round_trip)
    }
}

/// The matrix of absolute values |M|, for error bounds (‖M·v‖ ≤ |M|·|v| componentwise).
fn abs_matrix(m: &crate::real::Mat4) -> crate::real::Mat4 {
    crate::real::Mat4::from_cols(
        m.x_axis.abs(),
        m.y_axis.abs(),
        m.z_axis.abs(),
        m.w_axis.abs(),
    )
}

impl Shape {
    /// The point of the generic surface's `part` nearest to (or, for the walls, radially
    /// across from) the object-space point q.
    #[must_use]
    pub fn project(&self, q: Vec3, part: Part) -> Vec3 {
        let radial = |q: Vec3, radius: Real| {
            let r = q.truncate().length();
            if r > 0.0 {
                let s = radius / r;
                Vec3::new(q.x * s, q.y * s, q.z)
            } else {
                q
            }
        };
        match (self, part) {
            (Shape::Sphere, _) => crate::numeric::normalize(q),
            (Shape::Plane, _) => Vec3::new(q.x, q.y, 0.0),
            (Shape::Cylinder, Part::TopCap) => Vec3::new(q.x, q.y, 1.0),
            (Shape::Cylinder, Part::BottomCap) => Vec3::new(q.x, q.y, -1.0),
            (Shape::Cylinder, _) => radial(q, 1.0),
            (Shape::Cone, Part::Base) => Vec3::new(q.x, q.y, -1.0),
            (Shape::Cone, Part::Apex) => Vec3::Z,
            (Shape::Cone, _) => {
                // in the (r, z) half-plane the wall is the line r + z = 1: step back along
                // its normal (1, 1)/√2 by k = (r + z − 1)/2 on each coordinate
                let r = q.truncate().length();
                let k = (r + q.z - 1.0) / 2.0;
                radial(Vec3::new(q.x, q.y, q.z - k), (r - k).max(0.0))
            }
            (Shape::Polyhedron(poly), Part::Facet(i)) => match poly.facets().get(i as usize) {
                Some(f) => q - f.normal() * (f.normal().dot(q) - f.d()),
                None => q,
            },
            (Shape::Polyhedron(_), _) => q,
        }
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
