//! The ways of finding a ray's nearest hit with the planet that the measurement compares: the
//! generic-object method alone, the library's nearest hit (the same, refined in the f32 build
//! by one Newton step in f64: `whitted::shapes::refine`), and fixes written here for the
//! measurement only.

use glam::DVec3;
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real};
use whitted::shapes::quadratic::stable_roots;
use whitted::shapes::{Numerics, Shape};

use super::setup::{Planet, wide3};

/// A way of finding the nearest hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The generic-object method alone: the ray carried into object space by M⁻¹, the unit
    /// sphere there ([`whitted::shapes::Shape::intersect_placed`], robust formulas).
    Generic,
    /// The library's nearest hit: [`Method::Generic`], then [`whitted::shapes::Object::refine`],
    /// which in the f32 build refines t by one Newton step in f64 (fix (c₂) on the one hit a
    /// ray shows) and in the f64 build leaves it.
    Library,
    /// (b) In world space relative to the centre C: f = e − C, a·t² + 2b·t + c = 0 with
    /// b = f·d and c = |f|² − R² (robust discriminant and roots).
    Centre,
    /// (b′) In world space relative to a point P₀ of the surface near the camera, with the
    /// outward normal n there (the centre is P₀ − R·n): g = e − P₀, b = d·g + R·(d·n),
    /// c = |g|² + 2R·(n·g). Nothing of size R² is subtracted: c is small because g is.
    Anchored,
    /// (c₁) M⁻¹ kept and applied in f64, the object-space ray then rounded to the build's
    /// precision and intersected with the unit sphere as usual.
    WideTransform,
    /// (c₂) M⁻¹ kept in f64, the transform and the unit-sphere solution done in f64; only the
    /// resulting t is rounded to the build's precision.
    Wide,
    /// (d) The tangent plane y = 0 instead of the sphere (the generic plane, placed by an
    /// exact quarter turn), measured against the plane itself.
    Plane,
}

impl Method {
    /// Every method, the generic-object method and the library's first.
    pub const ALL: [Method; 7] = [
        Method::Generic,
        Method::Library,
        Method::Centre,
        Method::Anchored,
        Method::WideTransform,
        Method::Wide,
        Method::Plane,
    ];

    /// The name in the workers' files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Generic => "generic",
            Method::Library => "library",
            Method::Centre => "centre",
            Method::Anchored => "anchored",
            Method::WideTransform => "f64-transform",
            Method::Wide => "f64",
            Method::Plane => "plane",
        }
    }

    /// The nearest hit t > 0 of the ray with the planet (with its tangent plane for
    /// [`Method::Plane`]), at the build's precision.
    pub fn nearest(self, planet: &Planet, ray: &Ray) -> Option<Real> {
        let formula = Numerics::Robust;
        match self {
            Method::Generic => planet
                .sphere
                .intersect_object_space(ray, formula)
                .first_after(0.0)
                .map(|h| h.t),
            Method::Library => planet
                .sphere
                .intersect_object_space(ray, formula)
                .first_after(0.0)
                .map(|h| planet.sphere.refine(ray, h, formula).t),
            Method::Centre => nearest_root(centre_roots(planet, ray)),
            Method::Anchored => nearest_root(anchored_roots(planet, ray)),
            Method::WideTransform => {
                let (e, d) = wide_object_ray(planet, ray);
                let narrow = |v: DVec3| Vec3::new(real(v.x), real(v.y), real(v.z));
                Shape::Sphere
                    .intersect_local(&Ray::new(narrow(e), narrow(d)), formula)
                    .first_after(0.0)
                    .map(|h| h.t)
            }
            Method::Wide => {
                let (e, d) = wide_object_ray(planet, ray);
                wide_unit_sphere(e, d).map(real)
            }
            Method::Plane => planet
                .plane
                .intersect_object_space(ray, formula)
                .first_after(0.0)
                .map(|h| h.t),
        }
    }
}

/// The smaller positive root.
fn nearest_root(roots: Option<(Real, Real)>) -> Option<Real> {
    let (t1, t2) = roots?;
    [t1, t2].into_iter().find(|t| *t > 0.0)
}

/// (b) Both roots in world space relative to the centre C: f = e − C, b = f·d, c = |f|² − R²,
/// the robust discriminant a·(R² − |f − (b/a)·d|²).
fn centre_roots(planet: &Planet, ray: &Ray) -> Option<(Real, Real)> {
    let r = planet.r;
    let (f, d) = (ray.origin - planet.centre, ray.dir);
    let (a, b) = (d.dot(d), f.dot(d));
    let c = f.dot(f) - r * r;
    let g = f - d * (b / a);
    let disc = a * (r * r - g.dot(g));
    stable_roots(a, b, c, disc)
}

/// (b′) Both roots in world space relative to the anchor P₀ ([`Planet::anchor`], the sphere's
/// top) with the outward normal n there ([`Planet::normal`]): |g + R·n|² = R² with g = e + d·t − P₀ gives
/// a·t² + 2b·t + c = 0 with a = |d|², b = d·(e − P₀) + R·(d·n), c = |e − P₀|² + 2R·n·(e − P₀).
/// (The anchor is the point below the camera; a renderer would pick it once per frame.)
pub fn anchored_roots(planet: &Planet, ray: &Ray) -> Option<(Real, Real)> {
    let (r, n) = (planet.r, planet.normal);
    let (g, d) = (ray.origin - planet.anchor, ray.dir);
    let a = d.dot(d);
    let b = d.dot(g) + r * d.dot(n);
    let c = g.dot(g) + 2.0 * r * n.dot(g);
    stable_roots(a, b, c, b * b - a * c)
}

/// The ray carried into object space by the f64 M⁻¹ ([`Planet::wide_inv`]), in f64.
fn wide_object_ray(planet: &Planet, ray: &Ray) -> (DVec3, DVec3) {
    let inv = &planet.wide_inv;
    (
        inv.transform_point3(wide3(ray.origin)),
        inv.transform_vector3(wide3(ray.dir)),
    )
}

/// The nearest hit t > 0 with the unit sphere, in f64: the library's robust formulas
/// (discriminant a·(1 − |e − (b/a)·d|²), roots q/a and c/q).
fn wide_unit_sphere(e: DVec3, d: DVec3) -> Option<f64> {
    let (a, b, c) = (d.dot(d), e.dot(d), e.dot(e) - 1.0);
    let f = e - d * (b / a);
    let disc = a * (1.0 - f.dot(f));
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let q = -(b + b.signum() * disc.sqrt());
    let (t1, t2) = (q / a, c / q);
    [t1.min(t2), t1.max(t2)].into_iter().find(|t| *t > 0.0)
}
