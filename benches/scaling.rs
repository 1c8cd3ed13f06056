//! The scaling benchmark: renders N random spheres over a plane (the `scatter` scene) at
//! 1280×720 with every `--accel`, and prints the median build and render times.
//!
//! ```text
//! cargo bench --bench scaling                               # N = 10 … 100 000, 3 runs each
//! cargo bench --bench scaling -- --sizes 10,1000 --runs 5 --budget 30
//! cargo bench --bench scaling -- --fog                      # the fog layout
//! cargo bench --bench scaling -- --eye 0,6,4                # a close-up (see below)
//! ```
//!
//! `--eye X,Y,Z` moves the camera (the scenes put it at 0,9,17, looking at the origin over the
//! whole field). From 0,6,4 it looks down on a patch about the size of the N = 10 field, so
//! the picture stays alike as the field grows around it: what is left of the growth is the
//! structures' own.
//!
//! A combination whose render is predicted (linearly from the previous size) to take longer
//! than `--budget` seconds is skipped and shown with its estimate.

use std::time::Instant;

use whitted::accel::{Accel, scatter};
use whitted::render::{self, Options, Stage};
use whitted::scene::parse;

struct Config {
    sizes: Vec<usize>,
    runs: usize,
    budget: f64,
    width: u32,
    height: u32,
    accels: Vec<Accel>,
    layout: scatter::Layout,
    eye: Option<[f64; 3]>,
}

fn parse_args() -> Result<Config, String> {
    let mut c = Config {
        sizes: vec![10, 100, 1_000, 10_000, 100_000],
        runs: 3,
        budget: 20.0,
        width: 1280,
        height: 720,
        accels: Accel::ALL.to_vec(),
        layout: scatter::Layout::Field,
        eye: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| args.next().ok_or(format!("{name} needs a value"));
        match a.as_str() {
            "--bench" => {} // passed by `cargo bench`
            "--sizes" => {
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
            "--runs" => c.runs = value("--runs")?.parse().map_err(|_| "bad --runs")?,
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
            other => return Err(format!("unknown argument `{other}`")),
        }
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

fn main() {
    let c = match parse_args() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    println!(
        "scaling ({:?} layout{}): {}×{}, {} run(s) each, {} thread(s), {}; median seconds, render (build)",
        c.layout,
        c.eye
            .map(|[x, y, z]| format!(", eye {x},{y},{z}"))
            .unwrap_or_default(),
        c.width,
        c.height,
        c.runs,
        rayon::current_num_threads(),
        whitted::real::PRECISION
    );
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
    let mut last: Vec<Option<(usize, f64)>> = vec![None; c.accels.len()];
    for &n in &c.sizes {
        let mut scene = parse(
            &scatter::scene_toml_with(n, 1, c.width, c.height, c.layout),
            "scatter.toml",
        )
        .expect("the scatter scene parses");
        if let Some([x, y, z]) = c.eye {
            scene.camera.eye = whitted::real::vec3(x, y, z);
        }
        print!("| {n} |");
        let mut rays = 0;
        for (k, &accel) in c.accels.iter().enumerate() {
            if let Some((n0, t0)) = last[k] {
                // brute force and lists grow linearly; hierarchies are not skipped on a guess
                let linear = matches!(accel, Accel::None | Accel::Boxes | Accel::Extents);
                let estimate = if linear {
                    t0 * n as f64 / n0 as f64
                } else {
                    t0
                };
                if estimate > c.budget {
                    print!(" skipped (≈{estimate:.0} s) |");
                    continue;
                }
            }
            let mut o = Options::for_scene(&scene, Stage::ReflectionRefraction);
            o.width = c.width;
            o.height = c.height;
            o.accel = accel;
            let (mut builds, mut renders) = (Vec::new(), Vec::new());
            for _ in 0..c.runs {
                let start = Instant::now();
                let acc = render::build_accel(&scene, &o);
                builds.push(start.elapsed().as_secs_f64());
                let start = Instant::now();
                let (_, stats) = render::render_with(&scene, &o, &acc, &|_| {});
                renders.push(start.elapsed().as_secs_f64());
                rays = stats.total();
            }
            let (b, r) = (median(builds), median(renders));
            last[k] = Some((n, r));
            print!(" {r:.3} ({b:.3}) |");
            use std::io::Write;
            let _ = std::io::stdout().flush();
        }
        println!(" {rays} |");
    }
}
