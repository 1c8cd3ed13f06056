//! The generic sphere: its quadratic, discriminant, normal and hits ("Generic Sphere").

use super::*;
use whitted::shapes::sphere;

/// "Generic Sphere": a = |d|², b = e·d, c = |e|² − 1.
#[test]
fn ex_sphere_coefficients_are_d_squared_e_dot_d_and_e_squared_minus_one() {
    // from (1, 2, 3) along (0.5, −1, 2): 0.25 + 1 + 4, 0.5 − 2 + 6, 1 + 4 + 9 − 1;
    // from (0, 0, 5) along −z: (1, −5, 24), the roots 4 and 6 of t² − 10t + 24
    for (e, d, expected) in [
        ([1.0, 2.0, 3.0], [0.5, -1.0, 2.0], [5.25, 4.5, 13.0]),
        ([0.0, 0.0, 5.0], [0.0, 0.0, -1.0], [1.0, -5.0, 24.0]),
    ] {
        let (a, b, c) = sphere::coefficients(&ray(e, d));
        let of = format!("of the ray e = {e:?}, d = {d:?}");
        assert_near(&format!("a = ‖d‖² {of}"), a, expected[0] as Real, TOL);
        assert_near(&format!("b = e·d {of}"), b, expected[1] as Real, TOL);
        assert_near(&format!("c = ‖e‖² − 1 {of}"), c, expected[2] as Real, TOL);
    }
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
        assert_near(
            &format!("b² − ac of the ray e = {e:?}, d = {d:?} (a = {a}, b = {b})"),
            sphere::discriminant(&r, a, b),
            expected,
            TOL,
        );
    }
    #[cfg(feature = "f32")]
    {
        let (a, b, c) = sphere::coefficients(&ray([0.0, 0.5, 1e4], [0.0, 0.0, -1.0]));
        assert_eq!(
            discriminant(a, b, c),
            0.0,
            "the textbook b² − ac from (0, ½, 10⁴) along −z loses it all"
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
        assert_eq!(sphere::normal(p), p, "n at P = {p}: P itself");
    }
}

/// "Generic Sphere": a ray through the centre enters at t = 4 and leaves at t = 6, with normals
/// equal to the hit points ("Surface Normals at Intersections").
#[test]
fn ex_hit_sphere_sphere_two_hits_with_the_point_as_normal() {
    let through = "from (0, 0, 5) along −z";
    let hits = sphere::intersect(&ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_hits(
        through,
        &hits,
        &[(4.0, Part::Surface), (6.0, Part::Surface)],
    );
    assert_normal(through, &hits, 0, Vec3::Z, TOL);
    assert_normal(through, &hits, 1, Vec3::NEG_Z, TOL);
    assert_entering(through, &hits, &[true, false]);
    // an oblique ray: e = (0.6, 0, 5), d = (0, 0, −1) meets z = ±0.8
    let oblique = "from (0.6, 0, 5) along −z";
    let hits = sphere::intersect(&ray([0.6, 0.0, 5.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_hits(
        oblique,
        &hits,
        &[(4.2, Part::Surface), (5.8, Part::Surface)],
    );
    assert_normal(oblique, &hits, 0, vec3(0.6, 0.0, 0.8), 10.0 * TOL);
}

/// "Generic Sphere": b² − ac = 0 grazes (one hit), b² − ac < 0 misses.
#[test]
fn ex_hit_sphere_sphere_tangent_ray_grazes_once_and_outside_ray_misses() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        for (e, graze) in [([1.0, 0.0, 5.0], Vec3::X), ([0.0, 1.0, 5.0], Vec3::Y)] {
            let what = format!("from {e:?} along −z, {numerics:?} (b² − ac = 0)");
            let hits = sphere::intersect(&ray(e, [0.0, 0.0, -1.0]), numerics);
            assert_hits(&what, &hits, &[(5.0, Part::Surface)]);
            assert_normal(&what, &hits, 0, graze, TOL);
        }
        // along −z from (1.5, 0, 5) and from (0, 2, 5) it misses (b² − ac < 0)
        for e in [[1.5, 0.0, 5.0], [0.0, 2.0, 5.0]] {
            let hits = sphere::intersect(&ray(e, [0.0, 0.0, -1.0]), numerics);
            assert!(
                hits.is_empty(),
                "the ray from {e:?} along −z, {numerics:?}, misses (b² − ac < 0): {hits:?}"
            );
        }
    }
    // a degenerate direction hits nothing
    let hits = sphere::intersect(&ray([0.0, 0.0, 5.0], [0.0, 0.0, 0.0]), Numerics::Robust);
    assert!(
        hits.is_empty(),
        "a ray from (0, 0, 5) with d = 0 (a = 0) hits nothing: {hits:?}"
    );
}
