//! A bounding volume hierarchy built with the binned surface area heuristic (SAH).
//!
//! The notes' bounding boxes, nested: a binary tree whose every node holds the box of the
//! objects below it. A ray that misses a node's box skips the whole subtree, so a ray meets
//! O(log n) boxes instead of n. Each node is split where the SAH predicts the cheapest
//! traversal: for a split into L and R,
//!
//! ```text
//! cost = C_box + (A(L)/A(node))·|L|·C_obj + (A(R)/A(node))·|R|·C_obj
//! ```
//!
//! (A the surface area: the chance that a ray through the node meets the child's box). The
//! candidate planes are the borders of 12 bins along each axis, over the objects' centres.
//! A node becomes a leaf when no split beats testing its objects one by one.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use arrayvec::ArrayVec;

use super::aabb::{Aabb, RayBox, Span, first_meeting, widen};
use crate::real::Real;

/// One node of the flattened tree: an inner node's left child follows it, its right child is
/// at `right`; a leaf lists `count` objects from `first` in [`Bvh::items`].
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: index of the first item; inner node: index of the right child.
    index: u32,
    /// Number of items in a leaf, 0 for an inner node.
    count: u32,
    /// Inner node: the axis (0, 1, 2 for x, y, z) its objects were split along, the left
    /// child holding the lower centres.
    axis: u32,
}

/// A BVH over boxes. Its leaves are ranges of [`Bvh::order`]: the walk reports positions in
/// that order, so a caller that stores its data in that order reads it sequentially.
#[derive(Clone, Debug)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Box indices in leaf order.
    items: Vec<u32>,
}

const BINS: usize = 12;

/// A [`crate::real::Real`] as f64 (the build's arithmetic is in f64 in both precisions).
#[allow(clippy::unnecessary_cast)] // a no-op in f64, a widening under the `f32` feature
#[inline]
fn wide(x: crate::real::Real) -> f64 {
    x as f64
}
/// Cost of a box test relative to an object test, for the SAH.
const BOX_COST: f64 = 0.3;
const MAX_LEAF: usize = 8;
/// Depth after which nodes are split at the median instead of by the SAH.
const SAH_DEPTH: u32 = 32;

struct Builder<'a> {
    boxes: &'a [Aabb],
    centres: Vec<[f64; 3]>,
    nodes: Vec<Node>,
}

impl Bvh {
    /// Builds the hierarchy over `boxes` (all finite).
    #[must_use]
    pub fn build(boxes: &[Aabb]) -> Self {
        let mut b = Builder {
            boxes,
            centres: boxes
                .iter()
                .map(|x| {
                    let c = x.centre();
                    [wide(c.x), wide(c.y), wide(c.z)]
                })
                .collect(),
            nodes: Vec::with_capacity(2 * boxes.len().max(1)),
        };
        let mut items: Vec<u32> = (0..boxes.len() as u32).collect();
        if !boxes.is_empty() {
            b.split(&mut items, 0, 0);
        }
        Self {
            nodes: b.nodes,
            items,
        }
    }

    /// The box indices in leaf order: position k of a walk is box `order()[k]`.
    #[must_use]
    pub fn order(&self) -> &[u32] {
        &self.items
    }

    /// Number of nodes (for reports).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Calls `visit(k)` for every position k (see [`Bvh::order`]) whose leaf box the ray meets with an entry not
    /// beyond `*limit` (re-read after each call, so a nearest-hit search can shrink it), nearer
    /// subtrees first. `visit` returns false to stop the walk.
    #[inline]
    pub fn walk(
        &self,
        ray: &RayBox,
        t_min: crate::real::Real,
        limit: &mut crate::real::Real,
        mut visit: impl FnMut(u32, &mut crate::real::Real) -> bool,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let mut node = 0u32;
        if !self.nodes[0].bounds.hit_between(ray, t_min, *limit) {
            return;
        }
        // the far children put aside, with the ray's entry into their boxes (an `ArrayVec`
        // costs nothing to set up, which matters when most walks are a few nodes long)
        let mut stack = ArrayVec::<(u32, Real), 64>::new();
        loop {
            let n = &self.nodes[node as usize];
            super::counters::node();
            if n.count > 0 {
                let first = n.index as usize;
                for k in first..first + n.count as usize {
                    if !visit(k as u32, limit) {
                        return;
                    }
                }
            } else {
                let (l, r) = (node + 1, n.index);
                let (le, lx) = self.nodes[l as usize].bounds.slabs(ray);
                let (re, rx) = self.nodes[r as usize].bounds.slabs(ray);
                let lim = widen(*limit);
                let hit_l = le <= lx && lx >= t_min && le <= lim;
                let hit_r = re <= rx && rx >= t_min && re <= lim;
                match (hit_l, hit_r) {
                    (true, true) => {
                        let (near, far, far_enter) = if le <= re { (l, r, re) } else { (r, l, le) };
                        if stack.try_push((far, far_enter)).is_ok() {
                            node = near;
                            continue;
                        }
                        // a degenerate, very deep tree: visit the far side without the stack
                        if !self.walk_from(far, ray, t_min, limit, &mut visit) {
                            return;
                        }
                        node = near;
                        continue;
                    }
                    (true, false) => {
                        node = l;
                        continue;
                    }
                    (false, true) => {
                        node = r;
                        continue;
                    }
                    (false, false) => {}
                }
            }
            // pop the next subtree that is still worth visiting: its box was met, and the
            // nearest hit found since may now lie before the entry
            loop {
                let Some((next, enter)) = stack.pop() else {
                    return;
                };
                if enter <= widen(*limit) {
                    node = next;
                    break;
                }
            }
        }
    }

    /// The walk of [`Bvh::walk`] for a packet of rays at once (Wald's "first active ray"):
    /// a node is opened when any ray of the packet meets its box, and the rays before the
    /// first one that does are dropped for its whole subtree. Of two children, the nearer
    /// along the split axis (for the direction of the first ray that needs either) goes
    /// first. `visit(k, from, limits, alone)` is called for every position k of a leaf some
    /// ray from index `from` on may meet (rays before `from` miss it; `alone`: k is the
    /// leaf's only position, whose box is the leaf's, so ray `from` meets it); ray r looks
    /// for hits after `t_min[r]` up to `limits[r]`, which `visit` may shrink, or set to NaN
    /// when the ray needs nothing more (a NaN limit is met by no box). `all` is the packet's
    /// [`Span`] for these limits, if it has one.
    pub(crate) fn walk_packet(
        &self,
        rays: &[RayBox],
        t_min: &[Real],
        limits: &mut [Real],
        all: Option<&Span>,
        mut visit: impl FnMut(u32, usize, &mut [Real], bool),
    ) {
        if self.nodes.is_empty() {
            return;
        }
        // the first ray from `from` on that meets node's box before its limit
        let first = |node: u32, from: usize, limits: &[Real]| {
            let b = &self.nodes[node as usize].bounds;
            first_meeting(b, rays, t_min, limits, all, from)
        };
        let Some(from) = first(0, 0, limits) else {
            return;
        };
        let mut stack = ArrayVec::<(u32, usize), 64>::new();
        let (mut node, mut from) = (0u32, from);
        loop {
            let n = &self.nodes[node as usize];
            super::counters::node();
            if n.count > 0 {
                let start = n.index;
                for k in start..start + n.count {
                    visit(k, from, limits, n.count == 1);
                }
            } else {
                let (l, r) = (node + 1, n.index);
                match (first(l, from, limits), first(r, from, limits)) {
                    (Some(fl), Some(fr)) => {
                        // the nearer side first, by the direction of the first ray that needs
                        // one (the left child holds the lower centres along the split axis):
                        // the hits found there may then spare the far side
                        let down = rays[fl.min(fr)].down[n.axis as usize];
                        let (near, far) = if down {
                            ((r, fr), (l, fl))
                        } else {
                            ((l, fl), (r, fr))
                        };
                        if stack.try_push(far).is_err() {
                            self.walk_packet_from(far, rays, t_min, limits, &mut visit);
                        }
                        (node, from) = near;
                        continue;
                    }
                    (Some(fl), None) => {
                        (node, from) = (l, fl);
                        continue;
                    }
                    (None, Some(fr)) => {
                        (node, from) = (r, fr);
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // pop the next subtree some ray still needs (the limits may have shrunk)
            loop {
                let Some((next, f)) = stack.pop() else {
                    return;
                };
                if let Some(f) = first(next, f, limits) {
                    (node, from) = (next, f);
                    break;
                }
            }
        }
    }

    /// The recursive packet walk of one subtree (used only past the stack's depth).
    fn walk_packet_from(
        &self,
        (node, from): (u32, usize),
        rays: &[RayBox],
        t_min: &[Real],
        limits: &mut [Real],
        visit: &mut impl FnMut(u32, usize, &mut [Real], bool),
    ) {
        let n = &self.nodes[node as usize];
        super::counters::node();
        let Some(from) = first_meeting(&n.bounds, rays, t_min, limits, None, from) else {
            return;
        };
        if n.count > 0 {
            for k in n.index..n.index + n.count {
                visit(k, from, limits, n.count == 1);
            }
            return;
        }
        self.walk_packet_from((node + 1, from), rays, t_min, limits, visit);
        self.walk_packet_from((n.index, from), rays, t_min, limits, visit);
    }

    /// The recursive walk of one subtree (used only past the stack's depth).
    fn walk_from(
        &self,
        node: u32,
        ray: &RayBox,
        t_min: crate::real::Real,
        limit: &mut crate::real::Real,
        visit: &mut impl FnMut(u32, &mut crate::real::Real) -> bool,
    ) -> bool {
        let n = &self.nodes[node as usize];
        super::counters::node();
        if !n.bounds.hit_between(ray, t_min, *limit) {
            return true;
        }
        if n.count > 0 {
            let first = n.index as usize;
            for k in first..first + n.count as usize {
                if !visit(k as u32, limit) {
                    return false;
                }
            }
            return true;
        }
        self.walk_from(node + 1, ray, t_min, limit, visit)
            && self.walk_from(n.index, ray, t_min, limit, visit)
    }
}

impl Builder<'_> {
    /// Builds the subtree over `items` (a slice of the global item list starting at `offset`)
    /// and returns its node index.
    fn split(&mut self, items: &mut [u32], offset: usize, depth: u32) -> u32 {
        let bounds = items
            .iter()
            .fold(Aabb::EMPTY, |b, &i| b.union(&self.boxes[i as usize]));
        let me = self.nodes.len() as u32;
        self.nodes.push(Node {
            bounds,
            index: offset as u32,
            count: items.len() as u32,
            axis: 0,
        });
        if items.len() <= 1 {
            return me;
        }
        // Past SAH_DEPTH levels (a distribution the bins keep peeling a few objects off) the
        // median split takes over, which bounds the depth by SAH_DEPTH + log₂ n.
        let sah = if depth < SAH_DEPTH {
            self.best_split(items, &bounds)
        } else {
            None
        };
        let Some((axis, border)) = sah else {
            if items.len() <= MAX_LEAF {
                return me;
            }
            // no useful SAH split (e.g. all centres equal): halve by position along the widest axis
            let ext = bounds.max - bounds.min;
            let axis = if ext.x >= ext.y && ext.x >= ext.z {
                0
            } else if ext.y >= ext.z {
                1
            } else {
                2
            };
            items.sort_by(|a, b| {
                self.centres[*a as usize][axis].total_cmp(&self.centres[*b as usize][axis])
            });
            let mid = items.len() / 2;
            return self.inner(me, items, (mid, axis), offset, depth);
        };
        // partition: centres below the border go left
        let mut mid = 0;
        for k in 0..items.len() {
            if self.centres[items[k] as usize][axis] < border {
                items.swap(k, mid);
                mid += 1;
            }
        }
        if mid == 0 || mid == items.len() {
            mid = items.len() / 2;
        }
        self.inner(me, items, (mid, axis), offset, depth)
    }

    /// Makes node `me` an inner node: `items[..mid]` to the left, the rest to the right, split
    /// along `axis`.
    fn inner(
        &mut self,
        me: u32,
        items: &mut [u32],
        (mid, axis): (usize, usize),
        offset: usize,
        depth: u32,
    ) -> u32 {
        let (left, right) = items.split_at_mut(mid);
        self.split(left, offset, depth + 1);
        let r = self.split(right, offset + mid, depth + 1);
        let n = &mut self.nodes[me as usize];
        n.index = r;
        n.count = 0;
        n.axis = axis as u32;
        me
    }

    /// The (axis, border) of the cheapest binned SAH split, or `None` if a leaf is cheaper.
    fn best_split(&self, items: &[u32], bounds: &Aabb) -> Option<(usize, f64)> {
        let mut best: Option<(f64, usize, f64)> = None;
        let leaf_cost = items.len() as f64;
        let area = wide(bounds.half_area());
        if area <= 0.0 {
            return None;
        }
        for axis in 0..3 {
            let (lo, hi) = items
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &i| {
                    let c = self.centres[i as usize][axis];
                    (lo.min(c), hi.max(c))
                });
            if hi <= lo {
                continue;
            }
            let scale = BINS as f64 / (hi - lo);
            let mut bin_boxes = [Aabb::EMPTY; BINS];
            let mut bin_counts = [0usize; BINS];
            for &i in items {
                let k = (((self.centres[i as usize][axis] - lo) * scale) as usize).min(BINS - 1);
                bin_boxes[k] = bin_boxes[k].union(&self.boxes[i as usize]);
                bin_counts[k] += 1;
            }
            // sweep from the right to get the area and count of every right part
            let mut right_area = [0.0f64; BINS];
            let mut right_count = [0usize; BINS];
            let (mut b, mut c) = (Aabb::EMPTY, 0);
            for k in (1..BINS).rev() {
                b = b.union(&bin_boxes[k]);
                c += bin_counts[k];
                right_area[k] = wide(b.half_area());
                right_count[k] = c;
            }
            let (mut b, mut c) = (Aabb::EMPTY, 0);
            for k in 1..BINS {
                b = b.union(&bin_boxes[k - 1]);
                c += bin_counts[k - 1];
                if c == 0 || right_count[k] == 0 {
                    continue;
                }
                let cost = BOX_COST
                    + (wide(b.half_area()) * c as f64 + right_area[k] * right_count[k] as f64)
                        / area;
                if best.is_none_or(|(bc, _, _)| cost < bc) {
                    best = Some((cost, axis, lo + k as f64 / scale));
                }
            }
        }
        match best {
            Some((cost, axis, border)) if cost < leaf_cost || items.len() > MAX_LEAF => {
                Some((axis, border))
            }
            _ => None,
        }
    }
}
