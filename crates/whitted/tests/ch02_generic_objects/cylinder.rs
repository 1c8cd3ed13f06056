//! The generic cylinder with its caps: the wall's quadratic, the normals, the hits through wall and caps ("Generic Cylinder").

use super::*;
use whitted::shapes::cylinder;

/// "Generic Cylinder": a = d_x² + d_y², b = e_x d_x + e_y d_y, c = e_x² + e_y² − 1.
#[test]
fn ex_cylinder_coefficients_follow_the_notes() {
    let (a, b, c) = cylinder::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    let of = "of the ray e = (1, 2, 3), d = (0.5, −1, 2)";
    assert_near(&format!("a = d_x² + d_y² {of}"), a, 1.25, TOL);
    assert_near(&format!("b = e_x·d_x + e_y·d_y {of}"), b, -1.5, TOL);
    assert_near(&format!("c = e_x² + e_y² − 1 {of}"), c, 4.0, TOL);
}

/// "Generic Cylinder": b² − ac as a·(1 − ‖f‖²), f the x, y of e − (b/a)·d. Along +y from
/// (0, −5, ½): a = 1, b = −5, c = 24, so 25 − 24 = 1; from (1.5, −5, 0): 25 − 26.25 = −1.25
/// (a miss); with d = (0, 2, 7) (z plays no part): a = 4, b = −10, 100 − 96 = 4. From
/// (½, 10⁴, 3) along −y the line passes ½ from the axis: exactly ¾, in f32 too.
#[test]
fn ex_cylinder_discriminant_is_b2_minus_ac_of_the_wall() {
    for (e, d, expected) in [
        ([0.0, -5.0, 0.5], [0.0, 1.0, 0.0], 1.0),
        ([1.5, -5.0, 0.0], [0.0, 1.0, 0.0], -1.25),
        ([0.0, -5.0, 0.5], [0.0, 2.0, 7.0], 4.0),
        ([0.5, 1e4, 3.0], [0.0, -1.0, 0.0], 0.75),
    ] {
        let r = ray(e, d);
        let (a, b, _) = cylinder::coefficients(&r);
        assert_near(
            &format!("the wall's b² − ac for the ray e = {e:?}, d = {d:?} (a = {a}, b = {b})"),
            cylinder::discriminant(&r, a, b),
            expected,
            TOL,
        );
    }
}

/// "Surface Normals at Intersections": the cylinder's wall normal is (x, y, 0), its top cap's
/// (0, 0, 1) and its bottom cap's (0, 0, −1), wherever on the cap.
#[test]
fn ex_cylinder_normal_cylinder_normals_are_x_y_0_on_the_wall_and_plus_minus_z_on_the_caps() {
    // the caps' normals are constants: exactly
    for (part, p, expected, tol) in [
        (Part::Wall, vec3(0.6, 0.8, 0.3), vec3(0.6, 0.8, 0.0), TOL),
        (Part::Wall, vec3(-1.0, 0.0, -0.9), Vec3::NEG_X, TOL),
        (Part::TopCap, vec3(0.2, -0.3, 1.0), Vec3::Z, 0.0),
        (Part::BottomCap, vec3(0.2, -0.3, -1.0), Vec3::NEG_Z, 0.0),
    ] {
        assert_vec_eq(
            &format!("n on the {part:?} at P = {p}"),
            cylinder::normal(part, p),
            expected,
            tol,
        );
    }
}

/// "Generic Cylinder" and "Surface Normals at Intersections": a ray across the wall hits at
/// y = ∓1 with normals (x, y, 0).
#[test]
fn ex_hit_cylinder_cylinder_wall_two_hits_with_normals_x_y_0() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (0, −5, 0.5) along +y, {numerics:?}");
        let hits = cylinder::intersect(&ray([0.0, -5.0, 0.5], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&what, &hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_normal(&what, &hits, 0, Vec3::NEG_Y, TOL);
        assert_normal(&what, &hits, 1, Vec3::Y, TOL);
    }
}

/// "Generic Cylinder": roots with z outside [−1, 1] do not count, and a tangent ray grazes once.
#[test]
fn ex_hit_cylinder_cylinder_miss_beyond_the_caps_and_tangent_graze() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        for (e, why) in [
            ([0.0, -5.0, 2.0], "above the top cap, z = 2"),
            ([1.5, -5.0, 0.0], "beside the wall, x = 1.5"),
        ] {
            let hits = cylinder::intersect(&ray(e, [0.0, 1.0, 0.0]), numerics);
            assert!(
                hits.is_empty(),
                "the ray from {e:?} along +y, {why}, misses, {numerics:?}: {hits:?}"
            );
        }
        let what = format!("from (1, −5, 0) along +y, tangent to the wall, {numerics:?}");
        let graze = cylinder::intersect(&ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&what, &graze, &[(5.0, Part::Wall)]);
        assert_normal(&what, &graze, 0, Vec3::X, TOL);
    }
}

/// "Generic Cylinder" (caps) and "Surface Normals at Intersections": a ray along the axis
/// (a = 0) enters through the top cap, normal (0, 0, 1), and leaves through the bottom cap,
/// normal (0, 0, −1).
#[test]
fn ex_hit_cylinder_cylinder_ray_along_the_axis_crosses_both_caps() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (0.3, 0.2, 5) along −z, {numerics:?}");
        let hits = cylinder::intersect(&ray([0.3, 0.2, 5.0], [0.0, 0.0, -1.0]), numerics);
        assert_hits(&what, &hits, &[(4.0, Part::TopCap), (6.0, Part::BottomCap)]);
        assert_normal(&what, &hits, 0, Vec3::Z, TOL);
        assert_normal(&what, &hits, 1, Vec3::NEG_Z, TOL);
    }
}

/// "Generic Cylinder": a slanted ray enters through the top cap (inside the unit circle) and
/// leaves through the wall.
#[test]
fn ex_hit_cylinder_cylinder_ray_from_cap_to_wall() {
    // e = (0, 0, 2), d = (0.5, 0, −1): z = 1 at t = 1 (x = 0.5, inside); x = 1 at t = 2 (z = 0)
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let what = format!("from (0, 0, 2) along (0.5, 0, −1), {numerics:?}");
        let hits = cylinder::intersect(&ray([0.0, 0.0, 2.0], [0.5, 0.0, -1.0]), numerics);
        assert_hits(&what, &hits, &[(1.0, Part::TopCap), (2.0, Part::Wall)]);
        assert_normal(&what, &hits, 1, Vec3::X, TOL);
    }
}
