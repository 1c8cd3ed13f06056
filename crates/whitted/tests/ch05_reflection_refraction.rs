//! Chapter 5 — reflection and refraction (notes: "Reflection and Refraction", "Lighting
//! Equations"): the mirror direction, Snell's law, total internal reflection, recursion.
//!
//! A test named `ex_NAME_…` checks the exercise NAME of `chapters/formulas.toml`;
//! `Tracer::reflect_and_refract` (5.5) is seen through the renderer and the inspector.

mod common;

use common::{
    TOL, assert_near, assert_vec_eq, centre, first_difference, render_at, render_both_ways,
    render_here, scene,
};
use whitted::offset::Offset;
use whitted::optics::{critical_angle, critical_angle_sine, indices, reflect, refract};
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::inspect::RayTree;
use whitted::render::inspect::{HitNode, RayNode};
use whitted::render::{Chapter, Options, RayKind, Stop, Tracer};

fn deg(x: Real) -> Real {
    x.to_radians()
}

/// A unit direction in the xy plane, `angle` degrees from −y (travelling down onto a surface
/// with normal +y), leaning towards +x.
fn incoming(angle: Real) -> Vec3 {
    Vec3::new(deg(angle).sin(), -deg(angle).cos(), 0.0)
}

/// The transmitted direction of `d` through a surface of normal +y, from index `n1` into `n2`,
/// which must exist.
#[track_caller]
fn refracted(d: Vec3, n1: Real, n2: Real) -> Vec3 {
    refract(d, Vec3::Y, n1, n2).unwrap_or_else(|| {
        panic!(
            "refract(d = {d}, n = y, n₁ = {n1}, n₂ = {n2}) gave none (total internal reflection), \
             expected a transmitted direction: sin θ₁ = {} is below sin θc",
            d.x
        )
    })
}

/// The hit of a ray tree's camera ray, which must be there; `what` names it.
#[track_caller]
fn first_hit(tree: &RayTree, what: &str) -> HitNode {
    tree.samples[0]
        .ray
        .hit
        .clone()
        .unwrap_or_else(|| panic!("the camera ray of the ray tree hits nothing, expected {what}"))
}

/// The hit of a branch of the ray tree, which must be there; `what` names the branch.
#[track_caller]
fn branch_hit(branch: &RayNode, what: &str) -> HitNode {
    branch.hit.clone().unwrap_or_else(|| {
        panic!(
            "{what} ({:?}, from {} along {}) hits nothing, expected a hit",
            branch.kind, branch.origin, branch.direction
        )
    })
}

/// "Reflection and Refraction" (erratum): l = d − 2(d·n)n from the ray direction d. A 45° ray
/// (1, −1, 0)/√2 on the floor y = 0 leaves as (1, 1, 0)/√2. The notes' r(t₀) − 2(r(t₀)·n)n,
/// built from the hit point, depends on where the floor is hit — it is not a direction.
#[test]
fn ex_mirror_ray_reflection_of_a_45_degree_ray() {
    let k = 1.0 / (2.0 as Real).sqrt();
    let d = vec3(1.0, -1.0, 0.0) * k;
    assert_vec_eq(
        "l for d = (1, −1, 0)/√2 on the floor n = y",
        reflect(d, Vec3::Y),
        vec3(1.0, 1.0, 0.0) * k,
        TOL,
    );
    // the notes' formula with the hit point r(t₀) = (3, 0, 0) instead of d
    let p = vec3(3.0, 0.0, 0.0);
    let as_printed = p - 2.0 * p.dot(Vec3::Y) * Vec3::Y;
    assert!(
        (as_printed.normalize() - vec3(1.0, 1.0, 0.0) * k).length() > 0.5,
        "the notes' r(t₀) − 2(r(t₀)·n)n at r(t₀) = (3, 0, 0) is {as_printed}, not a mirror \
         direction"
    );
    // angle in = angle out, and unit length kept, for any incidence
    for a in [0.0, 10.0, 45.0, 80.0] {
        let l = reflect(incoming(a), Vec3::Y);
        let of = format!("for d {a}° from −n, n = y (l = {l})");
        assert_near(&format!("‖l‖ {of}"), l.length(), 1.0, TOL);
        assert_near(
            &format!("l·n {of}; expected cos {a}°"),
            l.dot(Vec3::Y),
            deg(a).cos(),
            TOL,
        );
    }
    // for any d: ‖l‖ = ‖d‖, l·n = −(d·n), and −n gives the same l
    let n = vec3(2.0, -1.0, 2.0) / 3.0;
    let d = vec3(0.3, -4.0, 1.2);
    let l = reflect(d, n);
    let of = format!("for d = (0.3, −4, 1.2), n = (2, −1, 2)/3 (l = {l})");
    assert_near(
        &format!("‖l‖ {of}; expected ‖d‖"),
        l.length(),
        d.length(),
        10.0 * TOL,
    );
    assert_near(
        &format!("l·n {of}; expected −(d·n)"),
        l.dot(n),
        -d.dot(n),
        10.0 * TOL,
    );
    assert_vec_eq(
        &format!("l for −n {of}; expected the same l as for n"),
        reflect(d, -n),
        l,
        10.0 * TOL,
    );
    // by hand: d·n = (0.6 + 4 + 2.4)/3 = 7/3, l = d − (14/3)·n
    assert_vec_eq(
        "l = d − 2(d·n)·n for d = (0.3, −4, 1.2), n = (2, −1, 2)/3",
        l,
        d - (14.0 / 3.0) * n,
        10.0 * TOL,
    );
}

/// "Reflection and Refraction": Snell's law air → glass (n = 1.5) at 30°:
/// sin θ₂ = sin 30°/1.5 = 1/3, θ₂ ≈ 19.47°; the ray bends towards the normal and stays in the
/// plane of incidence.
#[test]
fn ex_refract_snell_air_to_glass_at_30_degrees() {
    let t = refract(incoming(30.0), Vec3::Y, 1.0, 1.5)
        .expect("refract from air into glass at 30°: a transmitted direction, not none");
    let of = format!("for air → glass at θ₁ = 30° (t = {t})");
    assert_near(&format!("‖t‖ {of}"), t.length(), 1.0, TOL);
    let sin2 = t.x; // the tangential component of a unit vector is sin θ₂
    assert_near(
        &format!("sin θ₂, t_x, {of}; expected sin 30°/1.5"),
        sin2,
        1.0 / 3.0,
        TOL,
    );
    // cos θ₂ = √(1 − 1/9)
    assert_near(
        &format!("cos θ₂, −t_y, {of}; expected √(1 − 1/9)"),
        -t.y,
        (8.0 as Real).sqrt() / 3.0,
        TOL,
    );
    assert_near(
        &format!("t_z {of}; expected in the plane of incidence"),
        t.z,
        0.0,
        TOL,
    );
    assert_near(
        &format!("θ₂ in degrees {of}"),
        sin2.asin().to_degrees(),
        real(19.471_220_634_490_69),
        1e4 * TOL,
    );
}

/// "Reflection and Refraction" (erratum): the critical angle satisfies (c₂/c₁)·sin θc = 1, so
/// glass → air gives sin θc = 1/1.5, θc ≈ 41.81°. The notes' (c₁/c₂)·sin θc = 1 asks for
/// sin θc = 1.5, which no angle has.
#[test]
fn ex_critical_angle_from_glass_to_air() {
    let theta_c = critical_angle(1.5, 1.0)
        .expect("glass (1.5) to air (1) has a critical angle: critical_angle_sine gave none");
    assert_near(
        "sin θc from glass to air; expected 1/1.5",
        theta_c.sin(),
        1.0 / 1.5,
        TOL,
    );
    assert_near(
        "θc in degrees from glass to air",
        theta_c.to_degrees(),
        real(41.810_314_895_778_6),
        1e4 * TOL,
    );
    // speeds: c = c₀/n, medium 1 glass, medium 2 air
    let (c1, c2): (Real, Real) = (1.0 / 1.5, 1.0);
    assert_near(
        "(c₂/c₁)·sin θc from glass to air",
        (c2 / c1) * theta_c.sin(),
        1.0,
        TOL,
    );
    let notes_sin = 1.0 / (c1 / c2); // from (c₁/c₂)·sin θc = 1
    assert!(
        notes_sin > 1.0,
        "the notes' form has no solution: sin θc = {notes_sin}"
    );
    let none = critical_angle(1.0, 1.5);
    assert!(
        none.is_none(),
        "the critical angle from air into glass: {none:?}, expected none (no total internal \
         reflection into a denser medium)"
    );
}

/// "Reflection and Refraction": glass → air just below the critical angle still refracts,
/// grazing out (sin θ₂ close to 1); just above it, total internal reflection.
#[test]
fn ex_refract_glass_to_air_just_below_and_just_above_the_critical_angle() {
    let theta_c = critical_angle(1.5, 1.0)
        .expect("glass (1.5) to air (1) has a critical angle")
        .to_degrees();
    let below = refract(incoming(theta_c - 0.1), Vec3::Y, 1.5, 1.0).unwrap_or_else(|| {
        panic!(
            "refract from glass to air at θc − 0.1° = {}°: none, expected a ray",
            theta_c - 0.1
        )
    });
    let of = format!("for glass → air at θc − 0.1° (t = {below})");
    assert_near(&format!("‖t‖ {of}"), below.length(), 1.0, 10.0 * TOL);
    assert!(
        below.x > 0.99 && below.x < 1.0,
        "sin θ₂, t_x, {of}: computed {}, expected just under 1 (grazing out)",
        below.x
    );
    for a in [theta_c + 0.1, 89.0] {
        let t = refract(incoming(a), Vec3::Y, 1.5, 1.0);
        assert!(
            t.is_none(),
            "refract from glass to air at θ₁ = {a}°, past θc = {theta_c}°: {t:?}, expected none \
             (total internal reflection)"
        );
    }
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
fn ex_reflect_and_refract_ray_along_the_axis_of_a_glass_sphere_leaves_undeflected() {
    assert_vec_eq(
        "t for d = −z at normal incidence, air → glass",
        refract(Vec3::NEG_Z, Vec3::Z, 1.0, 1.5)
            .expect("refract at normal incidence: a transmitted direction, not none"),
        Vec3::NEG_Z,
        TOL,
    );
    let s = scene(&glass_sphere_scene(5));
    let (c, stats) = centre(&s, Chapter::ReflectionRefraction);
    assert_vec_eq(
        "I through the glass sphere's axis; expected k_t·k_t·red = 0.9·0.9·(1, 0, 0)",
        c,
        vec3(0.81, 0.0, 0.0),
        10.0 * TOL,
    );
    assert_eq!(
        (stats.refracted, stats.reflected),
        (2, 0),
        "(transmitted, mirror) rays through the glass sphere's axis"
    );
}

/// "Lighting Equations": recursion stops at max_depth — a refracted ray needs depth 2 to get
/// through the sphere; with max_depth = 1 it is stopped inside.
#[test]
fn ex_reflect_and_refract_recursion_depth_limits_the_refracted_path() {
    let (c, stats) = centre(
        &scene(&glass_sphere_scene(1)),
        Chapter::ReflectionRefraction,
    );
    assert_eq!(
        stats.refracted, 1,
        "the transmitted rays with max_depth = 1"
    );
    assert_vec_eq(
        "I through the glass sphere with max_depth = 1; expected black: the inner hit has no local \
         light and may recurse no more",
        c,
        Vec3::ZERO,
        TOL,
    );
    let (_, stats) = centre(
        &scene(&glass_sphere_scene(0)),
        Chapter::ReflectionRefraction,
    );
    assert_eq!(
        stats.refracted, 0,
        "the transmitted rays with max_depth = 0"
    );
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
fn ex_reflect_and_refract_two_facing_mirrors_stop_at_max_depth() {
    for depth in [0, 1, 3, 5, 8] {
        let (c, stats) = centre(
            &scene(&facing_mirrors(depth, 0.5)),
            Chapter::ReflectionRefraction,
        );
        assert_eq!(
            stats.reflected, depth as u64,
            "the mirror rays between two mirrors, max_depth = {depth}"
        );
        let expected: Real = (0..=depth)
            .map(|i| 0.1 * (0.5 as Real).powi(i as i32))
            .sum();
        assert_near(
            &format!(
                "I (red) between two mirrors of k_r = 0.5, max_depth = {depth}; expected ρa·Σ k_r^i"
            ),
            c.x,
            expected,
            10.0 * TOL,
        );
    }
}

/// "Lighting Equations": a ray whose weight (product of shares) falls below the threshold is
/// not traced, whatever max_depth says: 0.5^k < 10⁻³ from k = 10 on.
#[test]
fn ex_reflect_and_refract_recursion_stops_when_the_weight_falls_below_the_threshold() {
    let s = scene(&facing_mirrors(50, 0.5));
    let (_, stats) = centre(&s, Chapter::ReflectionRefraction);
    assert_eq!(
        stats.reflected, 9,
        "the mirror rays between two mirrors of k_r = 0.5, max_depth = 50: 0.5⁹ ≥ 10⁻³ > 0.5¹⁰"
    );
    assert_eq!(Options::MIN_WEIGHT, 1e-3, "the weight threshold");
}

/// "Reflection and Refraction": inside a glass sphere, a ray meeting the wall beyond the
/// critical angle is totally reflected: no refracted ray, the transmitted share goes to the
/// mirror ray, and it stays trapped until max_depth.
#[test]
fn ex_reflect_and_refract_total_internal_reflection_sends_the_transmitted_share_into_reflection() {
    // the eye inside a glass ball of radius 10, near its wall, looking along it
    let text = "[camera]\neye = [0.0, 9.5, 0.0]\nlook_at = [1.0, 9.5, 0.0]\n[render]\nmax_depth = 4\n\
        [ambient]\nintensity = 1.0\n\
        [materials.glass]\nambient = 0.1\ndiffuse = 0.0\nspecular = 0.0\ntransmission = 0.5\nreflection = 0.0\nior = 1.5\n\
        [[objects]]\nsphere = { radius = 10.0 }\nmaterial = \"glass\"\n";
    let (c, stats) = centre(&scene(text), Chapter::ReflectionRefraction);
    assert_eq!(
        (stats.refracted, stats.total_internal, stats.reflected),
        (0, 4, 4),
        "(transmitted rays, total internal reflections, mirror rays) inside the glass ball, \
         max_depth = 4"
    );
    // each bounce adds ρa·I_m = 0.1, weighted by the whole transmitted share 0.5 per level
    let expected: Real = (0..=4).map(|i| 0.1 * (0.5 as Real).powi(i)).sum();
    assert_near(
        "I (red) inside the glass ball; expected ρa·Σ (k_r + k_t)^i, the transmitted share reflected",
        c.x,
        expected,
        10.0 * TOL,
    );
}

/// "Lighting Equations" and "model only what a scene requires": matte scenes cast no secondary
/// rays at chapter 5; a mirror adds reflected rays only; glass adds refracted ones.
#[test]
fn ex_reflect_and_refract_secondary_rays_only_for_mirror_and_glass_materials() {
    let matte = "[camera]\neye = [0.0, 0.0, 5.0]\n[[lights]]\nposition = [3.0, 3.0, 5.0]\n[[objects]]\nsphere = {}\n";
    let (_, stats) = render_at(&scene(matte), Chapter::ReflectionRefraction, 24, 24);
    assert_eq!(
        (stats.reflected, stats.refracted),
        (0, 0),
        "(mirror, transmitted) rays of a matte sphere"
    );
    assert!(
        stats.shadow > 0,
        "the feelers of a lit matte sphere: {}",
        stats.shadow
    );
    let mirror = format!("{matte}material = \"m\"\n[materials.m]\nreflection = 0.5\n");
    let (_, stats) = render_at(&scene(&mirror), Chapter::ReflectionRefraction, 24, 24);
    assert!(
        stats.reflected > 0 && stats.refracted == 0,
        "(mirror, transmitted) rays of a mirror sphere (k_r = 0.5): ({}, {}), expected some \
         mirror rays and no transmitted one",
        stats.reflected,
        stats.refracted
    );
    let (_, stats) = render_at(&scene(&mirror), Chapter::Shadows, 24, 24);
    assert_eq!(
        (stats.reflected, stats.refracted),
        (0, 0),
        "(mirror, transmitted) rays of a mirror sphere at chapter 4, which never recurses"
    );
    let glass = format!("{matte}material = \"g\"\n[materials.g]\ntransmission = 0.5\n");
    let (_, stats) = render_at(&scene(&glass), Chapter::ReflectionRefraction, 24, 24);
    assert!(
        stats.refracted > 0,
        "the transmitted rays of a glass sphere (k_t = 0.5): {}",
        stats.refracted
    );
}

/// Supersampling is deterministic: the same image every run, and different from one sample.
#[test]
fn supersampling_is_the_same_every_run() {
    let s = scene(&glass_sphere_scene(5));
    let mut o = Options::for_scene(&s, Chapter::ReflectionRefraction);
    o.width = 40;
    o.height = 30;
    o.samples = 4;
    let (a, sa) = render_both_ways(&s, &o);
    let (b, _) = render_here(&s, &o);
    let differ = first_difference(&a, &b);
    assert!(
        differ.is_none(),
        "two renders with 4 samples per pixel differ: (x, y, first, second) = {differ:?}"
    );
    assert_eq!(
        sa.primary,
        40 * 30 * 4,
        "the camera rays of 40 × 30 pixels, 4 samples each"
    );
    o.samples = 1;
    let (c, _) = render_here(&s, &o);
    assert!(
        first_difference(&a, &c).is_some(),
        "the render with 4 samples per pixel is the same as with one, all {} pixels of it",
        a.pixels.len()
    );
}

/// "Reflection and Refraction": a ray entering a material of index `ior` from air goes from
/// n₁ = 1 to n₂ = ior; leaving it, from n₁ = ior to n₂ = 1. The notes' index of medium 2
/// relative to medium 1 is n₂₁ = c₁/c₂; with speeds c = c₀/n it is (c₀/n₁)/(c₀/n₂) = n₂/n₁:
/// air → water c₁/c₂ = 1.33, water → air 1/1.33 ≈ 0.7519.
#[test]
fn ex_refractive_indices_indices_go_from_air_into_the_material_and_back() {
    for (entering, ior, expected) in [
        (true, 1.5, (1.0, 1.5)),
        (false, 1.5, (1.5, 1.0)),
        (true, 1.33, (1.0, 1.33)),
        (false, 2.42, (2.42, 1.0)),
    ] {
        let got = indices(entering, ior);
        assert!(
            got == expected,
            "(n₁, n₂) for entering = {entering}, ior = {ior}: computed {got:?}, expected \
             {expected:?} (n₁ the side the ray comes from)"
        );
    }
    let speed = |n: Real| 1.0 / n; // c = c₀/n with c₀ = 1
    let (n1, n2) = indices(true, 1.33);
    // n₂₁ = c₁/c₂
    assert_near(
        &format!("n₂₁ = c₁/c₂ from air into water, (n₁, n₂) = ({n1}, {n2})"),
        speed(n1) / speed(n2),
        1.33,
        TOL,
    );
    assert_near(
        &format!("c₁/c₂ from air into water, (n₁, n₂) = ({n1}, {n2}); expected n₂/n₁"),
        speed(n1) / speed(n2),
        n2 / n1,
        TOL,
    );
    let (n1, n2) = indices(false, 1.33);
    assert_near(
        &format!("n₂₁ = c₁/c₂ from water into air, (n₁, n₂) = ({n1}, {n2}); expected 1/1.33"),
        speed(n1) / speed(n2),
        real(0.751_879_699_248_120_3),
        TOL,
    );
}

/// "Reflection and Refraction" (erratum): sin θc = n₂/n₁, from (c₂/c₁)·sin θc = 1. Glass to
/// air, (1.5, 1): ⅔; diamond to water, (2.42, 1.33): 1.33/2.42 ≈ 0.549587; none from air into
/// glass or between equal indices, where no angle reflects totally.
#[test]
fn ex_critical_angle_sine_is_n2_over_n1() {
    for (n1, n2, expected) in [
        (1.5, 1.0, 2.0 / 3.0),
        (2.42, 1.33, real(0.549_586_776_859_504_1)),
    ] {
        let sine = critical_angle_sine(n1, n2).unwrap_or_else(|| {
            panic!("sin θc from n₁ = {n1} to n₂ = {n2}: none, expected n₂/n₁ = {expected}")
        });
        assert_near(
            &format!("sin θc from n₁ = {n1} to n₂ = {n2}; expected n₂/n₁"),
            sine,
            expected,
            TOL,
        );
    }
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.5)] {
        assert_eq!(
            critical_angle_sine(n1, n2),
            None,
            "sin θc from n₁ = {n1} to n₂ = {n2} (n₁ ≤ n₂: no total internal reflection)"
        );
    }
}

/// "Reflection and Refraction": at normal incidence the ray goes on unbent, whatever the
/// indices; between equal indices it goes on unbent at any angle; otherwise it bends towards
/// the normal going into the denser medium (sin θ₂ < sin θ₁) and away from it going out.
#[test]
fn ex_refract_refraction_bends_only_between_different_indices() {
    for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (1.33, 2.42)] {
        assert_vec_eq(
            &format!("t for d = −y at normal incidence, n₁ = {n1} → n₂ = {n2}; expected d, unbent"),
            refracted(Vec3::NEG_Y, n1, n2),
            Vec3::NEG_Y,
            TOL,
        );
    }
    for a in [10.0, 45.0, 80.0] {
        let d = incoming(a);
        assert_vec_eq(
            &format!("t for d {a}° from −n, n₁ = n₂ = 1.5; expected d, unbent"),
            refracted(d, 1.5, 1.5),
            d,
            10.0 * TOL,
        );
        let into = refracted(d, 1.0, 1.5);
        assert!(
            into.x < d.x,
            "sin θ₂ = t_x for d {a}° from −n, air → glass, is {}, sin θ₁ = {}: expected \
             smaller (towards the normal)",
            into.x,
            d.x
        );
    }
    let out = refracted(incoming(30.0), 1.5, 1.0);
    assert!(
        out.x > incoming(30.0).x,
        "sin θ₂ = t_x for d 30° from −n, glass → air, is {}, sin θ₁ = ½: expected larger \
         (away from the normal)",
        out.x
    );
}

/// "Reflection and Refraction": through a glass slab with parallel faces a ray comes out
/// parallel to the way it went in: into the glass through the top face (air to glass, the
/// normal (0, 1, 0) facing the ray), out through the bottom face (glass to air, the normal
/// facing the ray is (0, 1, 0) again).
#[test]
fn ex_refract_a_slab_with_parallel_faces_lets_the_ray_out_parallel() {
    for a in [0.0, 20.0, 55.0, 85.0] {
        let d = incoming(a);
        let (n1, n2) = indices(true, 1.5);
        let inside = refracted(d, n1, n2);
        let (n1, n2) = indices(false, 1.5);
        let out = refracted(inside, n1, n2);
        assert_vec_eq(
            &format!("t out of a slab of glass for d {a}° from −n (inside: {inside}); expected d"),
            out,
            d,
            10.0 * TOL,
        );
    }
}

/// "Reflection and Refraction": Snell's law sin θ₁/c₁ = sin θ₂/c₂, i.e. n₁·sin θ₁ = n₂·sin θ₂,
/// on `refract`'s output (for a unit t, sin θ₂ is its component along the surface). At 30°
/// from air into water: sin θ₂ = 0.5/1.33 = 50/133 ≈ 0.375940, bent towards the normal; from
/// water into air: sin θ₂ = 1.33·0.5 = 0.665, bent away. At 45° into water: sin θ₂ =
/// (√2/2)/1.33 ≈ 0.531659.
#[test]
fn ex_refract_refracted_ray_obeys_n1_sin_theta1_equals_n2_sin_theta2() {
    for (entering, angle, sin2) in [
        (true, 30.0, 0.375_939_849_624_060_13),
        (false, 30.0, 0.665),
        (true, 45.0, 0.531_659_233_974_847_8),
    ] {
        let (n1, n2) = indices(entering, 1.33);
        let t = refracted(incoming(angle), n1, n2);
        let of = format!("for θ₁ = {angle}°, n₁ = {n1} → n₂ = {n2} (t = {t})");
        assert_near(&format!("‖t‖ {of}"), t.length(), 1.0, 10.0 * TOL);
        assert_near(
            &format!("sin θ₂, t_x, {of}; expected n₁·sin θ₁/n₂"),
            t.x,
            real(sin2),
            10.0 * TOL,
        );
        assert_near(
            &format!("t_z {of}; expected in the plane of incidence"),
            t.z,
            0.0,
            TOL,
        );
        assert!(
            t.y < 0.0,
            "t_y {of} is {}: the ray should go on through the surface (t_y < 0)",
            t.y
        );
        assert_near(
            &format!("n₁·sin θ₁ − n₂·sin θ₂ {of}; expected by Snell's law"),
            n1 * deg(angle).sin() - n2 * t.x,
            0.0,
            10.0 * TOL,
        );
    }
}

/// "Reflection and Refraction", the notes' table of indices: from each material into air the
/// critical angle is θc = asin(n₂/n₁) = asin(1/n). By hand: water 1.33, asin(0.751880) =
/// 48.7535°; diamond 2.42, asin(0.413223) = 24.4075°; glass 1.5, asin(0.666667) = 41.8103°;
/// glass 1.9, asin(0.526316) = 31.7569°. 0.01° short of θc a ray still gets out, with
/// n·sin θ₁ = sin θ₂ just under 1; 0.01° past it, total internal reflection.
#[test]
fn ex_refract_critical_angles_of_the_notes_table() {
    for (n, sin_c, theta_c_deg) in [
        (1.33, 0.751_879_699_248_120_3, 48.753_466_631_327_235),
        (2.42, 0.413_223_140_495_867_8, 24.407_468_917_986_588),
        (1.5, 0.666_666_666_666_666_6, 41.810_314_895_778_596),
        (1.9, 0.526_315_789_473_684_2, 31.756_863_859_297_127),
    ] {
        let n = real(n);
        let sine = critical_angle_sine(n, 1.0)
            .unwrap_or_else(|| panic!("sin θc from n = {n} into air: none, expected 1/n"));
        assert_near(
            &format!("sin θc from n = {n} into air; expected 1/n"),
            sine,
            real(sin_c),
            TOL,
        );
        let theta_c = critical_angle(n, 1.0)
            .unwrap_or_else(|| panic!("θc from n = {n} into air: none, expected asin(1/n)"));
        assert_near(
            &format!("θc in radians from n = {n} into air"),
            theta_c,
            deg(real(theta_c_deg)),
            10.0 * TOL,
        );
        let none = critical_angle(1.0, n);
        assert!(
            none.is_none(),
            "θc from air into n = {n}: {none:?}, expected none"
        );
        let a = real(theta_c_deg - 0.01);
        let below = refract(incoming(a), Vec3::Y, n, 1.0).unwrap_or_else(|| {
            panic!("refract from n = {n} into air at θc − 0.01° = {a}°: none, expected a ray")
        });
        assert!(
            below.x < 1.0 && below.x > 0.99,
            "sin θ₂, t_x, from n = {n} into air at θc − 0.01°: computed {}, expected just under 1",
            below.x
        );
        assert_near(
            &format!("sin θ₂, t_x, from n = {n} into air at θc − 0.01°; expected n·sin θ₁"),
            below.x,
            n * deg(a).sin(),
            10.0 * TOL,
        );
        let past = refract(incoming(real(theta_c_deg + 0.01)), Vec3::Y, n, 1.0);
        assert!(
            past.is_none(),
            "refract from n = {n} into air at θc + 0.01°: {past:?}, expected none (total \
             internal reflection)"
        );
    }
}

/// A floor at y = 0 that is a mirror (k_r = 0.3) and translucent (k_t = 0.5, n = 1.5), seen
/// straight down from (0, 2, 0); an ambient-only ceiling at y = 5 above the camera; one light
/// at L = (√3, 1, 0); a blue-grey background below the floor.
const FIVE_TERMS: &str = "[camera]\neye = [0.0, 2.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\n\
    [image]\nbackground = [0.2, 0.4, 0.6]\n[render]\nmax_depth = 1\n\
    [ambient]\nintensity = [1.0, 0.5, 0.5]\n\
    [[lights]]\nposition = [1.7320508075688772, 1.0, 0.0]\nintensity = [1.0, 0.8, 0.6]\n\
    [materials.floor]\nambient = [0.1, 0.2, 0.3]\ndiffuse = [0.4, 0.3, 0.2]\nspecular = 0.2\nshininess = 3\n\
    reflection = 0.3\ntransmission = 0.5\nior = 1.5\n\
    [materials.ceiling]\nambient = [0.4, 0.6, 0.2]\ndiffuse = 0.0\nspecular = 0.0\n\
    [[objects]]\nplane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }\nmaterial = \"floor\"\n\
    [[objects]]\nplane = { point = [0.0, 5.0, 0.0], normal = [0.0, -1.0, 0.0] }\nmaterial = \"ceiling\"\n";

/// "Lighting Equations": I = I_a + I_d + I_s + I_l + I_r, all five non-zero, one level deep.
/// The camera ray d = (0, −1, 0) meets the floor at P = 0 with n = v = (0, 1, 0); s = (√3, 1, 0)/2
/// (60° from n, nothing in between, d = 2, no attenuation): n·s = ½, r = (−√3/2, ½, 0),
/// r·v = ½, (r·v)³ = ⅛. By hand, per channel (r, g, b):
/// - I_a = ρa·I_m = (0.1, 0.2, 0.3)·(1, 0.5, 0.5) = (0.1, 0.1, 0.15)
/// - I_d = I_p·ρd·(n·s) = (1, 0.8, 0.6)·(0.4, 0.3, 0.2)·½ = (0.2, 0.12, 0.06)
/// - I_s = I_p·ρs·(r·v)³ = (1, 0.8, 0.6)·0.2·⅛ = (0.025, 0.02, 0.015)
/// - I_l: the mirror ray (0, 1, 0) meets the ceiling, lit by ambient only:
///   k_r·ρa′·I_m = 0.3·(0.4, 0.6, 0.2)·(1, 0.5, 0.5) = 0.3·(0.4, 0.3, 0.1) = (0.12, 0.09, 0.03)
/// - I_r: the transmitted ray, at normal incidence straight down, meets nothing:
///   k_t·background = 0.5·(0.2, 0.4, 0.6) = (0.1, 0.2, 0.3)
///
/// I = (0.545, 0.53, 0.555): one feeler, one mirror ray, one transmitted ray. Exchanging k_r
/// and k_t would give (0.585, 0.51, 0.455), and dropping any term changes the sum.
#[test]
fn ex_reflect_and_refract_five_terms_of_the_lighting_equation_add_up() {
    let s = scene(FIVE_TERMS);
    let (c, stats) = centre(&s, Chapter::ReflectionRefraction);
    assert_vec_eq(
        "I_a + I_d + I_s + k_r·I_l + k_t·I_r at the floor (k_r and k_t exchanged would give \
         (0.585, 0.51, 0.455))",
        c,
        vec3(0.545, 0.53, 0.555),
        10.0 * TOL,
    );
    assert_eq!(
        (
            stats.primary,
            stats.shadow,
            stats.reflected,
            stats.refracted
        ),
        (1, 1, 1, 1),
        "(camera, feeler, mirror, transmitted) rays at the floor"
    );
    // the local part alone, at chapter 4: I_a + I_d + I_s
    let (local, _) = centre(&s, Chapter::Shadows);
    assert_vec_eq(
        "I_a + I_d + I_s at the floor, chapter 4",
        local,
        vec3(0.325, 0.24, 0.225),
        10.0 * TOL,
    );
}

/// "Lighting Equations": between two facing mirrors of k_r = 0.5, the number of reflected rays
/// never decreases as `max_depth` grows, stops growing at 9 (the weight limit: 0.5⁹ ≥ 10⁻³ >
/// 0.5¹⁰) whatever larger depth is allowed, and `max_depth = 0` casts none and gives the image
/// of chapter 4.
#[test]
fn ex_reflect_and_refract_the_recursion_stops_at_max_depth_or_at_the_weight_limit() {
    let mut last = 0;
    for depth in 0..=14 {
        let (_, stats) = render_at(
            &scene(&facing_mirrors(depth, 0.5)),
            Chapter::ReflectionRefraction,
            6,
            4,
        );
        let per_pixel = stats.reflected / 24;
        assert_eq!(
            stats.reflected % 24,
            0,
            "the mirror rays of 6 × 4 pixels, {} with max_depth = {depth}, split evenly: every \
             pixel sees the mirrors",
            stats.reflected
        );
        assert!(
            per_pixel >= last,
            "the mirror rays per pixel with max_depth = {depth}: {per_pixel}, fewer than the \
             {last} of max_depth = {}",
            depth - 1
        );
        assert_eq!(
            per_pixel,
            u64::from(depth.min(9)),
            "the mirror rays per pixel with max_depth = {depth}: min(max_depth, 9)"
        );
        last = per_pixel;
    }
    let s = scene(&facing_mirrors(0, 0.5));
    let (at_5, stats) = render_at(&s, Chapter::ReflectionRefraction, 6, 4);
    assert_eq!(stats.reflected, 0, "the mirror rays with max_depth = 0");
    let (at_4, _) = render_at(&s, Chapter::Shadows, 6, 4);
    let differ = first_difference(&at_5, &at_4);
    assert!(
        differ.is_none(),
        "the image with max_depth = 0 differs from chapter 4's: (x, y, chapter 5, chapter 4) = \
         {differ:?}"
    );
}

/// A row of 20 panes of clear glass (k_t = 0.5, k_r = 0, index 1: rays go straight through),
/// one unit apart, seen head-on with max_depth 50: the k-th transmitted ray carries weight
/// 0.5^k, so rays 1 to 9 are traced (0.5⁹ ≈ 0.002 ≥ 10⁻³) and the tenth is stopped by its weight
/// (0.5¹⁰ ≈ 0.00098), as the mirror rays between two mirrors are. The colour is then the
/// ambient light of the first ten panes, ρa·Σ 0.5^k for k = 0…9.
#[test]
fn ex_reflect_and_refract_a_transmitted_ray_too_faint_to_matter_is_not_traced() {
    let mut text = String::from(
        "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n[render]\nmax_depth = 50\n\
         [materials.pane]\nambient = 0.1\ndiffuse = 0.0\nspecular = 0.0\ntransmission = 0.5\nreflection = 0.0\nior = 1.0\n",
    );
    for k in 1..=20 {
        text += &format!(
            "[[objects]]\nplane = {{ point = [0.0, 0.0, -{k}.0], normal = [0.0, 0.0, 1.0] }}\nmaterial = \"pane\"\n"
        );
    }
    let s = scene(&text);
    let mut o = Options::for_scene(&s, Chapter::ReflectionRefraction);
    (o.width, o.height) = (1, 1);
    let tree = Tracer::new(&s, &o).inspect(0, 0);
    let mut hit = first_hit(&tree, "the first pane");
    let mut through = 0;
    while let Some(branch) = hit.branches.first() {
        through += 1;
        assert_eq!(
            branch.kind,
            RayKind::Transmitted,
            "the kind of branch {through} down the panes (k_r = 0)"
        );
        assert_near(
            &format!("the weight of transmitted ray {through}; expected 0.5^{through}"),
            branch.weight,
            0.5_f64.powi(through) as Real,
            TOL,
        );
        hit = branch_hit(branch, &format!("transmitted ray {through}"));
    }
    assert_eq!(
        through, 9,
        "the transmitted rays traced down the panes: the tenth (weight 0.5¹⁰ < 10⁻³) is not"
    );
    assert_eq!(
        hit.stopped,
        vec![(RayKind::Transmitted, Stop::Weight)],
        "why the branches of the ninth pane's hit stopped"
    );
    let (c, stats) = centre(&s, Chapter::ReflectionRefraction);
    let expected: f64 = (0..10).map(|k| 0.1 * 0.5_f64.powi(k)).sum();
    assert_vec_eq(
        "I through the panes; expected ρa·Σ 0.5^k for k = 0…9",
        c,
        Vec3::splat(expected as Real),
        1e-5,
    );
    assert_eq!(stats.refracted, 9, "the transmitted rays through the panes");
}

/// "Lighting Equations", as the inspector sees it: the floor of [`FIVE_TERMS`] sends its
/// transmitted ray first (k_t = 0.5, weight 0.5, depth 1), which brings back the background
/// (0.2, 0.4, 0.6), then its mirror ray (k_r = 0.3), which brings back the ceiling's ambient
/// light (0.4, 0.3, 0.1); with `Offset::Scaled(0.01)` they start 0.01 off the surface, each
/// on its own side, and nothing is stopped. Inside the glass ball of the total-internal-reflection scene the transmitted
/// branch is reported stopped by total internal reflection and the mirror ray carries
/// k_r + k_t = 0 + 0.5; at `max_depth` the branches are reported stopped by the depth, and
/// between the facing mirrors the tenth mirror ray by its weight.
#[test]
fn ex_reflect_and_refract_the_recorder_hears_each_branch_and_why_one_stopped() {
    let inspect_with = |text: &str, offset: Offset| {
        let s = scene(text);
        let mut o = Options::for_scene(&s, Chapter::ReflectionRefraction);
        (o.width, o.height, o.offset) = (1, 1, offset);
        Tracer::new(&s, &o).inspect(0, 0)
    };
    let inspect = |text: &str| inspect_with(text, Offset::default());
    let tree = inspect_with(FIVE_TERMS, Offset::Scaled(0.01));
    let floor = first_hit(&tree, "the floor");
    assert!(
        floor.stopped.is_empty(),
        "the floor's branches stopped: {:?}, expected none stopped",
        floor.stopped
    );
    let kinds: Vec<RayKind> = floor.branches.iter().map(|b| b.kind).collect();
    assert_eq!(
        kinds,
        [RayKind::Transmitted, RayKind::Mirror],
        "the floor's branches, in order: the transmitted ray first, then the mirror ray"
    );
    let (through, mirror) = (&floor.branches[0], &floor.branches[1]);
    assert_eq!(
        (through.depth, mirror.depth),
        (1, 1),
        "the depths of the floor's (transmitted, mirror) rays"
    );
    for (what, value, expected) in [
        ("k of the transmitted ray: k_t", through.k, 0.5),
        ("weight of the transmitted ray: 1·k_t", through.weight, 0.5),
        ("k of the mirror ray: k_r", mirror.k, 0.3),
        ("weight of the mirror ray: 1·k_r", mirror.weight, 0.3),
    ] {
        assert_near(&format!("the {what}"), value, expected, TOL);
    }
    assert_vec_eq(
        "the transmitted ray's direction (normal incidence, straight on)",
        through.direction,
        Vec3::NEG_Y,
        TOL,
    );
    assert_vec_eq(
        "the mirror ray's direction l = d − 2(d·n)·n",
        mirror.direction,
        Vec3::Y,
        TOL,
    );
    assert_vec_eq(
        "the transmitted ray's origin, 0.01 below the floor",
        through.origin,
        vec3(0.0, -0.01, 0.0),
        10.0 * TOL,
    );
    assert_vec_eq(
        "the mirror ray's origin, 0.01 above the floor",
        mirror.origin,
        vec3(0.0, 0.01, 0.0),
        10.0 * TOL,
    );
    assert!(
        through.hit.is_none(),
        "the transmitted ray hits {:?}, expected nothing below the floor",
        through.hit.as_ref().map(|h| (h.object, h.t))
    );
    assert_vec_eq(
        "the colour the transmitted ray brings back; expected the background",
        through.colour,
        vec3(0.2, 0.4, 0.6),
        TOL,
    );
    assert_vec_eq(
        "the colour the mirror ray brings back; expected the ceiling's ρa·I_m",
        mirror.colour,
        vec3(0.4, 0.3, 0.1),
        10.0 * TOL,
    );

    let tir = "[camera]\neye = [0.0, 9.5, 0.0]\nlook_at = [1.0, 9.5, 0.0]\n[render]\nmax_depth = 1\n\
        [materials.glass]\nambient = 0.1\ndiffuse = 0.0\nspecular = 0.0\ntransmission = 0.5\nreflection = 0.0\nior = 1.5\n\
        [[objects]]\nsphere = { radius = 10.0 }\nmaterial = \"glass\"\n";
    let tree = inspect(tir);
    let wall = first_hit(&tree, "the glass ball's wall from inside");
    assert_eq!(
        wall.stopped,
        vec![(RayKind::Transmitted, Stop::TotalInternalReflection)],
        "why the wall's branches stopped, seen from inside past the critical angle"
    );
    let kinds: Vec<RayKind> = wall.branches.iter().map(|b| b.kind).collect();
    assert_eq!(
        kinds,
        [RayKind::Mirror],
        "the wall's branches under total internal reflection"
    );
    assert_near(
        "the k of the mirror ray under total internal reflection; expected k_r + k_t = 0 + 0.5",
        wall.branches[0].k,
        0.5,
        TOL,
    );
    let next = branch_hit(&wall.branches[0], "the mirror ray inside the ball");
    assert_eq!(
        next.stopped,
        vec![(RayKind::Transmitted, Stop::MaxDepth)],
        "why the next hit's branches stopped at max_depth = 1: glass asks for a transmitted ray \
         only"
    );

    // the last hit down the chain of mirror rays, and how many mirror rays lead to it
    let deepest = |tree: &RayTree| {
        let mut hit = first_hit(tree, "a mirror");
        let mut mirrors = 0;
        while let Some(branch) = hit.branches.first() {
            mirrors += 1;
            assert_eq!(
                branch.kind,
                RayKind::Mirror,
                "the kind of branch {mirrors} between the mirrors"
            );
            hit = branch_hit(branch, &format!("mirror ray {mirrors}"));
        }
        (hit, mirrors)
    };
    let (last, mirrors) = deepest(&inspect(&facing_mirrors(50, 0.5)));
    assert_eq!(
        mirrors, 9,
        "the mirror rays traced between two mirrors of k_r = 0.5, max_depth = 50"
    );
    assert_eq!(
        last.stopped,
        vec![(RayKind::Mirror, Stop::Weight)],
        "why the ninth mirror ray's hit stopped: its branch's weight 0.5¹⁰ < 10⁻³"
    );
    let (last, mirrors) = deepest(&inspect(&facing_mirrors(2, 0.5)));
    assert_eq!(
        mirrors, 2,
        "the mirror rays traced between two mirrors, max_depth = 2"
    );
    assert_eq!(
        last.stopped,
        vec![(RayKind::Mirror, Stop::MaxDepth)],
        "why the second mirror ray's hit stopped at max_depth = 2"
    );
}
