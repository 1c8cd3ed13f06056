//! Chapter 5 — reflection and refraction (notes: "Reflection and Refraction", "Lighting
//! Equations"): the mirror direction, Snell's law, total internal reflection, recursion.

mod common;

use approx::assert_abs_diff_eq;
use common::{TOL, assert_vec_eq, centre, render_at, render_both_ways, scene};
use whitted::optics::{critical_angle, reflect, refract};
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::{Options, Stage, render};

fn deg(x: Real) -> Real {
    x.to_radians()
}

/// A unit direction in the xy plane, `angle` degrees from −y (travelling down onto a surface
/// with normal +y), leaning towards +x.
fn incoming(angle: Real) -> Vec3 {
    Vec3::new(deg(angle).sin(), -deg(angle).cos(), 0.0)
}

/// "Reflection and Refraction" (erratum): l = d − 2(d·n)n from the ray direction d. A 45° ray
/// (1, −1, 0)/√2 on the floor y = 0 leaves as (1, 1, 0)/√2. The notes' r(t₀) − 2(r(t₀)·n)n,
/// built from the hit point, depends on where the floor is hit — it is not a direction.
#[test]
fn reflection_of_a_45_degree_ray() {
    let k = 1.0 / (2.0 as Real).sqrt();
    let d = vec3(1.0, -1.0, 0.0) * k;
    assert_vec_eq(reflect(d, Vec3::Y), vec3(1.0, 1.0, 0.0) * k, TOL);
    // the notes' formula with the hit point r(t₀) = (3, 0, 0) instead of d
    let p = vec3(3.0, 0.0, 0.0);
    let as_printed = p - 2.0 * p.dot(Vec3::Y) * Vec3::Y;
    assert!((as_printed.normalize() - vec3(1.0, 1.0, 0.0) * k).length() > 0.5);
    // angle in = angle out, and unit length kept, for any incidence
    for a in [0.0, 10.0, 45.0, 80.0] {
        let l = reflect(incoming(a), Vec3::Y);
        assert_abs_diff_eq!(l.length(), 1.0, epsilon = TOL);
        assert_abs_diff_eq!(l.dot(Vec3::Y), deg(a).cos(), epsilon = TOL);
    }
}

/// "Reflection and Refraction": Snell's law air → glass (n = 1.5) at 30°:
/// sin θ₂ = sin 30°/1.5 = 1/3, θ₂ ≈ 19.47°; the ray bends towards the normal and stays in the
/// plane of incidence.
#[test]
fn snell_air_to_glass_at_30_degrees() {
    let t = refract(incoming(30.0), Vec3::Y, 1.0, 1.5).unwrap();
    assert_abs_diff_eq!(t.length(), 1.0, epsilon = TOL);
    let sin2 = t.x; // the tangential component of a unit vector is sin θ₂
    assert_abs_diff_eq!(sin2, 1.0 / 3.0, epsilon = TOL);
    assert_abs_diff_eq!(-t.y, (8.0 as Real).sqrt() / 3.0, epsilon = TOL); // cos θ₂ = √(1 − 1/9)
    assert_abs_diff_eq!(t.z, 0.0, epsilon = TOL);
    assert_abs_diff_eq!(
        sin2.asin().to_degrees(),
        real(19.471_220_634_490_69),
        epsilon = 1e4 * TOL
    );
}

/// "Reflection and Refraction" (erratum): the critical angle satisfies (c₂/c₁)·sin θc = 1, so
/// glass → air gives sin θc = 1/1.5, θc ≈ 41.81°. The notes' (c₁/c₂)·sin θc = 1 asks for
/// sin θc = 1.5, which no angle has.
#[test]
fn critical_angle_from_glass_to_air() {
    let theta_c = critical_angle(1.5, 1.0).unwrap();
    assert_abs_diff_eq!(theta_c.sin(), 1.0 / 1.5, epsilon = TOL);
    assert_abs_diff_eq!(
        theta_c.to_degrees(),
        real(41.810_314_895_778_6),
        epsilon = 1e4 * TOL
    );
    // speeds: c = c₀/n, medium 1 glass, medium 2 air
    let (c1, c2): (Real, Real) = (1.0 / 1.5, 1.0);
    assert_abs_diff_eq!((c2 / c1) * theta_c.sin(), 1.0, epsilon = TOL);
    let notes_sin = 1.0 / (c1 / c2); // from (c₁/c₂)·sin θc = 1
    assert!(
        notes_sin > 1.0,
        "the notes' form has no solution: sin θc = {notes_sin}"
    );
    assert!(
        critical_angle(1.0, 1.5).is_none(),
        "no TIR from air into glass"
    );
}

/// "Reflection and Refraction": glass → air just below the critical angle still refracts,
/// grazing out (sin θ₂ close to 1); just above it, total internal reflection.
#[test]
fn glass_to_air_just_below_and_just_above_the_critical_angle() {
    let theta_c = critical_angle(1.5, 1.0).unwrap().to_degrees();
    let below = refract(incoming(theta_c - 0.1), Vec3::Y, 1.5, 1.0).unwrap();
    assert_abs_diff_eq!(below.length(), 1.0, epsilon = 10.0 * TOL);
    assert!(below.x > 0.99 && below.x < 1.0, "sin θ₂ = {}", below.x);
    assert!(refract(incoming(theta_c + 0.1), Vec3::Y, 1.5, 1.0).is_none());
    assert!(refract(incoming(89.0), Vec3::Y, 1.5, 1.0).is_none());
}

/// A camera on the axis of a glass sphere, a red wall behind it.
fn glass_sphere_scene(max_depth: u32) -> String {
    format!(
        "[camera]\neye = [0.0, 0.0, 6.0]\nfov = 20\n[render]\nmax_depth = {max_depth}\n[ambient]\nintensity = 1.0\n\
         [materials.glass]\nambient = 0.0\ndiffuse = 0.0\nspecular = 0.0\ntransmission = 0.9\nreflection = 0.0\nior = 1.5\n\
         [materials.wall]\nambient = [1.0, 0.0, 0.0]\ndiffuse = 0.0\nspecular = 0.0\n\
         [[objects]]\nsphere = {{ radius = 1.0 }}\nmaterial = \"glass\"\n\
         [[objects]]\nplane = {{ point = [0.0, 0.0, -5.0], normal = [0.0, 0.0, 1.0] }}\nmaterial = \"wall\"\n"
    )
}

/// "Reflection and Refraction": a ray along the axis of a glass sphere meets both surfaces at
/// normal incidence and leaves undeflected: it reaches the wall straight behind, dimmed by
/// the transmission share twice.
#[test]
fn ray_along_the_axis_of_a_glass_sphere_leaves_undeflected() {
    assert_vec_eq(
        refract(Vec3::NEG_Z, Vec3::Z, 1.0, 1.5).unwrap(),
        Vec3::NEG_Z,
        TOL,
    );
    let s = scene(&glass_sphere_scene(5));
    let (c, stats) = centre(&s, Stage::ReflectionRefraction);
    assert_vec_eq(c, vec3(0.81, 0.0, 0.0), 10.0 * TOL); // 0.9 · 0.9 · red
    assert_eq!((stats.refracted, stats.reflected), (2, 0));
}

/// "Lighting Equations": recursion stops at max_depth — a refracted ray needs depth 2 to get
/// through the sphere; with max_depth = 1 it is stopped inside.
#[test]
fn recursion_depth_limits_the_refracted_path() {
    let (c, stats) = centre(&scene(&glass_sphere_scene(1)), Stage::ReflectionRefraction);
    assert_eq!(stats.refracted, 1);
    assert_vec_eq(c, Vec3::ZERO, TOL); // the inner hit has no local light and may recurse no more
    let (_, stats) = centre(&scene(&glass_sphere_scene(0)), Stage::ReflectionRefraction);
    assert_eq!(stats.refracted, 0);
}

/// Two parallel mirrors facing each other, the camera between them looking at one.
fn facing_mirrors(max_depth: u32, reflection: f64) -> String {
    format!(
        "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n[render]\nmax_depth = {max_depth}\n\
         [materials.mirror]\nambient = 0.1\ndiffuse = 0.0\nspecular = 0.0\nreflection = {reflection}\n\
         [[objects]]\nplane = {{ point = [0.0, 0.0, -2.0], normal = [0.0, 0.0, 1.0] }}\nmaterial = \"mirror\"\n\
         [[objects]]\nplane = {{ point = [0.0, 0.0, 2.0], normal = [0.0, 0.0, -1.0] }}\nmaterial = \"mirror\"\n"
    )
}

/// "Lighting Equations": between two facing mirrors the recursion stops at max_depth: one
/// reflected ray per level, and the colour is the geometric sum ρa·Σ kᵢ for i = 0…max_depth.
#[test]
fn two_facing_mirrors_stop_at_max_depth() {
    for depth in [0, 1, 3, 5, 8] {
        let (c, stats) = centre(
            &scene(&facing_mirrors(depth, 0.5)),
            Stage::ReflectionRefraction,
        );
        assert_eq!(stats.reflected, depth as u64, "max_depth {depth}");
        let expected: Real = (0..=depth)
            .map(|i| 0.1 * (0.5 as Real).powi(i as i32))
            .sum();
        assert_abs_diff_eq!(c.x, expected, epsilon = 10.0 * TOL);
    }
}

/// "Lighting Equations": a ray whose weight (product of shares) falls below the threshold is
/// not traced, whatever max_depth says: 0.5^k < 10⁻³ from k = 10 on.
#[test]
fn recursion_stops_when_the_weight_falls_below_the_threshold() {
    let s = scene(&facing_mirrors(50, 0.5));
    let (_, stats) = centre(&s, Stage::ReflectionRefraction);
    assert_eq!(stats.reflected, 9, "0.5^9 ≥ 1e-3 > 0.5^10");
    assert_eq!(Options::MIN_WEIGHT, 1e-3);
}

/// "Reflection and Refraction": inside a glass sphere, a ray meeting the wall beyond the
/// critical angle is totally reflected: no refracted ray, the transmitted share goes to the
/// mirror ray, and it stays trapped until max_depth.
#[test]
fn total_internal_reflection_sends_the_transmitted_share_into_reflection() {
    // the eye inside a glass ball of radius 10, near its wall, looking along it
    let text = "[camera]\neye = [0.0, 9.5, 0.0]\nlook_at = [1.0, 9.5, 0.0]\n[render]\nmax_depth = 4\n\
        [ambient]\nintensity = 1.0\n\
        [materials.glass]\nambient = 0.1\ndiffuse = 0.0\nspecular = 0.0\ntransmission = 0.5\nreflection = 0.0\nior = 1.5\n\
        [[objects]]\nsphere = { radius = 10.0 }\nmaterial = \"glass\"\n";
    let (c, stats) = centre(&scene(text), Stage::ReflectionRefraction);
    assert_eq!(stats.refracted, 0);
    assert_eq!(stats.total_internal, 4);
    assert_eq!(stats.reflected, 4);
    // each bounce adds ρa·I_m = 0.1, weighted by the whole transmitted share 0.5 per level
    let expected: Real = (0..=4).map(|i| 0.1 * (0.5 as Real).powi(i)).sum();
    assert_abs_diff_eq!(c.x, expected, epsilon = 10.0 * TOL);
}

/// "Lighting Equations" and "model only what a scene requires": matte scenes cast no secondary
/// rays at stage 5; a mirror adds reflected rays only; glass adds refracted ones.
#[test]
fn secondary_rays_only_for_mirror_and_glass_materials() {
    let matte = "[camera]\neye = [0.0, 0.0, 5.0]\n[[lights]]\nposition = [3.0, 3.0, 5.0]\n[[objects]]\nsphere = {}\n";
    let (_, stats) = render_at(&scene(matte), Stage::ReflectionRefraction, 24, 24);
    assert_eq!((stats.reflected, stats.refracted), (0, 0));
    assert!(stats.shadow > 0);
    let mirror = format!("{matte}material = \"m\"\n[materials.m]\nreflection = 0.5\n");
    let (_, stats) = render_at(&scene(&mirror), Stage::ReflectionRefraction, 24, 24);
    assert!(stats.reflected > 0);
    assert_eq!(stats.refracted, 0);
    let (_, stats) = render_at(&scene(&mirror), Stage::Shadows, 24, 24);
    assert_eq!(
        (stats.reflected, stats.refracted),
        (0, 0),
        "chapter 4 never recurses"
    );
    let glass = format!("{matte}material = \"g\"\n[materials.g]\ntransmission = 0.5\n");
    let (_, stats) = render_at(&scene(&glass), Stage::ReflectionRefraction, 24, 24);
    assert!(stats.refracted > 0);
}

/// Supersampling is deterministic: the same image every run, and different from one sample.
#[test]
fn supersampling_is_the_same_every_run() {
    let s = scene(&glass_sphere_scene(5));
    let mut o = Options::for_scene(&s, Stage::ReflectionRefraction);
    o.width = 40;
    o.height = 30;
    o.samples = 4;
    let (a, sa) = render_both_ways(&s, &o);
    let (b, _) = render(&s, &o);
    assert_eq!(a, b);
    assert_eq!(sa.primary, 40 * 30 * 4);
    o.samples = 1;
    let (c, _) = render(&s, &o);
    assert_ne!(a, c);
}
