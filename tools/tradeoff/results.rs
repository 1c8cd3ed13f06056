//! The raw results: everything the report and the plot are written from, kept as JSON
//! (docs/src/tradeoff.json) so that `--replot` can write both again without measuring.
//!
//! The measuring run writes the JSON first and then writes the report and the plot from the
//! JSON it just wrote (parsed back), exactly as `--replot` does: the committed SVG and
//! Markdown are then a function of the committed JSON alone, and a test re-plots it and
//! compares byte for byte.

use std::path::Path;

use serde::{Deserialize, Serialize};
use whitted::offset::OffsetKind;
use whitted::shapes::Numerics;

use crate::metrics::{Error, Row};
use crate::settings::{SCENES, Setting, formula_name};
use crate::shapes::ShapeTiming;

/// What the JSON file is, written at its top.
const ABOUT: &str = "Raw results of `cargo run --release --bin tradeoff`, from which it writes \
tradeoff.md and tradeoff.svg; `cargo run --release --bin tradeoff -- --replot` writes both again \
from this file without measuring. Times are in seconds, errors in 8-bit levels (rmse, max) or \
shares of the pixels (off, numeric).";

/// Everything one measuring run found.
#[derive(Debug, Serialize, Deserialize)]
pub struct Results {
    /// What the file is ([`ABOUT`]).
    pub about: String,
    /// Image width of every render.
    pub width: u32,
    /// Image height of every render.
    pub height: u32,
    /// Timed runs per setting (the median is kept).
    pub runs: usize,
    /// Samples per pixel of the reference images.
    pub reference_samples: u32,
    /// How long the whole run took, in seconds.
    pub seconds: f64,
    /// The machine that measured.
    pub machine: Machine,
    /// Every setting of both precisions, timed and compared.
    pub rows: Vec<Row>,
    /// ns per ray–shape test.
    pub shapes: Vec<ShapeTiming>,
    /// The planet measurements of each worker, the lines of its `planet.tsv`.
    pub planet: PlanetLines,
}

/// The machine that measured: its cores and its 1-minute load average at the start and the
/// end of the run (absent where it cannot be read).
#[derive(Debug, Serialize, Deserialize)]
pub struct Machine {
    /// Cores available to the run.
    pub cores: usize,
    /// Load average when the run started.
    pub load_before: Option<f64>,
    /// Load average when the run ended.
    pub load_after: Option<f64>,
}

/// Each worker's `planet.tsv`, line by line (see [`crate::planet::measure_all`]).
#[derive(Debug, Serialize, Deserialize)]
pub struct PlanetLines {
    /// The f64 worker's lines.
    pub f64: Vec<String>,
    /// The f32 worker's lines.
    pub f32: Vec<String>,
}

impl Results {
    /// The results of a run, with the file's description filled in.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        (width, height, runs, reference_samples): (u32, u32, usize, u32),
        seconds: f64,
        machine: Machine,
        rows: Vec<Row>,
        shapes: Vec<ShapeTiming>,
        planet: PlanetLines,
    ) -> Self {
        Self {
            about: ABOUT.into(),
            width,
            height,
            runs,
            reference_samples,
            seconds,
            machine,
            rows,
            shapes,
            planet,
        }
    }

    /// The JSON text (pretty-printed, ending in a newline).
    pub fn to_json(&self) -> Result<String, String> {
        let mut text = serde_json::to_string_pretty(self).map_err(|e| e.to_string())?;
        text.push('\n');
        Ok(text)
    }

    /// Parses the JSON text of [`Results::to_json`].
    pub fn from_json(text: &str) -> Result<Self, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// Reads and parses a JSON file.
    pub fn read(path: &Path) -> Result<Self, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        Self::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))
    }
}

/// A [`Row`] as the JSON holds it: names instead of enums and indices.
#[derive(Serialize, Deserialize)]
struct RowRecord {
    scene: String,
    precision: String,
    formula: String,
    offset: String,
    samples: u32,
    depth: u32,
    #[serde(with = "crate::finite")]
    seconds: f64,
    error: Error,
}

impl Serialize for Row {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let s = self.setting;
        RowRecord {
            scene: SCENES[s.scene].0.into(),
            precision: self.precision.into(),
            formula: formula_name(s.formula).into(),
            offset: s.offset.name().into(),
            samples: s.samples,
            depth: s.depth,
            seconds: self.seconds,
            error: self.error,
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Row {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error as _;
        let r = RowRecord::deserialize(deserializer)?;
        let unknown = |what: &str, name: &str| D::Error::custom(format!("unknown {what} `{name}`"));
        let scene = SCENES
            .iter()
            .position(|s| s.0 == r.scene)
            .ok_or_else(|| unknown("scene", &r.scene))?;
        let precision = ["f32", "f64"]
            .into_iter()
            .find(|p| *p == r.precision)
            .ok_or_else(|| unknown("precision", &r.precision))?;
        let formula = [Numerics::Textbook, Numerics::Robust]
            .into_iter()
            .find(|f| formula_name(*f) == r.formula)
            .ok_or_else(|| unknown("formula", &r.formula))?;
        let offset = OffsetKind::ALL
            .into_iter()
            .find(|o| o.name() == r.offset)
            .ok_or_else(|| unknown("offset", &r.offset))?;
        Ok(Row {
            precision,
            setting: Setting {
                scene,
                formula,
                offset,
                samples: r.samples,
                depth: r.depth,
            },
            seconds: r.seconds,
            error: r.error,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Results {
        let row = |precision, scene, seconds, rmse| Row {
            precision,
            setting: Setting {
                scene,
                formula: Numerics::Robust,
                offset: OffsetKind::Scaled,
                samples: 4,
                depth: 2,
            },
            seconds,
            error: Error {
                rmse,
                max: 12.0,
                off: 0.25,
                hit_miss: 3,
                non_finite: 0,
                numeric: f64::NAN,
            },
        };
        Results::new(
            (8, 6, 1, 2),
            1.5,
            Machine {
                cores: 2,
                load_before: Some(0.5),
                load_after: None,
            },
            vec![row("f32", 1, 0.1, 2.5), row("f64", 2, 0.3, 0.1 + 0.2)],
            vec![ShapeTiming {
                precision: "f64".into(),
                shape: "sphere".into(),
                formula: "Robust".into(),
                ns: f64::INFINITY,
            }],
            PlanetLines {
                f64: vec!["cost\tgeneric\t3.5".into()],
                f32: vec![],
            },
        )
    }

    #[test]
    fn json_round_trip_keeps_settings_and_text() {
        let json = sample().to_json().unwrap();
        let back = Results::from_json(&json).unwrap();
        assert_eq!(back.rows.len(), 2);
        assert_eq!(back.rows[0].precision, "f32");
        assert_eq!(back.rows[1].setting.scene, 2);
        assert_eq!(back.rows[1].setting.offset, OffsetKind::Scaled);
        assert_eq!(back.rows[1].setting.formula, Numerics::Robust);
        assert_eq!(
            (back.rows[1].setting.samples, back.rows[1].setting.depth),
            (4, 2)
        );
        assert!(
            back.rows[0].error.numeric.is_nan(),
            "NaN is written as null"
        );
        assert!(back.shapes[0].ns.is_nan(), "∞ is written as null");
        assert_eq!(back.machine.load_after, None);
        // writing what was read gives the same text: the file is a fixed point
        assert_eq!(back.to_json().unwrap(), json);
    }

    #[test]
    fn unknown_names_are_refused() {
        let json = sample()
            .to_json()
            .unwrap()
            .replace("\"far\"", "\"nowhere\"");
        let e = Results::from_json(&json).unwrap_err();
        assert!(e.contains("unknown scene `nowhere`"), "{e}");
    }
}
