//! The truth the errors are measured against: the nearest hit with the sphere to f64's
//! accuracy ([`reference()`]), and how far a point lies above the surface ([`height`]), both
//! computed so that no two numbers of size R² are subtracted.

use glam::DVec3;
use whitted::ray::Ray;

use super::setup::wide3;

/// How far the point p lies above the sphere of radius r whose top is the origin: |p − c| − R
/// with c = (0, −R, 0), written as (|p − c|² − R²)/(|p − c| + R) with
/// |p − c|² − R² = x² + z² + y·(y + 2R), so that no two numbers of size R² are subtracted.
pub fn height(p: DVec3, r: f64) -> f64 {
    let k = p.x * p.x + p.z * p.z + p.y * (p.y + 2.0 * r);
    k / (DVec3::new(p.x, p.y + r, p.z).length() + r)
}

/// The reference: the nearest hit t of the ray (the build's ray, taken exactly in f64) with
/// the sphere of radius r, to f64's accuracy, or `None`. Solved in f64 relative to the
/// sphere's top, where no term of size R² is formed ([`super::fixes::anchored_roots`] in f64), then
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
