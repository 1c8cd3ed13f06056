//! The pieces of Rust syntax the file check reads: which items `#[cfg(test)]` keeps out of a
//! build, the leaves of a `use` tree, and the runs of `a :: b :: c` inside the tokens of a macro
//! call or an attribute, which `syn` leaves unparsed.

use proc_macro2::{Spacing, TokenStream, TokenTree};
use syn::{Attribute, Meta, UseTree};

/// A path as written in a file: its segments (`crate`, `render`, `Options`) and the line where
/// it is written (of its last segment, the one that names the item).
#[derive(Clone, Debug)]
pub struct Written {
    /// The segments, `crate`, `super` and `self` included.
    pub segments: Vec<String>,
    /// The line (1-based) of the file.
    pub line: usize,
}

impl Written {
    /// The path as a reader writes it: `crate::render::Options`.
    pub fn text(&self) -> String {
        self.segments.join("::")
    }
}

/// Whether `attrs` hold a `#[cfg(…)]` true only in a test build: `test`, `all(…)` with `test`
/// among its parts, or `any(…)` whose every part is.
pub fn only_in_tests(attrs: &[Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("cfg")
            && matches!(&a.meta, Meta::List(list) if needs_test(&parts(list.tokens.clone())))
    })
}

/// Whether a `cfg` predicate, as its comma-separated parts, needs `test` (all of them must hold,
/// as in `cfg(a, b)` or `all(a, b)`).
fn needs_test(all: &[Vec<TokenTree>]) -> bool {
    all.iter().any(|part| match part.as_slice() {
        [TokenTree::Ident(i)] => i == "test",
        [TokenTree::Ident(i), TokenTree::Group(g)] if i == "all" => needs_test(&parts(g.stream())),
        [TokenTree::Ident(i), TokenTree::Group(g)] if i == "any" => {
            let inner = parts(g.stream());
            !inner.is_empty() && inner.iter().all(|p| needs_test(std::slice::from_ref(p)))
        }
        _ => false,
    })
}

/// The comma-separated parts of a token stream.
fn parts(tokens: TokenStream) -> Vec<Vec<TokenTree>> {
    let mut out = vec![Vec::new()];
    for t in tokens {
        match &t {
            TokenTree::Punct(p) if p.as_char() == ',' => out.push(Vec::new()),
            _ => out.last_mut().expect("never empty").push(t),
        }
    }
    out.retain(|p| !p.is_empty());
    out
}

/// One leaf of a `use` tree.
#[derive(Clone, Debug)]
pub enum Leaf {
    /// `use a::b::C;`, `use a::b::C as D;` and `use a::b::{self}`: the path named, and the name
    /// it binds in the module (none for `as _`).
    Name {
        /// The full path of the leaf (`a::b::C`; `a::b` for `self`).
        path: Written,
        /// The name bound (`C`, `D`, `b`), none for `as _`.
        binds: Option<String>,
    },
    /// `use a::b::*;`: the path whose names come in.
    Glob(Written),
}

/// The leaves of a `use` tree: groups opened, renames and `self` read. A tree that begins with
/// `::` names another crate and has no leaves here.
pub fn leaves(item: &syn::ItemUse) -> Vec<Leaf> {
    let mut out = Vec::new();
    if item.leading_colon.is_none() {
        walk(&item.tree, &mut Vec::new(), &mut out);
    }
    out
}

/// Walks one `use` subtree below `prefix`.
fn walk(tree: &UseTree, prefix: &mut Vec<String>, out: &mut Vec<Leaf>) {
    let written = |prefix: &[String], last: Option<&syn::Ident>, line: usize| Written {
        segments: prefix
            .iter()
            .cloned()
            .chain(last.map(ToString::to_string))
            .collect(),
        line,
    };
    match tree {
        UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            walk(&p.tree, prefix, out);
            prefix.pop();
        }
        UseTree::Name(n) if n.ident == "self" => out.push(Leaf::Name {
            path: written(prefix, None, line(&n.ident)),
            binds: prefix.last().cloned(),
        }),
        UseTree::Name(n) => out.push(Leaf::Name {
            path: written(prefix, Some(&n.ident), line(&n.ident)),
            binds: Some(n.ident.to_string()),
        }),
        UseTree::Rename(r) => out.push(Leaf::Name {
            path: if r.ident == "self" {
                written(prefix, None, line(&r.ident))
            } else {
                written(prefix, Some(&r.ident), line(&r.ident))
            },
            binds: (r.rename != "_").then(|| r.rename.to_string()),
        }),
        UseTree::Glob(g) => out.push(Leaf::Glob(Written {
            segments: prefix.clone(),
            line: g.star_token.spans[0].start().line,
        })),
        UseTree::Group(g) => {
            for t in &g.items {
                walk(t, prefix, out);
            }
        }
    }
}

/// The line of an identifier.
pub fn line(ident: &syn::Ident) -> usize {
    ident.span().start().line
}

/// The runs `a :: b :: c` (two segments or more) in a stream of tokens, groups entered: the
/// paths a macro call (`format!`, `assert!`, `json!` …) or an attribute's arguments name. A run
/// starts at an identifier that does not itself follow `::`; `$crate` reads as `crate`.
pub fn token_paths(tokens: TokenStream, out: &mut Vec<Written>) {
    let tokens: Vec<TokenTree> = tokens.into_iter().collect();
    let colons = |i: usize| {
        matches!((tokens.get(i), tokens.get(i + 1)),
            (Some(TokenTree::Punct(a)), Some(TokenTree::Punct(b)))
                if a.as_char() == ':' && a.spacing() == Spacing::Joint && b.as_char() == ':')
    };
    let mut i = 0;
    while i < tokens.len() {
        match &tokens[i] {
            TokenTree::Group(g) => {
                token_paths(g.stream(), out);
                i += 1;
            }
            TokenTree::Ident(first) if !(i >= 2 && colons(i - 2)) => {
                let mut segments = vec![first.to_string()];
                let mut last = first.span().start().line;
                let mut j = i + 1;
                while colons(j) {
                    match tokens.get(j + 2) {
                        Some(TokenTree::Ident(next)) => {
                            segments.push(next.to_string());
                            last = next.span().start().line;
                            j += 3;
                        }
                        _ => break,
                    }
                }
                if segments.len() >= 2 {
                    out.push(Written {
                        segments,
                        line: last,
                    });
                }
                i = j.max(i + 1);
            }
            _ => i += 1,
        }
    }
}

/// The paths serde's attribute names as strings (`#[serde(with = "crate::x")]`,
/// `serialize_with`, `deserialize_with`, `default`, `skip_serializing_if`): code that runs,
/// written in a string literal. Each comes with whether it names a module whose functions are
/// called (`with`), rather than a function.
pub fn serde_paths(attr: &Attribute, out: &mut Vec<(Written, bool)>) {
    const KEYS: [&str; 5] = [
        "with",
        "serialize_with",
        "deserialize_with",
        "default",
        "skip_serializing_if",
    ];
    let Meta::List(list) = &attr.meta else {
        return;
    };
    if !attr.path().is_ident("serde") {
        return;
    }
    let tokens: Vec<TokenTree> = list.tokens.clone().into_iter().collect();
    for w in tokens.windows(3) {
        if let [
            TokenTree::Ident(key),
            TokenTree::Punct(eq),
            TokenTree::Literal(lit),
        ] = w
            && eq.as_char() == '='
            && KEYS.iter().any(|k| key == k)
            && let Ok(text) = syn::parse_str::<syn::LitStr>(&lit.to_string())
            && let Ok(path) = syn::parse_str::<syn::Path>(&text.value())
            && path.leading_colon.is_none()
        {
            let written = Written {
                segments: path.segments.iter().map(|s| s.ident.to_string()).collect(),
                line: lit.span().start().line,
            };
            out.push((written, key == "with"));
        }
    }
}
