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

use super::{Hit, Hits, Part, entering_leaving};
use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// One facet: the plane n·P = d with n the outward unit normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facet {
    /// The outward unit normal n.
    pub normal: Vec3,
    /// The constant d of n·P = d.
    pub d: Real,
}

impl Facet {
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
    (facet.d - facet.normal.dot(ray.origin)) / facet.normal.dot(ray.dir)
}

/// A convex polyhedron given by its facets.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyhedron {
    /// The facets, outward unit normals.
    pub facets: Vec<Facet>,
}

impl Polyhedron {
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
        let mut t_near = Real::NEG_INFINITY;
        let mut t_far = Real::INFINITY;
        let (mut near_facet, mut far_facet) = (0, 0);
        for (i, facet) in self.facets.iter().enumerate() {
            let denom = facet.normal.dot(ray.dir); // n·d
            let num = facet.d - facet.normal.dot(ray.origin); // d − n·e
            if denom == 0.0 {
                if num < 0.0 {
                    return Hits::none(); // parallel and outside this facet
                }
                continue; // parallel and inside: this facet does not bound the ray
            }
            let t = num / denom;
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
            normal: self.facets[i].normal,
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
    }
}
