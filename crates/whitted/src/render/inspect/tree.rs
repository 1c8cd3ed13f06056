//! The ray tree as the road records it: the tree's types of `whitted_syllabus::tree`, filled
//! with the renderer's own numbers, vectors and names ([`Traced`]).
//!
//! The types are defined once, in `whitted_syllabus::tree`, with serde both ways, so that the
//! course tools (which never link the renderer) read the same tree the road records. Here
//! they get the renderer's kinds: `Real` and `Vec3` as the road computed them (no
//! conversion), and the renderer's [`Chapter`], [`View`], [`Encoding`], [`Part`], [`Numerics`]
//! and [`OffsetKind`], each written by its name (a chapter by its number). The JSON of
//! `--inspect X,Y --json` is serde's view of the [`RayTree`] the text view prints, in the
//! shape `docs/src/inspect.md` documents (version [`JSON_VERSION`]): vectors as `[x, y, z]`,
//! a number that is not finite as `null`, keys in the order of the fields.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::ops::{Deref, DerefMut};

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use serde_json::Value;
pub use whitted_syllabus::tree::{Document, FILE_VERSION, JSON_VERSION, Kinds, Plain};

use super::super::framebuffer::Encoding;
use super::super::{Chapter, View};
use crate::offset::OffsetKind;
use crate::real::{Real, Vec3};
use crate::shapes::{Numerics, Part};

/// The renderer's kinds of the tree: what the road computed, as it computed it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Traced;

impl Kinds for Traced {
    type Number = Real;
    type Vector = Vec3;
    type Chapter = Chapter;
    type View = View;
    type Encoding = Encoding;
    type Part = Part;
    type Numerics = Numerics;
    type Offset = OffsetKind;
}

/// One sample of the pixel ([`whitted_syllabus::tree::Sample`]).
pub type Sample = whitted_syllabus::tree::Sample<Traced>;
/// A camera, mirror or transmitted ray and what it brought back.
pub type RayNode = whitted_syllabus::tree::RayNode<Traced>;
/// The nearest hit of a ray, and how it was shaded.
pub type HitNode = whitted_syllabus::tree::HitNode<Traced>;
/// One light seen from a hit: the terms [`crate::shading::phong`] returned for it, and its
/// feeler.
pub type LightNode = whitted_syllabus::tree::LightNode<Traced>;
/// A feeler S(u) = P′ + (L − P′)·u and what it crosses.
pub type FeelerNode = whitted_syllabus::tree::FeelerNode<Traced>;
/// An object a feeler crosses between its start and the light.
pub type Crossing = whitted_syllabus::tree::Crossing<Traced>;
/// The options a tree was traced with, as a trees file records them.
pub type Settings = whitted_syllabus::tree::Settings<Traced>;
/// The first line `--inspect-grid STEP` prints: the trees file's version and the settings.
pub type GridHeader = whitted_syllabus::tree::GridHeader<Traced>;

/// The ray tree of one pixel: every sample's camera ray and all that followed from it
/// ([`whitted_syllabus::tree::RayTree`], whose fields it shows through `Deref`), with the
/// renderer's text view (`Display`, in [`super::text`]), its bytes and its JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct RayTree(pub whitted_syllabus::tree::RayTree<Traced>);

impl Deref for RayTree {
    type Target = whitted_syllabus::tree::RayTree<Traced>;
    fn deref(&self) -> &Self::Target {
        &self.0
    }
}

impl DerefMut for RayTree {
    fn deref_mut(&mut self) -> &mut Self::Target {
        &mut self.0
    }
}

impl RayTree {
    /// The pixel's bytes as the PNG holds them in the tree's [`encoding`](whitted_syllabus::tree::RayTree::encoding).
    #[must_use]
    pub fn bytes(&self) -> [u8; 3] {
        self.colour.to_array().map(|x| self.encoding.byte(x))
    }

    /// The tree as `--inspect X,Y --json` writes it: its version, the tree, its bytes.
    #[must_use]
    pub fn document(&self) -> Document<Traced> {
        Document {
            version: JSON_VERSION,
            tree: self.0.clone(),
            bytes: self.bytes(),
        }
    }

    /// The tree as JSON (the shape is documented in `docs/src/inspect.md`).
    #[must_use]
    pub fn to_json(&self) -> Value {
        // every key is a string and every value serialisable: this cannot fail
        serde_json::to_value(self.document()).unwrap_or(Value::Null)
    }

    /// The tree read as [`Plain`] types, as a reader that does not link the renderer (or a
    /// build of the other precision) reads its JSON.
    pub fn plain(&self) -> Result<Document<Plain>, serde_json::Error> {
        serde_json::from_value(self.to_json())
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

/// The parts that are not numbered, as [`Part::Facet`] is.
const WHOLE_PARTS: [Part; 6] = [
    Part::Surface,
    Part::Wall,
    Part::TopCap,
    Part::BottomCap,
    Part::Base,
    Part::Apex,
];

/// The part [`part_name`] words so.
fn part_named(name: &str) -> Option<Part> {
    if let Some(i) = name.strip_prefix("facet ") {
        return i.parse().ok().map(Part::Facet);
    }
    WHOLE_PARTS.into_iter().find(|p| part_name(*p) == name)
}

/// Serde for a type written by its name: the one among `ALL` whose `name()` it is.
macro_rules! by_name {
    ($type:ty, $what:literal) => {
        impl Serialize for $type {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }

        impl<'de> Deserialize<'de> for $type {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let given = String::deserialize(d)?;
                <$type>::ALL
                    .into_iter()
                    .find(|x| x.name() == given)
                    .ok_or_else(|| {
                        let names: Vec<&str> = <$type>::ALL.iter().map(|x| x.name()).collect();
                        D::Error::custom(format!(
                            "{}: `{given}` is none of {}",
                            $what,
                            names.join(", ")
                        ))
                    })
            }
        }
    };
}

by_name!(View, "view");
by_name!(Encoding, "encoding");
by_name!(Numerics, "numerics");
by_name!(OffsetKind, "offset");

impl Serialize for Chapter {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u8(self.number())
    }
}

impl<'de> Deserialize<'de> for Chapter {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let n = u8::deserialize(d)?;
        Chapter::from_number(n)
            .ok_or_else(|| D::Error::custom(format!("chapter: {n} is not 1 to 5")))
    }
}

impl Serialize for Part {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&part_name(*self))
    }
}

impl<'de> Deserialize<'de> for Part {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let given = String::deserialize(d)?;
        part_named(&given).ok_or_else(|| D::Error::custom(format!("part: `{given}` is no part")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every part reads back from the name it is written by.
    #[test]
    fn a_part_reads_back_from_its_name() {
        for part in WHOLE_PARTS
            .into_iter()
            .chain([Part::Facet(0), Part::Facet(17)])
        {
            let json = serde_json::to_string(&part).unwrap();
            let back: Part = serde_json::from_str(&json).unwrap();
            assert_eq!(
                back, part,
                "{json} read back as {back:?}, expected {part:?}"
            );
        }
        assert!(serde_json::from_str::<Part>("\"facet x\"").is_err());
    }

    /// A view, an encoding, the numerics and the offset read back from their names, and a
    /// name that is none of them says which it could have been.
    #[test]
    fn names_read_back_and_a_wrong_name_lists_the_right_ones() {
        for view in View::ALL {
            let back: View = serde_json::from_value(serde_json::to_value(view).unwrap()).unwrap();
            assert_eq!(back, view);
        }
        let e = serde_json::from_str::<Numerics>("\"fast\"").unwrap_err();
        assert_eq!(
            e.to_string(),
            "numerics: `fast` is none of textbook, robust",
            "the error for an unknown numerics"
        );
        let e = serde_json::from_str::<Chapter>("9").unwrap_err();
        assert_eq!(e.to_string(), "chapter: 9 is not 1 to 5");
    }
}
