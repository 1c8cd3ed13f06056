//! The reference's ray trees as data (`chapters/chNN_name/trees.json`) and the comparison that
//! finds where a tree first parts from them (`--against`, `cargo learn`): the trees shipped are
//! the renderer's in either precision (an f32 build of a correct road reports no difference);
//! a number that moves beyond its tolerance, or a tree of another shape, is reported at its
//! node with both values; and the functions each quantity names are the manifest's exercises,
//! every one of them.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use serde_json::Value;
use whitted::render::inspect::against::{Settings, TreeFile, first_difference};
use whitted::render::inspect::provenance::{Place, Quantity};
use whitted::render::{Chapter, Options, RayKind, Tracer, View};
use whitted::scene::{Scene, load_parts};

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

/// The table of where each number comes from cannot rot: every function it names is a
/// function of the manifest, and every exercise of the manifest computes some number of the
/// tree (so `cargo learn` can point at any of them).
#[test]
fn every_function_a_quantity_names_is_an_exercise_and_every_exercise_computes_one() {
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
        "exercises no quantity of the tree names: {unnamed:?}"
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

/// A tree of pixel (x, y) of `chapter`'s scene at 240 pixels wide, as JSON, with the names of
/// its objects' shapes.
fn tree(chapter: Chapter, x: u32, y: u32) -> (Value, Scene) {
    let s = scene(chapter);
    let mut o = Options::for_scene(&s, chapter);
    o.height = o.height * 240 / o.width;
    o.width = 240;
    let t = Tracer::new(&s, &o).inspect(x, y).to_json();
    (t, s)
}

/// The first difference of `mine` from `reference`, as `--against` reports it.
fn first(
    mine: &Value,
    reference: &Value,
    s: &Scene,
) -> Option<whitted::render::inspect::against::Difference> {
    let objects: Vec<&'static str> = s.objects.iter().map(|o| o.shape.name()).collect();
    first_difference(mine, reference, &move |i| objects.get(i).copied())
}

/// The hit of the camera ray of a tree's first sample.
fn hit(t: &mut Value) -> &mut Value {
    &mut t["samples"][0]["ray"]["hit"]
}

/// A number of the tree moved beyond its tolerance is the first difference, named by its
/// node and symbol with both values and the functions that computed it; a move within the
/// tolerance (what f32 rounding does) is none.
#[test]
fn a_number_moved_is_found_at_its_node_with_both_values() {
    // a point of the floor, lit by lights 0 and 1 through their feelers
    let (reference, s) = tree(Chapter::Shadows, 20, 140);
    assert_eq!(hit(&mut reference.clone())["name"], "floor");
    assert_eq!(first(&reference, &reference, &s), None);

    let mut mine = reference.clone();
    let t = hit(&mut mine)["t"].as_f64().unwrap();
    hit(&mut mine)["t"] = (t * (1.0 + 1e-7)).into();
    assert_eq!(first(&mine, &reference, &s), None, "within the tolerance");
    hit(&mut mine)["t"] = (t * 1.01).into();
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
    hit(&mut mine)["lights"][1]["diffuse"][0] = 0.5.into();
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
    *hit(&mut mine) = Value::Null;
    let d = first(&mine, &reference, &s).unwrap();
    assert_eq!(d.quantity, Quantity::Object);
    assert_eq!(
        (d.computed.as_str(), d.reference.as_str()),
        ("nothing", "`floor`")
    );
    assert!(d.functions.contains(&"shapes::nearer"), "{d:?}");
    // the box (object 3) more along light 0's feeler: the box's intersection is named
    let mut mine = reference.clone();
    let crossings = &mut hit(&mut mine)["lights"][0]["feeler"]["crossings"];
    let mut crossed = crossings.as_array().cloned().unwrap_or_default();
    crossed.push(serde_json::json!({"object": 3, "name": "box", "u": [0.5], "transmission": 0.0}));
    *crossings = Value::Array(crossed);
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
    let kept: Vec<Value> = h["branches"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|b| b["kind"] != "transmitted")
        .cloned()
        .collect();
    assert!(kept.len() < h["branches"].as_array().unwrap().len(), "{h}");
    h["branches"] = Value::Array(kept);
    h["stopped"] = serde_json::json!([{"kind": "transmitted", "why": "total_internal_reflection"}]);
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
    let settings = Settings::of(&o);
    let json = settings.to_json();
    assert_eq!(Settings::from_json(&json), Ok(settings.clone()));
    assert_eq!(
        settings.apply(&Options::for_scene(&s, Chapter::ReflectionRefraction)),
        o
    );
    let mut bad = json.clone();
    bad["view"] = "x-ray".into();
    let why = Settings::from_json(&bad).unwrap_err();
    assert!(why.contains("`view`") && why.contains("x-ray"), "{why}");
    let doc = |version: u64, x: u32| {
        serde_json::json!({"version": version, "settings": json,
            "pixels": [{"pixel": [x, 0], "tree": {"pixel": [x, 0]}}]})
        .to_string()
    };
    assert!(TreeFile::parse(&doc(1, 3)).is_ok());
    let why = TreeFile::parse(&doc(2, 3)).unwrap_err();
    assert!(why.contains("version 1"), "{why}");
    let why = TreeFile::parse(&doc(1, 240)).unwrap_err();
    assert!(why.contains("(240, 0) is outside the image"), "{why}");
}
