//! `--against TREES.json`: the pixels of a reference's trees (chapters/chNN_name/trees.json)
//! traced with this code and the settings the file records, and for each pixel whose tree
//! differs, the first quantity that does and the functions that computed it.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::Path;
use std::time::Instant;

use whitted::error::Error;
use whitted::render::Options;
use whitted::render::inspect::against::TreeFile;
use whitted::scene::Scene;

use super::args::Common;
use super::stdout::print_out;

/// `--against TREES.json`: each pixel of the file traced with this code and compared with the
/// reference's tree. In text, a line for each pixel that differs and one that sums up; in JSON
/// (`--json`), a line for every pixel. Returns how many pixels were traced, and in how many
/// seconds.
pub fn print_against(
    scene: &Scene,
    options: &Options,
    trees: &TreeFile,
    common: &Common,
) -> Result<(usize, f64), Error> {
    let start = Instant::now();
    let compared = trees.against(scene, options)?;
    let seconds = start.elapsed().as_secs_f64();
    let mut text = String::new();
    for c in &compared {
        if common.json {
            text += &serde_json::to_string(&c.to_line())
                .map_err(|e| Error::Usage(format!("cannot write the comparison as JSON: {e}")))?;
            text.push('\n');
        } else if c.difference.is_some() {
            text += &c.line();
            text.push('\n');
        }
    }
    if !common.json {
        let differ = compared.iter().filter(|c| c.difference.is_some()).count();
        let file = common.against.as_deref().unwrap_or(Path::new("")).display();
        text += &match differ {
            0 => format!(
                "against: the {} pixels' trees are the reference's ({file})\n",
                compared.len()
            ),
            n => format!(
                "against: {n} of {} pixels' trees differ from the reference's ({file})\n",
                compared.len()
            ),
        };
    }
    print_out(&text)?;
    Ok((compared.len(), seconds))
}
