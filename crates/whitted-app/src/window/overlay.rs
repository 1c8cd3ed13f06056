//! The ray tree of a clicked pixel, drawn over the image.
//!
//! Every ray of the tree ([`RayTree`]) becomes a segment in the world — a camera, mirror or
//! transmitted ray from its origin to its hit (or far along its direction when it hits
//! nothing), a feeler from its start towards its light — and is projected into the view with
//! the camera of the image, the inverse of the chapter 1 road:
//!
//! ```text
//! q = P − e,  z = −q·n  (distance in front of the eye),
//! u_c = N·(q·u)/z,  v_r = N·(q·v)/z,
//! column c = (u_c/W + 1)·n_cols/2,  row from the top y = m − (v_r/H + 1)·m/2
//! ```
//!
//! Segments are cut where they pass behind the near plane before they are projected. The
//! camera ray starts at the eye, so it projects to (nearly) a point: the clicked pixel, marked
//! with a ring. Each kind of ray has its colour ([`Stroke::colour`]) and each mark its shape;
//! what they mean ([`Stroke::legend`], [`Mark::legend`]) is printed by `H` and tabled in the
//! course book. Every stroke has a black outline so it reads on any image.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use whitted::camera::Camera;
use whitted::real::{Real, Vec3};
use whitted::render::inspect::{HitNode, LightNode, RayNode};
use whitted::render::{RayKind, RayTree};

/// The kinds of line in the overlay.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// A camera ray.
    Camera,
    /// A mirror ray.
    Mirror,
    /// A transmitted ray.
    Transmitted,
    /// A feeler that reaches its light whole.
    FeelerLit,
    /// A feeler up to the opaque object that blocks it.
    FeelerBlocked,
    /// A blocked feeler beyond its blocker, up to the light (dotted).
    FeelerBeyond,
    /// A feeler through transparent objects only: part of the light arrives.
    FeelerPartial,
    /// The direction to a light when no feeler is cast (dotted).
    ToLight,
}

impl Stroke {
    /// Every stroke, in the order the legend lists them.
    pub const ALL: [Stroke; 8] = [
        Stroke::Camera,
        Stroke::FeelerLit,
        Stroke::ToLight,
        Stroke::FeelerPartial,
        Stroke::FeelerBlocked,
        Stroke::FeelerBeyond,
        Stroke::Mirror,
        Stroke::Transmitted,
    ];

    /// How the stroke looks, in words, and what it means: its line of the legend.
    #[must_use]
    pub fn legend(self) -> (&'static str, &'static str) {
        match self {
            Self::Camera => (
                "white",
                "the camera ray; from the eye it projects onto the clicked pixel",
            ),
            Self::FeelerLit => ("yellow", "a feeler that reaches its light"),
            Self::ToLight => (
                "dotted yellow",
                "towards a light that casts no feeler (no shadows yet, or `shadows = false`)",
            ),
            Self::FeelerPartial => (
                "orange",
                "a feeler through transparent objects only: part of the light arrives",
            ),
            Self::FeelerBlocked => ("red", "a feeler up to the opaque object that blocks it"),
            Self::FeelerBeyond => (
                "dotted red",
                "a blocked feeler, on from its blocker to the light",
            ),
            Self::Mirror => ("cyan", "a mirror ray"),
            Self::Transmitted => ("magenta", "a transmitted ray"),
        }
    }

    /// The stroke's colour, `0x00RRGGBB`.
    #[must_use]
    pub fn colour(self) -> u32 {
        match self {
            Self::Camera => 0xff_ffff,
            Self::Mirror => 0x00_e5ff,
            Self::Transmitted => 0xff_40ff,
            Self::FeelerLit | Self::ToLight => 0xff_e000,
            Self::FeelerBlocked | Self::FeelerBeyond => 0xff_3030,
            Self::FeelerPartial => 0xff_9000,
        }
    }

    /// Whether the stroke is dotted.
    #[must_use]
    pub fn dotted(self) -> bool {
        matches!(self, Self::FeelerBeyond | Self::ToLight)
    }
}

/// The kinds of mark in the overlay.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// A hit point.
    Hit,
    /// Where an opaque object blocks a feeler (red ×).
    Blocker,
    /// A light.
    Light,
    /// The clicked pixel.
    Pixel,
}

impl Mark {
    /// Every mark, in the order the legend lists them.
    pub const ALL: [Mark; 4] = [Mark::Pixel, Mark::Hit, Mark::Light, Mark::Blocker];

    /// How the mark looks, in words, and what it means: its line of the legend.
    #[must_use]
    pub fn legend(self) -> (&'static str, &'static str) {
        match self {
            Self::Pixel => ("white ring", "the clicked pixel"),
            Self::Hit => ("white square", "a hit point"),
            Self::Light => ("yellow diamond", "a light"),
            Self::Blocker => ("red ×", "where an opaque object blocks a feeler"),
        }
    }
}

/// A segment in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Start.
    pub a: Vec3,
    /// End.
    pub b: Vec3,
    /// How it is drawn.
    pub stroke: Stroke,
}

/// The tree's segments and marks in the world. A ray that hits nothing is drawn `far` units
/// long.
#[must_use]
pub fn world(tree: &RayTree, far: Real) -> (Vec<Segment>, Vec<(Vec3, Mark)>) {
    let mut segments = Vec::new();
    let mut marks = Vec::new();
    for s in &tree.samples {
        ray(&s.ray, far, &mut segments, &mut marks);
    }
    (segments, marks)
}

fn ray(r: &RayNode, far: Real, segments: &mut Vec<Segment>, marks: &mut Vec<(Vec3, Mark)>) {
    let stroke = match r.kind {
        RayKind::Camera => Stroke::Camera,
        RayKind::Mirror => Stroke::Mirror,
        RayKind::Transmitted => Stroke::Transmitted,
    };
    let end = r.hit.as_ref().map_or_else(
        || r.origin + r.direction.normalize_or_zero() * far,
        |h| h.point,
    );
    segments.push(Segment {
        a: r.origin,
        b: end,
        stroke,
    });
    if let Some(h) = &r.hit {
        hit(h, far, segments, marks);
        marks.push((h.point, Mark::Hit));
    }
}

fn hit(h: &HitNode, far: Real, segments: &mut Vec<Segment>, marks: &mut Vec<(Vec3, Mark)>) {
    for light in &h.lights {
        if light.in_front {
            feeler(h, light, segments, marks);
            marks.push((light.position, Mark::Light));
        }
    }
    for b in &h.branches {
        ray(b, far, segments, marks);
    }
}

/// A feeler's segments: lit, partial, or blocked (up to the first opaque crossing, then
/// dotted to the light). Without a feeler, a dotted line to the light.
fn feeler(
    h: &HitNode,
    light: &LightNode,
    segments: &mut Vec<Segment>,
    marks: &mut Vec<(Vec3, Mark)>,
) {
    let l = light.position;
    let Some(f) = &light.feeler else {
        segments.push(Segment {
            a: h.point,
            b: l,
            stroke: Stroke::ToLight,
        });
        return;
    };
    let at = |u: Real| f.origin + (l - f.origin) * u; // S(u) = P′ + (L − P′)·u
    let blocker = f
        .crossings
        .iter()
        .filter(|c| c.transmission <= 0.0)
        .flat_map(|c| c.u.iter().copied())
        .reduce(Real::min);
    match blocker {
        Some(u) => {
            let p = at(u);
            segments.push(Segment {
                a: f.origin,
                b: p,
                stroke: Stroke::FeelerBlocked,
            });
            segments.push(Segment {
                a: p,
                b: l,
                stroke: Stroke::FeelerBeyond,
            });
            marks.push((p, Mark::Blocker));
        }
        None => segments.push(Segment {
            a: f.origin,
            b: l,
            stroke: if light.share < 1.0 {
                Stroke::FeelerPartial
            } else {
                Stroke::FeelerLit
            },
        }),
    }
}

/// Where world point `p` lands on the image, in pixels from the top left (pixel (x, y) covers
/// [x, x + 1) × [y, y + 1)); `None` when p is not in front of the eye.
#[must_use]
pub fn project(camera: &Camera, p: Vec3) -> Option<(Real, Real)> {
    let q = p - camera.eye();
    let z = -q.dot(camera.n());
    if z <= 0.0 {
        return None;
    }
    let u_c = camera.near() * q.dot(camera.u()) / z;
    let v_r = camera.near() * q.dot(camera.v()) / z;
    let (cols, rows) = (camera.columns() as Real, camera.rows() as Real);
    let c = (u_c / camera.half_width() + 1.0) * cols / 2.0;
    let r = (v_r / camera.half_height() + 1.0) * rows / 2.0;
    Some((c, rows - r))
}

/// The part of segment a–b in front of the plane at distance `near`·10⁻³ before the eye.
fn clip_front(camera: &Camera, a: Vec3, b: Vec3) -> Option<(Vec3, Vec3)> {
    let min = camera.near() * 1e-3;
    let depth = |p: Vec3| -(p - camera.eye()).dot(camera.n());
    let (za, zb) = (depth(a), depth(b));
    match (za >= min, zb >= min) {
        (true, true) => Some((a, b)),
        (false, false) => None,
        (true, false) => Some((a, a + (b - a) * ((za - min) / (za - zb)))),
        (false, true) => Some((b + (a - b) * ((zb - min) / (zb - za)), b)),
    }
}

/// A point in image coordinates: pixels from the top left.
pub type Point = (Real, Real);

/// The overlay in image coordinates, ready to draw.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overlay {
    /// Lines (start, end, stroke) in pixels from the top left.
    pub lines: Vec<(Point, Point, Stroke)>,
    /// Marks in pixels from the top left.
    pub marks: Vec<(Point, Mark)>,
}

impl Overlay {
    /// The tree projected with `camera` (the camera of the image it is drawn on).
    #[must_use]
    pub fn new(tree: &RayTree, camera: &Camera, far: Real) -> Self {
        let (segments, points) = world(tree, far);
        let mut lines = Vec::new();
        for s in segments {
            if let Some((a, b)) = clip_front(camera, s.a, s.b)
                && let (Some(pa), Some(pb)) = (project(camera, a), project(camera, b))
            {
                lines.push((pa, pb, s.stroke));
            }
        }
        let mut marks: Vec<_> = points
            .into_iter()
            .filter_map(|(p, m)| project(camera, p).map(|q| (q, m)))
            .collect();
        let (x, y) = tree.pixel;
        marks.push(((x as Real + 0.5, y as Real + 0.5), Mark::Pixel));
        Self { lines, marks }
    }

    /// Draws the overlay over `screen` (`0x00RRGGBB`, `width` × `height`), which shows the
    /// image scaled by `scale` (window pixels per image pixel, across and down): positions
    /// scale, strokes and marks keep their size in window pixels, so the drawing stays sharp
    /// in a window made larger. Outlines first, then colours, so crossing strokes stay
    /// readable.
    pub fn draw(&self, screen: &mut [u32], width: u32, height: u32, scale: (Real, Real)) {
        let mut canvas = Pen {
            screen,
            width: i64::from(width),
            height: i64::from(height),
        };
        let at = |p: Point| (p.0 * scale.0, p.1 * scale.1);
        for outline in [true, false] {
            for &(a, b, stroke) in &self.lines {
                canvas.line(at(a), at(b), stroke, outline);
            }
            for &(p, mark) in &self.marks {
                canvas.mark(at(p), mark, outline);
            }
        }
    }
}

/// Plots on a screen buffer, ignoring pixels outside it.
struct Pen<'s> {
    screen: &'s mut [u32],
    width: i64,
    height: i64,
}

impl Pen<'_> {
    fn plot(&mut self, x: i64, y: i64, colour: u32) {
        if (0..self.width).contains(&x) && (0..self.height).contains(&y) {
            self.screen[(y * self.width + x) as usize] = colour;
        }
    }

    /// A square of side `side` centred on (x, y).
    fn dab(&mut self, x: i64, y: i64, side: i64, colour: u32) {
        for dy in 0..side {
            for dx in 0..side {
                self.plot(x + dx - side / 2, y + dy - side / 2, colour);
            }
        }
    }

    /// A line 2 pixels wide (4 for the outline), walked one pixel at a time after clipping
    /// to the screen.
    fn line(&mut self, a: (Real, Real), b: (Real, Real), stroke: Stroke, outline: bool) {
        let Some((a, b)) = clip_2d(a, b, self.width as Real, self.height as Real) else {
            return;
        };
        let steps = (b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil().max(1.0) as i64;
        for i in 0..=steps {
            if stroke.dotted() && (i / 4) % 2 == 1 {
                continue;
            }
            let f = i as Real / steps as Real;
            let x = (a.0 + (b.0 - a.0) * f).floor() as i64;
            let y = (a.1 + (b.1 - a.1) * f).floor() as i64;
            if outline {
                self.dab(x, y, 4, 0);
            } else {
                self.dab(x, y, 2, stroke.colour());
            }
        }
    }

    fn mark(&mut self, p: (Real, Real), mark: Mark, outline: bool) {
        let (x, y) = (p.0.floor() as i64, p.1.floor() as i64);
        match (mark, outline) {
            (Mark::Hit, true) => self.dab(x, y, 7, 0),
            (Mark::Hit, false) => self.dab(x, y, 5, 0xff_ffff),
            (Mark::Blocker, _) => {
                let (side, colour) = if outline { (3, 0) } else { (2, 0xff_3030) };
                for d in -4..=4 {
                    self.dab(x + d, y + d, side, colour);
                    self.dab(x + d, y - d, side, colour);
                }
            }
            (Mark::Light, _) => {
                let (side, colour) = if outline { (3, 0) } else { (2, 0xff_e000) };
                for d in -5i64..=5 {
                    let e = 5 - d.abs();
                    self.dab(x + d, y + e, side, colour);
                    self.dab(x + d, y - e, side, colour);
                }
            }
            (Mark::Pixel, _) => {
                let (side, colour) = if outline { (3, 0) } else { (1, 0xff_ffff) };
                for i in 0..32 {
                    let a = i as Real * std::f64::consts::TAU as Real / 32.0;
                    let (s, c) = a.sin_cos();
                    self.dab(
                        x + (6.0 * c).round() as i64,
                        y + (6.0 * s).round() as i64,
                        side,
                        colour,
                    );
                }
            }
        }
    }
}

/// The part of segment a–b inside [−2, w + 2] × [−2, h + 2] (Liang–Barsky).
fn clip_2d(
    a: (Real, Real),
    b: (Real, Real),
    w: Real,
    h: Real,
) -> Option<((Real, Real), (Real, Real))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0 as Real, 1.0 as Real);
    for (p, q) in [
        (-dx, a.0 + 2.0),
        (dx, w + 2.0 - a.0),
        (-dy, a.1 + 2.0),
        (dy, h + 2.0 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return None;
            }
        }
    }
    if !(t0.is_finite() && t1.is_finite()) {
        return None;
    }
    Some((
        (a.0 + dx * t0, a.1 + dy * t0),
        (a.0 + dx * t1, a.1 + dy * t1),
    ))
}
