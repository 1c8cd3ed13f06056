//! Where one ray tree parts from another: the path to the node, the quantity in the notes'
//! symbols, both values as shown, and the functions that computed it. [`super::walk`] finds
//! it; `--against` and `cargo learn` print it.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use super::provenance::Quantity;

/// One step of the path from a pixel to a node of its tree.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Step {
    /// The kind of node: `sample`, `camera ray`, `mirror ray`, `transmitted ray`, `hit`,
    /// `light`, `feeler`, `crossing`.
    pub kind: &'static str,
    /// How the path shows it: "hit `cone`", "light 1".
    pub label: String,
}

/// Where a tree first parts from the reference's.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// The path from the pixel to the node that holds the quantity.
    pub path: Vec<Step>,
    /// The quantity.
    pub quantity: Quantity,
    /// How the notes write it.
    pub symbol: &'static str,
    /// Its value in the tree compared, as shown.
    pub computed: String,
    /// The reference's value, as shown.
    pub reference: String,
    /// The functions of the road that computed it (manifest paths; [`Quantity::computed_by`]).
    pub functions: Vec<&'static str>,
}

impl Difference {
    /// The path as a reader follows it: "camera ray → hit `cone` → light 1".
    #[must_use]
    pub fn path_text(&self) -> String {
        self.path
            .iter()
            .map(|s| s.label.as_str())
            .collect::<Vec<_>>()
            .join(" → ")
    }

    /// "camera ray → hit `cone`: t: 4.02 (the reference: 3.87)".
    #[must_use]
    pub fn text(&self) -> String {
        format!(
            "{}: {}: {} (the reference: {})",
            self.path_text(),
            self.symbol,
            self.computed,
            self.reference
        )
    }
}
