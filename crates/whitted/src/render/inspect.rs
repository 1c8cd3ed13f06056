//! The ray tree of one pixel: what `--inspect X,Y` prints, and what the live window draws.
//!
//! [`Tracer::inspect`] runs the road of one pixel ([`super::tracer`]) with a
//! [`TreeRecorder`], which keeps every event of the road ([`super::Recorder`]) as a tree:
//!
//! ```text
//! RayTree ── samples ─► Sample ── ray ─► RayNode (camera ray: e, d, colour)
//!                                          └─ hit ─► HitNode (object, part, t, P, n, entering,
//!                                                     I_a, lights, local light, stopped branches)
//!                                                       ├─ lights ─► LightNode (I_d, I_s, attenuation,
//!                                                       │             feeler ─► crossings (u, k_t), share)
//!                                                       └─ branches ─► RayNode (mirror: k_r, I_l;
//!                                                                      transmitted: k_t, I_r) …
//! ```
//!
//! The tree's colour is the pixel's colour bit for bit: the recorder writes down the values
//! the road computes; it computes nothing the road uses. The only values it adds are for the
//! reader: I_d and I_s apart and the attenuation (the road needs only their sum), and the
//! objects a feeler crosses, found by testing every object (the road's acceleration
//! structure may stop at the first opaque one).
//!
//! [`RayTree`]'s `Display` is the indented text of `--inspect X,Y`; [`RayTree::to_json`]
//! the JSON of `--inspect X,Y --json`, whose shape `docs/src/inspect.md` documents.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::fmt;

use serde_json::{Value, json};

use super::framebuffer::Encoding;
use super::recorder::{RayKind, Recorder, Stop};
use super::tracer::{Feeler, Surface};
use super::{Chapter, Stats, Tracer, View};
use crate::light::Light;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;
use crate::shadow;
use crate::shapes::{Nearest, Numerics, Part};

/// The version of the JSON shape `RayTree::to_json` writes (`docs/src/inspect.md`).
pub const JSON_VERSION: u32 = 1;

/// The ray tree of one pixel: every sample's camera ray and all that followed from it.
#[derive(Clone, Debug, PartialEq)]
pub struct RayTree {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// The chapter whose road was followed.
    pub chapter: Chapter,
    /// The view the colour is for.
    pub view: View,
    /// The pixel's colour: exactly what the render writes in the framebuffer (linear RGB).
    pub colour: Vec3,
    /// The encoding of the PNG the tree's bytes are shown for ([`RayTree::bytes`]); sRGB
    /// unless set otherwise (`--inspect` sets it from `--encoding`).
    pub encoding: Encoding,
    /// Every ray the pixel cast: camera, feeler, mirror and transmitted.
    pub rays: u64,
    /// The samples, in order.
    pub samples: Vec<Sample>,
}

/// One sample of the pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    /// Its number among the pixel's samples.
    pub index: u32,
    /// Where in the pixel its camera ray passes: (0.5, 0.5) is the centre.
    pub position: (Real, Real),
    /// Its camera ray.
    pub ray: RayNode,
}

/// A camera, mirror or transmitted ray and what it brought back.
#[derive(Clone, Debug, PartialEq)]
pub struct RayNode {
    /// Camera, mirror or transmitted.
    pub kind: RayKind,
    /// Its origin (the eye e, or the offset start on a surface).
    pub origin: Vec3,
    /// Its direction d (not unit length for a camera ray).
    pub direction: Vec3,
    /// The smallest t that counts as a hit.
    pub t_min: Real,
    /// Bounces that led to it (0 for a camera ray).
    pub depth: u32,
    /// The product of the k_r and k_t along the way (1 for a camera ray).
    pub weight: Real,
    /// The share of its colour that counts at its parent's hit: k_r for a mirror ray (plus
    /// k_t under total internal reflection), k_t for a transmitted ray, 1 for a camera ray.
    pub k: Real,
    /// Its nearest hit; `None` when it hits nothing (its colour is then the background).
    pub hit: Option<HitNode>,
    /// The colour it brings back: I_l for a mirror ray, I_r for a transmitted one.
    pub colour: Vec3,
}

/// The nearest hit of a ray, and how it was shaded.
#[derive(Clone, Debug, PartialEq)]
pub struct HitNode {
    /// The object's index in the scene.
    pub object: usize,
    /// The object's `name` in the scene file, if it has one.
    pub name: Option<String>,
    /// The generic shape: sphere, plane, cylinder, cone, polyhedron.
    pub shape: &'static str,
    /// The material's name in the scene file.
    pub material: String,
    /// The part of the shape hit.
    pub part: Part,
    /// The ray parameter of the hit.
    pub t: Real,
    /// The hit point P = r(t).
    pub point: Vec3,
    /// The unit normal at P, pointing out of the object (world space).
    pub normal: Vec3,
    /// Whether the ray goes from outside to inside there.
    pub entering: bool,
    /// I_a = ρa·I_m (from chapter 3, for the colour view).
    pub ambient: Option<Vec3>,
    /// Each light, in scene order (from chapter 3).
    pub lights: Vec<LightNode>,
    /// The local light I_a + Σ (I_d + I_s)·share (from chapter 3, for the colour view).
    pub local: Option<Vec3>,
    /// The mirror and transmitted rays traced from here, in the order they were traced.
    pub branches: Vec<RayNode>,
    /// The branches the material asks for but that were not traced, and why.
    pub stopped: Vec<(RayKind, Stop)>,
}

/// One light seen from a hit.
#[derive(Clone, Debug, PartialEq)]
pub struct LightNode {
    /// The light's index in the scene.
    pub index: usize,
    /// Its position L.
    pub position: Vec3,
    /// The diffuse term I_d = I_p·att·ρd·max(n·s, 0), before shadowing.
    pub i_d: Vec3,
    /// The specular term I_s = I_p·att·ρs·max(r·v, 0)^f, before shadowing.
    pub i_s: Vec3,
    /// att = 1/(a0 + a1·d + a2·d²) at the light's distance d.
    pub attenuation: Real,
    /// I_d + I_s as the road computed them.
    pub unshadowed: Vec3,
    /// Whether the light lies in front of the surface, n·(L − P) > 0 (else it adds nothing).
    pub in_front: bool,
    /// The feeler sent towards the light, if any.
    pub feeler: Option<FeelerNode>,
    /// The share of the light that arrives (1 without a feeler).
    pub share: Real,
    /// (I_d + I_s)·share: what the light adds to the local light.
    pub arriving: Vec3,
}

/// A feeler S(u) = P′ + (L − P′)·u and what it crosses.
#[derive(Clone, Debug, PartialEq)]
pub struct FeelerNode {
    /// Its start P′ (the hit point moved off the surface).
    pub origin: Vec3,
    /// Hits count for u ∈ ]u_min, 1].
    pub u_min: Real,
    /// Every object with a hit in ]u_min, 1], in scene order.
    pub crossings: Vec<Crossing>,
}

/// An object a feeler crosses between its start and the light.
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    /// The object's index in the scene.
    pub object: usize,
    /// Its `name` in the scene file, if any.
    pub name: Option<String>,
    /// The u of its hits in ]u_min, 1].
    pub u: Vec<Real>,
    /// Its material's transmission k_t (0: opaque).
    pub transmission: Real,
}

impl Tracer<'_> {
    /// The ray tree of pixel (x, y): the road of [`Tracer::pixel`], every stop written down.
    /// Its colour is the pixel's colour bit for bit.
    #[must_use]
    pub fn inspect(&self, x: u32, y: u32) -> RayTree {
        let mut tree = TreeRecorder::new(self.scene, self.options.numerics);
        let mut count = Stats::default();
        let colour = self.pixel(x, y, &mut (&mut tree, &mut count));
        RayTree {
            pixel: (x, y),
            chapter: self.options.chapter,
            view: self.options.view,
            colour,
            encoding: Encoding::default(),
            rays: count.total(),
            samples: tree.samples,
        }
    }
}

/// The recorder that keeps the tree ([`Tracer::inspect`] uses it).
pub struct TreeRecorder<'s> {
    scene: &'s Scene,
    numerics: Numerics,
    /// The rays under way, the camera ray first.
    stack: Vec<RayNode>,
    /// The sample under way: its index and position.
    sample: (u32, (Real, Real)),
    samples: Vec<Sample>,
}

impl<'s> TreeRecorder<'s> {
    /// An empty recorder for rays through `scene`, intersected with `numerics`.
    #[must_use]
    pub fn new(scene: &'s Scene, numerics: Numerics) -> Self {
        Self {
            scene,
            numerics,
            stack: Vec::new(),
            sample: (0, (0.5, 0.5)),
            samples: Vec::new(),
        }
    }

    /// The samples recorded so far.
    #[must_use]
    pub fn into_samples(self) -> Vec<Sample> {
        self.samples
    }

    fn top_hit(&mut self) -> Option<&mut HitNode> {
        self.stack.last_mut().and_then(|r| r.hit.as_mut())
    }

    /// Every object whose hits with the feeler lie in ]u_min, 1], tested one by one.
    fn crossings(&self, (ray, u_min): &Feeler) -> Vec<Crossing> {
        let scene = self.scene;
        let mut out = Vec::new();
        for (i, object) in scene.objects.iter().enumerate() {
            let hits = object.intersect(ray, self.numerics);
            if shadow::blocks(&hits, *u_min) {
                out.push(Crossing {
                    object: i,
                    name: scene.object_name(i).map(str::to_string),
                    u: hits
                        .as_slice()
                        .iter()
                        .map(|h| h.t)
                        .filter(|&u| u > *u_min && u <= 1.0)
                        .collect(),
                    transmission: scene.materials[object.material].transmission,
                });
            }
        }
        out
    }
}

/// I_d and I_s apart, and the attenuation, as [`shading::direct`] computes their sum.
fn phong_parts(s: &Surface, light: &Light) -> (Vec3, Vec3, Real) {
    let to_light = light.position - s.p;
    let d = to_light.length();
    if d == 0.0 {
        return (Vec3::ZERO, Vec3::ZERO, light.attenuation_at(d));
    }
    let dir = to_light / d;
    let att = light.attenuation_at(d);
    let m = s.material;
    let i_d = light.intensity * att * m.diffuse * shading::lambert(s.n, dir);
    let i_s = light.intensity * att * m.specular * shading::highlight(s.n, dir, -s.d, m.shininess);
    (i_d, i_s, att)
}

impl Recorder for TreeRecorder<'_> {
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        self.sample = (index, (dx, dy));
    }

    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real) {
        let k = match (kind, self.stack.last().and_then(|r| r.hit.as_ref())) {
            (RayKind::Camera, _) | (_, None) => 1.0,
            (kind, Some(hit)) => {
                let m = &self.scene.materials[self.scene.objects[hit.object].material];
                let tir = hit
                    .stopped
                    .contains(&(RayKind::Transmitted, Stop::TotalInternalReflection));
                match kind {
                    RayKind::Transmitted => m.transmission,
                    _ if tir => m.reflection + m.transmission,
                    _ => m.reflection,
                }
            }
        };
        self.stack.push(RayNode {
            kind,
            origin: ray.origin,
            direction: ray.dir,
            t_min,
            depth,
            weight,
            k,
            hit: None,
            colour: Vec3::ZERO,
        });
    }

    fn hit(&mut self, nearest: Option<&Nearest>) {
        let scene = self.scene;
        let Some(top) = self.stack.last_mut() else {
            return;
        };
        top.hit = nearest.map(|n| {
            let object = &scene.objects[n.object];
            let ray = Ray::new(top.origin, top.direction);
            HitNode {
                object: n.object,
                name: scene.object_name(n.object).map(str::to_string),
                shape: object.shape.name(),
                material: scene
                    .material_names
                    .get(object.material)
                    .cloned()
                    .unwrap_or_else(|| format!("#{}", object.material)),
                part: n.hit.part,
                t: n.hit.t,
                point: ray.at(n.hit.t),
                normal: n.hit.normal,
                entering: n.hit.entering,
                ambient: None,
                lights: Vec::new(),
                local: None,
                branches: Vec::new(),
                stopped: Vec::new(),
            }
        });
    }

    fn ambient(&mut self, i_a: Vec3) {
        if let Some(hit) = self.top_hit() {
            hit.ambient = Some(i_a);
        }
    }

    fn light(
        &mut self,
        light: usize,
        s: &Surface,
        unshadowed: Vec3,
        feeler: Option<&Feeler>,
        share: Real,
    ) {
        let l = &self.scene.lights[light];
        let (i_d, i_s, attenuation) = phong_parts(s, l);
        let feeler = feeler.map(|f| FeelerNode {
            origin: f.0.origin,
            u_min: f.1,
            crossings: self.crossings(f),
        });
        let node = LightNode {
            index: light,
            position: l.position,
            i_d,
            i_s,
            attenuation,
            unshadowed,
            in_front: s.n.dot(l.position - s.p) > 0.0,
            feeler,
            share,
            arriving: unshadowed * share,
        };
        if let Some(hit) = self.top_hit() {
            hit.lights.push(node);
        }
    }

    fn local(&mut self, colour: Vec3) {
        if let Some(hit) = self.top_hit() {
            hit.local = Some(colour);
        }
    }

    fn stopped(&mut self, kind: RayKind, why: Stop) {
        if let Some(hit) = self.top_hit() {
            hit.stopped.push((kind, why));
        }
    }

    fn done(&mut self, colour: Vec3) {
        let Some(mut node) = self.stack.pop() else {
            return;
        };
        node.colour = colour;
        match self.top_hit() {
            Some(parent) => parent.branches.push(node),
            None => {
                let (index, position) = self.sample;
                self.samples.push(Sample {
                    index,
                    position,
                    ray: node,
                });
            }
        }
    }
}

// ---- text ------------------------------------------------------------------------------

/// A vector as (x, y, z), each as [`N`] writes it.
struct V(Vec3);

impl fmt::Display for V {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, {})", N(self.0.x), N(self.0.y), N(self.0.z))
    }
}

/// A number with at most four decimals, trailing zeros dropped, without a sign on zero.
struct N(Real);

impl fmt::Display for N {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x.is_infinite() {
            return f.write_str(if x > 0.0 { "∞" } else { "−∞" });
        }
        let text = format!("{x:.4}");
        let text = text.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if text == "-0" { "0" } else { text })
    }
}

/// The words for a part of a shape.
#[must_use]
pub fn part_name(part: Part) -> String {
    match part {
        Part::Surface => "surface".into(),
        Part::Wall => "wall".into(),
        Part::TopCap => "top cap".into(),
        Part::BottomCap => "bottom cap".into(),
        Part::Base => "base".into(),
        Part::Apex => "apex".into(),
        Part::Facet(i) => format!("facet {i}"),
    }
}

/// `name` (object i), or object i.
fn object_label(name: Option<&str>, object: usize) -> String {
    match name {
        Some(n) => format!("`{n}` (object {object})"),
        None => format!("object {object}"),
    }
}

fn stop_reason(why: Stop) -> &'static str {
    match why {
        Stop::MaxDepth => "not traced: the maximum depth is reached",
        Stop::Weight => "not traced: its weight would fall below the minimum weight",
        Stop::TotalInternalReflection => {
            "none: total internal reflection (sin θ₂ > 1), k_t goes to the mirror ray"
        }
    }
}

impl fmt::Display for RayTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (x, y) = self.pixel;
        let n = self.samples.len();
        let png = match self.encoding {
            Encoding::Srgb => "sRGB",
            Encoding::Linear => "linear",
        };
        writeln!(
            f,
            "pixel ({x}, {y}), chapter {}, view {}: colour I = {} (linear RGB; {:?} in the {png} PNG), {} ray{}, {n} sample{}",
            self.chapter as u8,
            self.view.name(),
            V(self.colour),
            self.bytes(),
            self.rays,
            if self.rays == 1 { "" } else { "s" },
            if n == 1 { "" } else { "s" },
        )?;
        let shows = match (self.chapter, self.view) {
            (Chapter::CameraRays, _) => Some("the ray direction as a colour, (d̂ + 1)/2"),
            (Chapter::GenericObjects, View::Color) | (_, View::Flat) => {
                Some("the diffuse colour ρd of the material hit, unlit (background for a miss)")
            }
            (_, View::Normals) => Some("the normal facing the camera as a colour, (n + 1)/2"),
            (_, View::Depth) => {
                Some("the distance |t·d| of the hit on the depth view's grey scale")
            }
            (_, View::Shadows) => {
                Some("which lights reach the hit: light 0 red, 1 green, 2 blue, × share")
            }
            (_, View::Rays) => Some("the number of rays the pixel cast, on the heat scale"),
            _ => None,
        };
        if let Some(what) = shows {
            writeln!(f, "the colour shows {what}")?;
        }
        if n > 1 {
            writeln!(f, "I is the mean of the samples' colours")?;
        }
        for s in &self.samples {
            if n > 1 {
                writeln!(
                    f,
                    "sample {} at ({}, {}) in the pixel",
                    s.index,
                    N(s.position.0),
                    N(s.position.1)
                )?;
            }
            write_ray(f, &s.ray, 1)?;
        }
        Ok(())
    }
}

fn write_ray(f: &mut fmt::Formatter<'_>, r: &RayNode, level: usize) -> fmt::Result {
    let pad = "  ".repeat(level);
    match r.kind {
        RayKind::Camera => writeln!(
            f,
            "{pad}camera ray r(t) = e + d·t: e = {}, d = {} → colour {}",
            V(r.origin),
            V(r.direction),
            V(r.colour)
        )?,
        kind => {
            // the mirror ray brings back I_l (counted k_r times), the transmitted ray I_r (k_t)
            let (k, along, light) = match kind {
                RayKind::Mirror => ("k_r", "along l = ", "I_l"),
                _ => ("k_t", "along ", "I_r"),
            };
            writeln!(
                f,
                "{pad}{} ray (depth {}, {k} = {}, weight {}) from {} {along}{} → {light} = {}",
                kind.name(),
                r.depth,
                N(r.k),
                N(r.weight),
                V(r.origin),
                V(r.direction),
                V(r.colour)
            )?;
        }
    }
    let pad = "  ".repeat(level + 1);
    let Some(h) = &r.hit else {
        return writeln!(f, "{pad}hits nothing: the background colour");
    };
    writeln!(
        f,
        "{pad}hits {}: {}, material `{}`, on its {} at t = {}{}",
        object_label(h.name.as_deref(), h.object),
        h.shape,
        h.material,
        part_name(h.part),
        N(h.t),
        if h.entering {
            ", entering"
        } else {
            ", leaving"
        }
    )?;
    writeln!(f, "{pad}  P = {}, n = {}", V(h.point), V(h.normal))?;
    if let Some(i_a) = h.ambient {
        writeln!(f, "{pad}I_a = ρa·I_m = {}", V(i_a))?;
    }
    for l in &h.lights {
        write_light(f, l, &pad)?;
    }
    if let Some(local) = h.local {
        writeln!(
            f,
            "{pad}local light I_a + Σ (I_d + I_s)·share = {}",
            V(local)
        )?;
    }
    for b in &h.branches {
        write_ray(f, b, level + 1)?;
    }
    for (kind, why) in &h.stopped {
        writeln!(f, "{pad}{} ray: {}", kind.name(), stop_reason(*why))?;
    }
    if let (Some(_), false) = (h.local, h.branches.is_empty()) {
        let mut sum = String::from("I = local light");
        for b in &h.branches {
            sum += match b.kind {
                RayKind::Transmitted => " + k_t·I_r",
                _ => " + k_r·I_l",
            };
        }
        writeln!(f, "{pad}{sum} = {}", V(r.colour))?;
    }
    Ok(())
}

fn write_light(f: &mut fmt::Formatter<'_>, l: &LightNode, pad: &str) -> fmt::Result {
    writeln!(
        f,
        "{pad}light {} at {}: I_d = {}, I_s = {} (attenuation {})",
        l.index,
        V(l.position),
        V(l.i_d),
        V(l.i_s),
        N(l.attenuation)
    )?;
    match &l.feeler {
        None if !l.in_front => {
            return writeln!(f, "{pad}  behind the surface, n·(L − P) ≤ 0: adds nothing");
        }
        None if l.unshadowed == Vec3::ZERO => {
            return writeln!(f, "{pad}  adds nothing (no diffuse or specular colour)");
        }
        None => writeln!(
            f,
            "{pad}  no feeler (before chapter 4, or shadows = false): all of it arrives"
        )?,
        Some(feeler) => {
            writeln!(
                f,
                "{pad}  feeler S(u) = P′ + (L − P′)·u from P′ = {}, counting u ∈ ]{}, 1]",
                V(feeler.origin),
                N(feeler.u_min)
            )?;
            if feeler.crossings.is_empty() {
                writeln!(f, "{pad}    crosses nothing")?;
            }
            for c in &feeler.crossings {
                let us: Vec<String> = c.u.iter().map(|u| N(*u).to_string()).collect();
                writeln!(
                    f,
                    "{pad}    crosses {} at u = {} (k_t = {}{})",
                    object_label(c.name.as_deref(), c.object),
                    us.join(", "),
                    N(c.transmission),
                    if c.transmission == 0.0 {
                        ": opaque"
                    } else {
                        ""
                    }
                )?;
            }
        }
    }
    writeln!(
        f,
        "{pad}  share arriving {} → (I_d + I_s)·share = {}",
        N(l.share),
        V(l.arriving)
    )
}

// ---- JSON ------------------------------------------------------------------------------

fn v(x: Vec3) -> Value {
    json!([num(x.x), num(x.y), num(x.z)])
}

/// A number, or `null` for a non-finite one (JSON has no infinity).
#[allow(clippy::useless_conversion)] // Real is f64, or f32 with the `f32` feature
fn num(x: Real) -> Value {
    let x = f64::from(x);
    if x.is_finite() { json!(x) } else { Value::Null }
}

impl RayTree {
    /// The pixel's bytes as the PNG holds them in the tree's [`encoding`](RayTree::encoding).
    #[must_use]
    pub fn bytes(&self) -> [u8; 3] {
        self.colour.to_array().map(|x| self.encoding.byte(x))
    }

    /// The tree as JSON (the shape is documented in `docs/src/inspect.md`).
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "version": JSON_VERSION,
            "pixel": [self.pixel.0, self.pixel.1],
            "chapter": self.chapter as u8,
            "view": self.view.name(),
            "colour": v(self.colour),
            "encoding": self.encoding.name(),
            "bytes": self.bytes(),
            "rays": self.rays,
            "samples": self.samples.iter().map(|s| json!({
                "index": s.index,
                "position": [num(s.position.0), num(s.position.1)],
                "ray": ray_json(&s.ray),
            })).collect::<Vec<_>>(),
        })
    }
}

fn ray_json(r: &RayNode) -> Value {
    json!({
        "kind": r.kind.name(),
        "origin": v(r.origin),
        "direction": v(r.direction),
        "t_min": num(r.t_min),
        "depth": r.depth,
        "weight": num(r.weight),
        "k": num(r.k),
        "colour": v(r.colour),
        "hit": r.hit.as_ref().map(hit_json),
    })
}

fn hit_json(h: &HitNode) -> Value {
    json!({
        "object": h.object,
        "name": h.name,
        "shape": h.shape,
        "material": h.material,
        "part": part_name(h.part),
        "t": num(h.t),
        "point": v(h.point),
        "normal": v(h.normal),
        "entering": h.entering,
        "ambient": h.ambient.map(v),
        "lights": h.lights.iter().map(light_json).collect::<Vec<_>>(),
        "local": h.local.map(v),
        "branches": h.branches.iter().map(ray_json).collect::<Vec<_>>(),
        "stopped": h.stopped.iter().map(|(kind, why)| json!({
            "kind": kind.name(),
            "why": why.name(),
        })).collect::<Vec<_>>(),
    })
}

fn light_json(l: &LightNode) -> Value {
    json!({
        "index": l.index,
        "position": v(l.position),
        "i_d": v(l.i_d),
        "i_s": v(l.i_s),
        "attenuation": num(l.attenuation),
        "unshadowed": v(l.unshadowed),
        "in_front": l.in_front,
        "feeler": l.feeler.as_ref().map(|f| json!({
            "origin": v(f.origin),
            "u_min": num(f.u_min),
            "crossings": f.crossings.iter().map(|c| json!({
                "object": c.object,
                "name": c.name,
                "u": c.u.iter().map(|u| num(*u)).collect::<Vec<_>>(),
                "transmission": num(c.transmission),
            })).collect::<Vec<_>>(),
        })),
        "share": num(l.share),
        "arriving": v(l.arriving),
    })
}
