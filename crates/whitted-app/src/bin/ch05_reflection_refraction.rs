//! The complete Whitted renderer.
//! The chapter's name, number and title are the syllabus's, reached from its
//! [`Chapter`]; its README is under `chapters/`, its page in the course book.

#![deny(missing_docs)]

use whitted::render::Chapter;

/// What `--help` says the binary does, after the chapter's number and title.
const ABOUT: &str = "the complete renderer, I = I_a + I_d + I_s + I_l + I_r. Mirror materials spawn reflected \
    rays l = d − 2(d·n)n, translucent ones transmitted rays by Snell's law (with total \
    internal reflection), recursively up to --max-depth";

fn main() -> std::process::ExitCode {
    whitted_app::cli::main(Chapter::ReflectionRefraction, ABOUT)
}
