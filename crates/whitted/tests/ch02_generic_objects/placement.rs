//! Placement: the steps' matrices and their inverses (M, M⁻¹), rays into object space, a point of a ray, placed shapes hit at the world ray's t, normals back by (M⁻¹)ᵀ ("Ray Tracing Process", "Surface Normals at Intersections").

use super::*;
use whitted::shapes::sphere;

/// Places by the steps, which must make a placement; `what` names them in messages.
#[track_caller]
fn placed(steps: &[Step], what: &str) -> Placement {
    Placement::from_steps(steps)
        .unwrap_or_else(|| panic!("Placement::from_steps gave none for {what}: {steps:?}"))
}

/// Asserts the 4 × 4 matrix `m` is the identity within `tol`; `what` names the product.
#[track_caller]
fn assert_identity(what: &str, m: Mat4, tol: Real) {
    assert!(
        m.abs_diff_eq(Mat4::IDENTITY, tol),
        "{what}: computed {m}, expected the identity (tolerance {tol:e} per entry)"
    );
}

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
    assert_vec_eq(
        "S·(1, 1, 1) for a scale by (2, 3, 4)",
        scale.transform_point3(Vec3::ONE),
        vec3(2.0, 3.0, 4.0),
        TOL,
    );
    let turn = |step: Step, v: Vec3| step.matrix().transform_vector3(v);
    // quarter turns are exact: sin_cos_degrees gives 0 and ±1
    for (step, v, expected) in [
        (Step::RotateZ(90.0), Vec3::X, Vec3::Y),
        (Step::RotateX(90.0), Vec3::Y, Vec3::Z),
        (Step::RotateX(90.0), Vec3::Z, Vec3::NEG_Y),
        (Step::RotateY(90.0), Vec3::Z, Vec3::X),
    ] {
        assert_eq!(
            turn(step, v),
            expected,
            "S·{v} for {step:?}, exactly (sin_cos_degrees)"
        );
    }
    let r3 = (3.0 as Real).sqrt();
    let third = Step::RotateAxis(Vec3::ONE, 120.0);
    for (step, v, expected, tol) in [
        (
            Step::RotateZ(30.0),
            Vec3::X,
            Vec3::new(r3 / 2.0, 0.5, 0.0),
            TOL,
        ),
        (
            Step::RotateY(-30.0),
            Vec3::X,
            Vec3::new(r3 / 2.0, 0.0, 0.5),
            TOL,
        ),
        (
            Step::RotateAxis(vec3(0.0, 0.0, 2.0), 90.0),
            Vec3::X,
            Vec3::Y,
            TOL,
        ),
        (third, Vec3::X, Vec3::Y, 10.0 * TOL),
        (third, Vec3::Y, Vec3::Z, 10.0 * TOL),
        (third, Vec3::Z, Vec3::X, 10.0 * TOL),
    ] {
        assert_vec_eq(&format!("S·{v} for {step:?}"), turn(step, v), expected, tol);
    }
    let t = vec3(1.0, -2.0, 3.0);
    let shift = Step::Translate(t).matrix();
    assert_vec_eq(
        "S·(0, 0, 0) as a point, for a translation by (1, −2, 3)",
        shift.transform_point3(Vec3::ZERO),
        t,
        TOL,
    );
    assert_vec_eq(
        "S·(1, 1, 1) as a point, for a translation by (1, −2, 3)",
        shift.transform_point3(Vec3::ONE),
        vec3(2.0, -1.0, 4.0),
        TOL,
    );
    assert_vec_eq(
        "S·x as a direction, for a translation by (1, −2, 3); expected x, unmoved",
        shift.transform_vector3(Vec3::X),
        Vec3::X,
        TOL,
    );
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
        assert_eq!(step.inverse(), inverse, "the inverse of {step:?}");
        assert_identity(
            &format!("S·S⁻¹ for {step:?}"),
            step.matrix() * step.inverse().matrix(),
            10.0 * TOL,
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
    let by = "by M⁻¹ = a scale by (2, 1, ½) then a translation by (1, 2, 3)";
    assert_vec_eq(
        &format!("M⁻¹e for e = (1, 1, 1) {by} (moved as a point)"),
        local.origin,
        vec3(3.0, 3.0, 3.5),
        TOL,
    );
    assert_vec_eq(
        &format!("M⁻¹d for d = (3, 1, 0) {by} (moved as a vector, not renormalised)"),
        local.dir,
        vec3(6.0, 1.0, 0.0),
        TOL,
    );
    for t in [-1.0, 0.5, 2.0] {
        let on_world = world.origin + world.dir * t;
        assert_vec_eq(
            &format!("M⁻¹e + M⁻¹d·t at t = {t}; expected M⁻¹ of the world ray's point"),
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
    for (t, expected) in [
        (0.0, vec3(1.0, 2.0, 3.0)),
        (1.0, vec3(1.5, 1.0, 5.0)),
        (2.0, vec3(2.0, 0.0, 7.0)),
        (-1.0, vec3(0.5, 3.0, 1.0)),
    ] {
        assert_vec_eq(
            &format!("r({t}) for e = (1, 2, 3), d = (0.5, −1, 2)"),
            r.at(t),
            expected,
            TOL,
        );
    }
}

fn ellipsoid() -> Object {
    let steps = [
        Step::Scale(vec3(2.0, 0.5, 1.0)),
        Step::RotateZ(30.0),
        Step::Translate(vec3(1.0, -2.0, 3.0)),
    ];
    Object::new(
        Shape::Sphere,
        placed(
            &steps,
            "a scale by (2, ½, 1), 30° about z, a move by (1, −2, 3)",
        ),
    )
}

/// "Ray Tracing Process": M⁻¹ is built from the inverse steps; M·M⁻¹ = I.
#[test]
fn ex_placement_from_steps_inverse_from_inverse_steps_undoes_the_placement() {
    let o = ellipsoid();
    let steps = "for a scale by (2, ½, 1), 30° about z, then a move by (1, −2, 3)";
    assert_identity(
        &format!("M·M⁻¹ {steps}"),
        *o.placement.m() * *o.placement.inv(),
        10.0 * TOL,
    );
    // steps apply in order: scale first, so the scale stretches the object's own x axis
    let a = (30.0 as Real).to_radians();
    assert_vec_eq(
        &format!("M·(1, 0, 0) {steps} (the first step acts first: M = S₃·S₂·S₁)"),
        o.placement.m().transform_point3(Vec3::X),
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
    let (world_len, local_len) = (world.dir.length(), local.dir.length());
    assert!(
        (local_len - world_len).abs() > 0.1,
        "the scale changes ‖d‖: ‖M⁻¹d‖ = {local_len}, ‖d‖ = {world_len}"
    );
    let what = "from (−4, −1, 2.5) along (3, −0.5, 0.2) through the placed ellipsoid";
    let hits = o.intersect_object_space(&world, Numerics::Robust); // Shape::intersect_placed
    assert_eq!(
        hits.len(),
        2,
        "the number of hits of the ray {what}: {hits:?}"
    );
    for h in hits.as_slice() {
        let p_world = world.at(h.t);
        let p_object = local.at(h.t);
        assert_near(
            &format!(
                "‖M⁻¹e + M⁻¹d·t‖ at the hit's t = {} {what}; expected on the unit sphere",
                h.t
            ),
            p_object.length(),
            1.0,
            100.0 * TOL,
        );
        assert_vec_eq(
            &format!(
                "M·(M⁻¹e + M⁻¹d·t) at the hit's t = {}; expected e + d·t",
                h.t
            ),
            o.placement.m().transform_point3(p_object),
            p_world,
            100.0 * TOL,
        );
    }
    // renormalising M⁻¹d would change t: the hit would no longer be at world.at(t)
    let renormalised = Ray::new(local.origin, local.dir.normalize());
    let t_bad = nth(
        &sphere::intersect(&renormalised, Numerics::Robust),
        0,
        "M⁻¹ of the world ray, renormalised",
    )
    .t;
    let miss = o.placement.inv().transform_point3(world.at(t_bad)).length();
    assert!(
        (miss - 1.0).abs() > 0.1,
        "a renormalised t = {t_bad} lands off the surface: ‖M⁻¹r(t)‖ = {miss}"
    );
}

/// "Ray Tracing Process": a sphere of radius 2 centred at (0, 0, −10) (scale 2, then translate)
/// seen from the origin along d = (0, 0, −2): the world points (0, 0, −8) and (0, 0, −12) are
/// at the world ray's t = 4 and 6, and their object-space normals are (0, 0, ±1).
#[test]
fn ex_hit_placed_shape_a_placed_shape_is_hit_at_the_world_rays_t() {
    let placement = placed(
        &[
            Step::Scale(Vec3::splat(2.0)),
            Step::Translate(vec3(0.0, 0.0, -10.0)),
        ],
        "a scale by 2, then a move by (0, 0, −10)",
    );
    let what = "from the origin along (0, 0, −2) to the sphere of radius 2 at (0, 0, −10)";
    let world = ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0]);
    let hits = Shape::Sphere.intersect_placed(placement.inv(), &world, Numerics::Robust);
    assert_hits(what, &hits, &[(4.0, Part::Surface), (6.0, Part::Surface)]);
    assert_normal(what, &hits, 0, Vec3::Z, TOL);
    assert_normal(what, &hits, 1, Vec3::NEG_Z, TOL);
}

/// "Surface Normals at Intersections": n = (M⁻¹)ᵀ·n′ points the right way. Under the scale
/// (2, 1, 1), (M⁻¹)ᵀ = diag(½, 1, 1): n′ = (1, 1, 0)/√2 gives (½, 1, 0) ∝ (1, 2, 0), and a
/// translation after it changes nothing; a quarter turn about z turns (1, 0, 0) into
/// (0, 1, 0). Compared as directions, n/‖n‖ (that n is unit is the next test's).
#[test]
fn ex_normal_to_world_normals_go_back_by_the_inverse_transpose() {
    let s = (2.0 as Real).sqrt();
    let n_object = vec3(1.0, 1.0, 0.0) / s;
    let expected = vec3(1.0, 2.0, 0.0) / (5.0 as Real).sqrt();
    let stretched = placed(&[Step::Scale(vec3(2.0, 1.0, 1.0))], "a scale by (2, 1, 1)");
    let moved = placed(
        &[
            Step::Scale(vec3(2.0, 1.0, 1.0)),
            Step::Translate(vec3(5.0, -3.0, 2.0)),
        ],
        "a scale by (2, 1, 1), then a move",
    );
    let turned = placed(&[Step::RotateZ(90.0)], "a quarter turn about z");
    for (placement, n_object, expected, what) in [
        (
            &stretched,
            n_object,
            expected,
            "n′ = (1, 1, 0)/√2 under a scale by (2, 1, 1) ((M⁻¹)ᵀ·n′ ∝ (1, 2, 0); M·n′ would be ∝ (2, 1, 0))",
        ),
        (
            &moved,
            n_object,
            expected,
            "n′ = (1, 1, 0)/√2 under a scale by (2, 1, 1) then a move (a move turns no normal)",
        ),
        (
            &turned,
            Vec3::X,
            Vec3::Y,
            "n′ = (1, 0, 0) under a quarter turn about z",
        ),
    ] {
        let n = placement.normal_to_world(n_object);
        assert_vec_eq(
            &format!("n/‖n‖ for {what} (n = {n})"),
            unit(n),
            expected,
            TOL,
        );
    }
}

/// "Surface Normals at Intersections": n = (M⁻¹)ᵀ·n′ is made unit, whatever the placement
/// does to lengths and whatever the length of n′: (M⁻¹)ᵀ·n′ alone has length √5/(2√2) ≈ 0.79
/// for n′ = (1, 1, 0)/√2 under the scale (2, 1, 1), 1/3 for n′ = z under a scale by 3, and the
/// cone's n′ = (0, −1, 1) has length √2 under the identity.
#[test]
fn ex_normal_to_world_normals_come_back_unit() {
    let s = (2.0 as Real).sqrt();
    for (steps, n_object, what) in [
        (
            vec![Step::Scale(vec3(2.0, 1.0, 1.0))],
            vec3(1.0, 1.0, 0.0) / s,
            "n′ = (1, 1, 0)/√2 under a scale by (2, 1, 1)",
        ),
        (
            vec![Step::Scale(Vec3::splat(3.0)), Step::RotateX(30.0)],
            Vec3::Z,
            "n′ = (0, 0, 1) under a scale by 3, then 30° about x",
        ),
        (
            vec![],
            vec3(0.0, -1.0, 1.0),
            "the cone's n′ = (0, −1, 1) under the identity",
        ),
    ] {
        let n = placed(&steps, what).normal_to_world(n_object);
        assert_near(&format!("‖n‖ for {what} (n = {n})"), n.length(), 1.0, TOL);
    }
    assert_vec_eq(
        "n for the cone's n′ = (0, −1, 1) under the identity; expected (0, −1, 1)/√2",
        Placement::identity().normal_to_world(vec3(0.0, -1.0, 1.0)),
        vec3(0.0, -1.0, 1.0) / s,
        TOL,
    );
}

/// "Surface Normals at Intersections" and "Ray Tracing Process": a hit on a sphere under the
/// non-uniform scale (2, 1, 1) has its normal perpendicular to the surface. At P′ = n′ =
/// (1, 1, 0)/√2, (M⁻¹)ᵀn′ ∝ (1, 2, 0) is perpendicular to the surface's tangent M·(−1, 1, 0)/√2;
/// M·n′ ∝ (2, 1, 0) is not. Compared as directions (that n is unit is another test's).
#[test]
fn ex_normal_to_world_under_a_non_uniform_scale_the_normal_of_a_hit_is_perpendicular_to_the_surface()
 {
    let o = Object::new(
        Shape::Sphere,
        placed(&[Step::Scale(vec3(2.0, 1.0, 1.0))], "a scale by (2, 1, 1)"),
    );
    let s = (2.0 as Real).sqrt();
    let p_world = Vec3::new(s, 1.0 / s, 0.0); // M·(1/√2, 1/√2, 0)
    let r = Ray::new(p_world + vec3(1.0, 2.0, 0.0), vec3(-1.0, -2.0, 0.0));
    let what = "towards P = (√2, 1/√2, 0) on the sphere scaled by (2, 1, 1)";
    let hit = nth(&o.intersect(&r, Numerics::Robust), 0, what);
    assert_near(&format!("t of the hit {what}"), hit.t, 1.0, 10.0 * TOL);
    let right = vec3(1.0, 2.0, 0.0) / (5.0 as Real).sqrt();
    assert_vec_eq(
        &format!(
            "n/‖n‖ at P {what} (n = {}); expected (M⁻¹)ᵀ·n′ made unit, where M·n′ would give (2, 1, 0)/√5",
            hit.normal
        ),
        unit(hit.normal),
        right,
        10.0 * TOL,
    );
    // the tangent at P: M·(−1/√2, 1/√2, 0)
    let tangent = Vec3::new(-s, 1.0 / s, 0.0);
    assert_near(
        &format!("n·tangent at P (n = {}, tangent = {tangent})", hit.normal),
        hit.normal.dot(tangent),
        0.0,
        10.0 * TOL,
    );
    let wrong = o
        .placement
        .m()
        .transform_vector3(vec3(1.0, 1.0, 0.0) / s)
        .normalize();
    assert!(
        wrong.dot(tangent).abs() > 0.3 && (wrong - right).length() > 0.3,
        "M·n′ made unit, {wrong}, is not perpendicular to the surface: its dot product with the \
         tangent is {}",
        wrong.dot(tangent)
    );
}

/// "Ray Tracing Process": a placed cylinder (base, top, radius) is hit where the placement says.
#[test]
fn placed_cylinder_from_base_top_radius() {
    let scene = scene(
        "[[objects]]\ncylinder = { base = [0.0, 0.0, 0.0], top = [0.0, 4.0, 0.0], radius = 0.5 }\n",
    );
    let o = &scene.objects[0];
    // along x at height 1: wall at x = ∓0.5
    let across = "from (−3, 1, 0) along +x across the cylinder from (0, 0, 0) to (0, 4, 0)";
    let hits = o.intersect(&ray([-3.0, 1.0, 0.0], [1.0, 0.0, 0.0]), Numerics::Robust);
    assert_hits(across, &hits, &[(2.5, Part::Wall), (3.5, Part::Wall)]);
    assert_normal(across, &hits, 0, Vec3::NEG_X, TOL);
    // down the axis: top cap at y = 4, bottom at y = 0
    let down = "from (0.1, 10, 0) along −y down the cylinder's axis";
    let hits = o.intersect(&ray([0.1, 10.0, 0.0], [0.0, -1.0, 0.0]), Numerics::Robust);
    assert_hits(down, &hits, &[(6.0, Part::TopCap), (10.0, Part::BottomCap)]);
    assert_normal(down, &hits, 0, Vec3::Y, TOL);
    assert_normal(down, &hits, 1, Vec3::NEG_Y, TOL);
}

/// "Ray Tracing Process": a zero scale has no inverse; the placement refuses it.
#[test]
fn ex_placement_from_steps_zero_scale_is_not_invertible() {
    for (s, invertible) in [
        (vec3(1.0, 0.0, 1.0), false),
        (Vec3::new(1.0, Real::NAN, 1.0), false),
        (vec3(1.0, 2.0, 1.0), true),
    ] {
        let placement = Placement::from_steps(&[Step::Scale(s)]);
        assert_eq!(
            placement.is_some(),
            invertible,
            "the placement of a scale by {s}: {placement:?} (a zero or NaN scale has no inverse)"
        );
    }
}

/// "Ray Tracing Process": the placement form `cone = { base, apex, radius }` puts a base of the
/// given radius on `base` and the apex on `apex`.
#[test]
fn placed_cone_from_base_apex_radius() {
    let scene = scene(
        "[[objects]]\ncone = { base = [0.0, 0.0, 0.0], apex = [0.0, 3.0, 0.0], radius = 0.5 }\n",
    );
    let o = &scene.objects[0];
    // along x just above the floor: the wall at radius 0.5·(1 − 0.3/3) = 0.45
    let hits = o.intersect(&ray([-3.0, 0.3, 0.0], [1.0, 0.0, 0.0]), Numerics::Robust);
    assert_hits(
        "from (−3, 0.3, 0) along +x across the cone from (0, 0, 0) to (0, 3, 0)",
        &hits,
        &[(2.55, Part::Wall), (3.45, Part::Wall)],
    );
    // up the axis from below: base at y = 0, apex at y = 3
    let up = "from (0, −1, 0) along +y up the cone's axis";
    let hits = o.intersect(&ray([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]), Numerics::Robust);
    assert_eq!(
        hits.len(),
        2,
        "the number of hits of the ray {up}: {hits:?}"
    );
    assert_near(
        &format!("t of the first hit {up}"),
        nth(&hits, 0, up).t,
        1.0,
        10.0 * TOL,
    );
    assert_eq!(
        nth(&hits, 0, up).part,
        Part::Base,
        "the part of the first hit {up}"
    );
    assert_near(
        &format!("t of the second hit {up}"),
        nth(&hits, 1, up).t,
        4.0,
        10.0 * TOL,
    );
}

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
    for (theta, expected) in [
        (90.0, (1.0, 0.0)),
        (-90.0, (-1.0, 0.0)),
        (180.0, (0.0, -1.0)),
        (270.0, (-1.0, 0.0)),
        (450.0, (1.0, 0.0)),
        (-360.0, (0.0, 1.0)),
    ] {
        assert_eq!(
            sin_cos_degrees(theta),
            expected,
            "(sin θ, cos θ) for θ = {theta}°, exactly"
        );
    }
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
        let placement = placed(&[step], &format!("the turn of +z onto {to}"));
        for (m, name) in [
            (step.matrix(), "S"),
            (*placement.m(), "M"),
            (*placement.inv(), "M⁻¹"),
        ] {
            assert!(
                entries_are_exactly_0_or_1(&m),
                "{name} of the turn of +z onto {to} = {m}: entries exactly 0 or ±1 expected"
            );
        }
        assert_eq!(
            placement.m().transform_vector3(Vec3::Z),
            to,
            "M·z for the turn of +z onto {to}, exactly"
        );
        assert_eq!(
            placement.inv().transform_vector3(to),
            Vec3::Z,
            "M⁻¹·{to} for the turn of +z onto {to}, exactly"
        );
        assert_eq!(
            *placement.m() * *placement.inv(),
            Mat4::IDENTITY,
            "M·M⁻¹ for the turn of +z onto {to}, exactly"
        );
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
