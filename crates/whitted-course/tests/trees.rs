//! `whitted trees`: the known mistakes behind their switch (the mutated body and the reference
//! body, both whole, in one region), the shape and the features of a tree that choose the
//! pixels, and the command's errors.

mod common;

use common::root;

use serde_json::json;
use whitted_course::{handout, manifest, mistakes, trees};

/// In the sources with every hand-written mutant behind its switch, each mutated region
/// holds `if crate::__mutant::on("NAME") {` with the body as the mutant makes it, then the
/// reference body under `} else {`; nothing outside the regions changes.
#[test]
fn each_mutant_is_its_own_body_behind_its_switch() {
    let m = manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap();
    let mutants = mistakes::load(&root()).unwrap();
    assert!(mutants.len() >= 10);
    let regions = handout::regions(&root(), &m).unwrap();
    let switched = mistakes::switched_sources(&root(), &m, &mutants).unwrap();
    // each file with its switched regions put back as they were; an exercise with several
    // mutants holds them as one chain, `if … else if … else`, in the file's order
    let mut restored = switched.clone();
    let mut exercises: Vec<&str> = Vec::new();
    for mu in &mutants {
        if !exercises.contains(&mu.exercise.as_str()) {
            exercises.push(&mu.exercise);
        }
    }
    for exercise in exercises {
        let r = &regions[m.by_name(exercise).unwrap()];
        let mut expected = String::new();
        for (k, mu) in mutants
            .iter()
            .filter(|mu| mu.exercise == exercise)
            .enumerate()
        {
            let mutated = mistakes::mutated(r, mu).unwrap();
            assert_ne!(mutated, r.solution, "{}", mu.name);
            let keyword = if k == 0 { "if" } else { "} else if" };
            expected += &format!(
                "{}{keyword} crate::__mutant::on({:?}) {{\n{mutated}",
                r.indent, mu.name
            );
        }
        expected += &format!("{}}} else {{\n{}{}}}\n", r.indent, r.solution, r.indent);
        let text = restored.get_mut(&r.file).unwrap();
        assert!(
            text.contains(&expected),
            "exercise {exercise}: its switched region is not in {}",
            r.file.display()
        );
        *text = text.replacen(&expected, &r.solution, 1);
    }
    for (file, text) in &restored {
        let original = std::fs::read_to_string(root().join(file)).unwrap();
        assert!(
            *text == original,
            "{} changed outside the switched regions",
            file.display()
        );
    }
}

/// A mutant whose text is not in its exercise's body is refused, naming it.
#[test]
fn a_mutant_that_does_not_apply_is_named() {
    let m = manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap();
    let mut mutants = mistakes::load(&root()).unwrap();
    mutants.truncate(1);
    mutants[0].find = "no such code".into();
    let err = mistakes::switched_sources(&root(), &m, &mutants)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains(&mutants[0].name) && err.contains("`no such code` is not in"),
        "{err}"
    );
}

/// A tree of the floor lit by one light through its feeler and shadowed from another, with a
/// mirror ray that misses.
fn floor_tree(share: f64) -> serde_json::Value {
    json!({
        "pixel": [3, 1],
        "samples": [{ "ray": {
            "kind": "camera",
            "hit": {
                "object": 0, "name": "floor", "part": "surface", "entering": true,
                "lights": [
                    { "index": 0, "in_front": true, "share": 1.0,
                      "feeler": { "crossings": [] } },
                    { "index": 1, "in_front": true, "share": share,
                      "feeler": { "crossings": [{ "object": 4, "u": [0.2, 0.3] }] } }
                ],
                "stopped": [{ "kind": "transmitted", "why": "total_internal_reflection" }],
                "branches": [{ "kind": "mirror", "hit": null }]
            }
        }}]
    })
}

/// The shape of a tree changes with what its rays hit and cross, and with whether a share is
/// 1, 0 or between, not with the share's last bits; its features name each object and part,
/// each light's fate, each branch and stop, a miss and the quarter of the image.
#[test]
fn a_trees_shape_and_features_are_what_its_rays_meet() {
    let t = floor_tree(0.6);
    assert_eq!(
        trees::signature(&t),
        trees::signature(&floor_tree(0.600_000_02))
    );
    assert_ne!(trees::signature(&t), trees::signature(&floor_tree(0.0)));
    let f = trees::features(&t, (8, 4));
    let expected = [
        "`floor`, its surface, hit",
        "light 0: lit",
        "light 1: in a translucent shadow",
        "a transmitted ray stopped: total internal reflection",
        "a mirror ray",
        "a mirror ray misses every object",
        "the image's top left quarter",
    ];
    assert_eq!(f.iter().map(String::as_str).collect::<Vec<_>>(), {
        let mut e = expected.to_vec();
        e.sort_unstable();
        e
    });
    assert!(trees::features(&floor_tree(0.0), (8, 4)).contains("light 1: in shadow"));
}

/// Without the figures' manifest, `whitted trees` stops with one line and status 2.
#[test]
fn without_the_figures_manifest_trees_is_one_line_of_error() {
    let empty = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(empty.path().join("chapters")).unwrap();
    std::fs::copy(
        root().join(manifest::DEFAULT_PATH),
        empty.path().join(manifest::DEFAULT_PATH),
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_whitted"))
        .args(["trees", "--check", "--root"])
        .arg(empty.path())
        .output()
        .unwrap();
    let err = common::one_line_error(&out, "trees --check on an empty project");
    assert!(
        err.starts_with("error: ") && err.contains("figures.toml"),
        "{err}"
    );
}

/// The known mistakes of `chapters/mistakes.json` are told apart by their fingerprints alone:
/// each resembles itself and no other, so `learn`, which asks only the next exercise's, could
/// ask them all. Each names an exercise of the manifest and a hand-written mutant.
#[test]
fn each_known_mistake_resembles_itself_and_no_other() {
    let text = std::fs::read_to_string(root().join(trees::MISTAKES)).unwrap();
    let known: trees::Mistakes = serde_json::from_str(&text).unwrap();
    let m = manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap();
    let mutants = mistakes::load(&root()).unwrap();
    // the mutants no chapter picture or tree can show (their tests catch them): the notes'
    // textbook cone, which no picture uses, and a sample point upwards, the same at a pixel's
    // centre, where the trees' camera rays pass
    let unseen = ["cone-base-radius-one", "dy-upwards"];
    let mut named: Vec<&str> = known.mistakes.iter().map(|a| a.name.as_str()).collect();
    named.extend(unseen);
    named.sort_unstable();
    let mut all: Vec<&str> = mutants.iter().map(|mu| mu.name.as_str()).collect();
    all.sort_unstable();
    assert_eq!(
        named,
        all,
        "every hand-written mutant has a fingerprint in {} but those no tree shows",
        trees::MISTAKES
    );
    for a in &known.mistakes {
        assert!(m.by_name(&a.exercise).is_some(), "{}", a.exercise);
        let mu = mutants.iter().find(|mu| mu.name == a.name).unwrap();
        assert_eq!((&mu.exercise, &mu.why), (&a.exercise, &a.looks_like));
        for b in &known.mistakes {
            assert_eq!(
                a.fingerprint.resembles(&b.fingerprint),
                a.name == b.name,
                "{} and {}",
                a.name,
                b.name
            );
        }
    }
}
