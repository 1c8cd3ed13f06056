//! The generic cone with its base: the quadratic, the discriminant by a cross product, the normals, the hits through wall, base and apex ("Generic Cone").

use super::*;
use whitted::shapes::cone;

/// "Generic Cone": a = d_x² + d_y² − d_z², b = e_x d_x + e_y d_y + d_z(1 − e_z),
/// c = e_x² + e_y² − (1 − e_z)².
#[test]
fn ex_cone_coefficients_follow_the_notes() {
    let (a, b, c) = cone::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    let of = "of the ray e = (1, 2, 3), d = (0.5, −1, 2)";
    // 0.25 + 1 − 4; 0.5 − 2 + 2·(1 − 3); 1 + 4 − 4
    assert_near(&format!("a = d_x² + d_y² − d_z² {of}"), a, -2.75, TOL);
    assert_near(
        &format!("b = e_x·d_x + e_y·d_y + d_z·(1 − e_z) {of}"),
        b,
        -5.5,
        TOL,
    );
    assert_near(&format!("c = e_x² + e_y² − (1 − e_z)² {of}"), c, 1.0, TOL);
}

/// "Generic Cone": b² − ac = w_x² + w_y² − w_z² with w = d × (e − (0, 0, 1)). For e = (1, 2, 3),
/// d = (0.5, −1, 2): u = (1, 2, 2), w = (−6, 1, 2), 36 + 1 − 4 = 33 = (−5.5)² − (−2.75)·1.
/// Across the wall at z = 0 along +y from (0, −5, 0): w = (−1, 0, 0), 1 = 25 − 24. Touching it
/// from (1, −5, 0): w = (−1, 0, −1), 0, a graze.
#[test]
fn ex_cone_discriminant_is_b2_minus_ac() {
    for (e, d, expected) in [
        ([1.0, 2.0, 3.0], [0.5, -1.0, 2.0], 33.0),
        ([0.0, -5.0, 0.0], [0.0, 1.0, 0.0], 1.0),
        ([1.0, -5.0, 0.0], [0.0, 1.0, 0.0], 0.0),
    ] {
        let r = ray(e, d);
        let (a, b, c) = cone::coefficients(&r);
        let of = format!("of the ray e = {e:?}, d = {d:?}");
        assert_near(
            &format!("b² − ac from the coefficients (a, b, c) = ({a}, {b}, {c}) {of}"),
            b * b - a * c,
            expected,
            10.0 * TOL,
        );
        assert_near(
            &format!("b² − ac = w_x² + w_y² − w_z², w = d × (e − (0, 0, 1)), {of}"),
            cone::discriminant(&r),
            expected,
            10.0 * TOL,
        );
    }
}

/// "Surface Normals at Intersections": the cone's wall normal is (x, y, 1 − z), not unit; its
/// base's (0, 0, −1). At the apex, where (x, y, 1 − z) = 0, the axis (0, 0, 1) (an erratum:
/// the notes give no normal there).
#[test]
fn ex_cone_normal_cone_normals_are_x_y_one_minus_z_on_the_wall_and_minus_z_on_the_base() {
    // the base's and the apex's normals are constants: exactly
    for (part, p, expected, tol) in [
        (Part::Wall, vec3(0.5, 0.0, 0.5), vec3(0.5, 0.0, 0.5), TOL),
        (Part::Wall, vec3(0.0, -1.0, 0.0), vec3(0.0, -1.0, 1.0), TOL),
        (Part::Wall, vec3(1.2, -1.6, -1.0), vec3(1.2, -1.6, 2.0), TOL),
        (Part::Base, vec3(0.3, 0.4, -1.0), Vec3::NEG_Z, 0.0),
        (Part::Apex, Vec3::Z, Vec3::Z, 0.0),
        (Part::Wall, Vec3::Z, Vec3::Z, 0.0), // the wall's formula gives 0 there
    ] {
        assert_vec_eq(
            &format!("n on the {part:?} at P = {p}"),
            cone::normal(part, p),
            expected,
            tol,
        );
    }
}

/// "Generic Cone" and "Surface Normals at Intersections": across the wall at z = 0 the radius
/// is 1 − z = 1, hits at y = ∓1 with normals along (x, y, 1 − z).
#[test]
fn ex_hit_cone_cone_wall_two_hits_with_normals_x_y_one_minus_z() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (0, −5, 0) along +y, {numerics:?}");
        let hits = cone::intersect(&ray([0.0, -5.0, 0.0], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&what, &hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_normal_direction(&what, &hits, 0, vec3(0.0, -1.0, 1.0) * k, TOL);
        assert_normal_direction(&what, &hits, 1, vec3(0.0, 1.0, 1.0) * k, TOL);
    }
}

/// "Generic Cone": the base z = −1 is the disc of radius 2 (where the wall reaches
/// x² + y² = (1 − (−1))²; the notes call it a unit circle, an erratum) with normal (0, 0, −1);
/// from below at x = 0.5 the ray enters the base at t = 2 and leaves the wall where
/// (1 − z)² = 0.25, z = 0.5, t = 3.5.
#[test]
fn ex_hit_cone_cone_base_then_wall() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (0.5, 0, −3) along +z, {numerics:?}");
        let hits = cone::intersect(&ray([0.5, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics);
        assert_hits(&what, &hits, &[(2.0, Part::Base), (3.5, Part::Wall)]);
        assert_normal(&what, &hits, 0, Vec3::NEG_Z, TOL);
        assert_normal_direction(&what, &hits, 1, vec3(1.0, 0.0, 1.0) * k, TOL);
    }
}

/// "Generic Cone": the implicit equation also holds on the upper nappe (z > 1), which is not
/// part of the cone: a ray crossing it misses.
#[test]
fn ex_hit_cone_upper_nappe_of_the_double_cone_is_not_hit() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cone::intersect(&ray([0.0, -5.0, 1.5], [0.0, 1.0, 0.0]), numerics);
        assert!(
            hits.is_empty(),
            "the ray from (0, −5, 1.5) along +y crosses only the upper nappe (z = 1.5 > 1), \
             {numerics:?}: hits {hits:?}, expected none"
        );
    }
}

/// "Surface Normals at Intersections" (erratum: the apex): a ray down the axis passes the apex,
/// where (x, y, 1 − z) = 0; whitted returns the finite unit normal (0, 0, 1) there, then
/// leaves through the base.
#[test]
fn ex_hit_cone_cone_apex_has_a_finite_unit_normal() {
    let what = "from (0, 0, 3) along −z, down the axis";
    let hits = cone::intersect(&ray([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_hits(what, &hits, &[(2.0, Part::Apex), (4.0, Part::Base)]);
    assert_normal(what, &hits, 0, Vec3::Z, TOL);
}

/// "Generic Cone": a ray touching the wall at z = 0 (radius 1) has b² − ac = 0 and grazes once,
/// with the wall normal (x, y, 1 − z) there.
#[test]
fn ex_hit_cone_cone_tangent_ray_grazes_once() {
    let r = ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]);
    let (a, b, c) = cone::coefficients(&r);
    assert_near(
        &format!("b² − ac of the ray from (1, −5, 0) along +y, (a, b, c) = ({a}, {b}, {c})"),
        b * b - a * c,
        0.0,
        TOL,
    );
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (1, −5, 0) along +y, tangent, {numerics:?}");
        let hits = cone::intersect(&r, numerics);
        assert_hits(&what, &hits, &[(5.0, Part::Wall)]);
        assert_normal_direction(&what, &hits, 0, vec3(1.0, 0.0, 1.0) * k, TOL);
    }
    let hits = cone::intersect(&ray([1.2, -5.0, 0.0], [0.0, 1.0, 0.0]), Numerics::Robust);
    assert!(
        hits.is_empty(),
        "the ray from (1.2, −5, 0) along +y passes beside the wall: hits {hits:?}, expected none"
    );
}

/// "Generic Cone" (erratum: the base radius): at z = −1 the wall reaches x² + y² = (1 + 1)² = 4,
/// so the base it closes on has radius 2. A ray from below at x = 1.5 enters through the base
/// (a unit disc would let it into a hole) and leaves through the wall where 1 − z = 1.5.
#[test]
fn ex_hit_cone_cone_base_has_radius_two() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (1.5, 0, −3) along +z, {numerics:?} (the base has radius 2)");
        let hits = cone::intersect(&ray([1.5, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics);
        assert_hits(&what, &hits, &[(2.0, Part::Base), (2.5, Part::Wall)]);
        assert_normal_direction(&what, &hits, 1, vec3(1.0, 0.0, 1.0) * k, TOL);
        // just outside the radius-2 base: a miss
        let hits = cone::intersect(&ray([2.01, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics);
        assert!(
            hits.is_empty(),
            "the ray from (2.01, 0, −3) along +z passes outside the base of radius 2, \
             {numerics:?}: hits {hits:?}, expected none"
        );
    }
}
