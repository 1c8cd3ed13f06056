//! The nearest hit of each camera ray.
//! The chapter's name, number and title are the syllabus's, reached from its
//! [`Chapter`]; its README is under `chapters/`, its page in the course book.

#![deny(missing_docs)]

use whitted::render::Chapter;

/// What `--help` says the binary does, after the chapter's number and title.
const ABOUT: &str = "intersects each camera ray with the scene's spheres, planes, cylinders, cones and convex \
    polyhedra (each a generic shape placed by a matrix M), keeps the nearest hit and shows \
    it unlit: its material's flat colour, its normal, or its depth";

fn main() -> std::process::ExitCode {
    whitted_app::cli::main(Chapter::GenericObjects, ABOUT)
}
