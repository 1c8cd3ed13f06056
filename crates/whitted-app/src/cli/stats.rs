//! The lines on stderr after a render: [`summary`], the last one (resolution, rays by kind,
//! time, M rays/s), and with `--stats` in a build with the `counters` feature, [`work_line`].
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use whitted::render;

/// The line `--stats` adds in a build with the `counters` feature: what the queries tested, in
/// all and per query.
#[must_use]
pub fn work_line(w: &whitted::accel::counters::Counts) -> String {
    let per = |n: u64| n as f64 / w.queries.max(1) as f64;
    format!(
        "work: {} queries; {} node visits ({:.2} a query), {} box tests ({:.2}), {} object tests ({:.2})",
        w.queries,
        w.nodes,
        per(w.nodes),
        w.boxes,
        per(w.boxes),
        w.objects,
        per(w.objects)
    )
}

/// The final line: resolution, rays by kind, time (structure build and render) and M rays/s.
#[must_use]
pub fn summary(width: u32, height: u32, stats: &render::Stats, seconds: f64) -> String {
    format!(
        "{width}×{height}: rays {} primary, {} shadow, {} reflected, {} refracted ({} total); {:.3} s, {:.2} M rays/s",
        stats.primary,
        stats.shadow,
        stats.reflected,
        stats.refracted,
        stats.total(),
        seconds,
        stats.total() as f64 / seconds.max(1e-9) / 1e6
    )
}
