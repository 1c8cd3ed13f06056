//! Speed without changing a pixel (notes: "Computational Aspects"): every acceleration
//! technique gives exactly the brute-force image, whatever the number of threads.

// the helpers of the student's tests, shared
#[path = "../../crates/whitted/tests/common/mod.rs"]
mod common;

mod boxes;
mod bvh;
// every test there needs the `counters` feature (CI runs `--features counters --test accel`)
#[cfg(feature = "counters")]
mod counters;
mod extents;
mod images;
mod none;
mod octree;
mod packets;
mod scatter;

use whitted::accel::Accel;
use whitted::render::{self, Chapter, Framebuffer, Options, Stats};
use whitted::scene::Scene;

fn showcase() -> Scene {
    whitted::scene::showcase().expect("the showcase parses")
}

fn render_with(
    scene: &Scene,
    chapter: Chapter,
    w: u32,
    h: u32,
    f: impl Fn(&mut Options),
) -> Vec<(Accel, Framebuffer, Stats)> {
    Accel::ALL
        .iter()
        .map(|&accel| {
            let mut o = Options::for_scene(scene, chapter);
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
