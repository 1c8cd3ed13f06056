//! Speed without changing a pixel (notes: "Computational Aspects"): every acceleration
//! technique gives exactly the brute-force image, whatever the number of threads.

mod common;

use common::brute_share;
use whitted::accel::aabb::{RayBox, polyhedron_bounds, world_bounds};
use whitted::accel::extents::{Footprint, footprint};
use whitted::accel::{Aabb, Accel, Accelerator, Bvh, Octree};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::{self, Framebuffer, Options, Stage, Stats, TILE, View};
use whitted::scene::scatter;
use whitted::scene::{Scene, parse};
use whitted::shadow;
use whitted::shapes::{Facet, Polyhedron};

fn showcase() -> Scene {
    whitted::cli::read_scene(None).expect("the showcase parses")
}

fn render_with(
    scene: &Scene,
    stage: Stage,
    w: u32,
    h: u32,
    f: impl Fn(&mut Options),
) -> Vec<(Accel, Framebuffer, Stats)> {
    Accel::ALL
        .iter()
        .map(|&accel| {
            let mut o = Options::for_scene(scene, stage);
            o.width = w;
            o.height = h;
            o.accel = accel;
            f(&mut o);
            let (fb, stats) = render::render(scene, &o);
            (accel, fb, stats)
        })
        .collect()
}

/// Asserts that every option rendered the `none` image bit for bit, and cast the same rays.
fn assert_all_equal(renders: &[(Accel, Framebuffer, Stats)]) {
    let (_, reference, ref_stats) = &renders[0];
    assert!(
        reference.pixels.iter().any(|p| *p != reference.pixels[0]),
        "a blank image proves nothing"
    );
    for (accel, fb, stats) in &renders[1..] {
        let differing = fb
            .pixels
            .iter()
            .zip(&reference.pixels)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(
            differing,
            0,
            "--accel {} differs from none in {differing} pixels",
            accel.name()
        );
        // the rays cast must agree; the work behind them (counted with the `counters`
        // feature) is what the structures change
        let rays = |s: &Stats| Stats {
            work: Default::default(),
            ..*s
        };
        assert_eq!(
            rays(stats),
            rays(ref_stats),
            "--accel {} cast other rays",
            accel.name()
        );
    }
}

/// A scene with what strains the structures: a camera inside a sphere's box and objects
/// behind the eye (projection extents must give up there), overlapping glass spheres that a
/// feeler crosses in turn (transmissions multiplied in scene order), a custom polyhedron
/// larger than [−1, 1]³, a tilted cone and cylinder, and two planes.
const STRAIN: &str = r#"
[camera]
eye = [0.0, 1.0, 4.0]
look_at = [0.0, 0.8, 0.0]
up = [0.0, 1.0, 0.0]
fov = 70.0

[image]
width = 96
height = 72

[render]
max_depth = 4

[[lights]]
position = [2.0, 6.0, 3.0]
intensity = 0.8

[[lights]]
position = [-3.0, 2.0, -4.0]
intensity = 0.4

[materials.glass]
diffuse = 0.05
specular = 0.5
shininess = 80
reflection = 0.1
transmission = 0.8
ior = 1.4

[materials.haze]
diffuse = 0.2
transmission = 0.5
ior = 1.0

[materials.mirror]
diffuse = 0.2
reflection = 0.7

[materials.red]
diffuse = [0.7, 0.1, 0.1]
specular = 0.3
shininess = 20

[[objects]]
plane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }

[[objects]]
plane = { point = [0.0, 0.0, -6.0], normal = [0.0, 0.0, 1.0] }
material = "mirror"

[[objects]]
sphere = { center = [0.0, 1.0, 4.2], radius = 0.6 }
material = "haze"

[[objects]]
sphere = { center = [0.0, 1.0, 7.0], radius = 1.0 }
material = "red"

[[objects]]
sphere = { center = [-0.4, 1.0, 0.0], radius = 0.8 }
material = "glass"

[[objects]]
sphere = { center = [0.3, 1.2, 0.2], radius = 0.7 }
material = "glass"

[[objects]]
sphere = { center = [0.8, 2.5, 1.0], radius = 0.4 }
material = "haze"

[[objects]]
polyhedron = { facets = [[1, 0, 0, 3], [-1, 0, 0, 3], [0, 1, 0, 1], [0, -1, 0, 1], [0, 0, 1, 0.5], [0, 0, -1, 0.5]] }
transform = [ { scale = 0.3 }, { rotate_y = 25.0 }, { translate = [1.5, 0.4, -1.0] } ]
material = "red"

[[objects]]
cone = { base = [-2.0, 0.0, -1.5], apex = [-1.2, 2.0, -1.8], radius = 0.6 }
material = "mirror"

[[objects]]
cylinder = { base = [1.8, 0.0, 1.0], top = [2.4, 1.2, 0.2], radius = 0.3 }
material = "red"

[[objects]]
shape = "tetrahedron"
transform = [ { scale = 0.5 }, { translate = [-1.5, 0.5, 1.5] } ]
material = "glass"
"#;

/// Notes, "Computational Aspects": bounding boxes and extents only skip work. The showcase
/// renders identically with every `--accel`.
#[test]
fn every_accel_renders_the_showcase_exactly_as_brute_force() {
    let scene = showcase();
    assert_all_equal(&render_with(
        &scene,
        Stage::ReflectionRefraction,
        128,
        96,
        |_| {},
    ));
}

/// The chapter-2 views go through the same nearest-hit query: identical normals and depths.
#[test]
fn every_accel_gives_the_same_normals_and_depths() {
    let scene = showcase();
    for view in [View::Normals, View::Depth, View::Color] {
        assert_all_equal(&render_with(&scene, Stage::GenericObjects, 80, 60, |o| {
            o.view = view
        }));
    }
}

/// Translucent objects in a row, a camera inside a box, objects behind the eye, custom
/// facets, supersampling: still the brute-force image.
#[test]
fn every_accel_renders_a_demanding_scene_exactly_as_brute_force() {
    let scene = parse(STRAIN, "strain.toml").expect("the strain scene parses");
    assert_all_equal(&render_with(
        &scene,
        Stage::ReflectionRefraction,
        96,
        72,
        |_| {},
    ));
    assert_all_equal(&render_with(&scene, Stage::Shadows, 48, 36, |o| {
        o.samples = 4
    }));
}

/// Many small random spheres, the scaling scene: still the brute-force image.
#[test]
fn every_accel_renders_many_spheres_exactly_as_brute_force() {
    for layout in [scatter::Layout::Field, scatter::Layout::Fog] {
        let text = scatter::scene_toml_with(300, 7, 96, 54, layout);
        let scene = parse(&text, "scatter.toml").expect("parses");
        assert_eq!(scene.objects.len(), 301);
        assert_all_equal(&render_with(
            &scene,
            Stage::ReflectionRefraction,
            96,
            54,
            |_| {},
        ));
    }
}

/// Tiles are rendered in parallel, and each pixel depends only on its coordinates: one
/// thread and four give the same bytes.
#[test]
fn one_thread_and_four_render_the_same_image() {
    let scene = parse(STRAIN, "strain.toml").unwrap();
    let mut o = Options::for_scene(&scene, Stage::ReflectionRefraction);
    o.width = 70; // not a multiple of the tile size
    o.height = 45;
    o.samples = 2;
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| render::render(&scene, &o))
    };
    let (one, s1) = run(1);
    let (four, s4) = run(4);
    assert_eq!(
        whitted::output::to_rgb8(&one),
        whitted::output::to_rgb8(&four)
    );
    assert_eq!(one, four);
    assert_eq!(s1, s4);
}

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

/// The framebuffer limit: 8192 × 8192 is allowed, 65535 × 65535 is refused with one line.
#[test]
fn framebuffer_limit_allows_8192_squared_and_refuses_65535_squared() {
    assert!(render::check_size(8192, 8192).is_ok());
    let e = render::check_size(65_535, 65_535).unwrap_err().to_string();
    assert!(e.contains("too large") && !e.contains('\n'), "{e}");
}

/// The scaling scene is reproducible: same N and seed, same text; another seed, another scene.
#[test]
fn scatter_scenes_are_seeded() {
    assert_eq!(
        scatter::scene_toml(50, 1, 64, 36),
        scatter::scene_toml(50, 1, 64, 36)
    );
    assert_ne!(
        scatter::scene_toml(50, 1, 64, 36),
        scatter::scene_toml(50, 2, 64, 36)
    );
    let s = parse(&scatter::scene_toml(1000, 1, 64, 36), "s.toml").unwrap();
    assert_eq!(s.objects.len(), 1001);
    assert!((scatter::radius(10) / scatter::radius(1000) - 10.0).abs() < 1e-9);
}

/// `scatter --pov` writes the very scene whitted renders: the same spheres in the same
/// order, each centre with z negated (POV-Ray is left-handed), the same radius, and mirrors
/// where the TOML has them.
#[test]
fn scatter_writes_the_same_scene_for_povray() {
    for layout in [scatter::Layout::Field, scatter::Layout::Fog] {
        let scene = parse(&scatter::scene_toml_with(40, 5, 64, 36, layout), "s.toml").unwrap();
        let pov = scatter::scene_pov(40, 5, layout);
        let spheres: Vec<&str> = pov.lines().filter(|l| l.starts_with("sphere")).collect();
        assert_eq!(spheres.len(), 40);
        // object 0 is the floor; the spheres follow in the order they were drawn
        for (line, object) in spheres.iter().zip(&scene.objects[1..]) {
            let numbers: Vec<f64> = line
                .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                .filter_map(|w| w.parse().ok())
                .collect();
            let [x, y, z, r] = numbers[..] else {
                panic!("{line}")
            };
            let centre = object.placement.m().transform_point3(Vec3::ZERO);
            let radius = object.placement.m().transform_vector3(Vec3::X).length();
            let near = |a: f64, b: Real| (real(a) - b).abs() < 1e-4 * (1.0 + b.abs());
            assert!(
                near(x, centre.x) && near(y, centre.y) && near(-z, centre.z),
                "{line}"
            );
            assert!(near(r, radius), "{line}");
            let mirror = scene.materials[object.material].reflection > 0.0;
            assert_eq!(line.contains("Mirror"), mirror, "{line}");
        }
    }
}

/// Projection extents: a box in front of the eye covers the rectangle of its projected
/// corners, one straddling the eye plane may cover any pixel, one wholly behind it none.
#[test]
fn projection_extents_follow_the_box_around_the_eye() {
    let cam = showcase().camera.camera(64, 48); // eye (0, 2.4, 8.5) looking towards −z
    let boxed = |lo: [f64; 3], hi: [f64; 3]| Aabb {
        min: vec3(lo[0], lo[1], lo[2]),
        max: vec3(hi[0], hi[1], hi[2]),
    };
    match footprint(&boxed([-0.1, 0.8, -0.1], [0.1, 1.0, 0.1]), &cam) {
        Footprint::Rectangle([x0, x1, y0, y1]) => {
            // a small box at the point looked at: a few pixels around the image centre
            assert!(
                x0 > 20 && x1 < 44 && y0 > 14 && y1 < 34,
                "{x0} {x1} {y0} {y1}"
            );
            assert!(x0 < 32 && 32 < x1);
        }
        other => panic!("expected a rectangle, found {other:?}"),
    }
    assert_eq!(
        footprint(&boxed([-1.0, 2.0, 8.0], [1.0, 3.0, 9.0]), &cam),
        Footprint::Anywhere
    );
    assert_eq!(
        footprint(&boxed([-1.0, 2.0, 10.0], [1.0, 3.0, 12.0]), &cam),
        Footprint::Nowhere
    );
}

/// A distribution the SAH bins would peel one object at a time (centres in a geometric
/// progression) still gives a tree shallow enough to walk, which finds every box.
#[test]
fn a_bvh_over_a_geometric_progression_stays_walkable() {
    let boxes: Vec<Aabb> = (0..3000)
        .map(|i| {
            let x = (1.01 as Real).powi(i);
            Aabb {
                min: vec3(0.0, 0.0, 0.0) + Vec3::X * x,
                max: Vec3::new(x + 0.5, 1.0, 1.0),
            }
        })
        .collect();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(vec3(-1.0, 0.5, 0.5), vec3(1.0, 0.0, 0.0));
    let mut limit = Real::INFINITY;
    let mut seen = vec![false; boxes.len()];
    bvh.walk(&RayBox::new(&ray), 0.0, &mut limit, |k, _| {
        seen[bvh.order()[k as usize] as usize] = true;
        true
    });
    assert!(
        seen.iter().all(|&s| s),
        "the walk along the row must meet every box"
    );
}

/// Built with the `counters` feature, the counts show what each structure saves on camera
/// rays (chapter 2: one query a pixel): brute force tests every object and no box, `boxes`
/// one box per bounded object, and the BVH a few nodes and a small share of the objects.
#[cfg(feature = "counters")]
#[test]
fn counters_show_the_work_each_structure_saves() {
    let (w, h) = (48u32, 27u32);
    let scene = parse(&scatter::scene_toml(200, 3, w, h), "s.toml").unwrap();
    let work = |accel| {
        let mut o = Options::for_scene(&scene, Stage::GenericObjects);
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
        let want = brute.nearest(&scene.objects, ray, 0.0, Default::default(), None);
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
        assert!(rb.inv_dir.is_finite(), "{:?}", rb.inv_dir);
        assert_eq!(rb.inv_dir.x.is_sign_negative(), zero.is_sign_negative());
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
    assert_all_equal(&render_with(&scene, Stage::Shadows, 9, 9, |_| {}));
}

/// Packets of rays walked through the BVH or the octree together give, ray by ray, exactly what brute
/// force gives: nearest hits, and feeler shares (translucent blockers included). Coherent
/// packets (one origin, a narrow cone, as camera rays), incoherent ones (directions of every
/// sign, where the interval test stands aside) and axis-parallel rays, of every size.
#[test]
fn packets_answer_as_single_rays_do() {
    use whitted::accel::PACKET;
    let strain = parse(STRAIN, "strain.toml").unwrap();
    let field = parse(
        &scatter::scene_toml_with(300, 5, 96, 54, scatter::Layout::Fog),
        "fog.toml",
    )
    .unwrap();
    let mut rng = scatter::SplitMix64::new(11);
    let mut r = |lo: f64, hi: f64| rng.range(lo, hi);
    let mut checked = (0, 0, 0);
    for scene in [&strain, &field] {
        let cam = scene.camera();
        let brute = Accelerator::build(&scene.objects, &cam, Accel::None, TILE);
        for round in 0..600 {
            let kind = [Accel::Bvh, Accel::Octree][round % 2];
            let tree = Accelerator::build(&scene.objects, &cam, kind, TILE);
            let n = 1 + round % PACKET;
            let centre = vec3(r(-8.0, 8.0), r(-2.0, 8.0), r(-8.0, 8.0));
            let aim = vec3(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0));
            let rays: Vec<Ray> = (0..n)
                .map(|k| match round % 3 {
                    // one origin, a narrow cone
                    0 => Ray::new(centre, aim + vec3(r(-0.05, 0.05), r(-0.05, 0.05), 0.0)),
                    // anything
                    1 => Ray::new(
                        vec3(r(-8.0, 8.0), r(-2.0, 8.0), r(-8.0, 8.0)),
                        vec3(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)),
                    ),
                    // along an axis, from points of a line
                    _ => {
                        let mut d = [0.0; 3];
                        d[(round / 3) % 3] = if k % 2 == 0 { 1.0 } else { -1.0 };
                        Ray::new(
                            centre + Vec3::X * real(k as f64 * 0.1),
                            vec3(d[0], d[1], d[2]),
                        )
                    }
                })
                .collect();
            let t_min = if round % 2 == 0 {
                0.0
            } else {
                real(r(0.0, 1.0))
            };
            let mut got = vec![None; n];
            tree.nearest_packet(&scene.objects, &rays, t_min, Default::default(), &mut got);
            for (ray, got) in rays.iter().zip(&got) {
                let want = brute.nearest(&scene.objects, ray, t_min, Default::default(), None);
                assert_eq!(*got, want, "{kind:?}: {ray:?}, t_min {t_min}");
                checked.0 += usize::from(want.is_some());
            }
            // feelers from the rays' origins to one light
            let light = vec3(r(-6.0, 6.0), r(2.0, 9.0), r(-6.0, 6.0));
            let origins: Vec<Vec3> = rays.iter().map(|ray| ray.at(real(r(0.0, 4.0)))).collect();
            // tiny u_min, as the renderer's, and large ones (the feeler starts well along its
            // way), which the walk from the light must still cover to its end
            let u_max = if round % 4 < 2 { 1e-3 } else { 0.9 };
            let u_min: Vec<Real> = (0..n).map(|_| real(r(1e-9, u_max))).collect();
            let mut share = vec![Real::NAN; n];
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
            for k in 0..n {
                let want = brute_share(
                    &scene.objects,
                    &scene.materials,
                    &feelers[k],
                    u_min[k],
                    Default::default(),
                );
                assert_eq!(
                    share[k].to_bits(),
                    want.to_bits(),
                    "{kind:?}: feeler from {:?}",
                    origins[k]
                );
                checked.1 += usize::from(want == 0.0);
                checked.2 += usize::from(want > 0.0 && want < 1.0);
            }
        }
    }
    // the rays found things, and the feelers met opaque and translucent blockers
    assert!(
        checked.0 > 500 && checked.1 > 100 && checked.2 > 5,
        "{checked:?}"
    );
}

/// The octree's cube starts at the scene's lower corner: a flat layer of objects (spheres on a
/// floor) is not cut through its middle by the first split, which would copy every object
/// into two cells. A cube centred on the layer does exactly that.
#[test]
fn a_flat_layer_is_not_copied_into_two_halves() {
    // 400 small boxes on a 20 × 20 grid, all in the layer 0 ≤ y ≤ 0.7
    let boxes: Vec<Aabb> = (0..400)
        .map(|i| {
            let (x, z) = ((i % 20) as f64 * 10.0, (i / 20) as f64 * 10.0);
            Aabb {
                min: vec3(x, 0.0, z),
                max: vec3(x, 0.0, z) + vec3(0.7, 0.7, 0.7),
            }
        })
        .collect();
    let tree = Octree::build(&boxes, 4);
    let (fullest, pairs) = tree.leaf_load();
    assert!(fullest <= 4, "{fullest}");
    // a box may still straddle a vertical split now and then, but not every box
    assert!(
        pairs < boxes.len() * 5 / 4,
        "{pairs} (object, leaf) pairs for 400 boxes"
    );
    // and wherever the layer lies: moved down by half its height, around y = 0, the same
    // boxes land in as many cells (the old cube, centred on the scene, gave 800 pairs here)
    let centred: Vec<Aabb> = boxes
        .iter()
        .map(|b| Aabb {
            min: b.min - vec3(0.0, 0.35, 0.0),
            max: b.max - vec3(0.0, 0.35, 0.0),
        })
        .collect();
    let (_, centred_pairs) = Octree::build(&centred, 4).leaf_load();
    assert_eq!(
        centred_pairs, pairs,
        "the cube follows the layer wherever it lies"
    );
}

/// The octree renumbers its objects in the order its leaves name them: the order it returns
/// is a permutation of the objects, neighbours in space get neighbouring numbers (a leaf's
/// objects are numbered one after another), and a second renumbering changes nothing.
#[test]
fn the_octree_numbers_its_objects_leaf_by_leaf() {
    // 256 unit boxes on a 16 × 16 grid, listed in an order that scatters neighbours: the
    // scene's k-th box sits at grid cell (37·k mod 256)
    let boxes: Vec<Aabb> = (0..256)
        .map(|k| {
            let cell = (k * 37) % 256;
            let (x, z) = ((cell % 16) as f64 * 2.0, (cell / 16) as f64 * 2.0);
            Aabb {
                min: vec3(x, 0.0, z),
                max: vec3(x + 1.0, 1.0, z + 1.0),
            }
        })
        .collect();
    let mut tree = Octree::build(&boxes, 4);
    let order = tree.renumber(boxes.len());
    let mut sorted = order.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, (0..256).collect::<Vec<u32>>(), "a permutation");
    // each run of four consecutive new numbers is one leaf of four neighbours: within a
    // 4 × 4 patch of the grid (a cell of the octree), where the scene's order put them far
    // apart
    for run in order.chunks(4) {
        let at = |k: u32| {
            let c = (k as usize * 37) % 256;
            (c % 16, c / 16)
        };
        let (x0, z0) = at(run[0]);
        for &k in run {
            let (x, z) = at(k);
            assert!(x / 4 == x0 / 4 && z / 4 == z0 / 4, "{run:?}");
        }
    }
    assert_eq!(
        tree.renumber(boxes.len()),
        (0..256).collect::<Vec<u32>>(),
        "already in leaf order"
    );
}
