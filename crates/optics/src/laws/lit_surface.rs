//! The flags of a surface lit by a directional light, declared once for
//! every law that shades one (`optics shade`, `quiz lambert`, `quiz
//! blinn-phong`): `--normal`, `--light-dir`, `--view-dir`, `--radiance`.
//!
//! A macro rather than a flattened struct: a batch request refuses a field
//! its law does not have, which `serde` cannot check across a flattened
//! struct, so the fields are written into each law's own.

/// Declares a law's arguments that open with the lit surface's four
/// fields, then the law's own. The law gives `view_dir`'s type and help:
/// a Lambert surface needs no viewer.
macro_rules! lit_surface_args {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $(#[$view_meta:meta])*
            view_dir: $view:ty,
            $( $(#[$field_meta:meta])* pub $field:ident: $field_type:ty, )*
        }
    ) => {
        $(#[$meta])*
        pub struct $name {
            /// Surface normal (any length).
            #[arg(long, allow_hyphen_values = true)]
            pub normal: $crate::input::Vec3Arg,
            /// Direction towards the light (any length).
            #[arg(long, allow_hyphen_values = true)]
            pub light_dir: $crate::input::Vec3Arg,
            $(#[$view_meta])*
            #[arg(long, allow_hyphen_values = true)]
            pub view_dir: $view,
            /// The light's L_in, W/m² on a surface facing it.
            #[arg(long, allow_hyphen_values = true)]
            pub radiance: f64,
            $( $(#[$field_meta])* pub $field: $field_type, )*
        }
    };
}

pub(crate) use lit_surface_args;
