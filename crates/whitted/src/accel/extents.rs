//! Projection extents (notes: "Computational Aspects", item 1): "rectangles enclosing all
//! the image points of a particular object".
//!
//! A camera ray leaves the eye e through one image point, and every point P of the scene seen
//! through that image point lies on the same line. So an object can only be hit by the camera
//! rays of the pixels inside the projection of its bounding box. A box entirely in front of the
//! eye projects inside the rectangle around its eight projected corners; a box reaching behind
//! the eye may cover any pixel, and gets the whole image; a box wholly behind the eye is seen
//! by no camera ray, and gets no pixel.
//!
//! With q = P − e in the viewing basis, (q·u, q·v, q·n) with q·n < 0 in front, the ray
//! through P has d = s·q with s = N/(−q·n), so it crosses the near plane at
//! (u_c, v_r) = N·(q·u, q·v)/(−q·n), image column c = (u_c + W)·n_c/(2W) and row from the top
//! m − (v_r + H)·m/(2H). The rectangles are padded by a pixel on each side. A camera ray's
//! pixel is found by the same projection of its direction ([`Extents::pixel_of`]).
//!
//! The renderer works in 16 × 16 tiles, so each tile keeps the list of objects whose rectangle
//! overlaps it, and a camera ray of that tile tests only those (and the objects that may be
//! anywhere, kept in one list of their own). Which tile a camera ray belongs to is read off its
//! direction ([`Extents::pixel_of`]): the road hands the structure a camera ray, not a pixel.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use super::aabb::Aabb;
use crate::camera::Camera;
use crate::real::{Real, Vec3};

/// Per-tile candidate lists for camera rays.
#[derive(Clone, Debug)]
pub struct Extents {
    tile: u32,
    tiles_x: u32,
    /// For tile t: its objects are `items[starts[t]..starts[t + 1]]`.
    starts: Vec<u32>,
    items: Vec<u32>,
    /// Objects that may cover any pixel (kept once, not in every tile's list).
    everywhere: Vec<u32>,
    /// Where a camera ray crosses the image: [`Extents::pixel_of`].
    crossing: Crossing,
}

/// Where a line from the eye crosses the image, the box corners of [`rectangle`] and the
/// camera rays of [`Extents::pixel_of`] alike: along q (in front of the eye, −q·n > 0) it
/// crosses the near plane at (u_c, v_r) = N·(q·u, q·v)/(−q·n), which is image column
/// c = (u_c + W)·n_c/(2W) = c₀ + k_c·(q·u)/(−q·n) and row from the top
/// m − (v_r + H)·m/(2H) = m₀ − k_m·(q·v)/(−q·n), with (c₀, m₀) the image's centre,
/// k_c = N·n_c/(2W) and k_m = N·m/(2H).
#[derive(Clone, Debug)]
struct Crossing {
    u: Vec3,
    v: Vec3,
    n: Vec3,
    centre: (Real, Real),
    scale: (Real, Real),
    size: (u32, u32),
}

impl Crossing {
    fn of(camera: &Camera) -> Self {
        let (columns, rows) = (camera.columns() as Real, camera.rows() as Real);
        Self {
            u: camera.u(),
            v: camera.v(),
            n: camera.n(),
            centre: (columns / 2.0, rows / 2.0),
            scale: (
                camera.near() * columns / (2.0 * camera.half_width()),
                camera.near() * rows / (2.0 * camera.half_height()),
            ),
            size: (camera.columns(), camera.rows()),
        }
    }

    /// (column, row from the top) where the line along `q` crosses the image, not rounded.
    #[inline]
    fn point(&self, q: Vec3) -> (Real, Real) {
        let depth = 1.0 / -q.dot(self.n);
        (
            self.centre.0 + self.scale.0 * q.dot(self.u) * depth,
            self.centre.1 - self.scale.1 * q.dot(self.v) * depth,
        )
    }
}

/// Where a box lies on the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Footprint {
    /// Inside the rectangle [x0, x1] × [y0, y1] (pixel columns and rows from the top,
    /// inclusive; it may reach beyond the image).
    Rectangle([i64; 4]),
    /// Anywhere: the box reaches behind the eye.
    Anywhere,
    /// Nowhere: the box lies wholly behind the eye, where no camera ray goes (a camera ray
    /// e + d·t, t > 0, has depth t·N > 0).
    Nowhere,
}

/// The part of the image that may see the box.
#[must_use]
pub fn footprint(b: &Aabb, camera: &Camera) -> Footprint {
    let corner = |i: usize| {
        Vec3::new(
            if i & 1 == 0 { b.min.x } else { b.max.x },
            if i & 2 == 0 { b.min.y } else { b.max.y },
            if i & 4 == 0 { b.min.z } else { b.max.z },
        )
    };
    // depth is linear, so the box's deepest point is a corner
    let deepest = (0..8)
        .map(|i| {
            let q = corner(i) - camera.eye();
            -q.dot(camera.n()) / q.length().max(Real::MIN_POSITIVE)
        })
        .fold(Real::NEG_INFINITY, Real::max);
    if deepest < -1e-3 {
        return Footprint::Nowhere;
    }
    match rectangle(b, camera) {
        Some(r) => Footprint::Rectangle(r),
        None => Footprint::Anywhere,
    }
}

/// The image rectangle [x0, x1] × [y0, y1] (pixel columns and rows from the top, inclusive)
/// that may see the box, or `None` if the box may cover any pixel (it reaches behind the eye).
#[must_use]
pub fn rectangle(b: &Aabb, camera: &Camera) -> Option<[i64; 4]> {
    let crossing = Crossing::of(camera);
    let (mut x0, mut x1, mut y0, mut y1) = (
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
    );
    for i in 0..8 {
        let p = Vec3::new(
            if i & 1 == 0 { b.min.x } else { b.max.x },
            if i & 2 == 0 { b.min.y } else { b.max.y },
            if i & 4 == 0 { b.min.z } else { b.max.z },
        );
        let q = p - camera.eye();
        let depth = -q.dot(camera.n());
        if depth.is_nan() || depth <= 1e-6 * q.length() {
            return None;
        }
        let (c, y) = crossing.point(q);
        x0 = x0.min(c);
        x1 = x1.max(c);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let clamp = |v: Real| v.clamp(-1e9, 1e9) as i64;
    let r = [
        clamp(x0.floor()) - 1,
        clamp(x1.ceil()) + 1,
        clamp(y0.floor()) - 1,
        clamp(y1.ceil()) + 1,
    ];
    (x0.is_finite() && x1.is_finite() && y0.is_finite() && y1.is_finite()).then_some(r)
}

impl Extents {
    /// Builds the tile lists for the camera's image, tiles of `tile` × `tile` pixels; `boxes[i]`
    /// is the box of candidate i (lists keep candidates in increasing order).
    #[must_use]
    pub fn build(boxes: &[Aabb], camera: &Camera, tile: u32) -> Self {
        let tiles_x = camera.columns().div_ceil(tile);
        let tiles_y = camera.rows().div_ceil(tile);
        let count = (tiles_x as usize) * (tiles_y as usize);
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); count];
        let mut everywhere = Vec::new();
        let t = tile as i64;
        for (i, b) in boxes.iter().enumerate() {
            let (tx0, tx1, ty0, ty1) = match footprint(b, camera) {
                Footprint::Nowhere => continue,
                Footprint::Rectangle([x0, x1, y0, y1]) => {
                    if x1 < 0
                        || y1 < 0
                        || x0 >= camera.columns() as i64
                        || y0 >= camera.rows() as i64
                    {
                        continue; // off screen: no camera ray can see it
                    }
                    (
                        (x0.max(0) / t) as usize,
                        ((x1 / t) as usize).min(tiles_x as usize - 1),
                        (y0.max(0) / t) as usize,
                        ((y1 / t) as usize).min(tiles_y as usize - 1),
                    )
                }
                Footprint::Anywhere => {
                    everywhere.push(i as u32);
                    continue;
                }
            };
            for ty in ty0..=ty1 {
                for tx in tx0..=tx1 {
                    lists[ty * tiles_x as usize + tx].push(i as u32);
                }
            }
        }
        let mut starts = Vec::with_capacity(count + 1);
        let mut items = Vec::new();
        for l in &lists {
            starts.push(items.len() as u32);
            items.extend_from_slice(l);
        }
        starts.push(items.len() as u32);
        Self {
            tile,
            tiles_x,
            starts,
            items,
            everywhere,
            crossing: Crossing::of(camera),
        }
    }

    /// The pixel of the image that a camera ray with direction `d` passes through, clamped
    /// into the image. It may be a neighbour of the pixel the ray was made for (at a pixel's
    /// edge, rounding can tip it over), but every object the ray can hit has its rectangle,
    /// padded by a pixel, over it: its tile's candidates are enough.
    #[must_use]
    pub fn pixel_of(&self, d: Vec3) -> (u32, u32) {
        let (c, m) = self.crossing.point(d);
        let (columns, rows) = self.crossing.size;
        // clamped into the image first, the truncation is the floor (and a NaN, from a
        // direction that is no camera ray's, goes to pixel 0)
        let clamp = |x: Real, n: u32| x.clamp(0.0, n.saturating_sub(1) as Real) as u32;
        (clamp(c, columns), clamp(m, rows))
    }

    /// The candidates of the tile holding pixel (x, y) of the image, and those that may cover
    /// any pixel.
    #[inline]
    #[must_use]
    pub fn candidates(&self, x: u32, y: u32) -> (&[u32], &[u32]) {
        let t = ((y / self.tile) * self.tiles_x + x / self.tile) as usize;
        let here = match (self.starts.get(t), self.starts.get(t + 1)) {
            (Some(&a), Some(&b)) => &self.items[a as usize..b as usize],
            _ => &[],
        };
        (here, &self.everywhere)
    }
}
