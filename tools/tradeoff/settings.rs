//! What is measured: the fixed scenes and the render settings every precision renders.

use whitted::offset::OffsetKind;
use whitted::render::{Chapter, Options};
use whitted::scene::{self, Scene};
use whitted::shapes::Numerics;

/// The fixed scenes: (short name, file, text).
pub const SCENES: [(&str, &str, &str); 3] = [
    (
        "showcase",
        "scenes/showcase.toml",
        include_str!("../../scenes/showcase.toml"),
    ),
    (
        "far",
        "scenes/far.toml",
        include_str!("../../scenes/far.toml"),
    ),
    (
        "grazing",
        "scenes/grazing.toml",
        include_str!("../../scenes/grazing.toml"),
    ),
];

/// One render setting (the precision is the build's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setting {
    pub scene: usize,
    pub formula: Numerics,
    pub offset: OffsetKind,
    pub samples: u32,
    pub depth: u32,
}

impl Setting {
    /// The setting's name in the workers' files.
    pub fn key(&self) -> String {
        format!(
            "{}-{:?}-{}-s{}-d{}",
            SCENES[self.scene].0,
            self.formula,
            self.offset.name(),
            self.samples,
            self.depth
        )
    }

    /// The reference a scene's renders are compared with: f64 (the coordinator's build), robust
    /// formulas, error-bound offset, `samples` per pixel, depth 12.
    pub fn reference(scene: usize, samples: u32) -> Self {
        Setting {
            scene,
            formula: Numerics::Robust,
            offset: OffsetKind::ErrorBound,
            samples,
            depth: 12,
        }
    }
}

/// The settings every precision renders: every formula × offset at 1 sample and depth 5; the
/// classic (textbook, fixed) and the default (robust, error-bound) at 4 and 16 samples; the
/// default at depths 1 and 2.
pub fn settings() -> Vec<Setting> {
    let mut all = Vec::new();
    for scene in 0..SCENES.len() {
        let base = Setting {
            scene,
            formula: Numerics::Robust,
            offset: OffsetKind::ErrorBound,
            samples: 1,
            depth: 5,
        };
        for formula in [Numerics::Textbook, Numerics::Robust] {
            for offset in [
                OffsetKind::Fixed,
                OffsetKind::Scaled,
                OffsetKind::ErrorBound,
            ] {
                all.push(Setting {
                    formula,
                    offset,
                    ..base
                });
            }
        }
        for samples in [4, 16] {
            for (formula, offset) in [
                (Numerics::Textbook, OffsetKind::Fixed),
                (Numerics::Robust, OffsetKind::ErrorBound),
            ] {
                all.push(Setting {
                    formula,
                    offset,
                    samples,
                    ..base
                });
            }
        }
        for depth in [1, 2] {
            all.push(Setting { depth, ..base });
        }
    }
    all
}

/// The built-in scene number `scene`.
pub fn load(scene: usize) -> Scene {
    let (_, file, text) = SCENES[scene];
    scene::parse(text, file).expect("the built-in scenes are valid")
}

/// The render options of a setting at the given image size.
pub fn options(scene: &Scene, s: &Setting, width: u32, height: u32) -> Options {
    let mut o = Options::for_scene(scene, Chapter::ReflectionRefraction);
    (o.width, o.height) = (width, height);
    o.numerics = s.formula;
    o.offset = s.offset.offset();
    o.samples = s.samples;
    o.max_depth = s.depth;
    o
}

/// A formula's name in the report.
pub fn formula_name(f: Numerics) -> &'static str {
    match f {
        Numerics::Textbook => "textbook",
        Numerics::Robust => "robust",
    }
}
