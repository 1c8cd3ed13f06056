//! The bytes of the PNG: the framebuffer's linear intensities (the notes' I), sRGB-encoded
//! by default (IEC 61966-2-1) and written as they are with `--encoding linear`.
//!
//! ```text
//! V = 12.92·I                      for I ≤ 0.0031308
//! V = 1.055·I^(1/2.4) − 0.055      otherwise            byte = round(255·V), I clamped to [0, 1]
//! ```
//!
//! `Encoding::Srgb.byte` finds the byte without a power, in a table of the 255 intensities
//! where the byte steps up; these tests check it against the formula at every step, on both
//! sides, and over dense sweeps. Run in each precision (`--features f32`), they check that
//! precision's table against that precision's formula.

mod common;

use std::path::Path;
use std::process::Output;

use whitted::output::{Encoding, to_byte, to_rgb8};
use whitted::real::Real;
use whitted::render::{Chapter, Framebuffer, Options, render};

/// The sRGB byte by the formula, written out here as the module docs write it (the same
/// operations in the same order as the library's definition).
fn by_formula(x: Real) -> u8 {
    if x.is_nan() {
        return 0;
    }
    let x = x.clamp(0.0, 1.0);
    let v = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    (v * 255.0).round() as u8
}

/// The next float up and down (x finite and positive).
fn next_up(x: Real) -> Real {
    Real::from_bits(x.to_bits() + 1)
}
fn next_down(x: Real) -> Real {
    Real::from_bits(x.to_bits() - 1)
}

/// The 255 intensities where the formula's byte steps from k to k + 1 (k = 0 … 254): the
/// smallest float in ]0, 1] whose byte exceeds k, found by bisection on the bits, here in the
/// test, independently of the library's table.
fn steps() -> Vec<Real> {
    (0..255u8)
        .map(|k| {
            let (mut lo, mut hi) = (Real::to_bits(0.0), Real::to_bits(1.0));
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if by_formula(Real::from_bits(mid)) > k {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            Real::from_bits(hi)
        })
        .collect()
}

/// Bytes worked out by hand (with a calculator, in f64):
///
/// - 0 → V = 0 → 0; 1 → V = 1.055 − 0.055 = 1 → 255.
/// - 0.5: 0.5^(1/2.4) = e^(ln 0.5 / 2.4) = e^(−0.288811) = 0.749154; V = 1.055·0.749154 − 0.055
///   = 0.735357; 255·V = 187.516 → 188 (linear: 127.5 → 128).
/// - 0.18 (the photographers' mid grey): 0.18^(1/2.4) = e^(−0.714499) = 0.489437;
///   V = 0.516356 − 0.055 = 0.461356; 255·V = 117.646 → 118 (linear: 45.9 → 46).
/// - 0.214: 0.214^(1/2.4) = e^(−0.642408) = 0.526024; V = 0.499956; 255·V = 127.489 → 127,
///   just short of the byte 128: a viewer's half-way grey is about a fifth of the light.
/// - 0.05: 0.05^(1/2.4) = e^(−1.248222) = 0.287015; V = 0.247801; 255·V = 63.189 → 63.
/// - 0.8: 0.8^(1/2.4) = e^(−0.092976) = 0.911215; V = 0.906332; 255·V = 231.115 → 231.
/// - Near the knee, on the straight part: 0.001 → V = 12.92·0.001 = 0.01292, 255·V = 3.295
///   → 3; 0.002 → 0.02584, 6.589 → 7; the knee itself, 0.0031308 → 0.040450, 10.315 → 10.
/// - Just past the knee, on the curve: 0.0035^(1/2.4) = e^(−2.356247) = 0.094775;
///   V = 0.099988 − 0.055 = 0.044988; 255·V = 11.472 → 11 (the straight line would give
///   12.92·0.0035·255 = 11.531 → 12: the two parts meet at the knee, not beyond it).
#[test]
fn srgb_bytes_match_the_ones_worked_out_by_hand() {
    let cases: [(f64, u8, u8); 10] = [
        // (linear intensity, sRGB byte, linear byte)
        (0.0, 0, 0),
        (1.0, 255, 255),
        (0.5, 188, 128),
        (0.18, 118, 46),
        (0.214, 127, 55),
        (0.05, 63, 13),
        (0.8, 231, 204),
        (0.001, 3, 0),
        (0.002, 7, 1),
        (0.003_130_8, 10, 1),
    ];
    for (x, srgb, linear) in cases {
        let x = x as Real;
        assert_eq!(Encoding::Srgb.byte(x), srgb, "sRGB byte of {x}");
        assert_eq!(Encoding::Linear.byte(x), linear, "linear byte of {x}");
    }
    assert_eq!(Encoding::Srgb.byte(0.0035), 11);
    // outside [0, 1] the intensity is clamped; NaN is black
    for (x, byte) in [
        (-0.5, 0),
        (-0.0, 0),
        (1.5, 255),
        (Real::INFINITY, 255),
        (Real::NEG_INFINITY, 0),
        (Real::NAN, 0),
    ] {
        assert_eq!(Encoding::Srgb.byte(x), byte, "sRGB byte of {x}");
        assert_eq!(Encoding::Linear.byte(x), byte, "linear byte of {x}");
    }
}

/// The fast sRGB byte is the formula's byte at every step (the step itself and the floats
/// just below and above it), at 0, 1, outside [0, 1], at NaN and the infinities, and on a
/// dense even sweep and a logarithmic sweep down to tiny intensities. The linear byte is
/// [`to_byte`] everywhere.
#[test]
fn the_fast_srgb_byte_is_the_formulas_byte_everywhere() {
    let steps = steps();
    assert!(
        steps.windows(2).all(|w| w[0] < w[1]),
        "steps not increasing"
    );
    let mut values: Vec<Real> = Vec::new();
    for (k, &t) in steps.iter().enumerate() {
        // the formula steps up exactly there
        assert_eq!(usize::from(by_formula(t)), k + 1, "step {k} at {t}");
        assert_eq!(usize::from(by_formula(next_down(t))), k, "step {k} at {t}");
        let mut below = t;
        let mut above = t;
        values.push(t);
        for _ in 0..8 {
            below = next_down(below);
            above = next_up(above);
            values.extend([below, above]);
        }
    }
    let n = 1_000_000;
    values.extend((0..=n).map(|i| (-0.01 + 1.02 * f64::from(i) / f64::from(n)) as Real));
    // intensities from 10⁻³⁰ to 1, 10 000 a decade: the straight part and far below it
    values.extend((0..=300_000).map(|i| 10f64.powf(-30.0 + f64::from(i) / 10_000.0) as Real));
    values.extend([
        0.0,
        -0.0,
        1.0,
        next_down(1.0),
        -1.0,
        -Real::MIN_POSITIVE,
        Real::MIN_POSITIVE,
        Real::from_bits(1), // the smallest subnormal
        0.003_130_8,
        next_up(0.003_130_8),
        next_down(0.003_130_8),
        1.000_001,
        2.0,
        Real::MAX,
        Real::MIN,
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::NAN,
    ]);
    let mut wrong = Vec::new();
    for &x in &values {
        let (fast, slow) = (Encoding::Srgb.byte(x), by_formula(x));
        if fast != slow {
            wrong.push(format!("{x:e} (bits {:x}): {fast} ≠ {slow}", x.to_bits()));
        }
        assert_eq!(Encoding::Linear.byte(x), to_byte(x), "{x:e}");
    }
    assert!(
        wrong.is_empty(),
        "{} of {} values differ: {:?}",
        wrong.len(),
        values.len(),
        &wrong[..wrong.len().min(20)]
    );
}

/// Every sRGB byte is at least the linear byte of the same intensity (the curve lies above
/// the straight line on [0, 1]): the default image is the brighter one.
#[test]
fn the_srgb_byte_is_never_darker_than_the_linear_byte() {
    for i in 0..=100_000 {
        let x = (f64::from(i) / 100_000.0) as Real;
        assert!(Encoding::Srgb.byte(x) >= Encoding::Linear.byte(x), "{x}");
    }
}

// ---- the command line -------------------------------------------------------------------

/// The chapter whose binary these tests run: the first that shades.
const SHADING: Chapter = Chapter::Shading;

fn run(args: &[&str], dir: &Path) -> Output {
    common::run(&common::exe(SHADING), args, dir)
}

fn scene_path() -> std::path::PathBuf {
    common::scene(SHADING)
}

/// Chapter 3's scene at 64 pixels wide, rendered by the library as the binary renders it.
fn framebuffer() -> Framebuffer {
    let scene = whitted::scene::load(&scene_path()).unwrap();
    let mut options = Options::for_scene(&scene, SHADING);
    (options.width, options.height) = whitted_app::cli::image_size(&scene, Some(64), None);
    render(&scene, &options).0
}

/// Runs chapter 3 on its scene at 64 pixels wide with `extra` arguments and reads the PNG back.
fn png(extra: &[&str]) -> (u32, u32, Vec<u8>) {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_path();
    let mut args = vec![
        scene.to_str().unwrap(),
        "-o",
        "out.png",
        "--width",
        "64",
        "-q",
    ];
    args.extend(extra);
    let o = run(&args, dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    whitted::output::read_png(&dir.path().join("out.png")).unwrap()
}

/// `--encoding linear` writes the bytes whitted always wrote before sRGB: each intensity
/// clamped, times 255, rounded ([`to_byte`]), of the same framebuffer.
#[test]
fn encoding_linear_writes_the_intensities_as_bytes() {
    let fb = framebuffer();
    let old: Vec<u8> = fb
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(to_byte))
        .collect();
    assert_eq!(png(&["--encoding", "linear"]), (fb.width, fb.height, old));
}

/// Without `--encoding` (and with `--encoding srgb`) the PNG is the framebuffer sRGB-encoded;
/// it differs from the linear one and is nowhere darker.
#[test]
fn the_default_png_is_srgb_encoded() {
    let fb = framebuffer();
    let srgb = (fb.width, fb.height, to_rgb8(&fb, Encoding::Srgb));
    let default = png(&[]);
    assert_eq!(default, srgb);
    assert_eq!(png(&["--encoding", "srgb"]), srgb);
    let linear = to_rgb8(&fb, Encoding::Linear);
    assert_ne!(default.2, linear);
    assert!(default.2.iter().zip(&linear).all(|(s, l)| s >= l));
}

/// An encoding the command line does not know is one line `error: …` naming it, exit status
/// 2, and no image.
#[test]
fn an_unknown_encoding_is_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&["--encoding", "gamma", "-o", "out.png"], dir.path());
    let err = common::one_line_error(&o, "--encoding gamma");
    assert!(err.starts_with("error: ") && err.contains("gamma"), "{err}");
    assert!(!err.contains("panicked"));
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}
