//! The scaling benchmark: renders N random spheres over a plane (the `scatter` scene) at
//! 1280×720 with every `--accel`, and prints the median build and render times.
//!
//! ```text
//! cargo bench --bench scaling                               # N = 10 … 100 000
//! cargo bench --bench scaling -- --sizes 10,1000 --runs 5 --budget 30
//! cargo bench --bench scaling -- --fog                      # the fog layout
//! cargo bench --bench scaling -- --eye 0,6,4                # a close-up (see below)
//! cargo bench --bench scaling -- --pair 10,100000 --runs 21 --accel octree,bvh
//! ```
//!
//! `--eye X,Y,Z` moves the camera (the scenes put it at 0,9,17, looking at the origin over the
//! whole field). From 0,6,4 it looks down on a patch about the size of the N = 10 field, so
//! the picture stays alike as the field grows around it: what is left of the growth is the
//! structures' own.
//!
//! Each `--accel` renders its sizes in turns: one unmeasured render of each size, small to
//! large, then the measured runs, small to large, large to small, and so on. A steady drift
//! of the machine's speed during the bench then weighs on every size alike, and the growth
//! down a column is the structure's, not the drift's. A combination whose render is
//! predicted (linearly from the previous size's unmeasured render, for `none`, `boxes` and
//! `extents`) to take longer than `--budget` seconds is skipped and shown with its estimate.
//! Unless `--runs` says how many, each `--accel` takes as many runs as fit in about
//! [`AUTO_SECONDS`] of renders (by its unmeasured ones), at least 3 and at most 15: a render of
//! a tenth of a second wanders by ±15 % on a shared machine, and the median of three such runs
//! still moves a ratio by a tenth. Under the table, a row gives each column's growth: the
//! median at the last size it rendered over the median at the first (`--sizes` in its order).
//!
//! `--pair A,B` measures the growth from A to B spheres side by side, for a machine whose
//! speed wanders between invocations: both scenes and both structures are built first, one
//! render of each is left unmeasured, then the two renders alternate, run after run (A then
//! B, then B then A, so a steady drift weighs on both alike). The table gives each one's
//! median, the ratio of the medians, and the median and range of the runs' own ratios (each
//! B over the A next to it). `none`, `boxes` and `extents` are skipped where B's render,
//! predicted linearly from A's, would take longer than `--budget` seconds.

use std::time::Instant;

use whitted::accel::{Accel, Accelerator};
use whitted::render::{self, Chapter, Options};
use whitted::scene::scatter;
use whitted::scene::{Scene, parse};

/// What `--help` prints.
const USAGE: &str = "\
cargo bench --bench scaling -- [OPTIONS]

Renders N random spheres over a plane (the scatter scene) at 1280x720 with each --accel and
prints the median render time of each (the build time in brackets), and each one's growth
from the first size to the last it rendered.

  --sizes A,B,...   the numbers of spheres (default 10,100,1000,10000,100000)
  --pair A,B        only A and B, their renders alternated run by run, with their ratio
                    (instead of --sizes)
  --accel LIST      some of none,boxes,extents,octree,bvh, comma-separated (default all)
  --runs R          the runs each median is taken over (default: as many as fit in about 20 s
                    of renders per --accel, at least 3 and at most 15; with --pair, 15)
  --budget S        skip a linear option's render predicted to take over S seconds (default 20)
  --fog             the fog layout instead of the field
  --eye X,Y,Z       move the camera (0,6,4 is the close-up)
  --width W         the image width (default 1280)
  --height H        the image height (default 720)";

/// Seconds of renders an `--accel` is given when `--runs` is left out.
const AUTO_SECONDS: f64 = 20.0;

/// The fewest and the most runs `--runs` left out gives.
const AUTO_RUNS: (usize, usize) = (3, 15);

struct Config {
    sizes: Vec<usize>,
    /// `None`: chosen per `--accel` (see [`AUTO_SECONDS`]).
    runs: Option<usize>,
    budget: f64,
    width: u32,
    height: u32,
    accels: Vec<Accel>,
    layout: scatter::Layout,
    eye: Option<[f64; 3]>,
    pair: Option<(usize, usize)>,
}

fn parse_args() -> Result<Config, String> {
    let mut c = Config {
        sizes: vec![10, 100, 1_000, 10_000, 100_000],
        runs: None,
        budget: 20.0,
        width: 1280,
        height: 720,
        accels: Accel::ALL.to_vec(),
        layout: scatter::Layout::Field,
        eye: None,
        pair: None,
    };
    let mut sizes_given = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| args.next().ok_or(format!("{name} needs a value"));
        match a.as_str() {
            "--bench" => {} // passed by `cargo bench`
            "--help" | "-h" => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            "--sizes" => {
                sizes_given = true;
                c.sizes = value("--sizes")?
                    .split(',')
                    .map(|s| s.trim().parse().map_err(|_| format!("bad size `{s}`")))
                    .collect::<Result<_, _>>()?;
            }
            "--fog" => c.layout = scatter::Layout::Fog,
            "--eye" => {
                let v: Vec<f64> = value("--eye")?
                    .split(',')
                    .map(|s| {
                        s.trim()
                            .parse()
                            .map_err(|_| format!("bad coordinate `{s}`"))
                    })
                    .collect::<Result<_, _>>()?;
                let [x, y, z] = v[..] else {
                    return Err("--eye needs three coordinates: X,Y,Z".into());
                };
                c.eye = Some([x, y, z]);
            }
            "--pair" => {
                let v: Vec<usize> = value("--pair")?
                    .split(',')
                    .map(|s| s.trim().parse().map_err(|_| format!("bad size `{s}`")))
                    .collect::<Result<_, _>>()?;
                let [a, b] = v[..] else {
                    return Err("--pair needs two sizes: A,B".into());
                };
                c.pair = Some((a, b));
            }
            "--runs" => {
                c.runs = Some(
                    value("--runs")?
                        .parse()
                        .ok()
                        .filter(|&r| r > 0)
                        .ok_or("--runs needs a whole number of at least 1")?,
                );
            }
            "--budget" => c.budget = value("--budget")?.parse().map_err(|_| "bad --budget")?,
            "--width" => c.width = value("--width")?.parse().map_err(|_| "bad --width")?,
            "--height" => c.height = value("--height")?.parse().map_err(|_| "bad --height")?,
            "--accel" => {
                c.accels = value("--accel")?
                    .split(',')
                    .map(|s| {
                        Accel::ALL
                            .into_iter()
                            .find(|a| a.name() == s)
                            .ok_or(format!("unknown accel `{s}`"))
                    })
                    .collect::<Result<_, _>>()?;
            }
            other => return Err(format!("unknown argument `{other}` (see --help)")),
        }
    }
    if sizes_given && c.pair.is_some() {
        return Err("--pair A,B gives the two sizes itself; leave out --sizes".into());
    }
    Ok(c)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// The scatter scene of `n` spheres, seen from `--eye` if given.
fn scene(c: &Config, n: usize) -> Scene {
    let mut scene = parse(
        &scatter::scene_toml_with(n, 1, c.width, c.height, c.layout),
        "scatter.toml",
    )
    .expect("the scatter scene parses");
    if let Some([x, y, z]) = c.eye {
        scene.camera.eye = whitted::real::vec3(x, y, z);
    }
    scene
}

/// Chapter 5's options for the benchmark's image size and `accel`.
fn options(c: &Config, scene: &Scene, accel: Accel) -> Options {
    let mut o = Options::for_scene(scene, Chapter::ReflectionRefraction);
    o.width = c.width;
    o.height = c.height;
    o.accel = accel;
    o
}

/// Seconds to render `scene` with `acc`, and the rays it cast.
fn render_seconds(scene: &Scene, o: &Options, acc: &Accelerator) -> (f64, u64) {
    let start = Instant::now();
    let (_, stats) = render::render_with(scene, o, acc, &|_| {});
    (start.elapsed().as_secs_f64(), stats.total())
}

/// `--pair A,B`: the two sizes' renders alternated, with their ratio and the rays each casts.
fn pair(c: &Config, (a, b): (usize, usize)) {
    let runs = c.runs.unwrap_or(AUTO_RUNS.1);
    println!(
        "scaling pair ({:?} layout): N = {a} against {b}, {}×{}, {runs} run(s) alternating, {} thread(s), {}; seconds",
        c.layout,
        c.width,
        c.height,
        rayon::current_num_threads(),
        whitted::real::PRECISION
    );
    println!(
        "| accel | render N = {a} | render N = {b} | ratio of medians | median ratio (range) | build N = {b} | rays N = {a} / {b} |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    let scenes = [scene(c, a), scene(c, b)];
    for &accel in &c.accels {
        let o = [options(c, &scenes[0], accel), options(c, &scenes[1], accel)];
        let acc_a = render::build_accel(&scenes[0], &o[0]);
        // one render of each first, unmeasured: the thread pool and the memory warmed up
        let (warm, rays_a) = render_seconds(&scenes[0], &o[0], &acc_a);
        // brute force and lists grow linearly: skipped where B's render would be too long
        let linear = matches!(accel, Accel::None | Accel::Boxes | Accel::Extents);
        let estimate = warm * b as f64 / a.max(1) as f64;
        if linear && estimate > c.budget {
            println!(
                "| {} | skipped (N = {b}: ≈{estimate:.0} s a render, over --budget) | | | | | |",
                accel.name()
            );
            continue;
        }
        let start = Instant::now();
        let acc_b = render::build_accel(&scenes[1], &o[1]);
        let build_b = start.elapsed().as_secs_f64();
        let acc = [acc_a, acc_b];
        let (_, rays_b) = render_seconds(&scenes[1], &o[1], &acc[1]);
        let (mut ta, mut tb, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
        for run in 0..runs {
            // A then B, then B then A: a steady drift weighs on both alike
            let (x, y) = if run % 2 == 0 {
                let x = render_seconds(&scenes[0], &o[0], &acc[0]).0;
                (x, render_seconds(&scenes[1], &o[1], &acc[1]).0)
            } else {
                let y = render_seconds(&scenes[1], &o[1], &acc[1]).0;
                (render_seconds(&scenes[0], &o[0], &acc[0]).0, y)
            };
            ta.push(x);
            tb.push(y);
            ratios.push(y / x);
        }
        let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = ratios.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (ma, mb) = (median(ta), median(tb));
        println!(
            "| {} | {ma:.3} | {mb:.3} | {:.2}× | {:.2}× ({lo:.2}–{hi:.2}) | {build_b:.3} | {rays_a} / {rays_b} |",
            accel.name(),
            mb / ma,
            median(ratios)
        );
    }
}

fn main() {
    let c = match parse_args() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    if let Some(sizes) = c.pair {
        pair(&c, sizes);
        return;
    }
    println!(
        "scaling ({:?} layout{}): {}×{}, {}, {} thread(s), {}; median seconds, render (build)",
        c.layout,
        c.eye
            .map(|[x, y, z]| format!(", eye {x},{y},{z}"))
            .unwrap_or_default(),
        c.width,
        c.height,
        match c.runs {
            Some(r) => format!("{r} run(s) each"),
            None => "runs per --accel as the table says".to_string(),
        },
        rayon::current_num_threads(),
        whitted::real::PRECISION
    );
    // Each option's sizes are measured in turns (small to large, then large to small, …), so
    // that the machine's drift during the run weighs on every size alike and the growth read
    // down a column is not the drift's: first one unmeasured render of each size (which also
    // predicts whether the next size is worth trying), then the measured runs.
    let scenes: Vec<Scene> = c.sizes.iter().map(|&n| scene(&c, n)).collect();
    let mut cells: Vec<Vec<String>> = vec![Vec::new(); c.sizes.len()];
    let mut rays = vec![0; c.sizes.len()];
    // per --accel: the runs taken, and the growth over the sizes it rendered
    let mut footer: Vec<(usize, String)> = Vec::new();
    for &accel in &c.accels {
        eprintln!("{} …", accel.name());
        // brute force and lists grow linearly; hierarchies are not skipped on a guess
        let linear = matches!(accel, Accel::None | Accel::Boxes | Accel::Extents);
        let mut ready = Vec::new();
        let mut last: Option<(usize, f64)> = None;
        for (i, (&n, scene)) in c.sizes.iter().zip(&scenes).enumerate() {
            if let Some((n0, t0)) = last {
                let estimate = if linear {
                    t0 * n as f64 / n0 as f64
                } else {
                    t0
                };
                if estimate > c.budget {
                    cells[i].push(format!("skipped (≈{estimate:.0} s)"));
                    continue;
                }
            }
            let o = options(&c, scene, accel);
            // `--runs` builds timed (3 if left out); the last one is kept for the renders
            let mut builds = Vec::new();
            let mut acc = None;
            for _ in 0..c.runs.unwrap_or(AUTO_RUNS.0) {
                let start = Instant::now();
                let built = render::build_accel(scene, &o);
                builds.push(start.elapsed().as_secs_f64());
                acc = Some(built); // (the previous one dropped outside the timing)
            }
            let acc = acc.expect("--runs is at least 1");
            let (warm, r) = render_seconds(scene, &o, &acc);
            rays[i] = r;
            last = Some((n, warm));
            ready.push((i, o, acc, median(builds), Vec::new(), warm));
        }
        let round: f64 = ready.iter().map(|r| r.5).sum();
        let runs = c.runs.unwrap_or_else(|| {
            // (a float-to-int `as` saturates: an empty round gives the most runs)
            ((AUTO_SECONDS / round) as usize).clamp(AUTO_RUNS.0, AUTO_RUNS.1)
        });
        for run in 0..runs {
            let turn: Vec<usize> = if run % 2 == 0 {
                (0..ready.len()).collect()
            } else {
                (0..ready.len()).rev().collect()
            };
            for k in turn {
                let (i, o, acc, _, times, _) = &mut ready[k];
                times.push(render_seconds(&scenes[*i], o, acc).0);
            }
        }
        let mut ends = Vec::new();
        for (i, _, _, build, times, _) in ready {
            let m = median(times);
            cells[i].push(format!("{m:.3} ({build:.3})"));
            ends.push((i, m));
        }
        footer.push((runs, growth(&c.sizes, &ends)));
    }
    print!("| N |");
    for a in &c.accels {
        print!(" {} |", a.name());
    }
    println!(" rays |");
    print!("|---:|");
    for _ in &c.accels {
        print!("---:|");
    }
    println!("---:|");
    for ((n, row), rays) in c.sizes.iter().zip(cells).zip(rays) {
        println!("| {n} | {} | {rays} |", row.join(" | "));
    }
    print!("| growth |");
    for (_, g) in &footer {
        print!(" {g} |");
    }
    println!(" |");
    print!("| runs |");
    for (r, _) in &footer {
        print!(" {r} |");
    }
    println!(" |");
}

/// The growth down a column: the median render at the last size rendered over the one at the
/// first (`ends`: index into `sizes` and median, in the order of `sizes`), and the sizes it
/// spans when the column does not run from the first size to the last.
fn growth(sizes: &[usize], ends: &[(usize, f64)]) -> String {
    match (ends.first(), ends.last()) {
        (Some(&(i, a)), Some(&(j, b))) if j != i => {
            let span = if j + 1 == sizes.len() && i == 0 {
                String::new()
            } else {
                format!(" (N = {} to {})", sizes[i], sizes[j])
            };
            format!("{:.2}×{span}", b / a)
        }
        _ => "–".to_string(),
    }
}
