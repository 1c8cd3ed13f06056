//! Shape timings: nanoseconds per ray–shape test, textbook against robust, at the build's
//! precision, and [`ShapeTiming`], one of them as the results keep it.

use std::time::Instant;

use serde::{Deserialize, Serialize};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3};
use whitted::shapes::{Numerics, Object, Polyhedron, Shape};
use whitted::transform::Placement;

/// One shape's ns per ray–shape test at one precision and with one formula.
#[derive(Debug, Serialize, Deserialize)]
pub struct ShapeTiming {
    /// "f32" or "f64".
    pub precision: String,
    /// The shape's name.
    pub shape: String,
    /// "Textbook" or "Robust".
    pub formula: String,
    /// Nanoseconds per test (not a number where it could not be read).
    #[serde(with = "crate::finite")]
    pub ns: f64,
}

/// Nanoseconds per ray–shape test for each shape and formula, at this build's precision:
/// 4096 fixed rays through the generic shapes, the fastest of 15 timed passes (the least
/// disturbed by whatever else the machine runs).
pub fn shape_timings() -> Vec<(String, Numerics, f64)> {
    let shapes = [
        Shape::Sphere,
        Shape::Plane,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Polyhedron(Polyhedron::cube()),
    ];
    let rays = bench_rays(4096);
    let mut out = Vec::new();
    for shape in &shapes {
        let object = Object::new(shape.clone(), Placement::identity());
        for formula in [Numerics::Textbook, Numerics::Robust] {
            let mut times = Vec::new();
            for _ in 0..15 {
                let start = Instant::now();
                let mut count = 0usize;
                for _ in 0..8 {
                    for ray in &rays {
                        count += std::hint::black_box(object.intersect(ray, formula)).len();
                    }
                }
                std::hint::black_box(count);
                times.push(start.elapsed().as_secs_f64() * 1e9 / (8 * rays.len()) as f64);
            }
            let fastest = times.iter().copied().fold(f64::INFINITY, f64::min);
            out.push((shape.name().to_string(), formula, fastest));
        }
    }
    out
}

/// Deterministic rays from a shell of radius 2–6 towards points within 1.5 of the origin
/// (about two thirds hit the generic shapes).
fn bench_rays(n: usize) -> Vec<Ray> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..n)
        .map(|_| {
            let o = Vec3::new(next() as Real, next() as Real, next() as Real);
            let o = whitted::numeric::normalize(o) * (4.0 + 2.0 * next()) as Real;
            let t = Vec3::new(next() as Real, next() as Real, next() as Real) * 1.5;
            Ray::new(o, t - o)
        })
        .collect()
}
