//! The scales and palettes of the views of chapters 2–5 that need one: depth, shadow mask,
//! rays per pixel. What each view shows of a hit is drawn beside the road
//! ([`super::views`]); these only turn numbers into colours.
//!
//! A tile rendered alone (the live window draws the image tile by tile, and redraws a part
//! of it) must come out as it does in the whole image, so every scale is fixed before the
//! first pixel is traced ([`Scales::measure`], called when the tracer is made):
//!
//! - **depth**: the distance |t·d| to the nearest hit on an inverse scale, white at the nearest
//!   distance a probe of [`DEPTH_PROBES`]² camera rays spread over the image finds, grey 0.15 at
//!   its farthest (nearer or farther pixels are clamped), black for a miss. Grey falls with 1/d,
//!   not d: a floor running to the horizon would otherwise squeeze every object into white;
//!   with 1/d an object twice as far is about half as bright;
//! - **rays per pixel**: the rays a pixel casts (camera, feelers, mirror, transmitted, over
//!   all its samples) on a logarithmic heat scale, black for one ray to white for the most
//!   the scene and options allow ([`Scales::rays_max`]);
//! - **shadow mask**: which lights reach each point, light i painted in [`light_colour`]`(i)`
//!   (red, green, blue for the first three: white where all three arrive) times the share
//!   its feeler lets through.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::options::{Chapter, Options, View};
use super::query::Query;
use crate::camera::Camera;
use crate::real::{Real, Vec3};
use crate::scene::Scene;

/// The probe of the depth view traces at most this many camera rays across and down.
pub const DEPTH_PROBES: u32 = 64;

/// The scales of the depth and rays-per-pixel views, fixed before the first tile.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Scales {
    /// The nearest and farthest distance the depth probe found (the depth view only).
    pub depth: Option<(Real, Real)>,
    /// The most rays one pixel can cast with these options: samples × (1 + feelers a hit) ×
    /// the rays of a full binary tree of the maximum depth.
    pub rays_max: u64,
}

impl Default for Scales {
    fn default() -> Self {
        Self {
            depth: None,
            rays_max: 1,
        }
    }
}

impl Scales {
    /// The scales for rendering `scene` with `options` through `camera`, before the first
    /// tile: the depth probe asks `query` for the nearest hits of its camera rays, and runs
    /// only for the depth view.
    #[must_use]
    pub fn measure(options: &Options, scene: &Scene, camera: &Camera, query: &impl Query) -> Self {
        let o = options;
        let depth = (o.view == View::Depth && o.chapter >= Chapter::GenericObjects)
            .then(|| probe_depth(o, camera, query));
        Self {
            depth,
            rays_max: rays_max(o, scene),
        }
    }

    /// The depth view's grey for a camera ray whose nearest hit is at distance `distance`
    /// (`None` for a miss, black): 0.15 + 0.85·(1/d − 1/far)/(1/near − 1/far), clamped to
    /// [0.15, 1].
    #[must_use]
    // Not inlined: inlined into the road, its divisions by 1/near and 1/far were hoisted out
    // of the view's `match` and ran for every pixel of every view, on the unset scale of the
    // colour view too (measured: a quarter of the field's render time).
    #[inline(never)]
    pub fn depth(&self, distance: Option<Real>) -> Vec3 {
        let Some(d) = distance else {
            return Vec3::ZERO;
        };
        match self.depth {
            Some((near, far)) if far > near => {
                let x = ((1.0 / d - 1.0 / far) / (1.0 / near - 1.0 / far)).clamp(0.0, 1.0);
                Vec3::splat(0.15 + 0.85 * x)
            }
            _ => Vec3::ONE,
        }
    }

    /// The rays-per-pixel view's colour for a pixel that cast `rays` rays: ln(rays) /
    /// ln(rays_max) on [`heat`].
    #[must_use]
    pub fn heat(&self, rays: u64) -> Vec3 {
        let x = if self.rays_max <= 1 {
            1.0
        } else {
            ((rays.max(1) as Real).ln() / (self.rays_max as Real).ln()).min(1.0)
        };
        heat(x)
    }
}

/// The nearest and farthest hit distance over a grid of camera rays through pixel centres.
fn probe_depth(o: &Options, camera: &Camera, query: &impl Query) -> (Real, Real) {
    let (nx, ny) = (o.width.min(DEPTH_PROBES), o.height.min(DEPTH_PROBES));
    let (mut lo, mut hi) = (Real::INFINITY, Real::NEG_INFINITY);
    for j in 0..ny {
        for i in 0..nx {
            // the centre pixel of cell (i, j) of an nx × ny grid over the image
            let x = ((2 * i + 1) as u64 * u64::from(o.width) / (2 * u64::from(nx))) as u32;
            let y = ((2 * j + 1) as u64 * u64::from(o.height) / (2 * u64::from(ny))) as u32;
            let ray = camera.pixel_ray(x, y, 0.5, 0.5);
            if let Some(n) = query.nearest(&ray, 0.0) {
                let d = n.hit.t * ray.dir.length();
                lo = lo.min(d);
                hi = hi.max(d);
            }
        }
    }
    (lo, hi)
}

/// samples × (1 + feelers a hit can send) × (2^(depth + 1) − 1).
fn rays_max(o: &Options, scene: &Scene) -> u64 {
    let feelers = if o.chapter >= Chapter::Shadows {
        scene.lights.iter().filter(|l| l.shadows).count() as u64
    } else {
        0
    };
    let depth = if o.chapter == Chapter::ReflectionRefraction {
        o.max_depth.min(62)
    } else {
        0
    };
    let tree = (1u64 << (depth + 1)) - 1;
    u64::from(o.samples_per_pixel())
        .saturating_mul(1 + feelers)
        .saturating_mul(tree)
}

/// A heat colour for x ∈ [0, 1]: black, deep red, orange, yellow, white.
#[must_use]
pub fn heat(x: Real) -> Vec3 {
    const STOPS: [[Real; 3]; 5] = [
        [0.0, 0.0, 0.0],
        [0.5, 0.0, 0.1],
        [0.9, 0.3, 0.0],
        [1.0, 0.85, 0.1],
        [1.0, 1.0, 1.0],
    ];
    let x = x.clamp(0.0, 1.0) * (STOPS.len() - 1) as Real;
    let i = (x as usize).min(STOPS.len() - 2);
    let f = x - i as Real;
    let (a, b) = (Vec3::from(STOPS[i]), Vec3::from(STOPS[i + 1]));
    a + (b - a) * f
}

/// The shadow-mask colour of a hit whose lights add up to `reached` (Σ light_colour(i) ×
/// share_i): a dim grey 0.12 where no light arrives, so that objects stand out from the black
/// of a miss, plus 0.88 × `reached`, clamped at white.
#[must_use]
pub fn shadow_mask(reached: Vec3) -> Vec3 {
    (Vec3::splat(0.12) + 0.88 * reached).min(Vec3::ONE)
}

/// The colour of light number `i` in the shadow-mask view: red, green, blue, then yellow,
/// cyan, magenta, then the same six again.
#[must_use]
pub fn light_colour(i: usize) -> Vec3 {
    const PALETTE: [[Real; 3]; 6] = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 1.0],
        [1.0, 0.0, 1.0],
    ];
    Vec3::from(PALETTE[i % PALETTE.len()])
}
