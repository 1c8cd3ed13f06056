//! The layers a newcomer reads: the workspace's crates depend on one another one way (course
//! tools → (cargo) → the programs → the renderer), the renderer's modules depend on one another
//! without cycles, no file of any crate names a file that names it back, no source file outside
//! the tests is over 600 lines, the renderer carries no command-line code, and the road of one
//! pixel holds no speed machinery. These read the manifests and source files themselves.
//!
//! The files of a crate are read with `syn` (the modules from the crate's root by its `mod`
//! declarations, the paths each file writes, where each path leads): `syntax`, `modules`,
//! `paths`, `resolve` and `circles` hold that reader, bottom floor first; `workspace` finds
//! every crate's root file and every source file; `examples` proves the reader on small crates
//! written in memory.

mod circles;
mod examples;
mod modules;
mod paths;
mod resolve;
mod syntax;
mod workspace;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use circles::{circles, tell};
use modules::read_crate;
use resolve::file_graph;
use workspace::{crate_roots, disk, only_test_code, root, rust_sources, under_tests};

/// The longest a source file outside the tests may be, in lines.
const LONGEST: usize = 600;

/// The renderer's sources.
fn src() -> PathBuf {
    root().join("crates/whitted/src")
}

/// The packages a crate's manifest names in `section` (`dependencies`, `dev-dependencies` …).
fn named(manifest: &str, section: &str) -> BTreeSet<String> {
    let path = root().join(manifest);
    let text = std::fs::read_to_string(&path).unwrap();
    let table: toml::Table = text.parse().unwrap();
    table
        .get(section)
        .and_then(|v| v.as_table())
        .map(|t| t.keys().cloned().collect())
        .unwrap_or_default()
}

/// The crates depend one way: the syllabus on nothing unless a feature asks; the renderer on
/// none of the others and on nothing a command line, a window or a course tool needs; the
/// programs on the renderer only; the course tools on
/// neither (they run cargo on a project, so a student's edit never rebuilds them); and nothing
/// under `crates/` on the tools, benchmarks or these tests.
#[test]
fn the_crates_depend_one_way() {
    let core = named("crates/whitted/Cargo.toml", "dependencies");
    let app = named("crates/whitted-app/Cargo.toml", "dependencies");
    let course = named("crates/whitted-course/Cargo.toml", "dependencies");
    let outside = ["whitted-tools", "whitted-benches", "whitted-tests"];
    for (name, deps) in [
        ("whitted", &core),
        ("whitted-app", &app),
        ("whitted-course", &course),
    ] {
        for o in outside {
            assert!(!deps.contains(o), "{name} depends on {o}: {deps:?}");
        }
    }
    for not_core in [
        "whitted-app",
        "whitted-course",
        "clap",
        "minifb",
        "indicatif",
        "syn",
        "notify",
        "roxmltree",
        "plotters",
    ] {
        assert!(
            !core.contains(not_core),
            "the renderer depends on {not_core}: {core:?}"
        );
    }
    assert!(
        app.contains("whitted") && !app.contains("whitted-course"),
        "{app:?}"
    );
    assert!(
        !course.contains("whitted") && !course.contains("whitted-app"),
        "the course tools depend on the code they grade: {course:?}"
    );
    // the outline every layer reads depends on nothing but what a layer asks of it by a
    // feature (png, for the PNG reader)
    let text = std::fs::read_to_string(root().join("crates/whitted-syllabus/Cargo.toml")).unwrap();
    let table: toml::Table = text.parse().unwrap();
    let required: Vec<&String> = table
        .get("dependencies")
        .and_then(|v| v.as_table())
        .map(|t| {
            t.iter()
                .filter(|(_, v)| v.get("optional").and_then(toml::Value::as_bool) != Some(true))
                .map(|(k, _)| k)
                .collect()
        })
        .unwrap_or_default();
    assert!(
        required.is_empty(),
        "whitted-syllabus depends on {required:?} without a feature"
    );
    // the programs ask no feature of it that the renderer does not: a student's tests build
    // the renderer alone and the picture builds it with the programs, and a feature only
    // the programs turned on would make that a second build of the renderer at every save
    let features = |manifest: &str| -> BTreeSet<String> {
        let text = std::fs::read_to_string(root().join(manifest)).unwrap();
        let table: toml::Table = text.parse().unwrap();
        table["dependencies"]
            .get("whitted-syllabus")
            .and_then(|d| d.get("features"))
            .and_then(toml::Value::as_array)
            .map(|a| {
                a.iter()
                    .filter_map(|f| f.as_str().map(String::from))
                    .collect()
            })
            .unwrap_or_default()
    };
    let (of_core, of_app) = (
        features("crates/whitted/Cargo.toml"),
        features("crates/whitted-app/Cargo.toml"),
    );
    assert!(
        of_app.is_subset(&of_core),
        "the programs turn on features of whitted-syllabus the renderer does not: {of_app:?} against {of_core:?}"
    );
    // the student's tests need no more than the renderer (and its own dependencies)
    let dev = named("crates/whitted/Cargo.toml", "dev-dependencies");
    assert!(
        dev.is_empty(),
        "the student's tests have dev-dependencies: {dev:?}"
    );
}

/// The file's code without its comments (line comments, doc comments included).
fn code(text: &str) -> String {
    text.lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level module a file of `src/` belongs to (`render` for `src/render/tracer.rs`).
fn top_module(path: &Path) -> String {
    let rel = path.strip_prefix(src()).unwrap();
    let first = rel
        .components()
        .next()
        .unwrap()
        .as_os_str()
        .to_string_lossy();
    first.trim_end_matches(".rs").to_string()
}

/// Which top-level modules each top-level module names (`crate::x`).
fn dependencies() -> BTreeMap<String, BTreeSet<String>> {
    let mut deps: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in rust_sources(&src()) {
        let me = top_module(&file);
        if me == "lib" {
            continue;
        }
        let text = code(&std::fs::read_to_string(&file).unwrap());
        let entry = deps.entry(me.clone()).or_default();
        for (i, _) in text.match_indices("crate::") {
            let name: String = text[i + 7..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && name != me {
                entry.insert(name);
            }
        }
    }
    deps
}

/// The library's modules depend on one another without a cycle: they can be read in an order
/// where each uses only those before it (the order is printed).
#[test]
fn the_modules_form_no_cycle() {
    let deps = dependencies();
    assert!(deps.contains_key("render") && deps.contains_key("accel"));
    let mut done: Vec<String> = Vec::new();
    let mut left: BTreeSet<String> = deps.keys().cloned().collect();
    while !left.is_empty() {
        let ready: Vec<String> = left
            .iter()
            .filter(|m| {
                deps[*m]
                    .iter()
                    .all(|d| done.contains(d) || !deps.contains_key(d))
            })
            .cloned()
            .collect();
        assert!(
            !ready.is_empty(),
            "a cycle among {left:?}: {:?}",
            left.iter().map(|m| (m, &deps[m])).collect::<Vec<_>>()
        );
        for m in ready {
            left.remove(&m);
            done.push(m);
        }
    }
    println!("reading order: {}", done.join(" → "));
    // the speed machinery sits on the road, not under it
    let position = |m: &str| done.iter().position(|d| d == m).unwrap();
    assert!(position("accel") < position("render"));
    assert!(!deps["accel"].contains("render"), "{:?}", deps["accel"]);
}

/// The renderer carries no command-line code: `clap` appears nowhere in its sources (the
/// command line is `whitted-app`'s).
#[test]
fn the_renderer_knows_no_command_line() {
    let mut found = Vec::new();
    for file in rust_sources(&src()) {
        let text = code(&std::fs::read_to_string(&file).unwrap());
        if text.contains("clap") {
            found.push(file.display().to_string());
        }
    }
    assert!(found.is_empty(), "clap in the renderer: {found:?}");
}

/// The road of one pixel (`src/render/tracer.rs`) is plain: no tile, packet, mailbox or
/// counter code in it (no word of its code names one: `shadow::blocks`, an object blocking a
/// feeler, is not a block of pixels), and short enough to read in one sitting, the notes' step
/// 4 as the road asks it (`EveryObject`, its loop over every object) included.
#[test]
fn the_road_of_one_pixel_holds_no_speed_machinery() {
    let path = src().join("render/tracer.rs");
    let text = std::fs::read_to_string(&path).unwrap();
    let code = code(&text).to_lowercase();
    let words: BTreeSet<&str> = code
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    for word in [
        "packet", "packets", "packed", "tile", "tiles", "mailbox", "counters", "rayon", "block",
    ] {
        assert!(!words.contains(word), "the road's code names `{word}`");
    }
    // marker lines do not count: the exercises' (`// BEGIN SOLUTION local_light`, `// END SOLUTION`)
    // and the course book's (`// ANCHOR: ch3_shade`, `// ANCHOR_END: ch3_shade`)
    let lines = text
        .lines()
        .map(str::trim)
        .filter(|l| {
            !(l.starts_with("// BEGIN SOLUTION")
                || *l == "// END SOLUTION"
                || l.starts_with("// ANCHOR: ")
                || l.starts_with("// ANCHOR_END: "))
        })
        .count();
    assert!(lines <= 520, "the road is {lines} lines long");
}

/// The files of every crate the workspace builds depend on one another without a circle: in
/// each crate (a library, a binary, a test, a benchmark) the files can be read in an order
/// where each names only files before it. A file names another when its code (comments and
/// `#[cfg(test)]` code aside) writes a path that leads into it: `crate::…`, `super::…`,
/// `self::…` or a path from a child module or a `use`d name, in a `use`, an expression, a type,
/// a pattern, an attribute or a macro's arguments. A path through a re-export of a crate root or
/// a `mod.rs` (`pub use options::Options`) leads to the file that defines the item; a
/// `use super::*` names the parent's file. A circle is told as its chain of files and, for
/// each, the line where it names the next: break one of those namings (move the item both
/// files need to a file of its own, below both).
#[test]
fn no_file_of_any_crate_names_a_file_that_names_it_back() {
    let root = root();
    let roots = crate_roots(&root);
    for expected in [
        "crates/whitted/src/lib.rs",
        "crates/whitted-course/src/main.rs",
        "crates/whitted-app/src/bin/ch05_reflection_refraction.rs",
        "tools/tradeoff/main.rs",
        "benches/shapes.rs",
        "tests/extremes/main.rs",
        "crates/whitted/tests/ch02_generic_objects/main.rs",
    ] {
        assert!(
            roots.contains(&root.join(expected)),
            "{expected} is not among the crates read: {roots:?}"
        );
    }
    let mut problems = Vec::new();
    // each circle, told, with the crates (by root file) it is in: a file several crates
    // share (a test's `common/`) is told once
    let mut found: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut namings = 0;
    for crate_root in &roots {
        let krate = read_crate(crate_root, &disk);
        problems.extend(krate.problems.iter().cloned());
        let graph = file_graph(&krate);
        namings += graph.values().map(BTreeMap::len).sum::<usize>();
        for circle in circles(&graph) {
            found
                .entry(tell(&circle, &graph, &root))
                .or_default()
                .push(shown(crate_root, &root));
        }
    }
    assert!(
        problems.is_empty(),
        "files the layering check could not read:\n{}",
        problems.join("\n")
    );
    // the reader sees the namings there are: the renderer's files alone name one another
    // hundreds of times
    assert!(namings > 300, "only {namings} namings between files seen");
    let mut by_crates: BTreeMap<String, Vec<&String>> = BTreeMap::new();
    for (told, crates) in &found {
        by_crates.entry(crates.join(", ")).or_default().push(told);
    }
    let mut message = String::new();
    for (crates, told) in by_crates {
        message += &format!("in the crate of {crates}:\n");
        for t in told {
            message += t;
        }
    }
    assert!(
        found.is_empty(),
        "{} circle(s) among the files of a crate (each file names the next, the last names the \
         first; break one naming of each circle):\n{message}",
        found.len()
    );
}

/// No source file outside the tests is over 600 lines: a file that long usually does two jobs.
/// Test files are those under a `tests/` directory, those holding only `#[cfg(test)]` code, and
/// those only a `#[cfg(test)] mod` declaration leads to.
#[test]
fn no_source_file_outside_the_tests_is_over_600_lines() {
    let root = root();
    let mut reached = BTreeSet::new();
    let mut reached_by_tests = BTreeSet::new();
    for crate_root in crate_roots(&root) {
        let krate = read_crate(&crate_root, &disk);
        reached.extend(krate.files.into_iter().map(|(file, _, _)| file));
        reached_by_tests.extend(krate.test_files);
    }
    let mut long = Vec::new();
    for file in rust_sources(&root) {
        let relative = file.strip_prefix(&root).expect("a file of the workspace");
        if under_tests(relative) || (reached_by_tests.contains(&file) && !reached.contains(&file)) {
            continue;
        }
        let text = std::fs::read_to_string(&file).expect("a readable file");
        let lines = text.lines().count();
        if lines > LONGEST && !only_test_code(&text) {
            long.push((lines, relative.display().to_string()));
        }
    }
    long.sort_by(|a, b| b.cmp(a));
    let list: Vec<String> = long
        .iter()
        .map(|(lines, file)| format!("  {file}: {lines} lines"))
        .collect();
    assert!(
        long.is_empty(),
        "{} source file(s) over {LONGEST} lines (split each by its jobs):\n{}",
        long.len(),
        list.join("\n")
    );
}

/// A path shown relative to the workspace's root.
fn shown(path: &Path, root: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .display()
        .to_string()
}

/// The first names a file's code reaches through `prefix` (`super::`, `crate::render::`): for
/// `use super::{a, b::c};` the names `a` and `b`, for `super::x::y` the name `x`.
fn names_after(code: &str, prefix: &str) -> BTreeSet<String> {
    let ident = |s: &str| -> String {
        s.trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    let mut out = BTreeSet::new();
    for (i, _) in code.match_indices(prefix) {
        let rest = &code[i + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // the group's top-level elements, each by its first name
            let (mut depth, mut start) = (0, 0);
            for (k, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        out.insert(ident(&group[start..k]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.insert(ident(&group[start..k]));
                        start = k + 1;
                    }
                    _ => {}
                }
            }
        } else {
            out.insert(ident(rest));
        }
    }
    out.remove("");
    out
}

/// The road of one pixel reads top to bottom: what it asks and tells (the query trait, its
/// shortcuts, the recorder) sit beneath it and name nothing of it, and the road
/// (`render/tracer.rs`) names nothing of what sits beside it and calls it — the pixel and its
/// samples, the views and stages, the inspector, the acceleration structure as a query, the
/// packets and the tiles — neither a module nor an item `render/mod.rs` re-exports from one.
#[test]
fn the_road_calls_nothing_beside_it_and_its_floor_nothing_above() {
    let render = src().join("render");
    // the items render/mod.rs re-exports, by the module that defines them
    let mut items: BTreeMap<String, String> = BTreeMap::new();
    let mod_rs = code(&std::fs::read_to_string(render.join("mod.rs")).unwrap());
    for line in mod_rs.lines().filter(|l| l.starts_with("pub use ")) {
        let path = line["pub use ".len()..].trim_end_matches(';');
        if let Some((module, rest)) = path.split_once("::") {
            let names = rest.trim_start_matches('{').trim_end_matches('}');
            for name in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
                items.insert(name.to_string(), module.to_string());
            }
        }
    }
    let beside = [
        "accelerated",
        "views",
        "stages",
        "pixel",
        "inspect",
        "tiles",
        "packets",
    ];
    let above: Vec<&str> = beside.iter().copied().chain(["tracer"]).collect();
    let files: [(&str, &[&str]); 4] = [
        ("tracer.rs", &beside),
        ("query.rs", &above),
        ("shortcuts.rs", &above),
        ("recorder.rs", &above),
    ];
    for (file, forbidden) in files {
        let text = code(&std::fs::read_to_string(render.join(file)).unwrap());
        let mut named = names_after(&text, "super::");
        named.extend(names_after(&text, "crate::render::"));
        let reached: Vec<String> = named
            .iter()
            .filter(|n| {
                let module = items.get(*n).unwrap_or(n);
                forbidden.contains(&module.as_str())
            })
            .cloned()
            .collect();
        assert!(
            reached.is_empty(),
            "render/{file} names {reached:?}, of the modules above or beside it ({forbidden:?})"
        );
    }
}
