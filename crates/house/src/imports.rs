//! The import arrows between the files of one crate.
//!
//! An arrow runs from a file to the file that defines the module a path
//! names: `use crate::a::b::X`, `use super::X`, `use self::a::X`, `use
//! child::X` and `pub use child::X` (a re-export is an import too), and the
//! same paths written inline (`crate::needs::MAX_RAYS`, also inside macro
//! calls such as `write!`). A path is resolved to the deepest module it
//! names, so `crate::scene::Scene` points at `scene.rs` or `scene/mod.rs`
//! and `crate::Ui` at the crate root. `mod child;` is no arrow: declaring a
//! child is not using it. Code under `#[cfg(test)]` draws no arrows.

use std::path::{Path, PathBuf};

use proc_macro2::{TokenStream, TokenTree};
use syn::spanned::Spanned;
use syn::visit::{self, Visit};

use crate::cfg;
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

/// The arrows out of `file`, whose own module is `module`.
pub(crate) fn arrows(tree: &CrateTree, file: &Path, ast: &syn::File) -> Vec<Arrow> {
    let module = tree.files[file].clone();
    let mut visitor = Arrows {
        tree,
        file,
        modules: vec![module],
        found: Vec::new(),
    };
    visitor.visit_file(ast);
    visitor.found
}

struct Arrows<'a> {
    tree: &'a CrateTree,
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

    /// Records an arrow for `segments` if they name a module of this crate.
    fn path(&mut self, segments: &[String], line: usize) {
        let Some(absolute) = self.absolute(segments) else {
            return;
        };
        let Some(to) = (0..=absolute.len())
            .rev()
            .find_map(|n| self.tree.modules.get(&absolute[..n]))
        else {
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

    /// The module path from the crate root that `segments` start from, with
    /// the rest appended; `None` for another crate or a local name.
    fn absolute(&self, segments: &[String]) -> Option<Vec<String>> {
        let here = self.here();
        let first = segments.first()?;
        let mut base: Vec<String> = match first.as_str() {
            "crate" => Vec::new(),
            "self" => here.to_vec(),
            "super" => {
                let ups = segments.iter().take_while(|s| *s == "super").count();
                let kept = here.len().checked_sub(ups)?;
                let mut base = here[..kept].to_vec();
                base.extend(segments[ups..].iter().cloned());
                return Some(base);
            }
            _ => {
                let mut child = here.to_vec();
                child.push(first.clone());
                if !self.tree.modules.contains_key(&child) {
                    return None;
                }
                return Some([here, segments].concat());
            }
        };
        base.extend(segments[1..].iter().cloned());
        Some(base)
    }

    /// Finds `crate::a::b`, `super::a`, `self::a` in a macro's tokens.
    fn tokens(&mut self, tokens: TokenStream) {
        let trees: Vec<TokenTree> = tokens.into_iter().collect();
        let mut i = 0;
        while i < trees.len() {
            match &trees[i] {
                TokenTree::Group(group) => self.tokens(group.stream()),
                TokenTree::Ident(ident)
                    if ["crate", "super", "self"].contains(&&*ident.to_string()) =>
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
                        self.path(&segments, line);
                    }
                }
                _ => {}
            }
            i += 1;
        }
    }
}

/// Every full path a `use` tree names; a glob names its module.
fn use_paths(tree: &syn::UseTree, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            use_paths(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) if n.ident == "self" => out.push(prefix.clone()),
        syn::UseTree::Name(n) => out.push([prefix.as_slice(), &[n.ident.to_string()]].concat()),
        syn::UseTree::Rename(r) => out.push([prefix.as_slice(), &[r.ident.to_string()]].concat()),
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
            self.path(&path, line);
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
            self.path(&segments, path.span().start().line);
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
