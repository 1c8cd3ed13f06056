//! The generic sphere: its quadratic, discriminant, normal and hits ("Generic Sphere").

use super::*;
use whitted::shapes::sphere;

/// "Generic Sphere": a = |d|², b = e·d, c = |e|² − 1.
#[test]
fn ex_sphere_coefficients_are_d_squared_e_dot_d_and_e_squared_minus_one() {
    let (a, b, c) = sphere::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, 5.25, epsilon = TOL); // 0.25 + 1 + 4
    assert_abs_diff_eq!(b, 4.5, epsilon = TOL); // 0.5 − 2 + 6
    assert_abs_diff_eq!(c, 13.0, epsilon = TOL); // 1 + 4 + 9 − 1
    // from (0, 0, 5) along −z: (1, −5, 24), the roots 4 and 6 of t² − 10t + 24
    let (a, b, c) = sphere::coefficients(&ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]));
    assert_abs_diff_eq!(a, 1.0, epsilon = TOL);
    assert_abs_diff_eq!(b, -5.0, epsilon = TOL);
    assert_abs_diff_eq!(c, 24.0, epsilon = TOL);
}

/// "Generic Sphere": b² − ac computed as a·(1 − ‖e − (b/a)·d‖²). Along −z from (0, 0, 5):
/// 25 − 24 = 1; from (0, 2, 5): 25 − 28 = −3 (a miss); from (0, 1, 5): 0 (a graze); with
/// d = (0, 0, −2), a = 4, b = −10: 100 − 96 = 4. From (0, ½, 10⁴) the closest point of the line
/// is (0, ½, 0) and the discriminant exactly 1 − ¼ = ¾, in f32 too, where b² − ac =
/// 10⁸ − (10⁸ + ¼ − 1) rounds to 0.
#[test]
fn ex_sphere_discriminant_is_b2_minus_ac_without_cancellation() {
    for (e, d, expected) in [
        ([0.0, 0.0, 5.0], [0.0, 0.0, -1.0], 1.0),
        ([0.0, 2.0, 5.0], [0.0, 0.0, -1.0], -3.0),
        ([0.0, 1.0, 5.0], [0.0, 0.0, -1.0], 0.0),
        ([0.0, 0.0, 5.0], [0.0, 0.0, -2.0], 4.0),
        ([0.0, 0.5, 1e4], [0.0, 0.0, -1.0], 0.75),
    ] {
        let r = ray(e, d);
        let (a, b, _) = sphere::coefficients(&r);
        assert_abs_diff_eq!(sphere::discriminant(&r, a, b), expected, epsilon = TOL);
    }
    #[cfg(feature = "f32")]
    {
        let (a, b, c) = sphere::coefficients(&ray([0.0, 0.5, 1e4], [0.0, 0.0, -1.0]));
        assert_eq!(
            discriminant(a, b, c),
            0.0,
            "the textbook b² − ac loses it all"
        );
    }
}

/// "Surface Normals at Intersections": the generic sphere's normal at P is P.
#[test]
fn ex_sphere_normal_is_the_point() {
    for p in [
        vec3(0.6, 0.0, 0.8),
        vec3(0.0, 0.0, -1.0),
        vec3(0.48, 0.6, 0.64),
    ] {
        assert_eq!(sphere::normal(p), p);
    }
}

/// "Generic Sphere": a ray through the centre enters at t = 4 and leaves at t = 6, with normals
/// equal to the hit points ("Surface Normals at Intersections").
#[test]
fn ex_hit_sphere_sphere_two_hits_with_the_point_as_normal() {
    let hits = sphere::intersect(&ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_hits(&hits, &[(4.0, Part::Surface), (6.0, Part::Surface)]);
    let [h1, h2] = [hits.as_slice()[0], hits.as_slice()[1]];
    assert_vec_eq(h1.normal, Vec3::Z, TOL);
    assert_vec_eq(h2.normal, Vec3::NEG_Z, TOL);
    assert!(h1.entering && !h2.entering);
    // an oblique ray: e = (0.6, 0, 5), d = (0, 0, −1) meets z = ±0.8
    let hits = sphere::intersect(&ray([0.6, 0.0, 5.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_hits(&hits, &[(4.2, Part::Surface), (5.8, Part::Surface)]);
    assert_vec_eq(hits.as_slice()[0].normal, vec3(0.6, 0.0, 0.8), 10.0 * TOL);
}

/// "Generic Sphere": b² − ac = 0 grazes (one hit), b² − ac < 0 misses.
#[test]
fn ex_hit_sphere_sphere_tangent_ray_grazes_once_and_outside_ray_misses() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let graze = sphere::intersect(&ray([1.0, 0.0, 5.0], [0.0, 0.0, -1.0]), numerics);
        assert_hits(&graze, &[(5.0, Part::Surface)]);
        assert_vec_eq(graze.as_slice()[0].normal, Vec3::X, TOL);
        assert!(sphere::intersect(&ray([1.5, 0.0, 5.0], [0.0, 0.0, -1.0]), numerics).is_empty());
        // along −z from (0, 1, 5) it grazes at t = 5, from (0, 2, 5) it misses (b² − ac < 0)
        let graze = sphere::intersect(&ray([0.0, 1.0, 5.0], [0.0, 0.0, -1.0]), numerics);
        assert_hits(&graze, &[(5.0, Part::Surface)]);
        assert!(sphere::intersect(&ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0]), numerics).is_empty());
    }
    // a degenerate direction hits nothing
    assert!(sphere::intersect(&ray([0.0, 0.0, 5.0], [0.0, 0.0, 0.0]), Numerics::Robust).is_empty());
}
