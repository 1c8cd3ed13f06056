//! Spheres: small and far, large and near, grazing, tangent.

use super::{eps, f, hits, placed, rel_err, tol};
use whitted::numeric::normalize;
use whitted::ray::Ray;
use whitted::real::{Vec3, real, vec3};
use whitted::shapes::{Hit, Numerics, Object, Shape};
use whitted::transform::{Placement, Step};

/// A unit sphere centred at (0, 0, −D) and a ray from (h, 0, 0) along −z: hits at
/// t = D ∓ √(1 − h²).
fn far_sphere_case(h: f64, numerics: Numerics) -> Vec<Hit> {
    let sphere = placed(Shape::Sphere, &[Step::Translate(vec3(0.0, 0.0, -tol::FAR))]);
    let ray = Ray::new(vec3(h, 0.0, 0.0), vec3(0.0, 0.0, -1.0));
    hits(&sphere, &ray, numerics)
}

pub(super) fn far_sphere_is_right(hs: &[Hit], h: f64) -> bool {
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
        let robust = far_sphere_case(h, Numerics::Robust);
        assert!(
            far_sphere_is_right(&robust, h),
            "robust, h = {h}: {robust:?}"
        );
    }
    let textbook = far_sphere_case(0.5, Numerics::Textbook);
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
        let robust = far_sphere_case(h, Numerics::Robust);
        assert!(far_sphere_is_right(&robust, h), "h = {h}: {robust:?}");
    }
    let wrong = [0.99, 1.01]
        .iter()
        .filter(|&&h| !far_sphere_is_right(&far_sphere_case(h, Numerics::Textbook), h))
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
    let hs = hits(&sphere, &ray, Numerics::Robust);
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
    let robust = hits(&sphere, &ray, Numerics::Robust);
    let textbook = hits(&sphere, &ray, Numerics::Textbook);
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
