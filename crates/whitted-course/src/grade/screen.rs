//! The screen a student's body passes before the grader compiles it: a body may compute, and
//! nothing else.
//!
//! An exercise's body is a formula: arithmetic on vectors and reals, a few calls to the
//! renderer's other formulas, a loop, a `match`. It never needs to end its process, start
//! another, open a file or a socket, read the environment, run code at compile time or step
//! outside safe Rust. So the grader refuses, before compiling anything, a body whose tokens
//! name any of those things ([`screen`]), by any spelling the compiler would accept:
//!
//! - **identifiers**, wherever they stand (a path segment, a `use`, a macro's name, an
//!   argument handed to a `macro_rules!` that would paste it): `process`, `Command`, `fs`,
//!   `io`, `net`, `env`, `os`, `thread`, `libc`, `include_str`, `option_env` … ([`REFUSED`]),
//!   and the renderer's own functions that open a file or end the process
//!   ([`REFUSED_OF_THE_PROJECT`]); a raw identifier (`r#process`) is the same identifier;
//! - **keywords and items** that open a door: `unsafe`, `extern`, `macro_rules`, `macro`, `mod`;
//! - **attributes** other than lints, `inline`, `cold`, `must_use`, `derive` and `rustfmt`
//!   (so no `#[path]`, `#[no_mangle]`, `#[export_name]`, `#[link_section]`,
//!   `#[global_allocator]`, `#[cfg_attr(…)]`);
//! - a body whose **delimiters do not balance** (it could close its function and add items).
//!
//! A name in a string or a comment is not a token, and a variable may be called anything that
//! is not refused. The screen is the first of two locks: the second, the test runner's, passes
//! a test only when libtest itself reported it `ok` ([`super::sandbox`]), so a body that
//! found a way past the screen to end its process still passes nothing.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use proc_macro2::{Delimiter, TokenStream, TokenTree};

/// Identifiers a formula never needs, refused wherever they appear in a body: the standard
/// library's ways to end or start a process, reach files, sockets, the environment, threads,
/// raw memory, the panic machinery, and the macros that read files or the environment at
/// compile time.
pub const REFUSED: &[&str] = &[
    // ending the process, or starting another (`exit` and `abort` are reached only through
    // these paths, so a variable may be called `exit`, as a ray's exit point is)
    "process",
    "exec",
    "Command",
    "Stdio",
    "ExitCode",
    "Termination",
    // files, sockets, the environment, the operating system
    "fs",
    "io",
    "net",
    "env",
    "os",
    "File",
    "OpenOptions",
    "Path",
    "PathBuf",
    "TcpStream",
    "TcpListener",
    "UdpSocket",
    "UnixStream",
    "UnixListener",
    "stdin",
    "stdout",
    "stderr",
    // threads and other crates' processes, files and threads
    "thread",
    "rayon",
    "tempfile",
    "libc",
    // raw memory, the machine, the allocator
    "ptr",
    "intrinsics",
    "arch",
    "asm",
    "global_asm",
    "naked_asm",
    "alloc",
    "GlobalAlloc",
    "transmute",
    // the panic machinery (a hook or a catch could turn a failed assertion into something else)
    "set_hook",
    "take_hook",
    "catch_unwind",
    "resume_unwind",
    "always_abort",
    // what reads files or the environment at compile time, called or handed to a macro
    "include",
    "include_str",
    "include_bytes",
    "option_env",
    "concat_idents",
    "proc_macro",
];

/// The functions of the renderer and the syllabus that open a file or end the process, which
/// a body could otherwise reach through its own crate: refused by name like [`REFUSED`].
/// `tests/grade.rs` checks that these are all such functions there are.
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

/// Keywords that open a door out of safe, local computation.
const REFUSED_KEYWORDS: &[&str] = &["unsafe", "extern", "macro_rules", "macro", "mod"];

/// The attributes a body may carry: lints, inlining, `must_use`, `derive`, rustfmt's.
const ALLOWED_ATTRIBUTES: &[&str] = &[
    "allow", "expect", "warn", "deny", "forbid", "inline", "cold", "must_use", "derive", "rustfmt",
    "clippy",
];

/// What in `body` the grader refuses to compile, named as the body writes it (`` `process` ``,
/// `` `#[no_mangle]` ``, `` `unsafe` ``, "delimiters that do not balance"); `None` when the
/// body only computes. See the module's documentation for what is refused and why.
#[must_use]
pub fn screen(body: &str) -> Option<String> {
    match body.parse::<TokenStream>() {
        Ok(tokens) => walk(tokens),
        Err(_) => Some("delimiters that do not balance".into()),
    }
}

/// An identifier as the compiler resolves it: without `r#`.
fn resolved(ident: &str) -> String {
    ident.trim_start_matches("r#").to_string()
}

fn walk(tokens: TokenStream) -> Option<String> {
    let tokens: Vec<TokenTree> = tokens.into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Ident(id) => {
                let name = resolved(&id.to_string());
                if REFUSED_KEYWORDS.contains(&name.as_str()) {
                    return Some(format!("`{name}`"));
                }
                if REFUSED.contains(&name.as_str())
                    || REFUSED_OF_THE_PROJECT.contains(&name.as_str())
                {
                    return Some(format!("`{name}`"));
                }
            }
            TokenTree::Group(g) => {
                let after_hash =
                    i > 0 && matches!(&tokens[i - 1], TokenTree::Punct(p) if p.as_char() == '#');
                // `#[…]` or `#![…]`: the `!` stands between the `#` and the brackets
                let after_hash_bang = i > 1
                    && matches!(&tokens[i - 1], TokenTree::Punct(p) if p.as_char() == '!')
                    && matches!(&tokens[i - 2], TokenTree::Punct(p) if p.as_char() == '#');
                if g.delimiter() == Delimiter::Bracket && (after_hash || after_hash_bang) {
                    let first = g.stream().into_iter().next();
                    let name = match &first {
                        Some(TokenTree::Ident(id)) => resolved(&id.to_string()),
                        _ => String::new(),
                    };
                    if !ALLOWED_ATTRIBUTES.contains(&name.as_str()) {
                        return Some(format!("`#[{name}]`"));
                    }
                }
                if let Some(found) = walk(g.stream()) {
                    return Some(found);
                }
            }
            _ => {}
        }
    }
    None
}
