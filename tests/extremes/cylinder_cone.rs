//! Cylinder and cone: a ≈ 0, rims, apex, a small cone far away.

use super::sphere::far_sphere_is_right;
use super::{all_finite, f, hits, placed, tol};
use whitted::ray::Ray;
use whitted::real::vec3;
use whitted::shapes::{Hit, Numerics, Object, Part, Shape};
use whitted::transform::{Placement, Step};

/// The entry point of a ray through the rim point (cos φ, sin φ, 1) of the generic cylinder,
/// heading for an inner point: (ray, t of the rim).
fn rim_ray(phi: f64) -> (Ray, f64) {
    let rim = vec3(phi.cos(), phi.sin(), 1.0);
    let inner = vec3(-0.3 * phi.cos(), 0.2 * phi.sin(), -0.4);
    let dir = inner - rim;
    (Ray::new(rim - dir * 2.0, dir), 2.0)
}

/// Notes, "Generic Cylinder": a wall root is kept when z ∈ [−1, 1] and a cap point when it
/// lies inside the unit circle. A ray entering exactly through the rim is at z ≈ 1 *and*
/// x² + y² ≈ 1, and rounding can put it outside both tests: the ray then slips in with a single
/// (leaving) hit. Clipping the line to the tube and to the slab between the caps cannot lose it.
#[test]
fn ray_through_a_cylinder_rim_never_slips_between_wall_and_cap() {
    let cylinder = Object::new(Shape::Cylinder, Placement::identity());
    let n = 2000;
    let mut textbook_wrong = 0;
    for i in 0..n {
        let phi = std::f64::consts::TAU * i as f64 / n as f64;
        let (ray, t_rim) = rim_ray(phi);
        let robust = hits(&cylinder, &ray, Numerics::Robust);
        assert_eq!(robust.len(), 2, "φ = {phi}: {robust:?}");
        assert!(
            (f(robust[0].t) - t_rim).abs() < 1e-3,
            "φ = {phi}: {robust:?}"
        );
        assert!(robust[0].entering && !robust[1].entering);
        let textbook = hits(&cylinder, &ray, Numerics::Textbook);
        if textbook.len() != 2 || (f(textbook[0].t) - t_rim).abs() > 1e-3 {
            textbook_wrong += 1;
        }
    }
    assert!(
        textbook_wrong > 0,
        "the textbook rim tests were expected to let some rays slip in"
    );
}

/// Notes, "Generic Cylinder", a = d_x² + d_y² = 0: a ray along the axis meets no wall; the
/// closed cylinder is entered through one cap and left through the other. Nearly along the
/// axis (a ≈ 0) the same holds, and nothing non-finite leaks out.
#[test]
fn ray_along_the_cylinder_axis_crosses_both_caps() {
    let cylinder = Object::new(Shape::Cylinder, Placement::identity());
    for tilt in [0.0, 1e-30, 1e-12, 1e-6] {
        let ray = Ray::new(vec3(0.5, 0.0, -5.0), vec3(tilt, 0.0, 1.0));
        let hs = hits(&cylinder, &ray, Numerics::Robust);
        assert_eq!(hs.len(), 2, "tilt {tilt}: {hs:?}");
        assert_eq!((hs[0].part, hs[1].part), (Part::BottomCap, Part::TopCap));
        assert!((f(hs[0].t) - 4.0).abs() < 1e-4 && (f(hs[1].t) - 6.0).abs() < 1e-4);
    }
}

/// The ray crossing the generic cone's base at (½cos φ, ½sin φ, −1) and going up along a
/// generator direction (−cos φ, −sin φ, 1), so that a = d_x² + d_y² − d_z² = 0 (or, rounded, a
/// few ulps): it enters through the base at t = 2 and leaves through the wall at t = 3.25.
fn generator_ray(phi: f64) -> Ray {
    let base = vec3(0.5 * phi.cos(), 0.5 * phi.sin(), -1.0);
    let dir = vec3(-phi.cos(), -phi.sin(), 1.0);
    Ray::new(base - dir * 2.0, dir)
}

fn generator_ray_is_right(hs: &[Hit]) -> bool {
    hs.len() == 2
        && hs[0].part == Part::Base
        && hs[1].part == Part::Wall
        && (f(hs[0].t) - 2.0).abs() < 1e-3
        && (f(hs[1].t) - 3.25).abs() < 1e-3
}

/// Notes, "Generic Cone": a = d_x² + d_y² − d_z² is 0 for a ray parallel to a generator, and
/// the quadratic is then the linear 2b·t + c = 0. The notes' −b/a ± √(b² − ac)/a divides by zero
/// (or, for a of a few ulps, cancels to garbage) and loses the wall hit.
#[test]
fn cone_ray_parallel_to_a_generator_meets_the_base_and_the_wall_once() {
    let cone = Object::new(Shape::Cone, Placement::identity());
    let mut textbook_wrong = 0;
    for i in 0..360 {
        let phi = (i as f64).to_radians();
        let ray = generator_ray(phi);
        let robust = hits(&cone, &ray, Numerics::Robust);
        assert!(generator_ray_is_right(&robust), "φ = {i}°: {robust:?}");
        if !generator_ray_is_right(&hits(&cone, &ray, Numerics::Textbook)) {
            textbook_wrong += 1;
        }
    }
    // φ = 0 has a = 0 exactly
    assert!(!generator_ray_is_right(&hits(
        &cone,
        &generator_ray(0.0),
        Numerics::Textbook
    )));
    assert!(textbook_wrong > 0);
}

/// Notes, "Generic Cone": b² − ac with a = d_x² + d_y² − d_z², b = e_x·d_x + e_y·d_y +
/// d_z·(1 − e_z), c = e_x² + e_y² − (1 − e_z)². For a cone D units away b² and ac are ≈ D² and
/// the notes' difference has no digit left; the robust form w_x² + w_y² − w_z², w = d × (e −
/// apex), does not square D. The cone (axis along +y, wall radius 1 at its mid-height y = 0)
/// is seen from the side, so a ray at height 0 and offset h behaves like the far sphere's.
#[test]
fn small_cone_far_away_is_hit_where_the_textbook_discriminant_sees_nothing() {
    let cone = placed(
        Shape::Cone,
        &[
            Step::RotateX(-90.0),
            Step::Translate(vec3(0.0, 0.0, -tol::FAR)),
        ],
    );
    let case = |h: f64, numerics| {
        let ray = Ray::new(vec3(h, 0.0, 0.0), vec3(0.0, 0.0, -1.0));
        hits(&cone, &ray, numerics)
    };
    for h in [0.0, 0.5, 0.9, -0.95] {
        assert!(
            far_sphere_is_right(&case(h, Numerics::Robust), h),
            "h = {h}: {:?}",
            case(h, Numerics::Robust)
        );
    }
    assert!(case(1.05, Numerics::Robust).is_empty());
    assert!(
        !far_sphere_is_right(&case(0.5, Numerics::Textbook), 0.5),
        "the textbook discriminant was expected to fail: {:?}",
        case(0.5, Numerics::Textbook)
    );
}

/// Notes, "Surface Normals at Intersections": the cone wall normal (x, y, 1 − z) vanishes at the
/// apex. Rays through the apex from every side, and rays lying in the wall along a generator
/// (a = b = c = 0), get finite unit normals and ordered hits.
#[test]
fn rays_through_the_cone_apex_get_finite_unit_normals() {
    let cone = placed(
        Shape::Cone,
        &[Step::Scale(vec3(2.0, 2.0, 3.0)), Step::RotateX(-70.0)],
    );
    let apex = cone.placement.m().transform_point3(vec3(0.0, 0.0, 1.0));
    for i in 0..90 {
        let phi = (i as f64 * 4.0).to_radians();
        for (dz, lying) in [(-0.3, false), (-1.0, true), (-3.0, false), (0.5, false)] {
            let local = vec3(phi.cos(), phi.sin(), dz);
            let dir = cone.placement.m().transform_vector3(local);
            let ray = Ray::new(apex - dir * 3.0, dir);
            for numerics in [Numerics::Robust, Numerics::Textbook] {
                let hs = hits(&cone, &ray, numerics);
                assert!(all_finite(&hs), "{numerics:?} φ {i}: {hs:?}");
                for w in hs.windows(2) {
                    assert!(w[0].t <= w[1].t);
                }
                for h in &hs {
                    assert!(
                        (f(h.normal.length()) - 1.0).abs() < tol::UNIT,
                        "{numerics:?}: {h:?}"
                    );
                }
                if numerics == Numerics::Robust && !lying && dz < -1.0 {
                    // the apex is on the ray at t = 3 and the ray reaches the solid there
                    assert!(
                        hs.iter().any(|h| (f(h.t) - 3.0).abs() < 1e-3),
                        "φ {i} dz {dz}: {hs:?}"
                    );
                }
            }
        }
    }
}
