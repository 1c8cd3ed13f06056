//! Every path a file's code writes, with the module it is written in: the leaves of its `use`
//! trees, the paths of its expressions, types, patterns and attributes, and the `a::b` runs in
//! the tokens of its macro calls and attribute arguments. Comments (doc comments included) and
//! `#[cfg(test)]` code write none.

use syn::visit::{self, Visit};

use crate::modules::{Crate, attrs};
use crate::syntax::{Leaf, Written, leaves, only_in_tests, serde_paths, token_paths};

/// How a path is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// In code or in a `use` leaf: it names what it leads to.
    Named,
    /// `use path::*` or `#[serde(with = "path")]`: it names the module (or enum) itself, whose
    /// names it brings or whose functions it calls.
    Whole,
}

/// A path written in a file.
#[derive(Clone, Debug)]
pub struct Occurrence {
    /// The module it is written in (an inline module's, inside one).
    pub module: usize,
    /// The path.
    pub path: Written,
    /// How it is written.
    pub kind: Kind,
    /// The path as the file writes it (`super::*` for a glob), for a message.
    pub shown: String,
}

/// The paths written in `file`, whose top level is module `top` of `krate`.
pub fn occurrences(krate: &Crate, top: usize, file: &syn::File) -> Vec<Occurrence> {
    let mut walker = Walker {
        krate,
        modules: vec![top],
        out: Vec::new(),
    };
    if !only_in_tests(&file.attrs) {
        for item in &file.items {
            walker.visit_item(item);
        }
    }
    walker.out
}

/// Walks one file's syntax, knowing which module it is in.
struct Walker<'k> {
    krate: &'k Crate,
    /// The module being walked, innermost last.
    modules: Vec<usize>,
    out: Vec<Occurrence>,
}

impl Walker<'_> {
    /// Notes a path written in the module being walked, shown as `shown` (its own text when
    /// none is given).
    fn note(&mut self, path: Written, kind: Kind, shown: Option<String>) {
        let module = *self.modules.last().expect("a module is being walked");
        let shown = shown.unwrap_or_else(|| path.text());
        self.out.push(Occurrence {
            module,
            path,
            kind,
            shown,
        });
    }
}

impl<'ast> Visit<'ast> for Walker<'_> {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        if !only_in_tests(attrs(item)) {
            visit::visit_item(self, item);
        }
    }

    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        // a declaration `mod x;` names nothing; an inline module's body is walked as its own
        let Some((_, items)) = &m.content else {
            return;
        };
        let here = *self.modules.last().expect("a module is being walked");
        let Some(&child) = self.krate.modules[here].children.get(&m.ident.to_string()) else {
            return;
        };
        self.modules.push(child);
        for item in items {
            self.visit_item(item);
        }
        self.modules.pop();
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        for leaf in leaves(item) {
            match leaf {
                Leaf::Name { path, .. } => self.note(path, Kind::Named, None),
                Leaf::Glob(path) => {
                    let shown = format!("{}::*", path.text());
                    self.note(path, Kind::Whole, Some(shown));
                }
            }
        }
    }

    fn visit_path(&mut self, path: &'ast syn::Path) {
        if path.leading_colon.is_none()
            && let Some(last) = path.segments.last()
        {
            self.note(
                Written {
                    segments: path.segments.iter().map(|s| s.ident.to_string()).collect(),
                    line: last.ident.span().start().line,
                },
                Kind::Named,
                None,
            );
        }
        visit::visit_path(self, path);
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        visit::visit_macro(self, mac);
        let mut found = Vec::new();
        token_paths(mac.tokens.clone(), &mut found);
        for path in found {
            self.note(path, Kind::Named, None);
        }
    }

    fn visit_attribute(&mut self, attr: &'ast syn::Attribute) {
        // doc comments are comments, and `#[path]` is followed by the module reader
        if attr.path().is_ident("doc") || attr.path().is_ident("path") {
            return;
        }
        let mut strings = Vec::new();
        serde_paths(attr, &mut strings);
        for (path, whole) in strings {
            let shown = format!("\"{}\"", path.text());
            let kind = if whole { Kind::Whole } else { Kind::Named };
            self.note(path, kind, Some(shown));
        }
        let mut found = Vec::new();
        if let syn::Meta::List(list) = &attr.meta {
            token_paths(list.tokens.clone(), &mut found);
        }
        for path in found {
            self.note(path, Kind::Named, None);
        }
        visit::visit_attribute(self, attr);
    }

    fn visit_impl_item(&mut self, item: &'ast syn::ImplItem) {
        let attrs = match item {
            syn::ImplItem::Const(i) => &i.attrs,
            syn::ImplItem::Fn(i) => &i.attrs,
            syn::ImplItem::Type(i) => &i.attrs,
            syn::ImplItem::Macro(i) => &i.attrs,
            _ => return visit::visit_impl_item(self, item),
        };
        if !only_in_tests(attrs) {
            visit::visit_impl_item(self, item);
        }
    }

    fn visit_trait_item(&mut self, item: &'ast syn::TraitItem) {
        let attrs = match item {
            syn::TraitItem::Const(i) => &i.attrs,
            syn::TraitItem::Fn(i) => &i.attrs,
            syn::TraitItem::Type(i) => &i.attrs,
            syn::TraitItem::Macro(i) => &i.attrs,
            _ => return visit::visit_trait_item(self, item),
        };
        if !only_in_tests(attrs) {
            visit::visit_trait_item(self, item);
        }
    }

    fn visit_field(&mut self, field: &'ast syn::Field) {
        if !only_in_tests(&field.attrs) {
            visit::visit_field(self, field);
        }
    }

    fn visit_variant(&mut self, variant: &'ast syn::Variant) {
        if !only_in_tests(&variant.attrs) {
            visit::visit_variant(self, variant);
        }
    }

    fn visit_arm(&mut self, arm: &'ast syn::Arm) {
        if !only_in_tests(&arm.attrs) {
            visit::visit_arm(self, arm);
        }
    }

    fn visit_local(&mut self, local: &'ast syn::Local) {
        if !only_in_tests(&local.attrs) {
            visit::visit_local(self, local);
        }
    }

    fn visit_field_value(&mut self, field: &'ast syn::FieldValue) {
        if !only_in_tests(&field.attrs) {
            visit::visit_field_value(self, field);
        }
    }

    fn visit_stmt_macro(&mut self, mac: &'ast syn::StmtMacro) {
        if !only_in_tests(&mac.attrs) {
            visit::visit_stmt_macro(self, mac);
        }
    }
}
