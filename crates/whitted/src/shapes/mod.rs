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
//! the ray enters or leaves there ([`hits`]). The generic shapes are convex, so a line meets
//! each at most twice (the plane once). In the f32 build the hit a ray shows is refined in f64
//! where f32 cannot hold it, a huge object seen from close by ([`refine`]).
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
pub mod hits;
pub mod plane;
pub mod polyhedron;
pub mod quadratic;
pub mod refine;
pub mod sphere;

pub use hits::{Hit, Hits, Part};
pub use polyhedron::{Facet, Polyhedron};
pub use quadratic::Numerics;

use crate::ray::Ray;
use crate::real::{Mat4, Real, Vec3};
use crate::transform::Placement;
use refine::Surface;

/// The nearest hit of a ray over the objects of a scene: the hit (world normal) and the index
/// of the object hit.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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

    /// The generic equation of the shape's `part`, which [`refine::refine`] evaluates (in the
    /// f32 build); `None` where there is nothing to refine: the plane z = 0, whose t =
    /// −e′_z/d′_z subtracts nothing, a point (the cone's apex), a part the shape does not
    /// have.
    #[must_use]
    pub fn surface(&self, part: Part) -> Option<Surface> {
        match (self, part) {
            (Shape::Sphere, _) => Some(Surface::Sphere),
            // z = 0 subtracts nothing: t = −e′_z/d′_z keeps every digit (no refinement)
            (Shape::Plane, _) => None,
            (Shape::Cylinder, Part::TopCap) => Some(Surface::Level(1.0)),
            (Shape::Cylinder, Part::BottomCap) => Some(Surface::Level(-1.0)),
            (Shape::Cylinder, _) => Some(Surface::Tube),
            (Shape::Cone, Part::Base) => Some(Surface::Level(-1.0)),
            (Shape::Cone, Part::Apex) => None,
            (Shape::Cone, _) => Some(Surface::Cone),
            (Shape::Polyhedron(poly), Part::Facet(i)) => poly
                .facets()
                .get(i as usize)
                .map(|f| Surface::Facet(f.normal(), f.d())),
            (Shape::Polyhedron(_), _) => None,
        }
    }

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
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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

    /// The visible hit of a world ray with the object (found by
    /// [`Object::intersect_object_space`], normal still in object space) as the road shades
    /// it: in the f32 build its t refined by one Newton step in f64 where f32 has lost digits
    /// that matter ([`refine::refine`]), so that a huge object seen from close by is hit where
    /// it is; in the f64 build the hit as it is. Every query refines the one hit it answers, as it carries its normal to the
    /// world, and nothing else: the other hits, and those of feelers, stay as the formulas
    /// found them.
    #[inline]
    #[must_use]
    pub fn refine(&self, ray: &Ray, mut hit: Hit, numerics: Numerics) -> Hit {
        let surface = || self.shape.surface(hit.part);
        hit.t = refine::refine(hit.t, &self.placement, ray, numerics, surface);
        hit
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
