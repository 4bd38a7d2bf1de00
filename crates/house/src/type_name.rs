//! A type's name as the rules speak of it.

/// The last name of a type's path (`SceneError` for `scene::SceneError<'a>`,
/// also behind a reference), or an empty name when the type is no path.
pub(crate) fn type_name(ty: &syn::Type) -> String {
    match ty {
        syn::Type::Path(p) => p
            .path
            .segments
            .last()
            .map(|s| s.ident.to_string())
            .unwrap_or_default(),
        syn::Type::Reference(r) => type_name(&r.elem),
        _ => String::new(),
    }
}
