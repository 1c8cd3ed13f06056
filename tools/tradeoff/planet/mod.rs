//! A huge object seen from close by: a planet-sized sphere as the ground, the camera about
//! one unit above it.
//!
//! whitted intersects every object by the generic-object method: the world ray is carried
//! into the object's own space by M⁻¹ and meets the unit sphere there. For a sphere of radius
//! R the camera, one unit above the surface, lands at distance 1 + 1/R from the unit sphere's
//! centre, so the hit is known only to about R·u world units (u the unit roundoff). Each
//! worker measures, at its build's precision, for R = 1e3 … 1e7 and rays from the camera at
//! a few angles below the horizon:
//!
//! - how far the hit found lies from the true surface, and how far along the ray from the
//!   true hit (against an f64 reference computed in world space, see [`reference()`]), for the
//!   library's method and for the fixes of [`fixes`];
//! - the share of lit hit points whose feeler ray meets the planet again (shadow acne) under
//!   each offset strategy, and how far the error-bound offset pushes feelers out;
//! - the time per ray of each method.
//!
//! The sphere is placed as the scene file places `sphere = { center = [0, −R, 0], radius = R }`
//! (scale R, then translate): its top is the world origin, so every world coordinate the rays
//! and hits have is small, and the error measured is the method's, not the scene's.

pub mod fixes;
pub mod report;

use std::fmt::Write as _;
use std::path::Path;

use glam::{DMat4, DVec3};
use whitted::offset::{OffsetKind, SpawnPoint};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::shadow;
use whitted::shapes::{Numerics, Object, Shape};
use whitted::transform::{Placement, Step, rotation_from_z};

use crate::measure::{median, wide};
use fixes::Method;

/// The radii measured (world units).
pub const RADII: [f64; 5] = [1e3, 1e4, 1e5, 1e6, 1e7];
/// The rays' angles below the horizontal, in degrees, steep to grazing. The horizon of a
/// sphere of radius R seen from height h lies √(2h/R) radians below the horizontal: 2.6° for
/// R = 1e3, so every ray here meets every sphere.
pub const ANGLES: [f64; 4] = [90.0, 30.0, 10.0, 3.0];
/// Rays per radius and angle.
pub const RAYS: usize = 1000;
/// The light of the shadow-acne test, high above the patch the rays hit.
pub const LIGHT: [f64; 3] = [400.0, 1000.0, 300.0];

/// A planet of radius R: the sphere as the scene loader places it, and what the fixes need.
pub struct Planet {
    /// R, as the scene file gives it (every radius measured is exact in f32 and f64).
    pub radius: f64,
    /// The sphere placed by M = translate (0, −R, 0) · scale R: its top is the origin.
    pub sphere: Object,
    /// Fix (d): the plane y = 0, tangent to the sphere at its top.
    pub plane: Object,
    /// Fix (b): the centre (0, −R, 0) at the build's precision.
    pub centre: Vec3,
    /// R at the build's precision.
    pub r: Real,
    /// Fix (b′): a point of the surface near the camera, the top (0, 0, 0), chosen once, as a
    /// renderer would once per frame.
    pub anchor: Vec3,
    /// Fix (b′): the outward normal at the anchor, (0, 1, 0).
    pub normal: Vec3,
    /// Fixes (c₁) and (c₂): M⁻¹ = scale 1/R · translate (0, R, 0), built in f64.
    pub wide_inv: DMat4,
}

impl Planet {
    /// The planet of radius `radius`.
    pub fn new(radius: f64) -> Self {
        let steps = [
            Step::Scale(Vec3::splat(real(radius))),
            Step::Translate(vec3(0.0, -radius, 0.0)),
        ];
        let placement = Placement::from_steps(&steps).expect("a non-zero radius");
        let up = Placement::from_steps(&[rotation_from_z(Vec3::Y)]).expect("a rotation");
        Self {
            radius,
            sphere: Object::new(Shape::Sphere, placement),
            plane: Object::new(Shape::Plane, up),
            centre: vec3(0.0, -radius, 0.0),
            r: real(radius),
            anchor: Vec3::ZERO,
            normal: Vec3::Y,
            wide_inv: DMat4::from_scale(DVec3::splat(1.0 / radius))
                * DMat4::from_translation(DVec3::new(0.0, radius, 0.0)),
        }
    }
}

/// One camera ray: the ray at the build's precision and the number of its angle in
/// [`ANGLES`].
pub struct Sample {
    pub ray: Ray,
    pub angle: usize,
}

/// The rays of every angle: each from a camera at (x, 1 ± 0.1, z) with |x|, |z| ≤ 1, at a
/// random azimuth. The same f64 numbers in every build (then rounded to [`Real`]).
pub fn samples() -> Vec<Sample> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut out = Vec::with_capacity(ANGLES.len() * RAYS);
    for (angle, degrees) in ANGLES.iter().enumerate() {
        let (down, level) = degrees.to_radians().sin_cos();
        for _ in 0..RAYS {
            let e = vec3(next(), 1.0 + 0.1 * next(), next());
            let (s, c) = (std::f64::consts::PI * next()).sin_cos();
            let d = vec3(level * c, -down, level * s);
            out.push(Sample {
                ray: Ray::new(e, d),
                angle,
            });
        }
    }
    out
}

/// A vector of [`Real`] as f64.
fn wide3(v: Vec3) -> DVec3 {
    DVec3::new(wide(v.x), wide(v.y), wide(v.z))
}

/// How far the point p lies above the sphere of radius r whose top is the origin: |p − c| − R
/// with c = (0, −R, 0), written as (|p − c|² − R²)/(|p − c| + R) with
/// |p − c|² − R² = x² + z² + y·(y + 2R), so that no two numbers of size R² are subtracted.
pub fn height(p: DVec3, r: f64) -> f64 {
    let k = p.x * p.x + p.z * p.z + p.y * (p.y + 2.0 * r);
    k / (DVec3::new(p.x, p.y + r, p.z).length() + r)
}

/// The reference: the nearest hit t of the ray (the build's ray, taken exactly in f64) with
/// the sphere of radius r, to f64's accuracy, or `None`. Solved in f64 relative to the
/// sphere's top, where no term of size R² is formed ([`fixes::anchored_roots`] in f64), then
/// polished by a Newton step on the height along the ray.
pub fn reference(ray: &Ray, r: f64) -> Option<f64> {
    let (e, d) = (wide3(ray.origin), wide3(ray.dir));
    let a = d.dot(d);
    let b = d.dot(e) + r * d.y;
    let c = e.dot(e) + 2.0 * r * e.y;
    let disc = b * b - a * c;
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let q = -(b + b.signum() * disc.sqrt());
    let t = [q / a, c / q]
        .into_iter()
        .filter(|t| *t > 0.0)
        .fold(f64::INFINITY, f64::min);
    if !t.is_finite() {
        return None;
    }
    let p = e + d * t;
    let n = DVec3::new(p.x, p.y + r, p.z).normalize();
    Some(t - height(p, r) / d.dot(n))
}

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

/// Shadow acne on the planet: for each offset strategy, the share of lit hit points (found by
/// the library's method) whose feeler towards [`LIGHT`] meets the planet again, then the
/// median push of the error-bound offset (world units), then the share under the classic
/// fixed ε when the hits and the feelers are found by the anchored fix (b′).
pub fn acne(planet: &Planet, samples: &[Sample]) -> ([f64; 3], f64, f64) {
    let light = vec3(LIGHT[0], LIGHT[1], LIGHT[2]);
    let formula = Numerics::Robust;
    let (mut lit, mut blocked, mut pushes) = (0usize, [0usize; 3], Vec::new());
    let (mut lit_fixed, mut blocked_fixed) = (0usize, 0usize);
    for s in samples {
        if let Some(hit) = planet.sphere.intersect(&s.ray, formula).first_after(0.0) {
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

/// Everything a worker measures on the planets, as the lines of `planet.tsv`:
/// `hit R angle method both disagree surface along distance`, `acne R fixed scaled
/// error-bound push anchored-fixed` and `cost method ns`.
pub fn measure_all() -> String {
    let samples = samples();
    let planets: Vec<Planet> = RADII.iter().map(|&r| Planet::new(r)).collect();
    let mut out = String::new();
    for planet in &planets {
        for method in Method::ALL {
            for (angle, e) in hit_errors(planet, &samples, method).iter().enumerate() {
                let _ = writeln!(
                    out,
                    "hit\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}",
                    planet.radius,
                    ANGLES[angle],
                    method.name(),
                    e.both,
                    e.disagree,
                    e.surface,
                    e.along,
                    e.distance
                );
            }
        }
        let ([fixed, scaled, bound], push, anchored) = acne(planet, &samples);
        let _ = writeln!(
            out,
            "acne\t{}\t{fixed}\t{scaled}\t{bound}\t{push}\t{anchored}",
            planet.radius
        );
    }
    for (method, ns) in costs(&planets, &samples) {
        let _ = writeln!(out, "cost\t{}\t{ns}", method.name());
    }
    out
}

/// One worker's planet measurements, read back from `planet.tsv`.
#[derive(Default)]
pub struct Measured {
    /// (R, angle, method) and the errors.
    pub hits: Vec<(f64, f64, String, HitError)>,
    /// R, the acne share under fixed, scaled and error-bound, the error-bound push, and the
    /// share under fixed ε with the anchored fix.
    pub acne: Vec<(f64, [f64; 3], f64, f64)>,
    /// Method and ns per ray.
    pub costs: Vec<(String, f64)>,
}

impl Measured {
    /// The lines of a worker's `planet.tsv`.
    pub fn lines(dir: &Path) -> Result<Vec<String>, String> {
        let path = dir.join("planet.tsv");
        let text = std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        Ok(text.lines().map(str::to_string).collect())
    }

    /// Parses the lines of a worker's `planet.tsv` (`origin` names them in errors).
    pub fn parse(lines: &[String], origin: &str) -> Result<Self, String> {
        let bad = |line: &str| format!("{origin}: cannot read `{line}`");
        let mut m = Measured::default();
        for line in lines {
            let f: Vec<&str> = line.split('\t').collect();
            let num = |i: usize| f.get(i).and_then(|s| s.parse::<f64>().ok());
            match f[0] {
                "hit" => {
                    let e = HitError {
                        both: num(4).ok_or_else(|| bad(line))? as usize,
                        disagree: num(5).ok_or_else(|| bad(line))? as usize,
                        surface: num(6).ok_or_else(|| bad(line))?,
                        along: num(7).ok_or_else(|| bad(line))?,
                        distance: num(8).ok_or_else(|| bad(line))?,
                    };
                    let (r, a) = (
                        num(1).ok_or_else(|| bad(line))?,
                        num(2).ok_or_else(|| bad(line))?,
                    );
                    m.hits.push((r, a, f[3].to_string(), e));
                }
                "acne" => {
                    let v: Option<Vec<f64>> = (1..7).map(num).collect();
                    let v = v.ok_or_else(|| bad(line))?;
                    m.acne.push((v[0], [v[1], v[2], v[3]], v[4], v[5]));
                }
                "cost" => {
                    let ns = num(2).ok_or_else(|| bad(line))?;
                    m.costs.push((f[1].to_string(), ns));
                }
                _ => return Err(bad(line)),
            }
        }
        Ok(m)
    }

    /// The errors of `method` at radius `r` and angle `a`.
    pub fn hit(&self, r: f64, a: f64, method: Method) -> Option<&HitError> {
        self.hits
            .iter()
            .find(|h| h.0 == r && h.1 == a && h.2 == method.name())
            .map(|h| &h.3)
    }

    /// The errors of `method` at radius `r`, worst over the angles (disagreements summed).
    pub fn worst(&self, r: f64, method: Method) -> HitError {
        let mut w = HitError::default();
        for h in self
            .hits
            .iter()
            .filter(|h| h.0 == r && h.2 == method.name())
        {
            w.both += h.3.both;
            w.disagree += h.3.disagree;
            w.surface = w.surface.max(h.3.surface);
            w.along = w.along.max(h.3.along);
        }
        w
    }

    /// ns per ray of `method`.
    pub fn cost(&self, method: Method) -> f64 {
        self.costs
            .iter()
            .find(|c| c.0 == method.name())
            .map_or(f64::NAN, |c| c.1)
    }
}
