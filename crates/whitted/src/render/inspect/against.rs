//! Two ray trees of one pixel side by side: the first number where one computation parts from
//! another (`--against TREES.json`, and `cargo learn`).
//!
//! The reference's trees at a few pixels of each chapter scene ship with a handout as data
//! (`chapters/chNN_name/trees.json`, written by `whitted trees`: a [`TreeFile`]). A chapter
//! binary given `--against` traces the same pixels with the student's code and the settings
//! the file records ([`Settings`]), and [`first_difference`] walks each pair of trees in the
//! road's order — the camera ray, what it hits, the hit's t, P and n, the ambient term, each
//! light's factors, its feeler and what it crosses, the share, the local light, the branches
//! and, recursively, what they bring back — and stops at the first quantity that differs
//! beyond its [`Tolerance`](super::provenance::Tolerance), or where the trees' shapes part (another object hit, a branch
//! traced where the reference stops). The [`Difference`] names the pixel, the path to the
//! node, the quantity in the notes' symbols, both values, and the functions that computed it
//! ([`super::provenance`]).
//!
//! The comparison reads the trees' JSON (`docs/src/inspect.md`), the student's made by
//! [`super::RayTree::to_json`] like the reference's, so that both sides are read alike and a
//! file written by an f64 build is read by an f32 one.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::path::Path;

use serde_json::{Value, json};

use super::super::recorder::RayKind;
use super::super::tracer::{EveryObject, Tracer};
use super::super::{Chapter, Options, View};
use super::provenance::{Place, Quantity, number};
use crate::error::Error;
use crate::offset::{Offset, OffsetKind};
use crate::real::Real;
use crate::scene::Scene;
use crate::shapes::Numerics;

/// The version of the trees file's shape ([`TreeFile`]).
pub const FILE_VERSION: u64 = 1;

/// What a tree depends on besides the scene and the code: the options `whitted trees` traced
/// the reference's trees with, which `--against` traces the student's with.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// The chapter whose road is followed.
    pub chapter: Chapter,
    /// The view.
    pub view: View,
    /// The image's width and height.
    pub size: (u32, u32),
    /// Samples per pixel.
    pub samples: u32,
    /// The maximum recursion depth.
    pub max_depth: u32,
    /// The smallest weight a branch may carry.
    pub min_weight: Real,
    /// Which intersection formulas.
    pub numerics: Numerics,
    /// How secondary rays leave a surface.
    pub offset: OffsetKind,
    /// The seed of the sample positions.
    pub seed: u64,
}

impl Settings {
    /// The settings of a render with `options`.
    #[must_use]
    pub fn of(options: &Options) -> Self {
        let offset = OffsetKind::ALL
            .into_iter()
            .find(|k| k.offset() == options.offset)
            .unwrap_or(match options.offset {
                Offset::Fixed(_) => OffsetKind::Fixed,
                Offset::Scaled(_) => OffsetKind::Scaled,
                Offset::ErrorBound => OffsetKind::ErrorBound,
            });
        Self {
            chapter: options.chapter,
            view: options.view,
            size: (options.width, options.height),
            samples: options.samples,
            max_depth: options.max_depth,
            min_weight: options.min_weight,
            numerics: options.numerics,
            offset,
            seed: options.seed,
        }
    }

    /// `options` with these settings.
    #[must_use]
    pub fn apply(&self, options: &Options) -> Options {
        Options {
            chapter: self.chapter,
            view: self.view,
            width: self.size.0,
            height: self.size.1,
            samples: self.samples,
            max_depth: self.max_depth,
            min_weight: self.min_weight,
            numerics: self.numerics,
            offset: self.offset.offset(),
            seed: self.seed,
            ..options.clone()
        }
    }

    /// As JSON: `{ "chapter": 4, "view": "color", "width": 240, … }` (`docs/src/inspect.md`).
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "chapter": self.chapter.number(),
            "view": self.view.name(),
            "width": self.size.0,
            "height": self.size.1,
            "samples": self.samples,
            "max_depth": self.max_depth,
            "min_weight": self.min_weight,
            "numerics": self.numerics.name(),
            "offset": self.offset.name(),
            "seed": self.seed,
        })
    }

    /// Reads what [`Settings::to_json`] writes; the error says which key is wrong.
    pub fn from_json(v: &Value) -> Result<Self, String> {
        let int = |key: &str| -> Result<u64, String> {
            v.get(key)
                .and_then(Value::as_u64)
                .ok_or_else(|| format!("`{key}` must be a whole number"))
        };
        let small = |key: &str| -> Result<u32, String> {
            u32::try_from(int(key)?).map_err(|_| format!("`{key}` is too large"))
        };
        let name = |key: &str| -> Result<&str, String> {
            v.get(key)
                .and_then(Value::as_str)
                .ok_or_else(|| format!("`{key}` must be a name"))
        };
        let pick = |key: &str, names: &[&str]| -> Result<usize, String> {
            let given = name(key)?;
            names
                .iter()
                .position(|n| *n == given)
                .ok_or_else(|| format!("`{key}`: `{given}` is none of {}", names.join(", ")))
        };
        let chapter = u8::try_from(int("chapter")?)
            .ok()
            .and_then(Chapter::from_number)
            .ok_or("`chapter` must be 1 to 5")?;
        let views: Vec<&str> = View::ALL.iter().map(|v| v.name()).collect();
        let numerics: Vec<&str> = Numerics::ALL.iter().map(|n| n.name()).collect();
        let offsets: Vec<&str> = OffsetKind::ALL.iter().map(|o| o.name()).collect();
        Ok(Self {
            chapter,
            view: View::ALL[pick("view", &views)?],
            size: (small("width")?, small("height")?),
            samples: small("samples")?,
            max_depth: small("max_depth")?,
            min_weight: v
                .get("min_weight")
                .and_then(Value::as_f64)
                .ok_or("`min_weight` must be a number")? as Real,
            numerics: Numerics::ALL[pick("numerics", &numerics)?],
            offset: OffsetKind::ALL[pick("offset", &offsets)?],
            seed: int("seed")?,
        })
    }
}

/// A trees file (`chapters/chNN_name/trees.json`, version [`FILE_VERSION`]): the settings, and
/// the reference's tree at each pixel kept, in the order they are compared.
///
/// ```text
/// { "version": 1, "about": "…", "settings": { … },
///   "pixels": [ { "pixel": [x, y], "covers": ["…"], "tree": { …the tree's JSON… } } … ] }
/// ```
#[derive(Clone, Debug)]
pub struct TreeFile {
    /// What the trees were traced with.
    pub settings: Settings,
    /// Each pixel's tree, as `--inspect X,Y --json` writes it.
    pub trees: Vec<Value>,
}

impl TreeFile {
    /// Reads a trees file; the error names the file.
    pub fn read(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(&text).map_err(|why| Error::Usage(format!("{}: {why}", path.display())))
    }

    /// Reads the text of a trees file.
    pub fn parse(text: &str) -> Result<Self, String> {
        let v: Value = serde_json::from_str(text).map_err(|e| format!("not JSON: {e}"))?;
        match v.get("version").and_then(Value::as_u64) {
            Some(FILE_VERSION) => {}
            other => {
                return Err(format!(
                    "a trees file of version {FILE_VERSION} is expected, this one says {}",
                    other.map_or("none".to_string(), |n| n.to_string())
                ));
            }
        }
        let settings = Settings::from_json(v.get("settings").unwrap_or(&Value::Null))
            .map_err(|why| format!("settings: {why}"))?;
        let pixels = v
            .get("pixels")
            .and_then(Value::as_array)
            .ok_or("`pixels` must be a list")?;
        let mut trees = Vec::with_capacity(pixels.len());
        for (i, p) in pixels.iter().enumerate() {
            let tree = p
                .get("tree")
                .filter(|t| pixel_of(t).is_some())
                .ok_or_else(|| format!("pixels[{i}] has no tree with its pixel"))?;
            let (x, y) = pixel_of(tree).unwrap_or_default();
            if x >= settings.size.0 || y >= settings.size.1 {
                return Err(format!("pixels[{i}]: ({x}, {y}) is outside the image"));
            }
            trees.push(tree.clone());
        }
        Ok(Self { settings, trees })
    }

    /// Traces each pixel of the file with `scene` and the file's settings (over `options`),
    /// and compares the tree with the reference's: each pixel with its first difference, if
    /// any. The chapter followed is the file's, which must not come after `options`'.
    pub fn against(&self, scene: &Scene, options: &Options) -> Result<Vec<Compared>, Error> {
        if self.settings.chapter > options.chapter {
            return Err(Error::Usage(format!(
                "--against: the trees are chapter {}'s, which `{}` does not trace: run `{}`",
                self.settings.chapter.number(),
                options.chapter.about().binary,
                self.settings.chapter.about().binary
            )));
        }
        let options = self.settings.apply(options);
        let every = EveryObject {
            scene,
            numerics: options.numerics,
        };
        let tracer = Tracer::with_query(scene, &options, every);
        let shape_of = |i: usize| scene.objects.get(i).map(|o| o.shape.name());
        Ok(self
            .trees
            .iter()
            .map(|reference| {
                let (x, y) = pixel_of(reference).unwrap_or_default();
                let mine = tracer.inspect(x, y).to_json();
                Compared {
                    pixel: (x, y),
                    difference: first_difference(&mine, reference, &shape_of),
                }
            })
            .collect())
    }
}

/// One pixel of a trees file, traced and compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Compared {
    /// The pixel (x, y), row y from the top.
    pub pixel: (u32, u32),
    /// Where its tree first parts from the reference's; `None` when they agree.
    pub difference: Option<Difference>,
}

/// The pixel a tree's JSON names.
fn pixel_of(tree: &Value) -> Option<(u32, u32)> {
    let p = tree.get("pixel")?.as_array()?;
    let coordinate = |i: usize| p.get(i)?.as_u64().and_then(|c| u32::try_from(c).ok());
    Some((coordinate(0)?, coordinate(1)?))
}

/// One step of the path from a pixel to a node of its tree.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Step {
    /// The kind of node: `sample`, `camera ray`, `mirror ray`, `transmitted ray`, `hit`,
    /// `light`, `feeler`, `crossing`.
    pub kind: &'static str,
    /// How the path shows it: "hit `cone`", "light 1".
    pub label: String,
}

/// Where a tree first parts from the reference's.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// The path from the pixel to the node that holds the quantity.
    pub path: Vec<Step>,
    /// The quantity.
    pub quantity: Quantity,
    /// How the notes write it.
    pub symbol: &'static str,
    /// Its value in the tree compared, as shown.
    pub computed: String,
    /// The reference's value, as shown.
    pub reference: String,
    /// The functions of the road that computed it (manifest paths; [`Quantity::computed_by`]).
    pub functions: Vec<&'static str>,
}

impl Difference {
    /// The path as a reader follows it: "camera ray → hit `cone` → light 1".
    #[must_use]
    pub fn path_text(&self) -> String {
        self.path
            .iter()
            .map(|s| s.label.as_str())
            .collect::<Vec<_>>()
            .join(" → ")
    }

    /// "camera ray → hit `cone`: t: 4.02 (the reference: 3.87)".
    #[must_use]
    pub fn text(&self) -> String {
        format!(
            "{}: {}: {} (the reference: {})",
            self.path_text(),
            self.symbol,
            self.computed,
            self.reference
        )
    }
}

impl Compared {
    /// The line `--against` prints for the pixel.
    #[must_use]
    pub fn line(&self) -> String {
        let (x, y) = self.pixel;
        match &self.difference {
            None => format!("against: pixel ({x}, {y}): the reference's tree"),
            Some(d) => {
                let by = if d.functions.is_empty() {
                    String::new()
                } else {
                    format!("; computed by {}", d.functions.join(", "))
                };
                format!("against: pixel ({x}, {y}), {}{by}", d.text())
            }
        }
    }

    /// The same as JSON (`docs/src/inspect.md`): `{ "pixel": [x, y], "differs": false }`, or
    /// with `"differs": true` the path (`path`, and its node kinds `nodes`), the quantity (its
    /// key and symbol), both values as shown, the functions and the line of text.
    #[must_use]
    pub fn to_json(&self) -> Value {
        let (x, y) = self.pixel;
        match &self.difference {
            None => json!({ "pixel": [x, y], "differs": false }),
            Some(d) => json!({
                "pixel": [x, y],
                "differs": true,
                "path": d.path.iter().map(|s| s.label.clone()).collect::<Vec<_>>(),
                "nodes": d.path.iter().map(|s| s.kind).collect::<Vec<_>>(),
                "quantity": d.quantity.key(),
                "symbol": d.symbol,
                "computed": d.computed,
                "reference": d.reference,
                "functions": d.functions,
                "text": format!("pixel ({x}, {y}), {}", d.text()),
            }),
        }
    }
}

/// The first quantity where the tree `mine` parts from `reference` (both as
/// [`super::RayTree::to_json`] writes them), walking them in the road's order; `shape_of`
/// names the generic shape of an object by its index. `None` when every quantity agrees
/// within its tolerance.
#[must_use]
pub fn first_difference(
    mine: &Value,
    reference: &Value,
    shape_of: &dyn Fn(usize) -> Option<&'static str>,
) -> Option<Difference> {
    let chapter = reference
        .get("chapter")
        .and_then(Value::as_u64)
        .and_then(|c| u8::try_from(c).ok())
        .and_then(Chapter::from_number)
        .unwrap_or(Chapter::ReflectionRefraction);
    let view_name = reference.get("view").and_then(Value::as_str);
    let view = View::ALL
        .into_iter()
        .find(|v| Some(v.name()) == view_name)
        .unwrap_or_default();
    let mut walk = Walk {
        chapter,
        view,
        shape_of,
        path: Vec::new(),
    };
    walk.tree(mine, reference).err()
}

/// The walk of two trees: where it is, and what it needs to know to name a quantity's
/// functions.
struct Walk<'a> {
    chapter: Chapter,
    view: View,
    shape_of: &'a dyn Fn(usize) -> Option<&'static str>,
    path: Vec<Step>,
}

/// The walk goes on while the trees agree; the first difference stops it.
type Agree = Result<(), Difference>;

/// `v[key]`, or null.
fn at<'v>(v: &'v Value, key: &str) -> &'v Value {
    v.get(key).unwrap_or(&Value::Null)
}

/// The numbers of a JSON number or array of numbers (null, for a value that is not finite,
/// as NaN).
fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(items) => items.iter().flat_map(numbers).collect(),
        Value::Number(n) => vec![n.as_f64().unwrap_or(f64::NAN)],
        Value::Null => vec![f64::NAN],
        _ => Vec::new(),
    }
}

/// A number or a vector as the comparison shows it.
fn shown(v: &Value) -> String {
    let xs = numbers(v);
    let one = |x: f64| {
        if x.is_nan() {
            "none".to_string()
        } else {
            number(x)
        }
    };
    match (v, xs.as_slice()) {
        (Value::Array(_), _) => format!(
            "({})",
            xs.iter().map(|x| one(*x)).collect::<Vec<_>>().join(", ")
        ),
        (_, [x]) => one(*x),
        _ => v.to_string(),
    }
}

impl Walk<'_> {
    fn place<'s>(&self, ray: RayKind, shapes: &'s [&'s str]) -> Place<'s> {
        Place {
            chapter: self.chapter,
            view: self.view,
            ray,
            shapes,
        }
    }

    /// The difference in `quantity`, at the current path, on a ray of `ray`'s kind.
    fn differs(
        &self,
        quantity: Quantity,
        ray: RayKind,
        shapes: &[&str],
        computed: String,
        reference: String,
    ) -> Difference {
        Difference {
            path: self.path.clone(),
            quantity,
            symbol: quantity.symbol(ray),
            computed,
            reference,
            functions: quantity.computed_by(&self.place(ray, shapes)),
        }
    }

    /// Compares the number or vector under `key` of two nodes as `quantity`.
    fn value(
        &self,
        quantity: Quantity,
        ray: RayKind,
        shapes: &[&str],
        (mine, reference): (&Value, &Value),
        key: &str,
    ) -> Agree {
        let (a, b) = (at(mine, key), at(reference, key));
        let (xs, ys) = (numbers(a), numbers(b));
        // null stands for a number that is not finite: the same only as null
        let known = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .map(|x| if x.is_nan() { 0.0 } else { *x })
                .collect()
        };
        let same = xs.len() == ys.len()
            && xs.iter().zip(&ys).all(|(x, y)| x.is_nan() == y.is_nan())
            && quantity.tolerance().same_vectors(&known(&xs), &known(&ys));
        if same {
            Ok(())
        } else {
            Err(self.differs(quantity, ray, shapes, shown(a), shown(b)))
        }
    }

    /// The items of the lists under `key` of two nodes, side by side; lists of other lengths
    /// differ as `quantity`, by their counts.
    fn pairs<'v>(
        &self,
        quantity: Quantity,
        (ray, shapes): (RayKind, &[&str]),
        mine: &'v Value,
        reference: &'v Value,
        key: &str,
    ) -> Result<Vec<(&'v Value, &'v Value)>, Difference> {
        let list = |v: &'v Value| at(v, key).as_array().map_or(&[][..], Vec::as_slice);
        let (ms, rs) = (list(mine), list(reference));
        if ms.len() != rs.len() {
            return Err(self.differs(
                quantity,
                ray,
                shapes,
                ms.len().to_string(),
                rs.len().to_string(),
            ));
        }
        Ok(ms.iter().zip(rs).collect())
    }

    fn tree(&mut self, mine: &Value, reference: &Value) -> Agree {
        let samples = self.pairs(
            Quantity::Samples,
            (RayKind::Camera, &[]),
            mine,
            reference,
            "samples",
        )?;
        let several = samples.len() > 1;
        for (i, (m, r)) in samples.into_iter().enumerate() {
            let depth = self.path.len();
            if several {
                self.path.push(Step {
                    kind: "sample",
                    label: format!("sample {i}"),
                });
            }
            self.value(
                Quantity::SamplePosition,
                RayKind::Camera,
                &[],
                (m, r),
                "position",
            )?;
            self.ray(RayKind::Camera, at(m, "ray"), at(r, "ray"))?;
            self.path.truncate(depth);
        }
        Ok(())
    }

    fn ray(&mut self, kind: RayKind, mine: &Value, reference: &Value) -> Agree {
        let depth = self.path.len();
        self.path.push(Step {
            kind: match kind {
                RayKind::Camera => "camera ray",
                RayKind::Mirror => "mirror ray",
                RayKind::Transmitted => "transmitted ray",
            },
            label: format!("{} ray", kind.name()),
        });
        let pair = (mine, reference);
        self.value(Quantity::Origin, kind, &[], pair, "origin")?;
        self.value(Quantity::Direction, kind, &[], pair, "direction")?;
        if kind != RayKind::Camera {
            self.value(Quantity::TMin, kind, &[], pair, "t_min")?;
            self.value(Quantity::Depth, kind, &[], pair, "depth")?;
            self.value(Quantity::K, kind, &[], pair, "k")?;
            self.value(Quantity::Weight, kind, &[], pair, "weight")?;
        }
        let (mh, rh) = (at(mine, "hit"), at(reference, "hit"));
        let object = |h: &Value| h.get("object").and_then(Value::as_u64);
        let (mo, ro) = (object(mh), object(rh));
        if mo != ro {
            let shapes: Vec<&str> = [mo, ro]
                .into_iter()
                .flatten()
                .filter_map(|o| (self.shape_of)(o as usize))
                .collect();
            return Err(self.differs(
                Quantity::Object,
                kind,
                &shapes,
                object_label(mh),
                object_label(rh),
            ));
        }
        if ro.is_some() {
            self.path.push(Step {
                kind: "hit",
                label: format!("hit {}", object_label(rh)),
            });
            self.hit(kind, mh, rh)?;
            self.path.pop();
        }
        self.value(Quantity::Colour, kind, &[], pair, "colour")?;
        self.path.truncate(depth);
        Ok(())
    }

    fn hit(&mut self, kind: RayKind, mine: &Value, reference: &Value) -> Agree {
        let shape = at(reference, "object")
            .as_u64()
            .and_then(|o| (self.shape_of)(o as usize));
        let shapes: Vec<&str> = shape.into_iter().collect();
        let pair = (mine, reference);
        let exact = |key: &str, q: Quantity, show: &dyn Fn(&Value) -> String| {
            let (a, b) = (at(mine, key), at(reference, key));
            if a == b {
                Ok(())
            } else {
                Err(self.differs(q, kind, &shapes, show(a), show(b)))
            }
        };
        exact("part", Quantity::Part, &|v| {
            v.as_str().unwrap_or("none").to_string()
        })?;
        self.value(Quantity::T, kind, &shapes, pair, "t")?;
        exact("entering", Quantity::Entering, &|v| {
            if v.as_bool() == Some(true) {
                "entering".into()
            } else {
                "leaving".into()
            }
        })?;
        self.value(Quantity::Point, kind, &shapes, pair, "point")?;
        self.value(Quantity::Normal, kind, &shapes, pair, "normal")?;
        self.value(Quantity::Ambient, kind, &shapes, pair, "ambient")?;
        for (m, r) in self.pairs(Quantity::Lights, (kind, &shapes), mine, reference, "lights")? {
            self.path.push(Step {
                kind: "light",
                label: format!("light {}", at(r, "index")),
            });
            self.light(kind, m, r)?;
            self.path.pop();
        }
        self.value(Quantity::Local, kind, &shapes, pair, "local")?;
        self.branches(kind, mine, reference)
    }

    fn light(&mut self, kind: RayKind, mine: &Value, reference: &Value) -> Agree {
        let pair = (mine, reference);
        for (q, key) in [
            (Quantity::Attenuation, "attenuation"),
            (Quantity::Intensity, "intensity"),
            (Quantity::Diffuse, "diffuse"),
            (Quantity::Specular, "specular"),
            (Quantity::Unshadowed, "unshadowed"),
        ] {
            self.value(q, kind, &[], pair, key)?;
        }
        let (mf, rf) = (at(mine, "feeler"), at(reference, "feeler"));
        let sent = |f: &Value| if f.is_null() { "none" } else { "sent" }.to_string();
        if mf.is_null() != rf.is_null() {
            return Err(self.differs(Quantity::Feeler, kind, &[], sent(mf), sent(rf)));
        }
        if !rf.is_null() {
            self.path.push(Step {
                kind: "feeler",
                label: "feeler".into(),
            });
            self.feeler(kind, mf, rf)?;
            self.path.pop();
        }
        self.value(Quantity::Share, kind, &[], pair, "share")?;
        self.value(Quantity::Arriving, kind, &[], pair, "arriving")
    }

    fn feeler(&mut self, kind: RayKind, mine: &Value, reference: &Value) -> Agree {
        let pair = (mine, reference);
        self.value(Quantity::Start, kind, &[], pair, "origin")?;
        self.value(Quantity::UMin, kind, &[], pair, "u_min")?;
        let empty = Vec::new();
        let (mc, rc) = (
            at(mine, "crossings").as_array().unwrap_or(&empty),
            at(reference, "crossings").as_array().unwrap_or(&empty),
        );
        let objects = |c: &[Value]| -> Vec<u64> {
            c.iter().filter_map(|x| x.get("object")?.as_u64()).collect()
        };
        let (mo, ro) = (objects(mc), objects(rc));
        if mo != ro {
            let shapes: Vec<&str> = mo
                .iter()
                .filter(|o| !ro.contains(o))
                .chain(ro.iter().filter(|o| !mo.contains(o)))
                .filter_map(|&o| (self.shape_of)(o as usize))
                .collect();
            let names = |c: &[Value]| {
                if c.is_empty() {
                    "nothing".to_string()
                } else {
                    c.iter().map(object_label).collect::<Vec<_>>().join(", ")
                }
            };
            return Err(self.differs(Quantity::Crossed, kind, &shapes, names(mc), names(rc)));
        }
        for (m, r) in mc.iter().zip(rc) {
            self.path.push(Step {
                kind: "crossing",
                label: format!("crosses {}", object_label(r)),
            });
            let shapes: Vec<&str> = at(r, "object")
                .as_u64()
                .and_then(|o| (self.shape_of)(o as usize))
                .into_iter()
                .collect();
            self.value(Quantity::U, kind, &shapes, (m, r), "u")?;
            self.path.pop();
        }
        Ok(())
    }

    /// The branches leaving a hit: which are traced and which stopped (and why) first, then
    /// each traced one, recursively.
    fn branches(&mut self, kind: RayKind, mine: &Value, reference: &Value) -> Agree {
        for branch in [RayKind::Transmitted, RayKind::Mirror] {
            let (m, r) = (fate(mine, branch), fate(reference, branch));
            if m.word() != r.word() {
                let say = |f: &Fate| match f {
                    Fate::None => "none".to_string(),
                    Fate::Traced(_) => "traced".to_string(),
                    Fate::Stopped(why) => format!("not traced: {}", why.replace('_', " ")),
                };
                return Err(Difference {
                    symbol: match branch {
                        RayKind::Mirror => "its mirror ray",
                        _ => "its transmitted ray",
                    },
                    ..self.differs(Quantity::Branches, kind, &[], say(&m), say(&r))
                });
            }
        }
        for branch in [RayKind::Transmitted, RayKind::Mirror] {
            if let (Fate::Traced(m), Fate::Traced(r)) =
                (fate(mine, branch), fate(reference, branch))
            {
                self.ray(branch, m, r)?;
            }
        }
        Ok(())
    }
}

/// What became of a hit's branch of one kind.
#[derive(Debug)]
enum Fate<'v> {
    /// The material asks for none.
    None,
    /// Traced: its ray.
    Traced(&'v Value),
    /// Not traced, and why (the tree's word).
    Stopped(String),
}

impl Fate<'_> {
    /// What became of it, without the ray traced: the comparison of two trees' branches.
    fn word(&self) -> &str {
        match self {
            Fate::None => "none",
            Fate::Traced(_) => "traced",
            Fate::Stopped(why) => why,
        }
    }
}

fn fate<'v>(hit: &'v Value, kind: RayKind) -> Fate<'v> {
    let of_kind = |v: &&Value| v.get("kind").and_then(Value::as_str) == Some(kind.name());
    if let Some(ray) = at(hit, "branches")
        .as_array()
        .and_then(|b| b.iter().find(of_kind))
    {
        return Fate::Traced(ray);
    }
    match at(hit, "stopped")
        .as_array()
        .and_then(|s| s.iter().find(of_kind))
    {
        Some(s) => Fate::Stopped(at(s, "why").as_str().unwrap_or("?").to_string()),
        None => Fate::None,
    }
}

/// "`name`" (or "object i") for a hit or a crossing, "nothing" for no hit.
fn object_label(v: &Value) -> String {
    match (
        v.get("name").and_then(Value::as_str),
        v.get("object").and_then(Value::as_u64),
    ) {
        (Some(name), _) => format!("`{name}`"),
        (None, Some(i)) => format!("object {i}"),
        (None, None) => "nothing".into(),
    }
}
