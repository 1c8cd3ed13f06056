//! Scaling scenes: N random spheres over a plane, for measuring how each [`crate::accel::Accel`]
//! grows with the number of objects. Two layouts:
//!
//! - [`Layout::Field`] (the default): spheres of radius 0.35 at a constant density, one per
//!   4 square units, over a square of side 2√N centred under the camera, centres at heights
//!   between r and r + 1.5. The scene grows as N does, at the same density everywhere. The
//!   camera looks over the field to its horizon, so the picture itself fills with spheres as
//!   N grows; seen from above a small patch (the scaling benchmark's `--eye 0,6,4`), the
//!   picture stays alike and only the structure's own growth with N is left.
//! - [`Layout::Fog`]: spheres crowded into the fixed square [−10, 10]², their radius shrinking
//!   as r = √(120/(πN)) so they cover the same share of the floor at every N. At N = 100 000
//!   they are a fog of specks of radius 0.02 that every ray crosses for units on end: a harder
//!   test, where the number of boxes a ray must open grows with N as well.
//!
//! One sphere in ten is a mirror, so the scene has every kind of ray. The positions come from
//! a seeded generator (SplitMix64): the same N, layout and seed give the same scene.
//! [`scene_pov`] writes the same scene for POV-Ray 3.7, to time the classic renderer on it.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

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

/// How the spheres are spread (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Layout {
    /// Constant size and density over a square of side 2√N.
    #[default]
    Field,
    /// A fixed square; the radius shrinks as 1/√N.
    Fog,
}

impl Layout {
    /// Every layout.
    pub const ALL: [Layout; 2] = [Layout::Field, Layout::Fog];

    /// The layout's name, as `scatter --layout` takes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Layout::Field => "field",
            Layout::Fog => "fog",
        }
    }
}

/// The radius of each of N spheres in the fog layout: r = √(120/(πN)).
#[must_use]
pub fn radius(n: usize) -> f64 {
    (120.0 / (std::f64::consts::PI * n.max(1) as f64)).sqrt()
}

/// The scene file (TOML) of `n` random spheres over a plane in the default layout.
#[must_use]
pub fn scene_toml(n: usize, seed: u64, width: u32, height: u32) -> String {
    scene_toml_with(n, seed, width, height, Layout::Field)
}

/// The spheres of a scene: their common radius, and each centre (x, y, z) with its
/// material, drawn from `seed`.
fn spheres(
    n: usize,
    seed: u64,
    layout: Layout,
) -> (f64, impl Iterator<Item = ([f64; 3], &'static str)>) {
    let (r, half, top) = match layout {
        Layout::Field => (0.35, (n.max(1) as f64).sqrt(), 1.85),
        Layout::Fog => (radius(n), 10.0, radius(n).max(2.5)),
    };
    let mut rng = SplitMix64::new(seed);
    let centres = (0..n).map(move |i| {
        let x = rng.range(-half, half);
        let z = rng.range(-half, half);
        let y = rng.range(r, top);
        let material = if i % 10 == 0 { "mirror" } else { "matte" };
        ([x, y, z], material)
    });
    (r, centres)
}

/// The scene file (TOML) of `n` random spheres over a plane, drawn from `seed`, at
/// `width` × `height` pixels, in `layout`.
#[must_use]
pub fn scene_toml_with(n: usize, seed: u64, width: u32, height: u32, layout: Layout) -> String {
    let mut s = String::with_capacity(200 + n * 110);
    let _ = write!(
        s,
        "# {n} random spheres over a plane ({layout:?} layout, seed {seed}), written by `scatter`.\n\
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
    let (r, centres) = spheres(n, seed, layout);
    for ([x, y, z], material) in centres {
        let _ = write!(
            s,
            "\n[[objects]]\nsphere = {{ center = [{x:.6}, {y:.6}, {z:.6}], radius = {r:.6} }}\nmaterial = \"{material}\"\n"
        );
    }
    s
}

/// The same scene for POV-Ray 3.7 (see `benches/povray/showcase.pov` for how whitted's
/// camera, shading and handedness are carried over): z negated, the vertical field of view
/// turned into POV-Ray's horizontal angle, each material's ambient divided by its diffuse
/// colour (POV-Ray multiplies them), Phong's highlight, and `max_trace_level` = max_depth + 1.
/// For timing the classic renderer on the scaling scenes (`benches/povray/scaling.sh`).
#[must_use]
pub fn scene_pov(n: usize, seed: u64, layout: Layout) -> String {
    let mut s = String::with_capacity(1000 + n * 80);
    let _ = write!(
        s,
        "// {n} random spheres over a plane ({layout:?} layout, seed {seed}), written by `scatter --pov`.\n\
         global_settings {{ assumed_gamma 1.0 max_trace_level 4 adc_bailout 0.001 ambient_light rgb 1 }}\n\
         #declare Aspect = image_width / image_height;\n\
         camera {{ perspective location <0, 9, -17> look_at <0, 0, 0> up y right x * Aspect\n  \
         angle 2 * degrees(atan(tan(radians(50 / 2)) * Aspect)) }}\n\
         background {{ rgb <0.1, 0.12, 0.2> }}\n\
         light_source {{ <-8, 14, -10> color rgb <0.8, 0.78, 0.7> }}\n\
         #declare Floor = texture {{ pigment {{ rgb 0.6 }} finish {{ ambient 0.1 / 0.6 diffuse 1 }} }}\n\
         #declare Matte = texture {{ pigment {{ rgb <0.6, 0.45, 0.3> }} finish {{ ambient rgb <0.08 / 0.6, 0.06 / 0.45, 0.04 / 0.3> diffuse 1 phong 0.2 phong_size 30 }} }}\n\
         #declare Mirror = texture {{ pigment {{ rgb 0.1 }} finish {{ ambient 0.02 / 0.1 diffuse 1 phong 0.4 phong_size 80 reflection 0.6 }} }}\n\
         plane {{ y, 0 texture {{ Floor }} }}\n"
    );
    let (r, centres) = spheres(n, seed, layout);
    for ([x, y, z], material) in centres {
        let texture = if material == "mirror" {
            "Mirror"
        } else {
            "Matte"
        };
        let z = -z;
        let _ = writeln!(
            s,
            "sphere {{ <{x:.6}, {y:.6}, {z:.6}>, {r:.6} texture {{ {texture} }} }}"
        );
    }
    s
}
