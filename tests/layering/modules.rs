//! The modules of one crate, read from its root file (`lib.rs`, `main.rs`, a `src/bin/*.rs`, a
//! test's `main.rs`) by following its `mod` declarations: where each module's file is, what it
//! defines, and what its `use` declarations bind. Items under `#[cfg(test)]` are left out, and so
//! are the files only a `#[cfg(test)] mod` declaration leads to (they are noted as test files).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Component, Path, PathBuf};

use syn::visit::Visit;

use crate::syntax::{Leaf, Written, leaves, line, only_in_tests};

/// One module: a file, or an inline `mod name { … }` inside one.
#[derive(Debug)]
pub struct Module {
    /// The file holding its body.
    pub file: PathBuf,
    /// Where the files of its `mod x;` declarations are (`x.rs` or `x/mod.rs` in it).
    dir: PathBuf,
    /// Whether its body is the whole of `file` (not an inline module inside it).
    whole_file: bool,
    /// The module it is declared in (none for the crate's root).
    pub parent: Option<usize>,
    /// Its child modules by name.
    pub children: BTreeMap<String, usize>,
    /// The items it defines by name, each with the file that defines it.
    pub items: BTreeMap<String, PathBuf>,
    /// What each name a `use` binds in it leads to (`use a::B as C` binds `C` to `a::B`).
    pub bindings: BTreeMap<String, Written>,
    /// The paths its `use …::*` declarations bring every name of.
    pub globs: Vec<Written>,
    /// Whether a path through its re-exports counts as naming the file that defines the item
    /// (a crate's root, a `mod.rs`, a file with child module files), rather than its own file.
    pub front: bool,
}

/// One crate's modules and files.
pub struct Crate {
    /// Its modules; the first is the root.
    pub modules: Vec<Module>,
    /// Each file read, with the module its top level is, parsed.
    pub files: Vec<(PathBuf, usize, syn::File)>,
    /// The files only a `#[cfg(test)] mod x;` declaration leads to.
    pub test_files: BTreeSet<PathBuf>,
    /// What could not be read: a module's missing file, a file that does not parse.
    pub problems: Vec<String>,
}

/// Reads the crate whose root file is `root`; `read` gives a file's text (none when there is no
/// such file).
pub fn read_crate(root: &Path, read: &dyn Fn(&Path) -> Option<String>) -> Crate {
    let mut krate = Crate {
        modules: Vec::new(),
        files: Vec::new(),
        test_files: BTreeSet::new(),
        problems: Vec::new(),
    };
    match parse(root, read) {
        Ok(file) => {
            let dir = root.parent().unwrap_or(Path::new("")).to_path_buf();
            add_file(&mut krate, root.to_path_buf(), dir, None, file, read);
            krate.modules[0].front = true;
        }
        Err(e) => krate.problems.push(e),
    }
    krate
}

/// Reads and parses a file.
fn parse(path: &Path, read: &dyn Fn(&Path) -> Option<String>) -> Result<syn::File, String> {
    let text = read(path).ok_or_else(|| format!("{}: no such file", path.display()))?;
    syn::parse_file(&text).map_err(|e| {
        let at = e.span().start();
        format!("{}:{}:{}: {e}", path.display(), at.line, at.column + 1)
    })
}

/// Adds the module whose body is the whole of `file`, with its children.
fn add_file(
    krate: &mut Crate,
    path: PathBuf,
    dir: PathBuf,
    parent: Option<usize>,
    file: syn::File,
    read: &dyn Fn(&Path) -> Option<String>,
) -> usize {
    let index = add_module(krate, &path, dir, true, parent, &file.items, read);
    let has_child_files = krate
        .modules
        .iter()
        .any(|m| m.parent.is_some_and(|p| krate.modules[p].file == path) && m.file != path);
    krate.modules[index].front = path.file_name().is_some_and(|n| n == "mod.rs") || has_child_files;
    krate.files.push((path, index, file));
    index
}

/// Adds one module (a file's top level or an inline module) holding `items`, and its children.
fn add_module(
    krate: &mut Crate,
    file: &Path,
    dir: PathBuf,
    whole_file: bool,
    parent: Option<usize>,
    items: &[syn::Item],
    read: &dyn Fn(&Path) -> Option<String>,
) -> usize {
    let index = krate.modules.len();
    krate.modules.push(Module {
        file: file.to_path_buf(),
        dir,
        whole_file,
        parent,
        children: BTreeMap::new(),
        items: BTreeMap::new(),
        bindings: BTreeMap::new(),
        globs: Vec::new(),
        front: false,
    });
    for item in items {
        if let syn::Item::Mod(m) = item {
            if only_in_tests(&m.attrs) {
                if m.content.is_none()
                    && let Some(path) = module_file(&krate.modules[index], m, read)
                {
                    krate.test_files.insert(path);
                }
                continue;
            }
            let name = m.ident.to_string();
            let child = match &m.content {
                Some((_, inner)) => {
                    let dir = krate.modules[index].dir.join(&name);
                    add_module(krate, file, dir, false, Some(index), inner, read)
                }
                None => match module_file(&krate.modules[index], m, read) {
                    Some(path) => match parse(&path, read) {
                        Ok(parsed) => {
                            let dir = children_dir(&path, &m.attrs);
                            add_file(krate, path, dir, Some(index), parsed, read)
                        }
                        Err(e) => {
                            krate.problems.push(e);
                            continue;
                        }
                    },
                    None => {
                        krate.problems.push(format!(
                            "{}:{}: `mod {name};` has no file",
                            file.display(),
                            line(&m.ident)
                        ));
                        continue;
                    }
                },
            };
            krate.modules[index].children.insert(name, child);
        } else if !only_in_tests(attrs(item)) {
            define(krate, index, item);
            let mut uses = Uses(Vec::new());
            uses.visit_item(item);
            for leaf in uses.0 {
                let module = &mut krate.modules[index];
                match leaf {
                    Leaf::Name {
                        path,
                        binds: Some(name),
                    } => {
                        module.bindings.insert(name, path);
                    }
                    Leaf::Name { binds: None, .. } => {}
                    Leaf::Glob(path) => module.globs.push(path),
                }
            }
        }
    }
    index
}

/// Records the name an item defines (a `#[macro_export]` macro's at the crate's root too).
fn define(krate: &mut Crate, index: usize, item: &syn::Item) {
    use syn::Item;
    let file = krate.modules[index].file.clone();
    let mut names = Vec::new();
    match item {
        Item::Const(i) => names.push(i.ident.to_string()),
        Item::Enum(i) => names.push(i.ident.to_string()),
        Item::ExternCrate(i) => {
            names.push(i.rename.as_ref().map_or(&i.ident, |(_, r)| r).to_string())
        }
        Item::Fn(i) => names.push(i.sig.ident.to_string()),
        Item::ForeignMod(i) => {
            for f in &i.items {
                match f {
                    syn::ForeignItem::Fn(f) => names.push(f.sig.ident.to_string()),
                    syn::ForeignItem::Static(s) => names.push(s.ident.to_string()),
                    syn::ForeignItem::Type(t) => names.push(t.ident.to_string()),
                    _ => {}
                }
            }
        }
        Item::Macro(i) => {
            if let Some(name) = &i.ident {
                if i.attrs.iter().any(|a| a.path().is_ident("macro_export")) {
                    krate.modules[0]
                        .items
                        .insert(name.to_string(), file.clone());
                }
                names.push(name.to_string());
            }
        }
        Item::Static(i) => names.push(i.ident.to_string()),
        Item::Struct(i) => names.push(i.ident.to_string()),
        Item::Trait(i) => names.push(i.ident.to_string()),
        Item::TraitAlias(i) => names.push(i.ident.to_string()),
        Item::Type(i) => names.push(i.ident.to_string()),
        Item::Union(i) => names.push(i.ident.to_string()),
        _ => {}
    }
    for name in names {
        krate.modules[index].items.insert(name, file.clone());
    }
}

/// The attributes of an item.
pub fn attrs(item: &syn::Item) -> &[syn::Attribute] {
    use syn::Item;
    match item {
        Item::Const(i) => &i.attrs,
        Item::Enum(i) => &i.attrs,
        Item::ExternCrate(i) => &i.attrs,
        Item::Fn(i) => &i.attrs,
        Item::ForeignMod(i) => &i.attrs,
        Item::Impl(i) => &i.attrs,
        Item::Macro(i) => &i.attrs,
        Item::Mod(i) => &i.attrs,
        Item::Static(i) => &i.attrs,
        Item::Struct(i) => &i.attrs,
        Item::Trait(i) => &i.attrs,
        Item::TraitAlias(i) => &i.attrs,
        Item::Type(i) => &i.attrs,
        Item::Union(i) => &i.attrs,
        Item::Use(i) => &i.attrs,
        _ => &[],
    }
}

/// The `use` declarations in an item, those in its function bodies included (a name a body's
/// `use` binds is counted as the module's: paths written with it lead where it leads), those
/// in inline modules and test code left out.
struct Uses(Vec<Leaf>);

impl<'ast> Visit<'ast> for Uses {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        if !matches!(item, syn::Item::Mod(_)) && !only_in_tests(attrs(item)) {
            syn::visit::visit_item(self, item);
        }
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        self.0.extend(leaves(item));
    }
}

/// The file a `mod name;` declaration of `parent` names: its `#[path]`, else `name.rs` or
/// `name/mod.rs` in the parent's directory of children.
fn module_file(
    parent: &Module,
    m: &syn::ItemMod,
    read: &dyn Fn(&Path) -> Option<String>,
) -> Option<PathBuf> {
    if let Some(path) = path_attribute(&m.attrs) {
        let base = if parent.whole_file {
            parent.file.parent().unwrap_or(Path::new("")).to_path_buf()
        } else {
            parent.dir.clone()
        };
        return Some(normalize(&base.join(path)));
    }
    let name = m.ident.to_string();
    [
        parent.dir.join(format!("{name}.rs")),
        parent.dir.join(&name).join("mod.rs"),
    ]
    .into_iter()
    .map(|p| normalize(&p))
    .find(|p| read(p).is_some())
}

/// Where the files of a module file's own `mod x;` declarations are: beside a `mod.rs` (or a
/// file a `#[path]` names), in a directory named after any other file.
fn children_dir(file: &Path, attrs: &[syn::Attribute]) -> PathBuf {
    let dir = file.parent().unwrap_or(Path::new("")).to_path_buf();
    let mod_rs = file.file_name().is_some_and(|n| n == "mod.rs");
    if mod_rs || path_attribute(attrs).is_some() {
        dir
    } else {
        dir.join(file.file_stem().unwrap_or_default())
    }
}

/// The value of a `#[path = "…"]` attribute.
fn path_attribute(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find_map(|a| match &a.meta {
        syn::Meta::NameValue(nv) if nv.path.is_ident("path") => match &nv.value {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) => Some(s.value()),
            _ => None,
        },
        _ => None,
    })
}

/// `path` with its `.` and `dir/..` steps taken away, so one file has one name however a
/// `#[path]` reaches it.
pub fn normalize(path: &Path) -> PathBuf {
    let mut out: Vec<Component> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.last(), Some(Component::Normal(_))) => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out.iter().collect()
}
