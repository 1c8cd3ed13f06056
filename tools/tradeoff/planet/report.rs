//! The report's section on a huge object seen from close by, written from both workers'
//! measurements so that the text and the numbers cannot drift apart.

use super::errors::HitError;
use super::fixes::Method;
use super::setup::{ANGLES, LIGHT, RADII, RAYS};
use super::tsv::Measured;

/// A length or an error with two significant digits: plain between 0.001 and 10 000,
/// scientific outside.
fn num(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() {
        "–".into()
    } else if (1e-3..1e4).contains(&x.abs()) {
        let digits = (1 - x.abs().log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.1e}")
    }
}

/// A radius as a power of ten.
fn radius(r: f64) -> String {
    format!("1e{}", r.log10().round())
}

/// A share in percent.
fn percent(x: f64) -> String {
    format!("{:.1}%", 100.0 * x)
}

/// An error cell: the largest distance from the surface, and the rays that hit where the
/// reference misses or the other way round, if any.
fn cell(e: &HitError) -> String {
    if e.disagree > 0 {
        format!("{} ({} wrong hit/miss)", num(e.surface), e.disagree)
    } else {
        num(e.surface)
    }
}

/// The unit roundoff of each precision.
const U32: f64 = f32::EPSILON as f64 / 2.0;
const U64: f64 = f64::EPSILON / 2.0;
/// The ε of the *fixed* offset in the acne measurement (a no-op cast in the f64 build).
#[allow(clippy::unnecessary_cast)]
const EPSILON: f64 = whitted::offset::Offset::FIXED_EPSILON as f64;

/// The Markdown section, from the f64 and the f32 worker's measurements.
pub fn section(wide: &Measured, narrow: &Measured) -> String {
    let mut md = String::new();
    let mut w = |s: String| {
        md.push_str(&s);
        md.push('\n');
    };
    let big = RADII[RADII.len() - 2]; // 1e6, the planet the prose quotes
    let generic = narrow.worst(big, Method::Generic);
    let grazing = ANGLES[ANGLES.len() - 1];
    let along = narrow
        .hit(big, grazing, Method::Generic)
        .map_or(f64::NAN, |e| e.along);
    let acne_at = |m: &Measured, r: f64| m.acne.iter().find(|a| a.0 == r).copied();
    let big_acne = acne_at(narrow, big);

    w("## A huge object seen from close by".into());
    w(String::new());
    w(format!(
        "whitted intersects every object by the generic-object method: the world ray is carried into \
         the object's own space by M⁻¹ and meets a unit shape there. Here the object is a planet: \
         `sphere = {{ center = [0, -R, 0], radius = R }}` for R from {} to {}, its top at the world \
         origin, and the camera about one unit above it (x and z within ±1 of the top, height 1 ± 0.1). \
         From there {RAYS} rays at each of {} degrees below the horizontal, in random directions around, \
         meet the planet. Each hit is compared with a reference computed in f64 in world space (by fix \
         (b′) below, which forms no number of size R², polished by a Newton step); errors are in world \
         units, the largest over the rays. Both precisions are measured by the same command, \
         `cargo run --release --bin tradeoff`, in its two workers.",
        radius(RADII[0]),
        radius(RADII[RADII.len() - 1]),
        ANGLES.map(|a| format!("{a}")).join(", "),
    ));
    w(String::new());

    // what happens
    w("### What happens".into());
    w(String::new());
    w(format!(
        "M⁻¹ divides by R, so the camera, one unit above the surface, lands at distance 1 + 1/R from \
         the centre of the unit sphere: 1.000001 for R = {}. Floats near 1 are 2⁻²³ ≈ 1.2e-7 apart in \
         f32 (2.2e-16 in f64), and the camera's height above the unit sphere, 1/R, is held only to within \
         u (the unit roundoff, half that spacing), {} of it at R = {} in f32. The sphere test's \
         c = |e′|² − 1 ≈ 2/R subtracts two numbers near 1 and keeps exactly that error. Carried back to the world, everything the test finds near the surface is \
         known to about R·u (u = {} in f32, {} in f64): the hit points scatter above and below the true \
         surface by that much, in f32 {} at R = {}. Along a ray the error is that divided by the sine \
         of the angle at which the ray meets the surface: at {grazing}° it reaches {} units.",
        radius(big),
        percent(U32 * big),
        radius(big),
        num(U32),
        num(U64),
        num(generic.surface),
        radius(big),
        num(along),
    ));
    w(String::new());
    let distances: Vec<String> = ANGLES
        .iter()
        .map(|&a| {
            let d: Vec<f64> = RADII
                .iter()
                .filter_map(|&r| narrow.hit(r, a, Method::Generic).map(|e| e.distance))
                .collect();
            let (lo, hi) = (
                d.iter().copied().fold(f64::INFINITY, f64::min),
                d.iter().copied().fold(0.0, f64::max),
            );
            let short = |x: f64| {
                if x < 10.0 {
                    format!("{x:.1}")
                } else {
                    format!("{x:.0}")
                }
            };
            if short(lo) == short(hi) {
                short(lo)
            } else {
                format!("{}–{}", short(lo), short(hi))
            }
        })
        .collect();
    w(format!(
        "The generic-object method alone (table: the largest distance of a hit point from the true \
         surface, then, in f32, the largest error along the ray at each angle; the hits lie {} units \
         from the camera at {}°):",
        distances.join(", "),
        ANGLES.map(|a| format!("{a}")).join(", "),
    ));
    w(String::new());
    let mut head =
        "| R | R·u (f64) | f64: off the surface | R·u (f32) | f32: off the surface |".to_string();
    let mut rule = "|---:|---:|---:|---:|---:|".to_string();
    for a in ANGLES {
        head.push_str(&format!(" f32: along the ray, {a}° |"));
        rule.push_str("---:|");
    }
    w(head);
    w(rule);
    for r in RADII {
        let mut row = format!(
            "| {} | {} | {} | {} | {} |",
            radius(r),
            num(r * U64),
            cell(&wide.worst(r, Method::Generic)),
            num(r * U32),
            cell(&narrow.worst(r, Method::Generic)),
        );
        for a in ANGLES {
            let e = narrow.hit(r, a, Method::Generic);
            row.push_str(&format!(" {} |", e.map_or("–".into(), |e| num(e.along))));
        }
        w(row);
    }
    w(String::new());

    // acne
    // a fixed ε without acne where it is below R·u is luck, not accuracy
    let lucky: Vec<String> = RADII
        .iter()
        .filter(|&&r| r * U32 > EPSILON && acne_at(narrow, r).is_some_and(|a| a.1[0] == 0.0))
        .map(|&r| radius(r))
        .collect();
    let luck = match lucky.as_slice() {
        [] => String::new(),
        [one] => format!(
            " (At R = {one} the fixed ε shows no acne by luck of the rounding of these feelers' \
             starts, not by accuracy: ε = {EPSILON:.0e} is below R·u there.)"
        ),
        [first @ .., last] => format!(
            " (At R = {} and {last} the fixed ε shows no acne by luck of the rounding of these \
             feelers' starts, not by accuracy: ε = {EPSILON:.0e} is below R·u there.)",
            first.join(", ")
        ),
    };
    w(format!(
        "Left at that, a picture shows shading computed at points that wander by R·u from pixel to \
         pixel (a bumpy, noisy ground), and shadow acne: a feeler ray towards a light high above \
         (at ({}, {}, {})) starts from a hit point that may lie below the surface, and meets the \
         planet it leaves. The f32 build refines the hit each ray shows (see *What the f32 build \
         does* below), which puts the shading points and the feelers' starts back on the surface; \
         but a feeler is tested against the planet by the method alone, which knows its start only \
         to R·u, so an offset below R·u may still let it meet the planet it leaves. The table gives, for the hit points as the library shades them, the share \
         of lit ones whose feeler is blocked under each offset strategy (ε = 1e-4 for *fixed* and \
         *scaled*), and how far the default *error-bound* offset pushes the feeler out (the median \
         over the points): it avoids the acne by pushing by a bound on the error, which grows like \
         R·u too. At R = {} in f32 that is {} units: the feeler starts that far above the ground and \
         passes over anything lower standing there, which then casts no shadow.{}",
        LIGHT[0],
        LIGHT[1],
        LIGHT[2],
        radius(big),
        big_acne.map_or("–".into(), |a| num(a.2)),
        luck,
    ));
    w(String::new());
    w("| R | f64: fixed / scaled / error-bound | f64: error-bound push | f32: fixed | f32: scaled | f32: error-bound | f32: error-bound push | f32: fixed, hits and feelers by (b′) |".into());
    w("|---:|---:|---:|---:|---:|---:|---:|---:|".into());
    for r in RADII {
        let (Some(a64), Some(a32)) = (acne_at(wide, r), acne_at(narrow, r)) else {
            continue;
        };
        w(format!(
            "| {} | {} / {} / {} | {} | {} | {} | {} | {} | {} |",
            radius(r),
            percent(a64.1[0]),
            percent(a64.1[1]),
            percent(a64.1[2]),
            num(a64.2),
            percent(a32.1[0]),
            percent(a32.1[1]),
            percent(a32.1[2]),
            num(a32.2),
            percent(a32.3),
        ));
    }
    w(String::new());

    // fixes
    w("### What fixes it, and at what cost".into());
    w(String::new());
    w("The same rays in f32, found by the generic-object method alone, by the library (the same \
       method, then the f32 build's refinement of the hit a ray shows, below), and by four \
       alternatives written in the tool for this measurement (`tools/tradeoff/planet/fixes.rs`): the \
       largest distance of a hit point from the true surface over all angles, and the time per ray \
       to find the nearest hit (one thread, the fastest of 15 passes over every radius). The method \
       alone and the library do more than the fixes (they return both hits, each with its normal), \
       so compare the fixes with each other, the library with the method alone for what the \
       refinement costs, and the f64 row with the f32 row for what f64 costs."
        .into());
    w(String::new());
    let fixes = [
        (Method::Generic, "M⁻¹, unit sphere, alone"),
        (Method::Library, "library: the same, hit refined"),
        (Method::Centre, "(b) world, from the centre"),
        (Method::Anchored, "(b′) world, from a surface point"),
        (Method::WideTransform, "(c₁) M⁻¹ in f64 only"),
        (Method::Wide, "(c₂) M⁻¹ and the solution in f64"),
        (Method::Plane, "(d) the tangent plane"),
    ];
    w(format!("| R | {} |", fixes.map(|f| f.1).join(" | ")));
    w(format!("|---:|{}", "---:|".repeat(fixes.len())));
    for r in RADII {
        let cells: Vec<String> = fixes.iter().map(|f| cell(&narrow.worst(r, f.0))).collect();
        w(format!("| {} | {} |", radius(r), cells.join(" | ")));
    }
    let cost = |m: &Measured| -> Vec<String> {
        fixes
            .iter()
            .map(|f| format!("{:.1}", m.cost(f.0)))
            .collect()
    };
    w(format!(
        "| ns per ray, f32 build | {} |",
        cost(narrow).join(" | ")
    ));
    w(format!(
        "| ns per ray, f64 build | {} |",
        cost(wide).join(" | ")
    ));
    w(String::new());
    let at = |m: Method| num(narrow.worst(big, m).surface);
    for line in [
        format!(
            "- **(b) World space, measured from the centre**, does not help ({} at R = {}): e − C (C the \
             centre) has the size R, and c = |e − C|² − R² subtracts two numbers of size R² ≈ 1e{}. The matrix is \
             not the culprit; measuring positions from the centre is.",
            at(Method::Centre),
            radius(big),
            2.0 * big.log10()
        ),
        format!(
            "- **(b′) World space, measured from a point P₀ of the surface near the camera** (here the \
             top, with its normal n): the sphere |g + R·n|² = R², g = e − P₀ + d·t, gives \
             c = |e − P₀|² + 2R·n·(e − P₀), a sum of small terms and products, with nothing of size R² \
             subtracted. The f32 hits are then as good as the rounding of t itself ({} at R = {}), for \
             a few extra multiplications. The price is bookkeeping: P₀ must be chosen near the camera \
             (once per frame, in f64), and the error grows again with the distance from P₀.",
            at(Method::Anchored),
            radius(big),
        ),
        format!(
            "- **(c₁) Only M⁻¹ in f64** does not help ({}): the object-space ray is rounded to f32 \
             before the quadratic, and rounding 1 + 1/R to f32 is the whole loss. **(c₂) M⁻¹, the \
             transform and the quadratic in f64** for this object fixes it ({}): the object-space \
             numbers then carry f64's 1e-16, and only t is rounded to f32. The cost is f64 arithmetic \
             and converting the ray to f64 and t back (the ns rows); a CPU's scalar f64 is about as fast as f32, but SIMD lanes \
             and GPUs hold half as many f64. The library's f32 build takes this fix for the one hit a \
             ray shows, as one Newton step from the f32 root rather than a second solution \
             (*library*: {} at R = {}, {} at R = {}: one step leaves about the square of the f32 \
             root's error over the distance to the far root).",
            at(Method::WideTransform),
            at(Method::Wide),
            num(narrow.worst(RADII[1], Method::Library).surface),
            radius(RADII[1]),
            at(Method::Library),
            radius(big),
        ),
        format!(
            "- **(d) A plane instead of the planet**: the generic plane z = 0 is placed by an exact \
             quarter turn, with no scale, so t = −e_z/d_z is as exact as one division ({}). The plane \
             is not the sphere: it stands x²/2R above it at a distance x along the ground, 5 mm at \
             100 units for R = 1e6, 0.5 units at 1000. A huge *box* does not help: its face sits at \
             1 in object space, and 1 − (1 + 1/R) cancels like the sphere's c (the f32 build refines \
             a facet's hit as it does the sphere's).",
            at(Method::Plane),
        ),
        "- **(a) Moving the ray's origin near the object before transforming** (start at the \
           bounding box's entry, add that t back) is the fix for the opposite case, a small object \
           far away (the *far* scene above), where |e′|² in object space is huge. It cannot help \
           here: the camera is already one unit from the surface, and any point near the surface, \
           carried into object space, lands near 1, where f32 holds it only to R·u world units."
            .to_string(),
    ] {
        w(line);
    }
    w(String::new());
    library(&mut w, wide, narrow);
    w(format!(
        "In short: in f32, keep the numbers a test subtracts of the size of the distances that \
         matter. A planet should be a plane near the camera, or be intersected from a point of its \
         surface, or in f64 (the f32 build does the last for the hit each ray shows); the \
         error-bound offset keeps the shadows free of acne only by pushing feelers out by a bound \
         that grows like R·u ({} units at R = {}). In f64 the method holds to R·u = {} at R = {}.",
        big_acne.map_or("–".into(), |a| num(a.2)),
        radius(big),
        num(wide.worst(big, Method::Generic).surface),
        radius(big),
    ));
    md
}

/// The subsection on what the f32 build does at the planet: the refinement of the hit each ray
/// shows, its effect and its cost per ray from the measurements, then the side-by-side timings
/// of whole renders, measured apart (`tradeoff-f32-cost.md`, included by mdBook).
fn library(w: &mut impl FnMut(String), wide: &Measured, narrow: &Measured) {
    let at = |r: f64, m: Method| num(narrow.worst(r, m).surface);
    let (small, big) = (RADII[1], RADII[RADII.len() - 2]);
    w("### What the f32 build does".into());
    w(String::new());
    w(format!(
        "The f32 build takes fix (c₂) for the one hit each ray shows \
         (`crates/whitted/src/shapes/refine.rs`). Once the notes' formulas have found the nearest \
         hit in f32, the hit point e + d·t is carried into object space by M⁻¹ held in f64 \
         (inverted from M in f64 when the object is placed), the generic equation F of the part hit \
         (|P|² − 1 for the sphere) is evaluated there in f64, and t moves by one Newton step, \
         −F/(∇F·d′), rounded to f32 once. It does so only where the f32 root has lost digits that \
         matter: where the ray's origin is more than {} times farther from the object's centre than \
         from the hit (u·|e − c| against |d|·t), as from an eye near a planet; elsewhere a ray pays \
         one comparison, and the scenes above render as they would without it. The step starts \
         from the root the student's formulas found, so they still find every hit; the hits that \
         lose, and the feelers' hits, are left as they are; the plane z = 0, whose t subtracts \
         nothing, is not refined; and the f64 build does none of it (its images are the same, bit \
         for bit). On the planet the largest distance of a \
         hit point from the surface goes in f32 from {} to {} at R = {}, from {} to {} at R = {}, \
         for {:.1} ns per ray against {:.1} for the method alone (the table above; in the f64 build \
         {:.1} against {:.1}, the same work).",
        whitted::shapes::refine::FAR_FROM_CENTRE,
        at(small, Method::Generic),
        at(small, Method::Library),
        radius(small),
        at(big, Method::Generic),
        at(big, Method::Library),
        radius(big),
        narrow.cost(Method::Library),
        narrow.cost(Method::Generic),
        wide.cost(Method::Library),
        wide.cost(Method::Generic),
    ));
    w(String::new());
    w("{{#include tradeoff-f32-cost.md}}".into());
    w(String::new());
}
