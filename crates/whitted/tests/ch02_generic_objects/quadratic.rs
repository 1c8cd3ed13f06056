//! The quadratic of the quadric shapes: its roots by the sign of b² − ac, textbook or without cancellation ("Computational Aspects").

use super::*;

/// "Generic Sphere": t = −b/a ± √(b² − ac)/a; b² − ac < 0 no root, = 0 one, > 0 two.
#[test]
fn ex_quadratic_roots_quadratic_has_no_one_or_two_roots_by_the_sign_of_b2_minus_ac() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(solve(1.0, 0.0, 1.0, numerics), Roots::None); // t² + 1
        assert_eq!(solve(1.0, -2.0, 4.0, numerics), Roots::One(2.0)); // t² − 4t + 4
        match solve(1.0, -5.0, 24.0, numerics) {
            // t² − 10t + 24 = (t − 4)(t − 6)
            Roots::Two(t1, t2) => {
                assert_abs_diff_eq!(t1, 4.0, epsilon = TOL);
                assert_abs_diff_eq!(t2, 6.0, epsilon = TOL);
            }
            r => panic!("{r:?}"),
        }
    }
    assert_eq!(discriminant(1.0, -5.0, 24.0), 1.0);
}

/// "Generic Objects": a double root (Δ = 0, a ≠ 0) is one number, returned twice: t₁ = t₂ =
/// q/a. The other stable form, c/q, is the same root in exact arithmetic but rounds
/// differently: for a = 3, b = −7, c = b²/a it is one ulp off q/a, in f64 and in f32, and a
/// tangent ray would seem to cross the surface over a sliver of length 1 ulp.
#[test]
fn ex_stable_roots_a_double_root_is_returned_as_two_equal_values() {
    for (a, b) in [(3.0, -7.0), (3.0, -11.0), (6.0, -7.0), (11.0, -5.0)] {
        let (a, b): (Real, Real) = (a, b);
        let c = b * b / a;
        let (t1, t2) = stable_roots(a, b, c, 0.0).unwrap();
        assert_eq!(t1, -b / a, "a = {a}, b = {b}");
        assert_eq!(t2, t1, "a = {a}, b = {b}: the double root twice");
    }
}

/// "Generic Sphere", computed without cancellation: q = −(b + sign(b)·√Δ), t₁ = q/a,
/// t₂ = c/q, in increasing order. t² − 10t + 24 (b = −5, Δ = 1): q = 6, roots 6 and 24/6 = 4;
/// t² + 10t + 24 (b = 5): q = −6, roots −6 and −4; t² − 4t + 4 (Δ = 0): the double root 2,
/// twice; Δ < 0 or NaN: none. a = 0 (4t − 4 = 0, b = 2, c = −4, Δ = 4): q = −4, q/a = −∞ and
/// c/q = 1 = −c/(2b), the line's one root; a = b = 0: 0/0, none.
#[test]
fn ex_stable_roots_come_in_increasing_order() {
    assert_eq!(stable_roots(1.0, -5.0, 24.0, 1.0), Some((4.0, 6.0)));
    assert_eq!(stable_roots(1.0, 5.0, 24.0, 1.0), Some((-6.0, -4.0)));
    assert_eq!(stable_roots(1.0, -2.0, 4.0, 0.0), Some((2.0, 2.0)));
    assert_eq!(stable_roots(1.0, 0.0, 1.0, -1.0), None);
    assert_eq!(stable_roots(1.0, 0.0, 1.0, Real::NAN), None);
    assert_eq!(
        stable_roots(0.0, 2.0, -4.0, 4.0),
        Some((Real::NEG_INFINITY, 1.0))
    );
    assert_eq!(stable_roots(0.0, 0.0, 1.0, 0.0), None);
}

/// "Generic Sphere" (computational aspects): for t² − 2·10⁸·t + 1 = 0 (a = 1, b = −10⁸,
/// c = 1) the roots are 2·10⁸ and, from the product of the roots, 1/(2·10⁸) = 5·10⁻⁹, to full
/// precision in f64 and f32 alike: the large root q/a needs no subtraction, the small one is
/// c/q.
#[test]
fn ex_stable_roots_the_small_root_keeps_its_digits() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    let (t1, t2) = stable_roots(a, b, c, discriminant(a, b, c)).unwrap();
    assert_abs_diff_eq!(t1 / 5e-9, 1.0, epsilon = TOL);
    assert_abs_diff_eq!(t2 / 2e8, 1.0, epsilon = TOL);
}

/// "Generic Sphere": the notes' t = −b/a ± √(b² − ac)/a, as printed, loses the small root of
/// t² − 2·10⁸·t + 1 = 0 entirely (10⁸ − 10⁸ = 0), while the stable form keeps 5·10⁻⁹; both
/// drop what is not a finite root (a = 0: the stable form keeps the line's root 1 and drops
/// −∞) and find nothing for a NaN discriminant.
#[test]
fn ex_quadratic_roots_textbook_roots_lose_the_small_root_and_stable_ones_keep_it() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    assert_eq!(solve(a, b, c, Numerics::Textbook), Roots::Two(0.0, 2e8));
    match solve(a, b, c, Numerics::Robust) {
        Roots::Two(t1, t2) => {
            assert_abs_diff_eq!(t1 / 5e-9, 1.0, epsilon = TOL);
            assert_abs_diff_eq!(t2 / 2e8, 1.0, epsilon = TOL);
        }
        r => panic!("{r:?}"),
    }
    assert_eq!(
        solve_with_discriminant(0.0, 2.0, -4.0, 4.0, Numerics::Robust),
        Roots::One(1.0)
    );
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(
            solve_with_discriminant(1.0, 0.0, 1.0, Real::NAN, numerics),
            Roots::None
        );
    }
}
