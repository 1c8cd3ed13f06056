//! The screen a body passes before the grader compiles it, and which `cargo learn` runs at every
//! save: it says what an exercise's body is, a formula, and refuses what a formula never needs.
//!
//! A formula's body is statements and expressions: `let`, arithmetic on vectors and reals, calls
//! of the crate's functions and methods, closures, `if`, `match`, loops and their labels, `use`
//! of the crate's items, comments, lint attributes and a few of the standard macros
//! ([`MACROS`]). Any name is free: a variable may be called `env`, `load`, `save`, `path`,
//! `io`, `os` or `exit`. [`screen`] refuses, each with its line, a reason and a way to write it
//! instead ([`Refusal`]):
//!
//! - `unsafe`, `extern`, raw pointers (`*const`, `*mut`, `&raw`): a formula is safe Rust;
//! - **items** declared inside the body (`struct`, `enum`, `trait`, `impl`, `type`, `static`,
//!   `const`, `mod`, `union`), a **generic** helper function (`fn f<T>`), and macro definitions
//!   (`macro_rules!`): a constant is a `let`, a helper a closure or a plain `fn` for the types
//!   it needs. The known soundness holes of the compiler need one of these: a function whose
//!   named lifetimes stretch a borrow (rust-lang/rust#25860's `fn f<'a, 'b, T>(_: &'a &'b (),
//!   v: &'b T) -> &'a T`), generics to turn one type into another, a trait with a faulty impl.
//!   A plain helper `fn` is kept (the reference's own bodies have one): without lifetime names
//!   its signature can tie its result to one argument only, so it cannot stretch a borrow, and
//!   without generics it cannot change a type. Compile-time evaluation (`const`, `static`) is
//!   what stalls a build;
//! - **lifetimes** (`'a`, `'static`) other than loop labels: a formula takes and returns values;
//! - a **path** through a module of the process, files, the network, the environment, threads,
//!   raw memory or the panic machinery (`std::env::var`, `fs::read`, `process::exit`,
//!   `ptr::read`), or to one of the renderer's own functions that reach files
//!   ([`REFUSED_OF_THE_PROJECT`]): a path of two segments or more, or any name a `use` brings in;
//! - **macros** other than [`MACROS`] (`include_str!`, `env!`, `asm!` …), and **attributes**
//!   other than lints, `doc` (a `///` comment) and rustfmt's;
//! - a body whose brackets, braces, quotes or comments do not close inside it.
//!
//! The grader graded a refused body as not written; `cargo learn` says the same at the save,
//! so a student learns it before submitting.
//!
//! Course book: [The student's guide](../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};

pub mod refused;

/// The macros a body may call: printing, formatting, assertions, and the panics that mark what
/// is not written yet.
pub const MACROS: &[&str] = &[
    "assert",
    "assert_eq",
    "assert_ne",
    "debug_assert",
    "debug_assert_eq",
    "debug_assert_ne",
    "dbg",
    "eprint",
    "eprintln",
    "format",
    "matches",
    "panic",
    "print",
    "println",
    "todo",
    "unimplemented",
    "unreachable",
    "vec",
];

/// The attributes a body may carry: lints, doc comments and rustfmt's.
const ATTRIBUTES: &[&str] = &[
    "allow", "expect", "warn", "deny", "forbid", "doc", "rustfmt", "clippy",
];

/// The modules and types of the standard library (and the crates beside it) that reach beyond
/// computing: a path through one of them is refused, with what it reaches.
const STD_REFUSED: &[(&[&str], &str)] = &[
    (
        &["process", "Command", "Stdio", "ExitCode", "Termination"],
        "ends or starts a process",
    ),
    (
        &[
            "fs",
            "io",
            "File",
            "OpenOptions",
            "Path",
            "PathBuf",
            "stdin",
            "stdout",
            "stderr",
        ],
        "reaches files",
    ),
    (
        &[
            "net",
            "TcpStream",
            "TcpListener",
            "UdpSocket",
            "UnixStream",
            "UnixListener",
        ],
        "reaches the network",
    ),
    (&["env", "os", "ffi"], "reaches the environment"),
    (&["thread", "rayon"], "starts threads"),
    (
        &[
            "ptr",
            "alloc",
            "intrinsics",
            "arch",
            "asm",
            "transmute",
            "GlobalAlloc",
            "libc",
        ],
        "reaches raw memory",
    ),
    (
        &[
            "panic",
            "set_hook",
            "take_hook",
            "catch_unwind",
            "resume_unwind",
            "always_abort",
        ],
        "changes how a panic ends",
    ),
    (&["proc_macro", "tempfile"], "reaches the compiler or files"),
    (&["judge", "judged"], "reaches the grader's wire"),
];

/// The functions and types of the renderer and the syllabus that open a file or end the process:
/// a path to one is refused like a path through the standard library's modules of the process or
/// the files (`tests/grade.rs` checks this is all of them).
pub const REFUSED_OF_THE_PROJECT: &[&str] = &[
    "check_destination",
    "write_png",
    "read_png",
    "write_file",
    "save",
    "load",
    "load_parts",
    "read_rgba",
    "leave_after_args",
    "TreeFile",
];

/// Keywords that declare an item, which a body never needs (a plain `fn` is judged apart).
const ITEMS: &[&str] = &[
    "struct", "enum", "trait", "impl", "type", "static", "const", "mod", "union",
];

/// Rust's keywords: an identifier that is one is never a macro's name (`if !(a)`).
const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub",
    "ref", "return", "self", "Self", "static", "struct", "super", "trait", "true", "type",
    "unsafe", "use", "where", "while", "yield",
];

/// What the screen refuses in a body: the line (from 1, in the body), what was written, why a
/// formula never needs it, and how to write it instead.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// The line of the body, from 1.
    pub line: usize,
    /// What the body wrote (`` `std::env::var` ``, `` `unsafe` ``).
    pub what: String,
    /// Why a formula never needs it.
    pub why: String,
    /// How to write it instead.
    pub instead: String,
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "line {} of the body: {} {}; {}",
            self.line, self.what, self.why, self.instead
        )
    }
}

/// The first thing in `body` (an exercise's body, the lines between its markers) that the
/// screen refuses, or `None` when the body is a formula. See the module's documentation.
#[must_use]
pub fn screen(body: &str) -> Option<Refusal> {
    match body.parse::<TokenStream>() {
        Ok(tokens) => {
            let tokens: Vec<TokenTree> = tokens.into_iter().collect();
            walk(&tokens)
        }
        Err(e) => Some(Refusal {
            line: e.span().start().line.max(1),
            what: "a bracket, brace, quote or comment".into(),
            why: "does not close inside the body".into(),
            instead: "close each one before the body's end".into(),
        }),
    }
}

/// The line of a token, from 1.
fn line_of(t: &TokenTree) -> usize {
    t.span().start().line.max(1)
}

/// An identifier as the compiler resolves it: without `r#`.
fn ident(t: &TokenTree) -> Option<String> {
    match t {
        TokenTree::Ident(i) => Some(i.to_string().trim_start_matches("r#").to_string()),
        _ => None,
    }
}

fn punct(t: Option<&TokenTree>, c: char) -> bool {
    matches!(t, Some(TokenTree::Punct(p)) if p.as_char() == c)
}

/// Why a path segment is refused, when it is.
fn refused_segment(name: &str) -> Option<&'static str> {
    if REFUSED_OF_THE_PROJECT.contains(&name) {
        return Some("reaches files or ends the process");
    }
    STD_REFUSED
        .iter()
        .find(|(names, _)| names.contains(&name))
        .map(|(_, why)| *why)
}

fn refuse(line: usize, what: String, why: &str, instead: &str) -> Option<Refusal> {
    Some(Refusal {
        line,
        what,
        why: why.into(),
        instead: instead.into(),
    })
}

/// The path that starts at `tokens[i]`: its segments (`a::b::c`), and the index after it.
fn path_at(tokens: &[TokenTree], i: usize) -> (Vec<String>, usize) {
    let mut segments = Vec::new();
    let mut j = i;
    loop {
        let colons = punct(tokens.get(j), ':') && punct(tokens.get(j + 1), ':');
        if colons {
            j += 2;
            continue;
        }
        match tokens.get(j).and_then(ident) {
            Some(name) if segments.is_empty() || colons_before(tokens, j) => {
                segments.push(name);
                j += 1;
            }
            _ => break,
        }
    }
    (segments, j)
}

/// Whether `::` stands right before `tokens[j]`.
fn colons_before(tokens: &[TokenTree], j: usize) -> bool {
    j >= 2 && punct(tokens.get(j - 1), ':') && punct(tokens.get(j - 2), ':')
}

/// Whether the lifetime whose name is at `tokens[i]` (after its `'`) is a loop label: defined
/// (`'outer: loop`) or used (`break 'outer`).
fn is_label(tokens: &[TokenTree], i: usize) -> bool {
    let used = i >= 2
        && tokens
            .get(i - 2)
            .and_then(ident)
            .is_some_and(|k| k == "break" || k == "continue");
    let defined = punct(tokens.get(i + 1), ':')
        && !punct(tokens.get(i + 2), ':')
        && match tokens.get(i + 2) {
            Some(TokenTree::Group(g)) => g.delimiter() == Delimiter::Brace,
            Some(t) => ident(t).is_some_and(|k| matches!(k.as_str(), "loop" | "while" | "for")),
            None => false,
        };
    used || defined
}

fn walk(tokens: &[TokenTree]) -> Option<Refusal> {
    let mut i = 0;
    while i < tokens.len() {
        let t = &tokens[i];
        let line = line_of(t);
        match t {
            TokenTree::Punct(p) if p.as_char() == '\'' && p.spacing() == Spacing::Joint => {
                let name = tokens.get(i + 1).and_then(ident).unwrap_or_default();
                if !is_label(tokens, i + 1) {
                    return refuse(
                        line,
                        format!("`'{name}`"),
                        "names a lifetime, which a formula never needs",
                        "take and return values (Vec3, Real, Ray) and let the compiler infer the rest",
                    );
                }
                i += 2;
                continue;
            }
            TokenTree::Punct(p) if p.as_char() == '#' => {
                let inner = punct(tokens.get(i + 1), '!');
                let at = if inner { i + 2 } else { i + 1 };
                if let Some(TokenTree::Group(g)) = tokens.get(at)
                    && g.delimiter() == Delimiter::Bracket
                {
                    let first = g.stream().into_iter().next();
                    let name = first.as_ref().and_then(ident).unwrap_or_default();
                    if !ATTRIBUTES.contains(&name.as_str()) {
                        return refuse(
                            line,
                            format!("`#[{name}]`"),
                            "is an attribute a formula never needs",
                            "keep to lint attributes such as `#[allow(clippy::…)]`, and comments",
                        );
                    }
                    i = at + 1;
                    continue;
                }
            }
            // `mut` and `const` are keywords: after a `*` they make a pointer's type
            TokenTree::Punct(p)
                if p.as_char() == '*'
                    && tokens
                        .get(i + 1)
                        .and_then(ident)
                        .is_some_and(|k| k == "const" || k == "mut") =>
            {
                return refuse(
                    line,
                    "a raw pointer (`*const`, `*mut`)".into(),
                    "reaches raw memory, which a formula never needs",
                    "use references and values",
                );
            }
            TokenTree::Group(g) => {
                if let Some(r) = walk(&g.stream().into_iter().collect::<Vec<_>>()) {
                    return Some(r);
                }
            }
            TokenTree::Ident(_) => {
                let word = ident(t).unwrap_or_default();
                if let Some(r) = keyword(tokens, i, &word, line) {
                    return Some(r);
                }
                if word == "use" {
                    // every name a `use` brings in is a path, whatever its length
                    let end = (i..tokens.len())
                        .find(|&j| punct(tokens.get(j), ';'))
                        .unwrap_or(tokens.len());
                    if let Some(r) = use_tree(&tokens[i + 1..end]) {
                        return Some(r);
                    }
                    i = end + 1;
                    continue;
                }
                let (segments, after) = path_at(tokens, i);
                let rooted = colons_before(tokens, i);
                if (segments.len() > 1 || rooted)
                    && let Some((s, why)) = segments
                        .iter()
                        .find_map(|s| refused_segment(s).map(|w| (s, w)))
                {
                    return refuse(
                        line,
                        format!("`{}` (`{s}`)", segments.join("::")),
                        &format!("{why}, which a formula never needs"),
                        "compute the result from the function's arguments",
                    );
                }
                // a macro call: `name!(…)`, `path::name!{…}`
                let bang = punct(tokens.get(after), '!')
                    && matches!(tokens.get(after + 1), Some(TokenTree::Group(_)));
                let last = segments.last().cloned().unwrap_or_default();
                if bang && !KEYWORDS.contains(&last.as_str()) && !MACROS.contains(&last.as_str()) {
                    return refuse(
                        line,
                        format!("`{last}!`"),
                        "is a macro a formula never needs",
                        &format!("the macros a body may use are {}", MACROS.join("!, ") + "!"),
                    );
                }
                i = after.max(i + 1);
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// What a keyword at `tokens[i]` opens, when a formula never needs it.
fn keyword(tokens: &[TokenTree], i: usize, word: &str, line: usize) -> Option<Refusal> {
    match word {
        "unsafe" => refuse(
            line,
            "`unsafe`".into(),
            "steps outside safe Rust, which a formula never needs",
            "write it with the safe operations of Vec3 and Real",
        ),
        "extern" => refuse(
            line,
            "`extern`".into(),
            "links to code outside Rust, which a formula never needs",
            "call the crate's own functions",
        ),
        "macro_rules" | "macro" => refuse(
            line,
            format!("`{word}`"),
            "defines a macro, which a formula never needs",
            "write a closure: `let f = |x: Real| x * x;`",
        ),
        "raw"
            if i > 0
                && punct(tokens.get(i - 1), '&')
                && tokens
                    .get(i + 1)
                    .and_then(ident)
                    .is_some_and(|k| k == "const" || k == "mut") =>
        {
            refuse(
                line,
                "`&raw`".into(),
                "makes a raw pointer, which a formula never needs",
                "use references and values",
            )
        }
        // a helper function without generics, or a function pointer's type: `fn name(…)`,
        // `fn(…)`; a generic one (`fn name<T>(…)`) is refused
        "fn" => {
            let name = tokens.get(i + 1).and_then(ident);
            let params = if name.is_some() { i + 2 } else { i + 1 };
            match tokens.get(params) {
                Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Parenthesis => None,
                _ => refuse(
                    line,
                    format!("`fn {}<…>`", name.unwrap_or_default()),
                    "declares a generic function, which a formula never needs",
                    "write the helper for the types it takes (`fn square(x: Real) -> Real`), or as a closure",
                ),
            }
        }
        // `union` is a keyword only where it declares one
        "union" if tokens.get(i + 1).and_then(ident).is_none() => None,
        w if ITEMS.contains(&w) => {
            let instead = if matches!(w, "const" | "static") {
                "name the value with `let`: `let eps = 1e-9;`"
            } else {
                "write a helper as a closure, `let square = |x: Real| x * x;`, and let types be inferred"
            };
            refuse(
                line,
                format!("`{w}`"),
                "declares an item inside the body, which a formula never needs",
                instead,
            )
        }
        _ => None,
    }
}

/// The first refused name a `use` brings in (the tokens after `use`, to its `;`).
fn use_tree(tokens: &[TokenTree]) -> Option<Refusal> {
    for t in tokens {
        match t {
            TokenTree::Group(g) => {
                if let Some(r) = use_tree(&g.stream().into_iter().collect::<Vec<_>>()) {
                    return Some(r);
                }
            }
            TokenTree::Ident(_) => {
                let name = ident(t).unwrap_or_default();
                if let Some(why) = refused_segment(&name) {
                    return refuse(
                        line_of(t),
                        format!("`use` of `{name}`"),
                        &format!("{why}, which a formula never needs"),
                        "compute the result from the function's arguments",
                    );
                }
            }
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests;
