//! Rule e: a library error text that names a command-line flag.
//!
//! A library says what is wrong with which value; the front end that parsed
//! the flag adds its name. So outside the front ends ([`crate::FRONT_ENDS`]),
//! a string literal in an error's text may not hold `--` followed by a
//! letter. An error's text is
//! - a `#[error("...")]` attribute (thiserror), on the type or a variant;
//! - any string literal in an `impl Display for X` block, and in functions
//!   named like [`TEXT_FNS`] in an `impl X` block, where X is an error type.
//!
//! X is an error type when its name ends in `Error`, `Kind` or `Problem`, it
//! implements or derives `Error`, or it is the error `E` of a `Result<T, E>`
//! somewhere in the package (`NoReference` in `Result<Reference,
//! NoReference>`). Other strings may hold `--`: a CSS custom property
//! (`--second`), a command line a report quotes, an argument list for a
//! child process.

use std::collections::BTreeSet;

use proc_macro2::{TokenStream, TokenTree};
use syn::visit::{self, Visit};

use crate::cfg;
use crate::offender::{Offender, Place, Rule};
use crate::tree::Source;
use crate::type_name::type_name;

/// Names of functions of an error type that write its text.
pub(crate) const TEXT_FNS: [&str; 6] =
    ["fmt", "message", "text", "english", "hungarian", "describe"];

/// The error types of a package's product sources.
pub(crate) fn error_types<'a>(sources: impl Iterator<Item = &'a Source>) -> BTreeSet<String> {
    let mut found = ErrorTypes::default();
    for source in sources {
        found.visit_file(&source.ast);
    }
    found.0
}

#[derive(Default)]
struct ErrorTypes(BTreeSet<String>);

impl<'ast> Visit<'ast> for ErrorTypes {
    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_item_mod(self, item);
        }
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        if let Some((_, trait_path, _)) = &item.trait_ {
            if trait_path
                .segments
                .last()
                .is_some_and(|s| s.ident == "Error")
            {
                self.0.insert(type_name(&item.self_ty));
            }
        }
        visit::visit_item_impl(self, item);
    }

    fn visit_item_enum(&mut self, item: &'ast syn::ItemEnum) {
        if derives_error(&item.attrs) {
            self.0.insert(item.ident.to_string());
        }
        visit::visit_item_enum(self, item);
    }

    fn visit_item_struct(&mut self, item: &'ast syn::ItemStruct) {
        if derives_error(&item.attrs) {
            self.0.insert(item.ident.to_string());
        }
        visit::visit_item_struct(self, item);
    }

    fn visit_path_segment(&mut self, segment: &'ast syn::PathSegment) {
        if segment.ident == "Result" {
            if let syn::PathArguments::AngleBracketed(args) = &segment.arguments {
                let types: Vec<&syn::Type> = args
                    .args
                    .iter()
                    .filter_map(|a| match a {
                        syn::GenericArgument::Type(t) => Some(t),
                        _ => None,
                    })
                    .collect();
                if let [_, error] = types[..] {
                    self.0.insert(type_name(error));
                }
            }
        }
        visit::visit_path_segment(self, segment);
    }
}

fn derives_error(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|attr| {
        attr.path().is_ident("derive")
            && attr
                .parse_args_with(
                    syn::punctuated::Punctuated::<syn::Path, syn::Token![,]>::parse_terminated,
                )
                .is_ok_and(|paths| {
                    paths
                        .iter()
                        .any(|p| p.segments.last().is_some_and(|s| s.ident == "Error"))
                })
    })
}

/// Whether a type of this name is an error type, given those found.
fn is_error_type(name: &str, found: &BTreeSet<String>) -> bool {
    ["Error", "Kind", "Problem"]
        .iter()
        .any(|end| name.ends_with(end))
        || found.contains(name)
}

/// Rule e for one product file of a library package.
pub(crate) fn flags_in_errors(source: &Source, errors: &BTreeSet<String>) -> Vec<Offender> {
    let mut visitor = Texts {
        source,
        errors,
        owner: None,
        inherent: None,
        found: Vec::new(),
    };
    visitor.visit_file(&source.ast);
    visitor.found
}

struct Texts<'a> {
    source: &'a Source,
    errors: &'a BTreeSet<String>,
    /// The error type whose text the visitor is inside, if any.
    owner: Option<String>,
    /// The error type of the inherent `impl` block the visitor is in, if any.
    inherent: Option<String>,
    found: Vec<Offender>,
}

impl Texts<'_> {
    /// Checks one literal: `value` as the program sees it, `written` as the
    /// source spells it (the flag's own line is counted there), `line` where
    /// the literal starts.
    fn literal(&mut self, owner: &str, value: &str, written: &str, line: usize) {
        if let Some(flag) = flag(value) {
            let down = written
                .find(&flag)
                .map_or(0, |at| written[..at].matches('\n').count());
            let line = line + down;
            self.found.push(Offender {
                rule: Rule::FlagInLibraryError,
                place: Place::Text {
                    path: self.source.rel.clone(),
                    line,
                    owner: owner.to_string(),
                    flag,
                },
            });
        }
    }

    /// Every string literal among `tokens`, at any depth.
    fn tokens(&mut self, owner: &str, tokens: TokenStream) {
        for tree in tokens {
            match tree {
                TokenTree::Group(group) => self.tokens(owner, group.stream()),
                TokenTree::Literal(literal) => {
                    let line = literal.span().start().line;
                    let written = literal.to_string();
                    if let syn::Lit::Str(s) = syn::Lit::new(literal) {
                        self.literal(owner, &s.value(), &written, line);
                    }
                }
                _ => {}
            }
        }
    }

    fn error_attributes(&mut self, owner: &str, attrs: &[syn::Attribute]) {
        for attr in attrs {
            if let syn::Meta::List(list) = &attr.meta {
                if list.path.is_ident("error") {
                    self.tokens(owner, list.tokens.clone());
                }
            }
        }
    }

    fn within(&mut self, owner: Option<String>, walk: impl FnOnce(&mut Self)) {
        let outer = std::mem::replace(&mut self.owner, owner);
        walk(self);
        self.owner = outer;
    }
}

/// The first flag in `text`: `--` then a letter, through the name's end.
pub(crate) fn flag(text: &str) -> Option<String> {
    let at = text
        .match_indices("--")
        .map(|(i, _)| i)
        .find(|&i| text[i + 2..].starts_with(|c: char| c.is_ascii_alphabetic()))?;
    let name = text[at + 2..]
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_'))
        .next()
        .unwrap_or("");
    Some(format!("--{name}"))
}

impl<'ast> Visit<'ast> for Texts<'_> {
    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        if !cfg::is_test_only(&item.attrs) {
            visit::visit_item_mod(self, item);
        }
    }

    fn visit_item_enum(&mut self, item: &'ast syn::ItemEnum) {
        let name = item.ident.to_string();
        self.error_attributes(&name, &item.attrs);
        for variant in &item.variants {
            self.error_attributes(&format!("{name}::{}", variant.ident), &variant.attrs);
        }
    }

    fn visit_item_struct(&mut self, item: &'ast syn::ItemStruct) {
        self.error_attributes(&item.ident.to_string(), &item.attrs);
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        if cfg::is_test_only(&item.attrs) {
            return;
        }
        let name = type_name(&item.self_ty);
        let error = is_error_type(&name, self.errors);
        let display = item
            .trait_
            .as_ref()
            .is_some_and(|(_, path, _)| path.segments.last().is_some_and(|s| s.ident == "Display"));
        let owner = (display && error).then(|| name.clone());
        let inherent = (item.trait_.is_none() && error).then_some(name);
        let outer = std::mem::replace(&mut self.inherent, inherent);
        self.within(owner, |me| visit::visit_item_impl(me, item));
        self.inherent = outer;
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        if cfg::is_test_only(&item.attrs) {
            return;
        }
        let name = item.sig.ident.to_string();
        let text_fn = TEXT_FNS.contains(&name.as_str()) || name.contains("message");
        match self.inherent.clone() {
            Some(owner) if text_fn => {
                let owner = format!("{owner}::{name}");
                self.within(Some(owner), |me| visit::visit_impl_item_fn(me, item));
            }
            _ => visit::visit_impl_item_fn(self, item),
        }
    }

    fn visit_lit_str(&mut self, lit: &'ast syn::LitStr) {
        if let Some(owner) = self.owner.clone() {
            let written = lit.token().to_string();
            self.literal(&owner, &lit.value(), &written, lit.span().start().line);
        }
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        if let Some(owner) = self.owner.clone() {
            self.tokens(&owner, mac.tokens.clone());
        }
        visit::visit_macro(self, mac);
    }
}
