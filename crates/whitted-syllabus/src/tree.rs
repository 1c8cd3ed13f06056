//! The ray tree of one pixel, typed once (feature `tree`).
//!
//! The road records a pixel's tree, `--inspect X,Y` prints it, `--inspect X,Y --json` writes
//! it, and `--against`, `whitted trees` and the grader read it back: all of them through these
//! types, whose serde view is the JSON shape `docs/src/inspect.md` documents (tree version
//! [`JSON_VERSION`], trees file version [`FILE_VERSION`]).
//!
//! The types are generic over their [`Kinds`]: the renderer fills them with its own numbers,
//! vectors and enums (`Real`, `Vec3`, its `Chapter`, `View`, `Part` …), so that what the road
//! computed is recorded without a conversion; a reader that must not link the renderer (the
//! course tools), or that reads a file written by a build of the other precision, uses
//! [`Plain`]: numbers as `f64` (a number that is not finite is `null` in the JSON, and
//! [`Number`] reads it back as NaN), names as strings. Both read and write the same JSON.
//!
//! ```
//! use whitted_syllabus::tree::{Document, Plain};
//! let text = r#"{"version": 2, "pixel": [3, 4], "chapter": 1, "view": "color",
//!     "colour": [0.5, null, 0.0], "encoding": "srgb", "rays": 1, "samples": [], "bytes": [188, 0, 0]}"#;
//! let doc: Document<Plain> = serde_json::from_str(text).unwrap();
//! assert_eq!(doc.tree.pixel, (3, 4));
//! assert!(doc.tree.colour[1].0.is_nan());
//! assert_eq!(doc.bytes, [188, 0, 0]);
//! ```

use std::fmt::Debug;

use serde::de::{DeserializeOwned, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};

/// The version of the JSON shape of one tree ([`Document`]).
pub const JSON_VERSION: u32 = 2;

/// The version of a trees file's shape ([`TreeFile`]).
pub const FILE_VERSION: u32 = 1;

/// What fills the tree's types: the numbers, vectors and names of whoever reads or writes it.
///
/// Each type reads back what it writes, so a tree survives a trip through its JSON.
pub trait Kinds: Clone + Debug + PartialEq + 'static {
    /// A real number (`Real` for the renderer, [`Number`] for [`Plain`]).
    type Number: Copy + Debug + PartialEq + Serialize + DeserializeOwned;
    /// A 3-vector, written `[x, y, z]`.
    type Vector: Copy + Debug + PartialEq + Serialize + DeserializeOwned;
    /// A chapter, written as its number.
    type Chapter: Copy + Debug + PartialEq + Serialize + DeserializeOwned;
    /// A view of the render, written as its name (`color`, `normals` …).
    type View: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// The encoding of the PNG's bytes, written as its name (`srgb`, `linear`).
    type Encoding: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// The part of a shape a ray hits, written as its name (`wall`, `facet 3` …).
    type Part: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// Which intersection formulas, written as its name.
    type Numerics: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// How secondary rays leave a surface, written as its name.
    type Offset: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
}

/// The kinds of a reader that does not link the renderer: numbers as `f64`, names as strings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Plain;

impl Kinds for Plain {
    type Number = Number;
    type Vector = [Number; 3];
    type Chapter = u8;
    type View = String;
    type Encoding = String;
    type Part = String;
    type Numerics = String;
    type Offset = String;
}

/// A number of a [`Plain`] tree: the JSON's `null` (a number that was not finite) reads as NaN,
/// and NaN writes as `null`.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd, Default)]
pub struct Number(pub f64);

impl Serialize for Number {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.0.is_finite() {
            s.serialize_f64(self.0)
        } else {
            s.serialize_none()
        }
    }
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// Accepts any JSON number, and `null` as NaN.
        struct Reads;
        impl Visitor<'_> for Reads {
            type Value = Number;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number, or null")
            }
            fn visit_f64<E>(self, x: f64) -> Result<Number, E> {
                Ok(Number(x))
            }
            fn visit_u64<E>(self, x: u64) -> Result<Number, E> {
                Ok(Number(x as f64))
            }
            fn visit_i64<E>(self, x: i64) -> Result<Number, E> {
                Ok(Number(x as f64))
            }
            fn visit_unit<E>(self) -> Result<Number, E> {
                Ok(Number(f64::NAN))
            }
            fn visit_none<E>(self) -> Result<Number, E> {
                Ok(Number(f64::NAN))
            }
        }
        d.deserialize_any(Reads)
    }
}

/// The kind of a ray the road traces for a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RayKind {
    /// The camera ray r(t) = e + d·t of a sample of the pixel (chapter 1).
    Camera,
    /// The mirror ray l = d − 2(d·n)n, whose light I_l counts k_r times (chapter 5).
    Mirror,
    /// The transmitted ray of Snell's law, whose light I_r counts k_t times (chapter 5).
    Transmitted,
}

impl RayKind {
    /// The name used in the inspector's text and JSON: `camera`, `mirror`, `transmitted`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Camera => "camera",
            Self::Mirror => "mirror",
            Self::Transmitted => "transmitted",
        }
    }
}

/// Why a branch the material asks for was not traced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The ray would go past the maximum recursion depth (`--max-depth`).
    MaxDepth,
    /// Its weight, the product of the k_r and k_t that lead to it, would fall below the
    /// minimum weight: it could not change the pixel.
    Weight,
    /// Total internal reflection: no transmitted ray exists; its share k_t goes to the mirror
    /// ray.
    TotalInternalReflection,
}

impl Stop {
    /// The name used in the inspector's JSON: `max_depth`, `weight`, `total_internal_reflection`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::MaxDepth => "max_depth",
            Self::Weight => "weight",
            Self::TotalInternalReflection => "total_internal_reflection",
        }
    }
}

/// The ray tree of one pixel: every sample's camera ray and all that followed from it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct RayTree<K: Kinds> {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// The chapter whose road was followed.
    pub chapter: K::Chapter,
    /// The view the colour is for.
    pub view: K::View,
    /// The pixel's colour: exactly what the render writes in the framebuffer (linear RGB).
    pub colour: K::Vector,
    /// The encoding of the PNG the tree's bytes are shown for (`--inspect` sets it from
    /// `--encoding`).
    pub encoding: K::Encoding,
    /// Every ray the pixel cast: camera, feeler, mirror and transmitted.
    pub rays: u64,
    /// The samples, in order.
    pub samples: Vec<Sample<K>>,
}

/// One sample of the pixel.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Sample<K: Kinds> {
    /// Its number among the pixel's samples.
    pub index: u32,
    /// Where in the pixel its camera ray passes: (0.5, 0.5) is the centre.
    pub position: (K::Number, K::Number),
    /// Its camera ray.
    pub ray: RayNode<K>,
}

/// A camera, mirror or transmitted ray and what it brought back.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct RayNode<K: Kinds> {
    /// Camera, mirror or transmitted.
    pub kind: RayKind,
    /// Its origin (the eye e, or the offset start on a surface).
    pub origin: K::Vector,
    /// Its direction d (not unit length for a camera ray).
    pub direction: K::Vector,
    /// The smallest t that counts as a hit.
    pub t_min: K::Number,
    /// Bounces that led to it (0 for a camera ray).
    pub depth: u32,
    /// The product of the k_r and k_t along the way (1 for a camera ray).
    pub weight: K::Number,
    /// The share of its colour that counts at its parent's hit, as the road passed it: k_r
    /// for a mirror ray (plus k_t under total internal reflection), k_t for a transmitted ray,
    /// 1 for a camera ray.
    pub k: K::Number,
    /// The colour it brings back: I_l for a mirror ray, I_r for a transmitted one.
    pub colour: K::Vector,
    /// Its nearest hit; `None` when it hits nothing (its colour is then the background).
    pub hit: Option<HitNode<K>>,
}

/// The nearest hit of a ray, and how it was shaded.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct HitNode<K: Kinds> {
    /// The object's index in the scene.
    pub object: usize,
    /// The object's `name` in the scene file, if it has one.
    pub name: Option<String>,
    /// The generic shape: sphere, plane, cylinder, cone, polyhedron.
    pub shape: String,
    /// The material's name in the scene file.
    pub material: String,
    /// The part of the shape hit.
    pub part: K::Part,
    /// The ray parameter of the hit.
    pub t: K::Number,
    /// The hit point P = r(t), as the road computes it.
    pub point: K::Vector,
    /// The unit normal at P, pointing out of the object (world space).
    pub normal: K::Vector,
    /// Whether the ray goes from outside to inside there, as the shape's intersection says.
    pub entering: bool,
    /// I_a = ρa·I_m (from chapter 3, for the colour view).
    pub ambient: Option<K::Vector>,
    /// Each light, in scene order (from chapter 3).
    pub lights: Vec<LightNode<K>>,
    /// The local light I_a + Σ (I_d + I_s)·share (from chapter 3, for the colour view).
    pub local: Option<K::Vector>,
    /// The mirror and transmitted rays traced from here, in the order they were traced.
    pub branches: Vec<RayNode<K>>,
    /// The branches the material asks for but that were not traced, and why: in the JSON,
    /// `{ "kind": …, "why": … }` objects.
    #[serde(with = "stopped")]
    pub stopped: Vec<(RayKind, Stop)>,
}

/// One light seen from a hit: the terms the Phong model gave for it, and its feeler.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct LightNode<K: Kinds> {
    /// The light's index in the scene.
    pub index: usize,
    /// Its position L.
    pub position: K::Vector,
    /// att = 1/(a0 + a1·d + a2·d²) at the light's distance d.
    pub attenuation: K::Number,
    /// I_p·att: the light's intensity arriving at P.
    pub intensity: K::Vector,
    /// ρd·max(n·s, 0): the diffuse factor, so that I_d = I_p·att·ρd·max(n·s, 0).
    pub diffuse: K::Vector,
    /// ρs·max(r·v, 0)^f: the specular factor, so that I_s = I_p·att·ρs·max(r·v, 0)^f.
    pub specular: K::Vector,
    /// I_d + I_s = `intensity` × (`diffuse` + `specular`), before shadowing.
    pub unshadowed: K::Vector,
    /// Whether the light lies in front of the surface, n·(L − P) > 0, as the road decided it;
    /// a light behind adds nothing.
    pub in_front: bool,
    /// The feeler sent towards the light, if any.
    pub feeler: Option<FeelerNode<K>>,
    /// The share of the light that arrives (1 without a feeler).
    pub share: K::Number,
    /// (I_d + I_s)·share: what the light adds to the local light.
    pub arriving: K::Vector,
}

/// A feeler S(u) = P′ + (L − P′)·u and what it crosses.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct FeelerNode<K: Kinds> {
    /// Its start P′ (the hit point moved off the surface).
    pub origin: K::Vector,
    /// Hits count for u ∈ ]u_min, 1].
    pub u_min: K::Number,
    /// Every object with a hit in ]u_min, 1], in scene order.
    pub crossings: Vec<Crossing<K>>,
}

/// An object a feeler crosses between its start and the light.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Crossing<K: Kinds> {
    /// The object's index in the scene.
    pub object: usize,
    /// Its `name` in the scene file, if any.
    pub name: Option<String>,
    /// The u of its hits in ]u_min, 1].
    pub u: Vec<K::Number>,
    /// Its material's transmission k_t (0: opaque).
    pub transmission: K::Number,
}

/// One tree as `--inspect X,Y --json` writes it: the version of its shape, the tree, and the
/// pixel's bytes in the tree's encoding.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Document<K: Kinds> {
    /// [`JSON_VERSION`] when written.
    pub version: u32,
    /// The tree.
    #[serde(flatten)]
    pub tree: RayTree<K>,
    /// The pixel's bytes as the PNG holds them.
    pub bytes: [u8; 3],
}

/// What a tree depends on besides the scene and the code: the options `whitted trees` traced
/// the reference's trees with, which `--against` traces the student's with.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Settings<K: Kinds> {
    /// The chapter whose road is followed.
    pub chapter: K::Chapter,
    /// The view.
    pub view: K::View,
    /// The image's width.
    pub width: u32,
    /// The image's height.
    pub height: u32,
    /// Samples per pixel.
    pub samples: u32,
    /// The maximum recursion depth.
    pub max_depth: u32,
    /// The smallest weight a branch may carry.
    pub min_weight: K::Number,
    /// Which intersection formulas.
    pub numerics: K::Numerics,
    /// How secondary rays leave a surface.
    pub offset: K::Offset,
    /// The seed of the sample positions.
    pub seed: u64,
}

/// The first line `--inspect-grid STEP` prints: the version of a trees file and the settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct GridHeader<K: Kinds> {
    /// [`FILE_VERSION`] when written.
    pub version: u32,
    /// What the trees that follow were traced with.
    pub settings: Settings<K>,
}

/// A trees file (`chapters/chNN_name/trees.json`, version [`FILE_VERSION`]), written by
/// `whitted trees`: the settings, and the reference's tree at each pixel kept, in the order
/// they are compared.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct TreeFile<K: Kinds> {
    /// [`FILE_VERSION`] when written.
    pub version: u32,
    /// A sentence for a person who opens the file.
    pub about: String,
    /// What the trees were traced with.
    pub settings: Settings<K>,
    /// The pixels kept.
    pub pixels: Vec<Kept<K>>,
}

/// A pixel kept in a trees file, with what it is kept for.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Kept<K: Kinds> {
    /// The pixel (x, y).
    pub pixel: (u32, u32),
    /// What the pixel shows that no pixel kept before it does ("light 0: a highlight" …).
    pub covers: Vec<String>,
    /// Its tree.
    pub tree: Document<K>,
}

/// One pixel of a trees file as `--against … --json` prints it: the pixel, and where its tree
/// first parts from the reference's, if it does.
///
/// ```text
/// { "pixel": [x, y], "differs": false }
/// { "pixel": [x, y], "differs": true, "path": […], "nodes": […], "quantity": "t", … }
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Against {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// Whether its tree differs from the reference's: exactly when [`Against::first`] is
    /// `Some`.
    pub differs: bool,
    /// Where it first differs.
    #[serde(flatten)]
    pub first: Option<Parting>,
}

/// Where a tree first parts from the reference's, as `--against … --json` says it.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Parting {
    /// The path to the node that holds the quantity ("camera ray", "hit `cone`").
    pub path: Vec<String>,
    /// The kinds of the path's nodes ("camera ray", "hit").
    pub nodes: Vec<String>,
    /// The quantity's key in the tree (`t`, `normal`, `crossings` …).
    pub quantity: String,
    /// How the notes write it (`t`, `n`, `ρd·max(n·s, 0)` …).
    pub symbol: String,
    /// Its value in the tree compared, as shown.
    pub computed: String,
    /// The reference's value, as shown.
    pub reference: String,
    /// The functions that computed it, as the manifest spells them.
    pub functions: Vec<String>,
    /// "pixel (x, y), camera ray → hit `cone`: t: 4.02 (the reference: 3.87)".
    pub text: String,
}

/// The file's version, read first, so that a file of another version is named as such
/// rather than as a file whose keys are wrong.
#[derive(Deserialize)]
struct Versioned {
    version: Option<u32>,
}

impl<K: Kinds> TreeFile<K> {
    /// Reads a trees file's text: a file of another version, or one whose pixels lie outside
    /// its image, is refused with a sentence that says so.
    pub fn parse(text: &str) -> Result<Self, String> {
        let Versioned { version } =
            serde_json::from_str(text).map_err(|e| format!("not JSON: {e}"))?;
        if version != Some(FILE_VERSION) {
            return Err(format!(
                "a trees file of version {FILE_VERSION} is expected, this one says {}",
                version.map_or("none".to_string(), |n| n.to_string())
            ));
        }
        let file: Self = serde_json::from_str(text).map_err(|e| e.to_string())?;
        let (w, h) = (file.settings.width, file.settings.height);
        for (i, kept) in file.pixels.iter().enumerate() {
            let (x, y) = kept.tree.tree.pixel;
            if x >= w || y >= h {
                return Err(format!("pixels[{i}]: ({x}, {y}) is outside the image"));
            }
        }
        Ok(file)
    }

    /// The file's text, `pretty` for a file people read; ends with a newline.
    #[must_use]
    pub fn text(&self, pretty: bool) -> String {
        let text = if pretty {
            serde_json::to_string_pretty(self)
        } else {
            serde_json::to_string(self)
        };
        // every key is a string and every value serialisable: this cannot fail
        text.unwrap_or_default() + "\n"
    }
}

/// The stopped branches as `{ "kind": …, "why": … }` objects, both ways.
mod stopped {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use super::{RayKind, Stop};

    /// One stopped branch as the JSON holds it.
    #[derive(Serialize, Deserialize)]
    struct Stopped {
        kind: RayKind,
        why: Stop,
    }

    pub fn serialize<S: Serializer>(stopped: &[(RayKind, Stop)], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(stopped.iter().map(|&(kind, why)| Stopped { kind, why }))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<(RayKind, Stop)>, D::Error> {
        let all = Vec::<Stopped>::deserialize(d)?;
        Ok(all.into_iter().map(|s| (s.kind, s.why)).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A trees file read as plain types and written again is the same text, byte for byte:
    /// the types hold every key, in the order the renderer writes them.
    #[test]
    fn a_committed_trees_file_survives_a_trip_through_the_types() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../chapters");
        let mut read = 0;
        for entry in std::fs::read_dir(&root).unwrap() {
            let path = entry.unwrap().path().join("trees.json");
            let Ok(text) = std::fs::read_to_string(&path) else {
                continue;
            };
            let file = TreeFile::<Plain>::parse(&text)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(!file.pixels.is_empty(), "{}", path.display());
            let again = file.text(true);
            assert!(
                again == text,
                "{}: the text written again differs from the file ({} bytes, expected {})",
                path.display(),
                again.len(),
                text.len()
            );
            read += 1;
        }
        assert_eq!(read, 5, "trees files read under {}", root.display());
    }

    /// A number that was not finite is `null` in the JSON, and reads back as NaN.
    #[test]
    fn null_stands_for_a_number_that_is_not_finite() {
        let n: Number = serde_json::from_str("null").unwrap();
        assert!(n.0.is_nan(), "null read as {n:?}, expected NaN");
        assert_eq!(
            serde_json::to_string(&Number(f64::INFINITY)).unwrap(),
            "null"
        );
        assert_eq!(serde_json::to_string(&Number(0.25)).unwrap(), "0.25");
        let n: Number = serde_json::from_str("3").unwrap();
        assert_eq!(n, Number(3.0));
    }

    /// A pixel that agrees is two keys; one that differs reads back with where it differs.
    #[test]
    fn an_against_line_reads_back_as_written() {
        let same = Against {
            pixel: (3, 4),
            differs: false,
            first: None,
        };
        let text = serde_json::to_string(&same).unwrap();
        assert_eq!(text, r#"{"pixel":[3,4],"differs":false}"#);
        assert_eq!(serde_json::from_str::<Against>(&text).unwrap(), same);
        let differs = Against {
            pixel: (3, 4),
            differs: true,
            first: Some(Parting {
                quantity: "t".into(),
                functions: Vec::new(),
                ..Parting::default()
            }),
        };
        let text = serde_json::to_string(&differs).unwrap();
        assert!(text.contains(r#""functions":[]"#), "{text}");
        assert_eq!(serde_json::from_str::<Against>(&text).unwrap(), differs);
    }

    /// A file of another version is named as such, before its keys are looked at.
    #[test]
    fn a_file_of_another_version_is_refused_by_its_version() {
        let e = TreeFile::<Plain>::parse(r#"{"version": 7, "pixels": 3}"#).unwrap_err();
        assert_eq!(e, "a trees file of version 1 is expected, this one says 7");
        let e = TreeFile::<Plain>::parse("{}").unwrap_err();
        assert_eq!(
            e,
            "a trees file of version 1 is expected, this one says none"
        );
    }
}
