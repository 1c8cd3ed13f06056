//! One pixel, as the renderer's callers ask for it: its colour in the options' view
//! ([`Tracer::pixel`]) and its ray tree ([`Tracer::inspect`]).
//!
//! A pixel is the mean of its samples (one at its centre, or several spread over it from
//! chapter 5 on, [`super::sampling`]). Each sample's camera ray goes down the road of one pixel
//! ([`super::tracer`]), and its nearest hit is shown as the view asks ([`super::views`]): the
//! chapter's own colour is the road's, every other view is drawn from the road's steps. The
//! rays-per-pixel view shows how many rays the pixel cast instead of what they brought back.
//!
//! Course book: [Chapter 1, camera rays](../../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

use super::inspect::{self, RayTree};
use super::options::View;
use super::query::Query;
use super::recorder::Recorder;
use super::sampling;
use super::shortcuts::Shortcuts;
use super::stats::Stats;
use super::tracer::Tracer;
use super::views;
use crate::ray::Ray;
use crate::real::{Real, Vec3};

impl<Q: Query + Shortcuts> Tracer<'_, Q> {
    // ANCHOR: ch1_pixel
    /// The colour of pixel (x, y), row y from the top: the mean over its samples. `rec`
    /// hears every stop of the road ([`Stats`] counts the rays).
    pub fn pixel(&self, x: u32, y: u32, rec: &mut impl Recorder) -> Vec3 {
        if self.options.view == View::Rays {
            // the colour is the number of rays this pixel cast
            let mut count = Stats::default();
            self.samples(x, y, &mut (rec, &mut count));
            return self.scales().heat(count.total());
        }
        self.samples(x, y, rec)
    }

    /// The mean of the colours the samples of pixel (x, y) bring back.
    fn samples(&self, x: u32, y: u32, rec: &mut impl Recorder) -> Vec3 {
        let samples = self.options.samples_per_pixel();
        let mut sum = Vec3::ZERO;
        for s in 0..samples {
            let ((dx, dy), ray) = self.sample_ray(x, y, (s, samples));
            rec.sample(s, dx, dy);
            let colour = self.sample_colour(&ray, rec);
            if samples == 1 {
                return colour; // the mean of one colour
            }
            sum += colour;
        }
        sum / samples as Real
    }

    /// Where sample `s` of the `n` of pixel (x, y) lies in the pixel, and its camera ray
    /// (chapter 1: r(t) = e + d·t through that point of the image).
    pub(crate) fn sample_ray(&self, x: u32, y: u32, (s, n): (u32, u32)) -> ((Real, Real), Ray) {
        let (dx, dy) = sampling::sample_position(self.options.seed, n, x, y, s);
        ((dx, dy), self.camera().pixel_ray(x, y, dx, dy))
    }
    // ANCHOR_END: ch1_pixel

    /// What the camera ray `ray` of a sample brings back: the road's camera ray, its nearest
    /// hit shown as the options' view asks ([`views::colour`]).
    #[inline]
    pub(crate) fn sample_colour(&self, ray: &Ray, rec: &mut impl Recorder) -> Vec3 {
        self.camera_ray(ray, rec, |nearest, rec| {
            views::colour(self, ray, nearest, rec)
        })
    }

    /// The ray tree of pixel (x, y): the road of [`Tracer::pixel`], every stop written down
    /// ([`inspect::ray_tree`]). Its colour is the pixel's colour bit for bit.
    #[must_use]
    pub fn inspect(&self, x: u32, y: u32) -> RayTree {
        inspect::ray_tree(self, x, y)
    }
}
