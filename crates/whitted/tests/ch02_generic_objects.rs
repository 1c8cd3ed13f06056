//! Chapter 2 — generic objects (notes: "Ray Tracing Process", "Generic Objects", "Surface
//! Normals at Intersections"): every shape's miss, graze and two-hit cases with hand-computed
//! t and normals, and the placement M, M⁻¹, (M⁻¹)ᵀ.
//!
//! A test named `ex2_K_…` checks exercise 2.K of `chapters/formulas.toml` and calls only it and
//! the exercises before it: the shapes' tests call `sphere::intersect`, `cylinder::intersect` …
//! directly (normals in object space), and leave `Object::intersect`, which also carries the
//! normals back to the world (exercise 2.26), to the tests of placed objects.

mod common;

use approx::assert_abs_diff_eq;
use common::{TOL, assert_vec_eq, centre, render_at, render_both_ways, scene};
use whitted::accel::Accel;
use whitted::ray::Ray;
use whitted::real::{Mat4, Real, Vec3, vec3};
use whitted::render::{Chapter, Options, Tracer};
use whitted::shapes::quadratic::{
    Numerics, Roots, discriminant, solve, solve_with_discriminant, stable_roots,
};
use whitted::shapes::{
    Hit, Hits, Object, Part, Polyhedron, Shape, cone, cylinder, nearer, plane, polyhedron, sphere,
};
use whitted::transform::{Placement, Step, rotation_from_z, sin_cos_degrees};

fn ray(e: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(vec3(e[0], e[1], e[2]), vec3(d[0], d[1], d[2]))
}

/// The direction of a (non-zero) normal, to compare the cone's (x, y, 1 − z) with a unit vector.
fn unit(n: Vec3) -> Vec3 {
    n.normalize()
}

/// Asserts the hits' t values and parts.
#[track_caller]
fn assert_hits(hits: &Hits, expected: &[(Real, Part)]) {
    let got: Vec<(Real, Part)> = hits.as_slice().iter().map(|h| (h.t, h.part)).collect();
    assert_eq!(
        got.len(),
        expected.len(),
        "hits {got:?}, expected {expected:?}"
    );
    for ((t, part), (te, pe)) in got.iter().zip(expected) {
        assert!(
            (t - te).abs() <= 10.0 * TOL,
            "t = {t}, expected {te} (all: {got:?})"
        );
        assert_eq!(part, pe);
    }
}

// --- placement steps and rays -----------------------------------------------------------

/// "Ray Tracing Process" (q = M·q′): each kind of step has the matrix of its transformation.
/// A scale by (2, 3, 4) takes (1, 1, 1) to (2, 3, 4). Right-handed quarter turns, exactly:
/// about z, x goes to y; about x, y goes to z and z to −y; about y, z goes to x. By 30° about
/// z, x goes to (cos 30°, sin 30°, 0) = (√3/2, ½, 0); by −30° about y, to (√3/2, 0, ½). A
/// quarter turn about the axis (0, 0, 2) is the one about z; a third of a turn about
/// (1, 1, 1) takes x to y, y to z and z to x. A translation by (1, −2, 3) moves a point, not
/// a direction.
#[test]
fn ex_step_matrix_each_step_has_the_matrix_of_its_transformation() {
    let scale = Step::Scale(vec3(2.0, 3.0, 4.0)).matrix();
    assert_vec_eq(scale.transform_point3(Vec3::ONE), vec3(2.0, 3.0, 4.0), TOL);
    let turn = |step: Step, v: Vec3| step.matrix().transform_vector3(v);
    assert_eq!(turn(Step::RotateZ(90.0), Vec3::X), Vec3::Y);
    assert_eq!(turn(Step::RotateX(90.0), Vec3::Y), Vec3::Z);
    assert_eq!(turn(Step::RotateX(90.0), Vec3::Z), Vec3::NEG_Y);
    assert_eq!(turn(Step::RotateY(90.0), Vec3::Z), Vec3::X);
    let r3 = (3.0 as Real).sqrt();
    assert_vec_eq(
        turn(Step::RotateZ(30.0), Vec3::X),
        Vec3::new(r3 / 2.0, 0.5, 0.0),
        TOL,
    );
    assert_vec_eq(
        turn(Step::RotateY(-30.0), Vec3::X),
        Vec3::new(r3 / 2.0, 0.0, 0.5),
        TOL,
    );
    assert_vec_eq(
        turn(Step::RotateAxis(vec3(0.0, 0.0, 2.0), 90.0), Vec3::X),
        Vec3::Y,
        TOL,
    );
    let third = Step::RotateAxis(Vec3::ONE, 120.0);
    assert_vec_eq(turn(third, Vec3::X), Vec3::Y, 10.0 * TOL);
    assert_vec_eq(turn(third, Vec3::Y), Vec3::Z, 10.0 * TOL);
    assert_vec_eq(turn(third, Vec3::Z), Vec3::X, 10.0 * TOL);
    let t = vec3(1.0, -2.0, 3.0);
    let shift = Step::Translate(t).matrix();
    assert_vec_eq(shift.transform_point3(Vec3::ZERO), t, TOL);
    assert_vec_eq(shift.transform_point3(Vec3::ONE), vec3(2.0, -1.0, 4.0), TOL);
    assert_vec_eq(shift.transform_vector3(Vec3::X), Vec3::X, TOL);
}

/// "Ray Tracing Process": S⁻¹ undoes S — scale by 1/s, rotate by −θ about the same axis,
/// translate by −t — so S·S⁻¹ = I.
#[test]
fn ex_step_inverse_each_step_is_undone_by_its_inverse() {
    let axis = vec3(1.0, 2.0, -0.5);
    let t = vec3(1.0, -2.0, 3.0);
    let cases = [
        (
            Step::Scale(vec3(2.0, 4.0, 0.5)),
            Step::Scale(vec3(0.5, 0.25, 2.0)),
        ),
        (Step::RotateX(30.0), Step::RotateX(-30.0)),
        (Step::RotateY(-75.0), Step::RotateY(75.0)),
        (Step::RotateZ(90.0), Step::RotateZ(-90.0)),
        (Step::RotateAxis(axis, 40.0), Step::RotateAxis(axis, -40.0)),
        (Step::Translate(t), Step::Translate(-t)),
    ];
    for (step, inverse) in cases {
        assert_eq!(step.inverse(), inverse, "{step:?}");
        let product = step.matrix() * step.inverse().matrix();
        assert!(
            product.abs_diff_eq(Mat4::IDENTITY, 10.0 * TOL),
            "{step:?}: {product:?}"
        );
    }
}

/// "Ray Tracing Process": M⁻¹r(t) = M⁻¹e + M⁻¹d·t. With M⁻¹ a scale by (2, 1, ½) then a
/// translation by (1, 2, 3), the origin (1, 1, 1) moves as a point, to (3, 3, 3.5), and the
/// direction (3, 1, 0) as a vector, to (6, 1, 0), not renormalised: the point at t on the
/// carried ray is M⁻¹ of the point at t on the world ray.
#[test]
fn ex_ray_in_object_space_a_ray_moves_its_origin_as_a_point_and_its_direction_as_a_vector() {
    let m = Mat4::from_translation(vec3(1.0, 2.0, 3.0)) * Mat4::from_scale(vec3(2.0, 1.0, 0.5));
    let world = ray([1.0, 1.0, 1.0], [3.0, 1.0, 0.0]);
    let local = world.transformed(&m);
    assert_vec_eq(local.origin, vec3(3.0, 3.0, 3.5), TOL);
    assert_vec_eq(local.dir, vec3(6.0, 1.0, 0.0), TOL);
    for t in [-1.0, 0.5, 2.0] {
        let on_world = world.origin + world.dir * t;
        assert_vec_eq(
            local.origin + local.dir * t,
            m.transform_point3(on_world),
            10.0 * TOL,
        );
    }
}

/// "Ray Tracing Process": r(t) = e + d·t. For e = (1, 2, 3), d = (0.5, −1, 2): r(0) = e,
/// r(1) = (1.5, 1, 5), r(2) = (2, 0, 7), r(−1) = (0.5, 3, 1).
#[test]
fn ex_point_on_ray_r_of_t_is_e_plus_d_t() {
    let r = ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]);
    assert_vec_eq(r.at(0.0), vec3(1.0, 2.0, 3.0), TOL);
    assert_vec_eq(r.at(1.0), vec3(1.5, 1.0, 5.0), TOL);
    assert_vec_eq(r.at(2.0), vec3(2.0, 0.0, 7.0), TOL);
    assert_vec_eq(r.at(-1.0), vec3(0.5, 3.0, 1.0), TOL);
}

// --- the quadratic ------------------------------------------------------------------------

/// "Generic Sphere": t = −b/a ± √(b² − ac)/a; b² − ac < 0 no root, = 0 one, > 0 two.
#[test]
fn ex_quadratic_roots_quadratic_has_no_one_or_two_roots_by_the_sign_of_b2_minus_ac() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(solve(1.0, 0.0, 1.0, numerics), Roots::None); // t² + 1
        assert_eq!(solve(1.0, -2.0, 4.0, numerics), Roots::One(2.0)); // t² − 4t + 4
        match solve(1.0, -5.0, 24.0, numerics) {
            // t² − 10t + 24 = (t − 4)(t − 6)
            Roots::Two(t1, t2) => {
                assert_abs_diff_eq!(t1, 4.0, epsilon = TOL);
                assert_abs_diff_eq!(t2, 6.0, epsilon = TOL);
            }
            r => panic!("{r:?}"),
        }
    }
    assert_eq!(discriminant(1.0, -5.0, 24.0), 1.0);
}

/// "Generic Objects": a double root (Δ = 0, a ≠ 0) is one number, returned twice: t₁ = t₂ =
/// q/a. The other stable form, c/q, is the same root in exact arithmetic but rounds
/// differently: for a = 3, b = −7, c = b²/a it is one ulp off q/a, in f64 and in f32, and a
/// tangent ray would seem to cross the surface over a sliver of length 1 ulp.
#[test]
fn ex_stable_roots_a_double_root_is_returned_as_two_equal_values() {
    for (a, b) in [(3.0, -7.0), (3.0, -11.0), (6.0, -7.0), (11.0, -5.0)] {
        let (a, b): (Real, Real) = (a, b);
        let c = b * b / a;
        let (t1, t2) = stable_roots(a, b, c, 0.0).unwrap();
        assert_eq!(t1, -b / a, "a = {a}, b = {b}");
        assert_eq!(t2, t1, "a = {a}, b = {b}: the double root twice");
    }
}

/// "Generic Sphere", computed without cancellation: q = −(b + sign(b)·√Δ), t₁ = q/a,
/// t₂ = c/q, in increasing order. t² − 10t + 24 (b = −5, Δ = 1): q = 6, roots 6 and 24/6 = 4;
/// t² + 10t + 24 (b = 5): q = −6, roots −6 and −4; t² − 4t + 4 (Δ = 0): the double root 2,
/// twice; Δ < 0 or NaN: none. a = 0 (4t − 4 = 0, b = 2, c = −4, Δ = 4): q = −4, q/a = −∞ and
/// c/q = 1 = −c/(2b), the line's one root; a = b = 0: 0/0, none.
#[test]
fn ex_stable_roots_come_in_increasing_order() {
    assert_eq!(stable_roots(1.0, -5.0, 24.0, 1.0), Some((4.0, 6.0)));
    assert_eq!(stable_roots(1.0, 5.0, 24.0, 1.0), Some((-6.0, -4.0)));
    assert_eq!(stable_roots(1.0, -2.0, 4.0, 0.0), Some((2.0, 2.0)));
    assert_eq!(stable_roots(1.0, 0.0, 1.0, -1.0), None);
    assert_eq!(stable_roots(1.0, 0.0, 1.0, Real::NAN), None);
    assert_eq!(
        stable_roots(0.0, 2.0, -4.0, 4.0),
        Some((Real::NEG_INFINITY, 1.0))
    );
    assert_eq!(stable_roots(0.0, 0.0, 1.0, 0.0), None);
}

/// "Generic Sphere" (computational aspects): for t² − 2·10⁸·t + 1 = 0 (a = 1, b = −10⁸,
/// c = 1) the roots are 2·10⁸ and, from the product of the roots, 1/(2·10⁸) = 5·10⁻⁹, to full
/// precision in f64 and f32 alike: the large root q/a needs no subtraction, the small one is
/// c/q.
#[test]
fn ex_stable_roots_the_small_root_keeps_its_digits() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    let (t1, t2) = stable_roots(a, b, c, discriminant(a, b, c)).unwrap();
    assert_abs_diff_eq!(t1 / 5e-9, 1.0, epsilon = TOL);
    assert_abs_diff_eq!(t2 / 2e8, 1.0, epsilon = TOL);
}

/// "Generic Sphere": the notes' t = −b/a ± √(b² − ac)/a, as printed, loses the small root of
/// t² − 2·10⁸·t + 1 = 0 entirely (10⁸ − 10⁸ = 0), while the stable form keeps 5·10⁻⁹; both
/// drop what is not a finite root (a = 0: the stable form keeps the line's root 1 and drops
/// −∞) and find nothing for a NaN discriminant.
#[test]
fn ex_quadratic_roots_textbook_roots_lose_the_small_root_and_stable_ones_keep_it() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    assert_eq!(solve(a, b, c, Numerics::Textbook), Roots::Two(0.0, 2e8));
    match solve(a, b, c, Numerics::Robust) {
        Roots::Two(t1, t2) => {
            assert_abs_diff_eq!(t1 / 5e-9, 1.0, epsilon = TOL);
            assert_abs_diff_eq!(t2 / 2e8, 1.0, epsilon = TOL);
        }
        r => panic!("{r:?}"),
    }
    assert_eq!(
        solve_with_discriminant(0.0, 2.0, -4.0, 4.0, Numerics::Robust),
        Roots::One(1.0)
    );
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(
            solve_with_discriminant(1.0, 0.0, 1.0, Real::NAN, numerics),
            Roots::None
        );
    }
}

// --- sphere -------------------------------------------------------------------------------

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

// --- plane --------------------------------------------------------------------------------

/// "Generic Plane": t = −e_z/d_z, normal (0, 0, 1).
#[test]
fn ex_hit_plane_plane_is_hit_at_minus_ez_over_dz() {
    let hits = plane::intersect(&ray([3.0, -1.0, 2.0], [1.0, 0.0, -0.5]));
    assert_hits(&hits, &[(4.0, Part::Surface)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
    assert!(hits.as_slice()[0].entering); // from the +z side
    let below = plane::intersect(&ray([0.0, 0.0, -2.0], [0.0, 0.0, 4.0]));
    assert_hits(&below, &[(0.5, Part::Surface)]);
    assert!(!below.as_slice()[0].entering);
}

/// "Generic Plane": a ray with d_z = 0 is parallel and misses — never ±∞ or NaN, for +0 and −0,
/// whether it starts off the plane or on it; so does one whose −e_z/d_z overflows.
#[test]
fn ex_hit_plane_ray_parallel_to_the_plane_misses() {
    for dz in [0.0, -0.0] {
        for ez in [1.0, 0.0, -1.0] {
            let hits = plane::intersect(&ray([0.0, 0.0, ez], [1.0, 2.0, dz]));
            assert!(hits.is_empty(), "d_z = {dz}, e_z = {ez}: {hits:?}");
        }
    }
    // a d_z so small that −e_z/d_z overflows: the hit is beyond every number, so none
    let far = Ray::new(
        Vec3::new(0.0, 0.0, Real::MAX),
        Vec3::new(1.0, 0.0, -Real::MIN_POSITIVE),
    );
    assert!(plane::intersect(&far).is_empty());
}

// --- cylinder -----------------------------------------------------------------------------

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

// --- cone ---------------------------------------------------------------------------------

/// "Generic Cone": a = d_x² + d_y² − d_z², b = e_x d_x + e_y d_y + d_z(1 − e_z),
/// c = e_x² + e_y² − (1 − e_z)².
#[test]
fn ex_cone_coefficients_follow_the_notes() {
    let (a, b, c) = cone::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, -2.75, epsilon = TOL); // 0.25 + 1 − 4
    assert_abs_diff_eq!(b, -5.5, epsilon = TOL); // 0.5 − 2 + 2·(1 − 3)
    assert_abs_diff_eq!(c, 1.0, epsilon = TOL); // 1 + 4 − 4
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
        assert_abs_diff_eq!(b * b - a * c, expected, epsilon = 10.0 * TOL);
        assert_abs_diff_eq!(cone::discriminant(&r), expected, epsilon = 10.0 * TOL);
    }
}

/// "Surface Normals at Intersections": the cone's wall normal is (x, y, 1 − z), not unit; its
/// base's (0, 0, −1). At the apex, where (x, y, 1 − z) = 0, the axis (0, 0, 1) (an erratum:
/// the notes give no normal there).
#[test]
fn ex_cone_normal_cone_normals_are_x_y_one_minus_z_on_the_wall_and_minus_z_on_the_base() {
    assert_vec_eq(
        cone::normal(Part::Wall, vec3(0.5, 0.0, 0.5)),
        vec3(0.5, 0.0, 0.5),
        TOL,
    );
    assert_vec_eq(
        cone::normal(Part::Wall, vec3(0.0, -1.0, 0.0)),
        vec3(0.0, -1.0, 1.0),
        TOL,
    );
    assert_vec_eq(
        cone::normal(Part::Wall, vec3(1.2, -1.6, -1.0)),
        vec3(1.2, -1.6, 2.0),
        TOL,
    );
    assert_eq!(cone::normal(Part::Base, vec3(0.3, 0.4, -1.0)), Vec3::NEG_Z);
    assert_eq!(cone::normal(Part::Apex, Vec3::Z), Vec3::Z);
    assert_eq!(cone::normal(Part::Wall, Vec3::Z), Vec3::Z);
}

/// "Generic Cone" and "Surface Normals at Intersections": across the wall at z = 0 the radius
/// is 1 − z = 1, hits at y = ∓1 with normals along (x, y, 1 − z).
#[test]
fn ex_hit_cone_cone_wall_two_hits_with_normals_x_y_one_minus_z() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cone::intersect(&ray([0.0, -5.0, 0.0], [0.0, 1.0, 0.0]), numerics);
        assert_hits(&hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_vec_eq(
            unit(hits.as_slice()[0].normal),
            vec3(0.0, -1.0, 1.0) * k,
            TOL,
        );
        assert_vec_eq(
            unit(hits.as_slice()[1].normal),
            vec3(0.0, 1.0, 1.0) * k,
            TOL,
        );
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
        let hits = cone::intersect(&ray([0.5, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics);
        assert_hits(&hits, &[(2.0, Part::Base), (3.5, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_Z, TOL);
        assert_vec_eq(
            unit(hits.as_slice()[1].normal),
            vec3(1.0, 0.0, 1.0) * k,
            TOL,
        );
    }
}

/// "Generic Cone": the implicit equation also holds on the upper nappe (z > 1), which is not
/// part of the cone: a ray crossing it misses.
#[test]
fn ex_hit_cone_upper_nappe_of_the_double_cone_is_not_hit() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cone::intersect(&ray([0.0, -5.0, 1.5], [0.0, 1.0, 0.0]), numerics);
        assert!(hits.is_empty(), "{numerics:?}: {hits:?}");
    }
}

/// "Surface Normals at Intersections" (erratum: the apex): a ray down the axis passes the apex,
/// where (x, y, 1 − z) = 0; whitted returns the finite unit normal (0, 0, 1) there, then
/// leaves through the base.
#[test]
fn ex_hit_cone_cone_apex_has_a_finite_unit_normal() {
    let hits = cone::intersect(&ray([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]), Numerics::Robust);
    assert_eq!(hits.len(), 2, "{hits:?}");
    let (apex, base) = (hits.as_slice()[0], hits.as_slice()[1]);
    assert_abs_diff_eq!(apex.t, 2.0, epsilon = 10.0 * TOL);
    assert_vec_eq(apex.normal, Vec3::Z, TOL);
    assert!(apex.normal.is_finite());
    assert_abs_diff_eq!(base.t, 4.0, epsilon = 10.0 * TOL);
    assert_eq!(base.part, Part::Base);
}

// --- polyhedra ----------------------------------------------------------------------------

/// "Convex Polyhedra" (erratum): the notes print t = d − n·e / n·d; by precedence that is
/// d − (n·e)/(n·d), whose point is not on the facet. t = (d − n·e)/(n·d) is.
#[test]
fn ex_facet_crossing_facet_t_is_d_minus_n_dot_e_all_over_n_dot_d() {
    let facet = polyhedron::Facet::new(Vec3::Z, 1.0).unwrap(); // the plane z = 1
    let r = ray([0.0, 0.0, 5.0], [0.0, 0.0, -2.0]);
    let as_printed = facet.d() - facet.normal().dot(r.origin) / facet.normal().dot(r.dir); // 1 − 5/(−2) = 3.5
    let right = polyhedron::facet_t(&facet, &r); // (1 − 5)/(−2) = 2
    assert_abs_diff_eq!(right, 2.0, epsilon = TOL);
    assert_abs_diff_eq!(facet.normal().dot(r.at(right)), facet.d(), epsilon = TOL); // on the facet
    assert_abs_diff_eq!(as_printed, 3.5, epsilon = TOL);
    assert!((facet.normal().dot(r.at(as_printed)) - facet.d()).abs() > 1.0); // z = −2: not on it
}

/// "Convex Polyhedra": the cube [−1, 1]³ along z: enters facet +z (index 4) at t = 4, leaves
/// facet −z (index 5) at t = 6, each with its facet's outward normal.
#[test]
fn ex_hit_polyhedron_cube_entering_and_leaving_facets() {
    let hits = Polyhedron::cube().intersect(&ray([0.2, 0.3, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(&hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Z, TOL);
}

/// "Convex Polyhedra" (erratum: the table swaps inside and outside): with n·d = 0, the notes'
/// own rule (Q·n < d is inside) makes d − n·e < 0 *outside* — a miss — and d − n·e > 0 inside,
/// where the facet does not stop the ray. The notes' table says the opposite.
#[test]
fn ex_hit_polyhedron_ray_parallel_to_a_facet_misses_outside_and_passes_inside() {
    let cube = Polyhedron::cube();
    // parallel to the facet y = 1 (index 2), at y = 2: d − n·e = 1 − 2 < 0, outside
    let facet = Polyhedron::cube().facets()[2];
    let e = vec3(0.0, 2.0, 5.0);
    assert!(facet.d() - facet.normal().dot(e) < 0.0);
    assert!(
        facet.normal().dot(e) > facet.d(),
        "Q·n > d: outside, by the notes' rule"
    );
    assert!(
        cube.intersect(&ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0]))
            .is_empty()
    );
    // parallel to it at y = 0.5 (inside its half-space)
    let hits = cube.intersect(&ray([0.0, 0.5, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(&hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
}

/// "Convex Polyhedra": the solid is closed (n·P ≤ d), so a ray lying in the plane of a facet
/// (n·d = 0 and n·e = d) is not outside that facet: along the cube's face y = 1 it enters at
/// the top (t = 4) and leaves at the bottom (t = 6). Taking n·e ≥ d for "outside" misses it.
#[test]
fn ex_hit_polyhedron_a_ray_along_a_face_touches_the_closed_solid() {
    let hits = Polyhedron::cube().intersect(&ray([0.0, 1.0, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(&hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
}

/// "Convex Polyhedra": in the half-space z ≤ 0 (one facet: `Polyhedron::new` takes any facets,
/// scenes only closed solids), a ray from inside going up meets no facet that raises t_near,
/// which stays −∞; its one hit is the finite bound t_far = 2, where it leaves (entering =
/// false). From above, going down, the one hit enters.
#[test]
fn ex_hit_polyhedron_with_only_a_leaving_bound_the_one_hit_leaves() {
    let half_space = Polyhedron::new(vec![polyhedron::Facet::new(Vec3::Z, 0.0).unwrap()]);
    let up = half_space.intersect(&ray([0.0, 0.0, -2.0], [0.0, 0.0, 1.0]));
    assert_hits(&up, &[(2.0, Part::Facet(0))]);
    assert!(!up.as_slice()[0].entering, "going out of the solid");
    let down = half_space.intersect(&ray([0.0, 0.0, 2.0], [0.0, 0.0, -1.0]));
    assert_hits(&down, &[(2.0, Part::Facet(0))]);
    assert!(down.as_slice()[0].entering, "coming into the solid");
}

/// "Convex Polyhedra": the octahedron |x| + |y| + |z| ≤ 1 along x at y = 0.25, z = 0.1 spans
/// |x| ≤ 0.65: t = 4.35 through the facet with normal (1, 1, 1)/√3.
#[test]
fn ex_hit_polyhedron_octahedron_hits_through_its_facets() {
    let hits = Polyhedron::octahedron().intersect(&ray([5.0, 0.25, 0.1], [-1.0, 0.0, 0.0]));
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits.as_slice()[0].t, 4.35, epsilon = 10.0 * TOL);
    assert_abs_diff_eq!(hits.as_slice()[1].t, 5.65, epsilon = 10.0 * TOL);
    let k = 1.0 / (3.0 as Real).sqrt();
    assert_vec_eq(hits.as_slice()[0].normal, vec3(1.0, 1.0, 1.0) * k, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, vec3(-1.0, 1.0, 1.0) * k, TOL);
}

/// "Convex Polyhedra": the tetrahedron with vertices (1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1),
/// along z at x = 0.2, spans z ∈ [−0.8, 0.8].
#[test]
fn ex_hit_polyhedron_tetrahedron_hits_through_its_facets() {
    let hits = Polyhedron::tetrahedron().intersect(&ray([0.2, 0.0, 5.0], [0.0, 0.0, -1.0]));
    let k = 1.0 / (3.0 as Real).sqrt();
    assert_hits(&hits, &[(4.2, Part::Facet(2)), (5.8, Part::Facet(3))]);
    assert_vec_eq(hits.as_slice()[0].normal, vec3(1.0, -1.0, 1.0) * k, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, vec3(1.0, 1.0, -1.0) * k, TOL);
    // every preset's vertices satisfy n·P ≤ d with equality on three or more facets
    let vertices = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    for v in vertices {
        let p = vec3(v[0], v[1], v[2]);
        let on = Polyhedron::tetrahedron()
            .facets()
            .iter()
            .filter(|f| (f.normal().dot(p) - f.d()).abs() <= TOL)
            .count();
        assert_eq!(on, 3);
    }
}

// --- placement ----------------------------------------------------------------------------

fn ellipsoid() -> Object {
    let steps = [
        Step::Scale(vec3(2.0, 0.5, 1.0)),
        Step::RotateZ(30.0),
        Step::Translate(vec3(1.0, -2.0, 3.0)),
    ];
    Object::new(Shape::Sphere, Placement::from_steps(&steps).unwrap())
}

/// "Ray Tracing Process": M⁻¹ is built from the inverse steps; M·M⁻¹ = I.
#[test]
fn ex_placement_from_steps_inverse_from_inverse_steps_undoes_the_placement() {
    let o = ellipsoid();
    let product = o.placement.m() * o.placement.inv();
    assert!(
        product.abs_diff_eq(Mat4::IDENTITY, 10.0 * TOL),
        "{product:?}"
    );
    // steps apply in order: scale first, so the scale stretches the object's own x axis
    let p = o.placement.m().transform_point3(Vec3::X);
    let a = (30.0 as Real).to_radians();
    assert_vec_eq(
        p,
        Vec3::new(2.0 * a.cos() + 1.0, 2.0 * a.sin() - 2.0, 3.0),
        10.0 * TOL,
    );
}

/// "Ray Tracing Process": M⁻¹d is not renormalised, so the t that `Shape::intersect_placed`
/// finds in object space gives the same point in world space: M·(M⁻¹e + M⁻¹d·t) = e + d·t,
/// under a non-uniform scale.
#[test]
fn ex_hit_placed_shape_t_is_the_same_in_world_and_object_space() {
    let o = ellipsoid();
    let world = ray([-4.0, -1.0, 2.5], [3.0, -0.5, 0.2]);
    let local = world.transformed(o.placement.inv());
    assert!(
        (local.dir.length() - world.dir.length()).abs() > 0.1,
        "the scale changes |d|"
    );
    let hits = o.intersect_object_space(&world, Numerics::Robust); // Shape::intersect_placed
    assert_eq!(hits.len(), 2);
    for h in hits.as_slice() {
        let p_world = world.at(h.t);
        let p_object = local.at(h.t);
        assert_abs_diff_eq!(p_object.length(), 1.0, epsilon = 100.0 * TOL); // on the unit sphere
        assert_vec_eq(
            o.placement.m().transform_point3(p_object),
            p_world,
            100.0 * TOL,
        );
    }
    // renormalising M⁻¹d would change t: the hit would no longer be at world.at(t)
    let renormalised = Ray::new(local.origin, local.dir.normalize());
    let t_bad = sphere::intersect(&renormalised, Numerics::Robust).as_slice()[0].t;
    let miss = o.placement.inv().transform_point3(world.at(t_bad)).length();
    assert!(
        (miss - 1.0).abs() > 0.1,
        "renormalised t lands off the surface ({miss})"
    );
}

/// "Ray Tracing Process": a sphere of radius 2 centred at (0, 0, −10) (scale 2, then translate)
/// seen from the origin along d = (0, 0, −2): the world points (0, 0, −8) and (0, 0, −12) are
/// at the world ray's t = 4 and 6, and their object-space normals are (0, 0, ±1).
#[test]
fn ex_hit_placed_shape_a_placed_shape_is_hit_at_the_world_rays_t() {
    let placement = Placement::from_steps(&[
        Step::Scale(Vec3::splat(2.0)),
        Step::Translate(vec3(0.0, 0.0, -10.0)),
    ])
    .unwrap();
    let world = ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0]);
    let hits = Shape::Sphere.intersect_placed(placement.inv(), &world, Numerics::Robust);
    assert_hits(&hits, &[(4.0, Part::Surface), (6.0, Part::Surface)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Z, TOL);
}

/// "Surface Normals at Intersections": n = (M⁻¹)ᵀ·n′, made unit. Under the scale (2, 1, 1),
/// (M⁻¹)ᵀ = diag(½, 1, 1): n′ = (1, 1, 0)/√2 gives (½, 1, 0) ∝ (1, 2, 0)/√5, and a translation
/// after it changes nothing; a quarter turn about z turns (1, 0, 0) into (0, 1, 0); the identity
/// makes the cone's (0, −1, 1) unit.
#[test]
fn ex_normal_to_world_normals_go_back_by_the_inverse_transpose() {
    let s = (2.0 as Real).sqrt();
    let stretched = Placement::from_steps(&[Step::Scale(vec3(2.0, 1.0, 1.0))]).unwrap();
    let expected = vec3(1.0, 2.0, 0.0) / (5.0 as Real).sqrt();
    assert_vec_eq(
        stretched.normal_to_world(vec3(1.0, 1.0, 0.0) / s),
        expected,
        TOL,
    );
    let moved = Placement::from_steps(&[
        Step::Scale(vec3(2.0, 1.0, 1.0)),
        Step::Translate(vec3(5.0, -3.0, 2.0)),
    ])
    .unwrap();
    assert_vec_eq(
        moved.normal_to_world(vec3(1.0, 1.0, 0.0) / s),
        expected,
        TOL,
    );
    let turned = Placement::from_steps(&[Step::RotateZ(90.0)]).unwrap();
    assert_vec_eq(turned.normal_to_world(Vec3::X), Vec3::Y, TOL);
    assert_vec_eq(
        Placement::identity().normal_to_world(vec3(0.0, -1.0, 1.0)),
        vec3(0.0, -1.0, 1.0) / s,
        TOL,
    );
}

/// "Surface Normals at Intersections" and "Ray Tracing Process": under the non-uniform scale
/// (2, 1, 1), the object-space normal n′ = (1, 1, 0)/√2 at P′ = n′ becomes (M⁻¹)ᵀn′ ∝ (1, 2, 0),
/// perpendicular to the surface; M·n′ ∝ (2, 1, 0) is not.
#[test]
fn ex_normal_to_world_normal_under_non_uniform_scale_uses_inverse_transpose() {
    let o = Object::new(
        Shape::Sphere,
        Placement::from_steps(&[Step::Scale(vec3(2.0, 1.0, 1.0))]).unwrap(),
    );
    let s = (2.0 as Real).sqrt();
    let p_world = Vec3::new(s, 1.0 / s, 0.0); // M·(1/√2, 1/√2, 0)
    let r = Ray::new(p_world + vec3(1.0, 2.0, 0.0), vec3(-1.0, -2.0, 0.0));
    let hit = o.intersect(&r, Numerics::Robust).as_slice()[0];
    assert_abs_diff_eq!(hit.t, 1.0, epsilon = 10.0 * TOL);
    let right = vec3(1.0, 2.0, 0.0) / (5.0 as Real).sqrt();
    assert_vec_eq(hit.normal, right, 10.0 * TOL);
    // the tangent at P: M·(−1/√2, 1/√2, 0)
    let tangent = Vec3::new(-s, 1.0 / s, 0.0);
    assert_abs_diff_eq!(hit.normal.dot(tangent), 0.0, epsilon = 10.0 * TOL);
    let wrong = o
        .placement
        .m()
        .transform_vector3(vec3(1.0, 1.0, 0.0) / s)
        .normalize();
    assert!(
        wrong.dot(tangent).abs() > 0.3,
        "M·n′ is not perpendicular to the surface"
    );
    assert!((wrong - right).length() > 0.3);
}

/// "Ray Tracing Process": a placed cylinder (base, top, radius) is hit where the placement says.
#[test]
fn placed_cylinder_from_base_top_radius() {
    let scene = whitted::scene::parse(
        "[[objects]]\ncylinder = { base = [0.0, 0.0, 0.0], top = [0.0, 4.0, 0.0], radius = 0.5 }\n",
        "t.toml",
    )
    .unwrap();
    let o = &scene.objects[0];
    // along x at height 1: wall at x = ∓0.5
    let hits = o.intersect(&ray([-3.0, 1.0, 0.0], [1.0, 0.0, 0.0]), Numerics::Robust);
    assert_hits(&hits, &[(2.5, Part::Wall), (3.5, Part::Wall)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_X, TOL);
    // down the axis: top cap at y = 4, bottom at y = 0
    let hits = o.intersect(&ray([0.1, 10.0, 0.0], [0.0, -1.0, 0.0]), Numerics::Robust);
    assert_hits(&hits, &[(6.0, Part::TopCap), (10.0, Part::BottomCap)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Y, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Y, TOL);
}

/// "Ray Tracing Process": a zero scale has no inverse; the placement refuses it.
#[test]
fn ex_placement_from_steps_zero_scale_is_not_invertible() {
    assert!(Placement::from_steps(&[Step::Scale(vec3(1.0, 0.0, 1.0))]).is_none());
    assert!(Placement::from_steps(&[Step::Scale(Vec3::new(1.0, Real::NAN, 1.0))]).is_none());
    assert!(Placement::from_steps(&[Step::Scale(vec3(1.0, 2.0, 1.0))]).is_some());
}

/// "Generic Cone": a ray touching the wall at z = 0 (radius 1) has b² − ac = 0 and grazes once,
/// with the wall normal (x, y, 1 − z) there.
#[test]
fn ex_hit_cone_cone_tangent_ray_grazes_once() {
    let r = ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]);
    let (a, b, c) = cone::coefficients(&r);
    assert_abs_diff_eq!(b * b - a * c, 0.0, epsilon = TOL);
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cone::intersect(&r, numerics);
        assert_hits(&hits, &[(5.0, Part::Wall)]);
        assert_vec_eq(
            unit(hits.as_slice()[0].normal),
            vec3(1.0, 0.0, 1.0) * k,
            TOL,
        );
    }
    assert!(cone::intersect(&ray([1.2, -5.0, 0.0], [0.0, 1.0, 0.0]), Numerics::Robust).is_empty());
}

/// "Convex Polyhedra": a ray across an edge of the cube enters (facet +z) and leaves (facet +x)
/// at the same t: t_near = t_far, one grazing hit; a little further out it misses
/// (t_near > t_far).
#[test]
fn ex_hit_polyhedron_polyhedron_ray_across_an_edge_grazes_once() {
    let cube = Polyhedron::cube();
    let hits = cube.intersect(&ray([0.0, 0.0, 2.0], [1.0, 0.0, -1.0]));
    assert_hits(&hits, &[(1.0, Part::Facet(4))]);
    assert!(
        cube.intersect(&ray([0.5, 0.0, 2.5], [1.0, 0.0, -1.0]))
            .is_empty()
    );
}

/// "Convex Polyhedra": the presets are closed solids; their corners are where three facets meet.
#[test]
fn presets_are_closed_solids_with_the_expected_corners() {
    let distinct = |p: &Polyhedron| {
        let mut v: Vec<Vec3> = Vec::new();
        for q in p.vertices() {
            if v.iter().all(|w| (*w - q).length() > 1e3 * TOL) {
                v.push(q);
            }
        }
        v
    };
    for (p, corners) in [
        (Polyhedron::cube(), 8),
        (Polyhedron::tetrahedron(), 4),
        (Polyhedron::octahedron(), 6),
    ] {
        assert_eq!(p.check(), Ok(()));
        let v = distinct(&p);
        assert_eq!(v.len(), corners, "{v:?}");
        for q in v {
            assert_abs_diff_eq!(q.abs().max_element(), 1.0, epsilon = 1e3 * TOL); // corners on the unit cube's surface
        }
    }
}

/// "Convex Polyhedra": facets that leave a direction open, contradict each other, or squeeze
/// the solid flat describe no polyhedron; `check` says which.
#[test]
fn open_empty_or_flat_facet_sets_are_not_polyhedra() {
    let from = |rows: &[[f64; 4]]| {
        Polyhedron::new(
            rows.iter()
                .map(|r| polyhedron::Facet::new(vec3(r[0], r[1], r[2]), r[3] as Real).unwrap())
                .collect(),
        )
    };
    let open = from(&[
        [0.0, -1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0, 1.0],
        [-1.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 0.5],
    ]);
    assert!(open.check().unwrap_err().contains("unbounded"));
    let empty = from(&[
        [1.0, 0.0, 0.0, -1.0],
        [-1.0, 0.0, 0.0, -1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, -1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [0.0, 0.0, -1.0, 1.0],
    ]);
    assert!(empty.check().unwrap_err().contains("no solid"));
    let flat = from(&[
        [1.0, 0.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, -1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [0.0, 0.0, -1.0, 1.0],
    ]);
    assert!(flat.check().unwrap_err().contains("flat"));
}

/// "Generic Cone" (erratum: the base radius): at z = −1 the wall reaches x² + y² = (1 + 1)² = 4,
/// so the base it closes on has radius 2. A ray from below at x = 1.5 enters through the base
/// (a unit disc would let it into a hole) and leaves through the wall where 1 − z = 1.5.
#[test]
fn ex_hit_cone_cone_base_has_radius_two() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        let hits = cone::intersect(&ray([1.5, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics);
        assert_hits(&hits, &[(2.0, Part::Base), (2.5, Part::Wall)]);
        assert_vec_eq(
            unit(hits.as_slice()[1].normal),
            vec3(1.0, 0.0, 1.0) * k,
            TOL,
        );
        // just outside the radius-2 base: a miss
        assert!(cone::intersect(&ray([2.01, 0.0, -3.0], [0.0, 0.0, 1.0]), numerics).is_empty());
    }
}

/// "Ray Tracing Process": the placement form `cone = { base, apex, radius }` puts a base of the
/// given radius on `base` and the apex on `apex`.
#[test]
fn placed_cone_from_base_apex_radius() {
    let scene = whitted::scene::parse(
        "[[objects]]\ncone = { base = [0.0, 0.0, 0.0], apex = [0.0, 3.0, 0.0], radius = 0.5 }\n",
        "t.toml",
    )
    .unwrap();
    let o = &scene.objects[0];
    // along x just above the floor: the wall at radius 0.5·(1 − 0.3/3) = 0.45
    let hits = o.intersect(&ray([-3.0, 0.3, 0.0], [1.0, 0.0, 0.0]), Numerics::Robust);
    assert_hits(&hits, &[(2.55, Part::Wall), (3.45, Part::Wall)]);
    // up the axis from below: base at y = 0, apex at y = 3
    let hits = o.intersect(&ray([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]), Numerics::Robust);
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits.as_slice()[0].t, 1.0, epsilon = 10.0 * TOL);
    assert_eq!(hits.as_slice()[0].part, Part::Base);
    assert_abs_diff_eq!(hits.as_slice()[1].t, 4.0, epsilon = 10.0 * TOL);
}

// --- the nearest hit (step 5) ------------------------------------------------------------

/// Three spheres on the axis of a camera at the origin looking down −z, listed far, behind,
/// near (so the answer cannot come from the order alone).
const THREE_SPHERES: &str = "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n\
    [materials.far]\ndiffuse = [0.0, 0.0, 1.0]\n[materials.behind]\ndiffuse = [0.0, 1.0, 0.0]\n\
    [materials.near]\ndiffuse = [1.0, 0.0, 0.0]\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, -10.0], radius = 1.0 }\nmaterial = \"far\"\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, 5.0], radius = 2.0 }\nmaterial = \"behind\"\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, -5.0], radius = 1.0 }\nmaterial = \"near\"\n";

/// "Ray Tracing Process", step 5: of all the hits the visible one has the smallest t > 0.
/// Along r(t) = (0, 0, −2t), |r(t) − c|² = ρ² gives by hand: the far sphere (c_z = −10, ρ = 1)
/// (10 − 2t)² = 1, t = 4.5 or 5.5; the near one (c_z = −5, ρ = 1) (5 − 2t)² = 1, t = 2 or 3;
/// the one behind the eye (c_z = 5, ρ = 2) (5 + 2t)² = 4, t = −1.5 or −3.5, both < 0. The
/// near sphere (object 2) wins at t = 2 with normal +z; from t_min = 2.5 its far side (t = 3,
/// leaving, normal −z); from t_min = 3.5 the far sphere at t = 4.5; for every accelerator.
#[test]
fn nearest_hit_has_the_smallest_positive_t() {
    let s = scene(THREE_SPHERES);
    let ray = ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0]);
    for accel in Accel::ALL {
        let mut o = Options::for_scene(&s, Chapter::GenericObjects);
        o.accel = accel;
        let tracer = Tracer::new(&s, &o);
        let near = tracer
            .nearest(&ray, 0.0)
            .expect("the near sphere is in front");
        assert_eq!(near.object, 2, "{accel:?}");
        assert_abs_diff_eq!(near.hit.t, 2.0, epsilon = 10.0 * TOL);
        assert_vec_eq(near.hit.normal, Vec3::Z, 10.0 * TOL);
        assert!(near.hit.entering);
        let inside = tracer.nearest(&ray, 2.5).unwrap();
        assert_eq!(inside.object, 2, "{accel:?}");
        assert_abs_diff_eq!(inside.hit.t, 3.0, epsilon = 10.0 * TOL);
        assert_vec_eq(inside.hit.normal, Vec3::NEG_Z, 10.0 * TOL);
        assert!(!inside.hit.entering);
        let beyond = tracer.nearest(&ray, 3.5).unwrap();
        assert_eq!(beyond.object, 0, "{accel:?}");
        assert_abs_diff_eq!(beyond.hit.t, 4.5, epsilon = 10.0 * TOL);
        assert!(tracer.nearest(&ray, 5.5).is_none(), "{accel:?}");
    }
    // the chapter-2 image shows the near sphere's flat colour ρd
    let (c, _) = centre(&s, Chapter::GenericObjects);
    assert_vec_eq(c, vec3(1.0, 0.0, 0.0), 0.0);
}

/// "Ray Tracing Process", step 5 for one object: of its hits at t = 2 (entering) and t = 5
/// (leaving), a ray from t_min sees the first one past t_min: the one at 2 from t_min = −10 or
/// 0, the one at 5 from 2 (a hit at exactly t_min does not count) or 3, none from 5 on.
#[test]
fn ex_visible_hit_the_visible_hit_is_the_first_after_t_min() {
    let at = |t: Real, entering: bool| Hit {
        t,
        normal: Vec3::Z,
        part: Part::Surface,
        entering,
    };
    let hits = Hits::two(at(2.0, true), at(5.0, false));
    assert_eq!(hits.first_after(-10.0), Some(at(2.0, true)));
    assert_eq!(hits.first_after(0.0), Some(at(2.0, true)));
    assert_eq!(hits.first_after(2.0), Some(at(5.0, false)));
    assert_eq!(hits.first_after(3.0), Some(at(5.0, false)));
    assert_eq!(hits.first_after(5.0), None);
    assert_eq!(Hits::one(at(-1.0, true)).first_after(0.0), None);
    assert_eq!(Hits::none().first_after(0.0), None);
}

/// "Ray Tracing Process", step 5 (the tie rule of `shapes::nearer`): a smaller t wins whatever
/// the order; of two hits at the same t, the object listed first.
#[test]
fn ex_nearer_hit_equal_t_goes_to_the_object_listed_first() {
    assert!(nearer(2.0, 0, 2.0, 1));
    assert!(!nearer(2.0, 1, 2.0, 0));
    assert!(!nearer(2.0, 3, 2.0, 3));
    assert!(nearer(1.5, 7, 2.0, 0));
    assert!(!nearer(2.5, 0, 2.0, 7));
    assert!(nearer(1e9, usize::MAX, Real::INFINITY, 0)); // anything beats "no hit yet"
}

/// Two coincident unit spheres of different materials at (0, 0, −5), seen along the camera's
/// axis.
fn coincident(first: &str, second: &str) -> String {
    format!(
        "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n\
         [materials.red]\ndiffuse = [1.0, 0.0, 0.0]\n[materials.green]\ndiffuse = [0.0, 1.0, 0.0]\n\
         [[objects]]\nsphere = {{ center = [0.0, 0.0, -5.0] }}\nmaterial = \"{first}\"\n\
         [[objects]]\nsphere = {{ center = [0.0, 0.0, -5.0] }}\nmaterial = \"{second}\"\n"
    )
}

/// "Ray Tracing Process", step 5: two coincident spheres are hit at the same t = 4 (|(0, 0, −t)
/// − (0, 0, −5)| = 1); the one listed first shows, red before green or green before red, for
/// every accelerator, in the rendered 1 × 1 image and through `Tracer::nearest`.
#[test]
fn coincident_objects_show_the_first_listed_for_every_accel() {
    for (first, second, colour) in [
        ("red", "green", vec3(1.0, 0.0, 0.0)),
        ("green", "red", vec3(0.0, 1.0, 0.0)),
    ] {
        let s = scene(&coincident(first, second));
        for accel in Accel::ALL {
            let mut o = Options::for_scene(&s, Chapter::GenericObjects);
            (o.width, o.height, o.accel) = (1, 1, accel);
            let (fb, _) = render_both_ways(&s, &o);
            assert_eq!(fb.pixels[0], colour, "{first} first, {accel:?}");
            let near = Tracer::new(&s, &o)
                .nearest(&ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]), 0.0)
                .unwrap();
            assert_eq!(near.object, 0, "{first} first, {accel:?}");
            assert_abs_diff_eq!(near.hit.t, 4.0, epsilon = 10.0 * TOL);
        }
    }
}

/// "Convex Polyhedra": a facet with n·d < 0 is crossed from outside to inside, one with n·d > 0
/// from inside to outside. On the triangular prism y ≥ 0, x + y ≤ 2, −x + y ≤ 2, |z| ≤ 1
/// (facets 0–4, normals (0, −1, 0), (1, 1, 0)/√2, (−1, 1, 0)/√2, ±z; the slanted facets have
/// d = 2/√2), t = (d − n·e)/(n·d), written below with the √2 of the slanted facets cancelled:
/// - e = (5, 0.5, 0), d = (−1, 0, 0): facet 1 has n·d = −1/√2 < 0, t = (2 − 5.5)/(−1) = 3.5
///   (x = 1.5), entering; facet 2 has n·d = 1/√2 > 0, t = (2 − (−4.5))/1 = 6.5 (x = −1.5),
///   leaving; facet 0 and the caps are parallel with e inside them.
/// - e = (0.5, −3, 0.2), d = (0, 2, 0): facet 0 n·d = −2, t = (0 − 3)/(−2) = 1.5 (y = 0),
///   entering; facet 1 n·d = 2/√2, t = (2 − (−2.5))/2 = 2.25 (y = 1.5), leaving; facet 2
///   t = (2 − (−3.5))/2 = 2.75 comes later and does not bound the ray.
/// - from inside, e = (0.5, 0.5, 0), d = (1, 0, 0): entering through facet 2 behind the origin
///   at t = (2 − 0)/(−1) = −2 (x = −1.5), leaving through facet 1 at t = (2 − 1)/1 = 1.
#[test]
fn ex_hit_polyhedron_polyhedron_enters_where_n_dot_d_is_negative_and_leaves_where_positive() {
    let facet =
        |n: [f64; 3], d: f64| polyhedron::Facet::new(vec3(n[0], n[1], n[2]), d as Real).unwrap();
    let prism = Polyhedron::new(vec![
        facet([0.0, -1.0, 0.0], 0.0),
        facet([1.0, 1.0, 0.0], 2.0),
        facet([-1.0, 1.0, 0.0], 2.0),
        facet([0.0, 0.0, 1.0], 1.0),
        facet([0.0, 0.0, -1.0], 1.0),
    ]);
    assert_eq!(prism.check(), Ok(()));
    let k = 1.0 / (2.0 as Real).sqrt();
    let (n1, n2) = (vec3(1.0, 1.0, 0.0) * k, vec3(-1.0, 1.0, 0.0) * k);
    let cases = [
        (
            ray([5.0, 0.5, 0.0], [-1.0, 0.0, 0.0]),
            [(3.5, 1, n1), (6.5, 2, n2)],
        ),
        (
            ray([0.5, -3.0, 0.2], [0.0, 2.0, 0.0]),
            [(1.5, 0, Vec3::NEG_Y), (2.25, 1, n1)],
        ),
        (
            ray([0.5, 0.5, 0.0], [1.0, 0.0, 0.0]),
            [(-2.0, 2, n2), (1.0, 1, n1)],
        ),
    ];
    for (r, expected) in cases {
        let hits = prism.intersect(&r);
        assert_hits(
            &hits,
            &[
                (expected[0].0, Part::Facet(expected[0].1)),
                (expected[1].0, Part::Facet(expected[1].1)),
            ],
        );
        let [enter, leave] = [hits.as_slice()[0], hits.as_slice()[1]];
        assert_vec_eq(enter.normal, expected[0].2, TOL);
        assert_vec_eq(leave.normal, expected[1].2, TOL);
        assert!(enter.entering && enter.normal.dot(r.dir) < 0.0, "{r:?}");
        assert!(!leave.entering && leave.normal.dot(r.dir) > 0.0, "{r:?}");
    }
}

// --- exact quarter turns -----------------------------------------------------------------

/// True when every entry of `m` is exactly 0, 1 or −1.
fn entries_are_exactly_0_or_1(m: &Mat4) -> bool {
    m.to_cols_array()
        .iter()
        .all(|&x| x == 0.0 || x.abs() == 1.0)
}

/// "Ray Tracing Process" (q = M·q′): a rotation by a whole multiple of 90° has sine and cosine
/// exactly 0 and ±1, so M and M⁻¹ hold nothing else: sin 90° = 1, cos 90° = 0 (where
/// `to_radians().sin_cos()` gives cos 90° = 6.1e-17 in f64, −4.4e-8 in f32); −90° → (−1, 0);
/// 180° → (0, −1); 270° → (−1, 0); 450° = 360° + 90° → (1, 0). Turning +z onto ±x, ±y and −z
/// gives such matrices, which carry +z exactly onto the target and multiply to I exactly.
#[test]
fn ex_placement_from_steps_rotations_by_multiples_of_90_degrees_are_exact() {
    assert_eq!(sin_cos_degrees(90.0), (1.0, 0.0));
    assert_eq!(sin_cos_degrees(-90.0), (-1.0, 0.0));
    assert_eq!(sin_cos_degrees(180.0), (0.0, -1.0));
    assert_eq!(sin_cos_degrees(270.0), (-1.0, 0.0));
    assert_eq!(sin_cos_degrees(450.0), (1.0, 0.0));
    assert_eq!(sin_cos_degrees(-360.0), (0.0, 1.0));
    assert_ne!(
        (90.0 as Real).to_radians().cos(),
        0.0,
        "why the special case exists"
    );
    for to in [
        Vec3::X,
        Vec3::NEG_X,
        Vec3::Y,
        Vec3::NEG_Y,
        Vec3::NEG_Z,
        Vec3::Z,
    ] {
        let step = rotation_from_z(to);
        let placement = Placement::from_steps(&[step]).unwrap();
        for m in [step.matrix(), *placement.m(), *placement.inv()] {
            assert!(entries_are_exactly_0_or_1(&m), "+z → {to}: {m:?}");
        }
        assert_eq!(placement.m().transform_vector3(Vec3::Z), to);
        assert_eq!(placement.inv().transform_vector3(to), Vec3::Z);
        assert_eq!(*placement.m() * *placement.inv(), Mat4::IDENTITY);
    }
}

/// The floor `plane = { point = [0, 0, 0], normal = [0, 1, 0] }` seen from a camera at
/// y = 1 looking at (0, 1, `look_z`).
fn floor_scene(look_z: f64) -> String {
    format!(
        "[camera]\neye = [0.0, 1.0, 0.0]\nlook_at = [0.0, 1.0, {look_z}]\n\
         [image]\nbackground = [0.0, 0.2, 0.8]\n[materials.floor]\ndiffuse = [0.9, 0.6, 0.1]\n\
         [[objects]]\nplane = {{ point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }}\nmaterial = \"floor\"\n"
    )
}

/// "Generic Plane" placed by "Ray Tracing Process": with normal (0, 1, 0) the plane is the
/// generic z = 0 turned by −90° about x, exactly, so a world ray with d_y = 0 has d_z = 0 in
/// object space and misses ("if d_z = 0 the ray is parallel"), in f64 and f32 alike: along ±x
/// and ±z, at heights 1 and 10⁻³. A camera at y = 1 looking along −z (and one looking along
/// +z) sees it on no pixel of the middle row of a 5 × 3 image (v_r = H(2·1.5/3 − 1) = 0, so
/// d_y = 0), and on every pixel of the bottom row (v_r = −2H/3, the floor at distance
/// 1/(2H/3) ≈ 2.6); the top row is background too. Before rotations by quarter turns were
/// made exact, cos 90° ≠ 0 tilted the floor, and the middle row on one side met it about
/// 1/cos 90° away, 10¹⁶–10¹⁷ in f64 and 10⁷–10⁸ in f32: floor colour where the horizon
/// should be.
#[test]
fn ray_parallel_to_a_placed_floor_misses_it() {
    let s = scene(&floor_scene(-1.0));
    let floor = &s.objects[0];
    for y in [1.0, 1e-3] {
        for d in [
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ] {
            let hits = floor.intersect(&ray([0.3, y, -0.7], d), Numerics::Robust);
            assert!(hits.is_empty(), "y = {y}, d = {d:?}: {hits:?}");
        }
        // the same floor turned by the inexact angle: some parallel ray meets it very far away
        let inexact = Mat4::from_rotation_x((90.0 as Real).to_radians()); // M⁻¹ of −90° about x
        let far = [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
            .iter()
            .flat_map(|&d| {
                Shape::Plane
                    .intersect_placed(&inexact, &ray([0.3, y, -0.7], d), Numerics::Robust)
                    .as_slice()
                    .to_vec()
            })
            .filter(|h| h.t > 0.0)
            .map(|h| h.t)
            .fold(0.0, Real::max);
        assert!(far > 1e4, "y = {y}: the inexact floor is met at t = {far}");
    }
    let (sky, ground) = (vec3(0.0, 0.2, 0.8), vec3(0.9, 0.6, 0.1));
    for look_z in [-1.0, 1.0] {
        let (fb, _) = render_at(&scene(&floor_scene(look_z)), Chapter::GenericObjects, 5, 3);
        for x in 0..5 {
            assert_eq!(
                fb.get(x, 0),
                sky,
                "top row, column {x}, looking at z = {look_z}"
            );
            assert_eq!(
                fb.get(x, 1),
                sky,
                "middle row, column {x}, looking at z = {look_z}"
            );
            assert_eq!(
                fb.get(x, 2),
                ground,
                "bottom row, column {x}, looking at z = {look_z}"
            );
        }
    }
}
