//! What each module of a crate names, read from its file's syntax tree:
//! the items it defines, the names its `use` declarations bind, and the
//! modules it globs. A `use` binds a name whatever its visibility: a
//! `pub use child::Name` re-exports it, and a private `use` makes it
//! reachable as `super::Name` from the module's children all the same.
//!
//! Code under `#[cfg(test)]` names nothing here, as it draws no arrows.

use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

use crate::cfg;
use crate::tree::{CrateTree, Source};

/// Where a name a `use` binds leads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Binding {
    /// A path as written, read from the module that binds it.
    Path(Vec<String>),
    /// Another crate: `extern crate`, or a path from `::`.
    Outside,
}

/// The names of one module.
#[derive(Default, Debug)]
pub(crate) struct Scope {
    /// Items defined here: fn, struct, enum, union, trait, const, static,
    /// type, `macro_rules!`.
    pub defs: BTreeSet<String>,
    /// Names bound by `use` (renamed ones by their new name).
    pub bindings: BTreeMap<String, Binding>,
    /// Paths globbed by `use path::*`, as written.
    pub globs: Vec<Vec<String>>,
}

/// The names of every product module of one crate, by module path.
#[derive(Default, Debug)]
pub(crate) struct Scopes(BTreeMap<Vec<String>, Scope>);

impl Scopes {
    /// Reads every product file of `tree`.
    pub(crate) fn new(tree: &CrateTree, sources: &BTreeMap<PathBuf, Source>) -> Self {
        let mut scopes = Scopes::default();
        for (file, module) in &tree.files {
            if let (false, Some(source)) = (tree.modules[module].test, sources.get(file)) {
                scopes.collect(&source.ast.items, module);
            }
        }
        scopes
    }

    /// The names of `module`, if it has any.
    pub(crate) fn get(&self, module: &[String]) -> Option<&Scope> {
        self.0.get(module)
    }

    fn collect(&mut self, items: &[syn::Item], module: &[String]) {
        for item in items {
            if cfg::is_test_only(attributes(item)) {
                continue;
            }
            match item {
                syn::Item::Mod(inner) => {
                    if let Some((_, items)) = &inner.content {
                        let inner = [module, &[unraw(&inner.ident)]].concat();
                        self.collect(items, &inner);
                    }
                }
                syn::Item::Use(used) => {
                    let scope = self.0.entry(module.to_vec()).or_default();
                    let outside = used.leading_colon.is_some();
                    bind(&used.tree, &mut Vec::new(), outside, scope);
                }
                syn::Item::ExternCrate(extern_crate) => {
                    let name = extern_crate
                        .rename
                        .as_ref()
                        .map_or(&extern_crate.ident, |r| &r.1);
                    let scope = self.0.entry(module.to_vec()).or_default();
                    scope.bindings.insert(unraw(name), Binding::Outside);
                }
                other => {
                    if let Some(name) = defined(other) {
                        let scope = self.0.entry(module.to_vec()).or_default();
                        scope.defs.insert(name);
                    }
                }
            }
        }
    }
}

/// The name an item defines, if it defines one by name.
fn defined(item: &syn::Item) -> Option<String> {
    let ident = match item {
        syn::Item::Const(i) => &i.ident,
        syn::Item::Enum(i) => &i.ident,
        syn::Item::Fn(i) => &i.sig.ident,
        syn::Item::Macro(i) => i.ident.as_ref()?,
        syn::Item::Static(i) => &i.ident,
        syn::Item::Struct(i) => &i.ident,
        syn::Item::Trait(i) => &i.ident,
        syn::Item::TraitAlias(i) => &i.ident,
        syn::Item::Type(i) => &i.ident,
        syn::Item::Union(i) => &i.ident,
        _ => return None,
    };
    Some(unraw(ident))
}

/// Records the names one `use` tree binds and the paths it globs.
fn bind(tree: &syn::UseTree, prefix: &mut Vec<String>, outside: bool, scope: &mut Scope) {
    let mut insert = |name: String, path: Vec<String>| {
        let binding = if outside {
            Binding::Outside
        } else {
            Binding::Path(path)
        };
        if name != "_" {
            scope.bindings.entry(name).or_insert(binding);
        }
    };
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(unraw(&p.ident));
            bind(&p.tree, prefix, outside, scope);
            prefix.pop();
        }
        syn::UseTree::Name(n) if n.ident == "self" => {
            if let Some(name) = prefix.last() {
                insert(name.clone(), prefix.clone());
            }
        }
        syn::UseTree::Name(n) => insert(
            unraw(&n.ident),
            [prefix.as_slice(), &[unraw(&n.ident)]].concat(),
        ),
        syn::UseTree::Rename(r) if r.ident == "self" => insert(unraw(&r.rename), prefix.clone()),
        syn::UseTree::Rename(r) => {
            insert(
                unraw(&r.rename),
                [prefix.as_slice(), &[unraw(&r.ident)]].concat(),
            );
        }
        syn::UseTree::Glob(_) if !outside => scope.globs.push(prefix.clone()),
        syn::UseTree::Glob(_) => {}
        syn::UseTree::Group(g) => g.items.iter().for_each(|t| bind(t, prefix, outside, scope)),
    }
}

/// An identifier as a path segment, without its `r#`.
pub(crate) fn unraw(ident: &syn::Ident) -> String {
    ident.to_string().trim_start_matches("r#").to_string()
}

/// The attributes of an item.
fn attributes(item: &syn::Item) -> &[syn::Attribute] {
    match item {
        syn::Item::Const(i) => &i.attrs,
        syn::Item::Enum(i) => &i.attrs,
        syn::Item::ExternCrate(i) => &i.attrs,
        syn::Item::Fn(i) => &i.attrs,
        syn::Item::ForeignMod(i) => &i.attrs,
        syn::Item::Impl(i) => &i.attrs,
        syn::Item::Macro(i) => &i.attrs,
        syn::Item::Mod(i) => &i.attrs,
        syn::Item::Static(i) => &i.attrs,
        syn::Item::Struct(i) => &i.attrs,
        syn::Item::Trait(i) => &i.attrs,
        syn::Item::TraitAlias(i) => &i.attrs,
        syn::Item::Type(i) => &i.attrs,
        syn::Item::Union(i) => &i.attrs,
        syn::Item::Use(i) => &i.attrs,
        _ => &[],
    }
}
