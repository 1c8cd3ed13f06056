//! Chapter 4 — shadows (notes: "Shadowing"): feeler rays S(u) = P + (L − P)u, occluders with
//! u ∈ ]0, 1], translucent occluders, and no self-shadowing ("acne").
//!
//! A test named `ex_NAME_…` checks the exercise NAME of `chapters/formulas.toml`.
//! `Tracer::feeler` (4.4) is seen only through the renderer, which hands each colour to
//! `Tracer::reflect_and_refract` (5.5): before chapter 5 it returns the colour unchanged, but it
//! must not be `todo!()`.

mod common;

use common::{TOL, assert_near, assert_vec_eq, centre, render_at, render_both_ways, scene};
use whitted::accel::{Accel, Accelerator};
use whitted::camera::Camera;
use whitted::material::Material;
use whitted::offset::Offset;
use whitted::real::{Real, Vec3, vec3};
use whitted::render::{Chapter, Options, Tracer};
use whitted::shadow;
use whitted::shapes::{Hit, Hits, Numerics, Object, Shape};
use whitted::transform::{Placement, Step};

fn ball(center: Vec3, material: usize) -> Object {
    let p = Placement::from_steps(&[Step::Scale(Vec3::splat(1.0)), Step::Translate(center)])
        .unwrap_or_else(|| panic!("Placement::from_steps gave none for a move to {center}"));
    Object {
        material,
        ..Object::new(Shape::Sphere, p)
    }
}

fn materials() -> Vec<Material> {
    let glass = Material {
        transmission: 0.6,
        ..Material::default()
    };
    vec![Material::default(), glass]
}

const P: Vec3 = Vec3::ZERO;

/// The share of the light at `light` that reaches P through `objects`, every object tested in
/// turn (`--accel none`): the feeler S(u) = P + (L − P)·u, its blockers with u ∈ ]0, 1] and the
/// product of their transmissions.
fn share(objects: &[Object], light: Vec3) -> Real {
    let camera = Camera::new(vec3(0.0, 0.0, 5.0), P, Vec3::Y, 60.0, 1.0, 4, 4)
        .expect("a camera at (0, 0, 5) looking at the origin has a basis (viewing_basis)");
    let brute = Accelerator::build(objects, &camera, Accel::None, 16);
    let feeler = shadow::feeler(P, light);
    brute.transmittance(objects, &materials(), &feeler, 0.0, Numerics::Robust)
}
const L: Vec3 = Vec3::new(0.0, 10.0, 0.0);

/// Whether `object` blocks the feeler from P to `light`: `shadow::blocks` on its hits.
fn blocks(object: &Object, light: Vec3) -> bool {
    shadow::blocks(&hits_on_feeler(object, light), 0.0)
}

/// The hits of `object` on the feeler from P to `light`, at the feeler's u.
fn hits_on_feeler(object: &Object, light: Vec3) -> Hits {
    object.intersect(&shadow::feeler(P, light), Numerics::Robust)
}

/// Asserts whether the unit ball at `center` blocks the feeler from P = 0 to `light`, the
/// message giving the u of its hits and `why`.
#[track_caller]
fn assert_blocks(center: Vec3, light: Vec3, expected: bool, why: &str) {
    let ball = ball(center, 0);
    let u: Vec<Real> = hits_on_feeler(&ball, light)
        .as_slice()
        .iter()
        .map(|h| h.t)
        .collect();
    assert_eq!(
        blocks(&ball, light),
        expected,
        "does the unit ball at {center}, met at u = {u:?} on the feeler from P = 0 to L = \
         {light}, block it? {why}"
    );
}

/// "Shadowing": a sphere between P and L (u ≈ 0.5) blocks the feeler.
#[test]
fn ex_blocks_light_opaque_sphere_between_point_and_light_shadows_it() {
    assert_blocks(vec3(0.0, 5.0, 0.0), L, true, "u ∈ ]0, 1]: between P and L");
}

/// "Shadowing": a sphere beyond the light (u > 1) casts no shadow on P.
#[test]
fn ex_blocks_light_sphere_beyond_the_light_casts_no_shadow() {
    assert_blocks(vec3(0.0, 15.0, 0.0), L, false, "u > 1: beyond the light");
    // the same sphere with the light moved behind it does
    assert_blocks(
        vec3(0.0, 15.0, 0.0),
        vec3(0.0, 20.0, 0.0),
        true,
        "u ∈ ]0, 1]: the light moved behind it",
    );
}

/// "Shadowing": a sphere behind the point (u ≤ 0) casts no shadow on P.
#[test]
fn ex_blocks_light_sphere_behind_the_point_casts_no_shadow() {
    assert_blocks(vec3(0.0, -5.0, 0.0), L, false, "u < 0: behind P");
}

/// "Shadowing": u ∈ ]0, 1] — an occluder whose surface touches the light (u = 1) counts.
#[test]
fn ex_blocks_light_occluder_reaching_the_light_counts() {
    // surface at y = 10: u = 1 exactly
    assert_blocks(
        vec3(0.0, 11.0, 0.0),
        L,
        true,
        "u = 1 counts: ]0, 1] is closed at 1",
    );
}

/// "Shadowing", through every object in turn: an opaque sphere between P and L lets nothing
/// through (share 0), and so does one the light sits on; one beyond the light or behind P
/// lets everything through (share 1), and so does an empty scene.
#[test]
fn ex_transmittance_an_opaque_occluder_lets_nothing_through() {
    for (y, expected, where_) in [
        (5.0, 0.0, "between P and L"),
        (11.0, 0.0, "touching L (u = 1)"),
        (15.0, 1.0, "beyond L (u > 1)"),
        (-5.0, 1.0, "behind P (u < 0)"),
    ] {
        assert_eq!(
            share(&[ball(vec3(0.0, y, 0.0), 0)], L),
            expected,
            "the share of L = (0, 10, 0) reaching P = 0 past an opaque unit ball at y = {y}, \
             {where_}"
        );
    }
    assert_eq!(share(&[], L), 1.0, "the share reaching P in an empty scene");
}

/// "Shadowing" (extended to translucent objects): the share is the product of the crossed
/// objects' transmissions k_t: 1 for none, 0.5·0.5 = 0.25, 0.5·0.8·0.25 = 0.1, and 0 as soon as
/// one is opaque — after which no other is even looked at.
#[test]
fn ex_transmittance_multiplies_the_shares() {
    for (k_t, expected) in [
        (vec![], 1.0),
        (vec![0.6], 0.6),
        (vec![0.5, 0.5], 0.25),
        (vec![0.5, 0.0, 0.7], 0.0),
    ] {
        assert_eq!(
            shadow::transmittance(k_t.iter().copied()),
            expected,
            "the share Π k_t through objects of k_t = {k_t:?}"
        );
    }
    assert_near(
        "the share Π k_t through objects of k_t = [0.5, 0.8, 0.25]",
        shadow::transmittance([0.5, 0.8, 0.25]),
        0.1,
        TOL,
    );
    let after_opaque = [0.5, 0.0]
        .into_iter()
        .chain(std::iter::from_fn(|| -> Option<Real> {
            panic!(
                "transmittance of k_t = {:?}, … asked for a k_t after the opaque one (k_t = 0): \
                 stop at the first 0, the share is 0 whatever comes after",
                [0.5, 0.0]
            )
        }));
    assert_eq!(
        shadow::transmittance(after_opaque),
        0.0,
        "the share through k_t = 0.5, then an opaque object"
    );
}

/// "Shadowing" (extended): a translucent occluder lets its transmission share through; two of
/// them, the product.
#[test]
fn ex_transmittance_translucent_occluders_let_their_transmission_through() {
    let one = [ball(vec3(0.0, 3.0, 0.0), 1)];
    assert_near(
        "the share reaching P past one glass ball of k_t = 0.6",
        share(&one, L),
        0.6,
        TOL,
    );
    let two = [ball(vec3(0.0, 3.0, 0.0), 1), ball(vec3(0.0, 7.0, 0.0), 1)];
    assert_near(
        "the share reaching P past two glass balls of k_t = 0.6; expected 0.6²",
        share(&two, L),
        0.36,
        TOL,
    );
    let mixed = [ball(vec3(0.0, 3.0, 0.0), 1), ball(vec3(0.0, 7.0, 0.0), 0)];
    assert_eq!(
        share(&mixed, L),
        0.0,
        "the share reaching P past a glass ball and an opaque one"
    );
}

/// A floor lit from above with a sphere hovering over it: the point under the sphere is in
/// shadow at chapter 4 (ambient only) and lit at chapter 3.
#[test]
fn ex_send_feeler_point_under_a_sphere_is_lit_at_stage_3_and_shadowed_at_stage_4() {
    let s = scene(
        "[camera]\neye = [0.0, 6.0, 0.001]\nlook_at = [0.0, 0.0, 0.0]\n[ambient]\nintensity = 1.0\n\
         [[lights]]\nposition = [0.0, 10.0, 0.0]\n\
         [materials.m]\nambient = 0.1\ndiffuse = 0.6\nspecular = 0.0\n\
         [[objects]]\nplane = { normal = [0.0, 1.0, 0.0] }\nmaterial = \"m\"\n\
         [[objects]]\nsphere = { center = [0.0, 3.0, 3.0], radius = 0.5 }\n",
    );
    // the eye looks straight down at the origin; the sphere is off to the side, not in view
    let (lit, s3) = centre(&s, Chapter::Shading);
    assert_vec_eq(
        "I of the floor point, the sphere off to the side, chapter 3; expected ρa + ρd",
        lit,
        Vec3::splat(0.1 + 0.6),
        TOL,
    );
    assert_eq!(s3.shadow, 0, "the feelers cast at chapter 3");
    let (also_lit, s4) = centre(&s, Chapter::Shadows);
    assert_vec_eq(
        "I of the floor point, the sphere off to the side, chapter 4; expected ρa + ρd, lit",
        also_lit,
        Vec3::splat(0.7),
        TOL,
    );
    assert_eq!(
        s4.shadow, 1,
        "the feelers cast at chapter 4: one to the one light"
    );
    // move the sphere between the floor point and the light
    let shadowed = scene(
        "[camera]\neye = [0.0, 6.0, 0.001]\nlook_at = [0.0, 0.0, 0.0]\n[ambient]\nintensity = 1.0\n\
         [[lights]]\nposition = [0.0, 10.0, 0.0]\n\
         [materials.m]\nambient = 0.1\ndiffuse = 0.6\nspecular = 0.0\n\
         [[objects]]\nplane = { normal = [0.0, 1.0, 0.0] }\nmaterial = \"m\"\n\
         [[objects]]\nsphere = { center = [0.0, 8.0, 0.0], radius = 0.5 }\n",
    );
    let (dark, _) = centre(&shadowed, Chapter::Shadows);
    assert_vec_eq(
        "I of the floor point under the sphere, chapter 4; expected ρa only, in shadow",
        dark,
        Vec3::splat(0.1),
        TOL,
    );
}

/// The same floor, light and occluder as above, moved 100 units down: whether the light is in
/// front of the point depends on L − P alone (n·(L − P) > 0, as the local light decides it),
/// not on where the scene sits, and so does the feeler, from P towards L: the point is still
/// shadowed and its one feeler is still cast. (A test of n·(L + P), or of n·L, or a feeler
/// along L, passes at the origin and fails here.)
#[test]
fn ex_send_feeler_the_light_is_in_front_by_l_minus_p_wherever_the_scene_sits() {
    let shadowed = scene(
        "[camera]\neye = [0.0, -94.0, 0.001]\nlook_at = [0.0, -100.0, 0.0]\n[ambient]\nintensity = 1.0\n\
         [[lights]]\nposition = [0.0, -90.0, 0.0]\n\
         [materials.m]\nambient = 0.1\ndiffuse = 0.6\nspecular = 0.0\n\
         [[objects]]\nplane = { point = [0.0, -100.0, 0.0], normal = [0.0, 1.0, 0.0] }\nmaterial = \"m\"\n\
         [[objects]]\nsphere = { center = [0.0, -92.0, 0.0], radius = 0.5 }\n",
    );
    let (dark, stats) = centre(&shadowed, Chapter::Shadows);
    assert_vec_eq(
        "I of the floor point at y = −100 under the sphere; expected ρa only, in shadow",
        dark,
        Vec3::splat(0.1),
        TOL,
    );
    assert_eq!(
        stats.shadow, 1,
        "the feelers cast: one to the light in front, n·(L − P) > 0"
    );
}

/// A scene of one convex object (a lit sphere), or one lit plane: nothing can shadow a point
/// that faces the light, so chapter 4 must equal chapter 3 pixel for pixel; `n_bad` counts the
/// pixels that differ.
fn wrongly_shadowed(text: &str, offset: Offset) -> (usize, usize) {
    let s = scene(text);
    let mut o3 = Options::for_scene(&s, Chapter::Shading);
    o3.width = 96;
    o3.height = 72;
    let o4 = Options {
        chapter: Chapter::Shadows,
        offset,
        ..o3.clone()
    };
    let (a, _) = render_both_ways(&s, &o3);
    let (b, _) = render_both_ways(&s, &o4);
    let lit = a
        .pixels
        .iter()
        .filter(|p| p.max_element() > 0.2 + 1e-3)
        .count();
    let bad = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .filter(|(x, y)| (**x - **y).abs().max_element() > 1e-6)
        .count();
    (bad, lit)
}

const LIT_SPHERE: &str = "[camera]\neye = [0.3, 0.4, 4.0]\nfov = 40\n[ambient]\nintensity = 1.0\n\
    [[lights]]\nposition = [4.0, 5.0, 6.0]\n[materials.m]\nambient = 0.2\ndiffuse = 0.6\nspecular = 0.2\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, 0.0], radius = 1.3 }\nmaterial = \"m\"\n";

const LIT_PLANE: &str = "[camera]\neye = [0.0, 3.0, 6.0]\nlook_at = [0.0, 0.0, -4.0]\n[ambient]\nintensity = 1.0\n\
    [[lights]]\nposition = [2.0, 6.0, 1.0]\n[materials.m]\nambient = 0.2\ndiffuse = 0.6\nspecular = 0.2\n\
    [[objects]]\nplane = { point = [0.0, -0.7, 0.0], normal = [0.1, 1.0, 0.2] }\nmaterial = \"m\"\n";

/// "Shadowing" (self-intersection): with the default offset a lit sphere and a lit plane show
/// no wrongly shadowed pixel, while feelers started exactly at the hit point (no offset at
/// all) shadow a good share of them — which is why the offset exists.
#[test]
fn ex_send_feeler_lit_sphere_and_plane_show_no_shadow_acne() {
    for (text, name) in [(LIT_SPHERE, "a lit sphere"), (LIT_PLANE, "a lit plane")] {
        let (bad, lit) = wrongly_shadowed(text, Offset::default());
        assert!(
            lit > 1000,
            "{name} shows {lit} lit pixels at chapter 3, expected more than 1000"
        );
        assert_eq!(
            bad, 0,
            "the pixels of {name} ({lit} lit) that chapter 4 changes: nothing can shadow them, \
             so a feeler meets the surface it leaves (shadow acne: start it off the surface)"
        );
    }
    let (bad, lit) = wrongly_shadowed(LIT_SPHERE, Offset::Fixed(0.0));
    assert!(
        bad as Real > 0.05 * lit as Real,
        "with no offset at all, {bad} of {lit} lit pixels of the sphere show acne, expected more \
         than 5%"
    );
}

/// "Shadowing": feelers are cast only where needed — one per light facing the point, none for
/// a light with `shadows = false`, none in a scene without lights, none towards a light whose
/// terms add nothing (a black material).
#[test]
fn ex_send_feeler_feelers_only_where_a_scene_needs_them() {
    let base = "[camera]\neye = [0.0, 0.0, 5.0]\n[[objects]]\nsphere = {}\n";
    let (_, none) = render_at(&scene(base), Chapter::Shadows, 16, 16);
    assert_eq!(none.shadow, 0, "the feelers cast without lights");
    let off = format!("{base}[[lights]]\nposition = [0.0, 0.0, 10.0]\nshadows = false\n");
    let (_, off) = render_at(&scene(&off), Chapter::Shadows, 16, 16);
    assert_eq!(
        off.shadow, 0,
        "the feelers cast to a light with shadows = false"
    );
    let on = format!("{base}[[lights]]\nposition = [0.0, 0.0, 10.0]\n");
    let (fb, on) = render_at(&scene(&on), Chapter::Shadows, 16, 16);
    let hits = fb.pixels.iter().filter(|p| **p != Vec3::ZERO).count() as u64;
    assert!(
        hits > 0,
        "the sphere's lit pixels in a 16 × 16 image: {hits}"
    );
    assert_eq!(
        on.shadow, hits,
        "the feelers cast: one per visible lit point ({hits} pixels)"
    );
    // the same light in front of a black sphere: its terms add nothing, so nothing to shadow
    let black = format!(
        "{base}material = \"black\"\n[[lights]]\nposition = [0.0, 0.0, 10.0]\n\
         [materials.black]\nambient = 0.2\ndiffuse = 0.0\nspecular = 0.0\n"
    );
    let (_, black) = render_at(&scene(&black), Chapter::Shadows, 16, 16);
    assert_eq!(
        black.shadow, 0,
        "the feelers cast to a light in front of a black sphere (I_d + I_s = 0)"
    );
}

/// "Shadowing": S(u) = r(t₀) + (L − r(t₀))·u starts at the point and reaches the light at u = 1.
/// Hand values for P = (1, 2, 3), L = (−4, 6, 0.5): L − P = (−5, 4, −2.5), S(0) = P,
/// S(1) = L, S(½) = (−1.5, 4, 1.75), the midpoint.
#[test]
fn ex_feeler_ray_feeler_starts_at_the_point_and_reaches_the_light_at_u_one() {
    let (p, l) = (vec3(1.0, 2.0, 3.0), vec3(-4.0, 6.0, 0.5));
    let s = shadow::feeler(p, l);
    let of = "of the feeler from P = (1, 2, 3) to L = (−4, 6, 0.5)";
    assert_vec_eq(
        &format!("the direction L − P {of} (not made unit)"),
        s.dir,
        vec3(-5.0, 4.0, -2.5),
        TOL,
    );
    assert_vec_eq(&format!("S(0) {of}; expected P"), s.at(0.0), p, TOL);
    assert_vec_eq(&format!("S(1) {of}; expected L"), s.at(1.0), l, TOL);
    assert_vec_eq(
        &format!("S(½) {of}; expected the midpoint"),
        s.at(0.5),
        vec3(-1.5, 4.0, 1.75),
        TOL,
    );
    assert_vec_eq(
        &format!("the origin {of}; expected P exactly"),
        s.origin,
        p,
        0.0,
    );
}

/// A hit at u alone, for `shadow::blocks`.
fn at_u(u: Real) -> Hits {
    Hits::one(Hit {
        t: u,
        ..Hit::default()
    })
}

/// "Shadowing": only u ∈ ]0, 1] counts, and the open end is open. An occluder met at u = 0
/// exactly — the feeler starts on its surface — casts no shadow: from P = 0 towards
/// L = (0, 10, 0), a unit sphere centred at (0, −1, 0) is met where (10u + 1)² = 1, u = 0 or
/// −0.2, and the floor y = 0 where 10u = 0. A sphere centred at (0, 1, 0) is met at u = 0 and
/// u = 0.2: the feeler goes through it, so it does shadow.
#[test]
fn ex_blocks_light_occluder_at_u_zero_does_not_shadow() {
    let l = vec3(0.0, 10.0, 0.0);
    let feeler = shadow::feeler(P, l);
    let under = ball(vec3(0.0, -1.0, 0.0), 0);
    let hits = under.intersect(&feeler, Numerics::Robust);
    let u: Vec<Real> = hits.as_slice().iter().map(|h| h.t).collect();
    assert!(
        u.len() == 2 && (u[0] + 0.2).abs() <= TOL && u[1].abs() <= TOL,
        "the feeler from P = 0 to L = (0, 10, 0) meets the unit ball at (0, −1, 0): u computed \
         {u:?}, expected [−0.2, 0] (tolerance {TOL:e})"
    );
    assert!(
        !shadow::blocks(&hits, 0.0),
        "a ball met at u = {u:?} (u_min = 0) blocks the feeler: u = 0 is where it starts, not \
         in ]0, 1]"
    );
    let s = scene(
        "[[objects]]\nplane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }\n\
         [[objects]]\nsphere = { center = [0.0, -1.0, 0.0] }\n",
    );
    let floor = s.objects[0].intersect(&feeler, Numerics::Robust);
    let u: Vec<Real> = floor.as_slice().iter().map(|h| h.t).collect();
    assert_eq!(
        u,
        [0.0],
        "the u of the floor y = 0 on the feeler from P = 0 to L = (0, 10, 0)"
    );
    assert!(
        !shadow::blocks(&floor, 0.0),
        "the floor met at u = {u:?} (u_min = 0) blocks the feeler: u = 0 is where it starts"
    );
    // the same point on the underside of a sphere above it: the feeler crosses it, u = 0.2
    assert_blocks(
        vec3(0.0, 1.0, 0.0),
        l,
        true,
        "crossed from u = 0 to u = 0.2, it is in ]0, 1]",
    );
}

/// "Shadowing": the floor and the sphere under P, both met at u = 0, let the whole light
/// through, whether the objects are tested one by one or through the acceleration structure;
/// the sphere over P, crossed at u = 0.2, lets none through.
#[test]
fn ex_transmittance_occluders_at_u_zero_let_the_light_through() {
    let l = vec3(0.0, 10.0, 0.0);
    let feeler = shadow::feeler(P, l);
    let s = scene(
        "[[objects]]\nplane = { point = [0.0, 0.0, 0.0], normal = [0.0, 1.0, 0.0] }\n\
         [[objects]]\nsphere = { center = [0.0, -1.0, 0.0] }\n",
    );
    assert_eq!(
        common::brute_share(&s.objects, &s.materials, &feeler, 0.0, Numerics::Robust),
        1.0,
        "the share past the floor and the ball under P, both met at u = 0, object by object"
    );
    assert_eq!(
        share(&s.objects, l),
        1.0,
        "the share past the floor and the ball under P, both met at u = 0, through the accelerator"
    );
    assert_eq!(
        share(&[ball(vec3(0.0, 1.0, 0.0), 0)], l),
        0.0,
        "the share past the opaque ball over P, crossed at u = 0.2"
    );
}

/// "Shadowing" with the start left on the surface: a hit at u ≤ u_min is the surface the
/// feeler leaves and does not count; one just above u_min does. With u_min = 0.25, a plane
/// y = 2.5 crossed by the feeler from 0 to (0, 10, 0) at u = 2.5/10 = 0.25 exactly does not
/// block; the plane y = 2.51, at u = 0.251, does. u = 1 (the light) still counts, u just above
/// 1 does not.
#[test]
fn ex_blocks_light_hit_at_or_before_u_min_does_not_count_and_just_after_does() {
    for (u, u_min, expected) in [
        (0.25, 0.25, false),
        (0.1, 0.25, false),
        (0.251, 0.25, true),
        (1.0, 0.25, true),
        (1.001, 0.25, false),
        (0.25, 0.0, true),
    ] {
        assert_eq!(
            shadow::blocks(&at_u(u), u_min),
            expected,
            "does a hit at u = {u} block a feeler with u_min = {u_min}? (u_min < u ≤ 1)"
        );
    }
    let u_min: Real = 0.25;
    let feeler = shadow::feeler(P, L);
    let plane_at = |y: f64| {
        scene(&format!(
            "[[objects]]\nplane = {{ point = [0.0, {y}, 0.0], normal = [0.0, 1.0, 0.0] }}\n"
        ))
    };
    for (y, u, expected) in [(2.5, 0.25, false), (2.51, 0.251, true)] {
        let plane = plane_at(y);
        let hits = plane.objects[0].intersect(&feeler, Numerics::Robust);
        let got: Vec<Real> = hits.as_slice().iter().map(|h| h.t).collect();
        assert!(
            got.len() == 1 && (got[0] - u).abs() <= TOL,
            "the u of the plane y = {y} on the feeler from 0 to (0, 10, 0): {got:?}, expected \
             [{u}] (tolerance {TOL:e})"
        );
        assert_eq!(
            shadow::blocks(&hits, u_min),
            expected,
            "does the plane y = {y}, met at u = {u}, block a feeler with u_min = {u_min}?"
        );
    }
}

/// "Shadowing" with the start left on the surface, in the share of the light: with
/// u_min = 0.25 the plane y = 2.5, met at u = 0.25, lets the whole light through, the plane
/// y = 2.51 none of it.
#[test]
fn ex_transmittance_a_plane_at_u_min_lets_the_light_through_and_one_just_after_does_not() {
    let u_min: Real = 0.25;
    let feeler = shadow::feeler(P, L);
    let plane_at = |y: f64| {
        scene(&format!(
            "[[objects]]\nplane = {{ point = [0.0, {y}, 0.0], normal = [0.0, 1.0, 0.0] }}\n"
        ))
    };
    for (y, expected) in [(2.5, 1.0), (2.51, 0.0)] {
        let plane = plane_at(y);
        assert_eq!(
            common::brute_share(
                &plane.objects,
                &plane.materials,
                &feeler,
                u_min,
                Numerics::Robust
            ),
            expected,
            "the share past the opaque plane y = {y} on the feeler from 0 to (0, 10, 0), \
             u_min = {u_min}"
        );
    }
}

/// The floor under a light at (0, 10, 0), seen straight down at P = (0, 0, 0), with an opaque
/// sphere of radius ½ at (0, 8, 0) in between.
const FLOOR_UNDER_A_BALL: &str = "[camera]\neye = [0.0, 6.0, 0.001]\nlook_at = [0.0, 0.0, 0.0]\n\
    [[lights]]\nposition = [0.0, 10.0, 0.0]\n[materials.m]\nambient = 0.1\ndiffuse = 0.6\nspecular = 0.0\n\
    [[objects]]\nplane = { normal = [0.0, 1.0, 0.0] }\nmaterial = \"m\"\n\
    [[objects]]\nsphere = { center = [0.0, 8.0, 0.0], radius = 0.5 }\n";

/// "Shadowing", as the inspector sees it: the feeler starts where the offset strategy puts it
/// and runs to the light, S(u) = P′ + (L − P′)·u. With `Offset::Scaled(0.01)` the start is P
/// moved 0.01 towards the light, P′ = (0, 0.01, 0), u_min = 0, and the sphere y ∈ [7.5, 8.5]
/// is crossed at u = 7.49/9.99 and 8.49/9.99; with `Offset::Fixed(0.01)` the start is P itself
/// and u_min = 0.01/‖L − P‖ = 0.001, the sphere crossed at u = 0.75 and 0.85. Either way no
/// light arrives: the pixel is ambient only, 0.1. At chapter 3 there is no feeler at all.
#[test]
fn ex_send_feeler_the_feeler_leaves_from_the_offset_start_towards_the_light() {
    let s = scene(FLOOR_UNDER_A_BALL);
    let cases = [
        (
            Offset::Scaled(0.01),
            vec3(0.0, 0.01, 0.0),
            0.0,
            [7.49 / 9.99, 8.49 / 9.99],
        ),
        (Offset::Fixed(0.01), Vec3::ZERO, 0.001, [0.75, 0.85]),
    ];
    for (offset, start, u_min, u) in cases {
        let mut o = Options::for_scene(&s, Chapter::Shadows);
        (o.width, o.height, o.offset) = (1, 1, offset);
        let tree = Tracer::new(&s, &o).inspect(0, 0);
        let hit = tree.samples[0]
            .ray
            .hit
            .as_ref()
            .expect("the ray tree of the centre pixel records the floor's hit");
        let light = hit
            .lights
            .first()
            .expect("the ray tree records the one light (rec.light)");
        let feeler = light.feeler.as_ref().unwrap_or_else(|| {
            panic!("the floor point sends no feeler towards the light in front of it, {offset:?}")
        });
        assert_vec_eq(
            &format!("the feeler's start P′ with {offset:?}"),
            feeler.origin,
            start,
            10.0 * TOL,
        );
        assert_near(
            &format!("the feeler's u_min with {offset:?}"),
            feeler.u_min,
            u_min,
            10.0 * TOL,
        );
        let crossed: Vec<(usize, Vec<Real>)> = feeler
            .crossings
            .iter()
            .map(|c| (c.object, c.u.clone()))
            .collect();
        let expected = [(1, u.to_vec())];
        assert!(
            crossed.len() == 1
                && crossed[0].0 == 1
                && crossed[0].1.len() == 2
                && (crossed[0].1[0] - u[0]).abs() <= 10.0 * TOL
                && (crossed[0].1[1] - u[1]).abs() <= 10.0 * TOL,
            "the (object, u) the feeler crosses with {offset:?}: {crossed:?}, expected \
             {expected:?} (tolerance {:e})",
            10.0 * TOL
        );
        assert_eq!(
            light.share, 0.0,
            "the share of the light reaching the floor past the opaque sphere, {offset:?}"
        );
        assert_vec_eq(
            &format!("the pixel's colour with {offset:?}; expected ρa only"),
            tree.colour,
            Vec3::splat(0.1),
            TOL,
        );
        assert_eq!(
            tree.rays, 2,
            "the rays of the tree: the camera ray and one feeler"
        );
    }
    let mut o = Options::for_scene(&s, Chapter::Shading);
    (o.width, o.height) = (1, 1);
    let tree = Tracer::new(&s, &o).inspect(0, 0);
    let hit = tree.samples[0]
        .ray
        .hit
        .as_ref()
        .expect("the ray tree of the centre pixel records the floor's hit at chapter 3");
    let feeler = hit.lights.first().map(|l| &l.feeler);
    assert!(
        matches!(feeler, Some(None)),
        "the feeler of the one light at chapter 3: {feeler:?}, expected none"
    );
    assert_eq!(
        tree.rays, 1,
        "the rays of the tree at chapter 3: the camera ray"
    );
}
