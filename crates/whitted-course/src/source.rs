//! Finding a function of the crate in its source, and rewriting function bodies.
//!
//! A path such as `camera::Camera::direction` is read the way `use whitted::…` reads it. The
//! longest prefix of module names that is a file of the renderer's crate (`src/camera.rs` or
//! `src/camera/mod.rs` under `crates/whitted/`; no prefix at all is `src/lib.rs`) gives the file; the rest must be a free function `fn`, or
//! `Type::method` inside an `impl Type` or `impl Trait for Type` block of that file. When the
//! file has no such item but re-exports the name (`pub use polyhedron::{Facet, Polyhedron};`),
//! the search follows the re-export, so `shapes::Polyhedron::intersect` is found in
//! `src/shapes/polyhedron.rs`; and a method missing from its module's file is looked for in the
//! `impl` blocks of that module's children (`accel::Accelerator::nearest` is in
//! `src/accel/query.rs`). Inline `mod name { … }` blocks and `#[path]` attributes are not
//! followed.
//!
//! The file is parsed with `syn`, and the body block `{ … }` of the function is given as a byte
//! range of the file's text, braces included. [`edit_bodies`] rewrites such ranges: a statement
//! put first in a body (the proof's poison guard), or a body replaced (a handout's `todo!()`).
//! Everything outside the edited bodies is kept byte for byte.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ops::Range;
use std::path::{Path, PathBuf};

use syn::{ImplItem, Item, UseTree, Visibility};

/// How many re-exports a search may follow before giving up (a cycle, or a very long chain).
const MAX_REEXPORTS: usize = 8;

/// Where a function is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The source file, relative to the project's root (`crates/whitted/src/camera.rs`).
    pub file: PathBuf,
    /// The line of the function's `fn` keyword (from 1).
    pub line: usize,
    /// The byte range of the body block in the file's text, from `{` to `}` included.
    pub body: Range<usize>,
    /// Whether the function is a `const fn` (whose body cannot call a run-time guard).
    pub is_const: bool,
}

/// A change to one function body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Edit {
    /// Insert this text right after the body's opening brace.
    Prepend(String),
    /// Replace everything between the body's braces with this text.
    Replace(String),
}

/// Finds the renderer's function `path` (`module::fn` or `module::Type::method`) in the project
/// at `root` (see [`crate::layout`]). The error says what is missing and where it was looked
/// for.
pub fn locate(root: &Path, path: &str) -> Result<Location, String> {
    let segments: Vec<String> = path.split("::").map(str::to_string).collect();
    locate_segments(root, &segments, 0)
}

fn locate_segments(root: &Path, segments: &[String], hops: usize) -> Result<Location, String> {
    if hops > MAX_REEXPORTS {
        return Err(format!(
            "more than {MAX_REEXPORTS} re-exports followed (is there a cycle of `pub use`?)"
        ));
    }
    // the longest module prefix that is a file; no prefix at all is the crate root
    let (modules, file) = (0..segments.len())
        .rev()
        .find_map(|k| module_file(root, &segments[..k]).map(|f| (k, f)))
        .unwrap_or_else(|| (0, crate::layout::core_lib()));
    let module = &segments[..modules];
    let rest = &segments[modules..];
    let shown = file.display().to_string();

    let text = std::fs::read_to_string(root.join(&file))
        .map_err(|e| format!("cannot read {shown}: {e}"))?;
    let ast = parse(&text, &shown)?;

    let found = match rest {
        [name] => free_fns(&ast, name),
        [ty, method] => methods(&ast, ty, method),
        _ => {
            return Err(format!(
                "expected `fn` or `Type::method` after the module path `{}` (file {shown}), found `{}`",
                module.join("::"),
                rest.join("::")
            ));
        }
    };
    let what = match rest {
        [name] => format!("fn {name}"),
        _ => format!("method {} in an `impl {}` block", rest[1], rest[0]),
    };
    match found.as_slice() {
        [one] => Ok(Location {
            file,
            ..one.clone()
        }),
        [] => {
            // a type's `impl` blocks may sit in the files of its module's children
            // (`accel::Accelerator::nearest` is in `src/accel/query.rs`)
            if let [ty, method] = rest {
                let inner = child_methods(root, &ast, module, ty, method)?;
                if let [one] = inner.as_slice() {
                    return Ok(one.clone());
                }
                if inner.len() > 1 {
                    return Err(format!(
                        "method {method} of `{ty}` is defined in {} child modules of {shown}: the path must name exactly one",
                        inner.len()
                    ));
                }
            }
            // not defined here: follow a re-export of the first name, if there is one, and
            // report the first one's error when none leads to the function
            let mut first_error = None;
            for target in reexports(&ast, module, &rest[0]) {
                let mut next = target;
                next.extend_from_slice(&rest[1..]);
                match locate_segments(root, &next, hops + 1) {
                    Ok(found) => return Ok(found),
                    Err(e) => {
                        first_error.get_or_insert(e);
                    }
                }
            }
            if let Some(e) = first_error {
                return Err(e);
            }
            let hint = match rest {
                [ty, _] => format!(
                    " (nor a module `{}` with a file of its own)",
                    module
                        .iter()
                        .chain([ty])
                        .cloned()
                        .collect::<Vec<_>>()
                        .join("::")
                ),
                _ => String::new(),
            };
            Err(format!("no {what} in {shown}{hint}"))
        }
        many => {
            let lines: Vec<String> = many.iter().map(|l| l.line.to_string()).collect();
            Err(format!(
                "{what} is defined {} times in {shown} (lines {}): the path must name exactly one",
                many.len(),
                lines.join(", ")
            ))
        }
    }
}

/// The methods `method` of `impl ty` blocks in the files of the child modules that `ast` (the
/// file of `module`) declares with `mod name;`, each with its file.
fn child_methods(
    root: &Path,
    ast: &syn::File,
    module: &[String],
    ty: &str,
    method: &str,
) -> Result<Vec<Location>, String> {
    let mut found = Vec::new();
    for item in &ast.items {
        let Item::Mod(m) = item else { continue };
        if m.content.is_some() {
            continue; // an inline module: not followed
        }
        let mut child = module.to_vec();
        child.push(m.ident.to_string());
        let Some(file) = module_file(root, &child) else {
            continue;
        };
        let shown = file.display().to_string();
        let text = std::fs::read_to_string(root.join(&file))
            .map_err(|e| format!("cannot read {shown}: {e}"))?;
        let child_ast = parse(&text, &shown)?;
        for one in methods(&child_ast, ty, method) {
            found.push(Location {
                file: file.clone(),
                ..one
            });
        }
    }
    Ok(found)
}

/// The file of the renderer's module `segments` in the project at `root`, relative to `root`, if
/// it exists (`crates/whitted/src/a/b.rs` first, then `…/src/a/b/mod.rs`). No segments is the
/// crate root, `crates/whitted/src/lib.rs`.
#[must_use]
pub fn module_file(root: &Path, segments: &[String]) -> Option<PathBuf> {
    if segments.is_empty() {
        let lib = crate::layout::core_lib();
        return root.join(&lib).is_file().then_some(lib);
    }
    let mut dir = crate::layout::core_src();
    dir.extend(segments.iter().map(String::as_str));
    let flat = dir.with_extension("rs");
    let nested = dir.join("mod.rs");
    [flat, nested].into_iter().find(|f| root.join(f).is_file())
}

/// Parses Rust source text; `file` names it in the error.
pub fn parse(text: &str, file: &str) -> Result<syn::File, String> {
    // a byte-order mark becomes three spaces, so byte offsets stay those of `text`
    let masked;
    let text = match text.strip_prefix('\u{feff}') {
        Some(rest) => {
            masked = format!("   {rest}");
            masked.as_str()
        }
        None => text,
    };
    syn::parse_str::<syn::File>(text).map_err(|e| {
        let start = e.span().start();
        format!(
            "{file}:{}:{}: cannot parse the Rust source: {e}",
            start.line,
            start.column + 1
        )
    })
}

/// A location without its file, for one function found in a parsed file.
fn location(sig: &syn::Signature, block: &syn::Block) -> Location {
    Location {
        file: PathBuf::new(),
        line: sig.fn_token.span.start().line,
        body: block.brace_token.span.join().byte_range(),
        is_const: sig.constness.is_some(),
    }
}

/// The top-level free functions named `name`.
fn free_fns(ast: &syn::File, name: &str) -> Vec<Location> {
    ast.items
        .iter()
        .filter_map(|item| match item {
            Item::Fn(f) if f.sig.ident == name => Some(location(&f.sig, &f.block)),
            _ => None,
        })
        .collect()
}

/// The methods `method` of the top-level `impl` blocks whose type is named `ty` (inherent or
/// trait impls, whatever their generics).
fn methods(ast: &syn::File, ty: &str, method: &str) -> Vec<Location> {
    let mut found = Vec::new();
    for item in &ast.items {
        let Item::Impl(imp) = item else { continue };
        let syn::Type::Path(self_ty) = imp.self_ty.as_ref() else {
            continue;
        };
        let named = self_ty.path.segments.last().is_some_and(|s| s.ident == ty);
        if !named {
            continue;
        }
        for impl_item in &imp.items {
            if let ImplItem::Fn(f) = impl_item
                && f.sig.ident == method
            {
                found.push(location(&f.sig, &f.block));
            }
        }
    }
    found
}

/// The crate paths that the visible (`pub`, `pub(crate)` …) `use` items of module `module`
/// bind to `name`: named imports first, then the glob imports' candidates.
fn reexports(ast: &syn::File, module: &[String], name: &str) -> Vec<Vec<String>> {
    let mut named = Vec::new();
    let mut globs = Vec::new();
    for item in &ast.items {
        let Item::Use(u) = item else { continue };
        if matches!(u.vis, Visibility::Inherited) {
            continue;
        }
        let mut bindings = Vec::new();
        use_bindings(&u.tree, Vec::new(), &mut bindings);
        for (path, bound) in bindings {
            let Some(absolute) = absolute(module, &path) else {
                continue;
            };
            match bound {
                Some(bound) if bound == name => named.push(absolute),
                None => {
                    let mut candidate = absolute;
                    candidate.push(name.to_string());
                    globs.push(candidate);
                }
                Some(_) => {}
            }
        }
    }
    named.extend(globs);
    named
}

/// Flattens a use tree into (path, the name it binds); a glob binds `None` (any name).
fn use_bindings(tree: &UseTree, prefix: Vec<String>, out: &mut Vec<(Vec<String>, Option<String>)>) {
    let with = |ident: &syn::Ident| {
        let mut p = prefix.clone();
        p.push(ident.to_string());
        p
    };
    match tree {
        UseTree::Path(p) => use_bindings(&p.tree, with(&p.ident), out),
        UseTree::Name(n) if n.ident == "self" => {
            if let Some(last) = prefix.last() {
                out.push((prefix.clone(), Some(last.clone())));
            }
        }
        UseTree::Name(n) => out.push((with(&n.ident), Some(n.ident.to_string()))),
        UseTree::Rename(r) => out.push((with(&r.ident), Some(r.rename.to_string()))),
        UseTree::Glob(_) => out.push((prefix, None)),
        UseTree::Group(g) => {
            for tree in &g.items {
                use_bindings(tree, prefix.clone(), out);
            }
        }
    }
}

/// A use path seen from module `module`, as a path from the crate root: `crate::…` is already
/// one, `self::…` and a bare `a::…` start at the module, each `super` climbs one level.
/// `None` when it climbs above the root.
fn absolute(module: &[String], path: &[String]) -> Option<Vec<String>> {
    let mut base: Vec<String> = module.to_vec();
    let mut rest = path;
    match rest.first().map(String::as_str) {
        Some("crate") => {
            base.clear();
            rest = &rest[1..];
        }
        Some("self") => rest = &rest[1..],
        _ => {}
    }
    while rest.first().is_some_and(|s| s == "super") {
        base.pop()?;
        rest = &rest[1..];
    }
    base.extend_from_slice(rest);
    Some(base)
}

/// `text` with the function bodies at `edits` changed; each range must be a body block as
/// [`locate`] gives it (from `{` to `}`), and no two may overlap. Every byte outside the edits
/// is kept as it was.
pub fn edit_bodies(text: &str, edits: &[(Range<usize>, Edit)]) -> Result<String, String> {
    let mut sorted: Vec<&(Range<usize>, Edit)> = edits.iter().collect();
    sorted.sort_by_key(|(range, _)| range.start);
    for pair in sorted.windows(2) {
        if pair[0].0.end > pair[1].0.start {
            return Err(format!(
                "the bodies at bytes {:?} and {:?} overlap",
                pair[0].0, pair[1].0
            ));
        }
    }
    let mut out = String::with_capacity(text.len() + 64 * edits.len());
    let mut copied = 0;
    for (range, edit) in sorted {
        let block = text
            .get(range.clone())
            .filter(|b| b.len() >= 2 && b.starts_with('{') && b.ends_with('}'))
            .ok_or_else(|| format!("bytes {range:?} are not a body block {{ … }} of the text"))?;
        out.push_str(&text[copied..range.start]);
        match edit {
            Edit::Prepend(statement) => {
                out.push('{');
                out.push_str(statement);
                out.push_str(&block[1..]);
            }
            Edit::Replace(body) => {
                out.push('{');
                out.push_str(body);
                out.push('}');
            }
        }
        copied = range.end;
    }
    out.push_str(&text[copied..]);
    Ok(out)
}

/// Finds every manifest function under `root`. An error names the entry and the file.
pub fn locate_all(
    root: &Path,
    manifest: &crate::manifest::Manifest,
) -> Result<Vec<Location>, crate::ToolError> {
    manifest
        .entries
        .iter()
        .map(|entry| {
            let found =
                locate(root, &entry.function).map_err(|message| crate::ToolError::Function {
                    manifest: manifest.file.clone(),
                    line: entry.line,
                    function: entry.function.clone(),
                    message,
                })?;
            if found.is_const {
                return Err(crate::ToolError::Function {
                    manifest: manifest.file.clone(),
                    line: entry.line,
                    function: entry.function.clone(),
                    message: format!(
                        "is a const fn ({}:{}): its body cannot test the poison switch",
                        found.file.display(),
                        found.line
                    ),
                });
            }
            Ok(found)
        })
        .collect()
}
