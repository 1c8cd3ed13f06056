//! Choosing the pixels a trees file keeps: the *steady* trees (whose neighbours all have
//! their shape), and among them, greedily, the fewest that show every feature of the scene.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::BTreeSet;

use super::grid::Grid;

/// A tree chosen from a [`Grid`], by its index, with what it is chosen for.
pub(super) type Pick = (usize, Vec<String>);

/// How steady a tree is: how many of the 9 trees of the 3 × 3 pixels around it (itself
/// included) have its shape, and how many of the 25 of the 5 × 5. A tree is *steady* when all
/// 9 do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Steadiness {
    /// Of the 9 trees of the 3 × 3 pixels around it, those of its shape.
    pub(super) near: usize,
    /// Of the 25 trees of the 5 × 5 pixels around it, those of its shape.
    pub(super) around: usize,
}

impl Steadiness {
    /// Whether all 9 trees around it have its shape.
    pub(super) fn steady(self) -> bool {
        self.near == 9
    }
}

/// Each tree's [`Steadiness`].
pub(super) fn steadiness(grid: &Grid) -> Vec<Steadiness> {
    let shapes = &grid.shapes;
    let (columns, rows) = (grid.columns as i64, grid.rows() as i64);
    let same = |i: usize, dc: i64, dr: i64| {
        let (c, r) = ((i as i64 % columns) + dc, (i as i64 / columns) + dr);
        (0..columns).contains(&c)
            && (0..rows).contains(&r)
            && shapes[(r * columns + c) as usize] == shapes[i]
    };
    let count = |i: usize, reach: i64| {
        (-reach..=reach)
            .flat_map(|dr| (-reach..=reach).map(move |dc| (dc, dr)))
            .filter(|&(dc, dr)| same(i, dc, dr))
            .count()
    };
    (0..shapes.len())
        .map(|i| Steadiness {
            near: count(i, 1),
            around: count(i, 2),
        })
        .collect()
}

/// The pixels kept for the scene's features: greedily, the steady tree that shows the most
/// features not shown yet (the steadiest first, then in row order), until every feature a
/// steady tree shows is shown. Returns each pick (tree index, the features it is kept for)
/// and the features only unsteady pixels show.
pub(super) fn choose(grid: &Grid, steady: &[Steadiness]) -> (Vec<Pick>, Vec<String>) {
    let shown = &grid.shows;
    let mut wanted: BTreeSet<String> = BTreeSet::new();
    let mut everywhere: BTreeSet<String> = BTreeSet::new();
    for (i, f) in shown.iter().enumerate() {
        everywhere.extend(f.iter().cloned());
        if steady[i].steady() {
            wanted.extend(f.iter().cloned());
        }
    }
    let mut picks = Vec::new();
    while !wanted.is_empty() {
        let best = (0..shown.len())
            .filter(|&i| steady[i].steady())
            .max_by_key(|&i| {
                let new = shown[i].intersection(&wanted).count();
                (new, steady[i], std::cmp::Reverse(i))
            });
        let Some(i) = best else { break };
        let covers: Vec<String> = shown[i].intersection(&wanted).cloned().collect();
        if covers.is_empty() {
            break;
        }
        for f in &covers {
            wanted.remove(f);
        }
        picks.push((i, covers));
    }
    let unsteady: Vec<String> = everywhere
        .into_iter()
        .filter(|f| !picks.iter().any(|(_, c)| c.contains(f)))
        .collect();
    (picks, unsteady)
}

/// A chapter's grid, each tree's steadiness, and the pixels kept from it.
pub(super) struct Chosen {
    /// The trees to choose from.
    pub(super) grid: Grid,
    /// Each tree's [`Steadiness`].
    pub(super) steady: Vec<Steadiness>,
    /// The trees kept, in the order they were chosen.
    pub(super) picks: Vec<Pick>,
}

impl Chosen {
    /// The pixels `grid` keeps for its scene's features ([`choose`]), and the features only
    /// unsteady pixels show.
    pub(super) fn from(grid: Grid) -> (Self, Vec<String>) {
        let steady = steadiness(&grid);
        let (picks, unsteady) = choose(&grid, &steady);
        (
            Self {
                grid,
                steady,
                picks,
            },
            unsteady,
        )
    }

    /// The features the picks are kept for, counted over all of them.
    pub(super) fn features(&self) -> usize {
        self.picks.iter().map(|(_, c)| c.len()).sum()
    }

    /// The pixels kept, in their order, as their trees name them.
    pub(super) fn pixels(&self) -> Vec<(u32, u32)> {
        self.picks
            .iter()
            .map(|(i, _)| self.grid.trees[*i].tree.pixel)
            .collect()
    }
}
