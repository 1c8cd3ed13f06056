//! The BVH: a distribution its SAH bins would peel one object at a time stays walkable.

use whitted::accel::aabb::RayBox;
use whitted::accel::{Aabb, Bvh};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, vec3};

/// A distribution the SAH bins would peel one object at a time (centres in a geometric
/// progression) still gives a tree shallow enough to walk, which finds every box.
#[test]
fn a_bvh_over_a_geometric_progression_stays_walkable() {
    let boxes: Vec<Aabb> = (0..3000)
        .map(|i| {
            let x = (1.01 as Real).powi(i);
            Aabb {
                min: vec3(0.0, 0.0, 0.0) + Vec3::X * x,
                max: Vec3::new(x + 0.5, 1.0, 1.0),
            }
        })
        .collect();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(vec3(-1.0, 0.5, 0.5), vec3(1.0, 0.0, 0.0));
    let mut limit = Real::INFINITY;
    let mut seen = vec![false; boxes.len()];
    bvh.walk(&RayBox::new(&ray), 0.0, &mut limit, |k, _| {
        seen[bvh.order()[k as usize] as usize] = true;
        true
    });
    assert!(
        seen.iter().all(|&s| s),
        "the walk along the row must meet every box"
    );
}
