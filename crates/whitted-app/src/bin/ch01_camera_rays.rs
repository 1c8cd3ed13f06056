//! One ray per pixel, coloured by its direction (d̂ + 1)/2.
//! The chapter's name, number and title are the syllabus's, reached from its
//! [`Chapter`]; its README is under `chapters/`, its page in the course book.

#![deny(missing_docs)]

use whitted::render::Chapter;

/// What `--help` says the binary does, after the chapter's number and title.
const ABOUT: &str = "builds the viewing coordinates and the near plane from the scene's camera and shoots one \
    ray through each pixel centre. Each pixel shows its ray's direction as a colour: red = \
    x, green = y, blue = z, each mapped from [−1, 1] to [0, 1]";

fn main() -> std::process::ExitCode {
    whitted_app::cli::main(Chapter::CameraRays, ABOUT)
}
