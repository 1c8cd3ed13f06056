//! Whole scenes: nothing non-finite reaches a pixel of the extreme scenes, and corrupted
//! example scenes load or fail with an error, never a panic.

use super::config;
use proptest::prelude::*;
use whitted::offset::OffsetKind;
use whitted::render::{self, Chapter, Options};
use whitted::scene;
use whitted::shapes::Numerics;

/// Notes, "Lighting Equations": I = I_a + I_d + I_s + I_l + I_r is finite at every pixel of the
/// far and grazing scenes, for every formula and offset strategy.
#[test]
fn no_nan_or_infinity_reaches_a_pixel_of_the_extreme_scenes() {
    for (name, text) in [
        ("scenes/far.toml", include_str!("../../scenes/far.toml")),
        (
            "scenes/grazing.toml",
            include_str!("../../scenes/grazing.toml"),
        ),
    ] {
        let scene = scene::parse(text, name).expect("valid scene");
        for numerics in [Numerics::Textbook, Numerics::Robust] {
            for offset in OffsetKind::ALL {
                let mut options = Options::for_scene(&scene, Chapter::ReflectionRefraction);
                (options.width, options.height) = (40, 30);
                options.numerics = numerics;
                options.offset = offset.offset();
                let (fb, _) = render::render(&scene, &options);
                assert!(
                    fb.pixels
                        .iter()
                        .all(|p| p.is_finite() && p.min_element() >= 0.0),
                    "{name} {numerics:?} {offset:?}"
                );
            }
        }
    }
}

/// The example scenes the loader is fuzzed with.
const SCENES: [(&str, &str); 8] = [
    (
        "scenes/showcase.toml",
        include_str!("../../scenes/showcase.toml"),
    ),
    ("scenes/far.toml", include_str!("../../scenes/far.toml")),
    (
        "scenes/grazing.toml",
        include_str!("../../scenes/grazing.toml"),
    ),
    (
        "scenes/ch01_camera_rays.toml",
        include_str!("../../scenes/ch01_camera_rays.toml"),
    ),
    (
        "scenes/ch02_generic_objects.toml",
        include_str!("../../scenes/ch02_generic_objects.toml"),
    ),
    (
        "scenes/ch03_shading.toml",
        include_str!("../../scenes/ch03_shading.toml"),
    ),
    (
        "scenes/ch04_shadows.toml",
        include_str!("../../scenes/ch04_shadows.toml"),
    ),
    (
        "scenes/ch05_reflection_refraction.toml",
        include_str!("../../scenes/ch05_reflection_refraction.toml"),
    ),
];

/// Pieces spliced into a scene: TOML punctuation, values at the edge of what is allowed, and
/// well-formed lines with bad values.
const PIECES: [&str; 34] = [
    "",
    "[",
    "]",
    "{",
    "}",
    "=",
    ",",
    "\"",
    "#",
    "\n",
    ".",
    "-",
    "nan",
    "inf",
    "-inf",
    "1e309",
    "-0.0",
    "0",
    "1e-320",
    "-1",
    "3.4e38",
    "18446744073709551616",
    "[[objects]]",
    "[camera]",
    "sphere = { center = [0, 0, 0], radius = 0 }",
    "material = \"nowhere\"",
    "transform = [ { scale = 0.0 } ]",
    "max_depth = 4294967295",
    "width = 0",
    "fov = 180",
    "near = 0",
    "ior = 0",
    "\u{0}",
    "é🦀",
];

/// One corruption: at a relative position, delete some bytes and insert a piece (or repeat a
/// slice of the text).
#[derive(Clone, Debug)]
struct Corruption {
    at: f64,
    delete: usize,
    piece: usize,
    copy_from: Option<f64>,
}

fn corruption() -> impl Strategy<Value = Corruption> {
    (
        0.0f64..1.0,
        0usize..8,
        0..PIECES.len(),
        prop::option::weighted(0.2, 0.0f64..1.0),
    )
        .prop_map(|(at, delete, piece, copy_from)| Corruption {
            at,
            delete,
            piece,
            copy_from,
        })
}

fn corrupt(text: &str, cuts: &[Corruption]) -> String {
    let mut bytes = text.as_bytes().to_vec();
    for c in cuts {
        let at = ((c.at * bytes.len() as f64) as usize).min(bytes.len());
        let end = (at + c.delete).min(bytes.len());
        let insert: Vec<u8> = match c.copy_from {
            Some(from) => {
                let start = ((from * bytes.len() as f64) as usize).min(bytes.len());
                bytes[start..(start + 40).min(bytes.len())].to_vec()
            }
            None => PIECES[c.piece].as_bytes().to_vec(),
        };
        bytes.splice(at..end, insert);
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

/// A corrupted scene that still loads is rendered tiny: every pixel must be finite.
fn loads_or_fails_politely(name: &str, text: &str) -> Result<(), TestCaseError> {
    match scene::parse(text, name) {
        Ok(scene) => {
            let mut options = Options::for_scene(&scene, Chapter::ReflectionRefraction);
            (options.width, options.height, options.samples) = (3, 2, 1);
            options.max_depth = options.max_depth.min(3);
            let (fb, _) = render::render(&scene, &options);
            prop_assert!(fb.pixels.iter().all(|p| p.is_finite()));
        }
        Err(e) => {
            let message = e.to_string();
            prop_assert!(message.starts_with(&format!("{name}:")), "{message}");
            prop_assert!(!message.contains('\n') || message.lines().count() < 20);
        }
    }
    Ok(())
}

/// The tables of a scene (each from its `[header]` line to the next), with the comment lines
/// before the first table as table 0.
fn tables(text: &str) -> Vec<&str> {
    let mut starts: Vec<usize> = text.match_indices("\n[").map(|(i, _)| i + 1).collect();
    starts.insert(0, 0);
    starts.push(text.len());
    starts.windows(2).map(|w| &text[w[0]..w[1]]).collect()
}

proptest! {
    #![proptest_config(config(6_000))]

    /// The scene loader ("Errors are for people"): random corruptions of the whole example
    /// scenes give a scene that renders to finite pixels, or an error naming the file, never a
    /// panic.
    #[test]
    fn corrupted_example_scenes_load_or_fail_with_an_error_never_a_panic(
        which in 0usize..SCENES.len(),
        cuts in prop::collection::vec(corruption(), 1..4),
    ) {
        let (name, text) = SCENES[which];
        loads_or_fails_politely(name, &corrupt(text, &cuts))?;
    }
}

proptest! {
    // with the 6 000 whole scenes above: 106 000 corrupted scenes. Parsing costs about 70 ns
    // per byte in a debug build, so most cases are excerpts of one to four tables.
    #![proptest_config(config(100_000))]

    /// The same for excerpts of the example scenes (a run of one to four of their tables,
    /// then one of their objects), corrupted: an error naming the file or a scene that renders
    /// to finite pixels, never a panic.
    #[test]
    fn corrupted_excerpts_of_the_example_scenes_load_or_fail_with_an_error_never_a_panic(
        which in 0usize..SCENES.len(),
        first in 0.0f64..1.0,
        count in 1usize..5,
        object in 0.0f64..1.0,
        cuts in prop::collection::vec(corruption(), 1..3),
    ) {
        let (name, text) = SCENES[which];
        let all = tables(text);
        let first = ((first * all.len() as f64) as usize).min(all.len() - 1);
        let objects: Vec<&str> = all.iter().copied().filter(|t| t.starts_with("[[objects]]")).collect();
        let object = objects[((object * objects.len() as f64) as usize).min(objects.len() - 1)];
        let mut excerpt: String = all[first..(first + count).min(all.len())].concat();
        excerpt.push_str(object);
        loads_or_fails_politely(name, &corrupt(&excerpt, &cuts))?;
    }
}
