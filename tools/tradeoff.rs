//! `tradeoff` — what each accuracy choice costs in time and buys in error, measured.
//!
//! ```text
//! cargo run --release --bin tradeoff            # writes docs/tradeoff.md and docs/tradeoff.svg
//! cargo run --release --bin tradeoff -- --quick # a smaller run, to try it out
//! ```
//!
//! It renders three fixed scenes (the showcase, the showcase seen from 1e4 units away, and a
//! grazing-angle scene) under a set of settings: precision f32/f64, textbook or robust
//! formulas, each offset strategy, 1/4/16 samples per pixel and several recursion depths. Each
//! setting's render time is the median of several runs; its error is measured against a
//! reference (f64, robust formulas, error-bound offset, many samples, deep recursion): RMSE and
//! largest error in 8-bit levels, the share of pixels off by more than 1/255, and the pixels
//! whose centre ray hits an object in one image and nothing in the other.
//!
//! Both precisions come from one command: the f64 build builds the f32 variant of itself
//! (`cargo build --release --features f32`, in its own target directory) and runs it as a
//! worker that renders the same settings and dumps raw pixels. The workers also time each
//! shape's intersection routine (ns per ray–shape test), textbook against robust.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

use clap::Parser;
use whitted::offset::OffsetKind;
use whitted::ray::Ray;
use whitted::real::{PRECISION, Real, Vec3};
use whitted::render::{self, Options, Stage, Tracer};
use whitted::scene::{self, Scene};
use whitted::shapes::{Formula, Object, Polyhedron, Shape};
use whitted::transform::Placement;

/// The fixed scenes: (short name, file, text).
const SCENES: [(&str, &str, &str); 3] = [
    (
        "showcase",
        "scenes/showcase.toml",
        include_str!("../scenes/showcase.toml"),
    ),
    ("far", "scenes/far.toml", include_str!("../scenes/far.toml")),
    (
        "grazing",
        "scenes/grazing.toml",
        include_str!("../scenes/grazing.toml"),
    ),
];

/// Measures the speed–accuracy trade of whitted's accuracy switches and writes a Markdown
/// table and an SVG plot under docs/.
#[derive(Parser)]
#[command(name = "tradeoff", version)]
struct Args {
    /// Image width of every render.
    #[arg(long, default_value_t = 240)]
    width: u32,
    /// Image height of every render.
    #[arg(long, default_value_t = 180)]
    height: u32,
    /// Timed runs per setting (the median is reported).
    #[arg(long, default_value_t = 7)]
    runs: usize,
    /// Samples per pixel of the reference images.
    #[arg(long, default_value_t = 64)]
    reference_samples: u32,
    /// A small, fast run: 80×60 pixels, 3 runs, a 16-sample reference.
    #[arg(long)]
    quick: bool,
    /// Where to write tradeoff.md and tradeoff.svg.
    #[arg(long, default_value = "docs")]
    out: PathBuf,
    /// Internal: render every setting at this build's precision into DIR and exit.
    #[arg(long, value_name = "DIR", hide = true)]
    worker: Option<PathBuf>,
}

/// One render setting (the precision is the build's).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Setting {
    scene: usize,
    formula: Formula,
    offset: OffsetKind,
    samples: u32,
    depth: u32,
}

impl Setting {
    fn key(&self) -> String {
        format!(
            "{}-{:?}-{}-s{}-d{}",
            SCENES[self.scene].0,
            self.formula,
            self.offset.name(),
            self.samples,
            self.depth
        )
    }
}

/// The settings every precision renders: every formula × offset at 1 sample and depth 5; the
/// classic (textbook, fixed) and the default (robust, error-bound) at 4 and 16 samples; the
/// default at depths 1 and 2.
fn settings() -> Vec<Setting> {
    let mut all = Vec::new();
    for scene in 0..SCENES.len() {
        let base = Setting {
            scene,
            formula: Formula::Robust,
            offset: OffsetKind::ErrorBound,
            samples: 1,
            depth: 5,
        };
        for formula in [Formula::Textbook, Formula::Robust] {
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
                (Formula::Textbook, OffsetKind::Fixed),
                (Formula::Robust, OffsetKind::ErrorBound),
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

fn load(scene: usize) -> Scene {
    let (_, file, text) = SCENES[scene];
    scene::parse(text, file).expect("the built-in scenes are valid")
}

fn options(scene: &Scene, s: &Setting, width: u32, height: u32) -> Options {
    let mut o = Options::for_scene(scene, Stage::ReflectionRefraction);
    (o.width, o.height) = (width, height);
    o.formula = s.formula;
    o.offset = s.offset.offset();
    o.samples = s.samples;
    o.max_depth = s.depth;
    o
}

/// What each pixel's centre ray hits: 0 for nothing, else 1 + the object's index (saturated).
fn hit_mask(scene: &Scene, options: &Options) -> Vec<u8> {
    let tracer = Tracer::new(scene, options);
    let mut mask = Vec::with_capacity((options.width * options.height) as usize);
    for y in 0..options.height {
        for x in 0..options.width {
            let ray = tracer.camera().pixel_ray(x, y, 0.5, 0.5);
            let hit = tracer.nearest(&ray, 0.0);
            mask.push(hit.map_or(0, |n| (n.object + 1).min(255) as u8));
        }
    }
    mask
}

/// A rendered setting: linear RGB (as f64) and the hit mask.
struct Image {
    pixels: Vec<[f64; 3]>,
    mask: Vec<u8>,
}

/// A [`Real`] as f64 (a no-op in the default precision, hence the allowed cast).
#[allow(clippy::unnecessary_cast)]
fn wide(x: Real) -> f64 {
    x as f64
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        (xs[n / 2 - 1] + xs[n / 2]) / 2.0
    }
}

/// Renders a setting `runs` times: the median time in seconds and the image.
fn measure(s: &Setting, width: u32, height: u32, runs: usize) -> (f64, Image) {
    let scene = load(s.scene);
    let o = options(&scene, s, width, height);
    let mut times = Vec::with_capacity(runs);
    let mut fb = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let (image, _) = render::render(&scene, &o);
        times.push(start.elapsed().as_secs_f64());
        fb = Some(image);
    }
    let fb = fb.expect("at least one run");
    let pixels = fb
        .pixels
        .iter()
        .map(|p| [wide(p.x), wide(p.y), wide(p.z)])
        .collect();
    (
        median(times),
        Image {
            pixels,
            mask: hit_mask(&scene, &o),
        },
    )
}

/// Nanoseconds per ray–shape test for each shape and formula, at this build's precision:
/// 4096 fixed rays through the generic shapes, the fastest of 15 timed passes (the least
/// disturbed by whatever else the machine runs).
fn shape_timings() -> Vec<(String, Formula, f64)> {
    let shapes = [
        Shape::Sphere,
        Shape::Plane,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Polyhedron(Polyhedron::cube()),
    ];
    let rays = bench_rays(4096);
    let mut out = Vec::new();
    for shape in &shapes {
        let object = Object::new(shape.clone(), Placement::identity());
        for formula in [Formula::Textbook, Formula::Robust] {
            let mut times = Vec::new();
            for _ in 0..15 {
                let start = Instant::now();
                let mut count = 0usize;
                for _ in 0..8 {
                    for ray in &rays {
                        count += std::hint::black_box(object.intersect(ray, formula)).len();
                    }
                }
                std::hint::black_box(count);
                times.push(start.elapsed().as_secs_f64() * 1e9 / (8 * rays.len()) as f64);
            }
            let fastest = times.iter().copied().fold(f64::INFINITY, f64::min);
            out.push((shape.name().to_string(), formula, fastest));
        }
    }
    out
}

/// Deterministic rays from a shell of radius 2–6 towards points within 1.5 of the origin
/// (about two thirds hit the generic shapes).
fn bench_rays(n: usize) -> Vec<Ray> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..n)
        .map(|_| {
            let o = Vec3::new(next() as Real, next() as Real, next() as Real);
            let o = whitted::numeric::normalize(o) * (4.0 + 2.0 * next()) as Real;
            let t = Vec3::new(next() as Real, next() as Real, next() as Real) * 1.5;
            Ray::new(o, t - o)
        })
        .collect()
}

/// Worker mode: renders every setting at this build's precision into `dir`.
fn worker(dir: &Path, args: &Args) -> std::io::Result<()> {
    fs::create_dir_all(dir)?;
    let mut index = String::new();
    for s in settings() {
        let (seconds, image) = measure(&s, args.width, args.height, args.runs);
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
    Ok(())
}

fn read_image(dir: &Path, key: &str, n: usize) -> std::io::Result<Image> {
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

/// Error of an image against the reference, on displayed values (clamped to [0, 1]).
#[derive(Clone, Copy, Debug, Default)]
struct Error {
    rmse: f64,
    max: f64,
    off: f64,
    hit_miss: usize,
    non_finite: usize,
    /// Share of pixels off by more than 1/255 against the f64 robust error-bound render with
    /// the same samples and depth: the numerical error alone, without the sampling error.
    numeric: f64,
}

fn compare(image: &Image, reference: &Image) -> Error {
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

/// Builds the f32 variant of this command and returns its path.
fn build_f32() -> Result<PathBuf, String> {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(manifest).join("target"))
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

fn run_worker(exe: &Path, dir: &Path, args: &Args) -> Result<(), String> {
    eprintln!("rendering with {} …", exe.display());
    let status = Command::new(exe)
        .arg("--worker")
        .arg(dir)
        .args(["--width", &args.width.to_string()])
        .args(["--height", &args.height.to_string()])
        .args(["--runs", &args.runs.to_string()])
        .status()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{} failed", exe.display()))
    }
}

/// One row of the results.
struct Row {
    precision: &'static str,
    setting: Setting,
    seconds: f64,
    error: Error,
}

fn read_times(dir: &Path) -> Result<Vec<(String, f64)>, String> {
    let text = fs::read_to_string(dir.join("times.tsv")).map_err(|e| e.to_string())?;
    Ok(text
        .lines()
        .filter_map(|l| {
            let (k, t) = l.split_once('\t')?;
            Some((k.to_string(), t.parse().ok()?))
        })
        .collect())
}

fn main() -> ExitCode {
    let mut args = Args::parse();
    if args.quick {
        (args.width, args.height, args.runs, args.reference_samples) = (80, 60, 3, 16);
    }
    if let Some(dir) = &args.worker {
        return match worker(dir, &args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        };
    }
    match coordinate(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// The machine's 1-minute load average (Linux), to judge how far the timings can be trusted.
fn load_average() -> Option<f64> {
    fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

fn coordinate(args: &Args) -> Result<(), String> {
    if PRECISION != "f64" {
        return Err("run the f64 build: it builds and runs the f32 variant itself".into());
    }
    let started = Instant::now();
    let load_before = load_average();
    let f32_exe = build_f32()?;
    let work = tempfile::tempdir().map_err(|e| e.to_string())?;
    let dirs = [
        ("f64", work.path().join("f64")),
        ("f32", work.path().join("f32")),
    ];
    let this = std::env::current_exe().map_err(|e| e.to_string())?;
    run_worker(&this, &dirs[0].1, args)?;
    run_worker(&f32_exe, &dirs[1].1, args)?;

    eprintln!("rendering the references …");
    let n = (args.width * args.height) as usize;
    let references: Vec<Image> = (0..SCENES.len())
        .map(|scene| {
            let s = Setting {
                scene,
                formula: Formula::Robust,
                offset: OffsetKind::ErrorBound,
                samples: args.reference_samples,
                depth: 12,
            };
            measure(&s, args.width, args.height, 1).1
        })
        .collect();

    let mut rows = Vec::new();
    for (precision, dir) in &dirs {
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
                formula: Formula::Robust,
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
    let mut micro = Vec::new();
    for (precision, dir) in &dirs {
        let text = fs::read_to_string(dir.join("shapes.tsv")).map_err(|e| e.to_string())?;
        for line in text.lines() {
            let parts: Vec<&str> = line.split('\t').collect();
            if let [shape, formula, ns] = parts[..] {
                micro.push((
                    *precision,
                    shape.to_string(),
                    formula.to_string(),
                    ns.parse::<f64>().unwrap_or(f64::NAN),
                ));
            }
        }
    }

    fs::create_dir_all(&args.out).map_err(|e| e.to_string())?;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let load = match (load_before, load_average()) {
        (Some(a), Some(b)) => format!(
            "The machine had {cores} cores and a load average of {a:.1} at the start and {b:.1} at the end{}.",
            if a.max(b) > cores as f64 {
                ": other work competed for the cores, so compare times within a precision and read \
                 the cross-precision render-time ratio with care (the ns-per-test table below, which \
                 keeps the fastest pass, is steadier)"
            } else {
                ""
            }
        ),
        _ => format!("The machine had {cores} cores."),
    };
    let md = report(&rows, &micro, args, started.elapsed().as_secs_f64(), &load);
    let md_path = args.out.join("tradeoff.md");
    whitted::output::write_file(&md_path, md.as_bytes()).map_err(|e| e.to_string())?;
    let svg_path = args.out.join("tradeoff.svg");
    plot(&rows, &svg_path)?;
    eprintln!(
        "wrote {} and {} in {:.0} s",
        md_path.display(),
        svg_path.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

fn formula_name(f: Formula) -> &'static str {
    match f {
        Formula::Textbook => "textbook",
        Formula::Robust => "robust",
    }
}

/// The geometric mean of time ratios between pairs of rows that differ only by `pick`.
fn cost_ratio(rows: &[Row], slow: impl Fn(&Row) -> bool, fast: impl Fn(&Row, &Row) -> bool) -> f64 {
    let mut logs = Vec::new();
    for a in rows.iter().filter(|r| slow(r)) {
        if let Some(b) = rows.iter().find(|b| fast(a, b)) {
            logs.push((a.seconds / b.seconds).ln());
        }
    }
    (logs.iter().sum::<f64>() / logs.len().max(1) as f64).exp()
}

fn find<'a>(rows: &'a [Row], precision: &str, s: Setting) -> Option<&'a Row> {
    rows.iter()
        .find(|r| r.precision == precision && r.setting == s)
}

fn report(
    rows: &[Row],
    micro: &[(&str, String, String, f64)],
    args: &Args,
    seconds: f64,
    load: &str,
) -> String {
    let mut md = String::new();
    let mut w = |s: String| {
        md.push_str(&s);
        md.push('\n');
    };
    w("# The speed–accuracy trade, measured".into());
    w(String::new());
    w(
        "Generated by `cargo run --release --bin tradeoff` (do not edit by hand: rerun it). "
            .to_string()
            + &format!(
                "Images {}×{}, render time = median of {} runs (rayon, all cores of the machine that ran it); \
             reference = f64, robust formulas, error-bound offset, {} samples per pixel, depth 12. \
             Errors are on displayed values (clamped to [0, 1]) in 8-bit levels: RMSE and max over all channels, \
             *off* = share of pixels with a channel off by more than 1/255, *hit/miss* = pixels whose centre ray \
             hits nothing in one image and something in the other, or another object, *non-finite* = NaN or ∞ channels, \
             *numeric* = share of pixels off by more than 1/255 against the f64 robust error-bound render with the \
             same samples and depth (the numerical error alone, without the sampling error). \
             This run took {:.0} s. {load}",
                args.width, args.height, args.runs, args.reference_samples, seconds
            ),
    );
    w(String::new());
    w("![error against time](tradeoff.svg)".into());
    w(String::new());

    // headline figures
    let same = |a: &Setting, b: &Setting| {
        a.scene == b.scene && a.samples == b.samples && a.depth == b.depth
    };
    let f64_cost = cost_ratio(
        rows,
        |r| r.precision == "f64",
        |a, b| b.precision == "f32" && b.setting == a.setting,
    );
    let robust_cost = |p: &'static str| {
        cost_ratio(
            rows,
            move |r| r.precision == p && r.setting.formula == Formula::Robust,
            move |a, b| {
                b.precision == p
                    && b.setting.formula == Formula::Textbook
                    && b.setting.offset == a.setting.offset
                    && same(&a.setting, &b.setting)
            },
        )
    };
    let eb_cost = cost_ratio(
        rows,
        |r| r.setting.offset == OffsetKind::ErrorBound,
        |a, b| {
            b.precision == a.precision
                && b.setting.offset == OffsetKind::Fixed
                && b.setting.formula == a.setting.formula
                && same(&a.setting, &b.setting)
        },
    );
    w("## Headline".into());
    w(String::new());
    w(format!(
        "- **f64 over f32:** renders take {:.2}× the f32 time (geometric mean over all {} matched settings).",
        f64_cost,
        rows.len() / 2
    ));
    w(format!(
        "- **robust over textbook formulas:** {:.2}× in f64, {:.2}× in f32 (same scene, offset, samples and depth).",
        robust_cost("f64"),
        robust_cost("f32")
    ));
    w(format!(
        "- **error-bound over fixed-ε offset:** {:.2}× (same precision, formula, samples and depth).",
        eb_cost
    ));
    let base = |scene: usize, formula, offset| Setting {
        scene,
        formula,
        offset,
        samples: 1,
        depth: 5,
    };
    for (scene, (name, _, _)) in SCENES.iter().enumerate() {
        let mut parts = Vec::new();
        for p in ["f32", "f64"] {
            for (f, o) in [
                (Formula::Textbook, OffsetKind::Fixed),
                (Formula::Robust, OffsetKind::ErrorBound),
            ] {
                if let Some(r) = find(rows, p, base(scene, f, o)) {
                    parts.push(format!(
                        "{p} {}+{}: {:.1}% off ({:.1}% numeric), {} hit/miss",
                        formula_name(f),
                        o.name(),
                        100.0 * r.error.off,
                        100.0 * r.error.numeric,
                        r.error.hit_miss
                    ));
                }
            }
        }
        w(format!(
            "- **{name}**, 1 sample, depth 5: {}.",
            parts.join("; ")
        ));
    }
    w(String::new());
    w("At one sample per pixel most of the remaining error against the many-sample reference is \
       aliasing at edges, which only more samples remove; the precision and formula columns show \
       their effect as the *difference* between rows of the same scene and samples, and the *numeric* \
       column isolates it."
        .into());
    w(String::new());

    w("## All settings".into());
    w(String::new());
    w("| scene | precision | formula | offset | samples | depth | time (ms) | RMSE | max | off > 1/255 | numeric | hit/miss | non-finite |".into());
    w("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|".into());
    for (scene, (scene_name, _, _)) in SCENES.iter().enumerate() {
        for r in rows.iter().filter(|r| r.setting.scene == scene) {
            let s = r.setting;
            w(format!(
                "| {} | {} | {} | {} | {} | {} | {:.1} | {:.2} | {:.0} | {:.2}% | {:.2}% | {} | {} |",
                scene_name,
                r.precision,
                formula_name(s.formula),
                s.offset.name(),
                s.samples,
                s.depth,
                r.seconds * 1e3,
                r.error.rmse,
                r.error.max,
                100.0 * r.error.off,
                100.0 * r.error.numeric,
                r.error.hit_miss,
                r.error.non_finite
            ));
        }
    }
    w(String::new());
    w("## ns per ray–shape test".into());
    w(String::new());
    w("Measured by the same command (4096 fixed rays through each generic shape, about two thirds \
       hitting, fastest of 15 passes, one thread). For criterion's statistics run the micro-benchmark \
       twice, once per precision: `cargo bench --bench shapes` and `cargo bench --bench shapes --features f32`."
        .into());
    w(String::new());
    w("| shape | f32 textbook | f32 robust | f64 textbook | f64 robust |".into());
    w("|---|---:|---:|---:|---:|".into());
    let shapes: Vec<String> = micro
        .iter()
        .filter(|m| m.0 == "f64" && m.2 == "Textbook")
        .map(|m| m.1.clone())
        .collect();
    for shape in shapes {
        let get = |p: &str, f: &str| {
            micro
                .iter()
                .find(|m| m.0 == p && m.1 == shape && m.2 == f)
                .map_or(f64::NAN, |m| m.3)
        };
        w(format!(
            "| {shape} | {:.1} | {:.1} | {:.1} | {:.1} |",
            get("f32", "Textbook"),
            get("f32", "Robust"),
            get("f64", "Textbook"),
            get("f64", "Robust")
        ));
    }
    md
}

/// Error (RMSE, 8-bit levels) against render time, one series per precision, log-log.
fn plot(rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let fail = |e: String| format!("cannot draw {}: {e}", path.display());
    // drawn into memory, then written atomically like every other output
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(e.to_string()))?;
        let floor = 0.01;
        let t_min = rows
            .iter()
            .map(|r| r.seconds * 1e3)
            .fold(f64::INFINITY, f64::min);
        let t_max = rows.iter().map(|r| r.seconds * 1e3).fold(0.0, f64::max);
        let e_max = rows.iter().map(|r| r.error.rmse).fold(floor, f64::max);
        let mut chart = ChartBuilder::on(&root)
            .caption("whitted: error against render time", ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (t_min * 0.8..t_max * 1.25).log_scale(),
                (floor..e_max * 1.5).log_scale(),
            )
            .map_err(|e| fail(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc("render time (ms, median)")
            .y_desc("RMSE against the reference (8-bit levels)")
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        let styles = [
            ("f32", "textbook", RGBColor(214, 39, 40)),
            ("f32", "robust", RGBColor(255, 152, 150)),
            ("f64", "textbook", RGBColor(31, 119, 180)),
            ("f64", "robust", RGBColor(140, 190, 230)),
        ];
        for (precision, formula, color) in styles {
            let points: Vec<(f64, f64, usize)> = rows
                .iter()
                .filter(|r| r.precision == precision && formula_name(r.setting.formula) == formula)
                .map(|r| (r.seconds * 1e3, r.error.rmse.max(floor), r.setting.scene))
                .collect();
            chart
                .draw_series(points.iter().map(|&(t, e, scene)| {
                    let style = color.filled();
                    match scene {
                        0 => Circle::new((t, e), 5, style).into_dyn(),
                        1 => TriangleMarker::new((t, e), 6, style).into_dyn(),
                        _ => Cross::new((t, e), 5, color.stroke_width(2)).into_dyn(),
                    }
                }))
                .map_err(|e| fail(e.to_string()))?
                .label(format!("{precision} {formula}"))
                .legend(move |(x, y)| Circle::new((x, y), 5, color.filled()));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        root.draw(&Text::new(
            "● showcase   ▲ far   × grazing",
            (80, 570),
            ("sans-serif", 15),
        ))
        .map_err(|e| fail(e.to_string()))?;
        root.present().map_err(|e| fail(e.to_string()))?;
    }
    whitted::output::write_file(path, svg.as_bytes()).map_err(|e| e.to_string())
}
