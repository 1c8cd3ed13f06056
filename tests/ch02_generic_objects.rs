//! Chapter 2 — generic objects (notes: "Ray Tracing Process", "Generic Objects", "Surface
//! Normals at Intersections"): every shape's miss, graze and two-hit cases with hand-computed
//! t and normals, and the placement M, M⁻¹, (M⁻¹)ᵀ.

mod common;

use approx::assert_abs_diff_eq;
use common::{TOL, assert_vec_eq, centre, render_at, render_both_ways, scene};
use whitted::accel::Accel;
use whitted::ray::Ray;
use whitted::real::{Mat4, Real, Vec3, vec3};
use whitted::render::{Options, Stage, Tracer};
use whitted::shapes::quadratic::{Formula, Roots, discriminant, solve};
use whitted::shapes::{
    Hits, Object, Part, Polyhedron, Shape, cone, cylinder, nearer, polyhedron, sphere,
};
use whitted::transform::{Placement, Step, rotation_from_z, sin_cos_degrees};

fn ray(e: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(vec3(e[0], e[1], e[2]), vec3(d[0], d[1], d[2]))
}

fn generic(shape: Shape) -> Object {
    Object::new(shape, Placement::identity())
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

// --- the quadratic ------------------------------------------------------------------------

/// "Generic Sphere": t = −b/a ± √(b² − ac)/a; b² − ac < 0 no root, = 0 one, > 0 two.
#[test]
fn quadratic_has_no_one_or_two_roots_by_the_sign_of_b2_minus_ac() {
    for formula in [Formula::Textbook, Formula::Robust] {
        assert_eq!(solve(1.0, 0.0, 1.0, formula), Roots::None); // t² + 1
        assert_eq!(solve(1.0, -2.0, 4.0, formula), Roots::One(2.0)); // t² − 4t + 4
        match solve(1.0, -5.0, 24.0, formula) {
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

// --- sphere -------------------------------------------------------------------------------

/// "Generic Sphere": a = |d|², b = e·d, c = |e|² − 1.
#[test]
fn sphere_coefficients_are_d_squared_e_dot_d_and_e_squared_minus_one() {
    let (a, b, c) = sphere::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, 5.25, epsilon = TOL); // 0.25 + 1 + 4
    assert_abs_diff_eq!(b, 4.5, epsilon = TOL); // 0.5 − 2 + 6
    assert_abs_diff_eq!(c, 13.0, epsilon = TOL); // 1 + 4 + 9 − 1
}

/// "Generic Sphere": a ray through the centre enters at t = 4 and leaves at t = 6, with normals
/// equal to the hit points ("Surface Normals at Intersections").
#[test]
fn sphere_two_hits_with_the_point_as_normal() {
    let hits =
        generic(Shape::Sphere).intersect(&ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]), Formula::Robust);
    assert_hits(&hits, &[(4.0, Part::Surface), (6.0, Part::Surface)]);
    let [h1, h2] = [hits.as_slice()[0], hits.as_slice()[1]];
    assert_vec_eq(h1.normal, Vec3::Z, TOL);
    assert_vec_eq(h2.normal, Vec3::NEG_Z, TOL);
    assert!(h1.entering && !h2.entering);
    // an oblique ray: e = (0.6, 0, 5), d = (0, 0, −1) meets z = ±0.8
    let hits =
        generic(Shape::Sphere).intersect(&ray([0.6, 0.0, 5.0], [0.0, 0.0, -1.0]), Formula::Robust);
    assert_hits(&hits, &[(4.2, Part::Surface), (5.8, Part::Surface)]);
    assert_vec_eq(hits.as_slice()[0].normal, vec3(0.6, 0.0, 0.8), 10.0 * TOL);
}

/// "Generic Sphere": b² − ac = 0 grazes (one hit), b² − ac < 0 misses.
#[test]
fn sphere_tangent_ray_grazes_once_and_outside_ray_misses() {
    let s = generic(Shape::Sphere);
    for formula in [Formula::Textbook, Formula::Robust] {
        let graze = s.intersect(&ray([1.0, 0.0, 5.0], [0.0, 0.0, -1.0]), formula);
        assert_hits(&graze, &[(5.0, Part::Surface)]);
        assert_vec_eq(graze.as_slice()[0].normal, Vec3::X, TOL);
        assert!(
            s.intersect(&ray([1.5, 0.0, 5.0], [0.0, 0.0, -1.0]), formula)
                .is_empty()
        );
    }
}

// --- plane --------------------------------------------------------------------------------

/// "Generic Plane": t = −e_z/d_z, normal (0, 0, 1).
#[test]
fn plane_is_hit_at_minus_ez_over_dz() {
    let p = generic(Shape::Plane);
    let hits = p.intersect(&ray([3.0, -1.0, 2.0], [1.0, 0.0, -0.5]), Formula::Robust);
    assert_hits(&hits, &[(4.0, Part::Surface)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
    assert!(hits.as_slice()[0].entering); // from the +z side
    let below = p.intersect(&ray([0.0, 0.0, -2.0], [0.0, 0.0, 4.0]), Formula::Robust);
    assert_hits(&below, &[(0.5, Part::Surface)]);
    assert!(!below.as_slice()[0].entering);
}

/// "Generic Plane": a ray with d_z = 0 is parallel and misses — never ±∞ or NaN, for +0 and −0,
/// whether it starts off the plane or on it.
#[test]
fn ray_parallel_to_the_plane_misses() {
    let p = generic(Shape::Plane);
    for dz in [0.0, -0.0] {
        for ez in [1.0, 0.0, -1.0] {
            let hits = p.intersect(&ray([0.0, 0.0, ez], [1.0, 2.0, dz]), Formula::Robust);
            assert!(hits.is_empty(), "d_z = {dz}, e_z = {ez}: {hits:?}");
        }
    }
}

// --- cylinder -----------------------------------------------------------------------------

/// "Generic Cylinder": a = d_x² + d_y², b = e_x d_x + e_y d_y, c = e_x² + e_y² − 1.
#[test]
fn cylinder_coefficients_follow_the_notes() {
    let (a, b, c) = cylinder::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, 1.25, epsilon = TOL);
    assert_abs_diff_eq!(b, -1.5, epsilon = TOL);
    assert_abs_diff_eq!(c, 4.0, epsilon = TOL);
}

/// "Generic Cylinder" and "Surface Normals at Intersections": a ray across the wall hits at
/// y = ∓1 with normals (x, y, 0).
#[test]
fn cylinder_wall_two_hits_with_normals_x_y_0() {
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits =
            generic(Shape::Cylinder).intersect(&ray([0.0, -5.0, 0.5], [0.0, 1.0, 0.0]), formula);
        assert_hits(&hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_Y, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::Y, TOL);
    }
}

/// "Generic Cylinder": roots with z outside [−1, 1] do not count, and a tangent ray grazes once.
#[test]
fn cylinder_miss_beyond_the_caps_and_tangent_graze() {
    for formula in [Formula::Textbook, Formula::Robust] {
        let c = generic(Shape::Cylinder);
        assert!(
            c.intersect(&ray([0.0, -5.0, 2.0], [0.0, 1.0, 0.0]), formula)
                .is_empty()
        );
        assert!(
            c.intersect(&ray([1.5, -5.0, 0.0], [0.0, 1.0, 0.0]), formula)
                .is_empty()
        );
        let graze = c.intersect(&ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]), formula);
        assert_hits(&graze, &[(5.0, Part::Wall)]);
        assert_vec_eq(graze.as_slice()[0].normal, Vec3::X, TOL);
    }
}

/// "Generic Cylinder" (caps) and "Surface Normals at Intersections": a ray along the axis
/// (a = 0) enters through the top cap, normal (0, 0, 1), and leaves through the bottom cap,
/// normal (0, 0, −1).
#[test]
fn cylinder_ray_along_the_axis_crosses_both_caps() {
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits =
            generic(Shape::Cylinder).intersect(&ray([0.3, 0.2, 5.0], [0.0, 0.0, -1.0]), formula);
        assert_hits(&hits, &[(4.0, Part::TopCap), (6.0, Part::BottomCap)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Z, TOL);
    }
}

/// "Generic Cylinder": a slanted ray enters through the top cap (inside the unit circle) and
/// leaves through the wall.
#[test]
fn cylinder_ray_from_cap_to_wall() {
    // e = (0, 0, 2), d = (0.5, 0, −1): z = 1 at t = 1 (x = 0.5, inside); x = 1 at t = 2 (z = 0)
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits =
            generic(Shape::Cylinder).intersect(&ray([0.0, 0.0, 2.0], [0.5, 0.0, -1.0]), formula);
        assert_hits(&hits, &[(1.0, Part::TopCap), (2.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[1].normal, Vec3::X, TOL);
    }
}

// --- cone ---------------------------------------------------------------------------------

/// "Generic Cone": a = d_x² + d_y² − d_z², b = e_x d_x + e_y d_y + d_z(1 − e_z),
/// c = e_x² + e_y² − (1 − e_z)².
#[test]
fn cone_coefficients_follow_the_notes() {
    let (a, b, c) = cone::coefficients(&ray([1.0, 2.0, 3.0], [0.5, -1.0, 2.0]));
    assert_abs_diff_eq!(a, -2.75, epsilon = TOL); // 0.25 + 1 − 4
    assert_abs_diff_eq!(b, -5.5, epsilon = TOL); // 0.5 − 2 + 2·(1 − 3)
    assert_abs_diff_eq!(c, 1.0, epsilon = TOL); // 1 + 4 − 4
}

/// "Generic Cone" and "Surface Normals at Intersections": across the wall at z = 0 the radius
/// is 1 − z = 1, hits at y = ∓1 with normals (x, y, 1 − z), renormalised.
#[test]
fn cone_wall_two_hits_with_normals_x_y_one_minus_z() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits = generic(Shape::Cone).intersect(&ray([0.0, -5.0, 0.0], [0.0, 1.0, 0.0]), formula);
        assert_hits(&hits, &[(4.0, Part::Wall), (6.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, vec3(0.0, -1.0, 1.0) * k, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, vec3(0.0, 1.0, 1.0) * k, TOL);
    }
}

/// "Generic Cone": the base z = −1 is the disc of radius 2 (where the wall reaches
/// x² + y² = (1 − (−1))²; the notes call it a unit circle, an erratum) with normal (0, 0, −1);
/// from below at x = 0.5 the ray enters the base at t = 2 and leaves the wall where
/// (1 − z)² = 0.25, z = 0.5, t = 3.5.
#[test]
fn cone_base_then_wall() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits = generic(Shape::Cone).intersect(&ray([0.5, 0.0, -3.0], [0.0, 0.0, 1.0]), formula);
        assert_hits(&hits, &[(2.0, Part::Base), (3.5, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_Z, TOL);
        assert_vec_eq(hits.as_slice()[1].normal, vec3(1.0, 0.0, 1.0) * k, TOL);
    }
}

/// "Generic Cone": the implicit equation also holds on the upper nappe (z > 1), which is not
/// part of the cone: a ray crossing it misses.
#[test]
fn upper_nappe_of_the_double_cone_is_not_hit() {
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits = generic(Shape::Cone).intersect(&ray([0.0, -5.0, 1.5], [0.0, 1.0, 0.0]), formula);
        assert!(hits.is_empty(), "{formula:?}: {hits:?}");
    }
}

/// "Surface Normals at Intersections" (erratum: the apex): a ray down the axis passes the apex,
/// where (x, y, 1 − z) = 0; whitted returns the finite unit normal (0, 0, 1) there, then
/// leaves through the base.
#[test]
fn cone_apex_has_a_finite_unit_normal() {
    let hits =
        generic(Shape::Cone).intersect(&ray([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]), Formula::Robust);
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
fn facet_t_is_d_minus_n_dot_e_all_over_n_dot_d() {
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
fn cube_entering_and_leaving_facets() {
    let hits = generic(Shape::Polyhedron(Polyhedron::cube()))
        .intersect(&ray([0.2, 0.3, 5.0], [0.0, 0.0, -1.0]), Formula::Robust);
    assert_hits(&hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Z, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Z, TOL);
}

/// "Convex Polyhedra" (erratum: the table swaps inside and outside): with n·d = 0, the notes'
/// own rule (Q·n < d is inside) makes d − n·e < 0 *outside* — a miss — and d − n·e > 0 inside,
/// where the facet does not stop the ray. The notes' table says the opposite.
#[test]
fn ray_parallel_to_a_facet_misses_outside_and_passes_inside() {
    let cube = generic(Shape::Polyhedron(Polyhedron::cube()));
    // parallel to the facet y = 1 (index 2), at y = 2: d − n·e = 1 − 2 < 0, outside
    let facet = Polyhedron::cube().facets()[2];
    let e = vec3(0.0, 2.0, 5.0);
    assert!(facet.d() - facet.normal().dot(e) < 0.0);
    assert!(
        facet.normal().dot(e) > facet.d(),
        "Q·n > d: outside, by the notes' rule"
    );
    assert!(
        cube.intersect(&ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0]), Formula::Robust)
            .is_empty()
    );
    // parallel to it at y = 0.5 (inside its half-space)
    let hits = cube.intersect(&ray([0.0, 0.5, 5.0], [0.0, 0.0, -1.0]), Formula::Robust);
    assert_hits(&hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
}

/// "Convex Polyhedra": the octahedron |x| + |y| + |z| ≤ 1 along x at y = 0.25, z = 0.1 spans
/// |x| ≤ 0.65: t = 4.35 through the facet with normal (1, 1, 1)/√3.
#[test]
fn octahedron_hits_through_its_facets() {
    let hits = generic(Shape::Polyhedron(Polyhedron::octahedron()))
        .intersect(&ray([5.0, 0.25, 0.1], [-1.0, 0.0, 0.0]), Formula::Robust);
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
fn tetrahedron_hits_through_its_facets() {
    let hits = generic(Shape::Polyhedron(Polyhedron::tetrahedron()))
        .intersect(&ray([0.2, 0.0, 5.0], [0.0, 0.0, -1.0]), Formula::Robust);
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
fn inverse_from_inverse_steps_undoes_the_placement() {
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

/// "Ray Tracing Process": M⁻¹d is not renormalised, so the t found in object space gives the
/// same point in world space: M·(M⁻¹e + M⁻¹d·t) = e + d·t, under a non-uniform scale.
#[test]
fn t_is_the_same_in_world_and_object_space() {
    let o = ellipsoid();
    let world = ray([-4.0, -1.0, 2.5], [3.0, -0.5, 0.2]);
    let local = world.transformed(o.placement.inv());
    assert!(
        (local.dir.length() - world.dir.length()).abs() > 0.1,
        "the scale changes |d|"
    );
    let hits = o.intersect(&world, Formula::Robust);
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
    let t_bad = sphere::intersect(&renormalised, Formula::Robust).as_slice()[0].t;
    let miss = o.placement.inv().transform_point3(world.at(t_bad)).length();
    assert!(
        (miss - 1.0).abs() > 0.1,
        "renormalised t lands off the surface ({miss})"
    );
}

/// "Surface Normals at Intersections" and "Ray Tracing Process": under the non-uniform scale
/// (2, 1, 1), the object-space normal n′ = (1, 1, 0)/√2 at P′ = n′ becomes (M⁻¹)ᵀn′ ∝ (1, 2, 0),
/// perpendicular to the surface; M·n′ ∝ (2, 1, 0) is not.
#[test]
fn normal_under_non_uniform_scale_uses_inverse_transpose() {
    let o = Object::new(
        Shape::Sphere,
        Placement::from_steps(&[Step::Scale(vec3(2.0, 1.0, 1.0))]).unwrap(),
    );
    let s = (2.0 as Real).sqrt();
    let p_world = Vec3::new(s, 1.0 / s, 0.0); // M·(1/√2, 1/√2, 0)
    let r = Ray::new(p_world + vec3(1.0, 2.0, 0.0), vec3(-1.0, -2.0, 0.0));
    let hit = o.intersect(&r, Formula::Robust).as_slice()[0];
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
    let hits = o.intersect(&ray([-3.0, 1.0, 0.0], [1.0, 0.0, 0.0]), Formula::Robust);
    assert_hits(&hits, &[(2.5, Part::Wall), (3.5, Part::Wall)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::NEG_X, TOL);
    // down the axis: top cap at y = 4, bottom at y = 0
    let hits = o.intersect(&ray([0.1, 10.0, 0.0], [0.0, -1.0, 0.0]), Formula::Robust);
    assert_hits(&hits, &[(6.0, Part::TopCap), (10.0, Part::BottomCap)]);
    assert_vec_eq(hits.as_slice()[0].normal, Vec3::Y, TOL);
    assert_vec_eq(hits.as_slice()[1].normal, Vec3::NEG_Y, TOL);
}

/// "Ray Tracing Process": a zero scale has no inverse; the placement refuses it.
#[test]
fn zero_scale_is_not_invertible() {
    assert!(Placement::from_steps(&[Step::Scale(vec3(1.0, 0.0, 1.0))]).is_none());
    assert!(Placement::from_steps(&[Step::Scale(Vec3::new(1.0, Real::NAN, 1.0))]).is_none());
    assert!(Placement::from_steps(&[Step::Scale(vec3(1.0, 2.0, 1.0))]).is_some());
}

/// "Generic Cone": a ray touching the wall at z = 0 (radius 1) has b² − ac = 0 and grazes once,
/// with the wall normal (x, y, 1 − z) there.
#[test]
fn cone_tangent_ray_grazes_once() {
    let r = ray([1.0, -5.0, 0.0], [0.0, 1.0, 0.0]);
    let (a, b, c) = cone::coefficients(&r);
    assert_abs_diff_eq!(b * b - a * c, 0.0, epsilon = TOL);
    let k = 1.0 / (2.0 as Real).sqrt();
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits = generic(Shape::Cone).intersect(&r, formula);
        assert_hits(&hits, &[(5.0, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[0].normal, vec3(1.0, 0.0, 1.0) * k, TOL);
    }
    assert!(
        generic(Shape::Cone)
            .intersect(&ray([1.2, -5.0, 0.0], [0.0, 1.0, 0.0]), Formula::Robust)
            .is_empty()
    );
}

/// "Convex Polyhedra": a ray across an edge of the cube enters (facet +z) and leaves (facet +x)
/// at the same t: t_near = t_far, one grazing hit; a little further out it misses
/// (t_near > t_far).
#[test]
fn polyhedron_ray_across_an_edge_grazes_once() {
    let cube = generic(Shape::Polyhedron(Polyhedron::cube()));
    let hits = cube.intersect(&ray([0.0, 0.0, 2.0], [1.0, 0.0, -1.0]), Formula::Robust);
    assert_hits(&hits, &[(1.0, Part::Facet(4))]);
    assert!(
        cube.intersect(&ray([0.5, 0.0, 2.5], [1.0, 0.0, -1.0]), Formula::Robust)
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
fn cone_base_has_radius_two() {
    let k = 1.0 / (2.0 as Real).sqrt();
    for formula in [Formula::Textbook, Formula::Robust] {
        let hits = generic(Shape::Cone).intersect(&ray([1.5, 0.0, -3.0], [0.0, 0.0, 1.0]), formula);
        assert_hits(&hits, &[(2.0, Part::Base), (2.5, Part::Wall)]);
        assert_vec_eq(hits.as_slice()[1].normal, vec3(1.0, 0.0, 1.0) * k, TOL);
        // just outside the radius-2 base: a miss
        assert!(
            generic(Shape::Cone)
                .intersect(&ray([2.01, 0.0, -3.0], [0.0, 0.0, 1.0]), formula)
                .is_empty()
        );
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
    let hits = o.intersect(&ray([-3.0, 0.3, 0.0], [1.0, 0.0, 0.0]), Formula::Robust);
    assert_hits(&hits, &[(2.55, Part::Wall), (3.45, Part::Wall)]);
    // up the axis from below: base at y = 0, apex at y = 3
    let hits = o.intersect(&ray([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]), Formula::Robust);
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
        let mut o = Options::for_scene(&s, Stage::GenericObjects);
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
    let (c, _) = centre(&s, Stage::GenericObjects);
    assert_vec_eq(c, vec3(1.0, 0.0, 0.0), 0.0);
}

/// "Ray Tracing Process", step 5 (the tie rule of `shapes::nearer`): a smaller t wins whatever
/// the order; of two hits at the same t, the object listed first.
#[test]
fn equal_t_goes_to_the_object_listed_first() {
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
            let mut o = Options::for_scene(&s, Stage::GenericObjects);
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
fn polyhedron_enters_where_n_dot_d_is_negative_and_leaves_where_positive() {
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
    let prism = generic(Shape::Polyhedron(prism));
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
        let hits = prism.intersect(&r, Formula::Robust);
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
fn rotations_by_multiples_of_90_degrees_are_exact() {
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
            let hits = floor.intersect(&ray([0.3, y, -0.7], d), Formula::Robust);
            assert!(hits.is_empty(), "y = {y}, d = {d:?}: {hits:?}");
        }
        // the same floor turned by the inexact angle: some parallel ray meets it very far away
        let inexact = Mat4::from_rotation_x((90.0 as Real).to_radians()); // M⁻¹ of −90° about x
        let far = [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
            .iter()
            .flat_map(|&d| {
                Shape::Plane
                    .intersect_placed(&inexact, &ray([0.3, y, -0.7], d), Formula::Robust)
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
        let (fb, _) = render_at(&scene(&floor_scene(look_z)), Stage::GenericObjects, 5, 3);
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
