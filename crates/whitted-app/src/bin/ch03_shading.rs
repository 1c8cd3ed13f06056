//! Ambient, diffuse and specular (Phong) light from every light source.
//! The chapter's name, number and title are the syllabus's, reached from its
//! [`Chapter`]; its README is under `chapters/`, its page in the course book.

#![deny(missing_docs)]

use whitted::render::Chapter;

/// What `--help` says the binary does, after the chapter's number and title.
const ABOUT: &str = "shades the nearest hit with the notes' Phong model, I = ρa·I_m + Σ I_p/(a0 + a1·d + \
    a2·d²)·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f), per RGB channel, for every light. No shadows \
    yet: every light reaches every point";

fn main() -> std::process::ExitCode {
    whitted_app::cli::main(Chapter::Shading, ABOUT)
}
