//! The judge outside the student's process: the code a copy of the project gains so that an
//! exercise's calls cross the wire of the renderer's `judge` module (its documentation tells
//! the whole design).
//!
//! [`add_wire`] writes three things into a copy, each from the manifest and the functions'
//! signatures, and nothing else:
//!
//! - **a stub** first in each exercise's function, on the line of its `{` (no line of the file
//!   moves, so a compiler error still names the student's line):
//!   `if crate::judged::remote(12) { return crate::judged::call(12, &(ray, a, b)); }`;
//! - **an answer** at the end of the function's file, where the signature's type names mean what
//!   they mean in it: it decodes the arguments, calls the function and encodes its value;
//! - **the table** (`crate::judged`) at the end of `lib.rs`, and the server program
//!   (`examples/judged_server.rs`).
//!
//! The same code goes into the judge's copy (the instructor's bodies, and the tests) and into
//! the server's (the student's bodies). An argument crosses by value: `&T` as a `T`, `&[T]` as
//! a `Vec<T>`. The road's three methods cross by the renderer's `render::crossing`: the
//! tracer's parts go, the recorder stays, and the events recorded on the other side come back
//! with the value. An iterator (`transmittance`'s) does not cross: the other side pulls its
//! items one by one as the function asks for them, since which items are pulled is part of the
//! contract (it stops at the first 0). A function with an argument that cannot cross gets no
//! stub: [`Wired::kept`] names it, and it runs where it is called (none of the course's).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::alone::quoted_prefixes;
use crate::manifest::Manifest;
use crate::source;
use crate::{ToolError, files, layout};

/// The environment variable that gives the judge's tests the server's command line (the
/// renderer's `judge::SERVER_VAR`): its words separated by `\x1f`.
pub const SERVER_VAR: &str = "WHITTED_JUDGE_SERVER";

/// The environment variable that makes the judge send every exercise of every test to the
/// server (the renderer's `judge::WHOLE_ROAD_VAR`): `--whole-road`.
pub const WHOLE_ROAD_VAR: &str = "WHITTED_JUDGE_WHOLE_ROAD";

/// The server program a wired copy gains, beside the renderer's crate's sources.
pub const SERVER_EXAMPLE: &str = "judged_server";

/// The road's type: its methods read the tracer and tell a recorder what they compute, and
/// cross by the renderer's `render::crossing` module.
const ROAD: &str = "Tracer";

/// The renderer's module that carries the road's methods across.
const CROSSING: &str = "crate::render::crossing";

/// The road's methods that `render::crossing` answers (`answer_NAME`).
const ROAD_ANSWERS: [&str; 3] = ["local_light", "feeler", "reflect_and_refract"];

/// What [`add_wire`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Wired {
    /// The manifest entries whose calls cross the wire.
    pub crossing: Vec<usize>,
    /// The entries that run where they are called, each with the argument that cannot cross.
    pub kept: Vec<(usize, String)>,
}

/// How one argument crosses.
#[derive(Debug, PartialEq, Eq)]
struct Crossing {
    /// What the stub sends for it.
    sent: String,
    /// The type the answer decodes.
    decoded: String,
    /// What the answer passes to the function (`a0`, `&a0`).
    passed: String,
    /// For an iterator, its name and its items' type: it does not cross with the arguments,
    /// its items are pulled one by one.
    pulled: Option<(String, String)>,
}

/// How the argument `param` (a parameter's text, `name: Type` or a receiver) crosses as the
/// answer's argument number `k`, or why it cannot.
fn crossing(param: &str, k: usize, self_type: Option<&str>) -> Result<Crossing, String> {
    let a = format!("a{k}");
    let param = param.trim();
    if param == "&self" {
        let ty = self_type.ok_or("a receiver outside an `impl`")?;
        if ty == ROAD {
            // the parts of the tracer its methods read; the other side asks every object
            return Ok(Crossing {
                sent: format!("{CROSSING}::RoadRef::of(self)"),
                decoded: String::new(),
                passed: String::new(),
                pulled: None,
            });
        }
        return Ok(Crossing {
            sent: "self".into(),
            decoded: ty.into(),
            passed: format!("&{a}"),
            pulled: None,
        });
    }
    let (name, ty) =
        top_level_split(param, ':').ok_or_else(|| format!("`{param}` is no `name: Type`"))?;
    let (name, ty) = (name.trim(), ty.trim());
    let name = name.strip_prefix("mut ").unwrap_or(name).trim();
    if !name.chars().all(|c| c == '_' || c.is_alphanumeric()) {
        return Err(format!("`{param}`: a pattern, not a name"));
    }
    if ty.starts_with("&mut") || ty.contains("Recorder") {
        return Err(format!(
            "`{param}`: what the function changes stays in its process"
        ));
    }
    if let Some(item) = ty
        .strip_prefix("impl IntoIterator<Item =")
        .and_then(|t| t.strip_suffix('>'))
    {
        // which items are pulled is part of the contract (`transmittance` stops at the first
        // 0): they are pulled one by one, never sent as a whole
        let item = item.trim();
        return Ok(Crossing {
            sent: String::new(),
            decoded: String::new(),
            passed: format!("crate::judged::pulled::<{item}>()"),
            pulled: Some((name.into(), item.into())),
        });
    }
    if ty.starts_with("impl ") || ty.contains("dyn ") {
        return Err(format!("`{param}`: a type the wire does not know"));
    }
    let (decoded, passed) =
        if let Some(slice) = ty.strip_prefix("&[").and_then(|t| t.strip_suffix(']')) {
            (format!("Vec<{}>", slice.trim()), format!("&{a}"))
        } else if let Some(inner) = ty.strip_prefix('&') {
            (inner.trim().to_string(), format!("&{a}"))
        } else {
            (ty.to_string(), a)
        };
    Ok(Crossing {
        sent: name.into(),
        decoded,
        passed,
        pulled: None,
    })
}

/// `text` split at its first `sep` outside brackets, or `None`.
fn top_level_split(text: &str, sep: char) -> Option<(&str, &str)> {
    let mut depth = 0i32;
    let mut previous = ' ';
    for (i, c) in text.char_indices() {
        let arrow = previous == '-';
        previous = c;
        match c {
            '(' | '[' | '<' | '{' => depth += 1,
            '>' if arrow => {}
            ')' | ']' | '>' | '}' => depth -= 1,
            c if c == sep && depth == 0 => return Some((&text[..i], &text[i + c.len_utf8()..])),
            _ => {}
        }
    }
    None
}

/// The parameters of the signature that ends where `body` (a function's `{`) starts: the text
/// between the parentheses after `fn NAME`, split at its top-level commas.
fn parameters(text: &str, body: usize, name: &str) -> Result<Vec<String>, String> {
    let head = &text[..body];
    let at = head
        .rfind(&format!("fn {name}"))
        .ok_or_else(|| format!("no `fn {name}` before its body"))?;
    let open = at
        + head[at..]
            .find('(')
            .ok_or_else(|| format!("`fn {name}` has no `(`"))?;
    let mut depth = 0i32;
    let mut close = None;
    for (i, c) in head[open..].char_indices() {
        match c {
            '(' | '[' | '<' => depth += 1,
            ')' | ']' | '>' if !head[open..open + i].ends_with('-') => {
                depth -= 1;
                if depth == 0 {
                    close = Some(open + i);
                    break;
                }
            }
            _ => {}
        }
    }
    let close = close.ok_or_else(|| format!("`fn {name}`'s parameters do not close"))?;
    let mut params = Vec::new();
    let mut rest = &head[open + 1..close];
    while let Some((one, after)) = top_level_split(rest, ',') {
        params.push(one.trim().to_string());
        rest = after;
    }
    if !rest.trim().is_empty() {
        params.push(rest.trim().to_string());
    }
    Ok(params)
}

/// The module path (`crate::shapes::sphere`) of a source file of the renderer's crate.
fn module_of(file: &Path) -> String {
    let relative = file.strip_prefix(layout::core_src()).unwrap_or(file);
    let mut parts: Vec<String> = relative
        .with_extension("")
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    std::iter::once("crate".to_string())
        .chain(parts)
        .collect::<Vec<_>>()
        .join("::")
}

/// The stub and the answer of the function `path` (the manifest's, `module::Type::method` or
/// `module::fn`) whose parameters are `params`, as exercise `n`.
fn stub_and_answer(n: usize, path: &str, params: &[String]) -> Result<Made, String> {
    let segments: Vec<&str> = path.split("::").collect();
    let function = segments.last().copied().unwrap_or_default();
    let self_type = segments
        .len()
        .checked_sub(2)
        .map(|i| segments[i])
        .filter(|s| s.starts_with(|c: char| c.is_uppercase()));
    if self_type == Some(ROAD) {
        return road_stub(n, function, params);
    }
    let crossings = params
        .iter()
        .enumerate()
        .map(|(k, p)| crossing(p, k, self_type))
        .collect::<Result<Vec<_>, _>>()?;
    let sent: Vec<&str> = crossings
        .iter()
        .filter(|c| c.pulled.is_none())
        .map(|c| c.sent.as_str())
        .collect();
    let sent = tuple(&sent);
    let pulled: Vec<&(String, String)> =
        crossings.iter().filter_map(|c| c.pulled.as_ref()).collect();
    let stub = match pulled.as_slice() {
        [] => {
            format!("if crate::judged::remote({n}) {{ return crate::judged::call({n}, &{sent}); }}")
        }
        [(name, item)] => format!(
            "if crate::judged::remote({n}) {{ let mut items = {name}.into_iter(); return crate::judged::call_pulling::<_, _, {item}>({n}, &{sent}, &mut items); }}"
        ),
        _ => return Err("two iterators: the wire pulls from one".into()),
    };
    let names: Vec<String> = (0..crossings.len())
        .filter(|&k| crossings[k].pulled.is_none())
        .map(|k| format!("a{k}"))
        .collect();
    let types: Vec<&str> = crossings
        .iter()
        .filter(|c| c.pulled.is_none())
        .map(|c| c.decoded.as_str())
        .collect();
    let passed: Vec<&str> = crossings.iter().map(|c| c.passed.as_str()).collect();
    let callee = match self_type {
        Some(ty) => format!("{ty}::{function}"),
        None => function.to_string(),
    };
    let answer = format!(
        "\n/// Written by `whitted grade`: exercise {n} run here for the other end of the grader's wire.\n#[doc(hidden)]\npub(crate) fn judged_answer_{n}(args: &[u8]) -> Result<Vec<u8>, String> {{\n    let {}: {} = crate::judge::decode(args)?;\n    crate::judge::encode(&{callee}({}))\n}}\n",
        tuple(&names),
        tuple(&types),
        passed.join(", "),
    );
    Ok(Made {
        stub,
        answer,
        answered_by: None,
    })
}

/// The Rust tuple of `parts`: `()` when there are none, `(a,)` for one.
fn tuple<S: AsRef<str>>(parts: &[S]) -> String {
    if parts.is_empty() {
        return "()".into();
    }
    let parts: Vec<&str> = parts.iter().map(AsRef::as_ref).collect();
    format!("({},)", parts.join(", "))
}

/// The stub of the road's method `function` (its parameters `params`): the tracer's parts and
/// the other arguments cross, the recorder does not; the events the method recorded on the
/// other side come back with its value, and the stub tells them to its own recorder.
fn road_stub(n: usize, function: &str, params: &[String]) -> Result<Made, String> {
    if !ROAD_ANSWERS.contains(&function) {
        return Err(format!(
            "`{ROAD}::{function}`: {CROSSING} has no answer for it"
        ));
    }
    let mut sent = Vec::new();
    let mut recorder = None;
    for (k, p) in params.iter().enumerate() {
        let name = p.split(':').next().unwrap_or_default().trim();
        if p.contains("Recorder") {
            recorder = Some(name.to_string());
        } else {
            sent.push(crossing(p, k, Some(ROAD))?.sent);
        }
    }
    let sent = tuple(&sent);
    let stub = match recorder {
        Some(rec) => format!(
            "if crate::judged::remote({n}) {{ let (value, events): (_, Vec<{CROSSING}::Event>) = crate::judged::call({n}, &{sent}); {CROSSING}::replay(&events, {rec}); return value; }}"
        ),
        None => {
            format!("if crate::judged::remote({n}) {{ return crate::judged::call({n}, &{sent}); }}")
        }
    };
    Ok(Made {
        stub,
        answer: String::new(),
        answered_by: Some(format!("{CROSSING}::answer_{function}")),
    })
}

/// One exercise's wire: its stub, the answer appended to its file, and the function that
/// answers for it when that is not the appended one.
struct Made {
    stub: String,
    answer: String,
    answered_by: Option<String>,
}

/// What one source file gains: the stubs, each inserted at a byte of the file's text (right
/// after its function's `{`, on the same line), and the answers appended.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileWire {
    /// Each stub and the byte of the file's text it goes at, in the order of the text.
    pub stubs: Vec<(usize, String)>,
    /// The answers, appended to the file.
    pub answers: String,
}

impl FileWire {
    /// `text` (the file's text the wire was planned on, or one whose bytes before each stub
    /// are the same) with the stubs in and the answers appended.
    #[must_use]
    pub fn apply(&self, text: &str) -> String {
        let mut out = String::with_capacity(text.len() + self.answers.len() + 128);
        let mut copied = 0;
        for (at, stub) in &self.stubs {
            out.push_str(&text[copied..*at]);
            out.push_str(stub);
            copied = *at;
        }
        out.push_str(&text[copied..]);
        out.push_str(&self.answers);
        out
    }
}

/// The wire of a project, planned from its files before any of them changes: what each file
/// gains, the table `lib.rs` gains, and which exercises cross.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Wire {
    /// What was wired.
    pub wired: Wired,
    /// By source file (relative to the project): its stubs and answers.
    pub files: BTreeMap<PathBuf, FileWire>,
    /// The module appended to `lib.rs`.
    pub table: String,
}

/// Plans the wire of the project at `project` from its files as they are (see the module's
/// documentation): nothing is written.
pub fn plan_wire(project: &Path, manifest: &Manifest) -> Result<Wire, ToolError> {
    let mut wire = Wire::default();
    let mut arms = Vec::new();
    for (n, entry) in manifest.entries.iter().enumerate() {
        let at =
            source::locate(project, &entry.function).map_err(|message| ToolError::Function {
                manifest: manifest.file.clone(),
                line: entry.line,
                function: entry.function.clone(),
                message,
            })?;
        let path = project.join(&at.file);
        let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
        let name = entry.function.rsplit("::").next().unwrap_or_default();
        let made = parameters(&text, at.body.start, name)
            .and_then(|params| stub_and_answer(n, &entry.function, &params));
        match made {
            Ok(made) => {
                let file = wire.files.entry(at.file.clone()).or_default();
                file.stubs.push((at.body.start + 1, made.stub));
                file.answers.push_str(&made.answer);
                let answer = made
                    .answered_by
                    .unwrap_or_else(|| format!("{}::judged_answer_{n}", module_of(&at.file)));
                arms.push(format!("            {n} => {answer}(args),"));
                wire.wired.crossing.push(n);
            }
            Err(why) => wire.wired.kept.push((n, why)),
        }
    }
    for file in wire.files.values_mut() {
        file.stubs.sort_by_key(|(at, _)| *at);
    }
    wire.table = table(manifest, &arms);
    Ok(wire)
}

impl Wire {
    /// Writes what is not in an exercise's file into the copy at `project`, whose `lib.rs` is
    /// the one the wire was planned on: the table at the end of `lib.rs`, and the server
    /// program.
    pub fn write_table(&self, project: &Path) -> Result<(), ToolError> {
        let lib = project.join(layout::core_lib());
        let text = std::fs::read_to_string(&lib).map_err(|e| ToolError::io(&lib, e))?;
        files::write_if_changed(&lib, format!("{text}{}", self.table).as_bytes())?;
        self.write_server(project)
    }

    /// Writes the server program (`examples/judged_server.rs`) beside the renderer's sources.
    pub fn write_server(&self, project: &Path) -> Result<(), ToolError> {
        let examples = project.join(layout::core_src()).with_file_name("examples");
        std::fs::create_dir_all(&examples).map_err(|e| ToolError::io(&examples, e))?;
        let server = examples.join(format!("{SERVER_EXAMPLE}.rs"));
        files::write_if_changed(
            &server,
            b"//! Written by `whitted grade`: the student's end of the grader's wire.\n\nfn main() -> std::process::ExitCode {\n    whitted::judged::serve()\n}\n",
        )
        .map(|_| ())
    }
}

/// Writes the wire into the copy of the project at `project`: every exercise's stub and answer
/// that can cross, the table, and the server program (see the module's documentation).
pub fn add_wire(project: &Path, manifest: &Manifest) -> Result<Wired, ToolError> {
    let wire = plan_wire(project, manifest)?;
    for (file, w) in &wire.files {
        let path = project.join(file);
        let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
        files::write_if_changed(&path, w.apply(&text).as_bytes())?;
    }
    wire.write_table(project)?;
    Ok(wire.wired)
}

/// The table module appended to `lib.rs`: the exercises' test prefixes and the dispatch over
/// the answers (`arms`).
fn table(manifest: &Manifest, arms: &[String]) -> String {
    let prefixes = quoted_prefixes(manifest);
    format!(
        r#"
/// Written by `whitted grade`: this copy's end of the grader's wire ([`crate::judge`]).
#[doc(hidden)]
pub mod judged {{
    static TABLE: crate::judge::Table = crate::judge::Table {{
        prefixes: &[{prefixes}],
        dispatch,
    }};

    fn dispatch(n: u16, args: &[u8]) -> Result<Vec<u8>, String> {{
        match n {{
{arms}
            _ => Err(format!("exercise {{n}} does not cross the wire")),
        }}
    }}

    /// Whether exercise `n`'s calls cross the wire in this process.
    #[must_use]
    pub fn remote(n: u16) -> bool {{
        crate::judge::remote(&TABLE, n)
    }}

    /// Exercise `n`'s value for `args`, from the other end of the wire.
    pub fn call<A: serde::Serialize + ?Sized, R: serde::de::DeserializeOwned>(n: u16, args: &A) -> R {{
        crate::judge::call(&TABLE, n, args)
    }}

    /// [`call`] for a function that also takes an iterator, whose items the other end pulls.
    pub fn call_pulling<A: serde::Serialize + ?Sized, R: serde::de::DeserializeOwned, T: serde::Serialize>(
        n: u16,
        args: &A,
        items: &mut dyn Iterator<Item = T>,
    ) -> R {{
        crate::judge::call_pulling(&TABLE, n, args, Some(items))
    }}

    /// The iterator of the call being answered, its items pulled from the other end.
    #[must_use]
    pub fn pulled<T>() -> crate::judge::Pulled<T> {{
        crate::judge::Pulled::new(&TABLE)
    }}

    /// The server's `main`.
    #[must_use]
    pub fn serve() -> std::process::ExitCode {{
        crate::judge::serve(&TABLE)
    }}
}}
"#,
        prefixes = prefixes.join(", "),
        arms = arms.join("\n"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind of parameter crosses as the wire can carry it: a receiver and `&T` by value,
    /// a slice and an iterator as a `Vec`; what the function changes does not cross.
    #[test]
    fn each_parameter_crosses_by_value_or_is_named_as_kept() {
        let c = |p: &str| crossing(p, 1, Some("Camera")).map(|c| (c.sent, c.decoded, c.passed));
        let own = |a: &str, b: &str, c: &str| Ok((a.to_string(), b.to_string(), c.to_string()));
        assert_eq!(c("&self"), own("self", "Camera", "&a1"));
        assert_eq!(c("ray: &Ray"), own("ray", "Ray", "&a1"));
        assert_eq!(c("steps: &[Step]"), own("steps", "Vec<Step>", "&a1"));
        assert_eq!(c("mut t: Real"), own("t", "Real", "a1"));
        let it = crossing("crossed: impl IntoIterator<Item = Real>", 1, None).unwrap();
        assert_eq!(
            (it.passed.as_str(), it.pulled),
            (
                "crate::judged::pulled::<Real>()",
                Some(("crossed".to_string(), "Real".to_string()))
            )
        );
        assert!(c("f: impl Fn(Real) -> Real").is_err());
        assert!(c("rec: &mut impl Recorder").is_err());
        assert!(c("t: &dyn Query").is_err());
        assert!(c("(a, b): (Real, Real)").is_err());
    }

    /// The parameters are read between the signature's own parentheses, whatever the types
    /// hold (generics, tuples, `->`).
    #[test]
    fn parameters_are_split_at_their_top_level_commas() {
        let text =
            "pub fn f(a: (Real, Real), m: &HashMap<u8, u8>, k: impl Fn(u8) -> u8) -> (u8, u8) {";
        let body = text.len() - 1;
        assert_eq!(
            parameters(text, body, "f").unwrap(),
            [
                "a: (Real, Real)",
                "m: &HashMap<u8, u8>",
                "k: impl Fn(u8) -> u8"
            ]
        );
        assert_eq!(
            parameters("fn g() {", 7, "g").unwrap(),
            Vec::<String>::new()
        );
    }

    /// A file's module path is the path the crate's root reaches it by.
    #[test]
    fn a_files_module_is_its_path_from_the_crate_root() {
        let src = layout::core_src();
        assert_eq!(
            module_of(&src.join("shapes/sphere.rs")),
            "crate::shapes::sphere"
        );
        assert_eq!(module_of(&src.join("shapes/mod.rs")), "crate::shapes");
        assert_eq!(module_of(&src.join("lib.rs")), "crate");
    }
}
