//! Which of its modes a chapter binary runs, read from its arguments before any scene is: print
//! one pixel's tree, print a grid of trees, trace a reference's trees, open the window, or
//! render a PNG. The switches that do not go together are refused here, and the reference's
//! trees of `--against` are read here, so that a bad file is reported before the scene is read.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use whitted::error::Error;
use whitted::render::inspect::against::TreeFile;

use super::parse::ChapterArgs;

/// What a run does.
pub enum Mode {
    /// `--inspect X,Y`: print the ray tree of pixel (X, Y).
    Inspect((u32, u32)),
    /// `--inspect-grid STEP`: print the trees of every STEP-th pixel of every STEP-th row.
    Grid(u32),
    /// `--against TREES.json` without `-o` or `--compare`: trace the file's pixels and print
    /// how their trees differ from the reference's; no image.
    Against(TreeFile),
    /// `--window`: the live window.
    Window,
    /// Render a PNG (with `--compare`, beside the reference); then, with `--against`, trace
    /// the reference's trees as [`Mode::Against`] does.
    Png(Option<TreeFile>),
}

impl Mode {
    /// The mode `args` ask for, or the error of switches that do not go together or of a
    /// `--against` file that cannot be read.
    pub fn of(args: &ChapterArgs) -> Result<Self, Error> {
        let common = &args.common;
        let inspect = args.objects.as_ref().and_then(|o| o.inspect);
        if common.window && inspect.is_some() {
            return Err(Error::Usage(
                "--window and --inspect do not go together: click a pixel in the window to inspect it"
                    .into(),
            ));
        }
        if common.json && inspect.is_none() && common.against.is_none() {
            return Err(Error::Usage(
                "--json goes with --inspect X,Y or --against TREES.json: it says how they print"
                    .into(),
            ));
        }
        let against = match &common.against {
            Some(path) => Some(TreeFile::read(path)?),
            None => None,
        };
        // an image is written unless the run only prints trees
        let image = common.output.is_some() || common.compare.is_some();
        Ok(match (inspect, common.inspect_grid, against) {
            (Some(pixel), _, _) => Mode::Inspect(pixel),
            (None, Some(step), _) => Mode::Grid(step),
            (None, None, Some(trees)) if !image => Mode::Against(trees),
            // clap keeps --window apart from --against
            (None, None, _) if common.window => Mode::Window,
            (None, None, trees) => Mode::Png(trees),
        })
    }

    /// Whether the mode writes an image (the window's on its save key): the destination is
    /// checked before the scene is read.
    #[must_use]
    pub fn writes_image(&self) -> bool {
        matches!(self, Mode::Window | Mode::Png(_))
    }
}
