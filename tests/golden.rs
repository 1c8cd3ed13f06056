//! Golden images: each chapter renders its own scene (`scenes/chNN_*.toml`) and the showcase,
//! at a reduced size, and the result must match the committed PNG in `tests/golden/`: at most
//! 0.5% of the pixels may differ by more than 2/255 in any channel (room for f32 and for
//! rounding across platforms, none for a changed formula).
//!
//! On a failure the render and a difference image (differing pixels in red over a grey copy)
//! are written to `target/golden-diff/`. After an intended change, regenerate the references
//! with `WHITTED_BLESS=1 cargo test --test golden` and look at them before committing.

use std::path::PathBuf;

use whitted::output::{to_rgb8, write_png};
use whitted::render::{Options, Stage, render};
use whitted::scene::load;

/// Share of pixels allowed to differ by more than [`MAX_DIFF`].
const MAX_SHARE: f64 = 0.005;
/// Largest per-channel difference (in 8-bit steps) that does not count as differing.
const MAX_DIFF: u8 = 2;
/// Width of the golden renders; the height follows the scene's aspect ratio.
const WIDTH: u32 = 160;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn check(scene_file: &str, stage: Stage, golden_name: &str) {
    let scene = load(&root().join("scenes").join(scene_file)).unwrap();
    let mut options = Options::for_scene(&scene, stage);
    options.width = WIDTH;
    options.height = (WIDTH as f64 * scene.height as f64 / scene.width as f64).round() as u32;
    let (fb, _) = render(&scene, &options);
    let actual = to_rgb8(&fb);
    let golden = root()
        .join("tests/golden")
        .join(format!("{golden_name}.png"));

    if std::env::var_os("WHITTED_BLESS").is_some() {
        write_png(&golden, fb.width, fb.height, &actual).unwrap();
        return;
    }
    let expected = image::open(&golden)
        .unwrap_or_else(|e| panic!("{}: {e} (bless with WHITTED_BLESS=1)", golden.display()))
        .to_rgb8();
    assert_eq!(
        (expected.width(), expected.height()),
        (fb.width, fb.height),
        "{golden_name}: size"
    );
    let expected = expected.into_raw();

    let mut diff = Vec::with_capacity(actual.len());
    let mut off = 0usize;
    for (a, e) in actual.chunks(3).zip(expected.chunks(3)) {
        let worst = a.iter().zip(e).map(|(x, y)| x.abs_diff(*y)).max().unwrap();
        if worst > MAX_DIFF {
            off += 1;
            diff.extend_from_slice(&[255, 0, 0]);
        } else {
            let grey = ((a[0] as u32 + a[1] as u32 + a[2] as u32) / 6) as u8;
            diff.extend_from_slice(&[grey, grey, grey]);
        }
    }
    let pixels = actual.len() / 3;
    let share = off as f64 / pixels as f64;
    if share > MAX_SHARE {
        let dir = root().join("target/golden-diff");
        std::fs::create_dir_all(&dir).unwrap();
        let (act, dif) = (
            dir.join(format!("{golden_name}-actual.png")),
            dir.join(format!("{golden_name}-diff.png")),
        );
        write_png(&act, fb.width, fb.height, &actual).unwrap();
        write_png(&dif, fb.width, fb.height, &diff).unwrap();
        panic!(
            "{golden_name}: {off} of {pixels} pixels ({:.2}%) differ by more than {MAX_DIFF}/255 (allowed {:.1}%); see {} and {}",
            100.0 * share,
            100.0 * MAX_SHARE,
            act.display(),
            dif.display()
        );
    }
}

/// Chapter 1's scene: ray directions as colours.
#[test]
fn golden_ch01_camera_rays() {
    check(
        "ch01_camera_rays.toml",
        Stage::CameraRays,
        "ch01_camera_rays",
    );
}

/// Chapter 2's scene: the five generic objects, flat colours.
#[test]
fn golden_ch02_generic_objects() {
    check(
        "ch02_generic_objects.toml",
        Stage::GenericObjects,
        "ch02_generic_objects",
    );
}

/// Chapter 3's scene: Phong spheres.
#[test]
fn golden_ch03_shading() {
    check("ch03_shading.toml", Stage::Shading, "ch03_shading");
}

/// Chapter 4's scene: shadows, opaque and translucent.
#[test]
fn golden_ch04_shadows() {
    check("ch04_shadows.toml", Stage::Shadows, "ch04_shadows");
}

/// Chapter 5's scene: mirror, glass and water.
#[test]
fn golden_ch05_reflection_refraction() {
    check(
        "ch05_reflection_refraction.toml",
        Stage::ReflectionRefraction,
        "ch05_reflection_refraction",
    );
}

/// The showcase (the default scene) through the full renderer.
#[test]
fn golden_showcase() {
    check("showcase.toml", Stage::ReflectionRefraction, "showcase");
}
