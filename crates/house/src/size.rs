//! Rules a and b: a product file over 400 lines, a product function over 80.
//!
//! A file's lines are its newline-terminated lines, as `wc -l` counts them,
//! the inline test module included: a reader reads the whole file. A
//! function runs from the line of its `fn` keyword to the line of its closing
//! brace (its doc comment and attributes not counted); functions inside a
//! `#[cfg(test)]` module, impl or function are test code and not counted.

use syn::spanned::Spanned;
use syn::visit::{self, Visit};

use crate::cfg;
use crate::offender::{Offender, Place, Rule, MAX_FILE_LINES, MAX_FN_LINES};
use crate::tree::Source;
use crate::type_name::type_name;

/// Rule a for one product file.
pub(crate) fn long_file(source: &Source) -> Option<Offender> {
    let lines = source.text.lines().count();
    (lines > MAX_FILE_LINES).then(|| Offender {
        rule: Rule::LongFile,
        place: Place::File {
            path: source.rel.clone(),
            lines,
        },
    })
}

/// Rule b for one product file.
pub(crate) fn long_functions(source: &Source) -> Vec<Offender> {
    let mut visitor = Functions {
        source,
        owners: Vec::new(),
        found: Vec::new(),
    };
    visitor.visit_file(&source.ast);
    visitor.found
}

struct Functions<'a> {
    source: &'a Source,
    /// The `impl` or `trait` blocks the visitor is inside, innermost last.
    owners: Vec<String>,
    found: Vec<Offender>,
}

impl Functions<'_> {
    fn measure(&mut self, name: &syn::Ident, fn_token: proc_macro2::Span, body: &syn::Block) {
        let line = fn_token.start().line;
        let lines = body.brace_token.span.close().start().line + 1 - line;
        if lines <= MAX_FN_LINES {
            return;
        }
        let name = match self.owners.last() {
            Some(owner) => format!("{owner}::{name}"),
            None => name.to_string(),
        };
        self.found.push(Offender {
            rule: Rule::LongFunction,
            place: Place::Function {
                path: self.source.rel.clone(),
                line,
                name,
                lines,
            },
        });
    }
}

impl<'ast> Visit<'ast> for Functions<'_> {
    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_item_mod(self, item);
        }
    }

    fn visit_item_fn(&mut self, item: &'ast syn::ItemFn) {
        if !cfg::is_test_only(&item.attrs) {
            self.measure(&item.sig.ident, item.sig.fn_token.span(), &item.block);
            visit::visit_item_fn(self, item);
        }
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        if !cfg::is_test_only(&item.attrs) {
            self.owners.push(type_name(&item.self_ty));
            visit::visit_item_impl(self, item);
            self.owners.pop();
        }
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        if !cfg::is_test_only(&item.attrs) {
            self.measure(&item.sig.ident, item.sig.fn_token.span(), &item.block);
            visit::visit_impl_item_fn(self, item);
        }
    }

    fn visit_item_trait(&mut self, item: &'ast syn::ItemTrait) {
        if !cfg::is_test_only(&item.attrs) {
            self.owners.push(item.ident.to_string());
            visit::visit_item_trait(self, item);
            self.owners.pop();
        }
    }

    fn visit_trait_item_fn(&mut self, item: &'ast syn::TraitItemFn) {
        if cfg::is_test_only(&item.attrs) {
            return;
        }
        if let Some(body) = &item.default {
            self.measure(&item.sig.ident, item.sig.fn_token.span(), body);
        }
        visit::visit_trait_item_fn(self, item);
    }
}
