//! Whole images: every `--accel` renders exactly the brute-force image (colour, normals,
//! depth, a demanding scene, many spheres), on one thread or four; and the framebuffer limit.

use super::{STRAIN, assert_all_equal, render_with, showcase};
use whitted::render::{self, Chapter, Options, View};
use whitted::scene::parse;
use whitted::scene::scatter;

/// Notes, "Computational Aspects": bounding boxes and extents only skip work. The showcase
/// renders identically with every `--accel`.
#[test]
fn every_accel_renders_the_showcase_exactly_as_brute_force() {
    let scene = showcase();
    assert_all_equal(&render_with(
        &scene,
        Chapter::ReflectionRefraction,
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
        assert_all_equal(&render_with(&scene, Chapter::GenericObjects, 80, 60, |o| {
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
        Chapter::ReflectionRefraction,
        96,
        72,
        |_| {},
    ));
    assert_all_equal(&render_with(&scene, Chapter::Shadows, 48, 36, |o| {
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
            Chapter::ReflectionRefraction,
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
    let mut o = Options::for_scene(&scene, Chapter::ReflectionRefraction);
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
    let srgb = whitted::output::Encoding::Srgb;
    assert_eq!(
        whitted::output::to_rgb8(&one, srgb),
        whitted::output::to_rgb8(&four, srgb)
    );
    assert_eq!(one, four);
    assert_eq!(s1, s4);
}

/// The framebuffer limit: 8192 × 8192 is allowed, 65535 × 65535 is refused with one line.
#[test]
fn framebuffer_limit_allows_8192_squared_and_refuses_65535_squared() {
    assert!(render::check_size(8192, 8192).is_ok());
    let e = render::check_size(65_535, 65_535).unwrap_err().to_string();
    assert!(e.contains("too large") && !e.contains('\n'), "{e}");
}
