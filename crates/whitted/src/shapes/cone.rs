//! The generic cone x² + y² = (1 − z)², z ∈ [−1, 1], with its base at z = −1 (notes: "Generic Cone").
//!
//! The apex is (0, 0, 1) and the base a disc of radius 2 at z = −1, where the wall reaches
//! x² + y² = (1 + 1)² (the notes call it a unit circle, which leaves a ring-shaped hole: an
//! erratum). With the ray e + d·t:
//!
//! ```text
//! a = d_x² + d_y² − d_z²
//! b = e_x·d_x + e_y·d_y + d_z·(1 − e_z)
//! c = e_x² + e_y² − (1 − e_z)²
//! ```
//!
//! and a·t² + 2b·t + c = 0. A root is on the wall when z ∈ [−1, 1]; the base is the plane
//! z = −1 inside the circle of radius 2. Normals: (x, y, 1 − z) on the wall and (0, 0, −1) on the
//! base. At the apex the wall normal (x, y, 1 − z) is the zero vector; whitted uses the axis
//! (0, 0, 1) there, so every hit has a finite unit normal.
//!
//! Note that a can be zero (a ray parallel to a generator of the cone: the equation is then
//! linear) or negative (a ray steeper than the wall: the solid is outside the roots). The
//! robust variant handles both by working with the set where a·t² + 2b·t + c ≤ 0 (inside the
//! double cone) and clipping it to the slab z ∈ [−1, 1], which keeps only the lower nappe. It
//! also computes b² − ac as w_x² + w_y² − w_z² with w = d × (e − apex) (see [`discriminant`]),
//! which keeps small cones far away from losing their discriminant to cancellation, and takes
//! the roots in the stable form q/a, c/q.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::cylinder::Extremes;
use super::hits::{Hit, Hits, Part, Span};
use super::quadratic::{Numerics, solve, stable_roots};
use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// The cone's quadratic coefficients (a, b, c) for a·t² + 2b·t + c = 0.
#[must_use]
pub fn coefficients(ray: &Ray) -> (Real, Real, Real) {
    // BEGIN SOLUTION cone_coefficients
    let (e, d) = (ray.origin, ray.dir);
    (
        d.x * d.x + d.y * d.y - d.z * d.z,                 // a
        e.x * d.x + e.y * d.y + d.z * (1.0 - e.z),         // b
        e.x * e.x + e.y * e.y - (1.0 - e.z) * (1.0 - e.z), // c
    )
    // END SOLUTION
}

/// The discriminant b² − ac of the cone's quadratic, computed without squaring distances.
///
/// With u = e − (0, 0, 1) (the origin seen from the apex) the coefficients are quadratic forms
/// of the metric diag(1, 1, −1): a = d·d, b = d·u, c = u·u in that metric. Lagrange's identity
/// then gives b² − ac = w_x² + w_y² − w_z² with w = d × u: the terms are of the size of the
/// cone as seen from e, not of |e|², so a small cone far away keeps its discriminant (the
/// cone's counterpart of the sphere's Ray Tracing Gems form).
#[must_use]
pub fn discriminant(ray: &Ray) -> Real {
    // BEGIN SOLUTION cone_discriminant
    let w = ray.dir.cross(ray.origin - Vec3::Z); // w = d × u
    w.x * w.x + w.y * w.y - w.z * w.z
    // END SOLUTION
}

/// The object-space normal of `part` at the point p.
#[must_use]
pub fn normal(part: Part, p: Vec3) -> Vec3 {
    // BEGIN SOLUTION cone_normal
    match part {
        Part::Base => Vec3::NEG_Z,
        Part::Apex => Vec3::Z,
        _ => {
            let n = Vec3::new(p.x, p.y, 1.0 - p.z); // the wall: (x, y, 1 − z)
            if n == Vec3::ZERO { Vec3::Z } else { n }
        }
    }
    // END SOLUTION
}

/// Intersects an object-space ray with the closed generic cone.
#[must_use]
pub fn intersect(ray: &Ray, numerics: Numerics) -> Hits {
    // BEGIN SOLUTION hit_cone
    // The notes' method: roots kept when z ∈ [−1, 1], and the base plane z = −1 kept when the
    // point lies inside the base circle (radius 2, not the notes' 1).
    fn intersect_textbook(ray: &Ray) -> Hits {
        let (a, b, c) = coefficients(ray);
        let mut found = Extremes::default();
        for t in solve(a, b, c, Numerics::Textbook).iter() {
            let p = ray.at(t);
            if (-1.0..=1.0).contains(&p.z) {
                found.add(Hit {
                    t,
                    normal: normal(Part::Wall, p),
                    part: Part::Wall,
                    entering: true,
                });
            }
        }
        if ray.dir.z != 0.0 {
            let t = (-1.0 - ray.origin.z) / ray.dir.z;
            let p = ray.at(t);
            if t.is_finite() && p.x * p.x + p.y * p.y <= 4.0 {
                // the base disc at z = −1 has radius 1 − (−1) = 2 (the notes say 1: an erratum)
                found.add(Hit {
                    t,
                    normal: Vec3::NEG_Z,
                    part: Part::Base,
                    entering: true,
                });
            }
        }
        found.hits()
    }

    // The set where a·t² + 2b·t + c ≤ 0 (inside the double cone), clipped to the slab
    // z ∈ [−1, 1], which keeps only the lower nappe.
    fn intersect_robust(ray: &Ray) -> Hits {
        let (a, b, c) = coefficients(ray);
        let wall = |lo: Real, hi: Real| Span {
            lo,
            lo_part: Part::Wall,
            hi,
            hi_part: Part::Wall,
        };
        // The stretches of the line inside the double cone (a·t² + 2b·t + c ≤ 0): one, or two
        // half-lines when a < 0.
        let mut pieces: [Option<Span>; 2] = [None, None];
        if a == 0.0 {
            // linear: 2b·t + c ≤ 0
            pieces[0] = if b > 0.0 {
                Some(wall(Real::NEG_INFINITY, -c / (2.0 * b)))
            } else if b < 0.0 {
                Some(wall(-c / (2.0 * b), Real::INFINITY))
            } else if c <= 0.0 {
                Some(Span::ALL)
            } else {
                None
            };
        } else {
            match stable_roots(a, b, c, discriminant(ray)) {
                Some((t1, t2)) if a > 0.0 => pieces[0] = Some(wall(t1, t2)),
                Some((t1, t2)) => {
                    pieces[0] = Some(wall(Real::NEG_INFINITY, t1));
                    pieces[1] = Some(wall(t2, Real::INFINITY));
                }
                // a < 0 without a real root: the whole line is inside the double cone
                None if a < 0.0 => pieces[0] = Some(Span::ALL),
                None => {}
            }
        }
        let Some(slab) = Span::slab(ray.origin.z, ray.dir.z, -1.0, Part::Base, 1.0, Part::Apex)
        else {
            return Hits::none();
        };
        // Within the slab only the lower nappe remains; keep the longest clipped piece.
        let best = pieces
            .into_iter()
            .flatten()
            .filter_map(|p| p.clip(slab))
            .max_by(|p, q| (p.hi - p.lo).total_cmp(&(q.hi - q.lo)));
        match best {
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
