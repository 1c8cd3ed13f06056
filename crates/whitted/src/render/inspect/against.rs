//! Two ray trees of one pixel side by side: the first number where one computation parts from
//! another (`--against TREES.json`, and `cargo learn`).
//!
//! The reference's trees at a few pixels of each chapter scene ship with a handout as data
//! (`chapters/chNN_name/trees.json`, written by `whitted trees`: a
//! `whitted_syllabus::tree::TreeFile`). A chapter binary given `--against` reads it
//! ([`TreeFile`]), traces the same pixels with the student's code and the settings the file
//! records ([`Settings`]), and walks each pair of trees in the road's order
//! ([`first_difference`], in [`super::walk`]) to the first quantity that differs beyond its
//! tolerance: a [`Difference`] names the pixel, the path to the node, the quantity in the
//! notes' symbols, both values, and the functions that computed it ([`super::provenance`]).
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::Path;

use whitted_syllabus::tree::{Against, Document, Parting, Plain};

use super::super::Options;
use super::super::tracer::{EveryObject, Tracer};
pub use super::difference::{Difference, Step};
pub use super::tree::{FILE_VERSION, Settings};
pub use super::walk::first_difference;
use crate::error::Error;
use crate::offset::{Offset, OffsetKind};
use crate::scene::Scene;

/// The settings of a render with `options`, as a trees file records them.
#[must_use]
pub fn settings_of(options: &Options) -> Settings {
    let offset = OffsetKind::ALL
        .into_iter()
        .find(|k| k.offset() == options.offset)
        .unwrap_or(match options.offset {
            Offset::Fixed(_) => OffsetKind::Fixed,
            Offset::Scaled(_) => OffsetKind::Scaled,
            Offset::ErrorBound => OffsetKind::ErrorBound,
        });
    Settings {
        chapter: options.chapter,
        view: options.view,
        width: options.width,
        height: options.height,
        samples: options.samples,
        max_depth: options.max_depth,
        min_weight: options.min_weight,
        numerics: options.numerics,
        offset,
        seed: options.seed,
    }
}

/// `options` with `settings`.
#[must_use]
pub fn apply(settings: &Settings, options: &Options) -> Options {
    Options {
        chapter: settings.chapter,
        view: settings.view,
        width: settings.width,
        height: settings.height,
        samples: settings.samples,
        max_depth: settings.max_depth,
        min_weight: settings.min_weight,
        numerics: settings.numerics,
        offset: settings.offset.offset(),
        seed: settings.seed,
        ..options.clone()
    }
}

/// A trees file as `--against` reads it: the settings in the renderer's kinds, the trees as
/// plain types (a file written by an f64 build is read alike by an f32 one).
#[derive(Clone, Debug)]
pub struct TreeFile {
    /// What the trees were traced with.
    pub settings: Settings,
    /// Each pixel's tree, as `--inspect X,Y --json` writes it, in the order they are compared.
    pub trees: Vec<Document<Plain>>,
}

impl TreeFile {
    /// Reads a trees file; the error names the file.
    pub fn read(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(&text).map_err(|why| Error::Usage(format!("{}: {why}", path.display())))
    }

    /// Reads the text of a trees file.
    pub fn parse(text: &str) -> Result<Self, String> {
        let file = whitted_syllabus::tree::TreeFile::<Plain>::parse(text)?;
        // the plain settings name the renderer's chapter, view, numerics and offset
        let settings = serde_json::to_value(&file.settings)
            .and_then(serde_json::from_value)
            .map_err(|e| format!("settings: {e}"))?;
        Ok(Self {
            settings,
            trees: file.pixels.into_iter().map(|p| p.tree).collect(),
        })
    }

    /// Traces each pixel of the file with `scene` and the file's settings (over `options`),
    /// and compares the tree with the reference's: each pixel with its first difference, if
    /// any. The chapter followed is the file's, which must not come after `options`'.
    pub fn against(&self, scene: &Scene, options: &Options) -> Result<Vec<Compared>, Error> {
        if self.settings.chapter > options.chapter {
            return Err(Error::Usage(format!(
                "--against: the trees are chapter {}'s, which `{}` does not trace: run `{}`",
                self.settings.chapter.number(),
                options.chapter.about().binary,
                self.settings.chapter.about().binary
            )));
        }
        let options = apply(&self.settings, options);
        let every = EveryObject {
            scene,
            numerics: options.numerics,
        };
        let tracer = Tracer::with_query(scene, &options, every);
        let shape_of = |i: usize| scene.objects.get(i).map(|o| o.shape.name());
        self.trees
            .iter()
            .map(|reference| {
                let (x, y) = reference.tree.pixel;
                let mine = tracer.inspect(x, y).plain().map_err(|e| {
                    Error::Usage(format!(
                        "--against: the tree of ({x}, {y}) reads back wrong: {e}"
                    ))
                })?;
                Ok(Compared {
                    pixel: (x, y),
                    difference: first_difference(&mine.tree, &reference.tree, &shape_of),
                })
            })
            .collect()
    }
}

/// One pixel of a trees file, traced and compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Compared {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// Where its tree first parts from the reference's; `None` when they agree.
    pub difference: Option<Difference>,
}

impl Compared {
    /// The line `--against` prints for the pixel.
    #[must_use]
    pub fn line(&self) -> String {
        let (x, y) = self.pixel;
        match &self.difference {
            None => format!("against: pixel ({x}, {y}): the reference's tree"),
            Some(d) => {
                let by = if d.functions.is_empty() {
                    String::new()
                } else {
                    format!("; computed by {}", d.functions.join(", "))
                };
                format!("against: pixel ({x}, {y}), {}{by}", d.text())
            }
        }
    }

    /// The same as `--against … --json` prints it (`docs/src/inspect.md`): the pixel, whether
    /// it differs, and where (the path and its node kinds, the quantity's key and symbol, both
    /// values as shown, the functions, and the line of text).
    #[must_use]
    pub fn to_line(&self) -> Against {
        let (x, y) = self.pixel;
        Against {
            pixel: self.pixel,
            differs: self.difference.is_some(),
            first: self.difference.as_ref().map(|d| Parting {
                path: d.path.iter().map(|s| s.label.clone()).collect(),
                nodes: d.path.iter().map(|s| s.kind.to_string()).collect(),
                quantity: d.quantity.key().to_string(),
                symbol: d.symbol.to_string(),
                computed: d.computed.clone(),
                reference: d.reference.clone(),
                functions: d.functions.iter().map(|f| f.to_string()).collect(),
                text: format!("pixel ({x}, {y}), {}", d.text()),
            }),
        }
    }
}
