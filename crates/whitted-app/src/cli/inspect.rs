//! The ray trees on stdout: `--inspect X,Y` prints one pixel's (as text, or JSON with
//! `--json`), and the hidden `--inspect-grid STEP` prints a grid of them as JSON lines after a
//! line with the settings they were traced with (`whitted trees` reads them).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use whitted::error::Error;
use whitted::output::Encoding;
use whitted::render::inspect::against;
use whitted::render::inspect::tree::GridHeader;
use whitted::render::{self, Options};
use whitted::scene::Scene;

use super::stdout::print_out;

/// `--inspect X,Y [--json]`: prints the ray tree of one pixel on stdout, its bytes in
/// `encoding` (those the PNG would hold).
pub fn print_tree(
    scene: &Scene,
    options: &Options,
    (x, y): (u32, u32),
    encoding: Encoding,
    json: bool,
) -> Result<(), Error> {
    let (w, h) = (options.width, options.height);
    if x >= w || y >= h {
        return Err(Error::Usage(format!(
            "--inspect {x},{y}: the pixel is outside the {w}×{h} image (X from 0 to {}, Y from 0 to {})",
            w - 1,
            h - 1
        )));
    }
    let mut tree = render::Tracer::new(scene, options).inspect(x, y);
    tree.encoding = encoding;
    let text = if json {
        let json = serde_json::to_string_pretty(&tree.to_json())
            .map_err(|e| Error::Usage(format!("cannot write the tree as JSON: {e}")))?;
        json + "\n"
    } else {
        tree.to_string()
    };
    print_out(&text)
}

/// `--inspect-grid STEP`: the settings as one JSON line, then the ray tree of every STEP-th
/// pixel of every STEP-th row (from STEP/2), one JSON line each.
pub fn print_grid(scene: &Scene, options: &Options, step: u32) -> Result<(), Error> {
    let tracer = render::Tracer::new(scene, options);
    let header = GridHeader {
        version: against::FILE_VERSION,
        settings: against::settings_of(options),
    };
    let header = serde_json::to_string(&header)
        .map_err(|e| Error::Usage(format!("cannot write the settings as JSON: {e}")))?;
    let mut text = format!("{header}\n");
    for y in (step / 2..options.height).step_by(step as usize) {
        for x in (step / 2..options.width).step_by(step as usize) {
            text += &tracer.inspect(x, y).to_json().to_string();
            text.push('\n');
        }
    }
    print_out(&text)
}
