//! `scatter N [--seed S] [-o scene.toml]`: writes the scaling scene of N random spheres over a
//! plane (see `whitted::scene::scatter`), to a file or to stdout.

#![deny(missing_docs)]

use std::process::ExitCode;

use whitted::scene::scatter;

/// Writes a scene of N random spheres over a plane, for measuring how rendering time grows
/// with the number of objects under each `--accel`.
#[derive(clap::Parser)]
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
    #[arg(long, value_parser = whitted_app::cli::choice::<scatter::Layout>(), default_value = scatter::Layout::Field.name())]
    layout: scatter::Layout,
    /// Write the scene for POV-Ray 3.7 instead of whitted (for `benches/povray/scaling.sh`);
    /// `--width` and `--height` then go on POV-Ray's command line (+W, +H).
    #[arg(long)]
    pov: bool,
    /// Where to write the scene [default: stdout].
    #[arg(short, long, value_name = "SCENE.toml")]
    output: Option<std::path::PathBuf>,
}

fn main() -> ExitCode {
    let a: Args = whitted_app::cli::parse_args();
    let text = if a.pov {
        scatter::scene_pov(a.n as usize, a.seed, a.layout)
    } else {
        scatter::scene_toml_with(a.n as usize, a.seed, a.width, a.height, a.layout)
    };
    match &a.output {
        Some(path) => match whitted::output::write_file(path, text.as_bytes()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        },
        None => {
            print!("{text}");
            ExitCode::SUCCESS
        }
    }
}
