//! The progress bar of a long render: on stderr, only when stderr is a terminal and not with
//! `--quiet`, and only once the render has lasted a second.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// A progress bar on stderr that appears only once a render has lasted a second.
pub struct Progress {
    bar: indicatif::ProgressBar,
    enabled: bool,
    shown: AtomicBool,
    start: Instant,
}

impl Progress {
    /// A bar for a render of `total` pixels, hidden until a second has passed; drawn at all
    /// only when `enabled`.
    #[must_use]
    pub fn new(total: u64, enabled: bool) -> Self {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(total),
            indicatif::ProgressDrawTarget::hidden(),
        );
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:40}] {percent:>3}% ({eta} left)",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        Self {
            bar,
            enabled,
            shown: AtomicBool::new(false),
            start: Instant::now(),
        }
    }

    /// Counts `pixels` more as done (from any render thread), and shows the bar once the
    /// render has lasted a second.
    pub fn advance(&self, pixels: u64) {
        if !self.enabled {
            return;
        }
        self.bar.inc(pixels);
        if !self.shown.load(Ordering::Relaxed)
            && self.start.elapsed() > Duration::from_secs(1)
            && !self.shown.swap(true, Ordering::Relaxed)
        {
            self.bar
                .set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    }

    /// Clears the bar, if it was shown.
    pub fn finish(&self) {
        if self.shown.load(Ordering::Relaxed) {
            self.bar.finish_and_clear();
        }
    }
}
