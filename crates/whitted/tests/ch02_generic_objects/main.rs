//! Chapter 2 — generic objects (notes: "Ray Tracing Process", "Generic Objects", "Surface
//! Normals at Intersections"): every shape's miss, graze and two-hit cases with hand-computed
//! t and normals, and the placement M, M⁻¹, (M⁻¹)ᵀ.
//!
//! A test named `ex_NAME_…` checks the exercise NAME of `chapters/formulas.toml` and calls only
//! it and the exercises before it: the shapes' tests call `sphere::intersect`, `cylinder::intersect` …
//! directly (normals in object space), and leave `Object::intersect`, which also carries the
//! normals back to the world (exercise 2.26), to the tests of placed objects.

#[path = "../common/mod.rs"]
mod common;

use common::{TOL, assert_near, assert_vec_eq, centre, render_at, render_both_ways, scene};
use whitted::accel::Accel;
use whitted::ray::Ray;
use whitted::real::{Mat4, Real, Vec3, vec3};
use whitted::render::{Chapter, Options, Tracer};
use whitted::shapes::quadratic::{
    Numerics, Roots, discriminant, solve, solve_with_discriminant, stable_roots,
};
use whitted::shapes::{Hit, Hits, Object, Part, Polyhedron, Shape, nearer};
use whitted::transform::{Placement, Step, rotation_from_z, sin_cos_degrees};

fn ray(e: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(vec3(e[0], e[1], e[2]), vec3(d[0], d[1], d[2]))
}

/// The direction of a (non-zero) normal, to compare the cone's (x, y, 1 − z) with a unit vector.
fn unit(n: Vec3) -> Vec3 {
    n.normalize()
}

/// Asserts the hits' t values and parts; `what` names the ray ("from (0, 0, 5) along −z").
#[track_caller]
fn assert_hits(what: &str, hits: &Hits, expected: &[(Real, Part)]) {
    let got: Vec<(Real, Part)> = hits.as_slice().iter().map(|h| (h.t, h.part)).collect();
    assert_eq!(
        got.len(),
        expected.len(),
        "the hits (t, part) of the ray {what}: computed {got:?}, expected {expected:?}"
    );
    for (i, ((t, part), (te, pe))) in got.iter().zip(expected).enumerate() {
        assert!(
            (t - te).abs() <= 10.0 * TOL,
            "t of hit {i} of the ray {what}: computed {t}, expected {te} (tolerance {:e}; all hits: \
             {got:?})",
            10.0 * TOL
        );
        assert_eq!(
            part, pe,
            "hit {i} of the ray {what}, at t = {t}: its part (all hits: {got:?})"
        );
    }
}

/// Asserts the `entering` flag of each hit, in order; `what` names the ray.
#[track_caller]
fn assert_entering(what: &str, hits: &Hits, expected: &[bool]) {
    let got: Vec<(Real, bool)> = hits.as_slice().iter().map(|h| (h.t, h.entering)).collect();
    let flags: Vec<bool> = got.iter().map(|&(_, e)| e).collect();
    assert_eq!(
        flags, expected,
        "the entering flags of the hits of the ray {what}, (t, entering) = {got:?}"
    );
}

/// Asserts the normal of hit number `i` of `hits`, the hits of the ray `what`; the message
/// names the hit by its t and part.
#[track_caller]
fn assert_normal(what: &str, hits: &Hits, i: usize, expected: Vec3, tol: Real) {
    let h = nth(hits, i, what);
    assert_vec_eq(
        &format!("n of hit {i} (t = {}, {:?}) of the ray {what}", h.t, h.part),
        h.normal,
        expected,
        tol,
    );
}

/// Asserts the direction n/‖n‖ of the normal of hit number `i`, for normals that are not
/// unit (the cone's wall has (x, y, 1 − z)).
#[track_caller]
fn assert_normal_direction(what: &str, hits: &Hits, i: usize, expected: Vec3, tol: Real) {
    let h = nth(hits, i, what);
    assert_vec_eq(
        &format!(
            "n/‖n‖ of hit {i} (t = {}, {:?}, n = {}) of the ray {what}",
            h.t, h.part, h.normal
        ),
        unit(h.normal),
        expected,
        tol,
    );
}

/// The hit number `i` of `hits`, which must be there; `what` names the ray.
#[track_caller]
fn nth(hits: &Hits, i: usize, what: &str) -> Hit {
    *hits.as_slice().get(i).unwrap_or_else(|| {
        panic!(
            "the ray {what} has {} hit(s), expected a hit number {i}: {hits:?}",
            hits.len()
        )
    })
}

// One module per shape, and the placement and the nearest hit around them.
mod cone;
mod cylinder;
mod nearest;
mod placement;
mod plane;
mod polyhedron;
mod quadratic;
mod sphere;
