//! The generic plane z = 0: hit at t = −e_z/d_z, and parallel rays ("Generic Plane").

use super::*;
use whitted::shapes::plane;

/// "Generic Plane": t = −e_z/d_z, normal (0, 0, 1); the hit enters from the +z side (d_z < 0)
/// and leaves towards it (d_z > 0).
#[test]
fn ex_hit_plane_plane_is_hit_at_minus_ez_over_dz() {
    let above = "from (3, −1, 2) along (1, 0, −0.5)";
    let hits = plane::intersect(&ray([3.0, -1.0, 2.0], [1.0, 0.0, -0.5]));
    assert_hits(above, &hits, &[(4.0, Part::Surface)]);
    assert_normal(above, &hits, 0, Vec3::Z, TOL);
    assert_entering(&format!("{above}, from the +z side"), &hits, &[true]);
    let below = "from (0, 0, −2) along (0, 0, 4)";
    let hits = plane::intersect(&ray([0.0, 0.0, -2.0], [0.0, 0.0, 4.0]));
    assert_hits(below, &hits, &[(0.5, Part::Surface)]);
    assert_entering(&format!("{below}, from the −z side"), &hits, &[false]);
}

/// "Generic Plane": a ray with d_z = 0 is parallel and misses — never ±∞ or NaN, for +0 and −0,
/// whether it starts off the plane or on it; so does one whose −e_z/d_z overflows.
#[test]
fn ex_hit_plane_ray_parallel_to_the_plane_misses() {
    for dz in [0.0, -0.0] {
        for ez in [1.0, 0.0, -1.0] {
            let hits = plane::intersect(&ray([0.0, 0.0, ez], [1.0, 2.0, dz]));
            assert!(
                hits.is_empty(),
                "the ray from (0, 0, {ez}) along (1, 2, {dz}), parallel, misses: {hits:?}"
            );
        }
    }
    // a d_z so small that −e_z/d_z overflows: the hit is beyond every number, so none
    let far = Ray::new(
        Vec3::new(0.0, 0.0, Real::MAX),
        Vec3::new(1.0, 0.0, -Real::MIN_POSITIVE),
    );
    let hits = plane::intersect(&far);
    assert!(
        hits.is_empty(),
        "the ray from e_z = {} along d_z = {}: −e_z/d_z overflows, so it misses: {hits:?}",
        Real::MAX,
        -Real::MIN_POSITIVE
    );
}
