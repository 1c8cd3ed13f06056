//! What a scene file says: the TOML layout, read with serde.
//!
//! Every table and key is optional unless noted, and every number is checked as it is read
//! (finite, positive where a size is meant, …), so a bad value is reported at its own line and
//! column. Unknown keys are refused. The full reference is `docs/src/scene-format.md`.
//!
//! Course book: [The scene file](../../../../../docs/book/scene-format.html) (`docs/src/scene-format.md`).

use std::collections::BTreeMap;
use std::fmt;

use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use toml::Spanned;

// ---------------------------------------------------------------------------------------------
// Checked numbers

/// True when x is finite in f64 *and* at the precision in use (1e300 is not an f32).
fn representable(x: f64) -> bool {
    x.is_finite() && crate::real::real(x).is_finite()
}

fn not_finite(x: f64) -> String {
    if x.is_finite() {
        format!(
            "expected a finite number, found {x:e}, which is too large for {} precision",
            crate::real::PRECISION
        )
    } else {
        format!("expected a finite number, found {x}")
    }
}

/// Reads one number (TOML float or integer) and applies `check`, which names what is expected.
fn number<'de, D: Deserializer<'de>>(
    de: D,
    check: fn(f64) -> Result<f64, &'static str>,
) -> Result<f64, D::Error> {
    let x = f64::deserialize(de)?;
    if !representable(x) {
        return Err(de::Error::custom(not_finite(x)));
    }
    check(x).map_err(|want| de::Error::custom(format!("expected {want}, found {x}")))
}

macro_rules! checked_number {
    ($(#[$doc:meta])* $name:ident, $check:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name(pub f64);
        impl<'de> Deserialize<'de> for $name {
            fn deserialize<D: Deserializer<'de>>(de: D) -> Result<Self, D::Error> {
                number(de, $check).map($name)
            }
        }
    };
}

checked_number!(
    /// Any finite number.
    Finite,
    Ok
);
checked_number!(
    /// A finite number > 0.
    Positive,
    |x| if x > 0.0 { Ok(x) } else { Err("a number > 0") }
);
checked_number!(
    /// A finite number ≥ 0.
    NonNegative,
    |x| if x >= 0.0 { Ok(x) } else { Err("a number ≥ 0") }
);
checked_number!(
    /// A finite number in [0, 1].
    Unit,
    |x| if (0.0..=1.0).contains(&x) { Ok(x) } else { Err("a number from 0 to 1") }
);
checked_number!(
    /// A vertical viewing angle in degrees, strictly between 0 and 180.
    Fov,
    |x| if x > 0.0 && x < 180.0 { Ok(x) } else { Err("a viewing angle strictly between 0 and 180 degrees") }
);
checked_number!(
    /// An index of refraction ≥ 1 would be physical; whitted accepts any value > 0.
    Ior,
    |x| if x > 0.0 { Ok(x) } else { Err("an index of refraction > 0") }
);

/// Three numbers, or one number meaning the same three times, each checked by `check`.
fn triple<'de, D: Deserializer<'de>>(
    de: D,
    what: &'static str,
    allow_scalar: bool,
    check: fn(f64) -> Result<f64, &'static str>,
) -> Result<[f64; 3], D::Error> {
    struct V {
        what: &'static str,
        allow_scalar: bool,
        check: fn(f64) -> Result<f64, &'static str>,
    }
    impl V {
        fn one<E: de::Error>(&self, x: f64) -> Result<f64, E> {
            if !representable(x) {
                return Err(E::custom(not_finite(x)));
            }
            (self.check)(x).map_err(|want| E::custom(format!("expected {want}, found {x}")))
        }
    }
    impl<'de> Visitor<'de> for V {
        type Value = [f64; 3];
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(self.what)
        }
        fn visit_f64<E: de::Error>(self, x: f64) -> Result<Self::Value, E> {
            if !self.allow_scalar {
                return Err(E::invalid_type(de::Unexpected::Float(x), &self));
            }
            let x = self.one(x)?;
            Ok([x; 3])
        }
        fn visit_i64<E: de::Error>(self, x: i64) -> Result<Self::Value, E> {
            self.visit_f64(x as f64)
        }
        fn visit_u64<E: de::Error>(self, x: u64) -> Result<Self::Value, E> {
            self.visit_f64(x as f64)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
            let mut out = [0.0; 3];
            for (i, slot) in out.iter_mut().enumerate() {
                let x: f64 = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(i, &self))?;
                *slot = self.one(x)?;
            }
            if seq.next_element::<de::IgnoredAny>()?.is_some() {
                return Err(de::Error::invalid_length(4, &self));
            }
            Ok(out)
        }
    }
    de.deserialize_any(V {
        what,
        allow_scalar,
        check,
    })
}

/// A point or vector: `[x, y, z]`, finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Xyz(pub [f64; 3]);
impl<'de> Deserialize<'de> for Xyz {
    fn deserialize<D: Deserializer<'de>>(de: D) -> Result<Self, D::Error> {
        triple(de, "an array of three numbers [x, y, z]", false, Ok).map(Xyz)
    }
}

/// An RGB triple `[r, g, b]` or one number for all three; each ≥ 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rgb(pub [f64; 3]);
impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(de: D) -> Result<Self, D::Error> {
        triple(
            de,
            "a colour: one number or an array [r, g, b], each ≥ 0",
            true,
            |x| {
                if x >= 0.0 {
                    Ok(x)
                } else {
                    Err("a value ≥ 0")
                }
            },
        )
        .map(Rgb)
    }
}

/// Scale factors `[sx, sy, sz]` or one number for all three; each non-zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaleFactors(pub [f64; 3]);
impl<'de> Deserialize<'de> for ScaleFactors {
    fn deserialize<D: Deserializer<'de>>(de: D) -> Result<Self, D::Error> {
        triple(
            de,
            "a scale: one number or an array [sx, sy, sz], none of them zero",
            true,
            |x| if x != 0.0 { Ok(x) } else { Err("a non-zero scale factor (a zero scale flattens the object and cannot be undone by M⁻¹)") },
        )
        .map(ScaleFactors)
    }
}

// ---------------------------------------------------------------------------------------------
// Tables

/// The whole file.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// `[camera]`.
    #[serde(default)]
    pub camera: Option<Spanned<CameraDesc>>,
    /// `[image]`.
    #[serde(default)]
    pub image: ImageDesc,
    /// `[render]`.
    #[serde(default)]
    pub render: RenderDesc,
    /// `[ambient]`.
    #[serde(default)]
    pub ambient: AmbientDesc,
    /// `[[lights]]`.
    #[serde(default)]
    pub lights: Vec<LightDesc>,
    /// `[materials.NAME]`.
    #[serde(default)]
    pub materials: BTreeMap<String, Spanned<MaterialDesc>>,
    /// `[[objects]]`.
    #[serde(default)]
    pub objects: Vec<Spanned<ObjectDesc>>,
}

fn default_eye() -> Xyz {
    Xyz([0.0, 0.0, 5.0])
}
fn default_up() -> Xyz {
    Xyz([0.0, 1.0, 0.0])
}
fn default_normal() -> Spanned<Xyz> {
    Spanned::new(0..0, default_up())
}
fn origin() -> Xyz {
    Xyz([0.0; 3])
}

/// `[camera]`: the synthetic camera of chapter 1.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraDesc {
    /// The eye e (default [0, 0, 5]).
    #[serde(default = "default_eye")]
    pub eye: Xyz,
    /// The point looked at (default the origin).
    #[serde(default = "origin")]
    pub look_at: Xyz,
    /// The up direction (default +y).
    #[serde(default = "default_up")]
    pub up: Xyz,
    /// θ in degrees (default 60).
    #[serde(default = "CameraDesc::default_fov")]
    pub fov: Fov,
    /// N (default 1).
    #[serde(default = "CameraDesc::default_near")]
    pub near: Positive,
}

impl CameraDesc {
    fn default_fov() -> Fov {
        Fov(60.0)
    }
    fn default_near() -> Positive {
        Positive(1.0)
    }
}

impl Default for CameraDesc {
    fn default() -> Self {
        Self {
            eye: default_eye(),
            look_at: origin(),
            up: default_up(),
            fov: Self::default_fov(),
            near: Self::default_near(),
        }
    }
}

/// `[image]`: size and background.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImageDesc {
    /// Columns n (default 640).
    #[serde(default = "ImageDesc::default_width")]
    pub width: Spanned<u32>,
    /// Rows m (default 480).
    #[serde(default = "ImageDesc::default_height")]
    pub height: Spanned<u32>,
    /// The colour of rays that hit nothing (default black).
    #[serde(default = "ImageDesc::default_background")]
    pub background: Rgb,
}

impl ImageDesc {
    fn default_width() -> Spanned<u32> {
        Spanned::new(0..0, 640)
    }
    fn default_height() -> Spanned<u32> {
        Spanned::new(0..0, 480)
    }
    fn default_background() -> Rgb {
        Rgb([0.0; 3])
    }
}

impl Default for ImageDesc {
    fn default() -> Self {
        Self {
            width: Self::default_width(),
            height: Self::default_height(),
            background: Self::default_background(),
        }
    }
}

/// `[render]`: recursion depth and samples per pixel.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderDesc {
    /// Maximum recursion depth of chapter 5 (default 5).
    #[serde(default = "RenderDesc::default_depth")]
    pub max_depth: Spanned<u32>,
    /// Samples per pixel (default 1).
    #[serde(default = "RenderDesc::default_samples")]
    pub samples: Spanned<u32>,
}

impl RenderDesc {
    fn default_depth() -> Spanned<u32> {
        Spanned::new(0..0, 5)
    }
    fn default_samples() -> Spanned<u32> {
        Spanned::new(0..0, 1)
    }
}

impl Default for RenderDesc {
    fn default() -> Self {
        Self {
            max_depth: Self::default_depth(),
            samples: Self::default_samples(),
        }
    }
}

/// `[ambient]`: I_m.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AmbientDesc {
    /// I_m per channel (default 1).
    #[serde(default = "AmbientDesc::default_intensity")]
    pub intensity: Rgb,
}

impl AmbientDesc {
    fn default_intensity() -> Rgb {
        Rgb([1.0; 3])
    }
}

impl Default for AmbientDesc {
    fn default() -> Self {
        Self {
            intensity: Self::default_intensity(),
        }
    }
}

/// `[[lights]]`: a point light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightDesc {
    /// L (required).
    pub position: Xyz,
    /// I_p (default 1).
    #[serde(default = "LightDesc::default_intensity")]
    pub intensity: Rgb,
    /// (a0, a1, a2), each ≥ 0, not all zero (default [1, 0, 0]).
    #[serde(default)]
    pub attenuation: Option<Spanned<[NonNegative; 3]>>,
    /// Cast feeler rays towards this light (default true).
    #[serde(default = "yes")]
    pub shadows: bool,
}

fn yes() -> bool {
    true
}

impl LightDesc {
    fn default_intensity() -> Rgb {
        Rgb([1.0; 3])
    }
}

/// `[materials.NAME]`: ρa, ρd, ρs, f, reflection, transmission, ior.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialDesc {
    /// ρa (default 0.1).
    pub ambient: Option<Rgb>,
    /// ρd (default 0.7).
    pub diffuse: Option<Rgb>,
    /// ρs (default 0.2).
    pub specular: Option<Rgb>,
    /// f (default 32).
    pub shininess: Option<Positive>,
    /// Mirror share (default 0).
    pub reflection: Option<Unit>,
    /// Transmitted share (default 0).
    pub transmission: Option<Unit>,
    /// Index of refraction (default 1.5).
    pub ior: Option<Ior>,
}

/// One placement step of a `transform` list.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum StepDesc {
    /// `{ scale = [sx, sy, sz] }` or `{ scale = s }`.
    Scale(ScaleFactors),
    /// `{ rotate_x = degrees }`.
    RotateX(Finite),
    /// `{ rotate_y = degrees }`.
    RotateY(Finite),
    /// `{ rotate_z = degrees }`.
    RotateZ(Finite),
    /// `{ rotate = { axis = [x, y, z], angle = degrees } }`.
    Rotate {
        /// The axis through the origin (non-zero).
        axis: Spanned<Xyz>,
        /// The angle in degrees.
        angle: Finite,
    },
    /// `{ translate = [x, y, z] }`.
    Translate(Xyz),
}

/// `sphere = { center, radius }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereDesc {
    /// Centre (default origin).
    #[serde(default = "origin")]
    pub center: Xyz,
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: Positive,
}

fn one() -> Positive {
    Positive(1.0)
}

/// `plane = { point, normal }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneDesc {
    /// A point of the plane (default origin).
    #[serde(default = "origin")]
    pub point: Xyz,
    /// Its normal, the side it faces (default +y).
    #[serde(default = "default_normal")]
    pub normal: Spanned<Xyz>,
}

/// `cylinder = { base, top, radius }` and `cone = { base, apex, radius }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxialDesc {
    /// Centre of the base disc.
    pub base: Xyz,
    /// Centre of the top disc (cylinder).
    pub top: Option<Xyz>,
    /// The apex (cone).
    pub apex: Option<Xyz>,
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: Positive,
}

/// `box = { min, max }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxDesc {
    /// The lower corner.
    pub min: Xyz,
    /// The upper corner.
    pub max: Xyz,
}

/// `polyhedron = { preset = "…" }` or `polyhedron = { facets = [[nx, ny, nz, d], …] }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolyhedronDesc {
    /// `cube`, `tetrahedron` or `octahedron`.
    pub preset: Option<Spanned<String>>,
    /// Facets n·P = d as [nx, ny, nz, d], n pointing out.
    pub facets: Option<Spanned<Vec<Spanned<[Finite; 4]>>>>,
}

/// `[[objects]]`: one object, by placement (`sphere = {…}` …) or generic (`shape = "…"`),
/// optionally followed by `transform` steps.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectDesc {
    /// A sphere by centre and radius.
    pub sphere: Option<SphereDesc>,
    /// A plane by point and normal.
    pub plane: Option<PlaneDesc>,
    /// A cylinder by base, top and radius.
    pub cylinder: Option<Spanned<AxialDesc>>,
    /// A cone by base, apex and radius.
    pub cone: Option<Spanned<AxialDesc>>,
    /// An axis-aligned box.
    #[serde(rename = "box")]
    pub box_: Option<Spanned<BoxDesc>>,
    /// A convex polyhedron.
    pub polyhedron: Option<Spanned<PolyhedronDesc>>,
    /// A generic shape: sphere, plane, cylinder, cone, cube, tetrahedron, octahedron.
    pub shape: Option<Spanned<String>>,
    /// Placement steps, applied in order (after the placement form, if any).
    #[serde(default)]
    pub transform: Vec<Spanned<StepDesc>>,
    /// Name of a `[materials.NAME]` table (default: a matte grey).
    pub material: Option<Spanned<String>>,
    /// A label for the object: the inspector (`--inspect X,Y`) and the live window name the
    /// object by it; the image does not depend on it.
    pub name: Option<String>,
}
