//! Convex polyhedra (notes: "Convex Polyhedra").
//!
//! A convex polyhedron is the set of points P with n·P ≤ d for every facet (n outward and unit
//! length). The ray e + d·t crosses a facet's plane where n·(e + d·t) = d, that is
//!
//! ```text
//! t = (d − n·e) / (n·d)
//! ```
//!
//! (the notes print `t = d − n·e / n·d`, which by the usual precedence is d − (n·e)/(n·d):
//! an erratum). The line is clipped facet by facet: where n·d < 0 the ray enters the facet's
//! half-space and t raises t_near; where n·d > 0 it leaves and t lowers t_far; where n·d = 0 it
//! is parallel, and misses unless its origin is inside (n·e ≤ d). The ray meets the solid when
//! t_near ≤ t_far, entering through the facet that set t_near and leaving through the one that
//! set t_far.
//!
//! ```toml
//! [[objects]]
//! polyhedron = { preset = "octahedron" }
//! transform = [ { scale = 0.8 }, { translate = [0.0, 1.0, 0.0] } ]
//! ```
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::hits::{Hit, Hits, Part, entering_leaving};
use crate::ray::Ray;
use crate::real::{Mat3, Real, Vec3};

/// One facet: the plane n·P = d with n the outward unit normal.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Facet {
    normal: Vec3,
    d: Real,
}

impl Facet {
    /// The outward unit normal n.
    #[inline]
    #[must_use]
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The constant d of n·P = d.
    #[inline]
    #[must_use]
    pub fn d(&self) -> Real {
        self.d
    }

    /// A facet from any non-zero normal: n and d are divided by |n|. `None` for a zero or
    /// non-finite normal.
    #[must_use]
    pub fn new(normal: Vec3, d: Real) -> Option<Self> {
        let len = normal.length();
        (len > 0.0 && len.is_finite() && d.is_finite()).then(|| Self {
            normal: normal / len,
            d: d / len,
        })
    }
}

/// The parameter where the ray e + d·t meets the plane n·P = d: t = (d − n·e)/(n·d).
#[inline]
#[must_use]
pub fn facet_t(facet: &Facet, ray: &Ray) -> Real {
    // BEGIN SOLUTION facet_crossing
    (facet.d() - facet.normal().dot(ray.origin)) / facet.normal().dot(ray.dir)
    // END SOLUTION
}

/// A convex polyhedron given by its facets.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Polyhedron {
    facets: Vec<Facet>,
}

impl Polyhedron {
    /// The polyhedron bounded by `facets` (see [`Polyhedron::check`] for whether they close a
    /// solid).
    #[must_use]
    pub fn new(facets: Vec<Facet>) -> Self {
        Self { facets }
    }

    /// The facets, in the order given.
    #[must_use]
    pub fn facets(&self) -> &[Facet] {
        &self.facets
    }

    /// The cube [−1, 1]³: six facets ±x, ±y, ±z at d = 1.
    #[must_use]
    pub fn cube() -> Self {
        let normals = [
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::Z,
            Vec3::NEG_Z,
        ];
        Self::from_unit(normals.iter().map(|&n| (n, 1.0)))
    }

    /// The regular tetrahedron with vertices (1, 1, 1), (1, −1, −1), (−1, 1, −1), (−1, −1, 1):
    /// each facet faces away from the vertex it does not contain, at distance 1/√3.
    #[must_use]
    pub fn tetrahedron() -> Self {
        let signs = [
            [1.0, 1.0, 1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, 1.0],
        ];
        Self::from_signs(&signs.map(|s| s.map(|x: Real| -x)))
    }

    /// The regular octahedron with vertices (±1, 0, 0), (0, ±1, 0), (0, 0, ±1): eight facets
    /// with normals (±1, ±1, ±1)/√3 at distance 1/√3.
    #[must_use]
    pub fn octahedron() -> Self {
        let mut signs = Vec::with_capacity(8);
        for x in [1.0, -1.0] {
            for y in [1.0, -1.0] {
                for z in [1.0, -1.0] {
                    signs.push([x, y, z]);
                }
            }
        }
        Self::from_signs(&signs)
    }

    /// Facets with normals (±1, ±1, ±1)/√3 at distance 1/√3.
    fn from_signs(signs: &[[Real; 3]]) -> Self {
        let k = 1.0 / (3.0 as Real).sqrt();
        Self::from_unit(signs.iter().map(|s| (Vec3::from_array(*s) * k, k)))
    }

    fn from_unit(facets: impl Iterator<Item = (Vec3, Real)>) -> Self {
        Self {
            facets: facets.map(|(normal, d)| Facet { normal, d }).collect(),
        }
    }

    /// The preset named `name` (`cube`, `tetrahedron`, `octahedron`), if there is one.
    #[must_use]
    pub fn preset(name: &str) -> Option<Self> {
        match name {
            "cube" => Some(Self::cube()),
            "tetrahedron" => Some(Self::tetrahedron()),
            "octahedron" => Some(Self::octahedron()),
            _ => None,
        }
    }

    /// The names accepted by [`Polyhedron::preset`].
    pub const PRESETS: [&'static str; 3] = ["cube", "tetrahedron", "octahedron"];

    /// Clips the object-space ray against every facet (the notes' "Convex Polyhedra").
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Hits {
        // BEGIN SOLUTION hit_polyhedron
        let mut t_near = Real::NEG_INFINITY;
        let mut t_far = Real::INFINITY;
        let (mut near_facet, mut far_facet) = (0, 0);
        for (i, facet) in self.facets.iter().enumerate() {
            let denom = facet.normal().dot(ray.dir); // n·d: < 0 entering, > 0 leaving
            if denom == 0.0 {
                if facet.normal().dot(ray.origin) > facet.d() {
                    return Hits::none(); // parallel and outside this facet
                }
                continue; // parallel and inside: this facet does not bound the ray
            }
            let t = facet_t(facet, ray);
            if denom < 0.0 {
                if t > t_near {
                    (t_near, near_facet) = (t, i); // outside to inside
                }
            } else if t < t_far {
                (t_far, far_facet) = (t, i); // inside to outside
            }
            if t_near > t_far {
                return Hits::none();
            }
        }
        let hit = |t: Real, i: usize| Hit {
            t,
            normal: self.facets[i].normal(),
            part: Part::Facet(i as u32),
            entering: true,
        };
        match (t_near.is_finite(), t_far.is_finite()) {
            (true, true) => entering_leaving(hit(t_near, near_facet), hit(t_far, far_facet)),
            (true, false) => Hits::one(hit(t_near, near_facet)),
            (false, true) => Hits::one(Hit {
                entering: false,
                ..hit(t_far, far_facet)
            }),
            (false, false) => Hits::none(),
        }
        // END SOLUTION
    }
}

impl Polyhedron {
    /// The most facets a scene may give one polyhedron (checking them costs O(n⁴)).
    pub const MAX_FACETS: usize = 64;

    /// The corners: each point where three facet planes meet that lies inside every facet.
    /// Corners shared by more than three facets appear more than once.
    #[must_use]
    pub fn vertices(&self) -> Vec<Vec3> {
        let f = &self.facets;
        let tol = self.tolerance();
        let mut out = Vec::new();
        for i in 0..f.len() {
            for j in i + 1..f.len() {
                for k in j + 1..f.len() {
                    let m = Mat3::from_cols(f[i].normal, f[j].normal, f[k].normal).transpose();
                    let det = m.determinant(); // of unit normals: in [−1, 1]
                    if det.abs() <= Real::EPSILON {
                        continue; // two of the planes are parallel, or all three share a line
                    }
                    let p = m.inverse() * Vec3::new(f[i].d, f[j].d, f[k].d);
                    if p.is_finite() && f.iter().all(|g| g.normal().dot(p) <= g.d() + tol) {
                        out.push(p);
                    }
                }
            }
        }
        out
    }

    fn tolerance(&self) -> Real {
        let scale = self
            .facets
            .iter()
            .fold(1.0, |m: Real, f| m.max(f.d().abs()));
        Real::EPSILON.sqrt() * scale
    }

    /// Checks that the facets enclose a bounded solid with an inside: not an empty set (facets
    /// that contradict each other), not an unbounded one (some direction leaves through no
    /// facet), not a flat one.
    pub fn check(&self) -> Result<(), &'static str> {
        let f = &self.facets;
        // Unbounded: some direction v with n·v ≤ 0 for every facet. If there is one, there is
        // one along an edge direction n_i × n_j (or the normals do not span space at all).
        let tol = Real::EPSILON.sqrt();
        for i in 0..f.len() {
            for j in i + 1..f.len() {
                let Some(v) = f[i].normal.cross(f[j].normal).try_normalize() else {
                    continue;
                };
                for dir in [v, -v] {
                    if f.iter().all(|g| g.normal().dot(dir) <= tol) {
                        return Err(
                            "the facets do not close the polyhedron: it is unbounded in some direction",
                        );
                    }
                }
            }
        }
        let vertices = self.vertices();
        if vertices.len() < 4 {
            return Err(
                "the facets enclose no solid: their half-spaces do not overlap in a volume",
            );
        }
        let centre = vertices.iter().copied().sum::<Vec3>() / vertices.len() as Real;
        let depth = f
            .iter()
            .map(|g| g.d() - g.normal().dot(centre))
            .fold(Real::INFINITY, Real::min);
        if depth <= self.tolerance() {
            return Err("the facets enclose no solid: the polyhedron is flat");
        }
        Ok(())
    }
}
