//! Scaling scenes: N random spheres over a plane, for measuring how each [`super::Accel`]
//! grows with the number of objects.
//!
//! The spheres fill the square [−10, 10]² above the floor, their centres at heights between
//! r and 2.5. Their radius shrinks as N grows, r = √(120/(πN)), so that the spheres cover
//! about the same share of the picture at every N (N·πr² = 120 on a 400-unit floor): the
//! images look alike and the work per pixel stays comparable, and only the number of objects
//! changes. One sphere in ten is a mirror, so the scene has every kind of ray. The positions
//! come from a seeded generator (SplitMix64): the same N and seed give the same scene.

use std::fmt::Write;

/// SplitMix64: a tiny seeded generator of well-mixed 64-bit numbers.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator started from `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64-bit number.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }
}

/// The radius of each of N spheres: r = √(120/(πN)).
#[must_use]
pub fn radius(n: usize) -> f64 {
    (120.0 / (std::f64::consts::PI * n.max(1) as f64)).sqrt()
}

/// The scene file (TOML) of `n` random spheres over a plane, drawn from `seed`, at
/// `width` × `height` pixels.
#[must_use]
pub fn scene_toml(n: usize, seed: u64, width: u32, height: u32) -> String {
    let mut s = String::with_capacity(200 + n * 110);
    let r = radius(n);
    let _ = write!(
        s,
        "# {n} random spheres over a plane (seed {seed}), written by `scatter`.\n\
         [camera]\neye = [0.0, 9.0, 17.0]\nlook_at = [0.0, 0.0, 0.0]\nup = [0.0, 1.0, 0.0]\nfov = 50.0\nnear = 1.0\n\n\
         [image]\nwidth = {width}\nheight = {height}\nbackground = [0.1, 0.12, 0.2]\n\n\
         [render]\nmax_depth = 3\n\n\
         [ambient]\nintensity = [1.0, 1.0, 1.0]\n\n\
         [[lights]]\nposition = [-8.0, 14.0, 10.0]\nintensity = [0.8, 0.78, 0.7]\n\n\
         [materials.floor]\nambient = 0.1\ndiffuse = 0.6\nspecular = 0.0\nshininess = 1\n\n\
         [materials.matte]\nambient = [0.08, 0.06, 0.04]\ndiffuse = [0.6, 0.45, 0.3]\nspecular = 0.2\nshininess = 30\n\n\
         [materials.mirror]\nambient = 0.02\ndiffuse = 0.1\nspecular = 0.4\nshininess = 80\nreflection = 0.6\n\n\
         [[objects]]\nplane = {{ point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }}\nmaterial = \"floor\"\n"
    );
    let mut rng = SplitMix64::new(seed);
    for i in 0..n {
        let x = rng.range(-10.0, 10.0);
        let z = rng.range(-10.0, 10.0);
        let y = rng.range(r, r.max(2.5));
        let material = if i % 10 == 0 { "mirror" } else { "matte" };
        let _ = write!(
            s,
            "\n[[objects]]\nsphere = {{ center = [{x:.6}, {y:.6}, {z:.6}], radius = {r:.6} }}\nmaterial = \"{material}\"\n"
        );
    }
    s
}
