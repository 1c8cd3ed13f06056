//! The generic cylinder x² + y² = 1, z ∈ [−1, 1], with caps at z = ±1 (notes: "Generic Cylinder").
//!
//! The wall: a = d_x² + d_y², b = e_x·d_x + e_y·d_y, c = e_x² + e_y² − 1, and a·t² + 2b·t + c = 0.
//! The notes keep a root when z = e_z + d_z·t ∈ [−1, 1] and test the cap planes z = ±1 for a
//! point inside the unit circle. The notes' cylinder is infinite; whitted's is finite and
//! closed, so a ray along the axis (a = 0) enters through one cap and leaves through the other.
//!
//! Normals: (x, y, 0) on the wall, (0, 0, 1) on the top cap and (0, 0, −1) on the bottom cap.
//!
//! The robust variant clips the line twice, as the notes clip a polyhedron: the stretch inside
//! the infinite tube (between the two roots), then the stretch between the cap planes. The
//! answer is their common part, so a ray through a rim can never slip between a wall test and
//! a cap test, and a = 0 needs no special case.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::hits::{Hit, Hits, Part, Span, entering_leaving};
use super::quadratic::{Numerics, solve, stable_roots};
use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// The wall's quadratic coefficients (a, b, c) for a·t² + 2b·t + c = 0.
#[must_use]
pub fn coefficients(ray: &Ray) -> (Real, Real, Real) {
    // BEGIN SOLUTION cylinder_coefficients
    let (e, d) = (ray.origin, ray.dir);
    (
        d.x * d.x + d.y * d.y,       // a = d_x² + d_y²
        e.x * d.x + e.y * d.y,       // b = e_x d_x + e_y d_y
        e.x * e.x + e.y * e.y - 1.0, // c = e_x² + e_y² − 1
    )
    // END SOLUTION
}

/// The wall's discriminant b² − ac, computed as a·(1 − |f|²) with f = (e − (b/a)·d) in x and
/// y: the point of the line's shadow on the z = 0 plane closest to the axis. The difference is
/// taken between numbers of the size of the radius, not of |e|², as for the sphere.
#[must_use]
pub fn discriminant(ray: &Ray, a: Real, b: Real) -> Real {
    // BEGIN SOLUTION cylinder_discriminant
    let f = ray.origin.truncate() - ray.dir.truncate() * (b / a);
    a * (1.0 - f.dot(f))
    // END SOLUTION
}

/// The object-space normal of `part` at the point p.
#[must_use]
pub fn normal(part: Part, p: Vec3) -> Vec3 {
    // BEGIN SOLUTION cylinder_normal
    match part {
        Part::TopCap => Vec3::Z,
        Part::BottomCap => Vec3::NEG_Z,
        _ => Vec3::new(p.x, p.y, 0.0), // the wall: (x, y, 0)
    }
    // END SOLUTION
}

/// Intersects an object-space ray with the closed unit cylinder.
#[must_use]
pub fn intersect(ray: &Ray, numerics: Numerics) -> Hits {
    // BEGIN SOLUTION hit_cylinder
    // The notes' method as written: roots of the wall quadratic kept when z ∈ [−1, 1], cap
    // planes kept when the point lies inside the unit circle.
    fn intersect_textbook(ray: &Ray) -> Hits {
        let (a, b, c) = coefficients(ray);
        let mut found = Extremes::default();
        let mut keep = |t: Real, part: Part| {
            let p = ray.at(t);
            found.add(Hit {
                t,
                normal: normal(part, p),
                part,
                entering: true,
            });
        };
        for t in solve(a, b, c, Numerics::Textbook).iter() {
            let z = ray.origin.z + ray.dir.z * t;
            if (-1.0..=1.0).contains(&z) {
                keep(t, Part::Wall);
            }
        }
        if ray.dir.z != 0.0 {
            for (z, part) in [(-1.0, Part::BottomCap), (1.0, Part::TopCap)] {
                let t = (z - ray.origin.z) / ray.dir.z;
                let p = ray.at(t);
                if t.is_finite() && p.x * p.x + p.y * p.y <= 1.0 {
                    keep(t, part);
                }
            }
        }
        found.hits()
    }

    // The line clipped twice, as the notes clip a polyhedron: the stretch inside the infinite
    // tube, then the stretch between the cap planes.
    fn intersect_robust(ray: &Ray) -> Hits {
        let (a, b, c) = coefficients(ray);
        let tube = if a == 0.0 {
            // parallel to the axis: inside the tube for every t, or never
            if c <= 0.0 {
                Span::ALL
            } else {
                return Hits::none();
            }
        } else {
            match stable_roots(a, b, c, discriminant(ray, a, b)) {
                Some((t1, t2)) => Span {
                    lo: t1,
                    lo_part: Part::Wall,
                    hi: t2,
                    hi_part: Part::Wall,
                },
                None => return Hits::none(),
            }
        };
        let slab = Span::slab(
            ray.origin.z,
            ray.dir.z,
            -1.0,
            Part::BottomCap,
            1.0,
            Part::TopCap,
        );
        match slab.and_then(|s| tube.clip(s)) {
            Some(span) => span.hits(|part, t| normal(part, ray.at(t))),
            None => Hits::none(),
        }
    }

    match numerics {
        Numerics::Textbook => intersect_textbook(ray),
        Numerics::Robust => intersect_robust(ray),
    }
    // END SOLUTION
}

/// For a convex shape: the first and last of the candidate hits, kept as they come (no
/// allocation); duplicates at rims collapse. At equal t the first candidate stays nearest and
/// the last one farthest.
#[derive(Default)]
pub(crate) struct Extremes {
    near: Option<Hit>,
    far: Option<Hit>,
}

impl Extremes {
    /// Takes one candidate hit.
    pub(crate) fn add(&mut self, hit: Hit) {
        if self.near.is_none_or(|n| hit.t < n.t) {
            self.near = Some(hit);
        }
        if self.far.is_none_or(|f| hit.t >= f.t) {
            self.far = Some(hit);
        }
    }

    /// The entering and leaving hits (one if they coincide, none without candidates).
    pub(crate) fn hits(self) -> Hits {
        match (self.near, self.far) {
            (Some(n), Some(f)) => entering_leaving(n, f),
            _ => Hits::none(),
        }
    }
}
