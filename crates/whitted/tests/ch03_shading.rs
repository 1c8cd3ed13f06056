//! Chapter 3 — shading (notes: "Shading"): ambient, diffuse and specular per RGB channel,
//! attenuation, several lights, and the rays a shaded render casts.
//!
//! A test named `ex_NAME_…` checks the exercise NAME of `chapters/formulas.toml`. The local light
//! (3.7) is seen only through the renderer, which also asks `Tracer::feeler` (4.4) for a
//! feeler and hands the colour to `Tracer::reflect_and_refract` (5.5): before chapter 4 and 5
//! they give nothing and return it unchanged, but they must not be `todo!()`.

mod common;

use common::{TOL, assert_exact, assert_near, assert_vec_eq, centre, render_at, scene};
use whitted::light::Light;
use whitted::material::Material;
use whitted::real::{Real, Vec3, vec3};
use whitted::render::{Chapter, Options, Tracer};
use whitted::shading::{ambient, direct, highlight, lambert, mirror};

/// A unit sphere at the origin seen from (0, 0, 5), with one light at `light` (a TOML array).
fn sphere_scene(light: &str, extra: &str) -> String {
    format!(
        "[camera]\neye = [0.0, 0.0, 5.0]\n[ambient]\nintensity = [0.5, 0.4, 0.3]\n\
         [[lights]]\nposition = {light}\nintensity = [0.9, 0.8, 0.7]\n{extra}\n\
         [materials.m]\nambient = [0.1, 0.2, 0.3]\ndiffuse = [0.5, 0.4, 0.3]\nspecular = [0.2, 0.3, 0.4]\nshininess = 10\n\
         [[objects]]\nsphere = {{}}\nmaterial = \"m\"\n"
    )
}

/// "Shading": with the light straight behind the eye, s = v = n at the nearest point, r·v = 1,
/// so I = ρa·I_m + I_p(ρd + ρs) in every channel.
#[test]
fn ex_local_light_light_behind_the_eye_gives_ambient_plus_full_diffuse_and_specular() {
    let s = scene(&sphere_scene("[0.0, 0.0, 10.0]", ""));
    let (c, _) = centre(&s, Chapter::Shading);
    let expected = vec3(0.1 * 0.5, 0.2 * 0.4, 0.3 * 0.3)
        + vec3(0.9, 0.8, 0.7) * vec3(0.5 + 0.2, 0.4 + 0.3, 0.3 + 0.4);
    assert_vec_eq(
        "I at the sphere's nearest point, the light behind the eye; expected ρa·I_m + I_p·(ρd + ρs)",
        c,
        expected,
        10.0 * TOL,
    );
}

/// "Shading": a light behind the surface (n·s < 0) adds nothing: ambient only.
#[test]
fn ex_local_light_light_behind_the_surface_gives_ambient_only() {
    let s = scene(&sphere_scene("[0.0, 0.0, -10.0]", ""));
    let (c, stats) = centre(&s, Chapter::Shading);
    assert_vec_eq(
        "I at the sphere's nearest point, the light behind the sphere; expected I_a = ρa·I_m only",
        c,
        vec3(0.05, 0.08, 0.09),
        10.0 * TOL,
    );
    assert_eq!(stats.shadow, 0, "the feelers cast at chapter 3");
}

/// "Shading" (erratum: negative dot products): unclamped, the notes' n·s would subtract light
/// for a light behind the surface. whitted clamps: max(n·s, 0) is 1 for s = n, cos 60° = ½ at
/// 60°, 0 at 90° and 0 — not −1 — for a light straight behind.
#[test]
fn ex_lambert_negative_dot_products_are_clamped() {
    let n = Vec3::Z;
    let a = (60.0 as Real).to_radians();
    assert_near("max(n·s, 0) for s = n = z", lambert(n, n), 1.0, TOL);
    assert_near(
        "max(n·s, 0) for n = z, s 60° from it",
        lambert(n, Vec3::new(a.sin(), 0.0, a.cos())),
        0.5,
        TOL,
    );
    assert_exact(
        "max(n·s, 0) for n = z, s = x (90°)",
        lambert(n, Vec3::X),
        0.0,
    );
    let s = Vec3::NEG_Z; // light exactly behind
    assert_exact(
        "max(n·s, 0) for n = z, s = −z (the light straight behind); expected max(−1, 0), n·s \
         being −1",
        lambert(n, s),
        0.0,
    );
}

/// "Shading" (erratum: negative dot products): unclamped, the notes' (r·v)^f would add a
/// highlight from a negative r·v with an even f, and a light behind the surface could still
/// shine on a viewer along r. whitted's highlight is 0 in both cases.
#[test]
fn ex_highlight_negative_dot_products_are_clamped() {
    let n = Vec3::Z;
    let s = Vec3::NEG_Z; // light exactly behind
    let v = Vec3::NEG_Z; // viewer on the far side too (e.g. seen through glass)
    // the notes' expression, unclamped, gives +1 here: r = −z is along v
    assert_near(
        "the notes' unclamped (r·v)^f for n = z, s = v = −z, f = 2",
        mirror(s, n).dot(v).powf(2.0),
        1.0,
        TOL,
    );
    assert_exact(
        "the highlight max(r·v, 0)^f for n = z, s = v = −z (light and viewer behind), f = 2; \
         expected none for n·s = −1 ≤ 0, where the notes' unclamped (r·v)^f is 1",
        highlight(n, s, v, 2.0),
        0.0,
    );
    // a light in front, a viewer more than 90° from r: r·v < 0, and f = 2 must not square it
    let k = 1.0 / (2.0 as Real).sqrt();
    let s = vec3(1.0, 0.0, 1.0) * k; // r = (−1, 0, 1)/√2
    assert_near(
        "the notes' unclamped (r·v)^f for n = z, s = (1, 0, 1)/√2, v = x, f = 2",
        mirror(s, n).dot(Vec3::X).powf(2.0),
        0.5,
        TOL,
    );
    assert_exact(
        "the highlight max(r·v, 0)^f for n = z, s = (1, 0, 1)/√2, v = x, f = 2; expected \
         max(−1/√2, 0)² with r = (−1, 0, 1)/√2, r·v = −1/√2",
        highlight(n, s, Vec3::X, 2.0),
        0.0,
    );
    // a light grazing the surface (n·s = 0) gives no highlight even to a viewer along r
    assert_exact(
        "the highlight max(r·v, 0)^f for n = z, s = x (grazing), v = −x, f = 5; expected none for \
         n·s = 0, though v lies along r = −x",
        highlight(n, Vec3::X, Vec3::NEG_X, 5.0),
        0.0,
    );
}

/// "Shading": r is the mirror of s about n, r = 2(n·s)n − s.
#[test]
fn ex_mirror_direction_of_the_light() {
    let k = 1.0 / (2.0 as Real).sqrt();
    assert_vec_eq(
        "r for s = (1, 0, 1)/√2, n = z",
        mirror(vec3(1.0, 0.0, 1.0) * k, Vec3::Z),
        vec3(-1.0, 0.0, 1.0) * k,
        TOL,
    );
    assert_vec_eq("r for s = n = z", mirror(Vec3::Z, Vec3::Z), Vec3::Z, TOL);
    // for unit s and n: r is unit, n·r = n·s, and r + s is parallel to n
    let n = vec3(1.0, 2.0, 2.0) / 3.0;
    let s = vec3(0.6, 0.0, 0.8);
    let r = mirror(s, n);
    let of = format!("for s = (0.6, 0, 0.8), n = (1, 2, 2)/3 (r = {r})");
    assert_near(&format!("‖r‖ {of}"), r.length(), 1.0, TOL);
    assert_near(&format!("n·r {of}; expected n·s"), n.dot(r), n.dot(s), TOL);
    assert_vec_eq(
        &format!("(r + s) × n {of}; expected r + s along n"),
        (r + s).cross(n),
        Vec3::ZERO,
        TOL,
    );
    // by hand: n·s = (0.6 + 1.6)/3 = 2.2/3, r = 2·(2.2/3)·(1, 2, 2)/3 − s
    let h = 4.4 / 9.0;
    assert_vec_eq(
        "r = 2(n·s)·n − s for s = (0.6, 0, 0.8), n = (1, 2, 2)/3",
        r,
        vec3(h - 0.6, 2.0 * h, 2.0 * h - 0.8),
        TOL,
    );
}

/// "Shading": the highlight (r·v)^f is 1 with v along r, cos(60°)^f = ½^f with v 60° away
/// from r, and smaller for a larger f at the same v ≠ r.
#[test]
fn ex_highlight_is_one_along_r_and_falls_with_the_angle() {
    let k = 1.0 / (2.0 as Real).sqrt();
    let s = vec3(1.0, 0.0, 1.0) * k;
    let r = vec3(-1.0, 0.0, 1.0) * k;
    assert_near(
        "the highlight max(r·v, 0)^f for n = z, s = (1, 0, 1)/√2, v = r = (−1, 0, 1)/√2, f = 50; \
         expected v along r",
        highlight(Vec3::Z, s, r, 50.0),
        1.0,
        TOL,
    );
    // r points 45° from +z towards −x; v 15° towards +x is 60° away from it
    let a = (15.0 as Real).to_radians();
    let v = Vec3::new(a.sin(), 0.0, a.cos());
    let (h3, h10) = (
        highlight(Vec3::Z, s, v, 3.0),
        highlight(Vec3::Z, s, v, 10.0),
    );
    let at_60 = "for n = z, s = (1, 0, 1)/√2 and v 60° from r";
    assert_near(
        &format!("the highlight max(r·v, 0)^f {at_60}, f = 3; expected cos³ 60° = ½³"),
        h3,
        (0.5 as Real).powi(3),
        10.0 * TOL,
    );
    assert_near(
        &format!("the highlight max(r·v, 0)^f {at_60}, f = 10; expected cos¹⁰ 60° = ½¹⁰"),
        h10,
        (0.5 as Real).powi(10),
        10.0 * TOL,
    );
    assert!(
        h10 < h3,
        "the highlight max(r·v, 0)^f {at_60}: computed {h10} for f = 10 and {h3} for f = 3, \
         expected less for the larger f"
    );
}

/// "Shading": the diffuse term follows the cosine law ρd·I_p·(n·s).
#[test]
fn ex_direct_light_diffuse_follows_the_cosine_law() {
    let m = Material {
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(0.8),
        specular: Vec3::ZERO,
        ..Material::default()
    };
    let p = Vec3::ZERO;
    let n = Vec3::Y;
    // a light 60° from the normal, at distance 2: n·s = cos 60° = 0.5
    let a = (60.0 as Real).to_radians();
    let light = Light::white(Vec3::new(2.0 * a.sin(), 2.0 * a.cos(), 0.0));
    let i = direct(&m, &light, p, n, Vec3::Y);
    assert_vec_eq(
        "I_d + I_s for ρd = 0.8, ρs = 0, a white light at 60° from n; expected ρd·I_p·(n·s) = 0.8·½",
        i,
        Vec3::splat(0.8 * 0.5),
        10.0 * TOL,
    );
}

/// "Shading": I_a = ρa·I_m, channel by channel: ρa = (0.1, 0.2, 0.3) under I_m = (0.5, 0.4, 0.3)
/// gives (0.05, 0.08, 0.09); the default material (ρa = 0.1) under 0.5 gives 0.05.
#[test]
fn ex_ambient_is_rho_a_times_i_m_per_channel() {
    let m = Material {
        ambient: vec3(0.1, 0.2, 0.3),
        ..Material::default()
    };
    assert_vec_eq(
        "I_a for ρa = (0.1, 0.2, 0.3), I_m = (0.5, 0.4, 0.3)",
        ambient(&m, vec3(0.5, 0.4, 0.3)),
        vec3(0.05, 0.08, 0.09),
        TOL,
    );
    assert_vec_eq(
        "I_a for the default material (ρa = 0.1), I_m = 0.5",
        ambient(&Material::default(), Vec3::splat(0.5)),
        Vec3::splat(0.05),
        TOL,
    );
    assert_vec_eq(
        "I_a for ρa = (0.1, 0.2, 0.3), I_m = 0",
        ambient(&m, Vec3::ZERO),
        Vec3::ZERO,
        0.0,
    );
}

/// "Shading", one light per RGB channel: a light straight above a surface facing up, seen from
/// v = n, gives I_p·(ρd + ρs) in each channel (n·s = r·v = 1); a red light (1, 0, 0) leaves
/// green and blue at 0; the light moved below the surface gives (0, 0, 0), and so does a light
/// at the point itself.
#[test]
fn ex_direct_light_one_light_three_channels() {
    let m = Material {
        ambient: vec3(0.3, 0.3, 0.3),
        diffuse: vec3(0.5, 0.4, 0.3),
        specular: vec3(0.2, 0.3, 0.4),
        shininess: 10.0,
        ..Material::default()
    };
    let (p, n) = (vec3(1.0, 0.0, -2.0), Vec3::Y);
    let mut light = Light {
        position: vec3(1.0, 3.0, -2.0),
        intensity: vec3(0.9, 0.8, 0.7),
        attenuation: [1.0, 0.0, 0.0],
        shadows: true,
    };
    assert_vec_eq(
        "I_d + I_s for I_p = (0.9, 0.8, 0.7) straight above, v = n; expected I_p·(ρd + ρs)",
        direct(&m, &light, p, n, n),
        vec3(0.9 * 0.7, 0.8 * 0.7, 0.7 * 0.7),
        10.0 * TOL,
    );
    light.intensity = vec3(1.0, 0.0, 0.0);
    assert_vec_eq(
        "I_d + I_s for a red light I_p = (1, 0, 0) straight above, v = n",
        direct(&m, &light, p, n, n),
        vec3(0.7, 0.0, 0.0),
        10.0 * TOL,
    );
    light.position = vec3(1.0, -3.0, -2.0);
    assert_vec_eq(
        "I_d + I_s for a light below the surface",
        direct(&m, &light, p, n, n),
        Vec3::ZERO,
        0.0,
    );
    light.position = p;
    assert_vec_eq(
        "I_d + I_s for a light at the point itself (d = 0, no s)",
        direct(&m, &light, p, n, n),
        Vec3::ZERO,
        0.0,
    );
}

/// The shortcuts that skip `powf` leave the numbers as they were: a viewer beyond 90° of r
/// gets exactly 0 (0^f, f > 0), f = 0 still gives 0^0 = 1, and a matte material (ρs = 0)
/// gets exactly its diffuse term, bit for bit, whatever the highlight would have been.
#[test]
fn ex_direct_light_skipping_the_highlight_changes_no_number() {
    let k = 1.0 / (2.0 as Real).sqrt();
    let s = vec3(1.0, 0.0, 1.0) * k; // r = (−1, 0, 1)/√2
    let beyond = vec3(1.0, 0.0, 0.0); // r·v = −1/√2 < 0
    let at_90 = vec3(1.0, 0.0, 1.0) * k; // r·v = 0
    for (v, f, expected, from) in [
        (beyond, 3.0, 0.0, "0³, r·v = −1/√2 < 0"),
        (at_90, 30.0, 0.0, "0³⁰, r·v = 0"),
        (at_90, 0.0, 1.0, "0⁰, r·v = 0"),
        (beyond, 0.0, 1.0, "0⁰, r·v = −1/√2 < 0"),
    ] {
        assert_exact(
            &format!(
                "the highlight max(r·v, 0)^f for n = z, s = (1, 0, 1)/√2 (r = (−1, 0, 1)/√2), \
                 v = {v}, f = {f}; expected {from}"
            ),
            highlight(Vec3::Z, s, v, f),
            expected,
        );
    }
    let matte = Material {
        ambient: Vec3::ZERO,
        diffuse: vec3(0.7, 0.4, 0.2),
        specular: Vec3::ZERO,
        shininess: 7.0,
        ..Material::default()
    };
    let light = Light::white(vec3(0.3, 2.0, 0.1));
    let (p, n) = (Vec3::ZERO, Vec3::Y);
    // v on the mirror direction: the highlight alone would be 1
    let to_light = light.position - p;
    let v = (2.0 * n.dot(to_light) * n - to_light).normalize();
    let d = to_light.length();
    let expected =
        light.intensity * light.attenuation_at(d) * (matte.diffuse * lambert(n, to_light / d));
    assert_vec_eq(
        "I_d + I_s of a matte material (ρs = 0) seen along r; expected I_p·att·ρd·(n·s) bit \
         for bit",
        direct(&matte, &light, p, n, v),
        expected,
        0.0,
    );
}

/// "Shading": I_p/(a0 + a1·d + a2·d²): at d = 2 with (1, 0.5, 0.25), the light is divided by 3;
/// (1, 0, 0) divides by nothing at any distance, (0, 0, 1) is the inverse square (¼ at d = 2,
/// 1/16 at d = 4), (1, 1, 0) gives ⅓ at d = 2, and (0, 1, 0) stays finite at d = 0.
#[test]
fn ex_attenuation_divides_by_a0_plus_a1_d_plus_a2_d_squared() {
    let mut light = Light::white(vec3(0.0, 2.0, 0.0));
    for (a, d, expected) in [
        ([1.0, 0.5, 0.25], 2.0, 1.0 / 3.0),
        ([1.0, 0.5, 0.25], 0.0, 1.0),
        ([1.0, 0.0, 0.0], 0.0, 1.0),
        ([1.0, 0.0, 0.0], 1.0, 1.0),
        ([1.0, 0.0, 0.0], 7.5, 1.0),
        ([1.0, 0.0, 0.0], 1e6, 1.0),
        ([0.0, 0.0, 1.0], 2.0, 0.25), // inverse square
        ([0.0, 0.0, 1.0], 4.0, 1.0 / 16.0),
        ([1.0, 1.0, 0.0], 2.0, 1.0 / 3.0),
        ([0.0, 1.0, 0.0], 0.5, 2.0),
    ] {
        light.attenuation = a;
        assert_near(
            &format!("1/(a0 + a1·d + a2·d²) for (a0, a1, a2) = {a:?}, d = {d}"),
            light.attenuation_at(d),
            expected,
            TOL,
        );
    }
    light.attenuation = [0.0, 1.0, 0.0];
    let at_zero = light.attenuation_at(0.0);
    assert!(
        at_zero.is_finite(),
        "1/(a0 + a1·d + a2·d²) for (a0, a1, a2) = (0, 1, 0), d = 0: computed {at_zero}, \
         expected a finite value, the denominator kept at least Real::EPSILON"
    );
}

/// "Shading": `direct` divides the light by its attenuation: a white light 2 above a white
/// diffuse surface facing it, with (1, 0.5, 0.25), gives 1/3 in every channel.
#[test]
fn ex_direct_light_is_divided_by_the_attenuation() {
    let mut light = Light::white(vec3(0.0, 2.0, 0.0));
    let m = Material {
        ambient: Vec3::ZERO,
        diffuse: Vec3::ONE,
        specular: Vec3::ZERO,
        ..Material::default()
    };
    light.attenuation = [1.0, 0.5, 0.25];
    let i = direct(&m, &light, Vec3::ZERO, Vec3::Y, Vec3::Y);
    assert_vec_eq(
        "I_d + I_s for a white light 2 above, (a0, a1, a2) = (1, 0.5, 0.25); expected ρd·I_p/3",
        i,
        Vec3::splat(1.0 / 3.0),
        10.0 * TOL,
    );
}

/// "Shading": through the renderer, the light at (0, 0, 10) with (1, 0.5, 0.25) reaches the
/// sphere's nearest point (0, 0, 1) from d = 9 away, divided by 1 + 4.5 + 20.25 = 25.75.
#[test]
fn ex_local_light_attenuated_light_through_the_renderer() {
    let s = scene(&sphere_scene(
        "[0.0, 0.0, 10.0]",
        "attenuation = [1.0, 0.5, 0.25]",
    ));
    let (c, _) = centre(&s, Chapter::Shading);
    let d: Real = 9.0; // from (0, 0, 1) to (0, 0, 10)
    let k = 1.0 / (1.0 + 0.5 * d + 0.25 * d * d);
    let expected = vec3(0.05, 0.08, 0.09) + vec3(0.9, 0.8, 0.7) * vec3(0.7, 0.7, 0.7) * k;
    assert_vec_eq(
        "I at the sphere's nearest point, the light 9 away, (1, 0.5, 0.25); expected I_a + I_p·(ρd + ρs)/25.75",
        c,
        expected,
        10.0 * TOL,
    );
}

/// "Shading": with several lights, each adds its own diffuse and specular terms.
#[test]
fn ex_local_light_several_lights_add_up() {
    let one = scene(&sphere_scene("[0.0, 0.0, 10.0]", ""));
    let two = scene(&sphere_scene(
        "[0.0, 0.0, 10.0]",
        "[[lights]]\nposition = [0.0, 0.0, 20.0]\nintensity = 0.5",
    ));
    let (c1, _) = centre(&one, Chapter::Shading);
    let (c2, _) = centre(&two, Chapter::Shading);
    assert_vec_eq(
        "I with a second light of 0.5 behind the first, less I with one light; expected 0.5·(ρd + ρs)",
        c2 - c1,
        Vec3::splat(0.5) * vec3(0.7, 0.7, 0.7),
        10.0 * TOL,
    );
}

/// "Shading": the plane is open; seen from below it is shaded with the normal turned to the
/// viewer, so a light on the viewer's side lights it.
#[test]
fn open_plane_is_shaded_on_the_side_the_viewer_sees() {
    let text = |eye: f64, light: f64| {
        format!(
            "[camera]\neye = [0.0, {eye}, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nup = [0.0, 0.0, 1.0]\n\
             [ambient]\nintensity = 0.0\n[[lights]]\nposition = [0.0, {light}, 0.0]\n\
             [materials.m]\nambient = 0.0\ndiffuse = 0.5\nspecular = 0.0\n\
             [[objects]]\nplane = {{ normal = [0.0, 1.0, 0.0] }}\nmaterial = \"m\"\n"
        )
    };
    let (above, _) = centre(&scene(&text(3.0, 5.0)), Chapter::Shading);
    let (below, _) = centre(&scene(&text(-3.0, -5.0)), Chapter::Shading);
    let (across, _) = centre(&scene(&text(-3.0, 5.0)), Chapter::Shading);
    assert_vec_eq(
        "I of the plane seen and lit from above",
        above,
        Vec3::splat(0.5),
        TOL,
    );
    assert_vec_eq(
        "I of the plane seen and lit from below",
        below,
        Vec3::splat(0.5),
        TOL,
    );
    assert_vec_eq(
        "I of the plane seen from below, lit from above; expected dark",
        across,
        Vec3::ZERO,
        TOL,
    );
}

/// "Shading": a chapter-3 render casts primary rays only — no feelers, no secondary rays.
#[test]
fn shading_casts_primary_rays_only() {
    let s = scene(&sphere_scene("[3.0, 3.0, 10.0]", ""));
    let (_, stats) = render_at(&s, Chapter::Shading, 20, 10);
    assert_eq!(stats.primary, 200, "the camera rays of a 20 × 10 image");
    assert_eq!(
        (stats.shadow, stats.reflected, stats.refracted),
        (0, 0, 0),
        "(feelers, mirror rays, transmitted rays) at chapter 3"
    );
}

/// "Shading": I = I_a + I_p/(a0 + a1·d + a2·d²)·(ρd·(n·s) + ρs·(r·v)^f) per channel, with both
/// cosines strictly between 0 and 1. At P = 0 with n = (0, 1, 0), the light at L = (√3, 1, 0)
/// is d = 2 away, s = (√3/2, ½, 0) at 60° from n: n·s = ½; r = 2(n·s)n − s = (−√3/2, ½, 0),
/// 60° on the other side of n. The viewer along v = (−sin 15°, cos 15°, 0) is 45° from r:
/// r·v = cos 45° = √2/2 (and n·v = cos 15° ≠ r·v, so n·v in its place would show); with
/// f = 3, (r·v)³ = √2/4 ≈ 0.353553. Attenuation (1, 0.25, 0.25): 1 + 0.5 + 1 = 2.5, a factor
/// 0.4. With ρd = (0.5, 0.4, 0.3), ρs = (0.2, 0.3, 0.4), I_p = (0.9, 0.8, 0.7):
/// - ρd·½ + ρs·√2/4 = (0.25 + 0.070711, 0.2 + 0.106066, 0.15 + 0.141421)
///   = (0.320711, 0.306066, 0.291421)
/// - × 0.4 × I_p = (0.115456, 0.097941, 0.081598)
/// - + ρa·I_m = (0.1, 0.2, 0.3)·(0.5, 0.4, 0.3) = (0.05, 0.08, 0.09)
/// - I = (0.165456, 0.177941, 0.171598)
///
/// by `shading::direct` and in a rendered 1 × 1 image of a floor seen from 2 away along v.
#[test]
fn phong_with_both_cosines_between_zero_and_one() {
    let r3 = (3.0 as Real).sqrt();
    let h = (2.0 as Real).sqrt() / 4.0; // (√2/2)³
    let m = Material {
        ambient: vec3(0.1, 0.2, 0.3),
        diffuse: vec3(0.5, 0.4, 0.3),
        specular: vec3(0.2, 0.3, 0.4),
        shininess: 3.0,
        ..Material::default()
    };
    let light = Light {
        position: Vec3::new(r3, 1.0, 0.0),
        intensity: vec3(0.9, 0.8, 0.7),
        attenuation: [1.0, 0.25, 0.25],
        shadows: true,
    };
    let (p, n) = (Vec3::ZERO, Vec3::Y);
    let a = (15.0 as Real).to_radians();
    let v = Vec3::new(-a.sin(), a.cos(), 0.0);
    let s = (light.position - p).normalize();
    assert_near(
        "max(n·s, 0) for s 60° from n; expected cos 60°",
        lambert(n, s),
        0.5,
        TOL,
    );
    assert_near(
        "r·v for r 60° on the other side of n, v 15° from n; expected cos 45°",
        mirror(s, n).dot(v),
        (2.0 as Real).sqrt() / 2.0,
        10.0 * TOL,
    );
    assert_near(
        "the highlight max(r·v, 0)^f for n = y, s 60° from n, v 15° from n, f = 3; expected (√2/2)³, r·v = cos 45°",
        highlight(n, s, v, 3.0),
        h,
        10.0 * TOL,
    );
    assert_near(
        "1/(a0 + a1·d + a2·d²) for (1, 0.25, 0.25), d = 2",
        light.attenuation_at(2.0),
        0.4,
        TOL,
    );
    let direct_by_hand =
        vec3(0.9, 0.8, 0.7) * 0.4 * (vec3(0.25, 0.2, 0.15) + vec3(0.2, 0.3, 0.4) * h);
    assert_vec_eq(
        "I_d + I_s by hand",
        direct_by_hand,
        vec3(0.115_456, 0.097_941, 0.081_598),
        1e-6,
    );
    assert_vec_eq(
        "I_d + I_s by shading::direct, n·s = ½, r·v = √2/2, f = 3, att = 0.4",
        direct(&m, &light, p, n, v),
        direct_by_hand,
        10.0 * TOL,
    );
    let i = vec3(0.05, 0.08, 0.09) + direct_by_hand;
    assert_vec_eq(
        "I = I_a + I_d + I_s by shading::ambient and shading::direct",
        ambient(&m, vec3(0.5, 0.4, 0.3)) + direct(&m, &light, p, n, v),
        i,
        10.0 * TOL,
    );
    // the eye at P + 2v = (−2 sin 15°, 2 cos 15°, 0)
    let text = "[camera]\neye = [-0.5176380902050415, 1.9318516525781366, 0.0]\nlook_at = [0.0, 0.0, 0.0]\n\
        [ambient]\nintensity = [0.5, 0.4, 0.3]\n\
        [[lights]]\nposition = [1.7320508075688772, 1.0, 0.0]\nintensity = [0.9, 0.8, 0.7]\n\
        attenuation = [1.0, 0.25, 0.25]\n\
        [materials.m]\nambient = [0.1, 0.2, 0.3]\ndiffuse = [0.5, 0.4, 0.3]\n\
        specular = [0.2, 0.3, 0.4]\nshininess = 3\n\
        [[objects]]\nplane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }\nmaterial = \"m\"\n";
    let (c, stats) = centre(&scene(text), Chapter::Shading);
    assert_vec_eq(
        "I in a 1 × 1 image of the floor seen along v",
        c,
        i,
        10.0 * TOL,
    );
    assert_eq!(stats.shadow, 0, "the feelers cast at chapter 3");
}

/// "Shading", as the inspector sees it: the local light tells the recorder each term it adds.
/// The sphere scene with a second light behind the sphere, at (0, 0, −10): at the nearest point
/// the recorder hears I_a = ρa·I_m = (0.05, 0.08, 0.09), the first light in front and its
/// unshadowed I_p·(ρd + ρs) = (0.9, 0.8, 0.7)·0.7 arriving whole (no feeler before chapter 4),
/// the second light behind and its zero, and the local light, their sum, which is the pixel's
/// colour at chapter 3.
#[test]
fn ex_local_light_the_recorder_hears_the_ambient_term_each_light_and_the_local_light() {
    let s = scene(&sphere_scene(
        "[0.0, 0.0, 10.0]",
        "[[lights]]\nposition = [0.0, 0.0, -10.0]",
    ));
    let mut o = Options::for_scene(&s, Chapter::Shading);
    (o.width, o.height) = (1, 1);
    let tree = Tracer::new(&s, &o).inspect(0, 0);
    let hit = tree.samples[0]
        .ray
        .hit
        .as_ref()
        .expect("the ray tree of the centre pixel records the sphere's hit");
    let i_a = vec3(0.05, 0.08, 0.09);
    let lit = vec3(0.9, 0.8, 0.7) * 0.7;
    let ambient = hit
        .ambient
        .expect("the recorder hears I_a (rec.ambient): it heard nothing");
    assert_vec_eq("I_a told to rec.ambient", ambient, i_a, TOL);
    assert_eq!(
        hit.lights.len(),
        2,
        "the lights told to rec.light, one call per light: {:?}",
        hit.lights
    );
    let (front, back) = (&hit.lights[0], &hit.lights[1]);
    assert_eq!(
        (front.index, back.index),
        (0, 1),
        "the light numbers told to rec.light, in scene order"
    );
    assert_eq!(
        (front.in_front, back.in_front),
        (true, false),
        "whether light 0 and light 1 lie in front of the surface, n·(L − P) > 0, told to rec.light"
    );
    assert_vec_eq(
        "I_d + I_s of light 0 told to rec.light (unshadowed)",
        front.unshadowed,
        lit,
        10.0 * TOL,
    );
    assert_eq!(
        (front.feeler.is_none(), front.share),
        (true, 1.0),
        "(no feeler, share) of light 0 at chapter 3"
    );
    assert_vec_eq(
        "(I_d + I_s)·share of light 0 told to rec.light (arriving)",
        front.arriving,
        lit,
        10.0 * TOL,
    );
    assert_eq!(
        back.unshadowed,
        Vec3::ZERO,
        "I_d + I_s of light 1, behind the sphere"
    );
    assert_eq!(
        (back.feeler.is_none(), back.share),
        (true, 1.0),
        "(no feeler, share) of light 1, behind the sphere"
    );
    let local = hit
        .local
        .expect("the recorder hears the local light I (rec.local): it heard nothing");
    assert_vec_eq(
        "I told to rec.local; expected I_a + Σ arriving",
        local,
        i_a + lit,
        10.0 * TOL,
    );
    assert_eq!(
        local, tree.colour,
        "I told to rec.local, and the pixel's colour"
    );
    assert_eq!(tree.rays, 1, "the rays of the tree: no feeler at chapter 3");
}
