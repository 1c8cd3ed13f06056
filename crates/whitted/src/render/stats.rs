//! Statistics: the rays a render cast, by kind, and (with the `counters` feature) the work
//! behind their queries.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use crate::accel::counters::Counts;

/// Rays cast, by kind, and (built with the `counters` feature) the work behind their queries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Camera rays.
    pub primary: u64,
    /// Feeler rays towards lights.
    pub shadow: u64,
    /// Mirror rays.
    pub reflected: u64,
    /// Transmitted rays.
    pub refracted: u64,
    /// Mirror rays spawned by total internal reflection (counted in `reflected` too).
    pub total_internal: u64,
    /// What the ray queries tested (all zero unless built with the `counters` feature).
    pub work: Counts,
}

impl Stats {
    /// All rays.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.primary + self.shadow + self.reflected + self.refracted
    }

    /// Two counts added together (for a parallel reduce).
    #[must_use]
    pub fn sum(mut self, o: Stats) -> Stats {
        self.add(&o);
        self
    }

    /// Adds another render's (or another tile's) counts to these.
    pub fn add(&mut self, o: &Stats) {
        self.primary += o.primary;
        self.shadow += o.shadow;
        self.reflected += o.reflected;
        self.refracted += o.refracted;
        self.total_internal += o.total_internal;
        self.work.add(&o.work);
    }
}
