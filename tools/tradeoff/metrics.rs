//! Error metrics: each worker's image against the reference, and the rows of results.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};
use whitted::offset::OffsetKind;
use whitted::shapes::Numerics;

use crate::measure::Image;
use crate::settings::{Setting, settings};
use crate::worker::{read_image, read_times};

/// Error of an image against the reference, on displayed values (clamped to [0, 1]).
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
pub struct Error {
    /// Root-mean-square error over all channels, in 8-bit levels.
    #[serde(with = "crate::finite")]
    pub rmse: f64,
    /// The largest error of a channel, in 8-bit levels.
    #[serde(with = "crate::finite")]
    pub max: f64,
    /// Share of pixels with a channel off by more than 1/255.
    #[serde(with = "crate::finite")]
    pub off: f64,
    /// Pixels whose centre ray hits nothing in one image and something in the other, or
    /// another object.
    pub hit_miss: usize,
    /// Channels that are NaN or ∞.
    pub non_finite: usize,
    /// Share of pixels off by more than 1/255 against the f64 robust error-bound render with
    /// the same samples and depth: the numerical error alone, without the sampling error.
    #[serde(with = "crate::finite")]
    pub numeric: f64,
}

/// RMSE and largest error in 8-bit levels, the share of pixels off by more than 1/255, the
/// hit/miss pixels and the non-finite channels of `image` against `reference` (`numeric` is
/// left at 0: see [`rows`]).
pub fn compare(image: &Image, reference: &Image) -> Error {
    let mut sum = 0.0;
    let mut max: f64 = 0.0;
    let mut off = 0usize;
    let mut non_finite = 0usize;
    for (p, r) in image.pixels.iter().zip(&reference.pixels) {
        let mut worst: f64 = 0.0;
        for k in 0..3 {
            if !p[k].is_finite() {
                non_finite += 1;
            }
            let a = if p[k].is_nan() {
                0.0
            } else {
                p[k].clamp(0.0, 1.0)
            };
            let e = (a - r[k].clamp(0.0, 1.0)).abs();
            sum += e * e;
            worst = worst.max(e);
        }
        max = max.max(worst);
        if worst > 1.0 / 255.0 {
            off += 1;
        }
    }
    let n = image.pixels.len() as f64;
    Error {
        rmse: (sum / (3.0 * n)).sqrt() * 255.0,
        max: max * 255.0,
        off: off as f64 / n,
        hit_miss: image
            .mask
            .iter()
            .zip(&reference.mask)
            .filter(|(a, b)| a != b)
            .count(),
        non_finite,
        numeric: 0.0,
    }
}

/// One row of the results (kept in the JSON by [`crate::results`]).
#[derive(Debug)]
pub struct Row {
    /// "f32" or "f64": the build that rendered it.
    pub precision: &'static str,
    /// The setting rendered.
    pub setting: Setting,
    /// Median render time, in seconds.
    pub seconds: f64,
    /// Error against the scene's reference.
    pub error: Error,
}

/// Every setting of every worker (`dirs`, the f64 worker first), timed and compared with its
/// scene's reference, and for `numeric` with the f64 robust error-bound render of the same
/// samples and depth. `n` is the number of pixels of an image.
pub fn rows(
    dirs: &[(&'static str, PathBuf)],
    references: &[Image],
    n: usize,
) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for (precision, dir) in dirs {
        let times = read_times(dir)?;
        for s in settings() {
            let key = s.key();
            let seconds = times
                .iter()
                .find(|(k, _)| *k == key)
                .map(|(_, t)| *t)
                .ok_or_else(|| format!("{precision} worker did not time {key}"))?;
            let image = read_image(dir, &key, n).map_err(|e| e.to_string())?;
            let mut error = compare(&image, &references[s.scene]);
            let twin = Setting {
                formula: Numerics::Robust,
                offset: OffsetKind::ErrorBound,
                ..s
            };
            let twin = read_image(&dirs[0].1, &twin.key(), n).map_err(|e| e.to_string())?;
            error.numeric = compare(&image, &twin).off;
            rows.push(Row {
                precision,
                setting: s,
                seconds,
                error,
            });
        }
    }
    Ok(rows)
}
