//! Packets: rays walked together through the BVH or the octree answer as single rays do.

use super::STRAIN;
use crate::common::brute_share;
use whitted::accel::{Accel, Accelerator};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::render::TILE;
use whitted::scene::parse;
use whitted::scene::scatter;
use whitted::shadow;

/// Packets of rays walked through the BVH or the octree together give, ray by ray, exactly what brute
/// force gives: nearest hits, and feeler shares (translucent blockers included). Coherent
/// packets (one origin, a narrow cone, as camera rays), incoherent ones (directions of every
/// sign, where the interval test stands aside) and axis-parallel rays, of every size.
#[test]
fn packets_answer_as_single_rays_do() {
    use whitted::accel::PACKET;
    let strain = parse(STRAIN, "strain.toml").unwrap();
    let field = parse(
        &scatter::scene_toml_with(300, 5, 96, 54, scatter::Layout::Fog),
        "fog.toml",
    )
    .unwrap();
    let mut rng = scatter::SplitMix64::new(11);
    let mut r = |lo: f64, hi: f64| rng.range(lo, hi);
    let mut checked = (0, 0, 0);
    for scene in [&strain, &field] {
        let cam = scene.camera();
        let brute = Accelerator::build(&scene.objects, &cam, Accel::None, TILE);
        for round in 0..600 {
            let kind = [Accel::Bvh, Accel::Octree][round % 2];
            let tree = Accelerator::build(&scene.objects, &cam, kind, TILE);
            let n = 1 + round % PACKET;
            let centre = vec3(r(-8.0, 8.0), r(-2.0, 8.0), r(-8.0, 8.0));
            let aim = vec3(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0));
            let rays: Vec<Ray> = (0..n)
                .map(|k| match round % 3 {
                    // one origin, a narrow cone
                    0 => Ray::new(centre, aim + vec3(r(-0.05, 0.05), r(-0.05, 0.05), 0.0)),
                    // anything
                    1 => Ray::new(
                        vec3(r(-8.0, 8.0), r(-2.0, 8.0), r(-8.0, 8.0)),
                        vec3(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)),
                    ),
                    // along an axis, from points of a line
                    _ => {
                        let mut d = [0.0; 3];
                        d[(round / 3) % 3] = if k % 2 == 0 { 1.0 } else { -1.0 };
                        Ray::new(
                            centre + Vec3::X * real(k as f64 * 0.1),
                            vec3(d[0], d[1], d[2]),
                        )
                    }
                })
                .collect();
            let t_min = if round % 2 == 0 {
                0.0
            } else {
                real(r(0.0, 1.0))
            };
            let mut got = vec![None; n];
            tree.nearest_packet(&scene.objects, &rays, t_min, Default::default(), &mut got);
            for (ray, got) in rays.iter().zip(&got) {
                let want = brute.nearest(&scene.objects, ray, t_min, Default::default());
                assert_eq!(*got, want, "{kind:?}: {ray:?}, t_min {t_min}");
                checked.0 += usize::from(want.is_some());
            }
            // feelers from the rays' origins to one light
            let light = vec3(r(-6.0, 6.0), r(2.0, 9.0), r(-6.0, 6.0));
            let origins: Vec<Vec3> = rays.iter().map(|ray| ray.at(real(r(0.0, 4.0)))).collect();
            // tiny u_min, as the renderer's, and large ones (the feeler starts well along its
            // way), which the walk from the light must still cover to its end
            let u_max = if round % 4 < 2 { 1e-3 } else { 0.9 };
            let u_min: Vec<Real> = (0..n).map(|_| real(r(1e-9, u_max))).collect();
            let mut share = vec![Real::NAN; n];
            let feelers: Vec<Ray> = origins.iter().map(|&o| shadow::feeler(o, light)).collect();
            tree.transmittance_packet(
                &scene.objects,
                &scene.materials,
                light,
                &feelers,
                &u_min,
                Default::default(),
                &mut share,
            );
            for k in 0..n {
                let want = brute_share(
                    &scene.objects,
                    &scene.materials,
                    &feelers[k],
                    u_min[k],
                    Default::default(),
                );
                assert_eq!(
                    share[k].to_bits(),
                    want.to_bits(),
                    "{kind:?}: feeler from {:?}",
                    origins[k]
                );
                checked.1 += usize::from(want == 0.0);
                checked.2 += usize::from(want > 0.0 && want < 1.0);
            }
        }
    }
    // the rays found things, and the feelers met opaque and translucent blockers
    assert!(
        checked.0 > 500 && checked.1 > 100 && checked.2 > 5,
        "{checked:?}"
    );
}
