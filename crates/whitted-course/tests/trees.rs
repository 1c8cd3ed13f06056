//! `whitted trees`: the known mistakes behind their switch (the mutated body and the reference
//! body, both whole, in one region), the shape and the features of a tree that choose the
//! pixels, and the command's errors.

mod common;

use common::root;

use whitted_course::{handout, manifest, mistakes, trees};
use whitted_syllabus::tree::{
    Crossing, FeelerNode, HitNode, LightNode, Number, Plain, RayKind, RayNode, RayTree, Sample,
    Stop, TreeFile,
};

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

/// Three equal numbers.
fn vector(x: f64) -> [Number; 3] {
    [Number(x); 3]
}

/// A ray of `kind` that meets `hit`; its numbers, which neither the shape nor the features
/// of a tree read, are zero.
fn ray(kind: RayKind, hit: Option<HitNode<Plain>>) -> RayNode<Plain> {
    RayNode {
        kind,
        origin: vector(0.0),
        direction: vector(0.0),
        t_min: Number(0.0),
        depth: 0,
        weight: Number(1.0),
        k: Number(1.0),
        colour: vector(0.0),
        hit,
    }
}

/// Light `index` seen in front of a hit, with the share `share` arriving, a feeler that
/// crosses `crossings` (each an object and its number of hits) or none, and the specular
/// factor ρs·max(r·v, 0)^f `specular` in the green channel.
fn light(
    index: usize,
    share: f64,
    crossings: Option<&[(usize, usize)]>,
    specular: f64,
) -> LightNode<Plain> {
    LightNode {
        index,
        position: vector(0.0),
        attenuation: Number(1.0),
        intensity: vector(1.0),
        diffuse: vector(0.0),
        specular: [Number(0.0), Number(specular), Number(0.0)],
        unshadowed: vector(0.0),
        in_front: true,
        feeler: crossings.map(|crossings| FeelerNode {
            origin: vector(0.0),
            u_min: Number(1e-4),
            crossings: crossings
                .iter()
                .map(|&(object, hits)| Crossing {
                    object,
                    name: None,
                    u: vec![Number(0.2); hits],
                    transmission: Number(0.5),
                })
                .collect(),
        }),
        share: Number(share),
        arriving: vector(0.0),
    }
}

/// A hit on the surface of object 0, named `name`, from outside, with `lights`, the stopped
/// branches `stopped` and the branches traced `branches`.
fn hit(
    name: &str,
    lights: Vec<LightNode<Plain>>,
    stopped: Vec<(RayKind, Stop)>,
    branches: Vec<RayNode<Plain>>,
) -> HitNode<Plain> {
    HitNode {
        object: 0,
        name: Some(name.into()),
        shape: "plane".into(),
        material: "matte".into(),
        part: "surface".into(),
        t: Number(1.0),
        point: vector(0.0),
        normal: vector(0.0),
        entering: true,
        ambient: None,
        lights,
        local: None,
        branches,
        stopped,
    }
}

/// The tree of pixel (3, 1) whose one sample's camera ray is `ray`.
fn tree_of(ray: RayNode<Plain>) -> RayTree<Plain> {
    RayTree {
        pixel: (3, 1),
        chapter: 5,
        view: "color".into(),
        colour: vector(0.0),
        encoding: "srgb".into(),
        rays: 1,
        samples: vec![Sample {
            index: 0,
            position: (Number(0.5), Number(0.5)),
            ray,
        }],
    }
}

/// A tree of the floor lit by one light through its feeler and shadowed from another, with a
/// mirror ray that misses.
fn floor_tree(share: f64) -> RayTree<Plain> {
    tree_of(ray(
        RayKind::Camera,
        Some(hit(
            "floor",
            vec![
                light(0, 1.0, Some(&[]), 0.0),
                light(1, share, Some(&[(4, 2)]), 0.0),
            ],
            vec![(RayKind::Transmitted, Stop::TotalInternalReflection)],
            vec![ray(RayKind::Mirror, None)],
        )),
    ))
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

/// A light whose specular factor ρs·max(r·v, 0)^f reaches [`trees::HIGHLIGHT`] in a channel,
/// and whose light arrives (share > 0), shows a highlight; a faint one, or one in shadow, does
/// not, so the pixels kept hold a highlight a mistake in r or in the highlight changes.
#[test]
fn a_highlight_that_arrives_is_a_feature() {
    let tree = |specular: f64, share: f64| {
        tree_of(ray(
            RayKind::Camera,
            Some(hit(
                "ball",
                vec![light(1, share, None, specular)],
                Vec::new(),
                Vec::new(),
            )),
        ))
    };
    let highlight = "light 1: a highlight";
    assert!(trees::features(&tree(0.3, 1.0), (8, 4)).contains(highlight));
    assert!(trees::features(&tree(trees::HIGHLIGHT, 0.5), (8, 4)).contains(highlight));
    assert!(!trees::features(&tree(4e-5, 1.0), (8, 4)).contains(highlight));
    assert!(!trees::features(&tree(0.3, 0.0), (8, 4)).contains(highlight));
}

/// Chapter 3's kept trees hold a real highlight: a light whose specular factor ρs·max(r·v, 0)^f
/// is at least [`trees::HIGHLIGHT`], so a wrong r or a wrong highlight changes a number `learn`
/// compares (not only factors of 10⁻⁵ at a highlight's edge).
#[test]
fn chapter_3s_trees_hold_a_highlight() {
    let path = root().join(trees::trees_file(3).unwrap());
    let file = TreeFile::<Plain>::parse(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let largest = file
        .pixels
        .iter()
        .flat_map(|p| &p.tree.tree.samples)
        .filter_map(|s| s.ray.hit.as_ref())
        .flat_map(|h| &h.lights)
        .flat_map(|l| l.specular)
        .map(|x| x.0)
        .fold(0.0, f64::max);
    assert!(
        largest >= trees::HIGHLIGHT,
        "the largest specular factor of {}: {largest}, expected at least {}",
        path.display(),
        trees::HIGHLIGHT
    );
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
/// ask them all — but for the pairs of [`ALIKE`], mistakes of two exercises that change the
/// same numbers of the trees in the same way, which `learn` tells apart by the exercise that
/// fails first. Each names an exercise of the manifest and a hand-written mutant.
/// The known mistakes whose fingerprints resemble each other, and why no tree can tell them
/// apart: each is in its own exercise, and the student is on the first one that fails.
const ALIKE: [(&str, &str, &str); 2] = [
    (
        "mirror-sign",
        "highlight-r-sign",
        "r's sign turned in mirror() or in the highlight gives the same −r: the trees hold the \
         highlight, not r",
    ),
    (
        "normals-by-m",
        "cone-normal-z-minus-one",
        "both turn the cone's normal, at the one cone pixel kept; chapter 2's picture shows no \
         normal",
    ),
];

#[test]
fn each_known_mistake_resembles_itself_and_no_other() {
    let text = std::fs::read_to_string(root().join(trees::MISTAKES)).unwrap();
    let known: trees::Mistakes = serde_json::from_str(&text).unwrap();
    let m = manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap();
    let mutants = mistakes::load(&root()).unwrap();
    // the mutants no chapter picture or tree can show (their tests catch them): the notes'
    // textbook cone, which no picture uses, a sample point upwards, the same at a pixel's
    // centre, where the trees' camera rays pass, and a sphere never left, which chapter 2's
    // camera rays, all outside every sphere, cannot tell (chapter 5's picture does)
    let unseen = ["cone-base-radius-one", "dy-upwards", "sphere-never-left"];
    let mut named: Vec<&str> = known
        .mistakes
        .iter()
        .filter(|a| a.fingerprint.is_some())
        .map(|a| a.name.as_str())
        .collect();
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
    let fingerprinted = known.mistakes.iter().filter(|a| a.fingerprint.is_some());
    for a in fingerprinted.clone() {
        assert!(m.by_name(&a.exercise).is_some(), "{}", a.exercise);
        let mu = mutants.iter().find(|mu| mu.name == a.name).unwrap();
        assert_eq!((&mu.exercise, &mu.why), (&a.exercise, &a.looks_like));
        for b in fingerprinted.clone() {
            let alike = ALIKE.iter().find(|(x, y, _)| {
                (*x, *y) == (a.name.as_str(), b.name.as_str())
                    || (*y, *x) == (a.name.as_str(), b.name.as_str())
            });
            if let Some((_, _, why)) = alike {
                assert_ne!(a.exercise, b.exercise, "{} and {}: {why}", a.name, b.name);
                continue;
            }
            let (fa, fb) = (a.fingerprint.as_ref(), b.fingerprint.as_ref());
            assert_eq!(
                fa.zip(fb).is_some_and(|(fa, fb)| fa.resembles(fb)),
                a.name == b.name,
                "{} and {}",
                a.name,
                b.name
            );
        }
    }
}

/// Every hand-written mutant moves a kept number or a pixel of its chapter (it has a
/// fingerprint in `chapters/mistakes.json` with a differing tree or pixel), or says why its
/// chapter's scene cannot show it; `whitted trees --check` names any that does neither, any that
/// says so but shows after all, and any fingerprint of no mutant.
#[test]
fn each_mistake_moves_a_kept_number_or_a_pixel_or_says_why_not() {
    let mutants = mistakes::load(&root()).unwrap();
    let known = whitted_learn::trees::load_mistakes(&root());
    let problems = trees::mistakes_unseen(&mutants, &known);
    assert!(problems.is_empty(), "{problems:#?}");
    let unseen: Vec<&str> = mutants
        .iter()
        .filter(|m| m.unseen.is_some())
        .map(|m| m.name.as_str())
        .collect();
    assert_eq!(
        unseen,
        ["cone-base-radius-one", "dy-upwards", "sphere-never-left"]
    );

    // a mutant without its fingerprint, one whose reason is stale, a fingerprint of no mutant
    let shown = &known[0];
    let hidden = mutants.iter().find(|m| m.unseen.is_some()).unwrap();
    let mut stale = hidden.clone();
    stale.name = shown.name.clone();
    let mut orphan = shown.clone();
    orphan.name = "no-such-mutant".into();
    let without: Vec<_> = known
        .iter()
        .filter(|k| k.name != known[1].name)
        .cloned()
        .collect();
    let cases = [
        (
            trees::mistakes_unseen(&mutants, &without),
            format!(
                "mistake {} ({}): no kept number and no pixel of its chapter moves",
                known[1].name, known[1].exercise
            ),
        ),
        (
            trees::mistakes_unseen(&[stale], std::slice::from_ref(shown)),
            format!(
                "mistake {} ({}): its chapter shows it now",
                shown.name, hidden.exercise
            ),
        ),
        (
            trees::mistakes_unseen(&mutants, &[known.clone(), vec![orphan]].concat()),
            "mistake no-such-mutant in chapters/mistakes.json is no hand-written mutant".into(),
        ),
    ];
    for (problems, expected) in cases {
        assert!(
            problems.len() == 1 && problems[0].starts_with(&expected),
            "computed {problems:?}, expected one problem starting {expected:?}"
        );
    }
}
