//! Micro-benchmark: the cost of one ray–shape test, per shape, textbook against robust formulas.
//!
//! Each benchmark intersects the same 1024 fixed rays (from a shell of radius 4–6 towards
//! points within 1.5 of the origin, about two thirds hitting) with one generic shape; criterion
//! reports the time per ray (throughput in elements). Run it once per precision:
//!
//! ```text
//! cargo bench --bench shapes                  # f64
//! cargo bench --bench shapes --features f32   # f32
//! ```

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_main};
use whitted::ray::Ray;
use whitted::real::{PRECISION, Real, Vec3};
use whitted::shapes::{Numerics, Object, Polyhedron, Shape};
use whitted::transform::Placement;

/// 1024 deterministic rays (xorshift), the same in both precisions up to rounding.
fn rays() -> Vec<Ray> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..1024)
        .map(|_| {
            let o = Vec3::new(next() as Real, next() as Real, next() as Real);
            let o = whitted::numeric::normalize(o) * (5.0 + next()) as Real;
            let t = Vec3::new(next() as Real, next() as Real, next() as Real) * 1.5;
            Ray::new(o, t - o)
        })
        .collect()
}

fn shapes(c: &mut Criterion) {
    let rays = rays();
    let mut group = c.benchmark_group(format!("ray-shape-{PRECISION}"));
    group.throughput(Throughput::Elements(rays.len() as u64));
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    for shape in [
        Shape::Sphere,
        Shape::Plane,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Polyhedron(Polyhedron::cube()),
    ] {
        let object = Object::new(shape.clone(), Placement::identity());
        for numerics in [Numerics::Textbook, Numerics::Robust] {
            let name = format!("{}/{numerics:?}", shape.name());
            group.bench_function(name, |b| {
                b.iter(|| {
                    let mut count = 0usize;
                    for ray in &rays {
                        count += black_box(object.intersect(black_box(ray), numerics)).len();
                    }
                    count
                });
            });
        }
    }
    group.finish();
}

/// criterion's entry points (in a private module: the generated functions carry no docs).
mod entry {
    criterion::criterion_group!(benches, super::shapes);
}

criterion_main!(entry::benches);
