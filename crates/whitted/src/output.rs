//! Writing images: linear RGB → 8-bit PNG, sRGB-encoded by default, atomically.
//!
//! The framebuffer holds linear intensities, the notes' I: twice the light is twice the
//! number. Screens and image viewers do not read a PNG's bytes that way: they assume the
//! bytes are sRGB-encoded (IEC 61966-2-1), a curve that spends more of the 256 steps on dark
//! values, where the eye tells them apart best. Written as bytes directly, linear values look
//! too dark: 0.5 becomes 128, which a viewer shows as about a fifth of full light, not half.
//! (POV-Ray, whose default output is gamma-corrected, gives brighter images of the same scene
//! for the same reason.) So [`save`] encodes each channel with the sRGB transfer function by
//! default, and 0.5 becomes 188:
//!
//! ```text
//! V = 12.92·I                      for I ≤ 0.0031308
//! V = 1.055·I^(1/2.4) − 0.055      otherwise            byte = round(255·V), I clamped to [0, 1]
//! ```
//!
//! [`Encoding::Linear`] (`--encoding linear`) writes the intensities as they are (clamped to
//! [0, 1], times 255, rounded: [`to_byte`]). Either way the encoding happens only here, on the
//! way out: the renderer, the framebuffer and the tests of values all work with linear
//! intensities, and the golden images the tests compare with are linear bytes.
//!
//! The PNG is first written to a temporary file in the destination directory and then renamed
//! over the destination, so an interrupted run never leaves a truncated image behind.
//!
//! Course book: [Chapter 3, shading](../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use std::io::{BufWriter, Write};
use std::path::Path;

use rayon::prelude::*;

use crate::error::Error;
use crate::render::Framebuffer;

pub use crate::render::framebuffer::{Encoding, to_byte};

/// The framebuffer as RGB bytes in `encoding`, row by row from the top (converted in parallel
/// chunks: on a large image this is otherwise the slowest serial step after the render).
#[must_use]
pub fn to_rgb8(fb: &Framebuffer, encoding: Encoding) -> Vec<u8> {
    const CHUNK: usize = 4096;
    let mut out = vec![0u8; fb.pixels.len() * 3];
    out.par_chunks_mut(3 * CHUNK)
        .zip(fb.pixels.par_chunks(CHUNK))
        .for_each(|(bytes, pixels)| {
            // written out channel by channel: `to_array().map(…)` costs 25 instructions a byte
            for (b, p) in bytes.chunks_exact_mut(3).zip(pixels) {
                b[0] = encoding.byte(p.x);
                b[1] = encoding.byte(p.y);
                b[2] = encoding.byte(p.z);
            }
        });
    out
}

/// Checks, before any rendering, that `path` can receive a PNG: it ends in `.png` and its
/// directory exists.
pub fn check_destination(path: &Path) -> Result<(), Error> {
    let fail = |message: &str| Error::Write {
        path: path.to_path_buf(),
        message: message.into(),
    };
    let is_png = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        return Err(fail(
            "only PNG output is supported: the name must end in .png",
        ));
    }
    check_place(path)
}

/// Checks that `path` can be a new file: it is not a directory and its directory exists.
fn check_place(path: &Path) -> Result<(), Error> {
    let fail = |message: &str| Error::Write {
        path: path.to_path_buf(),
        message: message.into(),
    };
    if path.is_dir() {
        return Err(fail("it is a directory"));
    }
    if !parent_dir(path).is_dir() {
        return Err(fail("its directory does not exist"));
    }
    Ok(())
}

fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Writes `path` through a temporary file in the same directory (named `.whitted-*` and
/// ending in `suffix`), flushed to disk and then renamed into place: a reader sees the old
/// file or the whole new one, and a failure leaves the old one untouched.
fn write_atomically(
    path: &Path,
    suffix: &str,
    fill: impl FnOnce(&mut BufWriter<&std::fs::File>) -> Result<(), String>,
) -> Result<(), Error> {
    let fail = |message: String| Error::Write {
        path: path.to_path_buf(),
        message,
    };
    let tmp = tempfile::Builder::new()
        .prefix(".whitted-")
        .suffix(suffix)
        .tempfile_in(parent_dir(path))
        .map_err(|e| fail(e.to_string()))?;
    {
        let mut out = BufWriter::new(tmp.as_file());
        fill(&mut out).map_err(fail)?;
        out.flush().map_err(|e| fail(e.to_string()))?;
    }
    tmp.as_file().sync_all().map_err(|e| fail(e.to_string()))?;
    #[cfg(unix)]
    {
        // a temporary file is private (0600); the output should be as readable as any new file
        use std::os::unix::fs::PermissionsExt;
        let perms = std::fs::Permissions::from_mode(0o644);
        tmp.as_file()
            .set_permissions(perms)
            .map_err(|e| fail(e.to_string()))?;
    }
    tmp.persist(path).map_err(|e| fail(e.error.to_string()))?;
    Ok(())
}

/// Encodes RGB bytes as PNG into `path`, through a temporary file renamed into place.
pub fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> Result<(), Error> {
    write_atomically(path, ".png.part", |out| {
        let mut encoder = png::Encoder::new(out, width, height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        // fast deflate: the file is a little larger, the (serial) encoding several times quicker
        encoder.set_compression(png::Compression::Fast);
        encoder.set_filter(png::Filter::Adaptive);
        let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
        writer.write_image_data(rgb).map_err(|e| e.to_string())?;
        writer.finish().map_err(|e| e.to_string())
    })
}

/// Reads a PNG (any colour type or depth the format allows) as 8-bit RGB, row by row from the
/// top: its width, height and bytes. The tests compare renders with the golden images so.
pub fn read_png(path: &Path) -> Result<(u32, u32, Vec<u8>), Error> {
    let fail = |message: String| Error::Read {
        path: path.to_path_buf(),
        source: std::io::Error::other(message),
    };
    let (width, height, rgba) = whitted_syllabus::words::read_rgba(path).map_err(fail)?;
    let rgb = rgba
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    Ok((width, height, rgb))
}

/// Writes `bytes` (a scene file, a report) into `path`, through a temporary file renamed
/// into place.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    check_place(path)?;
    write_atomically(path, ".part", |out| {
        out.write_all(bytes).map_err(|e| e.to_string())
    })
}

/// Writes the framebuffer as a PNG in `encoding`, atomically.
pub fn save(fb: &Framebuffer, path: &Path, encoding: Encoding) -> Result<(), Error> {
    write_png(path, fb.width, fb.height, &to_rgb8(fb, encoding))
}
