//! The file reader proved on small crates written in memory: it sees a circle through
//! `super::`, through a macro's arguments, through a glob and through an item of a `mod.rs`;
//! it sees none where a re-export only passes a name on, and none in comments or test code.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::circles::circles;
use crate::modules::read_crate;
use crate::resolve::{Graph, file_graph};
use crate::syntax::only_in_tests;

/// The file graph of the crate whose files are `files` (path, text), its root `src/lib.rs`.
fn graph(files: &[(&str, &str)]) -> Graph {
    let files: BTreeMap<PathBuf, String> = files
        .iter()
        .map(|(p, t)| (PathBuf::from(p), t.to_string()))
        .collect();
    let krate = read_crate(Path::new("src/lib.rs"), &|p| files.get(p).cloned());
    assert!(krate.problems.is_empty(), "{:?}", krate.problems);
    file_graph(&krate)
}

/// The namings of a graph, as `a → b` with the line where a names b.
fn namings(graph: &Graph) -> BTreeSet<String> {
    graph
        .iter()
        .flat_map(|(a, named)| {
            named
                .iter()
                .map(move |(b, n)| format!("{} → {} ({})", a.display(), b.display(), n.line))
        })
        .collect()
}

/// The circles of a graph, each as its files joined by ` → `.
fn told(graph: &Graph) -> Vec<String> {
    circles(graph)
        .iter()
        .map(|c| {
            c.iter()
                .map(|f| f.display().to_string())
                .collect::<Vec<_>>()
                .join(" → ")
        })
        .collect()
}

/// The set of strings written.
fn set(items: &[&str]) -> BTreeSet<String> {
    items.iter().map(ToString::to_string).collect()
}

/// Two files that name each other through `super::` (one in a `use`, one in a type) are a
/// circle, told with the line where each names the other.
#[test]
fn two_files_naming_each_other_through_super_are_a_circle() {
    let g = graph(&[
        ("src/lib.rs", "mod a;\nmod b;\n"),
        ("src/a.rs", "use super::b::B;\npub struct A;\n"),
        ("src/b.rs", "pub struct B;\n\npub fn f(_: super::a::A) {}\n"),
    ]);
    assert_eq!(
        namings(&g),
        set(&["src/a.rs → src/b.rs (1)", "src/b.rs → src/a.rs (3)"])
    );
    assert_eq!(told(&g), ["src/a.rs → src/b.rs"]);
}

/// A `mod.rs` that re-exports its children's items passes their names on: a child that writes
/// `crate::render::Options` names `options.rs`, not the `mod.rs`, and no circle closes; chains
/// of re-exports (the crate's root re-exporting the `mod.rs`'s) lead to the same file.
#[test]
fn a_reexport_passes_a_name_on_and_closes_no_circle() {
    let g = graph(&[
        ("src/lib.rs", "pub mod render;\npub use render::Options;\n"),
        (
            "src/render/mod.rs",
            "mod options;\nmod tracer;\npub use options::Options;\npub use tracer::trace;\n",
        ),
        ("src/render/options.rs", "pub struct Options;\n"),
        (
            "src/render/tracer.rs",
            "use crate::render::Options;\n\npub fn trace(_: &crate::Options) {}\n",
        ),
    ]);
    assert_eq!(
        namings(&g),
        set(&[
            "src/lib.rs → src/render/options.rs (2)",
            "src/render/mod.rs → src/render/options.rs (3)",
            "src/render/mod.rs → src/render/tracer.rs (4)",
            "src/render/tracer.rs → src/render/options.rs (1)",
        ])
    );
    assert!(told(&g).is_empty());
}

/// An item a `mod.rs` defines itself, used by a child it re-exports, closes the two-file
/// circle `mod.rs → child → mod.rs`.
#[test]
fn an_item_of_the_mod_rs_itself_closes_a_circle() {
    let g = graph(&[
        ("src/lib.rs", "mod render;\n"),
        (
            "src/render/mod.rs",
            "mod tracer;\npub use tracer::trace;\npub struct Settings;\n",
        ),
        (
            "src/render/tracer.rs",
            "use super::Settings;\npub fn trace() {}\n",
        ),
    ]);
    assert_eq!(told(&g), ["src/render/mod.rs → src/render/tracer.rs"]);
}

/// `use super::*` names the parent's file, whatever it brings; with the parent re-exporting
/// the child, that is a circle.
#[test]
fn a_glob_names_the_file_of_its_module() {
    let g = graph(&[
        ("src/lib.rs", "mod a;\npub use a::A;\n"),
        ("src/a.rs", "use super::*;\npub struct A;\n"),
    ]);
    assert!(namings(&g).contains("src/a.rs → src/lib.rs (1)"));
    assert_eq!(told(&g), ["src/a.rs → src/lib.rs"]);
}

/// The arguments of a macro call are read as tokens: `format!("{}", crate::b::NAME)` names
/// `b.rs`, `assert!(crate::a::f() …)` names `a.rs`, and `$crate::` reads as `crate::`.
#[test]
fn a_macro_call_names_what_its_arguments_name() {
    let g = graph(&[
        ("src/lib.rs", "mod a;\nmod b;\nmod c;\n"),
        (
            "src/a.rs",
            "pub fn f() -> String {\n    format!(\"{}\", crate::b::NAME)\n}\n",
        ),
        (
            "src/b.rs",
            "pub const NAME: &str = \"\";\npub fn g() {\n    assert!(crate::a::f().is_empty(), \"{}\", 1);\n}\n",
        ),
        (
            "src/c.rs",
            "macro_rules! m { () => { $crate::b::g() }; }\npub fn h() { m!(); vec![super::a::f()]; }\n",
        ),
    ]);
    assert_eq!(
        namings(&g),
        set(&[
            "src/a.rs → src/b.rs (2)",
            "src/b.rs → src/a.rs (3)",
            "src/c.rs → src/a.rs (2)",
            "src/c.rs → src/b.rs (1)",
        ])
    );
    assert_eq!(told(&g), ["src/a.rs → src/b.rs"]);
}

/// Comments, doc comments and test code name nothing: a `#[cfg(test)]` module (inline, or in a
/// file of its own), function, impl item or `cfg(all(test, …))` item does not make a circle.
#[test]
fn comments_and_test_code_name_nothing() {
    let g = graph(&[
        ("src/lib.rs", "mod a;\nmod b;\n"),
        (
            "src/a.rs",
            "// crate::b::g()\n/// [`crate::b::g`]\npub fn f() {}\n\
             #[cfg(test)]\nmod tests { use crate::b::*; }\n\
             #[cfg(all(test, feature = \"f32\"))]\nfn t() { crate::b::g() }\n\
             pub struct A;\nimpl A {\n    #[cfg(test)]\n    fn t() { crate::b::g() }\n}\n\
             #[cfg(test)]\nmod more;\n",
        ),
        ("src/a/more.rs", "use crate::b::g;\n"),
        ("src/b.rs", "pub fn g() { crate::a::f() }\n"),
    ]);
    assert_eq!(namings(&g), set(&["src/b.rs → src/a.rs (1)"]));
    assert!(told(&g).is_empty());
}

/// `use` trees are read whole: groups, `self`, renames (a renamed module's name leads on),
/// and a `use` inside a function body; serde's `with = "…"` names the module it gives,
/// `serialize_with = "…"` the function.
#[test]
fn use_groups_renames_and_self_lead_where_they_name() {
    let g = graph(&[
        ("src/lib.rs", "mod a;\nmod b;\nmod c;\nmod d;\nmod e;\n"),
        (
            "src/a.rs",
            "use crate::{\n    b::{self as bee},\n    c::C as See,\n};\n\
             pub fn f(_: See) {\n    bee::g();\n}\n\
             pub fn h() {\n    use crate::d;\n    d::D::new();\n}\n\
             #[derive(serde::Serialize)]\npub struct S(#[serde(with = \"crate::e\")] u8);\n",
        ),
        ("src/b.rs", "pub fn g() {}\n"),
        ("src/c.rs", "pub struct C;\n"),
        ("src/d.rs", "pub struct D;\n"),
        ("src/e.rs", "pub fn serialize() {}\n"),
    ]);
    assert_eq!(
        namings(&g),
        set(&[
            "src/a.rs → src/b.rs (6)",
            "src/a.rs → src/c.rs (3)",
            "src/a.rs → src/d.rs (10)",
            "src/a.rs → src/e.rs (13)",
        ])
    );
    let g = graph(&[
        ("src/lib.rs", "mod a;\nmod e;\n"),
        (
            "src/a.rs",
            "pub struct S(#[serde(serialize_with = \"crate::e::serialize\")] u8);\n",
        ),
        ("src/e.rs", "pub fn serialize() {}\n"),
    ]);
    assert_eq!(namings(&g), set(&["src/a.rs → src/e.rs (1)"]));
}

/// A name a file that is not a module's front re-exports stops at that file: writing
/// `crate::road::Query` names `road.rs`, even when `road.rs` took `Query` from `query.rs`.
#[test]
fn a_reexport_of_a_plain_file_names_that_file() {
    let g = graph(&[
        ("src/lib.rs", "mod query;\nmod road;\nmod user;\n"),
        ("src/query.rs", "pub trait Query {}\n"),
        ("src/road.rs", "pub use crate::query::Query;\n"),
        ("src/user.rs", "use crate::road::Query;\n"),
    ]);
    assert_eq!(
        namings(&g),
        set(&[
            "src/road.rs → src/query.rs (1)",
            "src/user.rs → src/road.rs (1)",
        ])
    );
}

/// `#[path]` finds a module's file (one file keeps one name however it is reached), and
/// inline modules are parts of their file: what they name, their file names.
#[test]
fn path_attributes_and_inline_modules_are_followed() {
    let g = graph(&[
        (
            "src/lib.rs",
            "#[path = \"../shared/./common.rs\"]\nmod common;\nmod a;\n",
        ),
        ("shared/common.rs", "pub fn help() {}\n"),
        (
            "src/a.rs",
            "mod inner {\n    pub fn f() { super::super::common::help() }\n}\npub use inner::f;\n",
        ),
    ]);
    assert_eq!(namings(&g), set(&["src/a.rs → shared/common.rs (2)"]));
}

/// The test configuration is read as cargo reads it: `test`, `all(test, …)` and an `any(…)`
/// of test-only parts hold only in tests; `not(test)`, `any(test, …)` and features do not.
#[test]
fn cfg_test_is_read_as_cargo_reads_it() {
    let only = |attr: &str| {
        let item: syn::ItemFn = syn::parse_str(&format!("{attr}\nfn f() {{}}")).unwrap();
        only_in_tests(&item.attrs)
    };
    assert!(only("#[cfg(test)]"));
    assert!(only("#[cfg(all(test, feature = \"f32\"))]"));
    assert!(only("#[cfg(any(test, all(test, unix)))]"));
    assert!(!only("#[cfg(not(test))]"));
    assert!(!only("#[cfg(any(test, feature = \"f32\"))]"));
    assert!(!only("#[cfg(feature = \"f32\")]"));
    assert!(!only("#[inline]"));
}
