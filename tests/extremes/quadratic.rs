//! The quadratic: the stable form keeps the small root, and a = 0 gives only finite roots.

use super::{rel_err, tol};
use whitted::real::{Real, real};
use whitted::shapes::Numerics;
use whitted::shapes::quadratic::{self, Roots};

/// Notes, "Generic Sphere": t = −b/a ± √(b² − ac)/a. When b² ≫ ac the smaller root subtracts
/// two nearly equal numbers; the stable form t₂ = c/q with q = −(b + sign(b)·√(b² − ac)) keeps
/// every digit.
#[test]
fn stable_quadratic_keeps_the_small_root_when_b_squared_dwarfs_ac() {
    let (a, b, c) = (1.0, -real(tol::BIG_B), 1.0);
    let small = 1.0 / (2.0 * tol::BIG_B); // t₁·t₂ = c/a = 1 and t₁ + t₂ = −2b/a
    let smallest = |roots: Roots| match roots {
        Roots::Two(t1, _) => t1,
        Roots::One(t) => t,
        Roots::None => Real::NAN,
    };
    let robust = smallest(quadratic::solve(a, b, c, Numerics::Robust));
    let textbook = smallest(quadratic::solve(a, b, c, Numerics::Textbook));
    assert!(
        rel_err(robust, small) < tol::ROOT_REL,
        "robust small root {robust} vs {small}"
    );
    assert!(
        textbook.is_nan() || rel_err(textbook, small) >= 0.1,
        "the textbook root {textbook} was expected to lose its digits (true {small})"
    );
}

/// Notes, "Generic Sphere" with a = 0 (a degenerate direction): the textbook form divides by
/// zero; the robust one never returns a non-finite root.
#[test]
fn quadratic_with_a_zero_returns_only_finite_roots() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        for (a, b, c) in [
            (0.0, 1.0, -2.0),
            (0.0, 0.0, 1.0),
            (0.0, 0.0, 0.0),
            (0.0, -0.0, 0.0),
        ] {
            match quadratic::solve(a, b, c, numerics) {
                Roots::None => {}
                Roots::One(t) => assert!(t.is_finite()),
                Roots::Two(t1, t2) => assert!(t1.is_finite() && t2.is_finite() && t1 <= t2),
            }
        }
    }
    // the linear case 2b·t + c = 0 is solved by the robust form: t = −c/(2b) = 1
    assert_eq!(
        quadratic::solve(0.0, 1.0, -2.0, Numerics::Robust),
        Roots::One(1.0)
    );
}
