//! The ray tree's types, and their JSON.
//!
//! Every type derives `Serialize`, so the JSON of `--inspect X,Y --json` is serde's view of
//! the same tree the text view prints, in the shape `docs/src/inspect.md` documents (version
//! [`JSON_VERSION`]): vectors as `[x, y, z]`, a number that is not finite as `null`, keys in
//! the order of the fields.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use serde::{Serialize, Serializer};
use serde_json::Value;

use super::super::framebuffer::Encoding;
use super::super::recorder::{RayKind, Stop};
use super::super::{Chapter, View};
use crate::real::{Real, Vec3};
use crate::shapes::Part;

/// The version of the JSON shape [`RayTree::to_json`] writes (`docs/src/inspect.md`).
pub const JSON_VERSION: u32 = 2;

/// The ray tree of one pixel: every sample's camera ray and all that followed from it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RayTree {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// The chapter whose road was followed.
    #[serde(serialize_with = "chapter_number")]
    pub chapter: Chapter,
    /// The view the colour is for.
    #[serde(serialize_with = "view_name")]
    pub view: View,
    /// The pixel's colour: exactly what the render writes in the framebuffer (linear RGB).
    pub colour: Vec3,
    /// The encoding of the PNG the tree's bytes are shown for ([`RayTree::bytes`]); sRGB
    /// unless set otherwise (`--inspect` sets it from `--encoding`).
    #[serde(serialize_with = "encoding_name")]
    pub encoding: Encoding,
    /// Every ray the pixel cast: camera, feeler, mirror and transmitted.
    pub rays: u64,
    /// The samples, in order.
    pub samples: Vec<Sample>,
}

/// One sample of the pixel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// Its number among the pixel's samples.
    pub index: u32,
    /// Where in the pixel its camera ray passes: (0.5, 0.5) is the centre.
    pub position: (Real, Real),
    /// Its camera ray.
    pub ray: RayNode,
}

/// A camera, mirror or transmitted ray and what it brought back.
#[derive(Clone, Debug, PartialEq, Serialize)]
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
    /// The share of its colour that counts at its parent's hit, as the road passed it: k_r
    /// for a mirror ray (plus k_t under total internal reflection), k_t for a transmitted ray,
    /// 1 for a camera ray.
    pub k: Real,
    /// The colour it brings back: I_l for a mirror ray, I_r for a transmitted one.
    pub colour: Vec3,
    /// Its nearest hit; `None` when it hits nothing (its colour is then the background).
    pub hit: Option<HitNode>,
}

/// The nearest hit of a ray, and how it was shaded.
#[derive(Clone, Debug, PartialEq, Serialize)]
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
    #[serde(serialize_with = "part")]
    pub part: Part,
    /// The ray parameter of the hit.
    pub t: Real,
    /// The hit point P = r(t) ([`crate::ray::Ray::at`], as the road computes it).
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
    #[serde(serialize_with = "stops")]
    pub stopped: Vec<(RayKind, Stop)>,
}

/// One light seen from a hit: the terms [`crate::shading::phong`] returned for it, and its
/// feeler.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LightNode {
    /// The light's index in the scene.
    pub index: usize,
    /// Its position L.
    pub position: Vec3,
    /// att = 1/(a0 + a1·d + a2·d²) at the light's distance d.
    pub attenuation: Real,
    /// I_p·att: the light's intensity arriving at P.
    pub intensity: Vec3,
    /// ρd·max(n·s, 0): the diffuse factor, so that I_d = I_p·att·ρd·max(n·s, 0).
    pub diffuse: Vec3,
    /// ρs·max(r·v, 0)^f: the specular factor, so that I_s = I_p·att·ρs·max(r·v, 0)^f.
    pub specular: Vec3,
    /// I_d + I_s = `intensity` × (`diffuse` + `specular`), before shadowing.
    pub unshadowed: Vec3,
    /// Whether the light lies in front of the surface, n·(L − P) > 0
    /// ([`crate::shadow::in_front`]); a light behind adds nothing.
    pub in_front: bool,
    /// The feeler sent towards the light, if any.
    pub feeler: Option<FeelerNode>,
    /// The share of the light that arrives (1 without a feeler).
    pub share: Real,
    /// (I_d + I_s)·share: what the light adds to the local light.
    pub arriving: Vec3,
}

/// A feeler S(u) = P′ + (L − P′)·u and what it crosses.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FeelerNode {
    /// Its start P′ (the hit point moved off the surface).
    pub origin: Vec3,
    /// Hits count for u ∈ ]u_min, 1].
    pub u_min: Real,
    /// Every object with a hit in ]u_min, 1], in scene order.
    pub crossings: Vec<Crossing>,
}

/// An object a feeler crosses between its start and the light.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Crossing {
    /// The object's index in the scene.
    pub object: usize,
    /// Its `name` in the scene file, if any.
    pub name: Option<String>,
    /// The u of its hits in ]u_min, 1] ([`crate::shadow::between`]).
    pub u: Vec<Real>,
    /// Its material's transmission k_t (0: opaque).
    pub transmission: Real,
}

/// The whole JSON document: the version of its shape, the tree, and the pixel's bytes.
#[derive(Serialize)]
struct Document<'t> {
    version: u32,
    #[serde(flatten)]
    tree: &'t RayTree,
    bytes: [u8; 3],
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
        let document = Document {
            version: JSON_VERSION,
            tree: self,
            bytes: self.bytes(),
        };
        // every key is a string and every value serialisable: this cannot fail
        serde_json::to_value(document).unwrap_or(Value::Null)
    }
}

/// The words for a part of a shape, in the text and the JSON alike.
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

impl Serialize for RayKind {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl Serialize for Stop {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

fn chapter_number<S: Serializer>(chapter: &Chapter, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_u8(chapter.number())
}

fn view_name<S: Serializer>(view: &View, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(view.name())
}

fn encoding_name<S: Serializer>(encoding: &Encoding, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(encoding.name())
}

fn part<S: Serializer>(part: &Part, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&part_name(*part))
}

/// The stopped branches as `{ "kind": …, "why": … }` objects.
fn stops<S: Serializer>(stopped: &[(RayKind, Stop)], s: S) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct Stopped {
        kind: RayKind,
        why: Stop,
    }
    s.collect_seq(stopped.iter().map(|&(kind, why)| Stopped { kind, why }))
}
