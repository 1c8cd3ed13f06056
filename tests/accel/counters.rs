//! With the `counters` feature: the work each structure saves, the BVH's nearer-child-first
//! packet walk, and the octree's mailbox (an object in several leaves tested once a ray).

use crate::common::brute_share;
use whitted::accel::aabb::world_bounds;
use whitted::accel::{Aabb, Accel, Accelerator, Octree};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::{self, Chapter, Options, TILE};
use whitted::scene::parse;
use whitted::scene::scatter;
use whitted::shadow;

/// Built with the `counters` feature, the counts show what each structure saves on camera
/// rays (chapter 2: one query a pixel): brute force tests every object and no box, `boxes`
/// one box per bounded object, and the BVH a few nodes and a small share of the objects.
#[cfg(feature = "counters")]
#[test]
fn counters_show_the_work_each_structure_saves() {
    let (w, h) = (48u32, 27u32);
    let scene = parse(&scatter::scene_toml(200, 3, w, h), "s.toml").unwrap();
    let work = |accel| {
        let mut o = Options::for_scene(&scene, Chapter::GenericObjects);
        (o.width, o.height, o.accel) = (w, h, accel);
        render::render(&scene, &o).1.work
    };
    let pixels = u64::from(w * h);
    let none = work(Accel::None);
    assert_eq!(none.queries, pixels);
    assert_eq!(
        none.objects,
        pixels * 201,
        "every sphere and the floor, every pixel"
    );
    assert_eq!((none.nodes, none.boxes), (0, 0));
    let boxes = work(Accel::Boxes);
    assert_eq!(
        boxes.boxes,
        pixels * 200,
        "a box per sphere; the floor has none"
    );
    assert!(boxes.objects < none.objects);
    let bvh = work(Accel::Bvh);
    assert_eq!(bvh.queries, pixels);
    assert!(bvh.nodes > 0 && bvh.boxes < boxes.boxes / 4, "{bvh:?}");
    assert!(bvh.objects * 20 < none.objects, "{bvh:?} against {none:?}");
    // gathered band by band on whatever thread ran them, the counts are the same every time
    assert_eq!(work(Accel::Bvh), bvh);
}

/// A packet walks the BVH nearer child first: the hits it finds there spare the far side.
/// Sixteen camera rays looking down −z meet two spheres one behind the other; the BVH splits
/// them along z, the far sphere on the left (the lower centres). Nearer first, the packet
/// tests the near sphere only (16 object tests); the far one first, as the walk did before
/// it read the split axis, it would test both (32).
#[cfg(feature = "counters")]
#[test]
fn a_packet_opens_the_nearer_child_of_the_bvh_first() {
    let scene = parse(
        "[camera]\neye = [0.0, 0.0, 20.0]\nlook_at = [0.0, 0.0, 0.0]\n\n\
         [[objects]]\nsphere = { center = [0.0, 0.0, -10.0], radius = 2.0 }\n\n\
         [[objects]]\nsphere = { center = [0.0, 0.0, 0.0], radius = 2.0 }\n",
        "row.toml",
    )
    .unwrap();
    let rays: Vec<Ray> = (0..16)
        .map(|k| {
            let (i, j) = (f64::from(k % 4), f64::from(k / 4));
            Ray::new(
                vec3(0.0, 0.0, 20.0),
                vec3(0.01 * i - 0.015, 0.01 * j - 0.015, -1.0),
            )
        })
        .collect();
    let brute = Accelerator::build(&scene.objects, &scene.camera(), Accel::None, TILE);
    let bvh = Accelerator::build(&scene.objects, &scene.camera(), Accel::Bvh, TILE);
    assert!(
        bvh.describe().contains("3 nodes"),
        "a root and two leaves: {}",
        bvh.describe()
    );
    let mut got = vec![None; 16];
    let _ = whitted::accel::counters::take();
    bvh.nearest_packet(&scene.objects, &rays, 0.0, Default::default(), &mut got);
    let work = whitted::accel::counters::take();
    assert_eq!(work.queries, 16);
    assert_eq!(work.objects, 16, "the near sphere only: {work:?}");
    for (ray, got) in rays.iter().zip(&got) {
        let want = brute.nearest(&scene.objects, ray, 0.0, Default::default());
        assert_eq!(want.map(|n| n.object), Some(1), "the near sphere is hit");
        assert_eq!(*got, want);
    }
}

/// An object that straddles the octree's cubes sits in several leaves; a packet crossing two
/// of them tests it once a ray, not once a leaf (the walk's mailbox), and the answers stay
/// brute force's. Sixteen feelers climb through a translucent sphere that every octant holds:
/// 16 object tests, where testing it in both leaves they cross would make 32.
#[cfg(feature = "counters")]
#[test]
fn an_object_in_several_leaves_is_tested_once_a_ray() {
    let mut toml = String::from(
        "[camera]\neye = [0.0, 0.0, 20.0]\nlook_at = [0.0, 0.0, 0.0]\n\n\
         [materials.haze]\ndiffuse = 0.2\ntransmission = 0.5\nior = 1.0\n\n\
         [[objects]]\nsphere = { center = [0.0, 0.0, 0.0], radius = 4.0 }\nmaterial = \"haze\"\n",
    );
    // one small opaque sphere in each octant, away from the feelers, so that the root splits
    for k in 0..8 {
        let c = [1, 2, 4].map(|bit| if k & bit == 0 { -3.0 } else { 3.0 });
        toml += &format!(
            "\n[[objects]]\nsphere = {{ center = [{:.1}, {:.1}, {:.1}], radius = 0.3 }}\n",
            c[0], c[1], c[2]
        );
    }
    let scene = parse(&toml, "shared.toml").unwrap();
    let boxes: Vec<Aabb> = scene.objects.iter().filter_map(world_bounds).collect();
    let (fullest, pairs) = Octree::build(&boxes, 4).leaf_load();
    assert_eq!(
        (fullest, pairs),
        (2, 16),
        "each octant holds the big sphere and one small one"
    );
    let light = vec3(0.5, 9.0, 0.5);
    let origins: Vec<Vec3> = (0..16)
        .map(|k| {
            let (i, j) = (f64::from(k % 4), f64::from(k / 4));
            vec3(0.5 + 0.05 * i, -9.0, 0.5 + 0.05 * j)
        })
        .collect();
    let u_min = [real(1e-6); 16];
    for kind in [Accel::Octree, Accel::Bvh] {
        let tree = Accelerator::build(&scene.objects, &scene.camera(), kind, TILE);
        let mut share = [Real::NAN; 16];
        let _ = whitted::accel::counters::take();
        let feelers: Vec<Ray> = origins.iter().map(|&o| shadow::feeler(o, light)).collect();
        tree.transmittance_packet(
            &scene.objects,
            &scene.materials,
            light,
            &feelers,
            &u_min,
            Default::default(),
            &mut share,
        );
        let work = whitted::accel::counters::take();
        assert_eq!(work.queries, 16);
        assert_eq!(
            work.objects, 16,
            "{kind:?}: the big sphere once a feeler: {work:?}"
        );
        for (k, &o) in origins.iter().enumerate() {
            let want = brute_share(
                &scene.objects,
                &scene.materials,
                &shadow::feeler(o, light),
                u_min[k],
                Default::default(),
            );
            assert_eq!(want, 0.5, "the feeler crosses the haze only");
            assert_eq!(share[k].to_bits(), want.to_bits(), "{kind:?}, feeler {k}");
        }
    }
}
