//! Space subdivision by an octree (notes: "Computational Aspects", item 2).
//!
//! The notes: enclose the scene in a cube, and subdivide the cube into smaller ones until each
//! holds at most a preset number k of surfaces, eliminating the cubes void of surfaces. The
//! cube here starts at the scene's lower corner (centred, its first split would cut a flat
//! scene, such as objects resting on a floor, through the middle of its layer). Here a
//! cell is split into its eight octants while it holds more than k objects (an object belongs
//! to every cell its box overlaps), down to a maximum depth; a split that would leave every
//! octant as crowded as its parent, or copy the objects into more than three octants on
//! average (objects as large as the cell), is not made. Empty octants are not stored.
//!
//! Each cell also keeps the box of what it holds (its objects' boxes, clipped to the cube): a
//! ray opens a cell only if it meets that box, so the emptier corners of a cube cost nothing.
//! A ray walks the cells front to back (along the ray, each axis goes from the near half of a
//! cube to the far half, so the octants come in a fixed order given by the signs of the
//! direction), and skips every cell whose contents start beyond the nearest hit found.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use super::aabb::{Aabb, RayBox, Span, first_meeting};
use crate::real::{Real, Vec3};

/// A packet of rays on its walk through the octree.
struct Packet<'a> {
    rays: &'a [RayBox],
    t_min: &'a [Real],
    all: Option<&'a Span>,
    /// Octant order: bit k set where the first ray moves down axis k.
    flip: usize,
}

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
    cells: Vec<Cell>,
    /// Per cell, what it holds: the union of its objects' boxes, clipped to the cube.
    content: Vec<Aabb>,
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
        // The enclosing cube, a little larger than the scene, from the scene's lower corner.
        // (Centred on the scene, its first split would cut a flat scene, such as spheres
        // resting on a floor, through the middle of its layer, and every object would be
        // copied into both halves.)
        let root = if boxes.is_empty() {
            Aabb::EMPTY
        } else {
            let side = (all.max - all.min).max_element() * 1.001;
            let min = all.min - (all.max - all.min) * 0.0005;
            Aabb {
                min,
                max: min + Vec3::splat(side),
            }
            .union(&all)
        };
        let mut tree = Self {
            cells: Vec::new(),
            content: Vec::new(),
            items: Vec::new(),
        };
        if !boxes.is_empty() {
            let list: Vec<u32> = (0..boxes.len() as u32).collect();
            tree.cells.push(Cell::Leaf { first: 0, count: 0 });
            tree.content.push(Aabb::EMPTY);
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
        let held = list
            .iter()
            .fold(Aabb::EMPTY, |b, &i| b.union(&boxes[i as usize]));
        self.content[cell] = Aabb {
            min: held.min.max(bounds.min),
            max: held.max.min(bounds.max),
        };
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
                // the children side by side, so that a ray testing them reads one stretch
                // of memory
                let mut children = [NONE; 8];
                for (o, part) in parts.iter().enumerate() {
                    if !part.is_empty() {
                        // (a cube void of surfaces is eliminated)
                        children[o] = self.cells.len() as u32;
                        self.cells.push(Cell::Leaf { first: 0, count: 0 });
                        self.content.push(Aabb::EMPTY);
                    }
                }
                self.cells[cell] = Cell::Inner(children);
                for (o, part) in parts.into_iter().enumerate() {
                    if children[o] != NONE {
                        let id = children[o] as usize;
                        self.fill(id, octant(&bounds, o), part, boxes, k, depth + 1);
                    }
                }
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

    /// Renumbers the `count` boxes the tree was built over in the order its leaves first
    /// name them, and returns that order: the new number k is the old box `order[k]`. The
    /// leaves come depth first, octant by octant, so neighbours in space get neighbouring
    /// numbers, and a caller that stores its objects' data in this order reads the objects
    /// of a cell from one stretch of memory instead of from all over the scene's list.
    pub fn renumber(&mut self, count: usize) -> Vec<u32> {
        let mut new = vec![u32::MAX; count];
        let mut order = Vec::with_capacity(count);
        for i in &mut self.items {
            let old = *i as usize;
            if new[old] == u32::MAX {
                new[old] = order.len() as u32;
                order.push(*i);
            }
            *i = new[old];
        }
        // boxes in no leaf (none, as every box overlaps the cube) keep a number all the same
        for (old, n) in new.iter().enumerate() {
            if *n == u32::MAX {
                order.push(old as u32);
            }
        }
        order
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
        // bit k set where the ray moves down axis k: there the upper octants come first
        let flip = usize::from(ray.inv_dir.x < 0.0)
            | usize::from(ray.inv_dir.y < 0.0) << 1
            | usize::from(ray.inv_dir.z < 0.0) << 2;
        if self.crosses(0, ray, t_min, *limit) {
            self.visit_cell(0, flip, ray, t_min, limit, &mut visit);
        }
    }

    /// The walk of [`Octree::walk`] for a packet of rays at once, as
    /// [`super::Bvh::walk_packet`] does it: a cell is opened when some ray of the packet meets
    /// what it holds, and the rays before the first one that does are dropped for all of it.
    /// `visit(i, from, limits, alone)` is called for the items of every leaf some ray from
    /// `from` on may meet (`alone`: i is the leaf's only item, so ray `from` meets its box,
    /// which holds the leaf's); a NaN limit is met by no box. `all` is the packet's [`Span`]
    /// for these limits, if it has one.
    pub(crate) fn walk_packet(
        &self,
        rays: &[RayBox],
        t_min: &[Real],
        limits: &mut [Real],
        all: Option<&Span>,
        mut visit: impl FnMut(u32, usize, &mut [Real], bool),
    ) {
        let Some(ray) = rays.first() else {
            return;
        };
        if self.cells.is_empty() {
            return;
        }
        // the octants' order from the first ray's directions (any order gives the same answers)
        let flip = usize::from(ray.down[0])
            | usize::from(ray.down[1]) << 1
            | usize::from(ray.down[2]) << 2;
        let packet = Packet {
            rays,
            t_min,
            all,
            flip,
        };
        if let Some(from) = self.first(&packet, 0, 0, limits) {
            self.visit_cell_packet(&packet, 0, from, limits, &mut visit);
        }
    }

    /// The first ray of the packet from `from` on that meets what `cell` holds before its
    /// limit.
    #[inline]
    fn first(&self, p: &Packet, cell: usize, from: usize, limits: &[Real]) -> Option<usize> {
        first_meeting(&self.content[cell], p.rays, p.t_min, limits, p.all, from)
    }

    fn visit_cell_packet(
        &self,
        p: &Packet,
        cell: usize,
        from: usize,
        limits: &mut [Real],
        visit: &mut impl FnMut(u32, usize, &mut [Real], bool),
    ) {
        super::counters::node();
        match &self.cells[cell] {
            Cell::Leaf { first, count } => {
                let first = *first as usize;
                for &i in &self.items[first..first + *count as usize] {
                    visit(i, from, limits, *count == 1);
                }
            }
            Cell::Inner(children) => {
                for j in 0..8 {
                    let child = children[j ^ p.flip];
                    if child != NONE
                        && let Some(f) = self.first(p, child as usize, from, limits)
                    {
                        self.visit_cell_packet(p, child as usize, f, limits, visit);
                    }
                }
            }
        }
    }

    /// Whether the ray meets what cell `cell` holds, between t_min and the limit.
    #[inline]
    fn crosses(&self, cell: usize, ray: &RayBox, t_min: Real, limit: Real) -> bool {
        self.content[cell].hit_between(ray, t_min, limit)
    }

    fn visit_cell(
        &self,
        cell: usize,
        flip: usize,
        ray: &RayBox,
        t_min: Real,
        limit: &mut Real,
        visit: &mut impl FnMut(u32, &mut Real) -> bool,
    ) -> bool {
        super::counters::node();
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
                // Along the ray each axis passes from its near half of the cube to its far half
                // only, so the octants come in increasing order of (octant XOR flip): front to
                // back. Each is opened only if the ray meets what it holds before the limit.
                for j in 0..8 {
                    let child = children[j ^ flip];
                    if child != NONE
                        && self.crosses(child as usize, ray, t_min, *limit)
                        && !self.visit_cell(child as usize, flip, ray, t_min, limit, visit)
                    {
                        return false;
                    }
                }
                true
            }
        }
    }
}
