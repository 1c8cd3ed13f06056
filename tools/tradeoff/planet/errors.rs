//! The measurements on one planet: each method's hit errors against the truth, shadow acne
//! under each offset strategy, and each method's cost per ray.

use whitted::offset::{OffsetKind, SpawnPoint};
use whitted::real::{Vec3, vec3};
use whitted::shadow;
use whitted::shapes::Numerics;

use super::fixes::{self, Method};
use super::setup::{ANGLES, LIGHT, Planet, Sample, wide3};
use super::truth::{height, reference};
use crate::measure::{median, wide};

/// The errors of one method at one radius and angle, over the rays both it and the reference
/// hit.
#[derive(Clone, Copy, Debug, Default)]
pub struct HitError {
    /// Rays both hit.
    pub both: usize,
    /// Rays one hits and the other misses.
    pub disagree: usize,
    /// The largest distance of a hit point from the true surface (world units).
    pub surface: f64,
    /// The largest distance along the ray from the true hit (world units).
    pub along: f64,
    /// The mean distance to the true hit.
    pub distance: f64,
}

/// The errors of `method` on the planet for each angle.
pub fn hit_errors(planet: &Planet, samples: &[Sample], method: Method) -> Vec<HitError> {
    let mut out = vec![HitError::default(); ANGLES.len()];
    for s in samples {
        let found = method.nearest(planet, &s.ray).map(wide);
        let (e, d) = (wide3(s.ray.origin), wide3(s.ray.dir));
        // the plane is measured against itself: y = 0
        let truth = match method {
            Method::Plane => Some(-e.y / d.y).filter(|t| *t > 0.0),
            _ => reference(&s.ray, planet.radius),
        };
        let err = &mut out[s.angle];
        match (found, truth) {
            (Some(t), Some(t_ref)) => {
                let p = e + d * t;
                let off = match method {
                    Method::Plane => p.y,
                    _ => height(p, planet.radius),
                };
                err.both += 1;
                err.surface = err.surface.max(off.abs());
                err.along = err.along.max((t - t_ref).abs() * d.length());
                err.distance += t_ref * d.length();
            }
            (None, None) => {}
            _ => err.disagree += 1,
        }
    }
    for err in &mut out {
        err.distance /= err.both.max(1) as f64;
    }
    out
}

/// Shadow acne on the planet: for each offset strategy, the share of lit hit points (the
/// library's, [`Method::Library`]) whose feeler towards [`LIGHT`] meets the planet again, then the
/// median push of the error-bound offset (world units), then the share under the classic
/// fixed ε when the hits and the feelers are found by the anchored fix (b′).
pub fn acne(planet: &Planet, samples: &[Sample]) -> ([f64; 3], f64, f64) {
    let light = vec3(LIGHT[0], LIGHT[1], LIGHT[2]);
    let formula = Numerics::Robust;
    let (mut lit, mut blocked, mut pushes) = (0usize, [0usize; 3], Vec::new());
    let (mut lit_fixed, mut blocked_fixed) = (0usize, 0usize);
    for s in samples {
        if let Some(hit) = planet.sphere.intersect(&s.ray, formula).first_after(0.0) {
            // the hit as the road shades it (in the f32 build, its t refined)
            let hit = planet.sphere.refine(&s.ray, hit, formula);
            let p = s.ray.at(hit.t);
            // the tracer's test: the light is on the outer side of the surface
            if hit.normal.dot(light - p) > 0.0 {
                lit += 1;
                let spawn = SpawnPoint::new(&planet.sphere, &s.ray, &hit);
                for (k, kind) in OffsetKind::ALL.into_iter().enumerate() {
                    let (start, u_min) = kind.offset().spawn(&spawn, light - p);
                    let feeler = shadow::feeler(start, light);
                    if shadow::blocks(&planet.sphere.intersect(&feeler, formula), u_min) {
                        blocked[k] += 1;
                    }
                }
                pushes.push(wide(hit.normal.abs().dot(spawn.error)));
            }
        }
        if let Some(t) = Method::Anchored.nearest(planet, &s.ray) {
            let p = s.ray.at(t);
            // the outward normal of the sphere at p, (p − c)/R
            let n = (p - planet.centre).normalize();
            if n.dot(light - p) > 0.0 {
                lit_fixed += 1;
                let (start, u_min) = OffsetKind::Fixed.offset().spawn(
                    &SpawnPoint {
                        p,
                        normal: n,
                        refined: p,
                        error: Vec3::ZERO,
                    },
                    light - p,
                );
                let feeler = shadow::feeler(start, light);
                let roots = fixes::anchored_roots(planet, &feeler);
                if roots.is_some_and(|(t1, t2)| [t1, t2].iter().any(|t| *t > u_min && *t <= 1.0)) {
                    blocked_fixed += 1;
                }
            }
        }
    }
    let share = |b: usize, n: usize| b as f64 / n.max(1) as f64;
    (
        blocked.map(|b| share(b, lit)),
        median(pushes),
        share(blocked_fixed, lit_fixed),
    )
}

/// Nanoseconds per ray for each method to find the nearest hit with the planet (all radii,
/// one thread, the fastest of 15 passes).
pub fn costs(planets: &[Planet], samples: &[Sample]) -> Vec<(Method, f64)> {
    Method::ALL
        .into_iter()
        .map(|method| {
            let mut fastest = f64::INFINITY;
            for _ in 0..15 {
                let start = std::time::Instant::now();
                let mut count = 0usize;
                for planet in planets {
                    for s in samples {
                        count +=
                            std::hint::black_box(method.nearest(planet, &s.ray)).is_some() as usize;
                    }
                }
                std::hint::black_box(count);
                let ns =
                    start.elapsed().as_secs_f64() * 1e9 / (planets.len() * samples.len()) as f64;
                fastest = fastest.min(ns);
            }
            (method, fastest)
        })
        .collect()
}
