//! The quadratic of the quadric shapes: its roots by the sign of b² − ac, textbook or without cancellation ("Computational Aspects").

use super::*;

/// "Generic Sphere": t = −b/a ± √(b² − ac)/a; b² − ac < 0 no root, = 0 one, > 0 two.
#[test]
fn ex_quadratic_roots_quadratic_has_no_one_or_two_roots_by_the_sign_of_b2_minus_ac() {
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(
            solve(1.0, 0.0, 1.0, numerics),
            Roots::None,
            "the roots of t² + 1 (a = 1, b = 0, c = 1, b² − ac = −1), {numerics:?}"
        );
        assert_eq!(
            solve(1.0, -2.0, 4.0, numerics),
            Roots::One(2.0),
            "the roots of t² − 4t + 4 (a = 1, b = −2, c = 4, b² − ac = 0), {numerics:?}"
        );
        // t² − 10t + 24 = (t − 4)(t − 6)
        let what = format!("of t² − 10t + 24 (a = 1, b = −5, c = 24), {numerics:?}");
        match solve(1.0, -5.0, 24.0, numerics) {
            Roots::Two(t1, t2) => {
                assert_near(&format!("t₁ {what}"), t1, 4.0, TOL);
                assert_near(&format!("t₂ {what}"), t2, 6.0, TOL);
            }
            r => panic!("the roots {what}: {r:?}, expected Two(4, 6)"),
        }
    }
    assert_eq!(
        discriminant(1.0, -5.0, 24.0),
        1.0,
        "b² − ac for a = 1, b = −5, c = 24"
    );
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
        let (t1, t2) = stable_roots(a, b, c, 0.0).unwrap_or_else(|| {
            panic!("stable_roots(a = {a}, b = {b}, c = b²/a, Δ = 0) gave none, expected −b/a twice")
        });
        assert_eq!(t1, -b / a, "t₁ for a = {a}, b = {b}, c = b²/a, Δ = 0: q/a");
        assert_eq!(
            t2, t1,
            "t₂ for a = {a}, b = {b}, c = b²/a, Δ = 0: the double root twice (q/a, not c/q)"
        );
    }
}

/// "Generic Sphere", computed without cancellation: q = −(b + sign(b)·√Δ), t₁ = q/a,
/// t₂ = c/q, in increasing order. t² − 10t + 24 (b = −5, Δ = 1): q = 6, roots 6 and 24/6 = 4;
/// t² + 10t + 24 (b = 5): q = −6, roots −6 and −4; t² − 4t + 4 (Δ = 0): the double root 2,
/// twice; Δ < 0 or NaN: none. a = 0 (4t − 4 = 0, b = 2, c = −4, Δ = 4): q = −4, q/a = −∞ and
/// c/q = 1 = −c/(2b), the line's one root; a = b = 0: 0/0, none.
#[test]
fn ex_stable_roots_come_in_increasing_order() {
    for (a, b, c, delta, expected) in [
        (1.0, -5.0, 24.0, 1.0, Some((4.0, 6.0))),
        (1.0, 5.0, 24.0, 1.0, Some((-6.0, -4.0))),
        (1.0, -2.0, 4.0, 0.0, Some((2.0, 2.0))),
        (1.0, 0.0, 1.0, -1.0, None),
        (1.0, 0.0, 1.0, Real::NAN, None),
        (0.0, 2.0, -4.0, 4.0, Some((Real::NEG_INFINITY, 1.0))),
        (0.0, 0.0, 1.0, 0.0, None),
    ] {
        assert_eq!(
            stable_roots(a, b, c, delta),
            expected,
            "(t₁, t₂) for a = {a}, b = {b}, c = {c}, Δ = {delta}"
        );
    }
}

/// "Generic Sphere" (computational aspects): for t² − 2·10⁸·t + 1 = 0 (a = 1, b = −10⁸,
/// c = 1) the roots are 2·10⁸ and, from the product of the roots, 1/(2·10⁸) = 5·10⁻⁹, to full
/// precision in f64 and f32 alike: the large root q/a needs no subtraction, the small one is
/// c/q.
#[test]
fn ex_stable_roots_the_small_root_keeps_its_digits() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    let (t1, t2) = stable_roots(a, b, c, discriminant(a, b, c)).unwrap_or_else(|| {
        panic!("stable_roots(a = {a}, b = {b}, c = {c}) gave none, expected 5·10⁻⁹ and 2·10⁸")
    });
    assert_near(
        "t₁/5·10⁻⁹ for t² − 2·10⁸·t + 1 (the small root, c/q)",
        t1 / 5e-9,
        1.0,
        TOL,
    );
    assert_near(
        "t₂/2·10⁸ for t² − 2·10⁸·t + 1 (the large root, q/a)",
        t2 / 2e8,
        1.0,
        TOL,
    );
}

/// "Generic Sphere": the notes' t = −b/a ± √(b² − ac)/a, as printed, loses the small root of
/// t² − 2·10⁸·t + 1 = 0 entirely (10⁸ − 10⁸ = 0), while the stable form keeps 5·10⁻⁹; both
/// drop what is not a finite root (a = 0: the stable form keeps the line's root 1 and drops
/// −∞) and find nothing for a NaN discriminant.
#[test]
fn ex_quadratic_roots_textbook_roots_lose_the_small_root_and_stable_ones_keep_it() {
    let (a, b, c) = (1.0, -1e8, 1.0);
    assert_eq!(
        solve(a, b, c, Numerics::Textbook),
        Roots::Two(0.0, 2e8),
        "the textbook roots of t² − 2·10⁸·t + 1, −b/a ∓ √(b² − ac)/a as printed"
    );
    match solve(a, b, c, Numerics::Robust) {
        Roots::Two(t1, t2) => {
            assert_near(
                "t₁/5·10⁻⁹ for t² − 2·10⁸·t + 1, Robust (stable_roots)",
                t1 / 5e-9,
                1.0,
                TOL,
            );
            assert_near(
                "t₂/2·10⁸ for t² − 2·10⁸·t + 1, Robust (stable_roots)",
                t2 / 2e8,
                1.0,
                TOL,
            );
        }
        r => panic!(
            "the Robust roots of t² − 2·10⁸·t + 1: {r:?}, expected Two(5·10⁻⁹, 2·10⁸) from stable_roots"
        ),
    }
    assert_eq!(
        solve_with_discriminant(0.0, 2.0, -4.0, 4.0, Numerics::Robust),
        Roots::One(1.0),
        "the Robust roots of 4t − 4 = 0 (a = 0, b = 2, c = −4, Δ = 4): −∞ dropped"
    );
    for numerics in [Numerics::Textbook, Numerics::Robust] {
        assert_eq!(
            solve_with_discriminant(1.0, 0.0, 1.0, Real::NAN, numerics),
            Roots::None,
            "the roots for a NaN Δ, {numerics:?}"
        );
    }
}
