//! Convex polyhedra: where a ray crosses a facet's plane, clipping a ray by the facets, the presets ("Convex Polyhedra").

use super::*;
use whitted::shapes::polyhedron;

/// "Convex Polyhedra" (erratum): the notes print t = d − n·e / n·d; by precedence that is
/// d − (n·e)/(n·d), whose point is not on the facet. t = (d − n·e)/(n·d) is.
#[test]
fn ex_facet_crossing_facet_t_is_d_minus_n_dot_e_all_over_n_dot_d() {
    let facet = polyhedron::Facet::new(Vec3::Z, 1.0).expect("the plane z = 1 is a facet");
    let r = ray([0.0, 0.0, 5.0], [0.0, 0.0, -2.0]);
    let as_printed = facet.d() - facet.normal().dot(r.origin) / facet.normal().dot(r.dir); // 1 − 5/(−2) = 3.5
    let right = polyhedron::facet_t(&facet, &r); // (1 − 5)/(−2) = 2
    let of = "of the ray from (0, 0, 5) along (0, 0, −2) with the facet z = 1 (n = z, d = 1)";
    assert_near(&format!("t = (d − n·e)/(n·d) {of}"), right, 2.0, TOL);
    assert_near(
        &format!("n·r(t) at that t {of}; expected d, on the facet"),
        facet.normal().dot(r.at(right)),
        facet.d(),
        TOL,
    );
    assert_near(
        &format!("the notes' d − n·e/n·d {of}"),
        as_printed,
        3.5,
        TOL,
    );
    let z = facet.normal().dot(r.at(as_printed));
    assert!(
        (z - facet.d()).abs() > 1.0,
        "n·r(t) at the notes' t = {as_printed} is {z}: not on the facet, as it should not be"
    );
}

/// "Convex Polyhedra": the cube [−1, 1]³ along z: enters facet +z (index 4) at t = 4, leaves
/// facet −z (index 5) at t = 6, each with its facet's outward normal.
#[test]
fn ex_hit_polyhedron_cube_entering_and_leaving_facets() {
    let what = "from (0.2, 0.3, 5) along −z through the cube";
    let hits = Polyhedron::cube().intersect(&ray([0.2, 0.3, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(what, &hits, &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))]);
    assert_normal(what, &hits, 0, Vec3::Z, TOL);
    assert_normal(what, &hits, 1, Vec3::NEG_Z, TOL);
    assert_entering(what, &hits, &[true, false]);
}

/// "Convex Polyhedra" (erratum: the table swaps inside and outside): with n·d = 0, the notes'
/// own rule (Q·n < d is inside) makes d − n·e < 0 *outside* — a miss — and d − n·e > 0 inside,
/// where the facet does not stop the ray. The notes' table says the opposite.
#[test]
fn ex_hit_polyhedron_ray_parallel_to_a_facet_misses_outside_and_passes_inside() {
    let cube = Polyhedron::cube();
    // parallel to the facet y = 1 (index 2), at y = 2: d − n·e = 1 − 2 < 0, outside
    let facet = Polyhedron::cube().facets()[2];
    let e = vec3(0.0, 2.0, 5.0);
    let (d, n_e) = (facet.d(), facet.normal().dot(e));
    assert!(
        d - n_e < 0.0 && n_e > d,
        "the facet y = 1 has d = {d} and n·e = {n_e} at e = {e}: d − n·e < 0, Q·n > d, outside \
         by the notes' rule"
    );
    let outside = cube.intersect(&ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0]));
    assert!(
        outside.is_empty(),
        "the ray from (0, 2, 5) along −z, parallel to the facet y = 1 and outside it, misses \
         the cube: hits {outside:?}, expected none"
    );
    // parallel to it at y = 0.5 (inside its half-space)
    let hits = cube.intersect(&ray([0.0, 0.5, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(
        "from (0, 0.5, 5) along −z, parallel to the facet y = 1 and inside it",
        &hits,
        &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))],
    );
}

/// "Convex Polyhedra": the solid is closed (n·P ≤ d), so a ray lying in the plane of a facet
/// (n·d = 0 and n·e = d) is not outside that facet: along the cube's face y = 1 it enters at
/// the top (t = 4) and leaves at the bottom (t = 6). Taking n·e ≥ d for "outside" misses it.
#[test]
fn ex_hit_polyhedron_a_ray_along_a_face_touches_the_closed_solid() {
    let hits = Polyhedron::cube().intersect(&ray([0.0, 1.0, 5.0], [0.0, 0.0, -1.0]));
    assert_hits(
        "from (0, 1, 5) along −z, in the plane of the facet y = 1",
        &hits,
        &[(4.0, Part::Facet(4)), (6.0, Part::Facet(5))],
    );
}

/// "Convex Polyhedra": in the half-space z ≤ 0 (one facet: `Polyhedron::new` takes any facets,
/// scenes only closed solids), a ray from inside going up meets no facet that raises t_near,
/// which stays −∞; its one hit is the finite bound t_far = 2, where it leaves (entering =
/// false). From above, going down, the one hit enters.
#[test]
fn ex_hit_polyhedron_with_only_a_leaving_bound_the_one_hit_leaves() {
    let half_space = Polyhedron::new(vec![
        polyhedron::Facet::new(Vec3::Z, 0.0).expect("the plane z = 0 is a facet"),
    ]);
    let going_up = "from (0, 0, −2) along +z, out of the half-space z ≤ 0";
    let up = half_space.intersect(&ray([0.0, 0.0, -2.0], [0.0, 0.0, 1.0]));
    assert_hits(going_up, &up, &[(2.0, Part::Facet(0))]);
    assert_entering(going_up, &up, &[false]);
    let going_down = "from (0, 0, 2) along −z, into the half-space z ≤ 0";
    let down = half_space.intersect(&ray([0.0, 0.0, 2.0], [0.0, 0.0, -1.0]));
    assert_hits(going_down, &down, &[(2.0, Part::Facet(0))]);
    assert_entering(going_down, &down, &[true]);
}

/// "Convex Polyhedra": the octahedron |x| + |y| + |z| ≤ 1 along x at y = 0.25, z = 0.1 spans
/// |x| ≤ 0.65: t = 4.35 through the facet with normal (1, 1, 1)/√3.
#[test]
fn ex_hit_polyhedron_octahedron_hits_through_its_facets() {
    let what = "from (5, 0.25, 0.1) along −x through the octahedron";
    let hits = Polyhedron::octahedron().intersect(&ray([5.0, 0.25, 0.1], [-1.0, 0.0, 0.0]));
    let t: Vec<Real> = hits.as_slice().iter().map(|h| h.t).collect();
    assert!(
        t.len() == 2 && (t[0] - 4.35).abs() <= 10.0 * TOL && (t[1] - 5.65).abs() <= 10.0 * TOL,
        "the hits' t of the ray {what}: computed {t:?}, expected [4.35, 5.65] (tolerance {:e})",
        10.0 * TOL
    );
    let k = 1.0 / (3.0 as Real).sqrt();
    assert_normal(what, &hits, 0, vec3(1.0, 1.0, 1.0) * k, TOL);
    assert_normal(what, &hits, 1, vec3(-1.0, 1.0, 1.0) * k, TOL);
}

/// "Convex Polyhedra": the tetrahedron with vertices (1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1),
/// along z at x = 0.2, spans z ∈ [−0.8, 0.8].
#[test]
fn ex_hit_polyhedron_tetrahedron_hits_through_its_facets() {
    let what = "from (0.2, 0, 5) along −z through the tetrahedron";
    let hits = Polyhedron::tetrahedron().intersect(&ray([0.2, 0.0, 5.0], [0.0, 0.0, -1.0]));
    let k = 1.0 / (3.0 as Real).sqrt();
    assert_hits(what, &hits, &[(4.2, Part::Facet(2)), (5.8, Part::Facet(3))]);
    assert_normal(what, &hits, 0, vec3(1.0, -1.0, 1.0) * k, TOL);
    assert_normal(what, &hits, 1, vec3(1.0, 1.0, -1.0) * k, TOL);
    // every preset's vertices satisfy n·P ≤ d with equality on three or more facets
    let vertices = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    for v in vertices {
        let p = vec3(v[0], v[1], v[2]);
        let on = Polyhedron::tetrahedron()
            .facets()
            .iter()
            .filter(|f| (f.normal().dot(p) - f.d()).abs() <= TOL)
            .count();
        assert_eq!(on, 3, "the tetrahedron's facets through its vertex {p}");
    }
}

/// "Convex Polyhedra": a ray across an edge of the cube enters (facet +z) and leaves (facet +x)
/// at the same t: t_near = t_far, one grazing hit; a little further out it misses
/// (t_near > t_far).
#[test]
fn ex_hit_polyhedron_polyhedron_ray_across_an_edge_grazes_once() {
    let cube = Polyhedron::cube();
    let hits = cube.intersect(&ray([0.0, 0.0, 2.0], [1.0, 0.0, -1.0]));
    assert_hits(
        "from (0, 0, 2) along (1, 0, −1), across the cube's edge x = z = 1",
        &hits,
        &[(1.0, Part::Facet(4))],
    );
    let beyond = cube.intersect(&ray([0.5, 0.0, 2.5], [1.0, 0.0, -1.0]));
    assert!(
        beyond.is_empty(),
        "the ray from (0.5, 0, 2.5) along (1, 0, −1) passes beyond the edge (t_near > t_far): \
         hits {beyond:?}, expected none"
    );
}

/// "Convex Polyhedra": the presets are closed solids; their corners are where three facets meet.
#[test]
fn presets_are_closed_solids_with_the_expected_corners() {
    let distinct = |p: &Polyhedron| {
        let mut v: Vec<Vec3> = Vec::new();
        for q in p.vertices() {
            if v.iter().all(|w| (*w - q).length() > 1e3 * TOL) {
                v.push(q);
            }
        }
        v
    };
    for (p, corners) in [
        (Polyhedron::cube(), 8),
        (Polyhedron::tetrahedron(), 4),
        (Polyhedron::octahedron(), 6),
    ] {
        assert_eq!(
            p.check(),
            Ok(()),
            "the preset with {corners} corners is a closed solid"
        );
        let v = distinct(&p);
        assert_eq!(v.len(), corners, "the preset's corners {v:?}");
        for q in v {
            // corners on the unit cube's surface
            assert_near(
                &format!("max(|x|, |y|, |z|) of the corner {q}"),
                q.abs().max_element(),
                1.0,
                1e3 * TOL,
            );
        }
    }
}

/// "Convex Polyhedra": facets that leave a direction open, contradict each other, or squeeze
/// the solid flat describe no polyhedron; `check` says which.
#[test]
fn open_empty_or_flat_facet_sets_are_not_polyhedra() {
    let from = |rows: &[[f64; 4]]| {
        Polyhedron::new(
            rows.iter()
                .map(|r| {
                    polyhedron::Facet::new(vec3(r[0], r[1], r[2]), r[3] as Real)
                        .unwrap_or_else(|| panic!("{r:?} is a facet"))
                })
                .collect(),
        )
    };
    let open = from(&[
        [0.0, -1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0, 1.0],
        [-1.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 0.5],
    ]);
    let open = open.check();
    assert!(
        open.as_ref().is_err_and(|e| e.contains("unbounded")),
        "check of facets open towards +y: {open:?}, expected an error saying unbounded"
    );
    let empty = from(&[
        [1.0, 0.0, 0.0, -1.0],
        [-1.0, 0.0, 0.0, -1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, -1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [0.0, 0.0, -1.0, 1.0],
    ]);
    let empty = empty.check();
    assert!(
        empty.as_ref().is_err_and(|e| e.contains("no solid")),
        "check of facets that contradict each other: {empty:?}, expected an error saying no solid"
    );
    let flat = from(&[
        [1.0, 0.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, -1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [0.0, 0.0, -1.0, 1.0],
    ]);
    let flat = flat.check();
    assert!(
        flat.as_ref().is_err_and(|e| e.contains("flat")),
        "check of facets squeezing x to 0: {flat:?}, expected an error saying flat"
    );
}

/// "Convex Polyhedra": a facet with n·d < 0 is crossed from outside to inside, one with n·d > 0
/// from inside to outside. On the triangular prism y ≥ 0, x + y ≤ 2, −x + y ≤ 2, |z| ≤ 1
/// (facets 0–4, normals (0, −1, 0), (1, 1, 0)/√2, (−1, 1, 0)/√2, ±z; the slanted facets have
/// d = 2/√2), t = (d − n·e)/(n·d), written below with the √2 of the slanted facets cancelled:
/// - e = (5, 0.5, 0), d = (−1, 0, 0): facet 1 has n·d = −1/√2 < 0, t = (2 − 5.5)/(−1) = 3.5
///   (x = 1.5), entering; facet 2 has n·d = 1/√2 > 0, t = (2 − (−4.5))/1 = 6.5 (x = −1.5),
///   leaving; facet 0 and the caps are parallel with e inside them.
/// - e = (0.5, −3, 0.2), d = (0, 2, 0): facet 0 n·d = −2, t = (0 − 3)/(−2) = 1.5 (y = 0),
///   entering; facet 1 n·d = 2/√2, t = (2 − (−2.5))/2 = 2.25 (y = 1.5), leaving; facet 2
///   t = (2 − (−3.5))/2 = 2.75 comes later and does not bound the ray.
/// - from inside, e = (0.5, 0.5, 0), d = (1, 0, 0): entering through facet 2 behind the origin
///   at t = (2 − 0)/(−1) = −2 (x = −1.5), leaving through facet 1 at t = (2 − 1)/1 = 1.
#[test]
fn ex_hit_polyhedron_polyhedron_enters_where_n_dot_d_is_negative_and_leaves_where_positive() {
    let facet = |n: [f64; 3], d: f64| {
        polyhedron::Facet::new(vec3(n[0], n[1], n[2]), d as Real)
            .unwrap_or_else(|| panic!("n = {n:?}, d = {d} is a facet"))
    };
    let prism = Polyhedron::new(vec![
        facet([0.0, -1.0, 0.0], 0.0),
        facet([1.0, 1.0, 0.0], 2.0),
        facet([-1.0, 1.0, 0.0], 2.0),
        facet([0.0, 0.0, 1.0], 1.0),
        facet([0.0, 0.0, -1.0], 1.0),
    ]);
    assert_eq!(
        prism.check(),
        Ok(()),
        "the triangular prism is a closed solid"
    );
    let k = 1.0 / (2.0 as Real).sqrt();
    let (n1, n2) = (vec3(1.0, 1.0, 0.0) * k, vec3(-1.0, 1.0, 0.0) * k);
    let cases = [
        (
            ray([5.0, 0.5, 0.0], [-1.0, 0.0, 0.0]),
            [(3.5, 1, n1), (6.5, 2, n2)],
        ),
        (
            ray([0.5, -3.0, 0.2], [0.0, 2.0, 0.0]),
            [(1.5, 0, Vec3::NEG_Y), (2.25, 1, n1)],
        ),
        (
            ray([0.5, 0.5, 0.0], [1.0, 0.0, 0.0]),
            [(-2.0, 2, n2), (1.0, 1, n1)],
        ),
    ];
    for (r, expected) in cases {
        let what = format!("from {} along {} through the prism", r.origin, r.dir);
        let hits = prism.intersect(&r);
        assert_hits(
            &what,
            &hits,
            &[
                (expected[0].0, Part::Facet(expected[0].1)),
                (expected[1].0, Part::Facet(expected[1].1)),
            ],
        );
        assert_normal(&what, &hits, 0, expected[0].2, TOL);
        assert_normal(&what, &hits, 1, expected[1].2, TOL);
        let [enter, leave] = [nth(&hits, 0, &what), nth(&hits, 1, &what)];
        assert_entering(
            &format!(
                "{what} (n·d = {} then {})",
                enter.normal.dot(r.dir),
                leave.normal.dot(r.dir)
            ),
            &hits,
            &[true, false],
        );
    }
}
