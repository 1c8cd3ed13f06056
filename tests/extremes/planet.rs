//! A huge sphere seen from close by (the planet case of the trade page, `docs/src/tradeoff.md`):
//! a sphere of radius 1e4 whose top is the world origin, seen from about 0.79 above it; and a
//! huge tube and a huge box, which lose their digits the same way.

use super::{f, rel_err, tol};
use whitted::accel::Accel;
use whitted::ray::Ray;
use whitted::real::{PRECISION, Real, Vec3, vec3};
use whitted::render::{Chapter, Options, Tracer, build_accel};
use whitted::scene::{self, Scene};
use whitted::shapes::{Nearest, Numerics};

/// The bodies' size R: the planet's and the tube's radius, half the box's side.
const R: f64 = 1e4;
/// The eyes: 0.79 above the top, and around that point (within a unit across, 0.02 up or
/// down); how much of the eye's height survives the rounding of 1 + h/R depends on h.
const EYES: [[f64; 3]; 5] = [
    [0.0, 0.79, 0.0],
    [1.0, 0.77, 0.0],
    [-1.0, 0.81, -1.0],
    [0.5, 0.79, 1.0],
    [-0.25, 0.80, 0.75],
];
/// The rays' angles below the horizontal, in degrees, steep to grazing (all meet the planet:
/// its horizon lies √(2h/R) ≈ 0.7° below the horizontal).
const ANGLES: [f64; 4] = [90.0, 30.0, 10.0, 3.0];
/// The rays' azimuths, in degrees.
const AZIMUTHS: [f64; 3] = [0.0, 40.0, 135.0];

/// The huge bodies, each with its top at the world origin: the planet (a sphere of radius
/// R), a tube (a cylinder of radius R lying along z) and a box (a cube of side 2R), as a scene
/// file gives them.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Body {
    Planet,
    Tube,
    Box,
}

impl Body {
    const ALL: [Body; 3] = [Body::Planet, Body::Tube, Body::Box];

    /// A scene of the body, object 0, with a small sphere beside it so that the acceleration
    /// structures have something to sort.
    fn scene(self) -> Scene {
        let body = match self {
            Body::Planet => "sphere = { center = [0.0, -1e4, 0.0], radius = 1e4 }",
            Body::Tube => {
                "cylinder = { base = [0.0, -1e4, -1e4], top = [0.0, -1e4, 1e4], radius = 1e4 }"
            }
            Body::Box => "box = { min = [-1e4, -2e4, -1e4], max = [1e4, 0.0, 1e4] }",
        };
        let text = format!(
            "[camera]\neye = [0.0, 0.79, 0.0]\nlook_at = [5.0, 0.0, 0.0]\n\
             [[objects]]\n{body}\n\
             [[objects]]\nsphere = {{ center = [40.0, 0.5, 40.0], radius = 0.5 }}\n"
        );
        scene::parse(&text, "planet.toml").expect("a valid scene")
    }

    /// The near root of the ray (its numbers as rounded to [`Real`], taken exactly in f64)
    /// with the body's top, to f64's accuracy. The planet's |P − C|² = R², C = (0, −R, 0), is
    /// written relative to the top P₀ = 0 with normal n = (0, 1, 0), |g + R·n|² = R² with
    /// g = e + d·t, so that no number of size R² is formed: a·t² + 2b·t + c = 0 with a = |d|²,
    /// b = d·e + R·d_y, c = |e|² + 2R·e_y (both terms of c positive: nothing cancels), solved by
    /// the stable root c/q and one Newton step; the tube is the same without z; the box's top
    /// is the plane y = 0.
    fn truth(self, ray: &Ray) -> f64 {
        let e = [f(ray.origin.x), f(ray.origin.y), f(ray.origin.z)];
        let d = [f(ray.dir.x), f(ray.dir.y), f(ray.dir.z)];
        let dims = match self {
            Body::Planet => 3,
            Body::Tube => 2,
            Body::Box => return -e[1] / d[1],
        };
        let dot = |u: [f64; 3], v: [f64; 3]| (0..dims).map(|i| u[i] * v[i]).sum::<f64>();
        let a = dot(d, d);
        let b = dot(d, e) + R * d[1];
        let c = dot(e, e) + 2.0 * R * e[1];
        let q = -(b + b.signum() * (b * b - a * c).sqrt());
        let t = c / q;
        // F(t) = a·t² + 2b·t + c, F′(t) = 2(a·t + b)
        t - (a * t * t + 2.0 * b * t + c) / (2.0 * (a * t + b))
    }
}

/// The rays from each eye of [`EYES`]: every angle of [`ANGLES`] at every azimuth of
/// [`AZIMUTHS`], as rounded to [`Real`].
fn rays() -> Vec<Ray> {
    let mut out = Vec::new();
    for [x, y, z] in EYES {
        for angle in ANGLES {
            for azimuth in AZIMUTHS {
                let (down, level) = angle.to_radians().sin_cos();
                let (s, c) = f64::to_radians(azimuth).sin_cos();
                out.push(Ray::new(vec3(x, y, z), vec3(level * c, -down, level * s)));
            }
        }
    }
    out
}

/// The largest relative error in t over [`rays`] of `near` (the t of the body's hit it finds)
/// against [`Body::truth`], with the ray, the t found and the true t; panics on a miss.
fn worst(body: Body, near: impl Fn(&Ray) -> Option<Real>) -> (f64, Ray, Real, f64) {
    let mut worst = (-1.0, Ray::new(Vec3::ZERO, Vec3::ZERO), 0.0, 0.0);
    for ray in rays() {
        let want = body.truth(&ray);
        let got = near(&ray).unwrap_or_else(|| panic!("{body:?}: {ray:?} missed"));
        let err = rel_err(got, want);
        if err > worst.0 {
            worst = (err, ray, got, want);
        }
    }
    worst
}

/// Notes, "Ray Tracing Process" (the ray carried into object space by M⁻¹) and "Generic
/// Sphere" (x² + y² + z² = 1) at the planet, on every render path: M⁻¹ carries an eye 0.79
/// above a sphere of radius R = 1e4 to the height 1 + 0.79/R = 1.000079 in object space, and
/// the unit sphere's c = |e′|² − 1 keeps only the digits of that number beyond 1. In f32
/// (numbers 1.2e-7 apart near 1) the eye's height survives to R·u = 6e-4 world units only;
/// the nearest hit each query answers must hold t to the precision's tolerance all the same
/// (in f32 by the refinement of `whitted::shapes::refine`), from straight down to 3° below
/// the horizon. A huge tube and a huge box (whose top face sits at y = 1 in object space)
/// lose their digits the same way, and are held the same way.
#[test]
fn huge_bodies_seen_from_close_by_are_hit_at_the_right_distance_on_every_path() {
    for body in Body::ALL {
        let scene = body.scene();
        let body_t = |n: Option<Nearest>| n.filter(|n| n.object == 0).map(|n| n.hit.t);
        for accel in Accel::ALL {
            let mut options = Options::for_scene(&scene, Chapter::ReflectionRefraction);
            options.accel = accel;
            let tracer = Tracer::new(&scene, &options);
            let (err, ray, got, want) = worst(body, |ray| body_t(tracer.nearest(ray, 0.0)));
            assert!(
                err <= tol::PLANET_REL,
                "{body:?}, --accel {}, {ray:?}: t = {got} against the true {want} (relative \
                 error {err:.3e} > {:.0e})",
                accel.name(),
                tol::PLANET_REL
            );
            // the packets of camera rays answer the same, ray by ray
            let structure = build_accel(&scene, &options);
            for ray in rays() {
                let mut packet = [None];
                let want = tracer.nearest(&ray, 0.0);
                structure.nearest_packet(
                    &scene.objects,
                    &[ray],
                    0.0,
                    options.numerics,
                    &mut packet,
                );
                assert_eq!(
                    packet[0],
                    want,
                    "{body:?}, --accel {} as a packet, {ray:?}",
                    accel.name()
                );
            }
            if accel == Accel::Bvh {
                eprintln!(
                    "{body:?}: worst relative error in t {err:.3e} (t = {got} against {want})"
                );
            }
        }
    }
}

/// Notes, "Ray Tracing Process": the generic-object method alone (M⁻¹ and the generic shape in
/// the build's precision, `Object::intersect`, with the robust formulas) holds the huge bodies
/// in f64, and in f32 misses the tolerance: what the refinement of the nearest hit is for.
#[test]
fn the_generic_method_alone_holds_the_huge_bodies_in_f64_only() {
    for body in Body::ALL {
        let scene = body.scene();
        let (err, ray, got, want) = worst(body, |ray| {
            let hits = scene.objects[0].intersect(ray, Numerics::Robust);
            hits.first_after(0.0).map(|h| h.t)
        });
        eprintln!("{body:?}, the generic method alone: worst relative error in t {err:.3e}");
        assert_eq!(
            err > tol::PLANET_REL,
            PRECISION == "f32",
            "{body:?} in {PRECISION}, {ray:?}: t = {got} against the true {want}: relative error \
             {err:.3e}, tolerance {:.0e}",
            tol::PLANET_REL
        );
    }
}
