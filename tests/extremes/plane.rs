//! The plane: d_z = ±0 (and a d_z so small that t overflows).

use super::{all_finite, hits};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3};
use whitted::shapes::{Numerics, Object, Shape};
use whitted::transform::Placement;

/// Notes, "Generic Plane": t = −e_z/d_z, and "if d_z = 0 the ray is parallel to the plane and
/// does not intersect it". Printed as is, the formula gives ±∞ for d_z = ±0 and NaN for a ray
/// lying in the plane; whitted's plane returns no hit for either zero, and none for a d_z so
/// small that t overflows.
#[test]
fn ray_parallel_to_the_plane_misses_with_either_sign_of_zero() {
    let plane = Object::new(Shape::Plane, Placement::identity());
    let tiny = Real::MIN_POSITIVE * Real::EPSILON; // the smallest subnormal
    for ez in [1.0, 0.0, -1.0] {
        for dz in [0.0, -0.0, tiny, -tiny] {
            let ray = Ray::new(Vec3::new(0.0, 0.0, ez), Vec3::new(1.0, 0.0, dz));
            let hs = hits(&plane, &ray, Numerics::Robust);
            assert!(all_finite(&hs), "e_z {ez} d_z {dz}: {hs:?}");
            if dz == 0.0 {
                assert!(hs.is_empty(), "e_z {ez} d_z {dz}: {hs:?}");
                let naive = -ray.origin.z / ray.dir.z; // the notes' t = −e_z/d_z
                assert!(!naive.is_finite());
            }
        }
    }
}
