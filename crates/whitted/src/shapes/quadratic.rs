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
//! [`Numerics::Robust`] (the default) uses it; [`Numerics::Textbook`] keeps the notes' form so
//! that its error can be measured.
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use crate::numeric::sign;
use crate::real::Real;

/// Which formulas the intersection routines use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Numerics {
    /// The notes' formulas as printed: t = −b/a ± √(b² − ac)/a, discriminant b² − ac,
    /// and the notes' range tests for the cylinder and cone.
    Textbook,
    /// Cancellation-free roots and discriminants, interval clipping for finite shapes.
    #[default]
    Robust,
}

impl Numerics {
    /// Both, the notes' first.
    pub const ALL: [Numerics; 2] = [Numerics::Textbook, Numerics::Robust];

    /// The name reports and `--numerics` use.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Numerics::Textbook => "textbook",
            Numerics::Robust => "robust",
        }
    }
}

/// The real roots of a quadratic, in increasing order; non-finite roots are dropped.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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
/// which may have a more accurate way than [`discriminant`]): the notes' form for
/// [`Numerics::Textbook`], [`stable_roots`] for [`Numerics::Robust`]. Roots that are not finite
/// are dropped.
#[must_use]
pub fn solve_with_discriminant(a: Real, b: Real, c: Real, disc: Real, numerics: Numerics) -> Roots {
    // BEGIN SOLUTION quadratic_roots
    // The notes' t = −b/a ± √(b² − ac)/a, as printed.
    fn textbook_roots(a: Real, b: Real, disc: Real) -> Roots {
        if disc.is_nan() || disc < 0.0 {
            return Roots::None;
        }
        if disc == 0.0 {
            let t = -b / a;
            return if t.is_finite() {
                Roots::One(t)
            } else {
                Roots::None
            };
        }
        let root = disc.sqrt();
        Roots::from_pair(-b / a - root / a, -b / a + root / a)
    }

    match numerics {
        Numerics::Textbook => textbook_roots(a, b, disc),
        Numerics::Robust => match stable_roots(a, b, c, disc) {
            Some((t1, t2)) => Roots::from_pair(t1, t2),
            None => Roots::None,
        },
    }
    // END SOLUTION
}

/// The roots of at² + 2bt + c = 0 with the notes' discriminant b² − ac.
#[must_use]
pub fn solve(a: Real, b: Real, c: Real, numerics: Numerics) -> Roots {
    solve_with_discriminant(a, b, c, discriminant(a, b, c), numerics)
}

/// Both roots of at² + 2bt + c = 0 from its discriminant Δ = b² − ac, in increasing order, by
/// the cancellation-free form
///
/// ```text
/// q = −(b + sign(b)·√Δ)      t₁ = q/a      t₂ = c/q      (t₁ = t₂ = q/a when Δ = 0)
/// ```
///
/// *keeping* infinite roots: for a of a few ulps the far root may overflow to ±∞, which is
/// still the right end of a stretch of the line (a tube or a cone nappe seen almost along its
/// axis), and for a = 0 (a linear equation) q/a is ±∞ and c/q = −c/(2b) the one real root.
/// `None` when Δ < 0, or when a root is NaN (a = b = 0).
#[must_use]
pub fn stable_roots(a: Real, b: Real, c: Real, disc: Real) -> Option<(Real, Real)> {
    // BEGIN SOLUTION stable_roots
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let q = -(b + sign(b) * disc.sqrt());
    let (t1, t2) = if disc == 0.0 && a != 0.0 {
        (q / a, q / a) // a double root
    } else {
        (q / a, c / q)
    };
    if t1.is_nan() || t2.is_nan() {
        return None;
    }
    Some((t1.min(t2), t1.max(t2)))
    // END SOLUTION
}
