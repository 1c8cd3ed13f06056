//! Self-intersection: shadow acne far from the camera, and spawned rays that never meet their
//! own surface where they start.

use super::{config, f, hits, placed, placement, shape_of, tol};
use proptest::prelude::*;
use whitted::numeric::normalize;
use whitted::offset::Offset;
use whitted::ray::Ray;
use whitted::real::{Vec3, real, vec3};
use whitted::render::{self, Chapter, Options};
use whitted::scene::{self, Scene};
use whitted::shapes::{Hit, Numerics};

/// A scene with one object ~`distance` units in front of the camera and one light on the
/// camera's side: nothing can shadow the object but itself.
fn lonely_scene(distance: f64, object: &str) -> Scene {
    let d = distance;
    let text = format!(
        r#"
[camera]
eye = [0.0, 0.0, 0.0]
look_at = [0.0, 0.0, {look}]
fov = 20.0
[image]
width = 48
height = 36
[ambient]
intensity = 0.1
[[lights]]
position = [{lx}, {ly}, 0.0]
intensity = 1.0
[materials.m]
ambient = 0.1
diffuse = 0.8
specular = 0.0
[[objects]]
{object}
material = "m"
"#,
        look = -d,
        lx = 0.3 * d,
        ly = 0.6 * d,
    );
    scene::parse(&text, "lonely.toml").expect("valid scene")
}

fn far_sphere_scene(d: f64) -> Scene {
    lonely_scene(
        d,
        &format!(
            "sphere = {{ center = [0.0, 0.0, {}], radius = {} }}",
            -d,
            0.15 * d
        ),
    )
}

fn tilted_plane_scene(d: f64) -> Scene {
    lonely_scene(
        d,
        &format!(
            "plane = {{ point = [0.0, 0.0, {}], normal = [0.2, 0.7, 0.6] }}",
            -d
        ),
    )
}

/// The share of pixels lit in chapter 3 (no shadows) that chapter 4 darkens: with a single
/// convex object or a plane and the light on the visible side, every such pixel is a false
/// shadow (shadow acne).
fn wrongly_shadowed_share(scene: &Scene, offset: Offset) -> f64 {
    let mut options = Options::for_scene(scene, Chapter::Shading);
    options.offset = offset;
    let (lit, _) = render::render(scene, &options);
    options.chapter = Chapter::Shadows;
    let (shadowed, _) = render::render(scene, &options);
    let ambient_only = scene.materials[1].ambient * scene.ambient;
    let mut lit_count = 0;
    let mut wrong = 0;
    for (l, s) in lit.pixels.iter().zip(&shadowed.pixels) {
        assert!(l.is_finite() && s.is_finite());
        if (*l - ambient_only).max_element() > 1e-3 {
            lit_count += 1;
            if (*l - *s).max_element() > 1e-3 {
                wrong += 1;
            }
        }
    }
    assert!(lit_count > 100, "the test scene should show lit pixels");
    wrong as f64 / lit_count as f64
}

/// Notes, "Shadowing": a feeler S(u) = P + (L − P)·u meeting an opaque object with u ∈ ]0, 1]
/// puts P in shadow. P itself carries rounding error of the size of its coordinates, so about
/// 1e4 units from the origin the feeler meets its own surface. The default error-bound offset
/// leaves no lit pixel wrongly shadowed, on a sphere and on a tilted plane.
#[test]
fn no_lit_pixel_is_wrongly_shadowed_ten_thousand_units_away() {
    for scene in [far_sphere_scene(1e4), tilted_plane_scene(1e4)] {
        assert_eq!(wrongly_shadowed_share(&scene, Offset::default()), 0.0);
    }
}

/// The classic fixed ε (1e-4 world units) is below the rounding error of hit points far enough
/// away (1e4 units in f32, 1e12 in f64): it shadows lit pixels there, on the sphere and the
/// tilted plane, while the default error-bound offset still shadows none.
#[test]
fn fixed_epsilon_shadows_lit_pixels_far_away_and_the_error_bound_does_not() {
    let d = tol::FIXED_EPS_FAILS_AT;
    for scene in [far_sphere_scene(d), tilted_plane_scene(d)] {
        let fixed = wrongly_shadowed_share(&scene, Offset::Fixed(Offset::FIXED_EPSILON));
        assert!(fixed > 0.01, "fixed ε wrongly shadowed only {fixed}");
        assert_eq!(wrongly_shadowed_share(&scene, Offset::ErrorBound), 0.0);
    }
}

proptest! {
    #![proptest_config(config(3000))]

    /// Notes, "Shadowing" and "Reflection and Refraction", at random placements: a ray spawned
    /// by the default (error-bound) offset from a hit on a convex shape never meets that surface
    /// again where it starts. Leaving outwards (n·dir > 0) it never meets the part it left
    /// (facet, cap, wall …) again; going inwards it meets that part at most once, on its way
    /// out, never entering it. (At an edge the pushed origin may sit just outside the
    /// neighbouring part, which the ray then crosses at once: an edge effect of any one-sided
    /// push, not a self-intersection.)
    #[test]
    fn spawned_rays_never_meet_their_own_surface_where_they_start(
        which in 0u8..5,
        (s, steps) in placement(),
        from in prop::array::uniform3(-60.0f64..60.0),
        towards in prop::array::uniform3(-0.9f64..0.9),
        tangent in prop::array::uniform3(-1.0f64..1.0),
        lift in 0.02f64..1.0,
        inwards in any::<bool>(),
    ) {
        let shape = shape_of(which);
        let object = placed(shape.clone(), &steps);
        let m = object.placement.m();
        let origin = m.transform_point3(Vec3::ZERO) + vec3(from[0] * s, from[1] * s, from[2] * s);
        let target = m.transform_point3(vec3(towards[0], towards[1], towards[2]));
        prop_assume!(origin != target);
        let ray = Ray::new(origin, target - origin);
        let hs = hits(&object, &ray, Numerics::Robust);
        let Some(hit) = hs.first() else { return Ok(()); };
        let n = hit.normal;
        let t = vec3(tangent[0], tangent[1], tangent[2]);
        let t = t - n * t.dot(n);
        let side = if inwards { -1.0 } else { 1.0 };
        let dir = normalize(t + n * real(side * lift));
        prop_assume!(f(dir.dot(n)) * side > 0.01);
        let spawn = whitted::offset::SpawnPoint::new(&object, &ray, hit);
        let (start, t_min) = Offset::ErrorBound.spawn(&spawn, dir);
        let again = hits(&object, &Ray::new(start, dir), Numerics::Robust);
        let ahead: Vec<&Hit> = again.iter().filter(|h| h.t > t_min).collect();
        // the surface it starts from: the same part (a facet, a cap, the wall …); at an edge the
        // ray may legitimately cross the neighbouring part right away
        let own: Vec<&&Hit> = ahead.iter().filter(|h| h.part == hit.part).collect();
        if !inwards || !shape.is_closed() {
            prop_assert!(own.is_empty(), "met its own surface again: {own:?} from {hit:?}");
        } else {
            prop_assert!(own.len() <= 1, "{:?} from {:?}", again, hit);
            prop_assert!(own.iter().all(|h| !h.entering), "entered its own surface again: {:?} from {:?}", again, hit);
        }
    }
}
