//! Chapter 1 — camera rays (notes: "Principles of Ray Tracing").
//!
//! Hand-computed values for H = N·tan(θ/2), W = H·A, (u_c, v_r) and
//! d = −N·n + W(2c/n − 1)·u + H(2r/m − 1)·v.

mod common;

use approx::assert_abs_diff_eq;
use common::{TOL, assert_vec_eq, centre, chapter_scene};
use whitted::camera::{
    Camera, direction_colour, near_plane_half_height, near_plane_half_width, pixel_on_near_plane,
    viewing_basis,
};
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::Chapter;

/// A camera at the origin looking down −z (so n = +z, u = +x, v = +y).
fn straight_camera(fov: Real, near: Real, columns: u32, rows: u32) -> Camera {
    Camera::new(
        Vec3::ZERO,
        vec3(0.0, 0.0, -1.0),
        Vec3::Y,
        fov,
        near,
        columns,
        rows,
    )
    .unwrap()
}

/// "Principles of Ray Tracing": H = N·tan(π/180·θ/2) for several θ and N.
#[test]
fn ex_near_plane_half_height_half_height_is_near_times_tangent_of_half_the_angle() {
    assert_abs_diff_eq!(near_plane_half_height(1.0, 90.0), 1.0, epsilon = TOL); // tan 45° = 1
    assert_abs_diff_eq!(
        near_plane_half_height(2.0, 60.0),
        2.0 / (3.0 as Real).sqrt(),
        epsilon = TOL
    ); // 2·tan 30°
    assert_abs_diff_eq!(
        near_plane_half_height(1.0, 45.0),
        (2.0 as Real).sqrt() - 1.0,
        epsilon = TOL
    ); // tan 22.5°
    assert_abs_diff_eq!(
        near_plane_half_height(0.5, 120.0),
        0.5 * (3.0 as Real).sqrt(),
        epsilon = TOL
    ); // ½·tan 60°
    // H grows with N: the near plane twice as far is twice as tall
    assert_abs_diff_eq!(
        near_plane_half_height(2.0, 73.0),
        2.0 * near_plane_half_height(1.0, 73.0),
        epsilon = TOL
    );
}

/// "Principles of Ray Tracing": the angle is in degrees; reading it as radians is wrong.
#[test]
fn ex_near_plane_half_height_viewing_angle_is_converted_from_degrees() {
    let h = near_plane_half_height(1.0, 60.0);
    let as_radians = (60.0 as Real / 2.0).tan(); // tan(30 rad) ≈ −6.405
    assert!(
        (h - as_radians).abs() > 1.0,
        "θ must be converted to radians first"
    );
    assert_abs_diff_eq!(h, real(0.577_350_269_189_625_8), epsilon = TOL);
}

/// "Principles of Ray Tracing": W = H·A with A = width/height, for several aspects.
#[test]
fn ex_near_plane_half_width_half_width_is_half_height_times_aspect() {
    let h = near_plane_half_height(1.0, 90.0);
    assert_abs_diff_eq!(
        near_plane_half_width(h, 4.0 / 3.0),
        4.0 / 3.0,
        epsilon = TOL
    );
    assert_abs_diff_eq!(
        near_plane_half_width(h, 16.0 / 9.0),
        16.0 / 9.0,
        epsilon = TOL
    );
    assert_abs_diff_eq!(near_plane_half_width(h, 1.0), 1.0, epsilon = TOL);
    let cam = straight_camera(60.0, 2.0, 640, 480);
    assert_abs_diff_eq!(
        cam.half_width(),
        cam.half_height() * 640.0 / 480.0,
        epsilon = TOL
    );
    assert_abs_diff_eq!(cam.half_height(), 2.0 / (3.0 as Real).sqrt(), epsilon = TOL);
}

/// "Principles of Ray Tracing": (u_c, v_r) = (−W + W·2c/n, −H + H·2r/m) puts c = r = 0 on the
/// lower-left corner (−W, −H), c = n, r = m on the upper-right (W, H) and the middle on (0, 0).
#[test]
fn ex_pixel_on_near_plane_pixel_formula_spans_the_near_plane_corner_to_corner() {
    let (w, h) = (2.0, 1.5);
    let (n, m) = (8.0, 6.0);
    let at = |c, r| pixel_on_near_plane(c, r, n, m, w, h);
    let close =
        |(a, b): (Real, Real), (x, y): (Real, Real)| (a - x).abs() <= TOL && (b - y).abs() <= TOL;
    assert!(close(at(0.0, 0.0), (-2.0, -1.5)));
    assert!(close(at(8.0, 0.0), (2.0, -1.5)));
    assert!(close(at(0.0, 6.0), (-2.0, 1.5)));
    assert!(close(at(8.0, 6.0), (2.0, 1.5)));
    assert!(close(at(4.0, 3.0), (0.0, 0.0)));
    // one pixel in: W·2/n = 0.5 and H·2/m = 0.5 further
    assert!(close(at(1.0, 1.0), (-1.5, -1.0)));
    // the centres of the first and last column and row, c = ½ and c = n − ½: W·(1/8 − 1) = −1.75
    // and W·(15/8 − 1) = 1.75; H·(1/6 − 1) = −1.25 and H·(11/6 − 1) = 1.25
    assert!(close(at(0.5, 0.5), (-1.75, -1.25)));
    assert!(close(at(7.5, 5.5), (1.75, 1.25)));
}

/// "Principles of Ray Tracing": the viewing coordinates u, v, n are orthonormal, n points from
/// the scene back to the eye, u to the right.
#[test]
fn ex_viewing_basis_is_orthonormal_and_n_points_back_to_the_eye() {
    let (u, v, n) = viewing_basis(vec3(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
    assert_vec_eq(n, Vec3::Z, TOL);
    assert_vec_eq(u, Vec3::X, TOL);
    assert_vec_eq(v, Vec3::Y, TOL);

    // looking from +x towards the origin: n = +x, u = up × n = −z, v = +y
    let (u, v, n) = viewing_basis(vec3(3.0, 0.0, 0.0), Vec3::ZERO, Vec3::Y).unwrap();
    assert_vec_eq(n, Vec3::X, TOL);
    assert_vec_eq(u, Vec3::NEG_Z, TOL);
    assert_vec_eq(v, Vec3::Y, TOL);

    // a tilted view still gives an orthonormal basis
    let (u, v, n) = viewing_basis(vec3(1.0, 2.0, 3.0), vec3(-1.0, 0.5, 0.0), Vec3::Y).unwrap();
    for (a, b) in [(u, v), (v, n), (n, u)] {
        assert_abs_diff_eq!(a.dot(b), 0.0, epsilon = TOL);
    }
    for x in [u, v, n] {
        assert_abs_diff_eq!(x.length(), 1.0, epsilon = TOL);
    }
    assert_abs_diff_eq!(u.cross(v).dot(n), 1.0, epsilon = TOL); // right-handed
}

/// "Principles of Ray Tracing": an up vector parallel to the view direction gives no basis.
#[test]
fn ex_viewing_basis_up_parallel_to_the_view_direction_has_no_basis() {
    assert!(viewing_basis(vec3(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y).is_none());
    assert!(viewing_basis(Vec3::ZERO, Vec3::ZERO, Vec3::Y).is_none());
}

/// "Principles of Ray Tracing": `up` only says which way is up; its part along the view
/// direction does not count. From (0, 0, 5) looking at the origin, n = (0, 0, 1), and up =
/// (0, 1, 1) gives the same basis as (0, 1, 0): u = (1, 0, 0), v = (0, 1, 0). For a tilted
/// view, up = y + 3n gives the basis of up = y.
#[test]
fn ex_viewing_basis_an_up_not_perpendicular_to_the_view_gives_the_same_basis() {
    let (u, v, n) = viewing_basis(vec3(0.0, 0.0, 5.0), Vec3::ZERO, vec3(0.0, 1.0, 1.0)).unwrap();
    assert_vec_eq(u, Vec3::X, TOL);
    assert_vec_eq(v, Vec3::Y, TOL);
    assert_vec_eq(n, Vec3::Z, TOL);
    let (eye, look_at) = (vec3(1.0, 2.0, 3.0), vec3(-1.0, 0.5, 0.0));
    let (u, v, n) = viewing_basis(eye, look_at, Vec3::Y).unwrap();
    let (u2, v2, n2) = viewing_basis(eye, look_at, Vec3::Y + 3.0 * n).unwrap();
    assert_vec_eq(u2, u, 10.0 * TOL);
    assert_vec_eq(v2, v, 10.0 * TOL);
    assert_vec_eq(n2, n, TOL);
    // n is the unit vector from look_at to the eye: (2, 1.5, 3)/√15.25
    assert_vec_eq(n, vec3(2.0, 1.5, 3.0) / (15.25 as Real).sqrt(), TOL);
}

/// "Principles of Ray Tracing": d = −N·n + W(2c/n − 1)·u + H(2r/m − 1)·v at the four corner
/// pixels of a 4 × 2 window with θ = 90°, N = 1 (H = 1, W = 2).
#[test]
fn ex_ray_direction_direction_at_the_four_corners() {
    let cam = straight_camera(90.0, 1.0, 4, 2);
    assert_abs_diff_eq!(cam.half_height(), 1.0, epsilon = TOL);
    assert_abs_diff_eq!(cam.half_width(), 2.0, epsilon = TOL);
    assert_vec_eq(cam.direction(0.0, 0.0), vec3(-2.0, -1.0, -1.0), TOL);
    assert_vec_eq(cam.direction(4.0, 0.0), vec3(2.0, -1.0, -1.0), TOL);
    assert_vec_eq(cam.direction(0.0, 2.0), vec3(-2.0, 1.0, -1.0), TOL);
    assert_vec_eq(cam.direction(4.0, 2.0), vec3(2.0, 1.0, -1.0), TOL);
    assert_vec_eq(cam.direction(2.0, 1.0), vec3(0.0, 0.0, -1.0), TOL); // the centre looks along −n
}

/// A camera looking down and sideways from (1, 2, 3): θ = 50°, N = 2.5, 320 × 200 pixels.
fn tilted_camera() -> Camera {
    Camera::new(
        vec3(1.0, 2.0, 3.0),
        vec3(-1.0, 0.5, 0.0),
        Vec3::Y,
        50.0,
        2.5,
        320,
        200,
    )
    .unwrap()
}

/// "Principles of Ray Tracing": e + d is the pixel's point on the near plane, at distance N in
/// front of the eye: d·(−n) = N for every pixel, and the middle of the image, (n/2, m/2),
/// looks straight along −n, d = −N·n (a tilted camera, N = 2.5, 320 × 200).
#[test]
fn ex_ray_direction_every_direction_reaches_the_near_plane() {
    let cam = tilted_camera();
    for (c, r) in [
        (0.0, 0.0),
        (320.0, 200.0),
        (37.5, 150.5),
        (319.5, 0.5),
        (160.0, 3.0),
    ] {
        let d = cam.direction(c, r);
        assert_abs_diff_eq!(d.dot(-cam.n()), 2.5, epsilon = 10.0 * TOL);
    }
    assert_vec_eq(cam.direction(160.0, 100.0), -2.5 * cam.n(), 10.0 * TOL);
}

/// "Principles of Ray Tracing": r(t) = e + d·t with d as above reaches the near plane at t = 1,
/// at the world point u_c·u + v_r·v − N·n + e.
#[test]
fn ex_ray_direction_ray_reaches_the_near_plane_pixel_at_t_equal_one() {
    let cam = tilted_camera();
    let (c, r) = (37.0, 150.0);
    let (u_c, v_r) = pixel_on_near_plane(c, r, 320.0, 200.0, cam.half_width(), cam.half_height());
    let world = u_c * cam.u() + v_r * cam.v() - cam.near() * cam.n() + cam.eye();
    let ray = cam.ray(c, r);
    assert_vec_eq(ray.origin + ray.dir, world, 1e3 * TOL); // r(1) = e + d
    // and that point lies at distance N in front of the eye
    assert_abs_diff_eq!((world - cam.eye()).dot(-cam.n()), 2.5, epsilon = 1e3 * TOL);
}

/// "Principles of Ray Tracing" (erratum: corners versus centres): the notes' integer (c, r)
/// are pixel corners, so column 0 starts at −W exactly. The renderer shoots through centres
/// (c + ½, r + ½), which makes the first and last pixel mirror images of each other.
#[test]
fn ex_pixel_ray_renderer_samples_pixel_centres_not_corners() {
    let cam = straight_camera(90.0, 1.0, 4, 2);
    // the notes' corner ray for column 0, row 0
    assert_vec_eq(cam.direction(0.0, 0.0), vec3(-2.0, -1.0, -1.0), TOL);
    // the renderer's ray for the bottom-left image pixel (x = 0, y = m − 1) goes through its centre
    let bottom_left = cam.pixel_ray(0, 1, 0.5, 0.5).dir;
    assert_vec_eq(bottom_left, vec3(-1.5, -0.5, -1.0), TOL); // W(2·0.5/4 − 1) = −1.5, H(2·0.5/2 − 1) = −0.5
    let top_right = cam.pixel_ray(3, 0, 0.5, 0.5).dir;
    assert_vec_eq(top_right, vec3(1.5, 0.5, -1.0), TOL);
    // symmetric: centres of opposite pixels mirror each other, corners would not
    assert_vec_eq(bottom_left + top_right, vec3(0.0, 0.0, -2.0), TOL);
    let corners = cam.direction(0.0, 0.0) + cam.direction(3.0, 1.0);
    assert!((corners - vec3(0.0, 0.0, -2.0)).length() > 0.5);
}

/// "Principles of Ray Tracing": r counts rows from the bottom, images store rows from the top:
/// the top image row looks up (+v), the bottom one down.
#[test]
fn ex_pixel_ray_top_image_row_looks_up() {
    let cam = straight_camera(60.0, 1.0, 10, 10);
    assert!(cam.pixel_ray(5, 0, 0.5, 0.5).dir.y > 0.0);
    assert!(cam.pixel_ray(5, 9, 0.5, 0.5).dir.y < 0.0);
    assert!(cam.pixel_ray(0, 5, 0.5, 0.5).dir.x < 0.0);
    assert!(cam.pixel_ray(9, 5, 0.5, 0.5).dir.x > 0.0);
}

/// "Principles of Ray Tracing": chapter 1 colours a ray by its unit direction, (d̂ + 1)/2 on
/// each channel. Hand values: (0, 0, −2) has d̂ = (0, 0, −1), so (½, ½, 0); (3, 4, 0) has
/// |d| = 5, d̂ = (0.6, 0.8, 0), so (1.6/2, 1.8/2, 1/2) = (0.8, 0.9, 0.5); (−7, 0, 0) gives
/// (0, ½, ½); (1, 1, 1) has d̂ = (1, 1, 1)/√3, so each channel is (1/√3 + 1)/2 ≈ 0.788675.
#[test]
fn ex_direction_colour_ray_colour_is_unit_direction_plus_one_over_two() {
    assert_vec_eq(
        direction_colour(vec3(0.0, 0.0, -2.0)),
        vec3(0.5, 0.5, 0.0),
        TOL,
    );
    assert_vec_eq(
        direction_colour(vec3(3.0, 4.0, 0.0)),
        vec3(0.8, 0.9, 0.5),
        TOL,
    );
    assert_vec_eq(
        direction_colour(vec3(-7.0, 0.0, 0.0)),
        vec3(0.0, 0.5, 0.5),
        TOL,
    );
    let k = (1.0 / (3.0 as Real).sqrt() + 1.0) / 2.0;
    assert_abs_diff_eq!(k, real(0.788_675_134_594_812_9), epsilon = TOL);
    assert_vec_eq(direction_colour(vec3(1.0, 1.0, 1.0)), Vec3::splat(k), TOL);
    // very long and very short directions too: in f32, ‖d‖² of 10³⁰ overflows and of 10⁻³⁰
    // underflows, so d/‖d‖ would give 0 or ∞
    assert_vec_eq(
        direction_colour(vec3(0.0, 1e30, 0.0)),
        vec3(0.5, 1.0, 0.5),
        TOL,
    );
    assert_vec_eq(
        direction_colour(vec3(0.0, 0.0, -1e-30)),
        vec3(0.5, 0.5, 0.0),
        TOL,
    );
}

/// "Principles of Ray Tracing": the only ray of a 1 × 1 image goes through the middle of the
/// near plane, d = −N·n. Looking along −z (n = +z) with N = 2 it is (0, 0, −2), coloured
/// (½, ½, 0) once made unit; looking along +x (n = −x) with N = 0.5 it is (0.5, 0, 0),
/// coloured (1, ½, ½).
#[test]
fn centre_pixel_of_a_chapter_one_image_is_the_colour_of_minus_n() {
    let along_minus_z = chapter_scene(
        "[camera]\neye = [0.0, 0.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nnear = 2.0\n[[objects]]\nsphere = {}\n",
        Chapter::CameraRays,
    );
    let (c, stats) = centre(&along_minus_z, Chapter::CameraRays);
    assert_vec_eq(c, vec3(0.5, 0.5, 0.0), TOL);
    assert_eq!(stats.primary, 1);
    let along_x = chapter_scene(
        "[camera]\neye = [-3.0, 1.0, 2.0]\nlook_at = [4.0, 1.0, 2.0]\nnear = 0.5\n[[objects]]\nsphere = {}\n",
        Chapter::CameraRays,
    );
    let (c, _) = centre(&along_x, Chapter::CameraRays);
    assert_vec_eq(c, vec3(1.0, 0.5, 0.5), TOL);
}
