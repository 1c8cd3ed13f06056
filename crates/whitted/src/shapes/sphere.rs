//! The generic sphere x² + y² + z² = 1 (notes: "Generic Sphere").
//!
//! With the ray e + d·t: a = |d|², b = e·d, c = |e|² − 1 and a·t² + 2b·t + c = 0;
//! b² − ac < 0 misses, = 0 grazes, > 0 enters and leaves. The normal at P is P itself.
//!
//! The robust variant computes the discriminant as a·(1 − |e − (b/a)·d|²): e − (b/a)·d is the
//! point of the line closest to the centre, so the difference is taken between numbers of the
//! size of the radius, not of |e|² (Ray Tracing Gems, ch. 7). This keeps small spheres far away
//! hittable in f32.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::hits::{Hit, Hits, Part, entering_leaving};
use super::quadratic::{self, Numerics, Roots, solve_with_discriminant};
use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// The sphere's quadratic coefficients (a, b, c) for a·t² + 2b·t + c = 0.
#[must_use]
pub fn coefficients(ray: &Ray) -> (Real, Real, Real) {
    // BEGIN SOLUTION sphere_coefficients
    let (e, d) = (ray.origin, ray.dir);
    (d.dot(d), e.dot(d), e.dot(e) - 1.0) // a = |d|², b = e·d, c = |e|² − 1
    // END SOLUTION
}

/// The robust discriminant b² − ac = a·(1 − |f|²), with f = e − (b/a)·d the point of the line
/// closest to the centre (Ray Tracing Gems, ch. 7): both terms are of the size of the radius.
#[must_use]
pub fn discriminant(ray: &Ray, a: Real, b: Real) -> Real {
    // BEGIN SOLUTION sphere_discriminant
    let f = ray.origin - ray.dir * (b / a);
    a * (1.0 - f.dot(f))
    // END SOLUTION
}

/// The normal at the point P of the generic sphere: P itself.
#[must_use]
pub fn normal(p: Vec3) -> Vec3 {
    // BEGIN SOLUTION sphere_normal
    // on the unit sphere about the origin, the point is its own outward unit normal: n = P
    p
    // END SOLUTION
}

/// Intersects an object-space ray with the unit sphere.
#[must_use]
pub fn intersect(ray: &Ray, numerics: Numerics) -> Hits {
    // BEGIN SOLUTION hit_sphere
    let (a, b, c) = coefficients(ray);
    if a == 0.0 || !a.is_finite() {
        return Hits::none();
    }
    let disc = match numerics {
        Numerics::Textbook => quadratic::discriminant(a, b, c),
        Numerics::Robust => discriminant(ray, a, b),
    };
    let hit = |t: Real| Hit {
        t,
        normal: normal(ray.at(t)),
        part: Part::Surface,
        entering: true,
    };
    match solve_with_discriminant(a, b, c, disc, numerics) {
        Roots::None => Hits::none(),
        Roots::One(t) => Hits::one(hit(t)),
        Roots::Two(t1, t2) => entering_leaving(hit(t1), hit(t2)),
    }
    // END SOLUTION
}
