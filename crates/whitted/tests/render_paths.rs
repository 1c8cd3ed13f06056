//! Every render path draws each chapter's image: the plain road of one pixel, each `--accel`,
//! packets on and off. Each test renders one chapter's scene (`scenes/chNN_*.toml`) through
//! one path at a reduced size and compares it with the committed PNG in `tests/golden/` (linear
//! bytes, `Encoding::Linear`: the framebuffer's values, not what a viewer shows): at
//! most 0.5% of the pixels may differ by more than 2/255 in any channel (room for f32 and for
//! rounding across platforms, none for a changed formula). The paths must also agree with one
//! another bit for bit.
//!
//! These are the tests `whitted formulas prove` runs: a formula function of chapter N
//! replaced by `todo!()` must make every `chN_` test fail, which shows that every path of that
//! chapter calls it (a path with a copy of its own would still pass).
//!
//! A handout that ends before a chapter holds no test of it: the tests of chapter N sit between
//! `// BEGIN CHAPTER N` and `// END CHAPTER` lines, and such a handout leaves the section out
//! (chapter 1's needs none: no handout ends before it).
//!
//! On a failure the render and a difference image (differing pixels in red over a grey copy)
//! are written to `target/golden-diff/`. After an intended change, regenerate the references
//! from the plain road with `WHITTED_BLESS=1 cargo test --test render_paths road` and look at
//! them before committing.

mod common;

use std::path::PathBuf;

use common::render_here;
use whitted::accel::Accel;
use whitted::output::{Encoding, read_png, to_rgb8, write_png};
use whitted::render::{Chapter, Framebuffer, Options};
use whitted::scene::{Scene, load_parts};

/// Share of pixels allowed to differ by more than [`MAX_DIFF`].
const MAX_SHARE: f64 = 0.005;
/// Largest per-channel difference (in 8-bit steps) that does not count as differing.
const MAX_DIFF: u8 = 2;
/// Width of the golden renders; the height follows the scene's aspect ratio.
const WIDTH: u32 = 160;

/// The workspace's root, which holds `scenes/` and `target/`: this crate sits in
/// `crates/whitted`.
fn root() -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("the crate sits two levels below the workspace's root")
        .to_path_buf()
}

/// The chapters' scenes and reference images: (scene file, chapter, golden name).
fn chapter(n: u32) -> (&'static str, Chapter, &'static str) {
    match n {
        1 => (
            "ch01_camera_rays.toml",
            Chapter::CameraRays,
            "ch01_camera_rays",
        ),
        2 => (
            "ch02_generic_objects.toml",
            Chapter::GenericObjects,
            "ch02_generic_objects",
        ),
        3 => ("ch03_shading.toml", Chapter::Shading, "ch03_shading"),
        4 => ("ch04_shadows.toml", Chapter::Shadows, "ch04_shadows"),
        5 => (
            "ch05_reflection_refraction.toml",
            Chapter::ReflectionRefraction,
            "ch05_reflection_refraction",
        ),
        _ => ("showcase.toml", Chapter::ReflectionRefraction, "showcase"),
    }
}

/// One render path: the acceleration structure and whether blocks go as packets.
#[derive(Clone, Copy, Debug)]
struct Path {
    accel: Accel,
    packets: bool,
}

/// The plain road: every object for every ray, pixel by pixel.
const ROAD: Path = Path {
    accel: Accel::None,
    packets: false,
};

/// Every path there is (packets only change anything with a BVH or an octree).
const PATHS: [Path; 7] = [
    ROAD,
    Path {
        accel: Accel::Boxes,
        packets: false,
    },
    Path {
        accel: Accel::Extents,
        packets: false,
    },
    Path {
        accel: Accel::Octree,
        packets: false,
    },
    Path {
        accel: Accel::Octree,
        packets: true,
    },
    Path {
        accel: Accel::Bvh,
        packets: false,
    },
    Path {
        accel: Accel::Bvh,
        packets: true,
    },
];

fn load_chapter(n: u32) -> (Scene, Options, &'static str) {
    let (file, chapter, golden) = chapter(n);
    // what the chapter's binary reads: chapter 1 places no object
    let scene = load_parts(&root().join("scenes").join(file), chapter.reads())
        .unwrap_or_else(|e| panic!("chapter {n}'s scene: {e}"));
    let mut options = Options::for_scene(&scene, chapter);
    options.width = WIDTH;
    options.height = (WIDTH as f64 * scene.height as f64 / scene.width as f64).round() as u32;
    (scene, options, golden)
}

fn render_path(scene: &Scene, options: &Options, path: Path) -> Framebuffer {
    let mut o = options.clone();
    o.accel = path.accel;
    o.packets = path.packets;
    render_here(scene, &o).0
}

/// Renders chapter `n`'s scene through `path` and compares it with its golden image (or, with
/// `WHITTED_BLESS` set, writes the golden image from the plain road).
fn check(n: u32, path: Path) {
    let (scene, options, golden_name) = load_chapter(n);
    let fb = render_path(&scene, &options, path);
    // the references hold linear bytes: the test is about the framebuffer, not the encoding
    let actual = to_rgb8(&fb, Encoding::Linear);
    let golden = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{golden_name}.png"));

    if std::env::var_os("WHITTED_BLESS").is_some() {
        if matches!(path.accel, Accel::None) {
            write_png(&golden, fb.width, fb.height, &actual)
                .unwrap_or_else(|e| panic!("cannot bless {}: {e}", golden.display()));
        }
        return;
    }
    let (width, height, expected) =
        read_png(&golden).unwrap_or_else(|e| panic!("{e} (bless with WHITTED_BLESS=1)"));
    assert_eq!(
        (width, height),
        (fb.width, fb.height),
        "{golden_name}: size"
    );

    let mut diff = Vec::with_capacity(actual.len());
    let mut off = 0usize;
    for (a, e) in actual.chunks(3).zip(expected.chunks(3)) {
        let worst = a
            .iter()
            .zip(e)
            .map(|(x, y)| x.abs_diff(*y))
            .max()
            .unwrap_or(0);
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
        std::fs::create_dir_all(&dir)
            .unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
        let tag = format!("{golden_name}-{}-{}", path.accel.name(), path.packets);
        let (act, dif) = (
            dir.join(format!("{tag}-actual.png")),
            dir.join(format!("{tag}-diff.png")),
        );
        for (path, bytes) in [(&act, &actual), (&dif, &diff)] {
            write_png(path, fb.width, fb.height, bytes)
                .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
        }
        panic!(
            "{golden_name} by {path:?}: {off} of {pixels} pixels ({:.2}%) differ by more than {MAX_DIFF}/255 (allowed {:.1}%); see {} and {}",
            100.0 * share,
            100.0 * MAX_SHARE,
            act.display(),
            dif.display()
        );
    }
}

/// Every path renders chapter `n`'s scene to the same bits as the plain road.
fn agree(n: u32) {
    let (scene, options, _) = load_chapter(n);
    let road = render_path(&scene, &options, ROAD);
    for path in PATHS {
        let fb = render_path(&scene, &options, path);
        let same =
            road.pixels.iter().zip(&fb.pixels).all(|(a, b)| {
                a.to_array().map(|x| x.to_bits()) == b.to_array().map(|x| x.to_bits())
            });
        assert!(same, "chapter {n}: {path:?} differs from the plain road");
    }
}

/// Declares one test per render path of a chapter, and the test that they agree.
macro_rules! paths {
    ($n:literal: $road:ident, $boxes:ident, $extents:ident, $octree:ident, $octree_packets:ident, $bvh:ident, $bvh_packets:ident, $agree:ident) => {
        /// The plain road: every object for every ray, pixel by pixel.
        #[test]
        fn $road() {
            check($n, PATHS[0]);
        }
        /// `--accel boxes`.
        #[test]
        fn $boxes() {
            check($n, PATHS[1]);
        }
        /// `--accel extents`.
        #[test]
        fn $extents() {
            check($n, PATHS[2]);
        }
        /// `--accel octree`, pixel by pixel.
        #[test]
        fn $octree() {
            check($n, PATHS[3]);
        }
        /// `--accel octree` with packets.
        #[test]
        fn $octree_packets() {
            check($n, PATHS[4]);
        }
        /// `--accel bvh`, pixel by pixel.
        #[test]
        fn $bvh() {
            check($n, PATHS[5]);
        }
        /// `--accel bvh` with packets (the default).
        #[test]
        fn $bvh_packets() {
            check($n, PATHS[6]);
        }
        /// Every path gives the plain road's image, bit for bit.
        #[test]
        fn $agree() {
            agree($n);
        }
    };
}

/// Chapter 1 intersects nothing: one path, the road (ray directions as colours).
#[test]
fn ch1_road() {
    check(1, ROAD);
}

// BEGIN CHAPTER 2
paths!(2: ch2_road, ch2_boxes, ch2_extents, ch2_octree, ch2_octree_packets, ch2_bvh, ch2_bvh_packets, ch2_paths_agree);
// END CHAPTER
// BEGIN CHAPTER 3
paths!(3: ch3_road, ch3_boxes, ch3_extents, ch3_octree, ch3_octree_packets, ch3_bvh, ch3_bvh_packets, ch3_paths_agree);
// END CHAPTER
// BEGIN CHAPTER 4
paths!(4: ch4_road, ch4_boxes, ch4_extents, ch4_octree, ch4_octree_packets, ch4_bvh, ch4_bvh_packets, ch4_paths_agree);
// END CHAPTER
// BEGIN CHAPTER 5
paths!(5: ch5_road, ch5_boxes, ch5_extents, ch5_octree, ch5_octree_packets, ch5_bvh, ch5_bvh_packets, ch5_paths_agree);
// END CHAPTER
// BEGIN CHAPTER 5 (the showcase's scene uses every chapter)
paths!(0: showcase_road, showcase_boxes, showcase_extents, showcase_octree, showcase_octree_packets, showcase_bvh, showcase_bvh_packets, showcase_paths_agree);
// END CHAPTER
