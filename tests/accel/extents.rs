//! Projection extents: the pixels a box covers, in front of the eye, around it and behind it.

use super::showcase;
use whitted::accel::extents::{Footprint, footprint};
use whitted::accel::{Aabb, Extents};
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

/// The road hands the structure a camera ray, not a pixel: the extents read the ray's pixel
/// off its direction. For every pixel of the showcase at 64 × 48 and sample positions across
/// it (its corners included), the pixel found is the ray's own or a neighbour (at a pixel's
/// edge rounding may tip it over, within the pixel of padding every rectangle has), and never
/// outside the image.
#[test]
fn a_camera_rays_pixel_is_found_from_its_direction() {
    let cam = showcase().camera.camera(64, 48);
    let extents = Extents::build(&[], &cam, 16);
    let mut exact = 0;
    for y in 0..48 {
        for x in 0..64 {
            for (dx, dy) in [
                (0.5, 0.5),
                (0.0, 0.0),
                (0.999, 0.999),
                (0.0, 0.999),
                (0.25, 0.75),
            ] {
                let ray = cam.pixel_ray(x, y, dx, dy);
                let (px, py) = extents.pixel_of(ray.dir);
                assert!(
                    px < 64 && py < 48,
                    "({x}, {y}) + ({dx}, {dy}) → ({px}, {py})"
                );
                assert!(
                    px.abs_diff(x) <= 1 && py.abs_diff(y) <= 1,
                    "({x}, {y}) + ({dx}, {dy}) → ({px}, {py})"
                );
                exact += usize::from((px, py) == (x, y));
            }
        }
    }
    assert!(
        exact >= 64 * 48 * 4,
        "only {exact} rays found their own pixel"
    );
}
