//! The nearest hit over the objects: the visible hit of one object, the nearer of two, and ties ("Ray Tracing Process", step 4).

use super::*;

/// Three spheres on the axis of a camera at the origin looking down −z, listed far, behind,
/// near (so the answer cannot come from the order alone).
const THREE_SPHERES: &str = "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n\
    [materials.far]\ndiffuse = [0.0, 0.0, 1.0]\n[materials.behind]\ndiffuse = [0.0, 1.0, 0.0]\n\
    [materials.near]\ndiffuse = [1.0, 0.0, 0.0]\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, -10.0], radius = 1.0 }\nmaterial = \"far\"\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, 5.0], radius = 2.0 }\nmaterial = \"behind\"\n\
    [[objects]]\nsphere = { center = [0.0, 0.0, -5.0], radius = 1.0 }\nmaterial = \"near\"\n";

/// "Ray Tracing Process", step 5: of all the hits the visible one has the smallest t > 0.
/// Along r(t) = (0, 0, −2t), |r(t) − c|² = ρ² gives by hand: the far sphere (c_z = −10, ρ = 1)
/// (10 − 2t)² = 1, t = 4.5 or 5.5; the near one (c_z = −5, ρ = 1) (5 − 2t)² = 1, t = 2 or 3;
/// the one behind the eye (c_z = 5, ρ = 2) (5 + 2t)² = 4, t = −1.5 or −3.5, both < 0. The
/// near sphere (object 2) wins at t = 2 with normal +z; from t_min = 2.5 its far side (t = 3,
/// leaving, normal −z); from t_min = 3.5 the far sphere at t = 4.5; for every accelerator.
#[test]
fn nearest_hit_has_the_smallest_positive_t() {
    let s = scene(THREE_SPHERES);
    let ray = ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0]);
    for accel in Accel::ALL {
        let mut o = Options::for_scene(&s, Chapter::GenericObjects);
        o.accel = accel;
        let tracer = Tracer::new(&s, &o);
        for (t_min, object, t, normal, entering) in [
            (0.0, 2, 2.0, Vec3::Z, true),
            (2.5, 2, 3.0, Vec3::NEG_Z, false),
            (3.5, 0, 4.5, Vec3::Z, true),
        ] {
            let what =
                format!("the nearest hit after t_min = {t_min} along (0, 0, −2t), {accel:?}");
            let near = tracer
                .nearest(&ray, t_min)
                .unwrap_or_else(|| panic!("{what}: none, expected object {object} at t = {t}"));
            assert_eq!(
                near.object, object,
                "the object of {what} (t = {})",
                near.hit.t
            );
            assert_near(&format!("t of {what}"), near.hit.t, t, 10.0 * TOL);
            assert_vec_eq(&format!("n of {what}"), near.hit.normal, normal, 10.0 * TOL);
            assert_eq!(near.hit.entering, entering, "entering of {what}");
        }
        let none = tracer.nearest(&ray, 5.5);
        assert!(
            none.is_none(),
            "the nearest hit after t_min = 5.5, past every sphere, {accel:?}: {none:?}, expected none"
        );
    }
    // the chapter-2 image shows the near sphere's flat colour ρd
    let (c, _) = centre(&s, Chapter::GenericObjects);
    assert_vec_eq(
        "the colour of a 1 × 1 image; expected the near sphere's ρd",
        c,
        vec3(1.0, 0.0, 0.0),
        0.0,
    );
}

/// "Ray Tracing Process", step 5 for one object: of its hits at t = 2 (entering) and t = 5
/// (leaving), a ray from t_min sees the first one past t_min: the one at 2 from t_min = −10 or
/// 0, the one at 5 from 2 (a hit at exactly t_min does not count) or 3, none from 5 on.
#[test]
fn ex_visible_hit_the_visible_hit_is_the_first_after_t_min() {
    let at = |t: Real, entering: bool| Hit {
        t,
        normal: Vec3::Z,
        part: Part::Surface,
        entering,
    };
    let hits = Hits::two(at(2.0, true), at(5.0, false));
    for (t_min, expected) in [
        (-10.0, Some(at(2.0, true))),
        (0.0, Some(at(2.0, true))),
        (2.0, Some(at(5.0, false))),
        (3.0, Some(at(5.0, false))),
        (5.0, None),
    ] {
        assert_eq!(
            hits.first_after(t_min),
            expected,
            "the visible hit after t_min = {t_min} of hits at t = 2 and t = 5"
        );
    }
    assert_eq!(
        Hits::one(at(-1.0, true)).first_after(0.0),
        None,
        "the visible hit after t_min = 0 of one hit at t = −1"
    );
    assert_eq!(
        Hits::none().first_after(0.0),
        None,
        "the visible hit after t_min = 0 of no hit"
    );
}

/// "Ray Tracing Process", step 5 (the tie rule of `shapes::nearer`): a smaller t wins whatever
/// the order; of two hits at the same t, the object listed first.
#[test]
fn ex_nearer_hit_equal_t_goes_to_the_object_listed_first() {
    for (t, object, best_t, best_object, expected) in [
        (2.0, 0, 2.0, 1, true),
        (2.0, 1, 2.0, 0, false),
        (2.0, 3, 2.0, 3, false),
        (1.5, 7, 2.0, 0, true),
        (2.5, 0, 2.0, 7, false),
        (1e9, usize::MAX, Real::INFINITY, 0, true), // anything beats "no hit yet"
    ] {
        assert_eq!(
            nearer(t, object, best_t, best_object),
            expected,
            "nearer(t = {t}, object = {object}, best_t = {best_t}, best_object = {best_object}): \
             is a hit of object {object} at t = {t} nearer than the best so far?"
        );
    }
}

/// Two coincident unit spheres of different materials at (0, 0, −5), seen along the camera's
/// axis.
fn coincident(first: &str, second: &str) -> String {
    format!(
        "[camera]\neye = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, -1.0]\n\
         [materials.red]\ndiffuse = [1.0, 0.0, 0.0]\n[materials.green]\ndiffuse = [0.0, 1.0, 0.0]\n\
         [[objects]]\nsphere = {{ center = [0.0, 0.0, -5.0] }}\nmaterial = \"{first}\"\n\
         [[objects]]\nsphere = {{ center = [0.0, 0.0, -5.0] }}\nmaterial = \"{second}\"\n"
    )
}

/// "Ray Tracing Process", step 5: two coincident spheres are hit at the same t = 4 (|(0, 0, −t)
/// − (0, 0, −5)| = 1); the one listed first shows, red before green or green before red, for
/// every accelerator, in the rendered 1 × 1 image and through `Tracer::nearest`.
#[test]
fn coincident_objects_show_the_first_listed_for_every_accel() {
    for (first, second, colour) in [
        ("red", "green", vec3(1.0, 0.0, 0.0)),
        ("green", "red", vec3(0.0, 1.0, 0.0)),
    ] {
        let s = scene(&coincident(first, second));
        for accel in Accel::ALL {
            let mut o = Options::for_scene(&s, Chapter::GenericObjects);
            (o.width, o.height, o.accel) = (1, 1, accel);
            let (fb, _) = render_both_ways(&s, &o);
            assert_eq!(
                fb.pixels[0], colour,
                "the colour of a 1 × 1 image, {first} first, {accel:?}"
            );
            let what = format!("the nearest hit along −z, {first} first, {accel:?}");
            let near = Tracer::new(&s, &o)
                .nearest(&ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]), 0.0)
                .unwrap_or_else(|| panic!("{what}: none, expected object 0 at t = 4"));
            assert_eq!(near.object, 0, "the object of {what}");
            assert_near(&format!("t of {what}"), near.hit.t, 4.0, 10.0 * TOL);
        }
    }
}
