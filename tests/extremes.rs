//! Numerical stability at the extremes (issue 4): what the robust formulas and the error-bound
//! offset buy, shown case by case, in both precisions.
//!
//! Each category has a case where the notes' formula as printed demonstrably fails, asserted
//! side by side with the default (robust) code passing on the same input, so that the test shows
//! why the robust code exists. Tolerances are stated per precision in [`tol`]; the inputs that
//! break the textbook forms are chosen per precision too (what breaks f32 at 1e4 units breaks
//! f64 only around 1e9 units).
//!
//! ```text
//! cargo test --test extremes                  # f64
//! cargo test --test extremes --features f32   # f32
//! ```

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use whitted::numeric::{normalize, normalize_naive};
use whitted::offset::{Offset, OffsetKind};
use whitted::optics;
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::{self, Options, Stage};
use whitted::scene::{self, Scene};
use whitted::shapes::quadratic::{self, Roots};
use whitted::shapes::{Formula, Hit, Object, Part, Shape};
use whitted::transform::{Placement, Step};

/// Tolerances and problem sizes for the precision under test.
#[cfg(not(feature = "f32"))]
mod tol {
    /// Relative error allowed on a root computed by the robust formulas.
    pub const ROOT_REL: f64 = 1e-12;
    /// |‖n‖ − 1| allowed on a world normal.
    pub const UNIT: f64 = 1e-12;
    /// A distance at which the notes' sphere discriminant b² − ac has no digit left.
    pub const FAR: f64 = 1e9;
    /// A distance at which the classic fixed ε = 1e-4 is below the rounding error of hit points.
    pub const FIXED_EPS_FAILS_AT: f64 = 1e12;
    /// b in a·t² + 2b·t + c with a = c = 1: b² dwarfs ac.
    pub const BIG_B: f64 = 1e9;
    /// Angle step either side of the critical angle (radians).
    pub const CRITICAL_STEP: f64 = 1e-9;
    /// A vector so large (or, inverted, so small) that its squared length overflows (underflows).
    pub const HUGE: f64 = 1e200;
}

/// Tolerances and problem sizes for the precision under test.
#[cfg(feature = "f32")]
mod tol {
    /// Relative error allowed on a root computed by the robust formulas.
    pub const ROOT_REL: f64 = 1e-5;
    /// |‖n‖ − 1| allowed on a world normal.
    pub const UNIT: f64 = 1e-5;
    /// A distance at which the notes' sphere discriminant b² − ac has no digit left.
    pub const FAR: f64 = 1e4;
    /// A distance at which the classic fixed ε = 1e-4 is below the rounding error of hit points.
    pub const FIXED_EPS_FAILS_AT: f64 = 1e4;
    /// b in a·t² + 2b·t + c with a = c = 1: b² dwarfs ac.
    pub const BIG_B: f64 = 1e5;
    /// Angle step either side of the critical angle (radians).
    pub const CRITICAL_STEP: f64 = 1e-4;
    /// A vector so large (or, inverted, so small) that its squared length overflows (underflows).
    pub const HUGE: f64 = 1e30;
}

/// The unit roundoff of [`Real`], as f64.
fn eps() -> f64 {
    f(Real::EPSILON) / 2.0
}

/// A [`Real`] widened to f64 (exact in both precisions; a no-op in f64, hence the allowed cast).
#[allow(clippy::unnecessary_cast)]
fn f(x: Real) -> f64 {
    x as f64
}

fn placed(shape: Shape, steps: &[Step]) -> Object {
    Object::new(
        shape,
        Placement::from_steps(steps).expect("invertible steps"),
    )
}

fn hits(object: &Object, ray: &Ray, formula: Formula) -> Vec<Hit> {
    object.intersect(ray, formula).as_slice().to_vec()
}

fn all_finite(hs: &[Hit]) -> bool {
    hs.iter().all(|h| h.t.is_finite() && h.normal.is_finite())
}

fn rel_err(got: Real, want: f64) -> f64 {
    (f(got) - want).abs() / want.abs().max(f64::MIN_POSITIVE)
}

// ---------------------------------------------------------------------------------------------
// The quadratic
// ---------------------------------------------------------------------------------------------

/// Notes, "Generic Sphere": t = −b/a ± √(b² − ac)/a. When b² ≫ ac the smaller root subtracts
/// two nearly equal numbers; the stable form t₂ = c/q with q = −(b + sign(b)·√(b² − ac)) keeps
/// every digit.
#[test]
fn stable_quadratic_keeps_the_small_root_when_b_squared_dwarfs_ac() {
    let (a, b, c) = (1.0, -real(tol::BIG_B), 1.0);
    let small = 1.0 / (2.0 * tol::BIG_B); // t₁·t₂ = c/a = 1 and t₁ + t₂ = −2b/a
    let smallest = |roots: Roots| match roots {
        Roots::Two(t1, _) => t1,
        Roots::One(t) => t,
        Roots::None => Real::NAN,
    };
    let robust = smallest(quadratic::solve(a, b, c, Formula::Robust));
    let textbook = smallest(quadratic::solve(a, b, c, Formula::Textbook));
    assert!(
        rel_err(robust, small) < tol::ROOT_REL,
        "robust small root {robust} vs {small}"
    );
    assert!(
        textbook.is_nan() || rel_err(textbook, small) >= 0.1,
        "the textbook root {textbook} was expected to lose its digits (true {small})"
    );
}

/// Notes, "Generic Sphere" with a = 0 (a degenerate direction): the textbook form divides by
/// zero; the robust one never returns a non-finite root.
#[test]
fn quadratic_with_a_zero_returns_only_finite_roots() {
    for formula in [Formula::Textbook, Formula::Robust] {
        for (a, b, c) in [
            (0.0, 1.0, -2.0),
            (0.0, 0.0, 1.0),
            (0.0, 0.0, 0.0),
            (0.0, -0.0, 0.0),
        ] {
            match quadratic::solve(a, b, c, formula) {
                Roots::None => {}
                Roots::One(t) => assert!(t.is_finite()),
                Roots::Two(t1, t2) => assert!(t1.is_finite() && t2.is_finite() && t1 <= t2),
            }
        }
    }
    // the linear case 2b·t + c = 0 is solved by the robust form: t = −c/(2b) = 1
    assert_eq!(
        quadratic::solve(0.0, 1.0, -2.0, Formula::Robust),
        Roots::One(1.0)
    );
}

// ---------------------------------------------------------------------------------------------
// Spheres: small and far, large and near, grazing
// ---------------------------------------------------------------------------------------------

/// A unit sphere centred at (0, 0, −D) and a ray from (h, 0, 0) along −z: hits at
/// t = D ∓ √(1 − h²).
fn far_sphere_case(h: f64, formula: Formula) -> Vec<Hit> {
    let sphere = placed(Shape::Sphere, &[Step::Translate(vec3(0.0, 0.0, -tol::FAR))]);
    let ray = Ray::new(vec3(h, 0.0, 0.0), vec3(0.0, 0.0, -1.0));
    hits(&sphere, &ray, formula)
}

fn far_sphere_is_right(hs: &[Hit], h: f64) -> bool {
    if h.abs() >= 1.0 {
        return hs.is_empty();
    }
    let half = (1.0 - h * h).sqrt();
    // both hits within a hundredth of the radius (f32 spacing at 1e4 is 1e-3)
    hs.len() == 2
        && (f(hs[0].t) - (tol::FAR - half)).abs() < 1e-2
        && (f(hs[1].t) - (tol::FAR + half)).abs() < 1e-2
}

/// Notes, "Generic Sphere": b² − ac < 0 misses, > 0 enters and leaves. For a unit sphere D
/// units away, b² and ac are both ≈ D² and their difference (≈ 1) is below the spacing of
/// numbers near D²: the notes' discriminant sees a graze or nothing. The Ray Tracing Gems ch. 7
/// form a·(1 − |e − (b/a)·d|²) subtracts numbers of the size of the radius instead.
#[test]
fn small_sphere_far_away_is_hit_where_the_textbook_discriminant_sees_nothing() {
    for h in [0.0, 0.3, 0.5, 0.8, 0.95] {
        let robust = far_sphere_case(h, Formula::Robust);
        assert!(
            far_sphere_is_right(&robust, h),
            "robust, h = {h}: {robust:?}"
        );
    }
    let textbook = far_sphere_case(0.5, Formula::Textbook);
    assert!(
        !far_sphere_is_right(&textbook, 0.5),
        "the textbook discriminant was expected to fail at distance {}: {textbook:?}",
        tol::FAR
    );
}

/// Notes, "Generic Sphere", grazing rays: a ray that passes just inside the silhouette of a
/// far sphere hits it twice and one just outside misses; the robust discriminant tells them
/// apart at distance D, the textbook one does not.
#[test]
fn grazing_rays_at_a_far_sphere_hit_inside_the_silhouette_and_miss_outside() {
    for h in [0.99, -0.99, 1.01, -1.01, 2.0] {
        let robust = far_sphere_case(h, Formula::Robust);
        assert!(far_sphere_is_right(&robust, h), "h = {h}: {robust:?}");
    }
    let wrong = [0.99, 1.01]
        .iter()
        .filter(|&&h| !far_sphere_is_right(&far_sphere_case(h, Formula::Textbook), h))
        .count();
    assert!(
        wrong > 0,
        "the textbook form was expected to misjudge a graze"
    );
}

/// Notes, "Generic Sphere": a tangent ray (b² − ac = 0) grazes at one point whose normal is
/// perpendicular to the ray.
#[test]
fn tangent_ray_grazes_the_sphere_at_one_point() {
    let sphere = Object::new(Shape::Sphere, Placement::identity());
    let ray = Ray::new(vec3(1.0, 0.0, -5.0), vec3(0.0, 0.0, 1.0));
    let hs = hits(&sphere, &ray, Formula::Robust);
    assert!(!hs.is_empty() && hs.len() <= 2, "{hs:?}");
    for h in &hs {
        assert!((f(h.t) - 5.0).abs() < 1e-3, "{h:?}");
        assert!(f(h.normal.dot(ray.dir)).abs() < 1e-3, "{h:?}");
    }
}

/// Notes, "Generic Sphere", the near root −b/a − √(b² − ac)/a of a large sphere seen from close
/// by: −b/a is of the size of the sphere and the root is its difference with another number of
/// that size. The stable root c/q does not subtract. A sphere of radius 2²⁰ ≈ 1e6 below an
/// eye one unit above its top (chosen so that the object-space origin is exact in both
/// precisions).
#[test]
fn large_sphere_close_by_keeps_the_near_root_accurate() {
    let r = (1u64 << 20) as f64;
    let sphere = placed(
        Shape::Sphere,
        &[
            Step::Scale(Vec3::splat(real(r))),
            Step::Translate(vec3(0.0, -r, 0.0)),
        ],
    );
    let dir = normalize(vec3(2.0, -3.0, 1.0));
    let ray = Ray::new(vec3(0.0, 1.0, 0.0), dir);
    // the truth in f64 for the direction actually used: |u + d·t|² = r² with u = (0, r + 1, 0)
    let d = [f(dir.x), f(dir.y), f(dir.z)];
    let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let b = (r + 1.0) * d[1];
    let c = 2.0 * r + 1.0; // (r + 1)² − r², exact
    let q = -(b + b.signum() * (b * b - a * c).sqrt());
    let near = c / q;
    let robust = hits(&sphere, &ray, Formula::Robust);
    let textbook = hits(&sphere, &ray, Formula::Textbook);
    // a few dozen roundings for the stable root; the textbook one loses ~log2(r) bits more
    let few_ulps = 64.0 * eps();
    assert!(
        rel_err(robust[0].t, near) < few_ulps,
        "robust near root {} vs {near}",
        robust[0].t
    );
    assert!(
        rel_err(textbook[0].t, near) > few_ulps,
        "the textbook near root {} was expected to lose digits (true {near})",
        textbook[0].t
    );
}

// ---------------------------------------------------------------------------------------------
// Cylinder and cone: a ≈ 0, rims, apex
// ---------------------------------------------------------------------------------------------

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
        let robust = hits(&cylinder, &ray, Formula::Robust);
        assert_eq!(robust.len(), 2, "φ = {phi}: {robust:?}");
        assert!(
            (f(robust[0].t) - t_rim).abs() < 1e-3,
            "φ = {phi}: {robust:?}"
        );
        assert!(robust[0].entering && !robust[1].entering);
        let textbook = hits(&cylinder, &ray, Formula::Textbook);
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
        let hs = hits(&cylinder, &ray, Formula::Robust);
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
        let robust = hits(&cone, &ray, Formula::Robust);
        assert!(generator_ray_is_right(&robust), "φ = {i}°: {robust:?}");
        if !generator_ray_is_right(&hits(&cone, &ray, Formula::Textbook)) {
            textbook_wrong += 1;
        }
    }
    // φ = 0 has a = 0 exactly
    assert!(!generator_ray_is_right(&hits(
        &cone,
        &generator_ray(0.0),
        Formula::Textbook
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
    let case = |h: f64, formula| {
        let ray = Ray::new(vec3(h, 0.0, 0.0), vec3(0.0, 0.0, -1.0));
        hits(&cone, &ray, formula)
    };
    for h in [0.0, 0.5, 0.9, -0.95] {
        assert!(
            far_sphere_is_right(&case(h, Formula::Robust), h),
            "h = {h}: {:?}",
            case(h, Formula::Robust)
        );
    }
    assert!(case(1.05, Formula::Robust).is_empty());
    assert!(
        !far_sphere_is_right(&case(0.5, Formula::Textbook), 0.5),
        "the textbook discriminant was expected to fail: {:?}",
        case(0.5, Formula::Textbook)
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
            for formula in [Formula::Robust, Formula::Textbook] {
                let hs = hits(&cone, &ray, formula);
                assert!(all_finite(&hs), "{formula:?} φ {i}: {hs:?}");
                for w in hs.windows(2) {
                    assert!(w[0].t <= w[1].t);
                }
                for h in &hs {
                    assert!(
                        (f(h.normal.length()) - 1.0).abs() < tol::UNIT,
                        "{formula:?}: {h:?}"
                    );
                }
                if formula == Formula::Robust && !lying && dz < -1.0 {
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

// ---------------------------------------------------------------------------------------------
// The plane: d_z = ±0
// ---------------------------------------------------------------------------------------------

/// Notes, "Generic Plane": t = −e_z/d_z, and "if d_z = 0 the ray is parallel to the plane and
/// does not intersect it". Printed as is, the formula gives ±∞ for d_z = ±0 and NaN for a ray
/// lying in the plane; whitted's plane returns no hit for either zero, and none for a d_z so
/// small that t overflows.
#[test]
fn ray_parallel_to_the_plane_misses_with_either_sign_of_zero() {
    let plane = Object::new(Shape::Plane, Placement::identity());
    let tiny = Real::MIN_POSITIVE * Real::EPSILON; // the smallest subnormal
    for ez in [1.0, 0.0, -1.0] {
        for dz in [0.0, -0.0, tiny, -tiny] {
            let ray = Ray::new(Vec3::new(0.0, 0.0, ez), Vec3::new(1.0, 0.0, dz));
            let hs = hits(&plane, &ray, Formula::Robust);
            assert!(all_finite(&hs), "e_z {ez} d_z {dz}: {hs:?}");
            if dz == 0.0 {
                assert!(hs.is_empty(), "e_z {ez} d_z {dz}: {hs:?}");
                let naive = -ray.origin.z / ray.dir.z; // the notes' t = −e_z/d_z
                assert!(!naive.is_finite());
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Placements from 1e-6 to 1e6, normalising huge and tiny vectors
// ---------------------------------------------------------------------------------------------

/// Notes, "Surface Normals at Intersections": n = (M⁻¹)ᵀn′, renormalised. v/|v| overflows
/// (|v|² = ∞ gives 0) or underflows (|v|² = 0 gives ∞ or NaN) for very large or very small
/// vectors; dividing by the largest component first keeps the unit vector.
#[test]
fn normalising_huge_and_tiny_vectors_gives_unit_vectors() {
    let huge = real(tol::HUGE);
    for v in [
        Vec3::new(huge, huge, 0.5 * huge),
        Vec3::new(1.0 / huge, -2.0 / huge, 0.0),
        Vec3::new(0.0, 0.0, -Real::MIN_POSITIVE * Real::EPSILON),
    ] {
        let n = normalize(v);
        assert!((f(n.length()) - 1.0).abs() < tol::UNIT, "{v:?} → {n:?}");
        assert!(n.dot(v) > 0.0);
        let naive = normalize_naive(v);
        assert!(
            naive.is_nan() || (f(naive.length()) - 1.0).abs() >= tol::UNIT,
            "v/|v| was expected to fail for {v:?}: {naive:?}"
        );
    }
    assert_eq!(normalize(Vec3::ZERO), Vec3::ZERO);
}

/// Notes, "Ray Tracing Process" (q = M·q′, rays by M⁻¹) at every scale from 1e-6 to 1e6: the
/// hit is on the placed surface to a relative tolerance and its normal is unit and faces the
/// ray, for every shape, uniform and non-uniform placements alike.
#[test]
fn placements_from_a_millionth_to_a_million_keep_hits_on_the_surface() {
    let shapes = [
        Shape::Sphere,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Polyhedron(whitted::shapes::Polyhedron::cube()),
    ];
    for k in -6..=6 {
        let s = 10f64.powi(k);
        for anisotropy in [vec3(1.0, 1.0, 1.0), vec3(1.0, 0.1, 10.0)] {
            for shape in &shapes {
                let steps = [
                    Step::Scale(anisotropy * real(s)),
                    Step::RotateY(30.0),
                    Step::Translate(vec3(3.0 * s, -2.0 * s, 1.0 * s)),
                ];
                let object = placed(shape.clone(), &steps);
                let centre = object.placement.m().transform_point3(Vec3::ZERO);
                let target = object.placement.m().transform_point3(vec3(0.1, 0.2, 0.3));
                let origin = centre + vec3(5.0 * s, 20.0 * s, 40.0 * s);
                let ray = Ray::new(origin, target - origin);
                let hs = hits(&object, &ray, Formula::Robust);
                assert_eq!(hs.len(), 2, "{} at scale {s}: {hs:?}", shape.name());
                let s_min = s * f(anisotropy.min_element());
                for h in &hs {
                    let p = ray.at(h.t);
                    let local = object.placement.inv().transform_point3(p);
                    let residual = surface_residual(shape, h.part, local);
                    // the rounding of world coordinates, seen in object units
                    let scale = 1.0 + (f(origin.length()) + f(p.length())) / s_min;
                    assert!(
                        residual < 1024.0 * eps() * scale,
                        "{} at scale {s}: residual {residual} at {local:?}",
                        shape.name()
                    );
                    assert!((f(h.normal.length()) - 1.0).abs() < tol::UNIT);
                }
                assert!(hs[0].normal.dot(ray.dir) < 0.0 && hs[1].normal.dot(ray.dir) > 0.0);
            }
        }
    }
}

/// How far an object-space point is from the part of the generic surface it was reported on
/// (in object units), plus how far it strays outside that part's extent.
fn surface_residual(shape: &Shape, part: Part, p: Vec3) -> f64 {
    let (x, y, z) = (f(p.x), f(p.y), f(p.z));
    let outside = |v: f64, lim: f64| (v.abs() - lim).max(0.0);
    let radial = (x * x + y * y).sqrt();
    match (shape, part) {
        (Shape::Sphere, _) => ((x * x + y * y + z * z).sqrt() - 1.0).abs(),
        (Shape::Plane, _) => z.abs(),
        (Shape::Cylinder, Part::Wall) => (radial - 1.0).abs() + outside(z, 1.0),
        (Shape::Cylinder, Part::TopCap) => (z - 1.0).abs() + outside(radial, 1.0),
        (Shape::Cylinder, _) => (z + 1.0).abs() + outside(radial, 1.0),
        (Shape::Cone, Part::Base) => (z + 1.0).abs() + outside(radial, 2.0),
        (Shape::Cone, _) => (radial - (1.0 - z)).abs() + outside(z, 1.0),
        (Shape::Polyhedron(poly), Part::Facet(i)) => {
            let facet = poly.facets()[i as usize];
            let on = (f(facet.normal().dot(p)) - f(facet.d())).abs();
            let out = poly
                .facets()
                .iter()
                .map(|g| (f(g.normal().dot(p)) - f(g.d())).max(0.0))
                .fold(0.0, f64::max);
            on + out
        }
        (Shape::Polyhedron(_), _) => f64::INFINITY,
    }
}

// ---------------------------------------------------------------------------------------------
// Self-intersection: shadow acne far from the camera
// ---------------------------------------------------------------------------------------------

/// A scene with one object ~`distance` units in front of the camera and one light on the
/// camera's side: nothing can shadow the object but itself.
fn lonely_scene(distance: f64, object: &str) -> Scene {
    let d = distance;
    let text = format!(
        r#"
[camera]
eye = [0.0, 0.0, 0.0]
look_at = [0.0, 0.0, {look}]
fov = 20.0
[image]
width = 48
height = 36
[ambient]
intensity = 0.1
[[lights]]
position = [{lx}, {ly}, 0.0]
intensity = 1.0
[materials.m]
ambient = 0.1
diffuse = 0.8
specular = 0.0
[[objects]]
{object}
material = "m"
"#,
        look = -d,
        lx = 0.3 * d,
        ly = 0.6 * d,
    );
    scene::parse(&text, "lonely.toml").expect("valid scene")
}

fn far_sphere_scene(d: f64) -> Scene {
    lonely_scene(
        d,
        &format!(
            "sphere = {{ center = [0.0, 0.0, {}], radius = {} }}",
            -d,
            0.15 * d
        ),
    )
}

fn tilted_plane_scene(d: f64) -> Scene {
    lonely_scene(
        d,
        &format!(
            "plane = {{ point = [0.0, 0.0, {}], normal = [0.2, 0.7, 0.6] }}",
            -d
        ),
    )
}

/// The share of pixels lit in chapter 3 (no shadows) that chapter 4 darkens: with a single
/// convex object or a plane and the light on the visible side, every such pixel is a false
/// shadow (shadow acne).
fn wrongly_shadowed_share(scene: &Scene, offset: Offset) -> f64 {
    let mut options = Options::for_scene(scene, Stage::Shading);
    options.offset = offset;
    let (lit, _) = render::render(scene, &options);
    options.stage = Stage::Shadows;
    let (shadowed, _) = render::render(scene, &options);
    let ambient_only = scene.materials[1].ambient * scene.ambient;
    let mut lit_count = 0;
    let mut wrong = 0;
    for (l, s) in lit.pixels.iter().zip(&shadowed.pixels) {
        assert!(l.is_finite() && s.is_finite());
        if (*l - ambient_only).max_element() > 1e-3 {
            lit_count += 1;
            if (*l - *s).max_element() > 1e-3 {
                wrong += 1;
            }
        }
    }
    assert!(lit_count > 100, "the test scene should show lit pixels");
    wrong as f64 / lit_count as f64
}

/// Notes, "Shadowing": a feeler S(u) = P + (L − P)·u meeting an opaque object with u ∈ ]0, 1]
/// puts P in shadow. P itself carries rounding error of the size of its coordinates, so about
/// 1e4 units from the origin the feeler meets its own surface. The default error-bound offset
/// leaves no lit pixel wrongly shadowed, on a sphere and on a tilted plane.
#[test]
fn no_lit_pixel_is_wrongly_shadowed_ten_thousand_units_away() {
    for scene in [far_sphere_scene(1e4), tilted_plane_scene(1e4)] {
        assert_eq!(wrongly_shadowed_share(&scene, Offset::default()), 0.0);
    }
}

/// The classic fixed ε (1e-4 world units) is below the rounding error of hit points far enough
/// away (1e4 units in f32, 1e12 in f64): it shadows lit pixels there, on the sphere and the
/// tilted plane, while the default error-bound offset still shadows none.
#[test]
fn fixed_epsilon_shadows_lit_pixels_far_away_and_the_error_bound_does_not() {
    let d = tol::FIXED_EPS_FAILS_AT;
    for scene in [far_sphere_scene(d), tilted_plane_scene(d)] {
        let fixed = wrongly_shadowed_share(&scene, Offset::Fixed(Offset::FIXED_EPSILON));
        assert!(fixed > 0.01, "fixed ε wrongly shadowed only {fixed}");
        assert_eq!(wrongly_shadowed_share(&scene, Offset::ErrorBound), 0.0);
    }
}

// ---------------------------------------------------------------------------------------------
// Refraction: total internal reflection either side of the critical angle
// ---------------------------------------------------------------------------------------------

/// Notes, "Reflection and Refraction": beyond the critical angle all light is reflected. From
/// glass (1.5) into air, sin θc = n₂/n₁ = 1/1.5: just below θc a transmitted ray exists (unit,
/// nearly tangent), just above there is none. The notes' (c₁/c₂)·sin θc = 1 asks for
/// sin θc = 1.5, which has no solution.
#[test]
fn total_internal_reflection_starts_exactly_at_the_critical_angle() {
    let (n1, n2) = (1.5 as Real, 1.0 as Real);
    let theta_c = optics::critical_angle(n1, n2).expect("glass to air has one");
    assert!((f(theta_c).to_degrees() - 41.810_314_895_778_6).abs() < 1e-4);
    let n = Vec3::Y;
    let at = |theta: f64| vec3(theta.sin(), -theta.cos(), 0.0);
    let below = optics::refract(at(f(theta_c) - tol::CRITICAL_STEP), n, n1, n2)
        .expect("below the critical angle light gets through");
    assert!((f(below.length()) - 1.0).abs() < 1e3 * eps());
    assert!(
        below.y < 0.0 && f(below.x) > 0.99,
        "nearly tangent: {below:?}"
    );
    assert_eq!(
        optics::refract(at(f(theta_c) + tol::CRITICAL_STEP), n, n1, n2),
        None
    );
    // the notes' condition (c₁/c₂)·sin θc = 1 with c = c₀/n: sin θc = n₁/n₂
    let notes = (n1 / n2).asin();
    assert!(notes.is_nan());
}

// ---------------------------------------------------------------------------------------------
// Whole renders: nothing non-finite reaches a pixel
// ---------------------------------------------------------------------------------------------

/// Notes, "Lighting Equations": I = I_a + I_d + I_s + I_l + I_r is finite at every pixel of the
/// far and grazing scenes, for every formula and offset strategy.
#[test]
fn no_nan_or_infinity_reaches_a_pixel_of_the_extreme_scenes() {
    for (name, text) in [
        ("scenes/far.toml", include_str!("../scenes/far.toml")),
        (
            "scenes/grazing.toml",
            include_str!("../scenes/grazing.toml"),
        ),
    ] {
        let scene = scene::parse(text, name).expect("valid scene");
        for formula in [Formula::Textbook, Formula::Robust] {
            for offset in OffsetKind::ALL {
                let mut options = Options::for_scene(&scene, Stage::ReflectionRefraction);
                (options.width, options.height) = (40, 30);
                options.formula = formula;
                options.offset = offset.offset();
                let (fb, _) = render::render(&scene, &options);
                assert!(
                    fb.pixels
                        .iter()
                        .all(|p| p.is_finite() && p.min_element() >= 0.0),
                    "{name} {formula:?} {offset:?}"
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Property tests
// ---------------------------------------------------------------------------------------------

/// The property tests' settings: `cases` cases from a fixed seed, so that CI is
/// reproducible; set `EXTREMES_SEED=<u64>` to explore other inputs.
fn config(cases: u32) -> ProptestConfig {
    let seed = std::env::var("EXTREMES_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_2026);
    ProptestConfig {
        cases,
        failure_persistence: None,
        rng_seed: RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

fn shape_of(i: u8) -> Shape {
    match i % 5 {
        0 => Shape::Sphere,
        1 => Shape::Cylinder,
        2 => Shape::Cone,
        3 => Shape::Polyhedron(whitted::shapes::Polyhedron::cube()),
        _ => Shape::Plane,
    }
}

prop_compose! {
    /// A random placement: an overall scale 10^k with k ∈ [−6, 6], a per-axis stretch up to 4×,
    /// any rotation, and a translation up to 50 sizes.
    fn placement()(k in -6.0f64..6.0, stretch in prop::array::uniform3(0.25f64..4.0),
                   axis in prop::array::uniform3(-1.0f64..1.0), angle in -180.0f64..180.0,
                   shift in prop::array::uniform3(-50.0f64..50.0))
                   -> (f64, Vec<Step>) {
        let s = 10f64.powf(k);
        let axis = if axis.iter().all(|a| a.abs() < 1e-3) { [0.0, 0.0, 1.0] } else { axis };
        (s, vec![
            Step::Scale(vec3(stretch[0] * s, stretch[1] * s, stretch[2] * s)),
            Step::RotateAxis(vec3(axis[0], axis[1], axis[2]), real(angle)),
            Step::Translate(vec3(shift[0] * s, shift[1] * s, shift[2] * s)),
        ])
    }
}

proptest! {
    #![proptest_config(config(4000))]

    /// Notes, "Generic Objects" and "Surface Normals at Intersections", for random rays and
    /// random placements of every shape: no NaN or infinity, hits in increasing t, unit normals
    /// facing out (against the ray where it enters, with it where it leaves), and every hit point
    /// on the generic surface to within a tolerance proportional to the rounding of the
    /// coordinates involved (2¹⁰·u·(1 + (|e| + |P|)/s_min) in object units).
    #[test]
    fn random_rays_at_random_placements_give_ordered_unit_outward_hits_on_the_surface(
        which in 0u8..5,
        (s, steps) in placement(),
        from in prop::array::uniform3(-60.0f64..60.0),
        towards in prop::array::uniform3(-1.5f64..1.5),
    ) {
        let shape = shape_of(which);
        let object = placed(shape.clone(), &steps);
        let m = object.placement.m();
        let origin = m.transform_point3(vec3(0.0, 0.0, 0.0)) + vec3(from[0] * s, from[1] * s, from[2] * s);
        let target = m.transform_point3(vec3(towards[0], towards[1], towards[2]));
        prop_assume!(origin != target);
        let ray = Ray::new(origin, target - origin);
        let hs = hits(&object, &ray, Formula::Robust);
        prop_assert!(all_finite(&hs), "{hs:?}");
        for w in hs.windows(2) {
            prop_assert!(w[0].t <= w[1].t, "{hs:?}");
        }
        let s_min = s * 0.25;
        let d = normalize(ray.dir);
        for h in &hs {
            prop_assert!((f(h.normal.length()) - 1.0).abs() < tol::UNIT, "{h:?}");
            let p = ray.at(h.t);
            let local = object.placement.inv().transform_point3(p);
            let scale = 1.0 + (f(origin.length()) + f(p.length())) / s_min;
            let residual = surface_residual(&shape, h.part, local);
            prop_assert!(residual <= 1024.0 * eps() * scale, "residual {residual} (scale {scale}) for {h:?} at {local:?}");
            if shape.is_closed() {
                // outward: against the ray where it enters, along it where it leaves (a graze
                // may be either, within rounding)
                let facing = f(h.normal.dot(d));
                let slack = 1e4 * eps();
                if h.entering {
                    prop_assert!(facing <= slack, "entering hit faces along the ray: {h:?}");
                } else {
                    prop_assert!(facing >= -slack, "leaving hit faces against the ray: {h:?}");
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(config(3000))]

    /// Notes, "Shadowing" and "Reflection and Refraction", at random placements: a ray spawned
    /// by the default (error-bound) offset from a hit on a convex shape never meets that surface
    /// again where it starts. Leaving outwards (n·dir > 0) it never meets the part it left
    /// (facet, cap, wall …) again; going inwards it meets that part at most once, on its way
    /// out, never entering it. (At an edge the pushed origin may sit just outside the
    /// neighbouring part, which the ray then crosses at once: an edge effect of any one-sided
    /// push, not a self-intersection.)
    #[test]
    fn spawned_rays_never_meet_their_own_surface_where_they_start(
        which in 0u8..5,
        (s, steps) in placement(),
        from in prop::array::uniform3(-60.0f64..60.0),
        towards in prop::array::uniform3(-0.9f64..0.9),
        tangent in prop::array::uniform3(-1.0f64..1.0),
        lift in 0.02f64..1.0,
        inwards in any::<bool>(),
    ) {
        let shape = shape_of(which);
        let object = placed(shape.clone(), &steps);
        let m = object.placement.m();
        let origin = m.transform_point3(Vec3::ZERO) + vec3(from[0] * s, from[1] * s, from[2] * s);
        let target = m.transform_point3(vec3(towards[0], towards[1], towards[2]));
        prop_assume!(origin != target);
        let ray = Ray::new(origin, target - origin);
        let hs = hits(&object, &ray, Formula::Robust);
        let Some(hit) = hs.first() else { return Ok(()); };
        let n = hit.normal;
        let t = vec3(tangent[0], tangent[1], tangent[2]);
        let t = t - n * t.dot(n);
        let side = if inwards { -1.0 } else { 1.0 };
        let dir = normalize(t + n * real(side * lift));
        prop_assume!(f(dir.dot(n)) * side > 0.01);
        let spawn = whitted::offset::SpawnPoint::new(&object, &ray, hit);
        let (start, t_min) = Offset::ErrorBound.spawn(&spawn, dir);
        let again = hits(&object, &Ray::new(start, dir), Formula::Robust);
        let ahead: Vec<&Hit> = again.iter().filter(|h| h.t > t_min).collect();
        // the surface it starts from: the same part (a facet, a cap, the wall …); at an edge the
        // ray may legitimately cross the neighbouring part right away
        let own: Vec<&&Hit> = ahead.iter().filter(|h| h.part == hit.part).collect();
        if !inwards || !shape.is_closed() {
            prop_assert!(own.is_empty(), "met its own surface again: {own:?} from {hit:?}");
        } else {
            prop_assert!(own.len() <= 1, "{:?} from {:?}", again, hit);
            prop_assert!(own.iter().all(|h| !h.entering), "entered its own surface again: {:?} from {:?}", again, hit);
        }
    }
}

/// The example scenes the loader is fuzzed with.
const SCENES: [(&str, &str); 8] = [
    (
        "scenes/showcase.toml",
        include_str!("../scenes/showcase.toml"),
    ),
    ("scenes/far.toml", include_str!("../scenes/far.toml")),
    (
        "scenes/grazing.toml",
        include_str!("../scenes/grazing.toml"),
    ),
    (
        "scenes/ch01_camera_rays.toml",
        include_str!("../scenes/ch01_camera_rays.toml"),
    ),
    (
        "scenes/ch02_generic_objects.toml",
        include_str!("../scenes/ch02_generic_objects.toml"),
    ),
    (
        "scenes/ch03_shading.toml",
        include_str!("../scenes/ch03_shading.toml"),
    ),
    (
        "scenes/ch04_shadows.toml",
        include_str!("../scenes/ch04_shadows.toml"),
    ),
    (
        "scenes/ch05_reflection_refraction.toml",
        include_str!("../scenes/ch05_reflection_refraction.toml"),
    ),
];

/// Pieces spliced into a scene: TOML punctuation, values at the edge of what is allowed, and
/// well-formed lines with bad values.
const PIECES: [&str; 34] = [
    "",
    "[",
    "]",
    "{",
    "}",
    "=",
    ",",
    "\"",
    "#",
    "\n",
    ".",
    "-",
    "nan",
    "inf",
    "-inf",
    "1e309",
    "-0.0",
    "0",
    "1e-320",
    "-1",
    "3.4e38",
    "18446744073709551616",
    "[[objects]]",
    "[camera]",
    "sphere = { center = [0, 0, 0], radius = 0 }",
    "material = \"nowhere\"",
    "transform = [ { scale = 0.0 } ]",
    "max_depth = 4294967295",
    "width = 0",
    "fov = 180",
    "near = 0",
    "ior = 0",
    "\u{0}",
    "é🦀",
];

/// One corruption: at a relative position, delete some bytes and insert a piece (or repeat a
/// slice of the text).
#[derive(Clone, Debug)]
struct Corruption {
    at: f64,
    delete: usize,
    piece: usize,
    copy_from: Option<f64>,
}

fn corruption() -> impl Strategy<Value = Corruption> {
    (
        0.0f64..1.0,
        0usize..8,
        0..PIECES.len(),
        prop::option::weighted(0.2, 0.0f64..1.0),
    )
        .prop_map(|(at, delete, piece, copy_from)| Corruption {
            at,
            delete,
            piece,
            copy_from,
        })
}

fn corrupt(text: &str, cuts: &[Corruption]) -> String {
    let mut bytes = text.as_bytes().to_vec();
    for c in cuts {
        let at = ((c.at * bytes.len() as f64) as usize).min(bytes.len());
        let end = (at + c.delete).min(bytes.len());
        let insert: Vec<u8> = match c.copy_from {
            Some(from) => {
                let start = ((from * bytes.len() as f64) as usize).min(bytes.len());
                bytes[start..(start + 40).min(bytes.len())].to_vec()
            }
            None => PIECES[c.piece].as_bytes().to_vec(),
        };
        bytes.splice(at..end, insert);
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

/// A corrupted scene that still loads is rendered tiny: every pixel must be finite.
fn loads_or_fails_politely(name: &str, text: &str) -> Result<(), TestCaseError> {
    match scene::parse(text, name) {
        Ok(scene) => {
            let mut options = Options::for_scene(&scene, Stage::ReflectionRefraction);
            (options.width, options.height, options.samples) = (3, 2, 1);
            options.max_depth = options.max_depth.min(3);
            let (fb, _) = render::render(&scene, &options);
            prop_assert!(fb.pixels.iter().all(|p| p.is_finite()));
        }
        Err(e) => {
            let message = e.to_string();
            prop_assert!(message.starts_with(&format!("{name}:")), "{message}");
            prop_assert!(!message.contains('\n') || message.lines().count() < 20);
        }
    }
    Ok(())
}

/// The tables of a scene (each from its `[header]` line to the next), with the comment lines
/// before the first table as table 0.
fn tables(text: &str) -> Vec<&str> {
    let mut starts: Vec<usize> = text.match_indices("\n[").map(|(i, _)| i + 1).collect();
    starts.insert(0, 0);
    starts.push(text.len());
    starts.windows(2).map(|w| &text[w[0]..w[1]]).collect()
}

proptest! {
    #![proptest_config(config(6_000))]

    /// The scene loader ("Errors are for people"): random corruptions of the whole example
    /// scenes give a scene that renders to finite pixels, or an error naming the file, never a
    /// panic.
    #[test]
    fn corrupted_example_scenes_load_or_fail_with_an_error_never_a_panic(
        which in 0usize..SCENES.len(),
        cuts in prop::collection::vec(corruption(), 1..4),
    ) {
        let (name, text) = SCENES[which];
        loads_or_fails_politely(name, &corrupt(text, &cuts))?;
    }
}

proptest! {
    // with the 6 000 whole scenes above: 106 000 corrupted scenes. Parsing costs about 70 ns
    // per byte in a debug build, so most cases are excerpts of one to four tables.
    #![proptest_config(config(100_000))]

    /// The same for excerpts of the example scenes (a run of one to four of their tables,
    /// then one of their objects), corrupted: an error naming the file or a scene that renders
    /// to finite pixels, never a panic.
    #[test]
    fn corrupted_excerpts_of_the_example_scenes_load_or_fail_with_an_error_never_a_panic(
        which in 0usize..SCENES.len(),
        first in 0.0f64..1.0,
        count in 1usize..5,
        object in 0.0f64..1.0,
        cuts in prop::collection::vec(corruption(), 1..3),
    ) {
        let (name, text) = SCENES[which];
        let all = tables(text);
        let first = ((first * all.len() as f64) as usize).min(all.len() - 1);
        let objects: Vec<&str> = all.iter().copied().filter(|t| t.starts_with("[[objects]]")).collect();
        let object = objects[((object * objects.len() as f64) as usize).min(objects.len() - 1)];
        let mut excerpt: String = all[first..(first + count).min(all.len())].concat();
        excerpt.push_str(object);
        loads_or_fails_politely(name, &corrupt(&excerpt, &cuts))?;
    }
}
