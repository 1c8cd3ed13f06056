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
        let near = tracer
            .nearest(&ray, 0.0)
            .expect("the near sphere is in front");
        assert_eq!(near.object, 2, "{accel:?}");
        assert_abs_diff_eq!(near.hit.t, 2.0, epsilon = 10.0 * TOL);
        assert_vec_eq(near.hit.normal, Vec3::Z, 10.0 * TOL);
        assert!(near.hit.entering);
        let inside = tracer.nearest(&ray, 2.5).unwrap();
        assert_eq!(inside.object, 2, "{accel:?}");
        assert_abs_diff_eq!(inside.hit.t, 3.0, epsilon = 10.0 * TOL);
        assert_vec_eq(inside.hit.normal, Vec3::NEG_Z, 10.0 * TOL);
        assert!(!inside.hit.entering);
        let beyond = tracer.nearest(&ray, 3.5).unwrap();
        assert_eq!(beyond.object, 0, "{accel:?}");
        assert_abs_diff_eq!(beyond.hit.t, 4.5, epsilon = 10.0 * TOL);
        assert!(tracer.nearest(&ray, 5.5).is_none(), "{accel:?}");
    }
    // the chapter-2 image shows the near sphere's flat colour ρd
    let (c, _) = centre(&s, Chapter::GenericObjects);
    assert_vec_eq(c, vec3(1.0, 0.0, 0.0), 0.0);
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
    assert_eq!(hits.first_after(-10.0), Some(at(2.0, true)));
    assert_eq!(hits.first_after(0.0), Some(at(2.0, true)));
    assert_eq!(hits.first_after(2.0), Some(at(5.0, false)));
    assert_eq!(hits.first_after(3.0), Some(at(5.0, false)));
    assert_eq!(hits.first_after(5.0), None);
    assert_eq!(Hits::one(at(-1.0, true)).first_after(0.0), None);
    assert_eq!(Hits::none().first_after(0.0), None);
}

/// "Ray Tracing Process", step 5 (the tie rule of `shapes::nearer`): a smaller t wins whatever
/// the order; of two hits at the same t, the object listed first.
#[test]
fn ex_nearer_hit_equal_t_goes_to_the_object_listed_first() {
    assert!(nearer(2.0, 0, 2.0, 1));
    assert!(!nearer(2.0, 1, 2.0, 0));
    assert!(!nearer(2.0, 3, 2.0, 3));
    assert!(nearer(1.5, 7, 2.0, 0));
    assert!(!nearer(2.5, 0, 2.0, 7));
    assert!(nearer(1e9, usize::MAX, Real::INFINITY, 0)); // anything beats "no hit yet"
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
            assert_eq!(fb.pixels[0], colour, "{first} first, {accel:?}");
            let near = Tracer::new(&s, &o)
                .nearest(&ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]), 0.0)
                .unwrap();
            assert_eq!(near.object, 0, "{first} first, {accel:?}");
            assert_abs_diff_eq!(near.hit.t, 4.0, epsilon = 10.0 * TOL);
        }
    }
}
