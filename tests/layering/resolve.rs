//! Where a written path leads, and from that the files of a crate each file depends on.
//!
//! The rule: file A depends on file B when A's code names a path that leads into B.
//! `crate::…`, `super::…`, `self::…` and a relative path whose first segment is a name A's
//! module knows (a child module, an item, a name a `use` binds, a name a glob brings) are
//! followed segment by segment. A name a crate root, a `mod.rs` or another file with child
//! module files re-exports (`pub use options::Options`) leads on to the file that defines the
//! item, through chains of re-exports; a name any other file re-exports leads to that file. A
//! path that ends at a module leads to no file (a module is a name, its items are the code),
//! except `use module::*` and `#[serde(with = "module")]`, which name the module's file. A name the reader cannot find in
//! a module counts as that module's file (an item a macro writes, say).

use std::collections::BTreeMap;
use std::path::PathBuf;

use crate::modules::Crate;
use crate::paths::{Kind, occurrences};

/// Where a path leads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// A module of the crate.
    Module(usize),
    /// An item, defined in this file.
    Item(PathBuf),
    /// Something outside the crate (another crate, the prelude, a generic parameter, `Self`).
    Outside,
}

/// How deep re-exports are followed before the reader gives up (a loop of `use`s).
const DEEPEST: usize = 32;

/// Where `segments`, written in module `from`, lead.
pub fn resolve(krate: &Crate, from: usize, segments: &[String]) -> Target {
    follow(krate, from, segments, 0)
}

/// [`resolve`], `depth` re-exports deep.
fn follow(krate: &Crate, from: usize, segments: &[String], depth: usize) -> Target {
    let Some((first, rest)) = segments.split_first() else {
        return Target::Outside;
    };
    if depth > DEEPEST {
        return Target::Outside;
    }
    let mut here = match first.as_str() {
        "crate" => Target::Module(0),
        "self" => Target::Module(from),
        "super" => parent(krate, from),
        name => match local(krate, from, name, depth) {
            Some(target) => target,
            None => return Target::Outside,
        },
    };
    for segment in rest {
        let Target::Module(m) = here else {
            // past an item: an associated item, a variant, a field
            return here;
        };
        here = match segment.as_str() {
            "self" => Target::Module(m),
            "super" => parent(krate, m),
            name => exterior(krate, m, name, depth)
                .unwrap_or_else(|| Target::Item(krate.modules[m].file.clone())),
        };
    }
    here
}

/// The module `m` is declared in.
fn parent(krate: &Crate, m: usize) -> Target {
    krate.modules[m]
        .parent
        .map_or(Target::Outside, Target::Module)
}

/// What `name` is to code written in module `m`: a child module, an item, what a `use` binding
/// or a glob leads to; none when the module does not know it.
fn local(krate: &Crate, m: usize, name: &str, depth: usize) -> Option<Target> {
    let module = &krate.modules[m];
    if let Some(&child) = module.children.get(name) {
        return Some(Target::Module(child));
    }
    if let Some(file) = module.items.get(name) {
        return Some(Target::Item(file.clone()));
    }
    if let Some(path) = module.bindings.get(name) {
        return Some(match follow(krate, m, &path.segments, depth + 1) {
            // a name of another crate, brought in here
            Target::Outside => Target::Item(module.file.clone()),
            target => target,
        });
    }
    module
        .globs
        .iter()
        .find_map(|glob| match follow(krate, m, &glob.segments, depth + 1) {
            Target::Module(g) if g != m => exterior(krate, g, name, depth + 1),
            _ => None,
        })
}

/// What `name` in module `m` is to a path from elsewhere (`crate::m::name`): what it is to
/// `m` itself, but a name a file that is no front re-exports stops at that file.
fn exterior(krate: &Crate, m: usize, name: &str, depth: usize) -> Option<Target> {
    let module = &krate.modules[m];
    let target = local(krate, m, name, depth)?;
    if module.front {
        return Some(target);
    }
    Some(match target {
        Target::Module(c) if krate.modules[c].parent == Some(m) => target,
        Target::Item(ref file) if *file == module.file => target,
        _ => Target::Item(module.file.clone()),
    })
}

/// Where a file names another: the first line, and the path written there.
#[derive(Clone, Debug)]
pub struct Naming {
    /// The line of the file that names the other.
    pub line: usize,
    /// The path written there.
    pub text: String,
}

/// The files of a crate and, for each, the files it depends on with where it first names each.
pub type Graph = BTreeMap<PathBuf, BTreeMap<PathBuf, Naming>>;

/// The file graph of a crate.
pub fn file_graph(krate: &Crate) -> Graph {
    let mut graph = Graph::new();
    for (file, top, syntax) in &krate.files {
        let named = graph.entry(file.clone()).or_default();
        for o in occurrences(krate, *top, syntax) {
            let target = match (resolve(krate, o.module, &o.path.segments), o.kind) {
                (Target::Item(f), _) => f,
                (Target::Module(m), Kind::Whole) => krate.modules[m].file.clone(),
                (Target::Module(_) | Target::Outside, _) => continue,
            };
            if target == *file {
                continue;
            }
            let naming = Naming {
                line: o.path.line,
                text: o.shown,
            };
            named
                .entry(target)
                .and_modify(|n| {
                    if naming.line < n.line {
                        *n = naming.clone();
                    }
                })
                .or_insert(naming);
        }
    }
    graph
}
