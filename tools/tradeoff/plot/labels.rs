//! Where the labels of the front's points go: beside their point ([`Side`]), inside the
//! panel, clear of each other, and over as few markers and line segments as can be
//! ([`place_labels`]). Sizes are estimated from the text ([`text_size`]); plotters cannot
//! measure text in an SVG.

use plotters::style::text_anchor::{HPos, VPos};

/// A point, or a size, in pixels.
pub type Pixel = (i32, i32);
/// A box in pixels: left, top, right, bottom.
pub type PixelBox = (i32, i32, i32, i32);

/// The estimated size in pixels of `text` at nominal font size `size`: plotters writes
/// 0.806·size px into the SVG, and a sans-serif character is about 0.55 em wide on average.
pub fn text_size(text: &str, size: u32) -> Pixel {
    let px = f64::from(size) * 0.806;
    (
        (text.chars().count() as f64 * px * 0.55).ceil() as i32,
        px.ceil() as i32,
    )
}

/// Where a label stands beside its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Below and to the left: the first choice for a point of the front, since a point there
    /// would be faster and more accurate, so there is none.
    LeftBelow,
    /// To the left, centred on the point's height.
    Left,
    /// Below, centred.
    Below,
    /// Below and to the right.
    RightBelow,
    /// Above and to the left.
    LeftAbove,
    /// To the right.
    Right,
    /// Above, centred.
    Above,
}

impl Side {
    /// Every side, in the order they are tried.
    pub const ALL: [Side; 7] = [
        Side::LeftBelow,
        Side::Left,
        Side::Below,
        Side::RightBelow,
        Side::LeftAbove,
        Side::Right,
        Side::Above,
    ];
    /// The gap between a point and its label, in pixels.
    const GAP: i32 = 8;

    /// The text's anchor relative to the point, and how the text sits on it.
    pub fn anchor(self) -> (Pixel, HPos, VPos) {
        let g = Self::GAP;
        match self {
            Side::LeftBelow => ((-g, g / 2), HPos::Right, VPos::Top),
            Side::Left => ((-g - 2, 0), HPos::Right, VPos::Center),
            Side::Below => ((0, g + 2), HPos::Center, VPos::Top),
            Side::RightBelow => ((g, g / 2), HPos::Left, VPos::Top),
            Side::LeftAbove => ((-g, -g / 2), HPos::Right, VPos::Bottom),
            Side::Right => ((g + 2, 0), HPos::Left, VPos::Center),
            Side::Above => ((0, -g - 2), HPos::Center, VPos::Bottom),
        }
    }

    /// The box of a label of size `(w, h)` on this side of the point `at`.
    pub fn bounds(self, at: Pixel, (w, h): Pixel) -> PixelBox {
        let ((dx, dy), hpos, vpos) = self.anchor();
        let (x, y) = (at.0 + dx, at.1 + dy);
        let left = match hpos {
            HPos::Left => x,
            HPos::Center => x - w / 2,
            HPos::Right => x - w,
        };
        let top = match vpos {
            VPos::Top => y,
            VPos::Center => y - h / 2,
            VPos::Bottom => y - h,
        };
        (left, top, left + w, top + h)
    }
}

/// Whether two boxes overlap.
fn overlaps(a: PixelBox, b: PixelBox) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// Whether the segment from `p` to `q` passes through the box.
fn crosses(p: Pixel, q: Pixel, b: PixelBox) -> bool {
    let steps = (p.0 - q.0).abs().max((p.1 - q.1).abs()).max(1);
    (0..=steps).any(|i| {
        let t = f64::from(i) / f64::from(steps);
        let x = f64::from(p.0) + t * f64::from(q.0 - p.0);
        let y = f64::from(p.1) + t * f64::from(q.1 - p.1);
        (f64::from(b.0)..=f64::from(b.2)).contains(&x)
            && (f64::from(b.1)..=f64::from(b.3)).contains(&y)
    })
}

/// The side of each label (its point and its size in pixels, in the order given): of the
/// sides where the label stays inside `area` and clear of the labels placed before it, the one
/// that covers the fewest markers (at `markers`, 6 px around each) and segments of the line
/// through `line`, the first of [`Side::ALL`] among equals; `None` where no side is inside and
/// clear.
pub fn place_labels(
    labels: &[(Pixel, Pixel)],
    markers: &[Pixel],
    line: &[Pixel],
    area: PixelBox,
) -> Vec<Option<Side>> {
    const PAD: i32 = 3;
    let mut placed: Vec<PixelBox> = Vec::new();
    labels
        .iter()
        .map(|&(at, size)| {
            let best = Side::ALL
                .into_iter()
                .map(|side| (side, side.bounds(at, size)))
                .filter(|(_, b)| b.0 >= area.0 && b.1 >= area.1 && b.2 <= area.2 && b.3 <= area.3)
                .filter(|(_, b)| {
                    let grown = (b.0 - PAD, b.1 - PAD, b.2 + PAD, b.3 + PAD);
                    placed.iter().all(|p| !overlaps(grown, *p))
                })
                .min_by_key(|(_, b)| {
                    let covered = markers
                        .iter()
                        .filter(|m| overlaps(*b, (m.0 - 6, m.1 - 6, m.0 + 6, m.1 + 6)))
                        .count();
                    let crossed = line.windows(2).filter(|s| crosses(s[0], s[1], *b)).count();
                    covered + crossed
                });
            best.map(|(side, b)| {
                placed.push(b);
                side
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{Side, overlaps, place_labels};

    const AREA: super::PixelBox = (0, 0, 400, 300);

    #[test]
    fn a_lone_label_goes_below_left_of_its_point() {
        assert_eq!(
            place_labels(&[((200, 100), (40, 12))], &[], &[], AREA),
            vec![Some(Side::LeftBelow)]
        );
        assert_eq!(
            Side::LeftBelow.bounds((200, 100), (40, 12)),
            (152, 104, 192, 116)
        );
    }

    #[test]
    fn labels_stay_inside_the_area() {
        // at the left edge the left sides (and the centred one) would leave it; at the
        // bottom, the lower ones
        let sides = place_labels(
            &[((5, 100), (40, 12)), ((200, 295), (40, 12))],
            &[],
            &[],
            AREA,
        );
        assert_eq!(sides, vec![Some(Side::RightBelow), Some(Side::LeftAbove)]);
    }

    #[test]
    fn labels_do_not_overlap_and_one_that_cannot_fit_is_left_out() {
        let labels = [((200, 100), (40, 12)), ((202, 101), (40, 12))];
        let sides = place_labels(&labels, &[], &[], AREA);
        let (a, b) = (sides[0].unwrap(), sides[1].unwrap());
        assert!(!overlaps(
            a.bounds(labels[0].0, labels[0].1),
            b.bounds(labels[1].0, labels[1].1)
        ));
        // a tiny area: the second label has nowhere to go
        let tiny = (150, 95, 230, 130);
        let sides = place_labels(&labels, &[], &[], tiny);
        assert_eq!(sides[0], Some(Side::LeftBelow));
        assert_eq!(sides[1], None);
    }

    #[test]
    fn labels_avoid_markers_and_the_line() {
        // a marker where the first choice would go: the next side free of it is taken
        let sides = place_labels(&[((200, 100), (40, 12))], &[(165, 114)], &[], AREA);
        assert_eq!(sides, vec![Some(Side::Left)]);
        // and a line through the left side too
        let sides = place_labels(
            &[((200, 100), (40, 12))],
            &[(165, 114)],
            &[(100, 100), (200, 100)],
            AREA,
        );
        assert_eq!(sides, vec![Some(Side::Below)]);
    }
}
