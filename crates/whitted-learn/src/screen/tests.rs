//! The screen's tests: what passes, what is refused with its line, what the loop names.

use super::*;

fn what(body: &str) -> Option<String> {
    screen(body).map(|r| r.what)
}

/// What a formula writes passes, whatever its names: `env`, `load`, `save`, `path`, `io`,
/// `os`, a `///` comment, a label, a lint, a closure, `std::mem::swap`.
#[test]
fn a_formula_passes_whatever_its_names() {
    for body in [
        "    near * (fov_degrees.to_radians() / 2.0).tan()\n",
        "let env = 1.0; let load = 2.0; let save = env * load; save",
        "let path = ray.at(t); let io = 0.5; let os = io + 1.0; path * os",
        "/// the square\nlet sq = |x: Real| x * x;\nsq(2.0)",
        "'outer: for i in 0..3 { for j in 0..3 { if i == j { continue 'outer; } break 'outer; } } 0.0",
        "#[allow(clippy::float_cmp)]\nif a == b { 1.0 } else { 0.0 }",
        "let (mut t0, mut t1) = (b, a); if t0 > t1 { std::mem::swap(&mut t0, &mut t1); } (t0, t1)",
        "if !(a > b) { todo!() } else { a * *b }",
        "use crate::shading::lambert;\nlambert(n, s) * 2.0",
        "let exit = t1.max(t0); let include_str = 1.0; exit * include_str",
        "let v = vec![1.0; 3]; assert!(v.len() == 3, \"{}\", v.len()); v[0]",
        "std::hint::black_box(d)",
        "fn square(x: Real) -> Real { x * x }\nlet f: fn(Real) -> Real = square;\nf(2.0)",
        "// std::process::exit(0)\n\"process exit unsafe\".len() as f64",
    ] {
        assert_eq!(screen(body), None, "{body}");
    }
}

/// What a formula never writes is refused, with its line, however it is spelled.
#[test]
fn what_a_formula_never_needs_is_refused_with_its_line() {
    for (body, found, line) in [
        (
            "std::process::exit(0)",
            "`std::process::exit` (`process`)",
            1,
        ),
        (
            "0.0;\n::std::process::abort()",
            "`std::process::abort` (`process`)",
            2,
        ),
        ("use std::process as p; p::exit(0)", "`use` of `process`", 1),
        ("use std::{io::Write, fmt}; 0.0", "`use` of `io`", 1),
        ("r#process::exit(0)", "`process::exit` (`process`)", 1),
        ("env::var(\"HOME\")", "`env::var` (`env`)", 1),
        (
            "crate::output::save(fb, p, e)",
            "`crate::output::save` (`save`)",
            1,
        ),
        (
            "crate::judged::call::<_, Real>(12, &(ray, a, b))",
            "`crate::judged::call` (`judged`)",
            1,
        ),
        (
            "whitted::judge::serve(t)",
            "`whitted::judge::serve` (`judge`)",
            1,
        ),
        ("unsafe { 0.0 }", "`unsafe`", 1),
        ("extern \"C\" { fn exit(c: i32); }", "`extern`", 1),
        ("macro_rules! m { () => {} }", "`macro_rules`", 1),
        ("include_str!(\"x\")", "`include_str!`", 1),
        (
            "include_bytes /* spaced */ ! (\"x\")",
            "`include_bytes!`",
            1,
        ),
        ("let a = 1;\nenv!(\"HOME\")", "`env!`", 2),
        ("#[path = \"/x.rs\"] mod m;", "`#[path]`", 1),
        ("#![no_mangle] 0.0", "`#[no_mangle]`", 1),
        (
            "fn helper<T>(x: T) -> T { x } helper(1.0)",
            "`fn helper<…>`",
            1,
        ),
        (
            "fn stretch<'a, 'b, T>(_: &'a &'b (), v: &'b T) -> &'a T { v }",
            "`fn stretch<…>`",
            1,
        ),
        (
            "const N: u64 = { let mut i = 0; loop { i += 1 } }; 0.0",
            "`const`",
            1,
        ),
        ("struct S; 0.0", "`struct`", 1),
        ("impl Drop for X { }", "`impl`", 1),
        ("let f = |x: &'static f64| *x; 0.0", "`'static`", 1),
        (
            "let p = &x as *const f64; 0.0",
            "a raw pointer (`*const`, `*mut`)",
            1,
        ),
        ("let p = &raw const x; 0.0", "`&raw`", 1),
        (
            "0.0 }\nfn evil() {",
            "a bracket, brace, quote or comment",
            1,
        ),
        ("let s = \"open;\n", "a bracket, brace, quote or comment", 1),
        (
            "println!(\"{}\", std::env::var(\"X\").unwrap())",
            "`std::env::var` (`env`)",
            1,
        ),
    ] {
        let r = screen(body).unwrap_or_else(|| panic!("{body}: passed"));
        assert_eq!((r.what.as_str(), r.line), (found, line), "{body}");
        assert!(!r.why.is_empty() && !r.instead.is_empty(), "{r:?}");
    }
    assert_eq!(what("#[allow(unused)] let x = 1.0; x"), None);
}

/// The loop finds a refused body in the student's sources and names its exercise, its file
/// and the refused line in that file; a body that computes is not named.
#[test]
fn the_loop_names_the_refused_line_in_the_students_file() {
    let manifest = crate::week::every_exercise();
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join(crate::layout::core_src());
    std::fs::create_dir_all(&src).unwrap();
    let text = "pub fn near_plane_half_width(h: Real, a: Real) -> Real {\n    // BEGIN SOLUTION near_plane_half_width\n    let env = h * a;\n    env\n    // END SOLUTION\n}\n\npub fn viewing_basis() {\n    // BEGIN SOLUTION viewing_basis\n    let home = 1.0;\n    let x = std::env::var(\"HOME\");\n    // END SOLUTION\n}\n";
    std::fs::write(src.join("camera.rs"), text).unwrap();
    let found = super::refused::refused(dir.path(), &manifest);
    assert_eq!(found.len(), 1, "{found:?}");
    let r = &found[0];
    assert_eq!(Some(r.entry), manifest.by_name("viewing_basis"));
    assert_eq!(
        (r.file.clone(), r.line),
        (crate::layout::core_src().join("camera.rs"), 11)
    );
    let line = r.line(&manifest);
    assert!(
        line.contains("exercise 1.1 (viewing_basis)")
            && line.contains("camera.rs:11: `std::env::var` (`env`) reaches the environment")
            && line.contains("compute the result from the function's arguments"),
        "{line}"
    );
}
