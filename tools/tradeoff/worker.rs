//! The workers: one per precision, each rendering every setting and timing the shapes at its
//! build's precision, and the files they leave for the coordinator. The f64 coordinator runs
//! itself as the f64 worker and builds the f32 variant of itself to run as the other.
//!
//! A worker's directory holds `KEY.raw` per setting (linear RGB as little-endian f32, then
//! the hit mask), `times.tsv` (key, median seconds), `shapes.tsv` (shape, formula, ns) and
//! `planet.tsv` (see [`planet::measure_all`]).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::measure::{self, Image};
use crate::planet;
use crate::settings::settings;
use crate::shapes::{ShapeTiming, shape_timings};

/// What a worker renders: the size of every image and the timed runs per setting (the
/// command line's `--width`, `--height` and `--runs`).
#[derive(Clone, Copy, Debug)]
pub struct Run {
    /// Image width of every render.
    pub width: u32,
    /// Image height of every render.
    pub height: u32,
    /// Timed runs per setting (the median is kept).
    pub runs: usize,
}

/// Worker mode: renders every setting at this build's precision into `dir`.
pub fn worker(dir: &Path, run: &Run) -> std::io::Result<()> {
    fs::create_dir_all(dir)?;
    let mut index = String::new();
    for s in settings() {
        let (seconds, image) = measure::measure(&s, run.width, run.height, run.runs);
        let mut raw = Vec::with_capacity(image.pixels.len() * 12 + image.mask.len());
        for p in &image.pixels {
            for c in p {
                raw.extend_from_slice(&(*c as f32).to_le_bytes());
            }
        }
        raw.extend_from_slice(&image.mask);
        fs::write(dir.join(format!("{}.raw", s.key())), raw)?;
        index.push_str(&format!("{}\t{seconds}\n", s.key()));
        eprint!(".");
    }
    eprintln!();
    fs::write(dir.join("times.tsv"), index)?;
    let mut micro = String::new();
    for (shape, formula, ns) in shape_timings() {
        micro.push_str(&format!("{shape}\t{formula:?}\t{ns}\n"));
    }
    fs::write(dir.join("shapes.tsv"), micro)?;
    fs::write(dir.join("planet.tsv"), planet::measure_all())?;
    Ok(())
}

/// Builds the f32 variant of this command and returns its path.
pub fn build_f32() -> Result<PathBuf, String> {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(manifest).join("../target"))
        .join("tradeoff-f32");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    eprintln!("building the f32 variant in {} …", target.display());
    let status = Command::new(cargo)
        .args([
            "build",
            "--release",
            "--features",
            "f32",
            "--bin",
            "tradeoff",
        ])
        .arg("--manifest-path")
        .arg(Path::new(manifest).join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&target)
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if !status.success() {
        return Err("building the f32 variant failed".into());
    }
    Ok(target.join("release").join("tradeoff"))
}

/// Runs the worker `exe` (this command or its f32 variant) into `dir`.
pub fn run_worker(exe: &Path, dir: &Path, run: &Run) -> Result<(), String> {
    eprintln!("rendering with {} …", exe.display());
    let status = Command::new(exe)
        .arg("--worker")
        .arg(dir)
        .args(["--width", &run.width.to_string()])
        .args(["--height", &run.height.to_string()])
        .args(["--runs", &run.runs.to_string()])
        .status()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{} failed", exe.display()))
    }
}

/// The image a worker rendered for the setting `key` (`n` pixels).
pub fn read_image(dir: &Path, key: &str, n: usize) -> std::io::Result<Image> {
    let raw = fs::read(dir.join(format!("{key}.raw")))?;
    let mut pixels = Vec::with_capacity(n);
    for i in 0..n {
        let c = |k: usize| {
            let at = (i * 3 + k) * 4;
            f64::from(f32::from_le_bytes(raw[at..at + 4].try_into().unwrap()))
        };
        pixels.push([c(0), c(1), c(2)]);
    }
    Ok(Image {
        pixels,
        mask: raw[n * 12..].to_vec(),
    })
}

/// The median render time of each setting a worker timed: (key, seconds).
pub fn read_times(dir: &Path) -> Result<Vec<(String, f64)>, String> {
    let text = fs::read_to_string(dir.join("times.tsv")).map_err(|e| e.to_string())?;
    Ok(text
        .lines()
        .filter_map(|l| {
            let (k, t) = l.split_once('\t')?;
            Some((k.to_string(), t.parse().ok()?))
        })
        .collect())
}

/// The workers' shape timings: ns per test for each precision, shape and formula.
pub fn read_shape_timings(dirs: &[(&'static str, PathBuf)]) -> Result<Vec<ShapeTiming>, String> {
    let mut micro = Vec::new();
    for (precision, dir) in dirs {
        let text = fs::read_to_string(dir.join("shapes.tsv")).map_err(|e| e.to_string())?;
        for line in text.lines() {
            let parts: Vec<&str> = line.split('\t').collect();
            if let [shape, formula, ns] = parts[..] {
                micro.push(ShapeTiming {
                    precision: precision.to_string(),
                    shape: shape.to_string(),
                    formula: formula.to_string(),
                    ns: ns.parse::<f64>().unwrap_or(f64::NAN),
                });
            }
        }
    }
    Ok(micro)
}
