//! Bounding boxes: world boxes hold every hit, a polyhedron's comes from its vertices, planes
//! have none (they stay outside the hierarchy), and the slab test for rays parallel to an axis.

use super::{STRAIN, assert_all_equal, render_with, showcase};
use whitted::accel::aabb::{RayBox, polyhedron_bounds, world_bounds};
use whitted::accel::{Aabb, Accel, Accelerator};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, vec3};
use whitted::render::{Chapter, TILE};
use whitted::scene::parse;
use whitted::scene::scatter;
use whitted::shapes::{Facet, Polyhedron};

/// The world box of a placed object holds every hit the object reports.
#[test]
fn world_boxes_hold_every_hit() {
    let scene = parse(STRAIN, "strain.toml").unwrap();
    let mut rng = scatter::SplitMix64::new(3);
    let mut checked = 0;
    for o in &scene.objects {
        let Some(b) = world_bounds(o) else {
            assert_eq!(o.shape.name(), "plane");
            continue;
        };
        for _ in 0..2000 {
            let origin = vec3(
                rng.range(-8.0, 8.0),
                rng.range(-8.0, 8.0),
                rng.range(-8.0, 8.0),
            );
            let target = b.centre()
                + vec3(
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                ) * (b.max - b.min) as Vec3;
            let ray = Ray::new(origin, target - origin);
            let hits = o.intersect(&ray, Default::default());
            for h in hits.as_slice() {
                let p = ray.at(h.t);
                assert!(
                    p.cmpge(b.min).all() && p.cmple(b.max).all(),
                    "{} hit at {p:?} outside its box {b:?}",
                    o.shape.name()
                );
                let (enter, exit) = b.slabs(&RayBox::new(&ray));
                assert!(enter <= h.t && h.t <= exit);
                checked += 1;
            }
        }
    }
    assert!(checked > 1000, "only {checked} hits checked");
}

/// A polyhedron's box comes from its vertices: the cube's is [−1, 1]³; a slab open on one
/// side has none (it lives outside the hierarchy).
#[test]
fn polyhedron_boxes_come_from_vertices_and_open_ones_have_none() {
    let b = polyhedron_bounds(&Polyhedron::cube()).expect("the cube is bounded");
    assert!((b.min - Vec3::splat(-1.0)).length() < 1e-6 && (b.max - Vec3::ONE).length() < 1e-6);
    let f = |n: [f64; 3], d: f64| Facet::new(vec3(n[0], n[1], n[2]), d as Real).unwrap();
    let long = Polyhedron::new(vec![
        f([1., 0., 0.], 3.),
        f([-1., 0., 0.], 3.),
        f([0., 1., 0.], 1.),
        f([0., -1., 0.], 1.),
        f([0., 0., 1.], 0.5),
        f([0., 0., -1.], 0.5),
    ]);
    let b = polyhedron_bounds(&long).expect("bounded");
    assert!((b.max - vec3(3.0, 1.0, 0.5)).length() < 1e-6);
    let open = Polyhedron::new(vec![
        f([1., 0., 0.], 1.),
        f([-1., 0., 0.], 1.),
        f([0., 1., 0.], 1.),
        f([0., -1., 0.], 1.),
        f([0., 0., 1.], 1.), // nothing closes −z
    ]);
    assert_eq!(polyhedron_bounds(&open), None);
}

/// Infinite planes live outside every hierarchy; everything else inside.
#[test]
fn planes_stay_outside_the_hierarchy() {
    let scene = showcase();
    let cam = scene.camera();
    for accel in [Accel::Boxes, Accel::Extents, Accel::Octree, Accel::Bvh] {
        let a = Accelerator::build(&scene.objects, &cam, accel, TILE);
        assert!(
            a.describe().contains("6 bounded, 1 unbounded"),
            "{}",
            a.describe()
        );
    }
    let a = Accelerator::build(&scene.objects, &cam, Accel::None, TILE);
    assert!(
        a.describe().contains("0 bounded, 7 unbounded"),
        "{}",
        a.describe()
    );
}

/// Rays with a zero direction component: 1/d is held at ±Real::MAX instead of ±∞, so the
/// slab test never computes 0·∞ (NaN), and its plain comparisons stay right. A ray parallel
/// to a slab, inside it, crosses the box; outside it, misses; lying in a face plane, either
/// answer is safe (the padded boxes keep every object off their faces), but never NaN.
#[test]
fn slab_test_handles_rays_parallel_to_an_axis() {
    let b = Aabb {
        min: vec3(-1.0, -1.0, -1.0),
        max: vec3(1.0, 1.0, 1.0),
    };
    for zero in [0.0, -0.0] {
        let rb = RayBox::new(&Ray::new(vec3(0.5, 0.5, -5.0), vec3(zero, zero, 1.0)));
        assert!(rb.inv_dir().is_finite(), "{:?}", rb.inv_dir());
        assert_eq!(rb.inv_dir().x.is_sign_negative(), zero.is_sign_negative());
        // inside the x and y slabs: enters at z = −1 (t = 4) and leaves at z = 1 (t = 6)
        let (enter, exit) = b.slabs(&rb);
        assert!((enter - 4.0).abs() < 1e-4 && (exit - 6.0).abs() < 1e-4);
        assert!(b.hit_between(&rb, 0.0, Real::INFINITY));
        // beside the box, in either direction along the axis
        for (x, dz) in [(1.5, 1.0), (-1.5, 1.0), (1.5, -1.0)] {
            let rb = RayBox::new(&Ray::new(vec3(x, 0.5, -5.0 * dz), vec3(zero, zero, dz)));
            assert!(
                !b.hit_between(&rb, 0.0, Real::INFINITY),
                "x = {x}, dz = {dz}"
            );
        }
        // in a face plane: no NaN, whichever answer
        for x in [-1.0, 1.0] {
            for dz in [1.0, -1.0] {
                let rb = RayBox::new(&Ray::new(vec3(x, 0.5, -5.0 * dz), vec3(zero, zero, dz)));
                let (enter, exit) = b.slabs(&rb);
                assert!(!enter.is_nan() && !exit.is_nan(), "x = {x}, dz = {dz}");
            }
        }
    }
    // what the clamp prevents: with 1/0 = ∞, a bound on the origin gives 0·∞
    let inf: Real = 1.0 / 0.0;
    assert!(((1.0 as Real - 1.0) * inf).is_nan());
    // a sphere seen along an axis is still found through every structure
    let text = r#"
[camera]
eye = [0.0, 0.0, 5.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
fov = 40.0
[image]
width = 9
height = 9
[materials.m]
diffuse = 0.5
[[objects]]
shape = "sphere"
material = "m"
[[lights]]
position = [0.0, 0.0, 5.0]
intensity = 1.0
"#;
    let scene = parse(text, "axis.toml").expect("parses");
    assert_all_equal(&render_with(&scene, Chapter::Shadows, 9, 9, |_| {}));
}
