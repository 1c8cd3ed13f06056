//! The quadratic at² + 2bt + c = 0 shared by the sphere, the cylinder and the cone
//! (notes: "Generic Sphere").
//!
//! The notes solve it as t = −b/a ± √(b² − ac)/a. When b² ≫ ac, the root −b/a + √(b² − ac)/a
//! subtracts two nearly equal numbers and loses most of its digits (catastrophic
//! cancellation); when a = 0 it divides by zero. The stable form computes the large root
//! first and the small one from the product of the roots, t₁·t₂ = c/a:
//!
//! ```text
//! q  = −(b + sign(b)·√(b² − ac))
//! t₁ = q / a        t₂ = c / q
//! ```
//!
//! [`Formula::Robust`] (the default) uses it; [`Formula::Textbook`] keeps the notes' form so
//! that its error can be measured.

use crate::numeric::sign;
use crate::real::Real;

/// Which formulas the intersection routines use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum Formula {
    /// The notes' formulas as printed: t = −b/a ± √(b² − ac)/a, discriminant b² − ac,
    /// and the notes' range tests for the cylinder and cone.
    #[value(help = "the notes' formulas as printed")]
    Textbook,
    /// Cancellation-free roots and discriminants, interval clipping for finite shapes.
    #[default]
    #[value(help = "cancellation-free roots and discriminants (default)")]
    Robust,
}

/// The real roots of a quadratic, in increasing order; non-finite roots are dropped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Roots {
    /// b² − ac < 0: no real root (the ray misses).
    None,
    /// b² − ac = 0, or a linear equation: one root (the ray grazes).
    One(Real),
    /// b² − ac > 0: two roots t₁ < t₂ (the ray enters and leaves).
    Two(Real, Real),
}

impl Roots {
    /// The roots in increasing order.
    pub fn iter(self) -> impl Iterator<Item = Real> {
        let (roots, n) = match self {
            Roots::None => ([0.0; 2], 0),
            Roots::One(t) => ([t, t], 1),
            Roots::Two(t1, t2) => ([t1, t2], 2),
        };
        roots.into_iter().take(n)
    }

    fn from_pair(t1: Real, t2: Real) -> Self {
        match (t1.is_finite(), t2.is_finite()) {
            (true, true) if t1 == t2 => Roots::One(t1),
            (true, true) => Roots::Two(t1.min(t2), t1.max(t2)),
            (true, false) => Roots::One(t1),
            (false, true) => Roots::One(t2),
            (false, false) => Roots::None,
        }
    }
}

/// The notes' discriminant b² − ac of at² + 2bt + c = 0.
#[inline]
#[must_use]
pub fn discriminant(a: Real, b: Real, c: Real) -> Real {
    b * b - a * c
}

/// The roots of at² + 2bt + c = 0 given its discriminant Δ = b² − ac (computed by the caller,
/// which may have a more accurate way than [`discriminant`]).
#[must_use]
pub fn solve_with_discriminant(a: Real, b: Real, c: Real, disc: Real, formula: Formula) -> Roots {
    if disc.is_nan() || disc < 0.0 {
        return Roots::None;
    }
    let root = disc.sqrt();
    match formula {
        Formula::Textbook => {
            // t = −b/a ± √(b² − ac)/a, as printed in the notes
            if disc == 0.0 {
                let t = -b / a;
                return if t.is_finite() {
                    Roots::One(t)
                } else {
                    Roots::None
                };
            }
            Roots::from_pair(-b / a - root / a, -b / a + root / a)
        }
        Formula::Robust => {
            let q = -(b + sign(b) * root);
            if disc == 0.0 && a != 0.0 {
                return Roots::from_pair(q / a, q / a);
            }
            // q/a is the root of large magnitude, c/q the small one; for a = 0 the equation is
            // linear, q = −2b and c/q = −c/(2b) is its only root.
            Roots::from_pair(q / a, c / q)
        }
    }
}

/// The roots of at² + 2bt + c = 0 with the notes' discriminant b² − ac.
#[must_use]
pub fn solve(a: Real, b: Real, c: Real, formula: Formula) -> Roots {
    solve_with_discriminant(a, b, c, discriminant(a, b, c), formula)
}

/// Both roots of at² + 2bt + c = 0 (a ≠ 0) from its discriminant Δ ≥ 0, in increasing order,
/// by the stable form, *keeping* infinite roots: for a of a few ulps the far root may overflow
/// to ±∞, which is still the right end of a stretch of the line (a tube or a cone nappe seen
/// almost along its axis). `None` when Δ < 0 or is NaN.
#[must_use]
pub fn stable_pair(a: Real, b: Real, c: Real, disc: Real) -> Option<(Real, Real)> {
    if disc.is_nan() || disc < 0.0 || a == 0.0 {
        return None;
    }
    let q = -(b + sign(b) * disc.sqrt());
    if q == 0.0 {
        // b = 0 and Δ = 0, so ac = 0 with a ≠ 0: the double root t = 0
        return Some((0.0, 0.0));
    }
    let (t1, t2) = (q / a, c / q);
    if t1.is_nan() || t2.is_nan() {
        return None;
    }
    Some((t1.min(t2), t1.max(t2)))
}
