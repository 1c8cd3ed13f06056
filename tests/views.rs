//! The views that need a scale or a palette (`--view depth|shadows|rays`): their scales are
//! fixed before the first pixel, and their colours say what they claim to.

// the helpers of the student's tests, shared
#[path = "../crates/whitted/tests/common/mod.rs"]
mod common;

use common::scene;
use whitted::real::{Real, Vec3, vec3};
use whitted::render::views::{heat, light_colour, shadow_mask};
use whitted::render::{Chapter, Options, Stats, Tracer, View, render};
use whitted::shadow;

/// An opaque ball above a floor, lit by three lights: light 0 straight above the ball, light 1
/// far to the right, light 2 behind the floor (below it: it reaches nothing on the top side).
const BALL: &str = r#"
[camera]
eye = [0.0, 6.0, 6.0]
look_at = [0.0, 0.0, 0.0]
[image]
width = 40
height = 30
[[lights]]
position = [0.0, 6.0, 0.0]
[[lights]]
position = [30.0, 1.0, 0.0]
[[lights]]
position = [0.0, -5.0, 0.0]
[[objects]]
name = "floor"
plane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }
[[objects]]
name = "ball"
sphere = { center = [0.0, 1.0, 0.0], radius = 0.5 }
"#;

/// The shadow-mask view: each light in its colour where it reaches the point (in front of the
/// surface, and from chapter 4 with no opaque object between), the dim grey 0.12 where none
/// does, black for a miss. Checked against feelers traced here by testing every object.
#[test]
fn the_shadow_mask_shows_which_lights_reach_each_point() {
    let s = scene(BALL);
    for chapter in [Chapter::Shading, Chapter::Shadows] {
        let mut o = Options::for_scene(&s, chapter);
        o.view = View::Shadows;
        let (fb, _) = render(&s, &o);
        let tracer = Tracer::new(&s, &o);
        let (mut shadowed, mut lit) = (0, 0);
        for y in 0..o.height {
            for x in 0..o.width {
                let ray = tracer.camera().pixel_ray(x, y, 0.5, 0.5);
                let expected = match tracer.nearest(&ray, 0.0) {
                    None => Vec3::ZERO,
                    Some(hit) => {
                        let p = ray.at(hit.hit.t);
                        let n = hit.hit.normal; // both objects are seen from outside
                        let mut reached = Vec3::ZERO;
                        for (l, light) in s.lights.iter().enumerate() {
                            let towards = light.position - p;
                            if n.dot(towards) <= 0.0 {
                                continue;
                            }
                            // a feeler from just off the surface
                            let feeler = shadow::feeler(p + n * 1e-6, light.position);
                            let blocked = chapter == Chapter::Shadows
                                && s.objects.iter().any(|obj| {
                                    shadow::blocks(&obj.intersect(&feeler, o.numerics), 0.0)
                                });
                            if !blocked {
                                reached += light_colour(l);
                            }
                        }
                        shadow_mask(reached)
                    }
                };
                let got = fb.get(x, y);
                assert_eq!(got, expected, "pixel ({x}, {y}) at {chapter:?}");
                if got == vec3(0.12, 0.12 + 0.88, 0.12) {
                    shadowed += 1; // light 1 (green) only: in the ball's shadow of light 0
                }
                if got == vec3(1.0, 1.0, 0.12) {
                    lit += 1; // lights 0 and 1
                }
            }
        }
        assert!(lit > 100, "{chapter:?}: {lit} pixels lit by lights 0 and 1");
        match chapter {
            Chapter::Shadows => assert!(shadowed > 5, "{shadowed} pixels in the ball's shadow"),
            _ => assert_eq!(shadowed, 0, "no shadows before chapter 4"),
        }
    }
}

/// The rays-per-pixel view: each pixel's colour is the heat of the rays that pixel casts (the
/// count a plain render makes of it alone), on a scale whose top, samples × (1 + feelers a
/// hit) × (2^(depth + 1) − 1), is known before the first pixel.
#[test]
fn the_rays_view_shows_the_rays_each_pixel_casts() {
    let s = scene(include_str!("../scenes/ch05_reflection_refraction.toml"));
    let mut o = Options::for_scene(&s, Chapter::ReflectionRefraction);
    (o.width, o.height) = (48, 32);
    o.view = View::Rays;
    let tracer = Tracer::new(&s, &o);
    // 1 sample, 2 lights with feelers, depth 6
    assert_eq!(tracer.scales().rays_max, (1 + 2) * ((1 << 7) - 1));
    let (fb, total) = render(&s, &o);
    let mut color = o.clone();
    color.view = View::Color;
    let colour_tracer = Tracer::new(&s, &color);
    let mut counts = Vec::new();
    for y in 0..o.height {
        for x in 0..o.width {
            let mut stats = Stats::default();
            let _ = colour_tracer.pixel(x, y, &mut stats);
            assert_eq!(
                fb.get(x, y),
                tracer.scales().heat(stats.total()),
                "({x}, {y})"
            );
            counts.push(stats.total());
        }
    }
    assert_eq!(counts.iter().sum::<u64>(), total.total());
    let (lo, hi) = (counts.iter().min().unwrap(), counts.iter().max().unwrap());
    assert!(
        lo < hi,
        "the glass scene's pixels cast from {lo} to {hi} rays"
    );
    assert_eq!(tracer.scales().heat(1), Vec3::ZERO, "one ray is black");
    assert_eq!(tracer.scales().heat(381), Vec3::ONE, "the most is white");
}

/// The heat scale runs from black to white and grows brighter all the way.
#[test]
fn the_heat_scale_brightens_from_black_to_white() {
    assert_eq!(heat(0.0), Vec3::ZERO);
    assert_eq!(heat(1.0), Vec3::ONE);
    let mut last = -1.0;
    for i in 0..=100 {
        let c = heat(i as Real / 100.0);
        let brightness = c.x + c.y + c.z;
        assert!(brightness > last, "step {i}: {c:?}");
        last = brightness;
    }
}

/// The depth view: grey 0.15 + 0.85·(1/d − 1/far)/(1/near − 1/far) with near and far measured
/// by a probe before the first pixel, clamped, black for a miss. For a floor seen from above, the nearest
/// pixel is white, the farthest grey 0.15, and grey falls with distance.
#[test]
fn the_depth_view_scale_is_known_before_the_first_pixel() {
    let s = scene(BALL);
    let mut o = Options::for_scene(&s, Chapter::GenericObjects);
    o.view = View::Depth;
    let tracer = Tracer::new(&s, &o);
    let (near, far) = tracer.scales().depth.expect("the depth view has a scale");
    assert!(near > 0.0 && near < far, "{near} {far}");
    let (fb, _) = render(&s, &o);
    let mut pixels = Vec::new();
    for y in 0..o.height {
        for x in 0..o.width {
            let ray = tracer.camera().pixel_ray(x, y, 0.5, 0.5);
            let d = tracer
                .nearest(&ray, 0.0)
                .map(|n| n.hit.t * ray.dir.length());
            let expected = match d {
                None => Vec3::ZERO,
                Some(d) => {
                    let x = (1.0 / d - 1.0 / far) / (1.0 / near - 1.0 / far);
                    Vec3::splat(0.15 + 0.85 * x.clamp(0.0, 1.0))
                }
            };
            assert_eq!(fb.get(x, y), expected, "({x}, {y})");
            pixels.push(fb.get(x, y).x);
        }
    }
    let max = pixels.iter().copied().fold(0.0, Real::max);
    let min = pixels
        .iter()
        .copied()
        .filter(|&g| g > 0.0)
        .fold(1.0, Real::min);
    assert_eq!(max, 1.0, "the nearest pixel is white");
    assert!(
        (min - 0.15).abs() < 1e-6,
        "the farthest is grey 0.15: {min}"
    );
    // no view but depth pays for the probe
    o.view = View::Color;
    assert_eq!(Tracer::new(&s, &o).scales().depth, None);
}
