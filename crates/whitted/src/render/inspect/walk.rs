//! Two ray trees of one pixel walked side by side, in the road's order, to the first quantity
//! where they part ([`first_difference`]).
//!
//! The walk goes the way the road went: the camera ray, what it hits, the hit's t, P and n,
//! the ambient term, each light's factors, its feeler and what it crosses, the share, the
//! local light, the branches and, recursively, what they bring back. It stops at the first
//! quantity that differs beyond its [`Tolerance`](super::provenance::Tolerance), or where the
//! trees' shapes part (another object hit, a branch traced where the reference stops).
//!
//! Both trees are read as [`Plain`] types — the student's tree through its JSON like the
//! reference's file — so that both sides are read alike, and a file written by an f64 build
//! compares with a tree of an f32 one.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use whitted_syllabus::tree::{Crossing, FeelerNode, HitNode, LightNode, Number, Plain, RayNode};

use super::super::recorder::RayKind;
use super::super::{Chapter, View};
use super::difference::{Difference, Step};
use super::provenance::{Place, Quantity, number};

/// A ray tree as the walk reads it.
pub type PlainTree = whitted_syllabus::tree::RayTree<Plain>;

/// The first quantity where the tree `mine` parts from `reference`, walking them in the
/// road's order; `shape_of` names the generic shape of an object by its index. `None` when
/// every quantity agrees within its tolerance.
#[must_use]
pub fn first_difference(
    mine: &PlainTree,
    reference: &PlainTree,
    shape_of: &dyn Fn(usize) -> Option<&'static str>,
) -> Option<Difference> {
    let chapter = Chapter::from_number(reference.chapter).unwrap_or(Chapter::ReflectionRefraction);
    let view = View::ALL
        .into_iter()
        .find(|v| v.name() == reference.view)
        .unwrap_or_default();
    let mut walk = Walk {
        chapter,
        view,
        shape_of,
        path: Vec::new(),
    };
    walk.tree(mine, reference).err()
}

/// A quantity of a tree as the comparison reads it: its numbers (NaN for one that is not
/// finite, or absent), and whether it shows as a list.
trait Numbers {
    /// Its numbers.
    fn numbers(&self) -> Vec<f64>;
    /// Whether it shows in brackets, `(x, y, z)`, rather than as one number.
    fn listed(&self) -> bool;
}

impl Numbers for Number {
    fn numbers(&self) -> Vec<f64> {
        vec![self.0]
    }
    fn listed(&self) -> bool {
        false
    }
}

impl Numbers for u32 {
    fn numbers(&self) -> Vec<f64> {
        vec![f64::from(*self)]
    }
    fn listed(&self) -> bool {
        false
    }
}

impl Numbers for [Number; 3] {
    fn numbers(&self) -> Vec<f64> {
        self.iter().map(|x| x.0).collect()
    }
    fn listed(&self) -> bool {
        true
    }
}

impl Numbers for (Number, Number) {
    fn numbers(&self) -> Vec<f64> {
        vec![self.0.0, self.1.0]
    }
    fn listed(&self) -> bool {
        true
    }
}

impl Numbers for Vec<Number> {
    fn numbers(&self) -> Vec<f64> {
        self.iter().map(|x| x.0).collect()
    }
    fn listed(&self) -> bool {
        true
    }
}

/// An absent quantity (the ambient term of a view without it) reads as one number that is
/// not finite: the same only as another absent one.
impl<T: Numbers> Numbers for Option<T> {
    fn numbers(&self) -> Vec<f64> {
        self.as_ref()
            .map_or_else(|| vec![f64::NAN], Numbers::numbers)
    }
    fn listed(&self) -> bool {
        self.as_ref().is_some_and(Numbers::listed)
    }
}

/// A number or a vector as the comparison shows it: "none" for a number that is not finite.
fn shown(v: &impl Numbers) -> String {
    let one = |x: f64| {
        if x.is_nan() {
            "none".to_string()
        } else {
            number(x)
        }
    };
    let xs = v.numbers();
    match (v.listed(), xs.as_slice()) {
        (false, [x]) => one(*x),
        _ => format!(
            "({})",
            xs.iter().map(|x| one(*x)).collect::<Vec<_>>().join(", ")
        ),
    }
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

    /// Compares a number or vector of two nodes as `quantity`.
    fn value<T: Numbers>(
        &self,
        quantity: Quantity,
        (ray, shapes): (RayKind, &[&str]),
        mine: &T,
        reference: &T,
    ) -> Agree {
        let (xs, ys) = (mine.numbers(), reference.numbers());
        // a number that is not finite is the same only as another that is not
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
            Err(self.differs(quantity, ray, shapes, shown(mine), shown(reference)))
        }
    }

    /// Two lists side by side; lists of other lengths differ as `quantity`, by their counts.
    fn pairs<'v, T>(
        &self,
        quantity: Quantity,
        (ray, shapes): (RayKind, &[&str]),
        mine: &'v [T],
        reference: &'v [T],
    ) -> Result<Vec<(&'v T, &'v T)>, Difference> {
        if mine.len() != reference.len() {
            return Err(self.differs(
                quantity,
                ray,
                shapes,
                mine.len().to_string(),
                reference.len().to_string(),
            ));
        }
        Ok(mine.iter().zip(reference).collect())
    }

    fn tree(&mut self, mine: &PlainTree, reference: &PlainTree) -> Agree {
        let camera = (RayKind::Camera, &[][..]);
        let samples = self.pairs(Quantity::Samples, camera, &mine.samples, &reference.samples)?;
        let several = samples.len() > 1;
        for (i, (m, r)) in samples.into_iter().enumerate() {
            let depth = self.path.len();
            if several {
                self.path.push(Step {
                    kind: "sample",
                    label: format!("sample {i}"),
                });
            }
            self.value(Quantity::SamplePosition, camera, &m.position, &r.position)?;
            self.ray(RayKind::Camera, &m.ray, &r.ray)?;
            self.path.truncate(depth);
        }
        Ok(())
    }

    fn ray(&mut self, kind: RayKind, mine: &RayNode<Plain>, reference: &RayNode<Plain>) -> Agree {
        let depth = self.path.len();
        self.path.push(Step {
            kind: match kind {
                RayKind::Camera => "camera ray",
                RayKind::Mirror => "mirror ray",
                RayKind::Transmitted => "transmitted ray",
            },
            label: format!("{} ray", kind.name()),
        });
        let at = (kind, &[][..]);
        self.value(Quantity::Origin, at, &mine.origin, &reference.origin)?;
        self.value(
            Quantity::Direction,
            at,
            &mine.direction,
            &reference.direction,
        )?;
        if kind != RayKind::Camera {
            self.value(Quantity::TMin, at, &mine.t_min, &reference.t_min)?;
            self.value(Quantity::Depth, at, &mine.depth, &reference.depth)?;
            self.value(Quantity::K, at, &mine.k, &reference.k)?;
            self.value(Quantity::Weight, at, &mine.weight, &reference.weight)?;
        }
        let object = |h: &Option<HitNode<Plain>>| h.as_ref().map(|h| h.object);
        let (mo, ro) = (object(&mine.hit), object(&reference.hit));
        if mo != ro {
            let shapes: Vec<&str> = [mo, ro]
                .into_iter()
                .flatten()
                .filter_map(|o| (self.shape_of)(o))
                .collect();
            return Err(self.differs(
                Quantity::Object,
                kind,
                &shapes,
                hit_label(mine.hit.as_ref()),
                hit_label(reference.hit.as_ref()),
            ));
        }
        if let (Some(mh), Some(rh)) = (&mine.hit, &reference.hit) {
            self.path.push(Step {
                kind: "hit",
                label: format!("hit {}", hit_label(Some(rh))),
            });
            self.hit(kind, mh, rh)?;
            self.path.pop();
        }
        self.value(Quantity::Colour, at, &mine.colour, &reference.colour)?;
        self.path.truncate(depth);
        Ok(())
    }

    fn hit(&mut self, kind: RayKind, mine: &HitNode<Plain>, reference: &HitNode<Plain>) -> Agree {
        let shapes: Vec<&str> = (self.shape_of)(reference.object).into_iter().collect();
        let at = (kind, &shapes[..]);
        if mine.part != reference.part {
            let (m, r) = (mine.part.clone(), reference.part.clone());
            return Err(self.differs(Quantity::Part, kind, &shapes, m, r));
        }
        self.value(Quantity::T, at, &mine.t, &reference.t)?;
        if mine.entering != reference.entering {
            let side = |entering: bool| if entering { "entering" } else { "leaving" }.to_string();
            return Err(self.differs(
                Quantity::Entering,
                kind,
                &shapes,
                side(mine.entering),
                side(reference.entering),
            ));
        }
        self.value(Quantity::Point, at, &mine.point, &reference.point)?;
        self.value(Quantity::Normal, at, &mine.normal, &reference.normal)?;
        self.value(Quantity::Ambient, at, &mine.ambient, &reference.ambient)?;
        for (m, r) in self.pairs(Quantity::Lights, at, &mine.lights, &reference.lights)? {
            self.path.push(Step {
                kind: "light",
                label: format!("light {}", r.index),
            });
            self.light(kind, m, r)?;
            self.path.pop();
        }
        self.value(Quantity::Local, at, &mine.local, &reference.local)?;
        self.branches(kind, mine, reference)
    }

    fn light(
        &mut self,
        kind: RayKind,
        mine: &LightNode<Plain>,
        reference: &LightNode<Plain>,
    ) -> Agree {
        let at = (kind, &[][..]);
        self.value(
            Quantity::Attenuation,
            at,
            &mine.attenuation,
            &reference.attenuation,
        )?;
        for (q, m, r) in [
            (Quantity::Intensity, &mine.intensity, &reference.intensity),
            (Quantity::Diffuse, &mine.diffuse, &reference.diffuse),
            (Quantity::Specular, &mine.specular, &reference.specular),
            (
                Quantity::Unshadowed,
                &mine.unshadowed,
                &reference.unshadowed,
            ),
        ] {
            self.value(q, at, m, r)?;
        }
        match (&mine.feeler, &reference.feeler) {
            (Some(mf), Some(rf)) => {
                self.path.push(Step {
                    kind: "feeler",
                    label: "feeler".into(),
                });
                self.feeler(kind, mf, rf)?;
                self.path.pop();
            }
            (None, None) => {}
            (m, r) => {
                let sent = |f: &Option<_>| if f.is_some() { "sent" } else { "none" }.to_string();
                return Err(self.differs(Quantity::Feeler, kind, &[], sent(m), sent(r)));
            }
        }
        self.value(Quantity::Share, at, &mine.share, &reference.share)?;
        self.value(Quantity::Arriving, at, &mine.arriving, &reference.arriving)
    }

    fn feeler(
        &mut self,
        kind: RayKind,
        mine: &FeelerNode<Plain>,
        reference: &FeelerNode<Plain>,
    ) -> Agree {
        let at = (kind, &[][..]);
        self.value(Quantity::Start, at, &mine.origin, &reference.origin)?;
        self.value(Quantity::UMin, at, &mine.u_min, &reference.u_min)?;
        let (mc, rc) = (&mine.crossings, &reference.crossings);
        let objects =
            |c: &[Crossing<Plain>]| -> Vec<usize> { c.iter().map(|x| x.object).collect() };
        let (mo, ro) = (objects(mc), objects(rc));
        if mo != ro {
            let shapes: Vec<&str> = mo
                .iter()
                .filter(|o| !ro.contains(o))
                .chain(ro.iter().filter(|o| !mo.contains(o)))
                .filter_map(|&o| (self.shape_of)(o))
                .collect();
            let names = |c: &[Crossing<Plain>]| {
                if c.is_empty() {
                    "nothing".to_string()
                } else {
                    c.iter()
                        .map(|x| object_label(x.name.as_deref(), x.object))
                        .collect::<Vec<_>>()
                        .join(", ")
                }
            };
            return Err(self.differs(Quantity::Crossed, kind, &shapes, names(mc), names(rc)));
        }
        for (m, r) in mc.iter().zip(rc) {
            self.path.push(Step {
                kind: "crossing",
                label: format!("crosses {}", object_label(r.name.as_deref(), r.object)),
            });
            let shapes: Vec<&str> = (self.shape_of)(r.object).into_iter().collect();
            self.value(Quantity::U, (kind, &shapes), &m.u, &r.u)?;
            self.path.pop();
        }
        Ok(())
    }

    /// The branches leaving a hit: which are traced and which stopped (and why) first, then
    /// each traced one, recursively.
    fn branches(
        &mut self,
        kind: RayKind,
        mine: &HitNode<Plain>,
        reference: &HitNode<Plain>,
    ) -> Agree {
        for branch in [RayKind::Transmitted, RayKind::Mirror] {
            let (m, r) = (Fate::of(mine, branch), Fate::of(reference, branch));
            if m.word() != r.word() {
                return Err(Difference {
                    symbol: match branch {
                        RayKind::Mirror => "its mirror ray",
                        _ => "its transmitted ray",
                    },
                    ..self.differs(Quantity::Branches, kind, &[], m.said(), r.said())
                });
            }
        }
        for branch in [RayKind::Transmitted, RayKind::Mirror] {
            if let (Fate::Traced(m), Fate::Traced(r)) =
                (Fate::of(mine, branch), Fate::of(reference, branch))
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
    Traced(&'v RayNode<Plain>),
    /// Not traced, and why.
    Stopped(&'static str),
}

impl<'v> Fate<'v> {
    /// What became of `hit`'s branch of `kind`.
    fn of(hit: &'v HitNode<Plain>, kind: RayKind) -> Self {
        if let Some(ray) = hit.branches.iter().find(|b| b.kind == kind) {
            return Fate::Traced(ray);
        }
        match hit.stopped.iter().find(|(k, _)| *k == kind) {
            Some((_, why)) => Fate::Stopped(why.name()),
            None => Fate::None,
        }
    }

    /// What became of it, without the ray traced: the comparison of two trees' branches.
    fn word(&self) -> &'static str {
        match self {
            Fate::None => "none",
            Fate::Traced(_) => "traced",
            Fate::Stopped(why) => why,
        }
    }

    /// What became of it, as the difference says it.
    fn said(&self) -> String {
        match self {
            Fate::Stopped(why) => format!("not traced: {}", why.replace('_', " ")),
            other => other.word().to_string(),
        }
    }
}

/// "`name`", or "object i", for an object.
fn object_label(name: Option<&str>, object: usize) -> String {
    match name {
        Some(name) => format!("`{name}`"),
        None => format!("object {object}"),
    }
}

/// The object a ray hits, or "nothing".
fn hit_label(hit: Option<&HitNode<Plain>>) -> String {
    hit.map_or("nothing".into(), |h| {
        object_label(h.name.as_deref(), h.object)
    })
}
