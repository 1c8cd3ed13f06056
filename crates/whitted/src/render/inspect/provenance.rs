//! Where each number of the ray tree comes from: for every quantity the tree holds, what the
//! notes call it, how near another computation of it must come to count as the same, and the
//! functions of the road that computed it. Which function computes which quantity is written
//! once, in the manifest (`chapters/formulas.toml`, each formula's `computes` list), and read
//! here ([`Quantity::computed_by`]); [`super::walk`] asks it to say which exercise computed the
//! first number that differs from the reference's. A test (`tests/trees.rs`) checks that every
//! entry of every `computes` list names a quantity and a place this module knows, and that
//! every exercise computes some quantity of the tree.
//!
//! A formula lists every quantity whose value depends on it directly, not only the last one:
//! a hit's t is the shape's roots of the ray carried by M⁻¹, so the ray's transform computes t
//! as well as the quadratic does. `cargo learn` narrows the functions to the exercises whose
//! own tests fail.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::sync::OnceLock;

use serde::Deserialize;

use super::super::recorder::RayKind;
use super::super::{Chapter, View};

/// A quantity of the ray tree, named by where it sits: every key of the tree's JSON
/// (`docs/src/inspect.md`) that the road computed, and the shape of the tree itself (which
/// object a ray hits, which branches leave a hit, which objects a feeler crosses).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// How many samples the pixel takes.
    Samples,
    /// Where a sample's camera ray crosses the pixel.
    SamplePosition,
    /// A ray's origin: the eye e, or a start P′ moved off a surface.
    Origin,
    /// A ray's direction d.
    Direction,
    /// The smallest t that counts as a hit of a ray.
    TMin,
    /// The bounces before a mirror or transmitted ray.
    Depth,
    /// The product of the k along the way to a ray.
    Weight,
    /// The k_r or k_t a branch's light counts at its parent's hit.
    K,
    /// The colour a ray brings back: the pixel's for the camera ray, I_l or I_r for a branch.
    Colour,
    /// Which object a ray hits first, or that it hits none.
    Object,
    /// The part of the shape hit.
    Part,
    /// The ray parameter t of the nearest hit.
    T,
    /// Whether the ray enters the object there.
    Entering,
    /// The hit point P = r(t).
    Point,
    /// The unit normal n at P, in the world.
    Normal,
    /// The ambient term I_a = ρa·I_m.
    Ambient,
    /// How many lights the hit is lit by.
    Lights,
    /// A light's attenuation 1/(a0 + a1·d + a2·d²).
    Attenuation,
    /// A light's intensity at P, I_p·att.
    Intensity,
    /// A light's diffuse factor ρd·max(n·s, 0).
    Diffuse,
    /// A light's specular factor ρs·max(r·v, 0)^f.
    Specular,
    /// A light's I_d + I_s before shadowing.
    Unshadowed,
    /// Whether a feeler is sent towards the light.
    Feeler,
    /// A feeler's start P′, the hit point moved off the surface.
    Start,
    /// The smallest u that counts along a feeler.
    UMin,
    /// Which objects the feeler crosses between its start and the light.
    Crossed,
    /// The u of an object's hits along the feeler.
    U,
    /// The share of the light that arrives.
    Share,
    /// What the light adds, (I_d + I_s)·share.
    Arriving,
    /// The local light I_a + Σ (I_d + I_s)·share.
    Local,
    /// Which mirror and transmitted rays leave the hit, and why those not traced stopped.
    Branches,
}

/// How near a value must come to the reference's to count as the same:
/// |a − b| ≤ `absolute` + `relative`·max(|a|, |b|), for a vector with |·| the largest
/// component. Integers, flags and names must be equal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// The absolute part, for values near zero.
    pub absolute: f64,
    /// The part relative to the size of the values.
    pub relative: f64,
}

impl Tolerance {
    /// Equal values only.
    pub const EXACT: Tolerance = Tolerance {
        absolute: 0.0,
        relative: 0.0,
    };

    /// Geometry: points, directions, normals, t, u, and the starts of secondary rays. The
    /// reference is traced in f64 and a student may build in f32, whose unit roundoff is
    /// 6e-8: at the steady pixels of every chapter scene (those `whitted trees` chooses from),
    /// an f32 build's trees differ from the f64 ones by at most 1.2e-5 relative (measured; the
    /// start of a feeler differs most, pushed off the surface by f32's larger error bound),
    /// so the tolerance leaves a margin of 80. A formula written wrong moves these by percents.
    pub const GEOMETRY: Tolerance = Tolerance {
        absolute: 1e-4,
        relative: 1e-3,
    };

    /// Light: colours, Phong's factors, attenuation, k, weights and shares. A highlight raises
    /// r·v to the power f (up to 120 in the chapter scenes), which multiplies its relative
    /// error by f: an f32 build's trees differ from the f64 ones by at most 6.6e-5 relative
    /// (measured as above), and a highlight near zero by 3.3e-5 absolute.
    pub const LIGHT: Tolerance = Tolerance {
        absolute: 1e-4,
        relative: 2e-3,
    };

    /// The smallest t or u that counts, which an offset may make 1e-5 and a missing offset 0:
    /// only relative.
    pub const THRESHOLD: Tolerance = Tolerance {
        absolute: 1e-12,
        relative: 1e-3,
    };

    /// Whether `a` and `b` count as the same number.
    #[must_use]
    pub fn same(self, a: f64, b: f64) -> bool {
        if a == b {
            return true; // infinities too
        }
        (a - b).abs() <= self.absolute + self.relative * a.abs().max(b.abs())
    }

    /// Whether the vectors `a` and `b` count as the same: componentwise, relative to the
    /// largest component of either.
    #[must_use]
    pub fn same_vectors(self, a: &[f64], b: &[f64]) -> bool {
        if a.len() != b.len() {
            return false;
        }
        let size = a.iter().chain(b).fold(0.0_f64, |m, x| m.max(x.abs()));
        a.iter()
            .zip(b)
            .all(|(x, y)| x == y || (x - y).abs() <= self.absolute + self.relative * size)
    }
}

/// Where a quantity sits, as much as its provenance depends on it.
#[derive(Clone, Copy, Debug)]
pub struct Place<'a> {
    /// The chapter whose road was followed.
    pub chapter: Chapter,
    /// The view the colours are for.
    pub view: View,
    /// The ray the quantity belongs to (or whose hit, light or feeler it belongs to).
    pub ray: RayKind,
    /// The generic shapes involved: the shape hit, or the shapes of the objects a feeler
    /// crosses (or misses) in one tree and not the other.
    pub shapes: &'a [&'a str],
}

impl Quantity {
    /// How the notes write it, as the inspector's text shows it.
    #[must_use]
    pub fn symbol(self, ray: RayKind) -> &'static str {
        match self {
            Quantity::Samples => "samples",
            Quantity::SamplePosition => "the sample's place in the pixel",
            Quantity::Origin if ray == RayKind::Camera => "e",
            Quantity::Origin => "its start",
            Quantity::Direction if ray == RayKind::Mirror => "l",
            Quantity::Direction => "d",
            Quantity::TMin => "t_min",
            Quantity::Depth => "depth",
            Quantity::Weight => "weight",
            Quantity::K if ray == RayKind::Mirror => "k_r",
            Quantity::K => "k_t",
            Quantity::Colour => match ray {
                RayKind::Camera => "colour",
                RayKind::Mirror => "I_l",
                RayKind::Transmitted => "I_r",
            },
            Quantity::Object => "the object hit",
            Quantity::Part => "the part hit",
            Quantity::T => "t",
            Quantity::Entering => "entering",
            Quantity::Point => "P",
            Quantity::Normal => "n",
            Quantity::Ambient => "I_a = ρa·I_m",
            Quantity::Lights => "lights",
            Quantity::Attenuation => "att = 1/(a0 + a1·d + a2·d²)",
            Quantity::Intensity => "I_p·att",
            Quantity::Diffuse => "ρd·max(n·s, 0)",
            Quantity::Specular => "ρs·max(r·v, 0)^f",
            Quantity::Unshadowed => "I_d + I_s",
            Quantity::Feeler => "a feeler",
            Quantity::Start => "P′",
            Quantity::UMin => "u_min",
            Quantity::Crossed => "the objects crossed",
            Quantity::U => "u",
            Quantity::Share => "share",
            Quantity::Arriving => "(I_d + I_s)·share",
            Quantity::Local => "local light",
            Quantity::Branches => "mirror and transmitted rays",
        }
    }

    /// How near another computation of it must come ([`Tolerance`]).
    #[must_use]
    pub fn tolerance(self) -> Tolerance {
        match self {
            Quantity::SamplePosition
            | Quantity::Origin
            | Quantity::Direction
            | Quantity::T
            | Quantity::Point
            | Quantity::Normal
            | Quantity::Start
            | Quantity::U => Tolerance::GEOMETRY,
            Quantity::TMin | Quantity::UMin => Tolerance::THRESHOLD,
            Quantity::Weight
            | Quantity::K
            | Quantity::Colour
            | Quantity::Ambient
            | Quantity::Attenuation
            | Quantity::Intensity
            | Quantity::Diffuse
            | Quantity::Specular
            | Quantity::Unshadowed
            | Quantity::Share
            | Quantity::Arriving
            | Quantity::Local => Tolerance::LIGHT,
            Quantity::Samples
            | Quantity::Depth
            | Quantity::Object
            | Quantity::Part
            | Quantity::Entering
            | Quantity::Lights
            | Quantity::Feeler
            | Quantity::Crossed
            | Quantity::Branches => Tolerance::EXACT,
        }
    }

    /// The functions of the road that computed it at `place`, as the manifest spells them
    /// (empty when no exercise computes it: the sample positions, a colour the view picks).
    /// Those whose entry names the place (a cone's t: the cone's own formulas) come first,
    /// then those that compute it wherever it sits (the ray's transform), each group in the
    /// manifest's order.
    #[must_use]
    pub fn computed_by(self, place: &Place) -> Vec<&'static str> {
        let mut found: Vec<(bool, &'static str)> = manifest()
            .iter()
            .filter_map(|(function, computes)| {
                let entries = computes.iter().filter(|c| c.covers(self, place));
                let general = entries.map(Computes::general).reduce(|a, b| a && b)?;
                Some((general, function.as_str()))
            })
            .collect();
        found.sort_by_key(|(general, _)| *general);
        found.into_iter().map(|(_, f)| f).collect()
    }

    /// Its word in the manifest's `computes` lists: its [`key`](Quantity::key), except for a
    /// feeler's start (`start`, where the key is `origin`, as for a ray) and the objects it
    /// crosses (`crossed`).
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            Quantity::Start => "start",
            Quantity::Crossed => "crossed",
            other => other.key(),
        }
    }

    /// Every quantity, in the order the comparison walks a node's.
    pub const ALL: [Quantity; 31] = [
        Quantity::Samples,
        Quantity::SamplePosition,
        Quantity::Origin,
        Quantity::Direction,
        Quantity::TMin,
        Quantity::Depth,
        Quantity::Weight,
        Quantity::K,
        Quantity::Colour,
        Quantity::Object,
        Quantity::Part,
        Quantity::T,
        Quantity::Entering,
        Quantity::Point,
        Quantity::Normal,
        Quantity::Ambient,
        Quantity::Lights,
        Quantity::Attenuation,
        Quantity::Intensity,
        Quantity::Diffuse,
        Quantity::Specular,
        Quantity::Unshadowed,
        Quantity::Feeler,
        Quantity::Start,
        Quantity::UMin,
        Quantity::Crossed,
        Quantity::U,
        Quantity::Share,
        Quantity::Arriving,
        Quantity::Local,
        Quantity::Branches,
    ];

    /// Its name in the comparison's JSON (`docs/src/inspect.md`): the tree's own key where it
    /// has one.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Quantity::Samples => "samples",
            Quantity::SamplePosition => "position",
            Quantity::Origin => "origin",
            Quantity::Direction => "direction",
            Quantity::TMin => "t_min",
            Quantity::Depth => "depth",
            Quantity::Weight => "weight",
            Quantity::K => "k",
            Quantity::Colour => "colour",
            Quantity::Object => "object",
            Quantity::Part => "part",
            Quantity::T => "t",
            Quantity::Entering => "entering",
            Quantity::Point => "point",
            Quantity::Normal => "normal",
            Quantity::Ambient => "ambient",
            Quantity::Lights => "lights",
            Quantity::Attenuation => "attenuation",
            Quantity::Intensity => "intensity",
            Quantity::Diffuse => "diffuse",
            Quantity::Specular => "specular",
            Quantity::Unshadowed => "unshadowed",
            Quantity::Feeler => "feeler",
            Quantity::Start => "origin",
            Quantity::UMin => "u_min",
            Quantity::Crossed => "crossings",
            Quantity::U => "u",
            Quantity::Share => "share",
            Quantity::Arriving => "arriving",
            Quantity::Local => "local",
            Quantity::Branches => "branches",
        }
    }
}

/// The number `x` as a comparison shows it: four decimals, or three significant digits in
/// scientific notation when it is smaller than 1e-3 (a u_min of 1e-5 is not 0).
#[must_use]
pub fn number(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.is_infinite() {
        if x > 0.0 {
            "∞".into()
        } else {
            "−∞".into()
        }
    } else if x.abs() < 1e-3 {
        format!("{x:.2e}")
    } else {
        let text = format!("{x:.4}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// The manifest's text, as the renderer was built with it.
const MANIFEST: &str = include_str!("../../../../../chapters/formulas.toml");

// a copy of the project that leaves the manifest out would name no function for any number:
// it does not build instead
const _: () = assert!(
    !MANIFEST.is_empty(),
    "chapters/formulas.toml is empty: the renderer names the functions of the ray tree's numbers from it"
);

/// One formula of the manifest, as far as provenance reads it: its function and its
/// `computes` entries as written.
#[derive(Deserialize)]
struct Formula {
    function: String,
    #[serde(default)]
    computes: Vec<String>,
}

/// The manifest, as far as provenance reads it.
#[derive(Deserialize)]
struct Manifest {
    formula: Vec<Formula>,
}

/// The manifest's formulas (none when it does not read: `tests/trees.rs` proves the
/// committed one reads).
fn formulas() -> Vec<Formula> {
    toml::from_str::<Manifest>(MANIFEST).map_or_else(|_| Vec::new(), |m| m.formula)
}

/// Each formula's function with what it computes, read once; an entry that does not read
/// counts for nothing here, and [`manifest_entries`] names it.
fn manifest() -> &'static [(String, Vec<Computes>)] {
    static TABLE: OnceLock<Vec<(String, Vec<Computes>)>> = OnceLock::new();
    TABLE.get_or_init(|| {
        formulas()
            .into_iter()
            .map(|f| {
                let read = f.computes.iter().filter_map(|c| Computes::parse(c).ok());
                (f.function, read.collect())
            })
            .collect()
    })
}

/// Every entry of every formula's `computes` list in the manifest, as written, with what it
/// means: the quantity and where it holds, or why this module cannot read it.
#[must_use]
pub fn manifest_entries() -> Vec<(String, String, Result<Computes, String>)> {
    formulas()
        .into_iter()
        .flat_map(|f| {
            let function = f.function;
            f.computes.into_iter().map(move |c| {
                let read = Computes::parse(&c);
                (function.clone(), c, read)
            })
        })
        .collect()
}

/// One entry of a formula's `computes` list: `QUANTITY` (the quantity's [`word`](Quantity::word))
/// wherever it sits, or `QUANTITY/WHERE` with one or more places `|`-separated — a generic shape
/// involved (`sphere`, `plane`, `cylinder`, `cone`, `polyhedron`, or `shape` for any), the kind
/// of ray it belongs to (`camera`, `mirror`, `transmitted`), or for a colour the road that
/// shades it (`ch1`: chapter 1's, whatever the view; `lit`: the colour view from chapter 3;
/// `ch5-lit`: the colour view of chapter 5).
#[derive(Clone, Debug, PartialEq)]
pub struct Computes {
    /// The quantity.
    pub quantity: Quantity,
    /// Where it holds: any of these (none: everywhere).
    pub places: Vec<Where>,
}

/// A place a `computes` entry holds at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Where {
    /// The generic shape of that name is involved.
    Shape(&'static str),
    /// Some shape is involved.
    AnyShape,
    /// The quantity belongs to a ray of this kind.
    Ray(RayKind),
    /// Chapter 1's colour, whatever the view.
    ChapterOne,
    /// The colour view from chapter 3 on, lit by the local light.
    Lit,
    /// The colour view of chapter 5, with mirror and transmitted light.
    LitChapterFive,
}

/// The generic shapes, as the tree names them.
const SHAPES: [&str; 5] = ["sphere", "plane", "cylinder", "cone", "polyhedron"];

impl Where {
    /// The place a word names.
    fn named(word: &str) -> Option<Where> {
        Some(match word {
            "shape" => Where::AnyShape,
            "camera" => Where::Ray(RayKind::Camera),
            "mirror" => Where::Ray(RayKind::Mirror),
            "transmitted" => Where::Ray(RayKind::Transmitted),
            "ch1" => Where::ChapterOne,
            "lit" => Where::Lit,
            "ch5-lit" => Where::LitChapterFive,
            shape => Where::Shape(SHAPES.into_iter().find(|s| *s == shape)?),
        })
    }

    /// Whether `place` is here.
    fn holds(self, place: &Place) -> bool {
        let lit = place.view == View::Color && place.chapter >= Chapter::Shading;
        match self {
            Where::Shape(s) => place.shapes.contains(&s),
            Where::AnyShape => !place.shapes.is_empty(),
            Where::Ray(kind) => place.ray == kind,
            Where::ChapterOne => place.chapter == Chapter::CameraRays,
            Where::Lit => lit,
            Where::LitChapterFive => lit && place.chapter == Chapter::ReflectionRefraction,
        }
    }
}

impl Computes {
    /// Reads an entry; the error says what is wrong with it.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (word, places) = match text.split_once('/') {
            Some((w, p)) => (w, Some(p)),
            None => (text, None),
        };
        let quantity = Quantity::ALL
            .into_iter()
            .find(|q| q.word() == word)
            .ok_or_else(|| format!("`{word}` is no quantity of the ray tree"))?;
        let places = match places {
            None => Vec::new(),
            Some(p) => p
                .split('|')
                .map(|w| Where::named(w).ok_or_else(|| format!("`{w}` is no place of `{text}`")))
                .collect::<Result<_, _>>()?,
        };
        Ok(Self { quantity, places })
    }

    /// Whether the entry holds wherever its quantity sits, or wherever some shape is involved:
    /// it names no place in particular.
    fn general(&self) -> bool {
        self.places.iter().all(|w| *w == Where::AnyShape)
    }

    /// Whether the entry says its formula computes `quantity` at `place`.
    #[must_use]
    pub fn covers(&self, quantity: Quantity, place: &Place) -> bool {
        self.quantity == quantity
            && (self.places.is_empty() || self.places.iter().any(|w| w.holds(place)))
    }
}
