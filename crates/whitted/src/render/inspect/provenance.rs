//! Where each number of the ray tree comes from: for every quantity the tree holds, what the
//! notes call it, how near another computation of it must come to count as the same, and the
//! functions of the road that computed it, spelled as `chapters/formulas.toml` spells them
//! (`shapes::cone::coefficients`). This table is the one place that knows it;
//! [`super::against`] reads it to say which exercise computed the first number that differs
//! from the reference's. A test (`tests/trees.rs`) checks that every path here is a function of
//! the manifest and that every exercise of the manifest computes some quantity of the tree.
//!
//! A quantity lists every function whose result it depends on directly, not only the last
//! one: a hit's t is the shape's roots of the ray carried by M⁻¹, so a wrong t may come from
//! the ray's transform as well as from the quadratic. `cargo learn` narrows the list to the
//! exercises whose own tests fail.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

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

/// The functions of chapter 1 that make a camera ray.
const CAMERA: &[&str] = &[
    "camera::viewing_basis",
    "camera::near_plane_half_height",
    "camera::near_plane_half_width",
    "camera::pixel_on_near_plane",
    "camera::Camera::direction",
    "camera::Camera::pixel_ray",
];

/// The functions that place an object: M from the steps, M⁻¹ from their inverses.
const PLACEMENT: &[&str] = &[
    "transform::Step::matrix",
    "transform::Step::inverse",
    "transform::Placement::from_steps",
];

/// The functions every ray–object test goes through: the ray carried into object space, and
/// the visible hit among the shape's.
const PLACED: &[&str] = &[
    "ray::Ray::transformed",
    "shapes::Shape::intersect_placed",
    "shapes::Hits::first_after",
];

/// The roots of a quadratic (the robust and the notes' forms).
const QUADRATIC: &[&str] = &[
    "shapes::quadratic::stable_roots",
    "shapes::quadratic::solve_with_discriminant",
];

/// The functions that intersect the generic shape named `shape` (as the tree names it).
fn intersect(shape: &str) -> Vec<&'static str> {
    let own: &[&str] = match shape {
        "sphere" => &[
            "shapes::sphere::coefficients",
            "shapes::sphere::discriminant",
            "shapes::sphere::intersect",
        ],
        "plane" => &["shapes::plane::intersect"],
        "cylinder" => &[
            "shapes::cylinder::coefficients",
            "shapes::cylinder::discriminant",
            "shapes::cylinder::intersect",
        ],
        "cone" => &[
            "shapes::cone::coefficients",
            "shapes::cone::discriminant",
            "shapes::cone::intersect",
        ],
        "polyhedron" => &[
            "shapes::polyhedron::facet_t",
            "shapes::Polyhedron::intersect",
        ],
        _ => &[],
    };
    let quadratic = matches!(shape, "sphere" | "cylinder" | "cone");
    let mut out: Vec<&'static str> = own.to_vec();
    if quadratic {
        out.extend(QUADRATIC);
    }
    out.extend(PLACED);
    out.extend(PLACEMENT);
    out
}

/// The function that gives the generic shape's normal (the plane's and a polyhedron's come
/// with the hit).
fn shape_normal(shape: &str) -> &'static str {
    match shape {
        "sphere" => "shapes::sphere::normal",
        "cylinder" => "shapes::cylinder::normal",
        "cone" => "shapes::cone::normal",
        "plane" => "shapes::plane::intersect",
        _ => "shapes::Polyhedron::intersect",
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
    #[must_use]
    pub fn computed_by(self, place: &Place) -> Vec<&'static str> {
        const TRACER: &str = "render::tracer::Tracer::reflect_and_refract";
        const LOCAL: &str = "render::tracer::Tracer::local_light";
        const FEELER: &str = "render::tracer::Tracer::feeler";
        let shapes = || {
            let mut out = Vec::new();
            for s in place.shapes {
                for f in intersect(s) {
                    if !out.contains(&f) {
                        out.push(f);
                    }
                }
            }
            out
        };
        match self {
            Quantity::Samples | Quantity::SamplePosition => Vec::new(),
            Quantity::Origin | Quantity::Direction if place.ray == RayKind::Camera => {
                CAMERA.to_vec()
            }
            Quantity::Direction if place.ray == RayKind::Mirror => vec!["optics::reflect", TRACER],
            Quantity::Direction => vec!["optics::refract", "optics::indices", TRACER],
            Quantity::Origin
            | Quantity::TMin
            | Quantity::Depth
            | Quantity::Weight
            | Quantity::K => {
                vec![TRACER]
            }
            Quantity::Colour => match (place.chapter, place.view) {
                (Chapter::CameraRays, _) => vec!["camera::direction_colour"],
                (Chapter::GenericObjects, _) | (_, View::Flat) => Vec::new(),
                (Chapter::ReflectionRefraction, View::Color) => vec![TRACER, LOCAL],
                (_, View::Color) => vec![LOCAL],
                _ => Vec::new(), // the other views' colours are the views' scales
            },
            Quantity::Object => {
                let mut out = vec!["shapes::nearer"];
                out.extend(shapes());
                out
            }
            Quantity::Part | Quantity::T | Quantity::Entering => shapes(),
            Quantity::Point => vec!["ray::Ray::at"],
            Quantity::Normal => {
                let mut out = Vec::new();
                for s in place.shapes {
                    out.push(shape_normal(s));
                }
                out.push("transform::Placement::normal_to_world");
                out.extend(PLACEMENT);
                out
            }
            Quantity::Ambient => vec!["shading::ambient"],
            Quantity::Lights | Quantity::Arriving | Quantity::Local => vec![LOCAL],
            Quantity::Attenuation | Quantity::Intensity => {
                vec!["light::Light::attenuation_at", "shading::phong"]
            }
            Quantity::Diffuse => vec!["shading::lambert", "shading::phong"],
            Quantity::Specular => vec!["shading::highlight", "shading::mirror", "shading::phong"],
            Quantity::Unshadowed => vec!["shading::phong"],
            Quantity::Feeler => vec![FEELER, LOCAL],
            Quantity::Start => vec![FEELER, "shadow::feeler"],
            Quantity::UMin => vec![FEELER],
            Quantity::Crossed | Quantity::U => {
                let mut out = vec!["shadow::between", "shadow::feeler", FEELER];
                out.extend(shapes());
                out
            }
            Quantity::Share => vec!["shadow::transmittance"],
            Quantity::Branches => vec![
                TRACER,
                "optics::refract",
                "optics::critical_angle_sine",
                "optics::indices",
            ],
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
