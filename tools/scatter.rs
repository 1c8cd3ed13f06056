//! `scatter N [--seed S] [-o scene.toml]`: writes the scaling scene of N random spheres over a
//! plane (see `whitted::accel::scatter`), to a file or to stdout.

use std::process::ExitCode;

use clap::Parser;
use whitted::accel::scatter;

/// Writes a scene of N random spheres over a plane, for measuring how rendering time grows
/// with the number of objects under each `--accel`.
#[derive(Parser)]
#[command(name = "scatter", version)]
struct Args {
    /// Number of spheres.
    #[arg(value_parser = clap::value_parser!(u32).range(1..=10_000_000))]
    n: u32,
    /// Seed of the positions: the same N and seed give the same scene.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Image width written into the scene.
    #[arg(long, default_value_t = 1280, value_parser = clap::value_parser!(u32).range(1..=65_535))]
    width: u32,
    /// Image height written into the scene.
    #[arg(long, default_value_t = 720, value_parser = clap::value_parser!(u32).range(1..=65_535))]
    height: u32,
    /// How the spheres are spread: a field growing with N, or a fog of shrinking spheres.
    #[arg(long, value_enum, default_value_t = scatter::Layout::Field)]
    layout: scatter::Layout,
    /// Where to write the scene [default: stdout].
    #[arg(short, long, value_name = "SCENE.toml")]
    output: Option<std::path::PathBuf>,
}

fn main() -> ExitCode {
    let a = Args::parse();
    let text = scatter::scene_toml_with(a.n as usize, a.seed, a.width, a.height, a.layout);
    match &a.output {
        Some(path) => match std::fs::write(path, text) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: cannot write {}: {e}", path.display());
                ExitCode::from(2)
            }
        },
        None => {
            print!("{text}");
            ExitCode::SUCCESS
        }
    }
}
