//! The student's render beside a reference image, with the difference marked: what
//! `--compare REF.png` writes and prints, and what the window shows on its compare key.
//!
//! Two images of one size are compared pixel by pixel, in the bytes the PNG holds (sRGB by
//! default). A pixel *differs* when one of its channels is off by more than [`TOLERANCE`]
//! steps of 255, the tolerance the renderer's golden tests allow for rounding (`f32`, another
//! platform); a changed formula moves far more. [`compare`] counts those pixels, finds the
//! first in row order (x from the left, y from the top) and draws the [`Comparison::difference`]
//! image: the reference in dimmed grey, each differing pixel in a colour that stands out and
//! says how far it is off,
//!
//! ```text
//! off by 3 steps ─► yellow (255, 255, 0) … orange … red (255, 0, 0) ◄─ off by HOT (64) or more
//! the same        ─► grey (r + g + b)/6 of the reference: at most half as bright as white
//! ```
//!
//! so a rounding slip (yellow) is told from a wrong formula (red) at a glance.
//! [`side_by_side`] lays images out left to right with a black [`GAP`] between them: the
//! student's render, the reference, the difference. [`Comparison::line`] says it in one line
//! for people and for `cargo learn`:
//!
//! ```text
//! compare: 312 of 28800 pixels differ by more than 2/255 (1.08%), by up to 87/255; the first at (17, 40), where the render has (255, 0, 255) and the reference (0, 66, 12)
//! compare: the same as the reference (no pixel differs by more than 2/255)
//! ```
//!
//! Course book: [The live window](../../../../docs/book/window.html) (`docs/src/window.md`).

use std::path::Path;

use whitted::error::Error;
use whitted::output::Encoding;
use whitted::render::Framebuffer;

/// The largest difference of a channel, in steps of 255, that still counts as the same (the
/// golden tests' `MAX_DIFF`).
pub const TOLERANCE: u8 = 2;

/// A pixel off by this many steps or more is marked full red; one off by `TOLERANCE + 1` is
/// yellow, and the colours between go through orange.
pub const HOT: u8 = 64;

/// The width in pixels of the black band between two images of [`side_by_side`].
pub const GAP: u32 = 4;

/// An 8-bit RGB image, row by row from the top, three bytes a pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The bytes: `3 × width × height` of them.
    pub rgb: Vec<u8>,
}

impl Image {
    /// An image of `width` × `height` pixels holding `rgb`; `None` unless `rgb` has three
    /// bytes for each pixel.
    #[must_use]
    pub fn new(width: u32, height: u32, rgb: Vec<u8>) -> Option<Self> {
        (rgb.len() == 3 * width as usize * height as usize).then_some(Self { width, height, rgb })
    }

    /// Reads the reference image of `--compare` (any PNG; see [`whitted::output::read_png`]).
    pub fn read_reference(path: &Path) -> Result<Self, Error> {
        let unreadable = |reason: String| {
            Error::Usage(format!(
                "cannot read the reference {}: {reason}",
                path.display()
            ))
        };
        let (width, height, rgb) = whitted::output::read_png(path).map_err(|e| match e {
            Error::Read { source, .. } => unreadable(source.to_string()),
            other => unreadable(other.to_string()),
        })?;
        Self::new(width, height, rgb).ok_or_else(|| unreadable("its pixels do not fill it".into()))
    }

    /// The framebuffer's pixels as the PNG written in `encoding` holds them.
    #[must_use]
    pub fn from_framebuffer(fb: &Framebuffer, encoding: Encoding) -> Self {
        Self {
            width: fb.width,
            height: fb.height,
            rgb: whitted::output::to_rgb8(fb, encoding),
        }
    }

    /// The size as (width, height).
    #[must_use]
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// The pixel at column `x`, row `y`.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y as usize * self.width as usize + x as usize);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// The pixels as a screen's `0x00RRGGBB` words, row by row.
    #[must_use]
    pub fn to_screen(&self) -> Vec<u32> {
        self.rgb
            .chunks_exact(3)
            .map(|p| (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]))
            .collect()
    }
}

/// How a render and its reference differ.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// The pixels a channel of which is off by more than [`TOLERANCE`].
    pub differing: usize,
    /// The pixels compared (width × height).
    pub pixels: usize,
    /// The first differing pixel in row order, (x, y) from the top left.
    pub first: Option<(u32, u32)>,
    /// The first differing pixel's bytes in the render and in the reference.
    pub first_bytes: Option<([u8; 3], [u8; 3])>,
    /// The largest difference of a channel over the whole image, in steps of 255.
    pub largest: u8,
    /// The reference in dimmed grey with each differing pixel marked ([`marked`]).
    pub difference: Image,
}

impl Comparison {
    /// Whether no pixel differs.
    #[must_use]
    pub fn same(&self) -> bool {
        self.differing == 0
    }

    /// The one line `--compare` prints (see the module's documentation).
    #[must_use]
    pub fn line(&self) -> String {
        let tol = TOLERANCE;
        match self.first {
            None => {
                format!(
                    "compare: the same as the reference (no pixel differs by more than {tol}/255)"
                )
            }
            Some((x, y)) => {
                let bytes = |c: [u8; 3]| format!("({}, {}, {})", c[0], c[1], c[2]);
                let values = self.first_bytes.map_or(String::new(), |(r, e)| {
                    format!(
                        ", where the render has {} and the reference {}",
                        bytes(r),
                        bytes(e)
                    )
                });
                format!(
                    "compare: {} of {} pixels differ by more than {tol}/255 ({}), by up to {}/255; the first at ({x}, {y}){values}",
                    self.differing,
                    self.pixels,
                    percent(self.differing, self.pixels),
                    self.largest
                )
            }
        }
    }

    /// The count in a few words, for the window's title: "312 of 28800 pixels differ by
    /// more than 2/255", or "no pixel differs by more than 2/255".
    #[must_use]
    pub fn count(&self) -> String {
        if self.same() {
            format!("no pixel differs by more than {TOLERANCE}/255")
        } else {
            format!(
                "{} of {} pixels differ by more than {TOLERANCE}/255",
                self.differing, self.pixels
            )
        }
    }
}

/// `part` of `whole` as a percentage with two decimals; a share that would round to zero
/// is written "under 0.01%", so that a few pixels never read as none.
fn percent(part: usize, whole: usize) -> String {
    let p = 100.0 * part as f64 / whole.max(1) as f64;
    if part > 0 && p < 0.005 {
        "under 0.01%".into()
    } else {
        format!("{p:.2}%")
    }
}

/// Two images of different sizes cannot be compared: the sizes, (width, height), of the
/// render and of the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizeMismatch {
    /// The render's size.
    pub render: (u32, u32),
    /// The reference's size.
    pub reference: (u32, u32),
}

/// Compares `render` with `reference` pixel by pixel (see the module's documentation).
pub fn compare(render: &Image, reference: &Image) -> Result<Comparison, SizeMismatch> {
    if render.size() != reference.size() {
        return Err(SizeMismatch {
            render: render.size(),
            reference: reference.size(),
        });
    }
    let width = render.width as usize;
    let mut differing = 0;
    let mut first = None;
    let mut first_bytes = None;
    let mut largest = 0;
    let mut rgb = Vec::with_capacity(reference.rgb.len());
    let pairs = render
        .rgb
        .chunks_exact(3)
        .zip(reference.rgb.chunks_exact(3));
    for (i, (r, e)) in pairs.enumerate() {
        let r = [r[0], r[1], r[2]];
        let e = [e[0], e[1], e[2]];
        let off = off_by(r, e);
        largest = largest.max(off);
        if off > TOLERANCE {
            differing += 1;
            if first.is_none() {
                first = Some(((i % width) as u32, (i / width) as u32));
                first_bytes = Some((r, e));
            }
        }
        rgb.extend_from_slice(&marked(r, e));
    }
    Ok(Comparison {
        differing,
        pixels: render.rgb.len() / 3,
        first,
        first_bytes,
        largest,
        difference: Image {
            width: reference.width,
            height: reference.height,
            rgb,
        },
    })
}

/// The largest difference of a channel between two pixels, in steps of 255.
#[must_use]
pub fn off_by(a: [u8; 3], b: [u8; 3]) -> u8 {
    (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)
}

/// The difference image's pixel for a render's pixel `render` and the reference's
/// `reference`: the reference's grey, (r + g + b)/6, when they are within [`TOLERANCE`];
/// otherwise yellow, (255, 255, 0), for a pixel off by `TOLERANCE + 1`, turning through orange
/// to red, (255, 0, 0), at [`HOT`] steps and beyond.
#[must_use]
pub fn marked(render: [u8; 3], reference: [u8; 3]) -> [u8; 3] {
    let off = off_by(render, reference);
    if off <= TOLERANCE {
        let sum: u32 = reference.iter().map(|&c| u32::from(c)).sum();
        let grey = (sum / 6) as u8;
        return [grey, grey, grey];
    }
    let (low, high) = (u32::from(TOLERANCE) + 1, u32::from(HOT));
    let toward_red = u32::from(off).min(high) - low;
    let green = 255 - 255 * toward_red / (high - low);
    [255, green as u8, 0]
}

/// The images left to right, top-aligned, with a black band [`GAP`] pixels wide between each
/// two; the composite is as tall as the tallest (black below a shorter one).
#[must_use]
pub fn side_by_side(images: &[&Image]) -> Image {
    let gaps = GAP * (images.len().max(1) as u32 - 1);
    let width = images.iter().map(|i| i.width).sum::<u32>() + gaps;
    let height = images.iter().map(|i| i.height).max().unwrap_or(0);
    let row = 3 * width as usize;
    let mut rgb = vec![0; row * height as usize];
    let mut left = 0;
    for image in images {
        let span = 3 * image.width as usize;
        for (y, src) in image.rgb.chunks_exact(span.max(1)).enumerate() {
            let start = y * row + 3 * left as usize;
            rgb[start..start + span].copy_from_slice(src);
        }
        left += image.width + GAP;
    }
    Image { width, height, rgb }
}

/// The error `--compare` gives for a reference of another size than the render: both sizes,
/// and how to render at the reference's.
#[must_use]
pub fn size_error(reference: &Path, sizes: SizeMismatch) -> Error {
    let (rw, rh) = sizes.reference;
    let (w, h) = sizes.render;
    Error::Usage(format!(
        "the reference {} is {rw}×{rh} but the render is {w}×{h}: render with the reference's size (--width {rw} --height {rh})",
        reference.display()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 2 image from its six pixels, row by row.
    fn image(pixels: [[u8; 3]; 6]) -> Image {
        Image::new(3, 2, pixels.concat()).unwrap()
    }

    const REFERENCE: [[u8; 3]; 6] = [
        [30, 60, 90],
        [100, 100, 100],
        [0, 0, 0],
        [200, 10, 10],
        [255, 255, 255],
        [12, 12, 12],
    ];

    /// The reference with pixel (1, 0) off by 3 in blue, (0, 1) by 2 in red (the same), and
    /// (2, 1) by 200 in green.
    fn render() -> Image {
        let mut p = REFERENCE;
        p[1][2] += 3;
        p[3][0] -= 2;
        p[5][1] += 200;
        image(p)
    }

    /// The count, the first pixel and the largest difference: two pixels differ, the one off
    /// by exactly the tolerance does not.
    #[test]
    fn the_count_and_the_first_differing_pixel() {
        let c = compare(&render(), &image(REFERENCE)).unwrap();
        assert_eq!((c.differing, c.pixels), (2, 6));
        assert_eq!(c.first, Some((1, 0)));
        assert_eq!(c.first_bytes, Some(([100, 100, 103], [100, 100, 100])));
        assert_eq!(c.largest, 200);
        assert!(!c.same());
    }

    /// A pixel 2 steps off in one channel is the same; 3 steps off, it differs.
    #[test]
    fn the_tolerance_edge_is_two_steps() {
        let base = Image::new(1, 1, vec![100, 100, 100]).unwrap();
        for (step, differs) in [(2u8, false), (3, true)] {
            for channel in 0..3 {
                for sign in [1i16, -1] {
                    let mut rgb = vec![100u8; 3];
                    rgb[channel] = (100 + sign * i16::from(step)) as u8;
                    let other = Image::new(1, 1, rgb).unwrap();
                    let c = compare(&other, &base).unwrap();
                    assert_eq!(
                        c.differing,
                        usize::from(differs),
                        "{step} steps in channel {channel}, sign {sign}: {c:?}"
                    );
                    assert_eq!(c.first.is_some(), differs);
                }
            }
        }
    }

    /// The difference image: the reference's grey where the pixels agree, yellow at 3 steps,
    /// red at HOT steps and beyond.
    #[test]
    fn the_difference_image_has_the_stated_colours() {
        let c = compare(&render(), &image(REFERENCE)).unwrap();
        let d = &c.difference;
        assert_eq!(d.size(), (3, 2));
        assert_eq!(d.pixel(0, 0), [30, 30, 30], "(30 + 60 + 90)/6");
        assert_eq!(d.pixel(1, 0), [255, 255, 0], "3 steps off: yellow");
        assert_eq!(d.pixel(2, 0), [0, 0, 0]);
        assert_eq!(
            d.pixel(0, 1),
            [36, 36, 36],
            "2 steps off is the same: (220)/6"
        );
        assert_eq!(d.pixel(1, 1), [127, 127, 127], "white dimmed to 765/6");
        assert_eq!(d.pixel(2, 1), [255, 0, 0], "200 steps off: red");
    }

    /// Between yellow and red the green falls evenly with the difference.
    #[test]
    fn the_marks_turn_from_yellow_to_red() {
        let at = |off: u8| marked([off, 0, 0], [0, 0, 0]);
        assert_eq!(at(3), [255, 255, 0]);
        // 60 of the 61 steps from yellow to red: green 255 − 255·60/61 = 5
        assert_eq!(at(HOT - 1), [255, 5, 0]);
        assert_eq!(at(HOT), [255, 0, 0]);
        assert_eq!(at(255), [255, 0, 0]);
        // (33 − 3)/(64 − 3) of the way: green 255 − 255·30/61 = 130
        assert_eq!(at(33), [255, 130, 0]);
    }

    /// Images of other sizes are not compared: both sizes are reported.
    #[test]
    fn images_of_other_sizes_are_refused() {
        let small = Image::new(1, 1, vec![0; 3]).unwrap();
        assert_eq!(
            compare(&small, &image(REFERENCE)),
            Err(SizeMismatch {
                render: (1, 1),
                reference: (3, 2)
            })
        );
        let e = size_error(
            Path::new("ref.png"),
            compare(&small, &image(REFERENCE)).unwrap_err(),
        );
        assert_eq!(
            e.to_string(),
            "the reference ref.png is 3×2 but the render is 1×1: render with the reference's size (--width 3 --height 2)"
        );
    }

    /// The composite: the three images left to right, black bands of GAP pixels between.
    #[test]
    fn side_by_side_lays_out_left_to_right_with_gaps() {
        let a = image(REFERENCE);
        let b = render();
        let c = compare(&b, &a).unwrap().difference;
        let all = side_by_side(&[&b, &a, &c]);
        assert_eq!(all.size(), (3 * 3 + 2 * GAP, 2));
        for y in 0..2 {
            for x in 0..3 {
                assert_eq!(all.pixel(x, y), b.pixel(x, y), "render at ({x}, {y})");
                assert_eq!(all.pixel(3 + GAP + x, y), a.pixel(x, y), "reference");
                assert_eq!(all.pixel(6 + 2 * GAP + x, y), c.pixel(x, y), "difference");
            }
            for g in 0..GAP {
                assert_eq!(all.pixel(3 + g, y), [0, 0, 0], "first gap");
                assert_eq!(all.pixel(6 + GAP + g, y), [0, 0, 0], "second gap");
            }
        }
        // a shorter image is padded below with black
        let short = Image::new(1, 1, vec![9, 9, 9]).unwrap();
        let padded = side_by_side(&[&short, &a]);
        assert_eq!(padded.size(), (1 + GAP + 3, 2));
        assert_eq!(padded.pixel(0, 0), [9, 9, 9]);
        assert_eq!(padded.pixel(0, 1), [0, 0, 0]);
        assert_eq!(padded.pixel(1 + GAP + 2, 1), a.pixel(2, 1));
    }

    /// The line says the count, the share, the largest difference and the first pixel; or
    /// that the images are the same.
    #[test]
    fn the_line_reads_as_documented() {
        let c = compare(&render(), &image(REFERENCE)).unwrap();
        assert_eq!(
            c.line(),
            "compare: 2 of 6 pixels differ by more than 2/255 (33.33%), by up to 200/255; the first at (1, 0), where the render has (100, 100, 103) and the reference (100, 100, 100)"
        );
        assert_eq!(c.count(), "2 of 6 pixels differ by more than 2/255");
        let same = compare(&image(REFERENCE), &image(REFERENCE)).unwrap();
        assert_eq!(
            same.line(),
            "compare: the same as the reference (no pixel differs by more than 2/255)"
        );
        assert_eq!(same.count(), "no pixel differs by more than 2/255");
        assert_eq!(same.largest, 0);
        assert_eq!(percent(1, 1_000_000), "under 0.01%");
        assert_eq!(percent(312, 28_800), "1.08%");
    }

    /// The screen's words are the bytes as 0x00RRGGBB.
    #[test]
    fn screen_pixels_pack_the_bytes() {
        let i = Image::new(2, 1, vec![1, 2, 3, 255, 128, 0]).unwrap();
        assert_eq!(i.to_screen(), vec![0x0001_0203, 0x00ff_8000]);
        assert!(Image::new(2, 1, vec![0; 5]).is_none());
    }
}
