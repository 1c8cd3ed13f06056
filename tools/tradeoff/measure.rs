//! Measuring one build: renders timed by their median, the hit masks, the references and the
//! machine's load.

use std::fs;
use std::time::Instant;

use whitted::real::Real;
use whitted::render::{self, Options, Tracer};
use whitted::scene::Scene;

use crate::settings::{self, SCENES, Setting};

/// A rendered setting: linear RGB (as f64) and the hit mask.
pub struct Image {
    pub pixels: Vec<[f64; 3]>,
    pub mask: Vec<u8>,
}

/// A [`Real`] as f64 (a no-op in the default precision, hence the allowed cast).
#[allow(clippy::unnecessary_cast)]
pub fn wide(x: Real) -> f64 {
    x as f64
}

/// The median (the mean of the middle two for an even count).
pub fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        (xs[n / 2 - 1] + xs[n / 2]) / 2.0
    }
}

/// What each pixel's centre ray hits: 0 for nothing, else 1 + the object's index (saturated).
fn hit_mask(scene: &Scene, options: &Options) -> Vec<u8> {
    let tracer = Tracer::new(scene, options);
    let mut mask = Vec::with_capacity((options.width * options.height) as usize);
    for y in 0..options.height {
        for x in 0..options.width {
            let ray = tracer.camera().pixel_ray(x, y, 0.5, 0.5);
            let hit = tracer.nearest(&ray, 0.0);
            mask.push(hit.map_or(0, |n| (n.object + 1).min(255) as u8));
        }
    }
    mask
}

/// Renders a setting `runs` times: the median time in seconds and the image.
pub fn measure(s: &Setting, width: u32, height: u32, runs: usize) -> (f64, Image) {
    let scene = settings::load(s.scene);
    let o = settings::options(&scene, s, width, height);
    let mut times = Vec::with_capacity(runs);
    let mut fb = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let (image, _) = render::render(&scene, &o);
        times.push(start.elapsed().as_secs_f64());
        fb = Some(image);
    }
    let fb = fb.expect("at least one run");
    let pixels = fb
        .pixels
        .iter()
        .map(|p| [wide(p.x), wide(p.y), wide(p.z)])
        .collect();
    (
        median(times),
        Image {
            pixels,
            mask: hit_mask(&scene, &o),
        },
    )
}

/// The reference image of every scene (rendered once, untimed, by this build).
pub fn references(width: u32, height: u32, samples: u32) -> Vec<Image> {
    (0..SCENES.len())
        .map(|scene| measure(&Setting::reference(scene, samples), width, height, 1).1)
        .collect()
}

/// The machine's 1-minute load average (Linux), to judge how far the timings can be trusted.
pub fn load_average() -> Option<f64> {
    fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}
