//! Refraction: total internal reflection either side of the critical angle.

use super::{eps, f, tol};
use whitted::optics;
use whitted::real::{Real, Vec3, vec3};

/// Notes, "Reflection and Refraction": beyond the critical angle all light is reflected. From
/// glass (1.5) into air, sin θc = n₂/n₁ = 1/1.5: just below θc a transmitted ray exists (unit,
/// nearly tangent), just above there is none. The notes' (c₁/c₂)·sin θc = 1 asks for
/// sin θc = 1.5, which has no solution.
#[test]
fn total_internal_reflection_starts_exactly_at_the_critical_angle() {
    let (n1, n2) = (1.5 as Real, 1.0 as Real);
    let theta_c = optics::critical_angle(n1, n2).expect("glass to air has one");
    assert!((f(theta_c).to_degrees() - 41.810_314_895_778_6).abs() < 1e-4);
    let n = Vec3::Y;
    let at = |theta: f64| vec3(theta.sin(), -theta.cos(), 0.0);
    let below = optics::refract(at(f(theta_c) - tol::CRITICAL_STEP), n, n1, n2)
        .expect("below the critical angle light gets through");
    assert!((f(below.length()) - 1.0).abs() < 1e3 * eps());
    assert!(
        below.y < 0.0 && f(below.x) > 0.99,
        "nearly tangent: {below:?}"
    );
    assert_eq!(
        optics::refract(at(f(theta_c) + tol::CRITICAL_STEP), n, n1, n2),
        None
    );
    // the notes' condition (c₁/c₂)·sin θc = 1 with c = c₀/n: sin θc = n₁/n₂
    let notes = (n1 / n2).asin();
    assert!(notes.is_nan());
}
