//! The reference's ray trees as data (`chapters/chNN_name/trees.json`) and the comparison that
//! finds where a tree first parts from them (`--against`, `cargo learn`): the trees shipped are
//! the renderer's in either precision (an f32 build of a correct road reports no difference);
//! a number that moves beyond its tolerance, or a tree of another shape, is reported at its
//! node with both values; and the functions each quantity names are the manifest's exercises,
//! every one of them.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use whitted::render::inspect::against::{TreeFile, apply, first_difference, settings_of};
use whitted::render::inspect::provenance::{Place, Quantity};
use whitted::render::inspect::tree::Settings;
use whitted::render::inspect::walk::PlainTree;
use whitted::render::{Chapter, Options, RayKind, Tracer, View};
use whitted::scene::{Scene, load_parts};
use whitted_syllabus::tree::{Crossing, HitNode, Number, Plain, Stop};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn scene(chapter: Chapter) -> Scene {
    load_parts(&root().join(chapter.about().scene()), chapter.reads()).unwrap()
}

/// The functions of `chapters/formulas.toml`, as its entries spell them.
fn manifest_functions() -> BTreeSet<String> {
    let text = std::fs::read_to_string(root().join("chapters/formulas.toml")).unwrap();
    let doc: toml::Value = toml::from_str(&text).unwrap();
    doc["formula"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["function"].as_str().unwrap().to_string())
        .collect()
}

/// Every function a quantity of the tree names, over every place it can sit.
fn every_named_function() -> BTreeSet<&'static str> {
    let shapes = ["sphere", "plane", "cylinder", "cone", "polyhedron"];
    let mut out = BTreeSet::new();
    for q in Quantity::ALL {
        for chapter in Chapter::ALL {
            for view in View::ALL {
                for ray in [RayKind::Camera, RayKind::Mirror, RayKind::Transmitted] {
                    for shape in shapes {
                        let place = Place {
                            chapter,
                            view,
                            ray,
                            shapes: &[shape],
                        };
                        out.extend(q.computed_by(&place));
                    }
                }
            }
        }
    }
    out
}

/// Where each number comes from is the manifest's to say, and it cannot rot: every entry of
/// every formula's `computes` list names a quantity of the tree and places it can sit, every
/// exercise computes some number of the tree (so `cargo learn` can point at any of them), and
/// every function a quantity names is a function of the manifest.
#[test]
fn every_exercise_computes_a_quantity_of_the_tree_and_says_which() {
    let entries = whitted::render::inspect::provenance::manifest_entries();
    let unread: Vec<String> = entries
        .iter()
        .filter_map(|(f, c, read)| read.as_ref().err().map(|why| format!("{f}: {c:?}: {why}")))
        .collect();
    assert!(
        unread.is_empty(),
        "computes entries of chapters/formulas.toml that do not read: {unread:?}"
    );
    let manifest = manifest_functions();
    let named = every_named_function();
    let unknown: Vec<&&str> = named.iter().filter(|f| !manifest.contains(**f)).collect();
    assert!(
        unknown.is_empty(),
        "functions named by render::inspect::provenance but not in chapters/formulas.toml: {unknown:?}"
    );
    let unnamed: Vec<&String> = manifest
        .iter()
        .filter(|f| !named.contains(f.as_str()))
        .collect();
    assert!(
        unnamed.is_empty(),
        "exercises whose `computes` names no quantity of the tree anywhere: {unnamed:?}"
    );
}

/// A `computes` entry reads as its quantity and places, and one that names no quantity or no
/// place is refused with the word it does not know.
#[test]
fn a_computes_entry_reads_as_its_quantity_and_places() {
    use whitted::render::inspect::provenance::{Computes, Where};
    let c = Computes::parse("t/sphere|cone").unwrap();
    assert_eq!(c.quantity, Quantity::T);
    assert_eq!(c.places, [Where::Shape("sphere"), Where::Shape("cone")]);
    let at = |shapes: &'static [&'static str]| Place {
        chapter: Chapter::Shadows,
        view: View::Color,
        ray: RayKind::Camera,
        shapes,
    };
    assert!(c.covers(Quantity::T, &at(&["cone"])));
    assert!(!c.covers(Quantity::T, &at(&["plane"])), "a plane's t");
    assert!(!c.covers(Quantity::Point, &at(&["cone"])), "a cone's P");
    assert_eq!(
        Computes::parse("tee/sphere").unwrap_err(),
        "`tee` is no quantity of the ray tree"
    );
    assert_eq!(
        Computes::parse("t/torus").unwrap_err(),
        "`torus` is no place of `t/torus`"
    );
}

/// Each chapter's trees file holds the trees this renderer traces at its pixels, within the
/// comparison's tolerances: in f64, the build that wrote them, and in f32, where a correct
/// road must report no difference (`cargo test --features f32`). The file says it is the
/// chapter's, and keeps a few pixels.
#[test]
fn each_chapters_trees_are_the_renderers_in_either_precision() {
    for chapter in Chapter::ALL {
        let about = chapter.about();
        let path = root()
            .join("chapters")
            .join(about.binary)
            .join("trees.json");
        let file = TreeFile::read(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(file.settings.chapter, chapter, "{}", path.display());
        assert!(
            (3..=20).contains(&file.trees.len()),
            "{}: {} pixels",
            path.display(),
            file.trees.len()
        );
        let s = scene(chapter);
        let compared = file.against(&s, &Options::for_scene(&s, chapter)).unwrap();
        assert_eq!(compared.len(), file.trees.len());
        for c in &compared {
            assert!(c.difference.is_none(), "{}: {}", path.display(), c.line());
        }
    }
}

/// A tree of pixel (x, y) of `chapter`'s scene at 240 pixels wide, as plain types (as
/// `--against` reads it), with the scene.
fn tree(chapter: Chapter, x: u32, y: u32) -> (PlainTree, Scene) {
    let s = scene(chapter);
    let mut o = Options::for_scene(&s, chapter);
    o.height = o.height * 240 / o.width;
    o.width = 240;
    let t = Tracer::new(&s, &o).inspect(x, y).plain().unwrap();
    (t.tree, s)
}

/// The first difference of `mine` from `reference`, as `--against` reports it.
fn first(
    mine: &PlainTree,
    reference: &PlainTree,
    s: &Scene,
) -> Option<whitted::render::inspect::against::Difference> {
    let objects: Vec<&'static str> = s.objects.iter().map(|o| o.shape.name()).collect();
    first_difference(mine, reference, &move |i| objects.get(i).copied())
}

/// The hit of the camera ray of a tree's first sample.
fn hit(t: &mut PlainTree) -> &mut HitNode<Plain> {
    t.samples[0].ray.hit.as_mut().expect("the camera ray hits")
}

/// A number of the tree moved beyond its tolerance is the first difference, named by its
/// node and symbol with both values and the functions that computed it; a move within the
/// tolerance (what f32 rounding does) is none.
#[test]
fn a_number_moved_is_found_at_its_node_with_both_values() {
    // a point of the floor, lit by lights 0 and 1 through their feelers
    let (reference, s) = tree(Chapter::Shadows, 20, 140);
    assert_eq!(hit(&mut reference.clone()).name.as_deref(), Some("floor"));
    assert_eq!(first(&reference, &reference, &s), None);

    let mut mine = reference.clone();
    let t = hit(&mut mine).t.0;
    hit(&mut mine).t = Number(t * (1.0 + 1e-7));
    assert_eq!(first(&mine, &reference, &s), None, "within the tolerance");
    hit(&mut mine).t = Number(t * 1.01);
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::T);
    assert_eq!(d.path_text(), "camera ray → hit `floor`");
    assert_eq!(d.reference, whitted::render::inspect::provenance::number(t));
    assert_eq!(
        d.computed,
        whitted::render::inspect::provenance::number(t * 1.01)
    );
    assert!(d.functions.contains(&"shapes::plane::intersect"), "{d:?}");
    assert!(d.functions.contains(&"ray::Ray::transformed"), "{d:?}");

    // light 1's diffuse factor
    let mut mine = reference.clone();
    hit(&mut mine).lights[1].diffuse[0] = Number(0.5);
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::Diffuse);
    assert_eq!(d.path_text(), "camera ray → hit `floor` → light 1");
    assert_eq!(d.symbol, "ρd·max(n·s, 0)");
    assert_eq!(d.functions, ["shading::lambert", "shading::phong"]);
    assert!(d.text().contains("(the reference: ("), "{}", d.text());
}

/// A tree of another shape differs where the shapes part: another object hit (or none), an
/// object more along a feeler, a transmitted ray where the reference has total internal
/// reflection.
#[test]
fn a_tree_of_another_shape_differs_where_the_shapes_part() {
    let (reference, s) = tree(Chapter::Shadows, 20, 140);
    // nothing hit
    let mut mine = reference.clone();
    mine.samples[0].ray.hit = None;
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::Object);
    assert_eq!(
        (d.computed.as_str(), d.reference.as_str()),
        ("nothing", "`floor`")
    );
    assert!(d.functions.contains(&"shapes::nearer"), "{d:?}");
    // the box (object 3) more along light 0's feeler: the box's intersection is named
    let mut mine = reference.clone();
    let feeler = hit(&mut mine).lights[0]
        .feeler
        .as_mut()
        .expect("light 0's feeler");
    feeler.crossings.push(Crossing {
        object: 3,
        name: Some("box".into()),
        u: vec![Number(0.5)],
        transmission: Number(0.0),
    });
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::Crossed);
    assert_eq!(d.path_text(), "camera ray → hit `floor` → light 0 → feeler");
    assert!(d.computed.contains("`box`"), "{d:?}");
    assert!(d.functions.contains(&"shadow::between"), "{d:?}");
    assert!(
        d.functions.contains(&"shapes::Polyhedron::intersect"),
        "{d:?}"
    );

    // chapter 5: a hit whose transmitted ray is traced, told it stopped by total internal
    // reflection
    let (reference, s) = tree(Chapter::ReflectionRefraction, 139, 65);
    let mut mine = reference.clone();
    let h = hit(&mut mine);
    let before = h.branches.len();
    h.branches.retain(|b| b.kind != RayKind::Transmitted);
    assert!(h.branches.len() < before, "{h:?}");
    h.stopped = vec![(RayKind::Transmitted, Stop::TotalInternalReflection)];
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::Branches);
    assert_eq!(d.symbol, "its transmitted ray");
    assert_eq!(
        (d.computed.as_str(), d.reference.as_str()),
        ("not traced: total internal reflection", "traced")
    );
    assert!(
        d.functions.contains(&"optics::critical_angle_sine"),
        "{d:?}"
    );
}

/// The settings a trees file records are read back as written; a wrong one is named.
#[test]
fn settings_are_read_back_as_written_and_a_wrong_one_is_named() {
    let s = scene(Chapter::ReflectionRefraction);
    let mut o = Options::for_scene(&s, Chapter::ReflectionRefraction);
    o.width = 240;
    o.height = 160;
    o.max_depth = 3;
    let settings = settings_of(&o);
    let json = serde_json::to_value(&settings).unwrap();
    assert_eq!(
        serde_json::from_value::<Settings>(json.clone()).unwrap(),
        settings,
        "the settings read back"
    );
    assert_eq!(
        apply(
            &settings,
            &Options::for_scene(&s, Chapter::ReflectionRefraction)
        ),
        o
    );
    // a trees file of one pixel's tree, its version and its pixel as given
    let tree = Tracer::new(&s, &o).inspect(3, 0).to_json();
    let doc = |version: u64, x: u32, settings: &serde_json::Value| {
        let mut tree = tree.clone();
        tree["pixel"] = serde_json::json!([x, 0]);
        serde_json::json!({"version": version, "about": "", "settings": settings,
            "pixels": [{"pixel": [x, 0], "covers": [], "tree": tree}]})
        .to_string()
    };
    let file = TreeFile::parse(&doc(1, 3, &json)).unwrap();
    assert_eq!((file.settings, file.trees.len()), (settings, 1));
    let why = TreeFile::parse(&doc(2, 3, &json)).unwrap_err();
    assert!(why.contains("version 1"), "{why}");
    let why = TreeFile::parse(&doc(1, 240, &json)).unwrap_err();
    assert!(why.contains("(240, 0) is outside the image"), "{why}");
    let mut bad = json.clone();
    bad["view"] = "x-ray".into();
    let why = TreeFile::parse(&doc(1, 3, &bad)).unwrap_err();
    assert!(why.contains("view") && why.contains("x-ray"), "{why}");
}
