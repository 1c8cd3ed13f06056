//! Chapter 1 — camera rays (notes: "Principles of Ray Tracing").
//!
//! Hand-computed values for H = N·tan(θ/2), W = H·A, (u_c, v_r) and
//! d = −N·n + W(2c/n − 1)·u + H(2r/m − 1)·v.

mod common;

use common::{TOL, assert_near, assert_vec_eq, centre, chapter_scene};
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
    .expect("a camera at the origin looking down −z with up = y has a basis (viewing_basis)")
}

/// "Principles of Ray Tracing": H = N·tan(π/180·θ/2) for several θ and N.
#[test]
fn ex_near_plane_half_height_half_height_is_near_times_tangent_of_half_the_angle() {
    let r3: Real = (3.0 as Real).sqrt();
    for (n, theta, expected) in [
        (1.0, 90.0, 1.0),                        // tan 45° = 1
        (2.0, 60.0, 2.0 / r3),                   // 2·tan 30°
        (1.0, 45.0, (2.0 as Real).sqrt() - 1.0), // tan 22.5°
        (0.5, 120.0, 0.5 * r3),                  // ½·tan 60°
    ] {
        assert_near(
            &format!("H for N = {n}, θ = {theta}°"),
            near_plane_half_height(n, theta),
            expected,
            TOL,
        );
    }
    // H grows with N: the near plane twice as far is twice as tall
    assert_near(
        "H for N = 2, θ = 73°; expected twice H for N = 1",
        near_plane_half_height(2.0, 73.0),
        2.0 * near_plane_half_height(1.0, 73.0),
        TOL,
    );
}

/// "Principles of Ray Tracing": the angle is in degrees; reading it as radians is wrong.
#[test]
fn ex_near_plane_half_height_viewing_angle_is_converted_from_degrees() {
    let h = near_plane_half_height(1.0, 60.0);
    let as_radians = (60.0 as Real / 2.0).tan(); // tan(30 rad) ≈ −6.405
    assert!(
        (h - as_radians).abs() > 1.0,
        "H for N = 1, θ = 60° is {h} = tan(30 rad): θ must be converted to radians first \
         (H = N·tan(π/180·θ/2) = tan 30° ≈ 0.57735)"
    );
    assert_near(
        "H for N = 1, θ = 60°; expected tan 30°",
        h,
        real(0.577_350_269_189_625_8),
        TOL,
    );
}

/// "Principles of Ray Tracing": W = H·A with A = width/height, for several aspects.
#[test]
fn ex_near_plane_half_width_half_width_is_half_height_times_aspect() {
    let h = near_plane_half_height(1.0, 90.0);
    for (a, name) in [(4.0 / 3.0, "4/3"), (16.0 / 9.0, "16/9"), (1.0, "1")] {
        assert_near(
            &format!("W for H = {h}, A = {name}"),
            near_plane_half_width(h, a),
            a,
            TOL,
        );
    }
    let cam = straight_camera(60.0, 2.0, 640, 480);
    assert_near(
        "the camera's W for 640 × 480 (H·640/480)",
        cam.half_width(),
        cam.half_height() * 640.0 / 480.0,
        TOL,
    );
    assert_near(
        "the camera's H for N = 2, θ = 60°",
        cam.half_height(),
        2.0 / (3.0 as Real).sqrt(),
        TOL,
    );
}

/// `pixel_on_near_plane` for a window of n × m = 8 × 6 pixels on a near plane of half-size
/// W × H = 2 × 1.5: asserts (u_c, v_r) at the notes' (c, r).
#[track_caller]
fn assert_pixel_lands(c: Real, r: Real, expected: (Real, Real)) {
    let (u_c, v_r) = pixel_on_near_plane(c, r, 8.0, 6.0, 2.0, 1.5);
    assert!(
        (u_c - expected.0).abs() <= TOL && (v_r - expected.1).abs() <= TOL,
        "(u_c, v_r) for (c, r) = ({c}, {r}) of 8 × 6 pixels, W = 2, H = 1.5: ({u_c}, {v_r}), \
         expected {expected:?} (tolerance {TOL:e})"
    );
}

/// "Principles of Ray Tracing": (u_c, v_r) = (−W + W·2c/n, −H + H·2r/m) puts c = r = 0 on the
/// lower-left corner (−W, −H), c = n, r = m on the upper-right (W, H) and the middle on (0, 0).
#[test]
fn ex_pixel_on_near_plane_pixel_formula_spans_the_near_plane_corner_to_corner() {
    // n × m = 8 × 6, W = 2, H = 1.5
    assert_pixel_lands(0.0, 0.0, (-2.0, -1.5));
    assert_pixel_lands(8.0, 0.0, (2.0, -1.5));
    assert_pixel_lands(0.0, 6.0, (-2.0, 1.5));
    assert_pixel_lands(8.0, 6.0, (2.0, 1.5));
    assert_pixel_lands(4.0, 3.0, (0.0, 0.0));
    // one pixel in: W·2/n = 0.5 and H·2/m = 0.5 further
    assert_pixel_lands(1.0, 1.0, (-1.5, -1.0));
    // the centres of the first and last column and row, c = ½ and c = n − ½: W·(1/8 − 1) = −1.75
    // and W·(15/8 − 1) = 1.75; H·(1/6 − 1) = −1.25 and H·(11/6 − 1) = 1.25
    assert_pixel_lands(0.5, 0.5, (-1.75, -1.25));
    assert_pixel_lands(7.5, 5.5, (1.75, 1.25));
}

/// `viewing_basis(eye, look_at, up)`, which must exist: `setup` says which in messages.
#[track_caller]
fn basis(eye: Vec3, look_at: Vec3, up: Vec3, setup: &str) -> (Vec3, Vec3, Vec3) {
    viewing_basis(eye, look_at, up).unwrap_or_else(|| {
        panic!("viewing_basis gave no basis {setup} (e = {eye}, look_at = {look_at}, up = {up})")
    })
}

/// Asserts the basis (u, v, n) is the expected one, vector by vector, `setup` saying which.
#[track_caller]
fn assert_basis(setup: &str, (u, v, n): (Vec3, Vec3, Vec3), expected: [Vec3; 3], tol: Real) {
    assert_vec_eq(&format!("n {setup}"), n, expected[2], tol);
    assert_vec_eq(
        &format!("u {setup} (u = up × n, made unit)"),
        u,
        expected[0],
        tol,
    );
    assert_vec_eq(&format!("v {setup} (v = n × u)"), v, expected[1], tol);
}

/// "Principles of Ray Tracing": the viewing coordinates u, v, n are orthonormal, n points from
/// the scene back to the eye, u to the right.
#[test]
fn ex_viewing_basis_is_orthonormal_and_n_points_back_to_the_eye() {
    let from_z = "looking from (0, 0, 5) at the origin, up = y";
    let b = basis(vec3(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y, from_z);
    assert_basis(from_z, b, [Vec3::X, Vec3::Y, Vec3::Z], TOL);

    // looking from +x towards the origin: n = +x, u = up × n = −z, v = +y
    let from_x = "looking from (3, 0, 0) at the origin, up = y";
    let b = basis(vec3(3.0, 0.0, 0.0), Vec3::ZERO, Vec3::Y, from_x);
    assert_basis(from_x, b, [Vec3::NEG_Z, Vec3::Y, Vec3::X], TOL);

    // a tilted view still gives an orthonormal basis
    let tilted = "looking from (1, 2, 3) at (−1, 0.5, 0), up = y";
    let (u, v, n) = basis(vec3(1.0, 2.0, 3.0), vec3(-1.0, 0.5, 0.0), Vec3::Y, tilted);
    for ((a, b), name) in [((u, v), "u·v"), ((v, n), "v·n"), ((n, u), "n·u")] {
        assert_near(&format!("{name} {tilted}"), a.dot(b), 0.0, TOL);
    }
    for (x, name) in [(u, "‖u‖"), (v, "‖v‖"), (n, "‖n‖")] {
        assert_near(&format!("{name} {tilted}"), x.length(), 1.0, TOL);
    }
    assert_near(
        &format!("(u × v)·n {tilted}; expected right-handed"),
        u.cross(v).dot(n),
        1.0,
        TOL,
    );
}

/// "Principles of Ray Tracing": an up vector parallel to the view direction gives no basis.
#[test]
fn ex_viewing_basis_up_parallel_to_the_view_direction_has_no_basis() {
    let along = viewing_basis(vec3(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y);
    assert!(
        along.is_none(),
        "looking from (0, 5, 0) at the origin with up = y, along the view: (u, v, n) computed \
         {along:?}, expected None (up × n = 0 cannot be made unit)"
    );
    let nowhere = viewing_basis(Vec3::ZERO, Vec3::ZERO, Vec3::Y);
    assert!(
        nowhere.is_none(),
        "the eye on look_at, both at the origin: (u, v, n) computed {nowhere:?}, expected None \
         (e − look_at = 0 cannot be made unit)"
    );
}

/// "Principles of Ray Tracing": `up` only says which way is up; its part along the view
/// direction does not count. From (0, 0, 5) looking at the origin, n = (0, 0, 1), and up =
/// (0, 1, 1) gives the same basis as (0, 1, 0): u = (1, 0, 0), v = (0, 1, 0). For a tilted
/// view, up = y + 3n gives the basis of up = y.
#[test]
fn ex_viewing_basis_an_up_not_perpendicular_to_the_view_gives_the_same_basis() {
    let slanted = "looking from (0, 0, 5) at the origin, up = (0, 1, 1)";
    let b = basis(
        vec3(0.0, 0.0, 5.0),
        Vec3::ZERO,
        vec3(0.0, 1.0, 1.0),
        slanted,
    );
    assert_basis(slanted, b, [Vec3::X, Vec3::Y, Vec3::Z], TOL);
    let (eye, look_at) = (vec3(1.0, 2.0, 3.0), vec3(-1.0, 0.5, 0.0));
    let tilted = "looking from (1, 2, 3) at (−1, 0.5, 0)";
    let (u, v, n) = basis(eye, look_at, Vec3::Y, &format!("{tilted}, up = y"));
    let with_n = format!("{tilted}, up = y + 3n (as for up = y)");
    let (u2, v2, n2) = basis(eye, look_at, Vec3::Y + 3.0 * n, &with_n);
    assert_vec_eq(&format!("u {with_n}"), u2, u, 10.0 * TOL);
    assert_vec_eq(&format!("v {with_n}"), v2, v, 10.0 * TOL);
    assert_vec_eq(&format!("n {with_n}"), n2, n, TOL);
    // n is the unit vector from look_at to the eye: (2, 1.5, 3)/√15.25
    assert_vec_eq(
        &format!("n {tilted}, (e − look_at)/‖e − look_at‖"),
        n,
        vec3(2.0, 1.5, 3.0) / (15.25 as Real).sqrt(),
        TOL,
    );
}

/// "Principles of Ray Tracing": d = −N·n + W(2c/n − 1)·u + H(2r/m − 1)·v at the four corner
/// pixels of a 4 × 2 window with θ = 90°, N = 1 (H = 1, W = 2).
#[test]
fn ex_ray_direction_direction_at_the_four_corners() {
    let cam = straight_camera(90.0, 1.0, 4, 2);
    assert_near("H for N = 1, θ = 90°", cam.half_height(), 1.0, TOL);
    assert_near("W for H = 1, 4 × 2 pixels", cam.half_width(), 2.0, TOL);
    for (c, r, expected) in [
        (0.0, 0.0, vec3(-2.0, -1.0, -1.0)),
        (4.0, 0.0, vec3(2.0, -1.0, -1.0)),
        (0.0, 2.0, vec3(-2.0, 1.0, -1.0)),
        (4.0, 2.0, vec3(2.0, 1.0, -1.0)),
        (2.0, 1.0, vec3(0.0, 0.0, -1.0)), // the centre looks along −n
    ] {
        assert_vec_eq(
            &format!("d for (c, r) = ({c}, {r}) of 4 × 2 pixels, N = 1, W = 2, H = 1"),
            cam.direction(c, r),
            expected,
            TOL,
        );
    }
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
    .expect("a camera at (1, 2, 3) looking at (−1, 0.5, 0) with up = y has a basis (viewing_basis)")
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
        assert_near(
            &format!("d·(−n) for (c, r) = ({c}, {r}), N = 2.5 (d = {d})"),
            d.dot(-cam.n()),
            2.5,
            10.0 * TOL,
        );
    }
    assert_vec_eq(
        "d for the middle of 320 × 200 pixels, (c, r) = (160, 100); expected −N·n",
        cam.direction(160.0, 100.0),
        -2.5 * cam.n(),
        10.0 * TOL,
    );
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
    assert_vec_eq(
        "r(1) = e + d for (c, r) = (37, 150); expected the pixel's point on the near plane",
        ray.origin + ray.dir,
        world,
        1e3 * TOL,
    );
    // and that point lies at distance N in front of the eye
    assert_near(
        "(u_c·u + v_r·v − N·n)·(−n) for (c, r) = (37, 150); expected N",
        (world - cam.eye()).dot(-cam.n()),
        2.5,
        1e3 * TOL,
    );
}

/// "Principles of Ray Tracing" (erratum: corners versus centres): the notes' integer (c, r)
/// are pixel corners, so column 0 starts at −W exactly. The renderer shoots through centres
/// (c + ½, r + ½), which makes the first and last pixel mirror images of each other.
#[test]
fn ex_pixel_ray_renderer_samples_pixel_centres_not_corners() {
    let cam = straight_camera(90.0, 1.0, 4, 2);
    // the notes' corner ray for column 0, row 0
    assert_vec_eq(
        "d for the notes' corner (c, r) = (0, 0) of 4 × 2 pixels",
        cam.direction(0.0, 0.0),
        vec3(-2.0, -1.0, -1.0),
        TOL,
    );
    // the renderer's ray for the bottom-left image pixel (x = 0, y = m − 1) goes through its
    // centre: W(2·0.5/4 − 1) = −1.5, H(2·0.5/2 − 1) = −0.5
    let bottom_left = cam.pixel_ray(0, 1, 0.5, 0.5).dir;
    assert_vec_eq(
        "d of pixel_ray(x = 0, y = 1, ½, ½), the bottom-left pixel's centre (c, r) = (½, ½)",
        bottom_left,
        vec3(-1.5, -0.5, -1.0),
        TOL,
    );
    let top_right = cam.pixel_ray(3, 0, 0.5, 0.5).dir;
    assert_vec_eq(
        "d of pixel_ray(x = 3, y = 0, ½, ½), the top-right pixel's centre (c, r) = (3.5, 1.5)",
        top_right,
        vec3(1.5, 0.5, -1.0),
        TOL,
    );
    // symmetric: centres of opposite pixels mirror each other, corners would not
    assert_vec_eq(
        "the sum of the bottom-left and top-right centres' d (mirror images about −n)",
        bottom_left + top_right,
        vec3(0.0, 0.0, -2.0),
        TOL,
    );
    let corners = cam.direction(0.0, 0.0) + cam.direction(3.0, 1.0);
    assert!(
        (corners - vec3(0.0, 0.0, -2.0)).length() > 0.5,
        "the sum of the corner rays d(0, 0) + d(3, 1) is {corners}: corners do not mirror"
    );
}

/// "Principles of Ray Tracing": r counts rows from the bottom, images store rows from the top:
/// the top image row looks up (+v), the bottom one down.
#[test]
fn ex_pixel_ray_top_image_row_looks_up() {
    let cam = straight_camera(60.0, 1.0, 10, 10);
    for (x, y, name, positive, side) in [
        (5, 0, "v", true, "the top row looks up"),
        (5, 9, "v", false, "the bottom row looks down"),
        (0, 5, "u", false, "the left column looks left"),
        (9, 5, "u", true, "the right column looks right"),
    ] {
        let d = cam.pixel_ray(x, y, 0.5, 0.5).dir;
        let along = d.dot(if name == "v" { cam.v() } else { cam.u() });
        assert!(
            if positive { along > 0.0 } else { along < 0.0 },
            "d of pixel_ray(x = {x}, y = {y}, ½, ½) of 10 × 10 pixels is {d}, d·{name} = \
             {along}: expected {side}, d·{name} {} 0 (y counts rows from the top, r from the \
             bottom)",
            if positive { ">" } else { "<" }
        );
    }
}

/// "Principles of Ray Tracing": a point (dx, dy) inside image pixel (x, y) is measured from the
/// pixel's top-left corner, dx to the right and dy *down*, as the image's rows go; the notes'
/// row r counts *up* from the image's bottom. So the point is the notes' (c, r) = (x + dx,
/// m − y − dy): the pixel's top edge, dy = 0, is r = m − y, and its centre r = m − y − ½. Every
/// pixel of a 4 × 2 window (θ = 90°, N = 1: W = 2, H = 1) at dx, dy ∈ {0, ¼, ½, ¾}, which
/// includes each pixel's top-left corner: the ray's (c, r), read back from d = −N·n + u_c·u +
/// v_r·v, must be those. (Taking dy upwards, r = m − 1 − y + dy, agrees at the centre only.)
#[test]
fn ex_pixel_ray_dx_runs_right_and_dy_runs_down_from_the_pixels_top_left_corner() {
    let cam = straight_camera(90.0, 1.0, 4, 2);
    let (n, m) = (4.0, 2.0);
    let (w, h) = (cam.half_width(), cam.half_height());
    let steps: [Real; 4] = [0.0, 0.25, 0.5, 0.75];
    for (y, x) in (0..2u32).flat_map(|y| (0..4u32).map(move |x| (y, x))) {
        for (dy, dx) in steps.iter().flat_map(|&dy| steps.map(|dx| (dy, dx))) {
            let d = cam.pixel_ray(x, y, dx, dy).dir;
            // u_c = d·u = W(2c/n − 1) and v_r = d·v = H(2r/m − 1), with d·(−n) = N = 1
            let c = n * (d.dot(cam.u()) / w + 1.0) / 2.0;
            let r = m * (d.dot(cam.v()) / h + 1.0) / 2.0;
            let (c_expected, r_expected) = (x as Real + dx, m - y as Real - dy);
            let at = format!(
                "pixel_ray(x = {x}, y = {y}, dx = {dx}, dy = {dy}) of 4 × 2 pixels (d = {d})"
            );
            assert!(
                (r - r_expected).abs() <= 10.0 * TOL,
                "the notes' row r that {at} goes through: computed {r}, expected m − y − dy = \
                 {r_expected}: dy runs down from the pixel's top, r up from the image's bottom \
                 (tolerance {:e})",
                10.0 * TOL
            );
            assert!(
                (c - c_expected).abs() <= 10.0 * TOL,
                "the notes' column c that {at} goes through: computed {c}, expected x + dx = \
                 {c_expected} (tolerance {:e})",
                10.0 * TOL
            );
            assert_near(
                &format!("d·(−n) of {at}; expected N"),
                d.dot(-cam.n()),
                1.0,
                TOL,
            );
        }
    }
    // the image's top-left corner, the first pixel's (0, 0): (c, r) = (0, m), d = (−W, H, −N)
    assert_vec_eq(
        "d of pixel_ray(0, 0, 0, 0), the image's top-left corner (c, r) = (0, m)",
        cam.pixel_ray(0, 0, 0.0, 0.0).dir,
        vec3(-2.0, 1.0, -1.0),
        TOL,
    );
}

/// "Principles of Ray Tracing": chapter 1 colours a ray by its unit direction, (d̂ + 1)/2 on
/// each channel. Hand values: (0, 0, −2) has d̂ = (0, 0, −1), so (½, ½, 0); (3, 4, 0) has
/// |d| = 5, d̂ = (0.6, 0.8, 0), so (1.6/2, 1.8/2, 1/2) = (0.8, 0.9, 0.5); (−7, 0, 0) gives
/// (0, ½, ½); (1, 1, 1) has d̂ = (1, 1, 1)/√3, so each channel is (1/√3 + 1)/2 ≈ 0.788675.
#[test]
fn ex_direction_colour_ray_colour_is_unit_direction_plus_one_over_two() {
    let k = (1.0 / (3.0 as Real).sqrt() + 1.0) / 2.0;
    assert_near(
        "(1/√3 + 1)/2, the hand value",
        k,
        real(0.788_675_134_594_812_9),
        TOL,
    );
    // very long and very short directions too: in f32, ‖d‖² of 10³⁰ overflows and of 10⁻³⁰
    // underflows, so d/‖d‖ would give 0 or ∞
    for (d, expected) in [
        (vec3(0.0, 0.0, -2.0), vec3(0.5, 0.5, 0.0)),
        (vec3(3.0, 4.0, 0.0), vec3(0.8, 0.9, 0.5)),
        (vec3(-7.0, 0.0, 0.0), vec3(0.0, 0.5, 0.5)),
        (vec3(1.0, 1.0, 1.0), Vec3::splat(k)),
        (vec3(0.0, 1e30, 0.0), vec3(0.5, 1.0, 0.5)),
        (vec3(0.0, 0.0, -1e-30), vec3(0.5, 0.5, 0.0)),
    ] {
        assert_vec_eq(
            &format!("the colour (d̂ + 1)/2 of d = {d}"),
            direction_colour(d),
            expected,
            TOL,
        );
    }
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
    assert_vec_eq(
        "the colour of a 1 × 1 image looking along −z, d = (0, 0, −2)",
        c,
        vec3(0.5, 0.5, 0.0),
        TOL,
    );
    assert_eq!(stats.primary, 1, "the camera rays of a 1 × 1 image");
    let along_x = chapter_scene(
        "[camera]\neye = [-3.0, 1.0, 2.0]\nlook_at = [4.0, 1.0, 2.0]\nnear = 0.5\n[[objects]]\nsphere = {}\n",
        Chapter::CameraRays,
    );
    let (c, _) = centre(&along_x, Chapter::CameraRays);
    assert_vec_eq(
        "the colour of a 1 × 1 image looking along +x, d = (0.5, 0, 0)",
        c,
        vec3(1.0, 0.5, 0.5),
        TOL,
    );
}
