//! A feeler ray towards each light.
//! The chapter's name, number and title are the syllabus's, reached from its
//! [`Chapter`]; its README is under `chapters/`, its page in the course book.

#![deny(missing_docs)]

use whitted::render::Chapter;

/// What `--help` says the binary does, after the chapter's number and title.
const ABOUT: &str = "chapter 3's shading, where each light first sends a feeler ray S(u) = P + (L − P)·u from \
    the hit point; an opaque object with u ∈ ]0, 1] leaves the point with ambient light \
    only, a translucent one lets its transmission share through";

fn main() -> std::process::ExitCode {
    whitted_app::cli::main(Chapter::Shadows, ABOUT)
}
