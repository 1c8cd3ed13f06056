//! Shared test helpers: tolerances per precision and small builders.
#![allow(dead_code)]

use std::fmt::Display;

use whitted::real::{Real, Vec3};

/// Absolute tolerance for values of order 1 computed in a handful of operations.
#[cfg(not(feature = "f32"))]
pub const TOL: Real = 1e-12;
/// Absolute tolerance for values of order 1 computed in a handful of operations.
#[cfg(feature = "f32")]
pub const TOL: Real = 1e-5;

/// What a failure message says of a quantity: `what` names it in the notes' symbols, with
/// what it was computed from ("H for N = 1, θ = 60°"); an optional tail after `"; expected "`
/// says where the expected value comes from ("r·v for …; expected cos 45°"). The message reads
/// "WHAT: computed A, expected B (WHERE FROM)": never "WHAT = A", which would read as an
/// equation that the failure disproves.
fn computed_expected(what: &str, actual: impl Display, expected: impl Display) -> String {
    match what.split_once("; expected ") {
        Some((quantity, from)) => {
            format!("{quantity}: computed {actual}, expected {expected} ({from})")
        }
        None => format!("{what}: computed {actual}, expected {expected}"),
    }
}

/// Asserts that the real `actual` lies within `tol` of `expected`; `what` names it in the notes'
/// symbols, with what it was computed from ("H for N = 1, θ = 60°"), and may say where the
/// expected value comes from after `"; expected "` ("…; expected tan 30°"). The message gives
/// the quantity, the value computed, the value expected, the tolerance and the difference:
/// "H for N = 1, θ = 60°: computed 0.5, expected 0.5773502691896257 (tan 30°) (tolerance 1e-12,
/// off by 7.7e-2)". A NaN never passes.
#[track_caller]
pub fn assert_near(what: &str, actual: Real, expected: Real, tol: Real) {
    let off = (actual - expected).abs();
    assert!(
        off <= tol,
        "{} (tolerance {tol:e}, off by {off:e})",
        computed_expected(what, actual, expected)
    );
}

/// Asserts that the real `actual` is exactly `expected` (a constant, or a value a clamp or a
/// shortcut must give bit for bit); `what` as for [`assert_near`]. A NaN never passes.
#[track_caller]
pub fn assert_exact(what: &str, actual: Real, expected: Real) {
    assert!(
        actual == expected,
        "{} (exactly)",
        computed_expected(what, actual, expected)
    );
}

/// Asserts two vectors agree component by component within `tol`; `what` names the vector in
/// the notes' symbols ("u", "d for (c, r) = (0, 0)"), as for [`assert_near`]. The message gives
/// the vector computed, the one expected, the tolerance and each component's difference. A NaN
/// never passes.
#[track_caller]
pub fn assert_vec_eq(what: &str, actual: Vec3, expected: Vec3, tol: Real) {
    let off = (actual - expected).abs();
    assert!(
        off.cmple(Vec3::splat(tol)).all(),
        "{} (tolerance {tol:e} per component, off by {off})",
        computed_expected(what, actual, expected)
    );
}

use whitted::render::{Chapter, Framebuffer, Options, Stats, render};
use whitted::scene::{Scene, parse};

/// Loads a scene from TOML text (panics on an error: test scenes are valid).
pub fn scene(text: &str) -> Scene {
    parse(text, "test.toml").unwrap_or_else(|e| panic!("{e}"))
}

/// Loads the parts of a scene that the chapter `chapter` reads, as its binary does (chapter 1:
/// the camera and the image, no object placed).
pub fn chapter_scene(text: &str, chapter: Chapter) -> Scene {
    whitted::scene::parse_parts(text, "test.toml", chapter.reads())
        .unwrap_or_else(|e| panic!("{e}"))
}

/// Renders `scene` at chapter `chapter` and the given size by the plain road of one pixel, and
/// checks that packets (on by default) give the same image bit for bit and the same rays.
pub fn render_at(scene: &Scene, chapter: Chapter, width: u32, height: u32) -> (Framebuffer, Stats) {
    let mut o = Options::for_scene(scene, chapter);
    o.width = width;
    o.height = height;
    render_both_ways(scene, &o)
}

/// Renders with `options` by the plain road (packets off) and with packets, asserts the two
/// agree bit for bit, and returns the road's image and rays.
pub fn render_both_ways(scene: &Scene, options: &Options) -> (Framebuffer, Stats) {
    let mut road = options.clone();
    road.packets = false;
    let mut packets = options.clone();
    packets.packets = true;
    let (fb, stats) = render_here(scene, &road);
    let (fb2, stats2) = render_here(scene, &packets);
    if let Some((x, y, road, packed)) = first_difference(&fb, &fb2) {
        panic!(
            "packets changed the image: pixel ({x}, {y}) is {road} by the road, {packed} with packets"
        );
    }
    assert_eq!(
        (
            stats.primary,
            stats.shadow,
            stats.reflected,
            stats.refracted
        ),
        (
            stats2.primary,
            stats2.shadow,
            stats2.reflected,
            stats2.refracted
        ),
        "packets changed the rays cast"
    );
    (fb, stats)
}

/// The first pixel, in row order, where two images of the same size differ bit for bit: its
/// (x, y) and its colour in each.
pub fn first_difference(a: &Framebuffer, b: &Framebuffer) -> Option<(u32, u32, Vec3, Vec3)> {
    let bits = |p: &Vec3| p.to_array().map(|x| x.to_bits());
    let i = (0..a.pixels.len().max(b.pixels.len()))
        .find(|&i| a.pixels.get(i).map(bits) != b.pixels.get(i).map(bits))?;
    let at = |fb: &Framebuffer| fb.pixels.get(i).copied().unwrap_or(Vec3::NAN);
    Some((i as u32 % a.width, i as u32 / a.width, at(a), at(b)))
}

/// Renders as [`render`] does, on threads of this test's own. A panic on one of them (an
/// exercise's `todo!()` met while rendering, a student's failing `expect`) prints its message
/// into this test's captured output, where `cargo learn` reads which exercise stopped it. On
/// rayon's global pool the message would go to the output of whichever test first started the
/// pool (a thread prints where the thread that spawned it printed), and this test would fail
/// without a word.
pub fn render_here(scene: &Scene, options: &Options) -> (Framebuffer, Stats) {
    rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap_or_else(|e| panic!("cannot start the test's render threads: {e}"))
        .install(|| render(scene, options))
}

/// The colour seen along the camera's axis: a 1 × 1 render, whose only ray is d = −N·n.
pub fn centre(scene: &Scene, chapter: Chapter) -> (Vec3, Stats) {
    let (fb, stats) = render_at(scene, chapter, 1, 1);
    (fb.pixels[0], stats)
}

use whitted::material::Material;
use whitted::ray::Ray;
use whitted::shapes::{Numerics, Object};

/// The share of a light that the feeler lets through, from first principles: every object in
/// scene order, [`whitted::shadow::blocks`] on its hits, [`whitted::shadow::transmittance`] of
/// the transmissions of those that block. The oracle the accelerated answers must match.
pub fn brute_share(
    objects: &[Object],
    materials: &[Material],
    feeler: &Ray,
    u_min: Real,
    numerics: Numerics,
) -> Real {
    let crossed = objects
        .iter()
        .filter(|o| whitted::shadow::blocks(&o.intersect(feeler, numerics), u_min))
        .map(|o| materials[o.material].transmission);
    whitted::shadow::transmittance(crossed)
}
