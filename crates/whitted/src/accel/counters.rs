//! Counting the work behind the ray queries (cargo feature `counters`).
//!
//! How many boxes and objects does a ray test under each `--accel`? Built with the feature,
//! every query, node visit, box test and object test is counted on the thread that does it,
//! the renderer gathers the counts per band of tiles, and `--stats` prints the totals:
//!
//! ```text
//! cargo run --release --features counters --bin ch05_reflection_refraction -- scene.toml --stats
//! ```
//!
//! Without the feature every counting call is empty and compiles to nothing, so the renders
//! measured in `docs/src/performance.md` pay nothing for it.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

/// The work done by ray queries: what [`super::Accelerator::nearest`] and
/// [`super::Accelerator::transmittance`] tested.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Counts {
    /// Queries: nearest hits and feelers.
    pub queries: u64,
    /// Nodes of the BVH or cells of the octree visited.
    pub nodes: u64,
    /// Slab tests of bounding boxes.
    pub boxes: u64,
    /// Ray–object intersection tests.
    pub objects: u64,
}

impl Counts {
    /// Adds another set of counts to this one.
    pub fn add(&mut self, o: &Counts) {
        self.queries += o.queries;
        self.nodes += o.nodes;
        self.boxes += o.boxes;
        self.objects += o.objects;
    }
}

/// Whether this build counts (the `counters` feature).
pub const ENABLED: bool = cfg!(feature = "counters");

#[cfg(feature = "counters")]
thread_local! {
    static HERE: std::cell::Cell<Counts> = const {
        std::cell::Cell::new(Counts { queries: 0, nodes: 0, boxes: 0, objects: 0 })
    };
}

/// Adds to this thread's counts (nothing without the feature).
#[inline(always)]
fn bump(_which: impl FnOnce(&mut Counts)) {
    #[cfg(feature = "counters")]
    HERE.with(|c| {
        let mut k = c.get();
        _which(&mut k);
        c.set(k);
    });
}

/// One query.
#[inline(always)]
pub(crate) fn query() {
    bump(|k| k.queries += 1);
}

/// One node visited.
#[inline(always)]
pub(crate) fn node() {
    bump(|k| k.nodes += 1);
}

/// One box tested.
#[inline(always)]
pub(crate) fn box_test() {
    bump(|k| k.boxes += 1);
}

/// One object tested.
#[inline(always)]
pub(crate) fn object() {
    bump(|k| k.objects += 1);
}

/// One query answered by the notes' loop over every object (`--accel none`), which tests all
/// `objects` of the scene.
#[inline(always)]
pub(crate) fn every_object(objects: usize) {
    bump(|k| {
        k.queries += 1;
        k.objects += objects as u64;
    });
}

/// This thread's counts since the last call, which starts them again from zero (all zero
/// without the feature).
#[must_use]
pub fn take() -> Counts {
    #[cfg(feature = "counters")]
    {
        HERE.with(|c| c.replace(Counts::default()))
    }
    #[cfg(not(feature = "counters"))]
    {
        Counts::default()
    }
}
