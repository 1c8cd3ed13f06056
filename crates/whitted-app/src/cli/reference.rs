//! `--compare REF.png`: the reference image a render is compared with, read before any work
//! starts. [`Reference::check`] refuses a render of another size and an output that would
//! replace the reference; [`Reference::write_comparison`] writes the render, the reference and
//! their difference side by side ([`crate::compare`]). The window compares with it too.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::{Path, PathBuf};

use whitted::error::Error;
use whitted::output::{self, Encoding};
use whitted::render;

use crate::compare::{self, Image};

/// The reference image of `--compare`, and the path it was read from.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The file, as the command line named it.
    pub path: PathBuf,
    /// Its pixels.
    pub image: Image,
}

impl Reference {
    /// The reference `--compare` names, read; `None` without one.
    pub fn of(path: Option<&Path>) -> Result<Option<Self>, Error> {
        match path {
            Some(path) => Ok(Some(Self {
                image: Image::read_reference(path)?,
                path: path.to_path_buf(),
            })),
            None => Ok(None),
        }
    }

    /// Checks, before any rendering, that a render of `size` can be compared with the
    /// reference and written to `out`: the sizes agree, and `out` is not the reference itself.
    pub fn check(&self, out: &Path, size: (u32, u32)) -> Result<(), Error> {
        if self.image.size() != size {
            let sizes = compare::SizeMismatch {
                render: size,
                reference: self.image.size(),
            };
            return Err(compare::size_error(&self.path, sizes));
        }
        let same = |a: &Path, b: &Path| matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y);
        if same(out, &self.path) {
            return Err(Error::Usage(format!(
                "-o {} is the reference itself: the comparison would replace it; write it elsewhere",
                out.display()
            )));
        }
        Ok(())
    }

    /// Compares the render `fb`, in `encoding`, with the reference, writes the three images
    /// side by side to `out` ([`compare::side_by_side`]: the render, the reference, the
    /// difference) and returns the line that says how they differ ([`compare::Comparison::line`]).
    pub fn write_comparison(
        &self,
        fb: &render::Framebuffer,
        encoding: Encoding,
        out: &Path,
    ) -> Result<String, Error> {
        let render = Image::from_framebuffer(fb, encoding);
        let c = compare::compare(&render, &self.image)
            .map_err(|sizes| compare::size_error(&self.path, sizes))?;
        let composite = compare::side_by_side(&[&render, &self.image, &c.difference]);
        output::write_png(out, composite.width, composite.height, &composite.rgb)?;
        Ok(c.line())
    }
}
