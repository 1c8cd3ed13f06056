//! The generic plane z = 0 (notes: "Generic Plane").
//!
//! e_z + d_z·t = 0 gives t = −e_z/d_z. A ray with d_z = 0 (either sign of zero) is parallel to
//! the plane and misses it: no ±∞ or NaN is ever returned. The normal is (0, 0, 1); the plane
//! is an open surface, and "entering" means hitting its +z face.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::hits::{Hit, Hits, Part};
use crate::ray::Ray;
use crate::real::Vec3;

/// Intersects an object-space ray with the plane z = 0.
#[must_use]
pub fn intersect(ray: &Ray) -> Hits {
    // BEGIN SOLUTION hit_plane
    let dz = ray.dir.z;
    if dz == 0.0 {
        return Hits::none(); // parallel to the plane
    }
    let t = -ray.origin.z / dz; // t = −e_z / d_z
    if !t.is_finite() {
        return Hits::none(); // d_z so small that the hit is beyond every number
    }
    Hits::one(Hit {
        t,
        normal: Vec3::Z,
        part: Part::Surface,
        entering: dz < 0.0,
    })
    // END SOLUTION
}
