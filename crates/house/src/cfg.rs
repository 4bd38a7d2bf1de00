//! Whether an item is compiled only for tests: `#[cfg(test)]`, or a `cfg`
//! whose predicate cannot hold without `test` (`all(test, unix)`).
//!
//! `cfg(any(test, feature = "x"))` is product code: it is compiled into a
//! build with the feature on, so it is held to the product rules.

use syn::punctuated::Punctuated;
use syn::{Attribute, Meta, Token};

/// Whether these attributes make their item test-only.
pub(crate) fn is_test_only(attrs: &[Attribute]) -> bool {
    attrs.iter().any(|attr| {
        attr.path().is_ident("cfg")
            && attr
                .parse_args::<Meta>()
                .map(|meta| implies_test(&meta))
                .unwrap_or(false)
    })
}

/// Whether the `cfg` predicate can only hold in a test build.
fn implies_test(meta: &Meta) -> bool {
    match meta {
        Meta::Path(path) => path.is_ident("test"),
        Meta::List(list) if list.path.is_ident("all") => list
            .parse_args_with(Punctuated::<Meta, Token![,]>::parse_terminated)
            .map(|parts| parts.iter().any(implies_test))
            .unwrap_or(false),
        Meta::List(list) if list.path.is_ident("any") => list
            .parse_args_with(Punctuated::<Meta, Token![,]>::parse_terminated)
            .map(|parts| !parts.is_empty() && parts.iter().all(implies_test))
            .unwrap_or(false),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::is_test_only;

    fn attrs(source: &str) -> Vec<syn::Attribute> {
        let item: syn::ItemMod = syn::parse_str(&format!("{source} mod m;")).unwrap();
        item.attrs
    }

    #[test]
    fn cfg_test_and_its_conjunctions_are_test_only() {
        for (source, test_only) in [
            ("#[cfg(test)]", true),
            ("#[cfg(all(test, unix))]", true),
            ("#[cfg(any(test, test))]", true),
            ("#[cfg(any(test, feature = \"faults\"))]", false),
            ("#[cfg(not(test))]", false),
            ("#[cfg(unix)]", false),
            ("#[allow(dead_code)]", false),
        ] {
            assert_eq!(is_test_only(&attrs(source)), test_only, "{source}");
        }
    }
}
