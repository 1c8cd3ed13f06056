//! The scaling scene (`scatter`): seeded, and written the same for POV-Ray.

use whitted::real::{Real, Vec3, real};
use whitted::scene::parse;
use whitted::scene::scatter;

/// The scaling scene is reproducible: same N and seed, same text; another seed, another scene.
#[test]
fn scatter_scenes_are_seeded() {
    assert_eq!(
        scatter::scene_toml(50, 1, 64, 36),
        scatter::scene_toml(50, 1, 64, 36)
    );
    assert_ne!(
        scatter::scene_toml(50, 1, 64, 36),
        scatter::scene_toml(50, 2, 64, 36)
    );
    let s = parse(&scatter::scene_toml(1000, 1, 64, 36), "s.toml").unwrap();
    assert_eq!(s.objects.len(), 1001);
    assert!((scatter::radius(10) / scatter::radius(1000) - 10.0).abs() < 1e-9);
}

/// `scatter --pov` writes the very scene whitted renders: the same spheres in the same
/// order, each centre with z negated (POV-Ray is left-handed), the same radius, and mirrors
/// where the TOML has them.
#[test]
fn scatter_writes_the_same_scene_for_povray() {
    for layout in [scatter::Layout::Field, scatter::Layout::Fog] {
        let scene = parse(&scatter::scene_toml_with(40, 5, 64, 36, layout), "s.toml").unwrap();
        let pov = scatter::scene_pov(40, 5, layout);
        let spheres: Vec<&str> = pov.lines().filter(|l| l.starts_with("sphere")).collect();
        assert_eq!(spheres.len(), 40);
        // object 0 is the floor; the spheres follow in the order they were drawn
        for (line, object) in spheres.iter().zip(&scene.objects[1..]) {
            let numbers: Vec<f64> = line
                .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                .filter_map(|w| w.parse().ok())
                .collect();
            let [x, y, z, r] = numbers[..] else {
                panic!("{line}")
            };
            let centre = object.placement.m().transform_point3(Vec3::ZERO);
            let radius = object.placement.m().transform_vector3(Vec3::X).length();
            let near = |a: f64, b: Real| (real(a) - b).abs() < 1e-4 * (1.0 + b.abs());
            assert!(
                near(x, centre.x) && near(y, centre.y) && near(-z, centre.z),
                "{line}"
            );
            assert!(near(r, radius), "{line}");
            let mirror = scene.materials[object.material].reflection > 0.0;
            assert_eq!(line.contains("Mirror"), mirror, "{line}");
        }
    }
}
