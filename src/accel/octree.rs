//! Space subdivision by an octree (notes: "Computational Aspects", item 2).
//!
//! The notes: enclose the scene in a cube, and subdivide the cube into smaller ones until each
//! holds at most a preset number k of surfaces, eliminating the cubes void of surfaces. Here a
//! cell is split into its eight octants while it holds more than k objects (an object belongs
//! to every cell its box overlaps), down to a maximum depth; a split that would leave every
//! octant as crowded as its parent, or copy the objects into more than three octants on
//! average (objects as large as the cell), is not made. Empty octants are not stored.
//!
//! A ray walks the cells it crosses front to back (the octants of a cell sorted by where the
//! ray enters them) and stops as soon as the next cell starts beyond the nearest hit found.

use super::aabb::{Aabb, RayBox, SLACK, widen};

/// Per axis, the parameters where the ray crosses a cell's near and far faces.
#[derive(Clone, Copy, Debug)]
struct Span {
    lo: Vec3,
    hi: Vec3,
}
use crate::real::{Real, Vec3};

/// No child in this octant.
const NONE: u32 = u32::MAX;

#[derive(Clone, Debug)]
enum Cell {
    /// Eight octants (index of a cell, or [`NONE`]); octant bit 0 = upper x, bit 1 = upper y,
    /// bit 2 = upper z.
    Inner([u32; 8]),
    /// A range of [`Octree::items`].
    Leaf { first: u32, count: u32 },
}

/// An octree over boxes; its leaves name the boxes' indices.
#[derive(Clone, Debug)]
pub struct Octree {
    root: Aabb,
    cells: Vec<Cell>,
    items: Vec<u32>,
}

/// The cube's octant `k`.
fn octant(b: &Aabb, k: usize) -> Aabb {
    let c = b.centre();
    let pick = |bit: usize, lo: Real, mid: Real, hi: Real| {
        if k & bit == 0 { (lo, mid) } else { (mid, hi) }
    };
    let (x0, x1) = pick(1, b.min.x, c.x, b.max.x);
    let (y0, y1) = pick(2, b.min.y, c.y, b.max.y);
    let (z0, z1) = pick(4, b.min.z, c.z, b.max.z);
    Aabb {
        min: Vec3::new(x0, y0, z0),
        max: Vec3::new(x1, y1, z1),
    }
}

impl Octree {
    /// The deepest subdivision.
    pub const MAX_DEPTH: u32 = 12;

    /// Builds the octree over `boxes`, splitting cells holding more than `k` of them.
    #[must_use]
    pub fn build(boxes: &[Aabb], k: usize) -> Self {
        let all = boxes.iter().fold(Aabb::EMPTY, |b, x| b.union(x));
        // the enclosing cube, a little larger than the scene
        let root = if boxes.is_empty() {
            Aabb::EMPTY
        } else {
            let half = (all.max - all.min).max_element() * 0.5 * 1.001;
            let c = all.centre();
            Aabb {
                min: c - Vec3::splat(half),
                max: c + Vec3::splat(half),
            }
            .union(&all)
        };
        let mut tree = Self {
            root,
            cells: Vec::new(),
            items: Vec::new(),
        };
        if !boxes.is_empty() {
            let list: Vec<u32> = (0..boxes.len() as u32).collect();
            tree.cells.push(Cell::Leaf { first: 0, count: 0 });
            tree.fill(0, root, list, boxes, k.max(1), 0);
        }
        tree
    }

    fn fill(
        &mut self,
        cell: usize,
        bounds: Aabb,
        list: Vec<u32>,
        boxes: &[Aabb],
        k: usize,
        depth: u32,
    ) {
        if list.len() > k && depth < Self::MAX_DEPTH {
            let parts: Vec<Vec<u32>> = (0..8)
                .map(|o| {
                    let ob = octant(&bounds, o);
                    list.iter()
                        .copied()
                        .filter(|&i| boxes[i as usize].overlaps(&ob))
                        .collect()
                })
                .collect();
            // split only if some octant is less crowded than its parent, and the objects are
            // small enough for the octants to separate them (not every object copied into
            // most octants)
            let copies: usize = parts.iter().map(Vec::len).sum();
            if parts.iter().any(|p| p.len() < list.len()) && copies <= 3 * list.len() {
                let mut children = [NONE; 8];
                for (o, part) in parts.into_iter().enumerate() {
                    if part.is_empty() {
                        continue; // a cube void of surfaces is eliminated
                    }
                    let id = self.cells.len();
                    self.cells.push(Cell::Leaf { first: 0, count: 0 });
                    children[o] = id as u32;
                    self.fill(id, octant(&bounds, o), part, boxes, k, depth + 1);
                }
                self.cells[cell] = Cell::Inner(children);
                return;
            }
        }
        let first = self.items.len() as u32;
        self.items.extend_from_slice(&list);
        self.cells[cell] = Cell::Leaf {
            first,
            count: list.len() as u32,
        };
    }

    /// The number of objects in the fullest leaf, and the number of (object, leaf) pairs.
    #[must_use]
    pub fn leaf_load(&self) -> (usize, usize) {
        let max = self
            .cells
            .iter()
            .map(|c| match c {
                Cell::Leaf { count, .. } => *count as usize,
                Cell::Inner(_) => 0,
            })
            .max()
            .unwrap_or(0);
        (max, self.items.len())
    }

    /// Number of cells (for reports).
    #[must_use]
    pub fn cell_count(&self) -> usize {
        self.cells.len()
    }

    /// Calls `visit(i, limit)` for every box index i in the leaves the ray crosses with an
    /// entry not beyond `*limit`, front to back; `visit` returns false to stop. An index held by
    /// several leaves may be visited more than once.
    pub fn walk(
        &self,
        ray: &RayBox,
        t_min: Real,
        limit: &mut Real,
        mut visit: impl FnMut(u32, &mut Real) -> bool,
    ) {
        if self.cells.is_empty() {
            return;
        }
        let (e, x) = self.root.slabs(ray);
        if e <= x && x >= t_min && e <= widen(*limit) {
            // per axis, where the ray crosses the cube's near and far faces
            let a = (self.root.min - ray.origin) * ray.inv_dir;
            let b = (self.root.max - ray.origin) * ray.inv_dir;
            let span = Span {
                lo: a.min(b),
                hi: a.max(b),
            };
            self.visit_cell(0, &self.root, span, ray, t_min, limit, &mut visit);
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn visit_cell(
        &self,
        cell: usize,
        bounds: &Aabb,
        span: Span,
        ray: &RayBox,
        t_min: Real,
        limit: &mut Real,
        visit: &mut impl FnMut(u32, &mut Real) -> bool,
    ) -> bool {
        match &self.cells[cell] {
            Cell::Leaf { first, count } => {
                let first = *first as usize;
                for &i in &self.items[first..first + *count as usize] {
                    if !visit(i, limit) {
                        return false;
                    }
                }
                true
            }
            Cell::Inner(children) => {
                // Where the ray crosses the three mid-planes: each octant's interval on an axis
                // is the near or the far half of the cell's, so no octant box is intersected
                // anew. A NaN (the origin on a mid-plane, moving along it) keeps both halves.
                let mid = (bounds.centre() - ray.origin) * ray.inv_dir;
                // bit k set where the ray moves down axis k: there the upper half comes first
                let flip = usize::from(ray.inv_dir.x < 0.0)
                    | usize::from(ray.inv_dir.y < 0.0) << 1
                    | usize::from(ray.inv_dir.z < 0.0) << 2;
                // Along the ray each axis passes from its near half to its far half only, so
                // the octants come in increasing order of (octant XOR flip): front to back.
                for j in 0..8 {
                    let o = j ^ flip;
                    let child = children[o];
                    if child == NONE {
                        continue;
                    }
                    let mut lo = span.lo;
                    let mut hi = span.hi;
                    for k in 0..3 {
                        let m = mid[k];
                        if m.is_nan() {
                            continue;
                        }
                        if j & (1 << k) == 0 {
                            hi[k] = m; // the near half
                        } else {
                            lo[k] = m; // the far half
                        }
                    }
                    let enter = lo.x.max(lo.y).max(lo.z);
                    let exit = hi.x.min(hi.y).min(hi.z);
                    let (e, x) = (enter - enter.abs() * SLACK, exit + exit.abs() * SLACK);
                    if e <= x && x >= t_min && e <= widen(*limit) {
                        let b = octant(bounds, o);
                        let sub = Span { lo, hi };
                        if !self.visit_cell(child as usize, &b, sub, ray, t_min, limit, visit) {
                            return false;
                        }
                    }
                }
                true
            }
        }
    }
}
