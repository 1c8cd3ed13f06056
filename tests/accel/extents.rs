//! Projection extents: the pixels a box covers, in front of the eye, around it and behind it.

use super::showcase;
use whitted::accel::Aabb;
use whitted::accel::extents::{Footprint, footprint};
use whitted::real::vec3;

/// Projection extents: a box in front of the eye covers the rectangle of its projected
/// corners, one straddling the eye plane may cover any pixel, one wholly behind it none.
#[test]
fn projection_extents_follow_the_box_around_the_eye() {
    let cam = showcase().camera.camera(64, 48); // eye (0, 2.4, 8.5) looking towards −z
    let boxed = |lo: [f64; 3], hi: [f64; 3]| Aabb {
        min: vec3(lo[0], lo[1], lo[2]),
        max: vec3(hi[0], hi[1], hi[2]),
    };
    match footprint(&boxed([-0.1, 0.8, -0.1], [0.1, 1.0, 0.1]), &cam) {
        Footprint::Rectangle([x0, x1, y0, y1]) => {
            // a small box at the point looked at: a few pixels around the image centre
            assert!(
                x0 > 20 && x1 < 44 && y0 > 14 && y1 < 34,
                "{x0} {x1} {y0} {y1}"
            );
            assert!(x0 < 32 && 32 < x1);
        }
        other => panic!("expected a rectangle, found {other:?}"),
    }
    assert_eq!(
        footprint(&boxed([-1.0, 2.0, 8.0], [1.0, 3.0, 9.0]), &cam),
        Footprint::Anywhere
    );
    assert_eq!(
        footprint(&boxed([-1.0, 2.0, 10.0], [1.0, 3.0, 12.0]), &cam),
        Footprint::Nowhere
    );
}
