//! The import arrows between the files of one crate.
//!
//! An arrow runs from a file to the file that defines the name a path
//! names (`resolve` says how a path is followed): `use crate::a::b::X`,
//! `use super::X`, `use self::a::X`, `use child::X` and `pub use child::X`
//! (a re-export is an import too), and the same paths written inline
//! (`crate::needs::MAX_RAYS`, also inside macro calls such as `write!`).
//! So `use crate::Real`, where the crate root only re-exports `real::Real`,
//! points at `real.rs`, and `crate::Ui`, defined in the root, at the root; a
//! path to a module itself (`use crate::fresnel;`) points at its file.
//! `mod child;` is no arrow: declaring a child is not using it, nor is
//! `$crate::X` in a `macro_rules!` body. Code under `#[cfg(test)]` draws
//! no arrows.

use std::path::{Path, PathBuf};

use proc_macro2::{TokenStream, TokenTree};
use syn::spanned::Spanned;
use syn::visit::{self, Visit};

use crate::cfg;
use crate::resolve::{Resolved, Resolver};
use crate::scope::unraw;
use crate::tree::CrateTree;

/// One import arrow between two files of a crate.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Arrow {
    pub from: PathBuf,
    pub to: PathBuf,
    pub line: usize,
    /// The path as written, `super::Tracer`.
    pub written: String,
}

/// The arrows out of `file`, which `resolver` reads in its crate.
pub(crate) fn arrows(resolver: &Resolver, file: &Path, ast: &syn::File) -> Vec<Arrow> {
    let tree = resolver.tree;
    let module = tree.files[file].clone();
    let mut visitor = Arrows {
        tree,
        resolver,
        file,
        modules: vec![module],
        found: Vec::new(),
    };
    visitor.visit_file(ast);
    visitor.found
}

struct Arrows<'a> {
    tree: &'a CrateTree,
    resolver: &'a Resolver<'a>,
    file: &'a Path,
    /// The module stack: the file's own module, then inline modules inside it.
    modules: Vec<Vec<String>>,
    found: Vec<Arrow>,
}

impl Arrows<'_> {
    fn here(&self) -> &[String] {
        self.modules
            .last()
            .expect("the file's own module is never popped")
    }

    /// Records an arrow for `segments` if they lead to a module of this
    /// crate: to the file defining the name they end in, or to the file of
    /// the module they name. A path written outside a `use` counts only
    /// when it starts at `crate`, `self`, `super` or a child module: one
    /// that starts at a name the file imports repeats that import's arrow.
    fn path(&mut self, segments: &[String], line: usize, used: bool) {
        let here = self.here();
        let anchored = match segments.first().map(String::as_str) {
            Some("crate" | "self" | "super") => true,
            Some(first) => {
                let child = [here, &[first.to_string()]].concat();
                self.tree.modules.contains_key(&child)
            }
            None => false,
        };
        if !used && !anchored {
            return;
        }
        let Some(module) = self
            .resolver
            .resolve(here, segments)
            .and_then(Resolved::module)
        else {
            return;
        };
        let Some(to) = self.tree.modules.get(&module) else {
            return;
        };
        if to.test || to.file == self.file {
            return;
        }
        self.found.push(Arrow {
            from: self.file.to_path_buf(),
            to: to.file.clone(),
            line,
            written: segments.join("::"),
        });
    }

    /// Finds `crate::a::b`, `super::a`, `self::a` in a macro's tokens.
    /// `$crate::a` in a `macro_rules!` body is no arrow: it is read where
    /// the macro is called, not where it is defined.
    fn tokens(&mut self, tokens: TokenStream) {
        let trees: Vec<TokenTree> = tokens.into_iter().collect();
        let mut i = 0;
        while i < trees.len() {
            match &trees[i] {
                TokenTree::Group(group) => self.tokens(group.stream()),
                TokenTree::Ident(ident)
                    if ["crate", "super", "self"].contains(&&*ident.to_string())
                        && !follows_dollar(&trees, i) =>
                {
                    let line = ident.span().start().line;
                    let mut segments = vec![ident.to_string()];
                    while let (
                        Some(TokenTree::Punct(a)),
                        Some(TokenTree::Punct(b)),
                        Some(TokenTree::Ident(next)),
                    ) = (trees.get(i + 1), trees.get(i + 2), trees.get(i + 3))
                    {
                        if a.as_char() != ':' || b.as_char() != ':' {
                            break;
                        }
                        segments.push(next.to_string());
                        i += 3;
                    }
                    if segments.len() > 1 {
                        self.path(&segments, line, false);
                    }
                }
                _ => {}
            }
            i += 1;
        }
    }
}

/// Whether the token at `i` comes right after a `$` (`$crate`).
fn follows_dollar(trees: &[TokenTree], i: usize) -> bool {
    i.checked_sub(1)
        .and_then(|before| trees.get(before))
        .is_some_and(|t| matches!(t, TokenTree::Punct(p) if p.as_char() == '$'))
}

/// Every full path a `use` tree names; a glob names its module.
fn use_paths(tree: &syn::UseTree, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(unraw(&p.ident));
            use_paths(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) if n.ident == "self" => out.push(prefix.clone()),
        syn::UseTree::Name(n) => out.push([prefix.as_slice(), &[unraw(&n.ident)]].concat()),
        syn::UseTree::Rename(r) if r.ident == "self" => out.push(prefix.clone()),
        syn::UseTree::Rename(r) => out.push([prefix.as_slice(), &[unraw(&r.ident)]].concat()),
        syn::UseTree::Glob(_) => out.push(prefix.clone()),
        syn::UseTree::Group(g) => g.items.iter().for_each(|t| use_paths(t, prefix, out)),
    }
}

impl<'ast> Visit<'ast> for Arrows<'_> {
    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        if cfg::is_test_only(&item.attrs) || item.content.is_none() {
            return;
        }
        let mut inner = self.here().to_vec();
        inner.push(item.ident.to_string());
        self.modules.push(inner);
        visit::visit_item_mod(self, item);
        self.modules.pop();
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        if cfg::is_test_only(&item.attrs) || item.leading_colon.is_some() {
            return;
        }
        let mut paths = Vec::new();
        use_paths(&item.tree, &mut Vec::new(), &mut paths);
        let line = item.use_token.span().start().line;
        for path in paths {
            self.path(&path, line, true);
        }
    }

    fn visit_item_fn(&mut self, item: &'ast syn::ItemFn) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_item_fn(self, item);
        }
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_item_impl(self, item);
        }
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_impl_item_fn(self, item);
        }
    }

    fn visit_path(&mut self, path: &'ast syn::Path) {
        if path.leading_colon.is_none() && path.segments.len() > 1 {
            let segments: Vec<String> = path.segments.iter().map(|s| s.ident.to_string()).collect();
            self.path(&segments, path.span().start().line, false);
        }
        visit::visit_path(self, path);
    }

    fn visit_attribute(&mut self, attr: &'ast syn::Attribute) {
        if let syn::Meta::List(list) = &attr.meta {
            self.tokens(list.tokens.clone());
        }
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        self.tokens(mac.tokens.clone());
        visit::visit_macro(self, mac);
    }
}
