//! The ray tree of one pixel (`--inspect X,Y`): it is the road of one pixel written down, so
//! its colour is the rendered pixel bit for bit, its numbers add up to that colour the way the
//! notes' I = I_a + I_d + I_s + I_l + I_r says, and it says why each branch stopped.

// the helpers of the student's tests, shared
#[path = "../crates/whitted/tests/common/mod.rs"]
mod common;

use common::scene;
use whitted::ray::Ray;
use whitted::real::{Real, Vec3};
use whitted::render::inspect::{HitNode, RayNode, RayTree};
use whitted::render::{
    Chapter, EveryObject, Feeler, Framebuffer, Options, RayKind, Recorder, Stats, Stop, Tracer,
    View, render,
};
use whitted::scene::{Scene, load_parts};
use whitted::shading::Phong;
use whitted::shadow;
use whitted::shapes::{Hits, Nearest};

use whitted::scene::SHOWCASE;
const GLASS: &str = include_str!("../scenes/ch05_reflection_refraction.toml");

fn options(scene: &Scene, chapter: Chapter, width: u32, height: u32) -> Options {
    let mut o = Options::for_scene(scene, chapter);
    o.width = width;
    o.height = height;
    o
}

/// The bits of a colour's channels, to compare colours exactly.
#[allow(clippy::useless_conversion)] // Real is f64, or f32 with the `f32` feature
fn bits(v: Vec3) -> [u64; 3] {
    v.to_array().map(|x| u64::from(x.to_bits()))
}

/// Asserts that the tree of every pixel of the image has the pixel's colour, bit for bit, and
/// casts the rays the pixel casts.
fn assert_trees_match(scene: &Scene, o: &Options) {
    let (fb, stats): (Framebuffer, Stats) = render(scene, o);
    let tracer = Tracer::new(scene, o);
    let mut rays = 0;
    for y in 0..o.height {
        for x in 0..o.width {
            let tree = tracer.inspect(x, y);
            assert_eq!(
                bits(tree.colour),
                bits(fb.get(x, y)),
                "pixel ({x}, {y}) of {:?} {:?} packets {}: tree {:?}, image {:?}",
                o.chapter,
                o.view,
                o.packets,
                tree.colour,
                fb.get(x, y)
            );
            rays += tree.rays;
        }
    }
    assert_eq!(rays, stats.total(), "the trees cast the image's rays");
}

/// The tree's colour is the rendered pixel, for every pixel of the showcase, in every chapter
/// that traces objects, with packets on and off.
#[test]
fn the_tree_colour_is_the_rendered_pixel_on_the_showcase() {
    let s = scene(SHOWCASE);
    for chapter in Chapter::ALL
        .into_iter()
        .filter(|&c| c >= Chapter::GenericObjects)
    {
        for packets in [true, false] {
            let mut o = options(&s, chapter, 48, 36);
            o.packets = packets;
            assert_trees_match(&s, &o);
        }
    }
}

/// The same on chapter 5's glass scene (a glass sphere and a water cylinder: transmitted rays,
/// total internal reflection), with 4 samples a pixel too.
#[test]
fn the_tree_colour_is_the_rendered_pixel_on_the_glass_scene() {
    let s = scene(GLASS);
    for (samples, packets) in [(1, true), (1, false), (4, true)] {
        let mut o = options(&s, Chapter::ReflectionRefraction, 48, 32);
        o.samples = samples;
        o.packets = packets;
        assert_trees_match(&s, &o);
    }
}

/// Every view's tree has the view's colour (the depth view's scale is fixed before the first
/// pixel, so one pixel inspected alone is shaded as in the whole image).
#[test]
fn the_tree_colour_is_the_rendered_pixel_in_every_view() {
    let s = scene(SHOWCASE);
    for view in View::ALL {
        let mut o = options(&s, Chapter::ReflectionRefraction, 32, 24);
        o.view = view;
        assert_trees_match(&s, &o);
    }
}

/// Visits every ray node of a tree.
fn each_node(tree: &RayTree, f: &mut impl FnMut(&RayNode)) {
    fn walk(n: &RayNode, f: &mut impl FnMut(&RayNode)) {
        f(n);
        if let Some(h) = &n.hit {
            for b in &h.branches {
                walk(b, f);
            }
        }
    }
    for s in &tree.samples {
        walk(&s.ray, f);
    }
}

/// Notes, "Reflection and refraction": I = I_a + I_d + I_s + I_l + I_r. At every hit of the
/// tree, each light's I_d + I_s is I_p·att·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f) of its own
/// factors, I_a plus each light's (I_d + I_s)·share is the local light, and the local light plus
/// k·(the colour of each branch) is the ray's colour, computed in the road's order, bit for
/// bit; the pixel is the mean of its samples.
#[test]
fn the_tree_adds_up_to_the_pixel() {
    let s = scene(GLASS);
    let mut o = options(&s, Chapter::ReflectionRefraction, 24, 16);
    o.samples = 2;
    let tracer = Tracer::new(&s, &o);
    let mut hits = 0;
    for y in 0..o.height {
        for x in 0..o.width {
            let tree = tracer.inspect(x, y);
            let mut sum = Vec3::ZERO;
            for sample in &tree.samples {
                sum += sample.ray.colour;
            }
            assert_eq!(bits(sum / tree.samples.len() as Real), bits(tree.colour));
            each_node(&tree, &mut |n| {
                let Some(h) = &n.hit else {
                    assert_eq!(n.colour, s.background, "a miss brings back the background");
                    return;
                };
                hits += 1;
                let mut local = h.ambient.expect("chapter 5 shades every hit");
                for l in &h.lights {
                    let unshadowed = l.intensity * (l.diffuse + l.specular); // I_p·att·(…)
                    assert_eq!(bits(l.unshadowed), bits(unshadowed), "light {l:?}");
                    assert_eq!(bits(l.arriving), bits(l.unshadowed * l.share));
                    local += l.arriving;
                }
                assert_eq!(bits(local), bits(h.local.unwrap()));
                let mut colour = local;
                for b in &h.branches {
                    colour += b.k * b.colour;
                }
                assert_eq!(bits(colour), bits(n.colour), "at {h:?}");
            });
        }
    }
    assert!(
        hits > 1000,
        "the glass scene's trees hold many hits ({hits})"
    );
}

/// Notes, "Shadowing": the share of a light that arrives is the product of the transmissions
/// k_t of the objects the feeler crosses with u ∈ ]u_min, 1] (0 if one is opaque); the tree
/// lists those objects, found by testing every object, and their u.
#[test]
fn a_feeler_share_is_the_product_of_what_it_crosses() {
    let s = scene(GLASS);
    let o = options(&s, Chapter::ReflectionRefraction, 32, 20);
    let tracer = Tracer::new(&s, &o);
    let (mut feelers, mut crossing) = (0, 0);
    for y in 0..o.height {
        for x in 0..o.width {
            each_node(&tracer.inspect(x, y), &mut |n| {
                for l in n.hit.iter().flat_map(|h: &HitNode| &h.lights) {
                    let Some(f) = &l.feeler else { continue };
                    feelers += 1;
                    let k_t: Vec<Real> = f.crossings.iter().map(|c| c.transmission).collect();
                    assert_eq!(l.share.to_bits(), shadow::transmittance(k_t).to_bits());
                    for c in &f.crossings {
                        crossing += 1;
                        assert!(!c.u.is_empty());
                        assert!(c.u.iter().all(|&u| u > f.u_min && u <= 1.0), "{c:?}");
                    }
                }
            });
        }
    }
    assert!(
        feelers > 500 && crossing > 50,
        "{feelers} feelers, {crossing} crossings"
    );
}

/// A scene whose only object is a mirror sphere in front of a mirror wall, seen head on:
/// rays bounce between them until a limit stops them.
const MIRRORS: &str = r#"
[camera]
eye = [0.0, 0.0, 5.0]
look_at = [0.0, 0.0, 0.0]
[image]
width = 1
height = 1
[render]
max_depth = 3
[[lights]]
position = [0.0, 5.0, 5.0]
[materials.mirror]
diffuse = 0.1
reflection = 0.5
[[objects]]
name = "ball"
sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }
material = "mirror"
[[objects]]
name = "wall"
plane = { point = [0.0, 0.0, 10.0], normal = [0.0, 0.0, -1.0] }
material = "mirror"
"#;

/// A ray of a chain: its kind, the object it hits, its weight.
type Link = (RayKind, Option<usize>, Real);

/// The chain of mirror rays below the camera ray, with the reasons recorded at its end.
fn chain(tree: &RayTree) -> (Vec<Link>, Vec<(RayKind, Stop)>) {
    let mut out = Vec::new();
    let mut node = &tree.samples[0].ray;
    loop {
        let hit = node.hit.as_ref();
        out.push((node.kind, hit.map(|h| h.object), node.weight));
        match hit.and_then(|h| h.branches.first()) {
            Some(next) => node = next,
            None => return (out, hit.map(|h| h.stopped.clone()).unwrap_or_default()),
        }
    }
}

/// A mirror ray is not traced past the maximum depth, and the tree says so.
#[test]
fn a_branch_past_the_maximum_depth_is_stopped_and_says_why() {
    let s = scene(MIRRORS);
    let o = options(&s, Chapter::ReflectionRefraction, 1, 1);
    let tree = Tracer::new(&s, &o).inspect(0, 0);
    let (rays, stopped) = chain(&tree);
    // camera → ball → wall → ball → wall: depths 0..3, each a mirror ray of weight 0.5^depth
    let expected = [
        (RayKind::Camera, Some(0), 1.0),
        (RayKind::Mirror, Some(1), 0.5),
        (RayKind::Mirror, Some(0), 0.25),
        (RayKind::Mirror, Some(1), 0.125),
    ];
    assert_eq!(rays, expected);
    assert_eq!(stopped, [(RayKind::Mirror, Stop::MaxDepth)]);
    assert_eq!(
        tree.rays,
        4 + 4,
        "4 rays on the chain and a feeler at each hit"
    );
    assert!(tree.to_string().contains("the maximum depth is reached"));
}

/// A mirror ray whose weight would fall below the minimum weight is not traced.
#[test]
fn a_branch_below_the_minimum_weight_is_stopped_and_says_why() {
    let s = scene(MIRRORS);
    let mut o = options(&s, Chapter::ReflectionRefraction, 1, 1);
    o.max_depth = 10;
    o.min_weight = 0.2; // 0.5, 0.25 pass; 0.125 does not
    let (rays, stopped) = chain(&Tracer::new(&s, &o).inspect(0, 0));
    assert_eq!(rays.len(), 3);
    assert_eq!(stopped, [(RayKind::Mirror, Stop::Weight)]);
}

/// A ray that hits nothing brings back the background, and the tree says it hit nothing.
#[test]
fn a_ray_that_hits_nothing_brings_back_the_background() {
    let mut s = scene(MIRRORS);
    s.objects.truncate(1); // the ball alone: its mirror ray flies off
    let o = options(&s, Chapter::ReflectionRefraction, 1, 1);
    let tree = Tracer::new(&s, &o).inspect(0, 0);
    let (rays, stopped) = chain(&tree);
    assert_eq!(rays.len(), 2);
    assert_eq!(rays[1].1, None);
    assert!(stopped.is_empty());
    assert!(
        tree.to_string()
            .contains("hits nothing: the background colour")
    );
}

/// Notes, "Refraction": from inside glass (n₁ = 1.5) at more than the critical angle
/// asin(1/1.5) ≈ 41.8° there is no transmitted ray; the tree says so, and the mirror ray takes
/// k_r + k_t.
#[test]
fn total_internal_reflection_is_recorded_and_the_mirror_ray_takes_k_t() {
    let s = scene(GLASS);
    let o = options(&s, Chapter::ReflectionRefraction, 96, 64);
    let tracer = Tracer::new(&s, &o);
    let mut found = 0;
    for y in 0..o.height {
        for x in 0..o.width {
            each_node(&tracer.inspect(x, y), &mut |n| {
                let Some(h) = &n.hit else { return };
                let tir = (RayKind::Transmitted, Stop::TotalInternalReflection);
                if h.stopped.contains(&tir) {
                    found += 1;
                    assert!(
                        !h.entering,
                        "only a ray leaving the glass is reflected whole"
                    );
                    let m = &s.materials[s.objects[h.object].material];
                    for b in &h.branches {
                        assert_eq!(b.kind, RayKind::Mirror);
                        assert_eq!(b.k, m.reflection + m.transmission);
                    }
                }
            });
        }
    }
    assert!(found > 0, "the glass scene shows total internal reflection");
}

/// The tree names objects by their scene `name`, else by index, and gives the hit's part, t,
/// point and normal: the point is r(t) and the normal is a unit vector.
#[test]
fn the_hit_names_the_object_and_its_point_is_on_the_ray() {
    let s = scene(SHOWCASE);
    let o = options(&s, Chapter::ReflectionRefraction, 64, 48);
    let tracer = Tracer::new(&s, &o);
    let tree = tracer.inspect(32, 24);
    let ray = &tree.samples[0].ray;
    let hit = ray
        .hit
        .as_ref()
        .expect("the centre pixel hits the glass sphere");
    assert_eq!(hit.name.as_deref(), Some("glass sphere"));
    assert_eq!(hit.material, "glass");
    let p = ray.origin + ray.direction * hit.t;
    assert!((p - hit.point).length() <= 1e-4 * p.length().max(1.0));
    assert!((hit.normal.length() - 1.0).abs() < 1e-4);
    let mut unnamed = s.clone();
    unnamed.object_names.clear();
    let tree = Tracer::new(&unnamed, &o).inspect(32, 24);
    let text = tree.to_string();
    assert!(text.contains("hits object 2:"), "{text}");
    assert!(!text.contains("glass sphere"));
}

/// The JSON of the tree parses, holds the documented fields, and its colour is the tree's.
#[test]
fn the_json_parses_and_carries_the_colour() {
    let s = scene(SHOWCASE);
    let o = options(&s, Chapter::ReflectionRefraction, 64, 48);
    let tree = Tracer::new(&s, &o).inspect(32, 24);
    let text = serde_json::to_string(&tree.to_json()).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["version"], whitted::render::inspect::JSON_VERSION);
    assert_eq!(v["version"], 2);
    assert_eq!(v["pixel"], serde_json::json!([32, 24]));
    assert_eq!(v["chapter"], 5);
    assert_eq!(v["rays"], tree.rays);
    let colour: Vec<Real> = v["colour"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() as Real)
        .collect();
    assert_eq!(bits(Vec3::from_slice(&colour)), bits(tree.colour));
    let ray = &v["samples"][0]["ray"];
    assert_eq!(ray["kind"], "camera");
    let hit = &ray["hit"];
    assert_eq!(hit["name"], "glass sphere");
    for key in [
        "t", "point", "normal", "entering", "part", "lights", "branches", "stopped",
    ] {
        assert!(!hit[key].is_null(), "hit.{key} missing: {hit}");
    }
    let light = &hit["lights"][0];
    for key in [
        "attenuation",
        "intensity",
        "diffuse",
        "specular",
        "unshadowed",
        "share",
        "arriving",
        "feeler",
    ] {
        assert!(!light[key].is_null(), "light.{key} missing: {light}");
    }
    assert!(hit["branches"][0]["k"].as_f64().unwrap() > 0.0);
}

/// Every value the road hands its recorder, in the order it hands them, as bits: what the
/// road computed for a pixel, written down without a tree.
#[derive(Default)]
struct Log {
    values: Vec<u64>,
    /// The rays under way, the camera ray first.
    rays: Vec<Ray>,
    /// The objects the feeler under way crosses, until its light's event.
    crossed: Vec<(usize, Hits, Real)>,
}

impl Log {
    #[allow(clippy::useless_conversion)] // Real is f64, or f32 with the `f32` feature
    fn number(&mut self, x: Real) {
        self.values.push(u64::from(x.to_bits()));
    }

    fn vector(&mut self, v: Vec3) {
        v.to_array().into_iter().for_each(|x| self.number(x));
    }

    fn count(&mut self, i: usize) {
        self.values.push(i as u64);
    }
}

impl Recorder for Log {
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        self.count(index as usize);
        self.number(dx);
        self.number(dy);
    }

    fn ray(&mut self, _: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real, k: Real) {
        self.rays.push(*ray);
        self.vector(ray.origin);
        self.vector(ray.dir);
        self.number(t_min);
        self.count(depth as usize);
        self.number(weight);
        self.number(k);
    }

    fn hit(&mut self, nearest: Option<&Nearest>) {
        if let Some(n) = nearest {
            self.count(n.object);
            self.number(n.hit.t);
            self.vector(n.hit.normal);
            // the shading point's P = r(t), as the road makes it (`ShadingPoint::new`)
            let ray = *self.rays.last().expect("a hit of the ray under way");
            self.vector(ray.at(n.hit.t));
        }
    }

    fn ambient(&mut self, i_a: Vec3) {
        self.vector(i_a);
    }

    fn crossing(&mut self, object: usize, hits: &Hits, k_t: Real) {
        self.crossed.push((object, *hits, k_t));
    }

    fn light(
        &mut self,
        light: usize,
        in_front: bool,
        phong: &Phong,
        feeler: Option<&Feeler>,
        share: Real,
        arriving: Vec3,
    ) {
        self.count(light);
        self.count(usize::from(in_front));
        self.number(phong.attenuation);
        for v in [phong.intensity, phong.diffuse, phong.specular, phong.sum] {
            self.vector(v);
        }
        if let Some(f) = feeler {
            self.vector(f.ray.origin);
            self.number(f.u_min);
            for (object, hits, k_t) in std::mem::take(&mut self.crossed) {
                self.count(object);
                for h in hits.as_slice() {
                    if shadow::between(h.t, f.u_min) {
                        self.number(h.t);
                    }
                }
                self.number(k_t);
            }
        }
        assert!(self.crossed.is_empty(), "crossings without a feeler");
        self.number(share);
        self.vector(arriving);
    }

    fn local(&mut self, colour: Vec3) {
        self.vector(colour);
    }

    fn done(&mut self, colour: Vec3) {
        self.rays.pop();
        self.vector(colour);
    }
}

/// The numbers of a tree, in the order the road computed them.
fn numbers(tree: &RayTree) -> Vec<u64> {
    fn ray(log: &mut Log, r: &RayNode) {
        log.vector(r.origin);
        log.vector(r.direction);
        log.number(r.t_min);
        log.count(r.depth as usize);
        log.number(r.weight);
        log.number(r.k);
        if let Some(h) = &r.hit {
            log.count(h.object);
            log.number(h.t);
            log.vector(h.normal);
            log.vector(h.point);
            if let Some(i_a) = h.ambient {
                log.vector(i_a);
            }
            for l in &h.lights {
                log.count(l.index);
                log.count(usize::from(l.in_front));
                log.number(l.attenuation);
                for v in [l.intensity, l.diffuse, l.specular, l.unshadowed] {
                    log.vector(v);
                }
                if let Some(f) = &l.feeler {
                    log.vector(f.origin);
                    log.number(f.u_min);
                    for c in &f.crossings {
                        log.count(c.object);
                        c.u.iter().for_each(|&u| log.number(u));
                        log.number(c.transmission);
                    }
                }
                log.number(l.share);
                log.vector(l.arriving);
            }
            if let Some(local) = h.local {
                log.vector(local);
            }
            for b in &h.branches {
                ray(log, b);
            }
        }
        log.vector(r.colour);
    }
    let mut log = Log::default();
    for s in &tree.samples {
        log.count(s.index as usize);
        log.number(s.position.0);
        log.number(s.position.1);
        ray(&mut log, &s.ray);
    }
    log.values
}

/// Record, never recompute: every number of a pixel's ray tree — each ray's origin, direction,
/// t_min, depth, weight and k, each hit's t, normal and point (r(t) of the ray handed), I_a,
/// each light's side (in front or not, as the road decided it), attenuation, I_p·att, diffuse
/// and specular factors, I_d + I_s, feeler, crossings, share and (I_d + I_s)·share, the local
/// light, each colour brought back — is, bit for bit and in the same order, a value the road
/// of that pixel handed its recorder (logged here by a recorder of this test's own, through
/// the plain road, [`EveryObject`]); and the road's colour is the pixel of the rendered image
/// (BVH and packets). For every pixel of each chapter's scene at its chapter, and of the
/// showcase.
#[test]
fn every_number_in_the_tree_is_the_roads() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let scenes = [
        ("ch02_generic_objects.toml", Chapter::GenericObjects),
        ("ch03_shading.toml", Chapter::Shading),
        ("ch04_shadows.toml", Chapter::Shadows),
        (
            "ch05_reflection_refraction.toml",
            Chapter::ReflectionRefraction,
        ),
        ("showcase.toml", Chapter::ReflectionRefraction),
    ];
    let mut checked = 0;
    for (file, chapter) in scenes {
        let s = load_parts(&root.join("scenes").join(file), chapter.reads()).unwrap();
        let o = options(&s, chapter, 40, 30);
        let (fb, _) = render(&s, &o);
        let tracer = Tracer::new(&s, &o);
        let plain = tracer.asking(EveryObject {
            scene: &s,
            numerics: o.numerics,
        });
        for y in 0..o.height {
            for x in 0..o.width {
                let mut log = Log::default();
                let colour = plain.pixel(x, y, &mut log);
                assert_eq!(
                    bits(colour),
                    bits(fb.get(x, y)),
                    "{file} pixel ({x}, {y}): the plain road and the render"
                );
                let tree = tracer.inspect(x, y);
                let from_tree = numbers(&tree);
                assert_eq!(
                    from_tree.len(),
                    log.values.len(),
                    "{file} pixel ({x}, {y}): the tree holds {} numbers, the road handed {}",
                    from_tree.len(),
                    log.values.len()
                );
                if let Some(i) = (0..from_tree.len()).find(|&i| from_tree[i] != log.values[i]) {
                    panic!(
                        "{file} pixel ({x}, {y}): number {i} of the tree is {:#x}, the road's {:#x}\n{tree}",
                        from_tree[i], log.values[i]
                    );
                }
                assert_eq!(bits(tree.colour), bits(colour));
                checked += from_tree.len();
            }
        }
    }
    assert!(checked > 100_000, "{checked} numbers checked");
}
