//! Placements from 1e-6 to 1e6 (fixed and random), normalising huge and tiny vectors, and
//! hit points on the placed surface.

use super::{all_finite, config, eps, f, hits, placed, placement, shape_of, tol};
use proptest::prelude::*;
use whitted::numeric::{normalize, normalize_naive};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::shapes::{Numerics, Part, Shape};
use whitted::transform::Step;

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
                let hs = hits(&object, &ray, Numerics::Robust);
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
        let hs = hits(&object, &ray, Numerics::Robust);
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
