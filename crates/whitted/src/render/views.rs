//! The views: what the nearest hit of a camera ray shows in each `--view` (from chapter 2 on).
//!
//! | view | a hit shows | a miss shows |
//! |---|---|---|
//! | `color`, `rays` | the chapter's own colour: the road's ([`Tracer`]) | the background |
//! | `flat` | the diffuse colour ρd of the material, unlit (chapter 2's colour) | the background |
//! | `normals` | (n + 1)/2, the normal turned towards the viewer | the background |
//! | `depth` | the distance \|t·d\| on the depth scale ([`Scales::depth`]) | black |
//! | `shadows` | which lights reach it: light i in [`light_colour`]`(i)` times its share | black |
//! | `ambient` … `mirrored` | the picture of one exercise ([`super::stages`]) | the background |
//!
//! Each view is drawn from the road's own steps (its flat colour, its feelers, its query), so
//! it shows what the road would compute; the road itself knows none of them. Their scales and
//! palettes are fixed before the first pixel, beneath the road ([`super::scales`], whose items
//! are also named here).
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::options::View;
use super::query::{Query, ShadingPoint};
use super::recorder::Recorder;
use super::shortcuts::Shortcuts;
use super::stages;
use super::tracer::Tracer;
use crate::camera::direction_colour;
use crate::ray::Ray;
use crate::real::Vec3;
use crate::shading;
use crate::shadow;
use crate::shapes::Nearest;

pub use super::scales::{DEPTH_PROBES, Scales, heat, light_colour, shadow_mask};

// ANCHOR: ch2_view_colour
/// The colour the view of `tracer`'s options shows for a camera ray `ray` (from chapter 2 on)
/// whose nearest hit is `nearest`.
pub(crate) fn colour<Q: Query + Shortcuts>(
    tracer: &Tracer<'_, Q>,
    ray: &Ray,
    nearest: Option<Nearest>,
    rec: &mut impl Recorder,
) -> Vec3 {
    let scene = tracer.scene;
    match tracer.options.view {
        View::Color | View::Rays => tracer.hit_colour(ray, nearest, rec),
        View::Flat => tracer.flat(nearest),
        View::Normals => nearest.map_or(scene.background, |n| {
            direction_colour(shading::facing(n.hit.normal, ray.dir))
        }),
        View::Depth => tracer
            .scales()
            .depth(nearest.map(|n| n.hit.t * ray.dir.length())),
        View::Shadows => nearest.map_or(Vec3::ZERO, |n| {
            let s = tracer.query().shading_point(scene, ray, &n);
            shadow_mask_at(tracer, &s, rec)
        }),
        stage => nearest.map_or(scene.background, |n| {
            let s = tracer.query().shading_point(scene, ray, &n);
            stages::colour(stage, &s, scene)
        }),
    }
}
// ANCHOR_END: ch2_view_colour

/// The shadow-mask view at the shading point `s`: which lights reach it, light i painted in
/// [`light_colour`]`(i)` times the share of it that arrives (before chapter 4, 1 for every
/// light in front). A light behind the surface cannot reach it and is left out. `rec` hears
/// each light in front, as from the road's local light.
fn shadow_mask_at<Q: Query + Shortcuts>(
    tracer: &Tracer<'_, Q>,
    s: &ShadingPoint,
    rec: &mut impl Recorder,
) -> Vec3 {
    let mut mask = Vec3::ZERO;
    for (l, light) in tracer.scene.lights.iter().enumerate() {
        let in_front = shadow::in_front(s.n, s.p, light.position); // n·(L − P) > 0
        if !in_front {
            continue; // behind the surface: the light cannot reach it
        }
        let feeler = tracer.feeler(s, light);
        let share = match &feeler {
            Some(feeler) => tracer.query().share(feeler, rec),
            None => 1.0,
        };
        let phong = shading::phong(s.material, light, s.p, s.n, -s.d);
        rec.light(
            l,
            in_front,
            &phong,
            feeler.as_ref(),
            share,
            phong.sum * share,
        );
        mask += light_colour(l) * share;
    }
    shadow_mask(mask)
}
