//! The generic cylinder with its caps: the wall's quadratic, the normals, the hits through wall and caps ("Generic Cylinder").

use super::*;
use whitted::shapes::cylinder;

/// "Generic Cylinder": a = d_x² + d_y², b = e_x d_x + e_y d_y, c = e_x² + e_y² − 1.
#[test]
fn ex_cylinder_coefficients_follow_the_notes() {
    let (a, b, c) = cylinder::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, 1.25, epsilon = TOL);
    assert_abs_diff_eq!(b, -1.5, epsilon = TOL);
    assert_abs_diff_eq!(c, 4.0, epsilon = TOL);
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
        assert_abs_diff_eq!(cylinder::discriminant(&r, a, b), expected, epsilon = TOL);
    }
}

/// "Surface Normals at Intersections": the cylinder's wall normal is (x, y, 0), its top cap's
/// (0, 0, 1) and its bottom cap's (0, 0, −1), wherever on the cap.
#[test]
fn ex_cylinder_normal_cylinder_normals_are_x_y_0_on_the_wall_and_plus_minus_z_on_the_caps() {
    assert_vec_eq(
        cylinder::normal(Part::Wall, vec3(0.6, 0.8, 0.3)),
        vec3(0.6, 0.8, 0.0),
        TOL,
    );
    assert_vec_eq(
        cylinder::normal(Part::Wall, vec3(-1.0, 0.0, -0.9)),
        Vec3::NEG_X,
        TOL,
    );
    assert_eq!(
        cylinder::normal(Part::TopCap, vec3(0.2, -0.3, 1.0)),
        Vec3::Z
    );
    assert_eq!(
        cylinder::normal(Part::BottomCap, vec3(0.2, -0.3, -1.0)),
        Vec3::NEG_Z
    );
}

/// "Generic Cylinder" and "Surface Normals at Intersections": a ray across the wall hits at
/// y = ∓1 with normals (x, y, 0).
#[test]
fn ex_hit_cylinder_cylinder_wall_two_hits_with_normals_x_y_0() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cylinder::intersect(&ray([0.0, -5.0, 0.5], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_Y, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::Y, TOL);
    }
}

/// "Generic Cylinder": roots with z outside [−1, 1] do not count, and a tangent ray grazes once.
#[test]
fn ex_hit_cylinder_cylinder_miss_beyond_the_caps_and_tangent_graze() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert!(cylinder::intersect(&ray([0.0, -5.0, 2.0], [0.0, 1.0, 0.0]), numerics).is_empty());
        assert!(cylinder::intersect(&ray([1.5, -5.0, 0.0], [0.0, 1.0, 0.0]), numerics).is_empty());
        let graze = cylinder::intersect(&ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&graze, &[(5.0, Part::Wall)]);
        assert_vec_eq(graze.as_slice()[0].normal, Vec3::X, TOL);
    }
}

/// "Generic Cylinder" (caps) and "Surface Normals at Intersections": a ray along the axis
/// (a = 0) enters through the top cap, normal (0, 0, 1), and leaves through the bottom cap,
/// normal (0, 0, −1).
#[test]
fn ex_hit_cylinder_cylinder_ray_along_the_axis_crosses_both_caps() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cylinder::intersect(&ray([0.3, 0.2, 5.0], [0.0, 0.0, -1.0]), numerics);
        assert_hits(&hits, &[(4.0, Part::TopCap), (6.0, Part::BottomCap)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Z, TOL);
    }
}

/// "Generic Cylinder": a slanted ray enters through the top cap (inside the unit circle) and
/// leaves through the wall.
#[test]
fn ex_hit_cylinder_cylinder_ray_from_cap_to_wall() {
    // e = (0, 0, 2), d = (0.5, 0, −1): z = 1 at t = 1 (x = 0.5, inside); x = 1 at t = 2 (z = 0)
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cylinder::intersect(&ray([0.0, 0.0, 2.0], [0.5, 0.0, -1.0]), numerics);
        assert_hits(&hits, &[(1.0, Part::TopCap), (2.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::X, TOL);
    }
}
