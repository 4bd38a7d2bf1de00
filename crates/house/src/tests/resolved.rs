//! Imports followed to the file that defines the name: re-exports are
//! passed through, a definition in an ancestor is an upward import, and a
//! circle drawn only by re-exports is still a circle.

use super::Tree;
use crate::Rule;

/// Offenders as the report prints them.
fn named(tree: &Tree) -> Vec<String> {
    tree.offenders().iter().map(|o| o.to_string()).collect()
}

#[test]
fn a_child_importing_what_its_parent_only_reexports_is_clean() {
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "mod floor;\nmod room;\nmod scene;\npub use floor::Floor;\n\
             pub(crate) use floor::{Door, Wall as Side};\npub use scene::*;\n",
        )
        .file(
            "src/floor.rs",
            "pub struct Floor;\npub struct Door;\npub struct Wall;\n",
        )
        .file(
            "src/room.rs",
            "use crate::{Door, Floor, Side};\nuse crate::Shape;\n\
             pub struct Room(Floor, Door, Side, Shape);\n",
        )
        .file(
            "src/scene/mod.rs",
            "mod shape;\nmod error;\npub use shape::Shape;\n",
        )
        .file("src/scene/shape.rs", "pub struct Shape;\n")
        .file(
            "src/scene/error.rs",
            "use super::Shape;\npub struct Error(Shape, crate::Floor);\n",
        );
    let found = tree.offenders();
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn a_child_importing_what_its_parent_defines_is_upward() {
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "mod floor;\nmod room;\npub use floor::Floor;\npub struct Ui;\n",
        )
        .file("src/floor.rs", "pub struct Floor;\n")
        .file(
            "src/room.rs",
            "use crate::{Floor, Ui};\npub struct Room(Floor, Ui);\n",
        );
    assert_eq!(
        named(&tree),
        ["src/room.rs:1: imports `crate::Ui` from its ancestor src/lib.rs"]
    );
}

#[test]
fn a_reexport_is_followed_through_every_floor_to_its_definition() {
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "mod scene;\nmod user;\npub use scene::Scene;\n",
        )
        .file(
            "src/scene/mod.rs",
            "mod model;\npub use self::model::Scene;\n",
        )
        .file(
            "src/scene/model.rs",
            "pub struct Scene;\npub fn used() { crate::user::scene(); }\n",
        )
        .file(
            "src/user.rs",
            "use crate::Scene;\npub fn scene() -> Scene { crate::Scene }\n",
        );
    // The model uses the user back: a circle of exactly these two files,
    // not of the floors the re-exports pass through.
    assert_eq!(
        named(&tree),
        ["import circle of 2 files: src/scene/model.rs src/user.rs"]
    );
}

#[test]
fn a_circle_drawn_only_by_reexports_is_a_circle() {
    // a.rs never uses B: it only hands it on; b.rs uses A from a.rs.
    let tree = Tree::new()
        .file("src/lib.rs", "mod a;\nmod b;\n")
        .file("src/a.rs", "pub use crate::b::B;\npub struct A;\n")
        .file("src/b.rs", "use crate::a::A;\npub struct B(pub A);\n");
    assert_eq!(
        named(&tree),
        ["import circle of 2 files: src/a.rs src/b.rs"]
    );
}

#[test]
fn variants_and_associated_items_lead_to_the_file_defining_the_type() {
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "mod lang;\nmod metal;\nmod text;\npub use lang::Lang;\n",
        )
        .file(
            "src/lang.rs",
            "pub enum Lang { En }\npub fn all() -> usize { crate::text::COUNT }\n",
        )
        .file(
            "src/metal/mod.rs",
            "mod conductor;\nmod slice;\npub use conductor::Conductor;\n",
        )
        .file(
            "src/metal/conductor.rs",
            "pub struct Conductor;\nimpl Conductor { pub fn new() -> Self { Conductor } }\n\
             pub fn used() -> u8 { super::slice::ONE }\n",
        )
        .file(
            "src/metal/slice.rs",
            "pub const ONE: u8 = 1;\npub fn metal() { super::Conductor::new(); }\n",
        )
        .file(
            "src/text.rs",
            "pub const COUNT: usize = 1;\npub fn en() { let _ = crate::Lang::En; }\n",
        );
    assert_eq!(
        named(&tree),
        [
            "import circle of 2 files: src/lang.rs src/text.rs",
            "import circle of 2 files: src/metal/conductor.rs src/metal/slice.rs",
        ]
    );
}

#[test]
fn a_path_to_a_module_points_at_its_file() {
    let tree = Tree::new()
        .file("src/lib.rs", "pub mod fresnel;\nmod snell;\n")
        .file("src/fresnel.rs", "pub fn f() -> u8 { crate::snell::N }\n")
        .file(
            "src/snell.rs",
            "use crate::fresnel;\npub const N: u8 = 1;\npub fn g() { fresnel::f(); }\n",
        );
    assert_eq!(tree.rules(), [Rule::ImportCircle]);
}

#[test]
fn dollar_crate_in_a_macro_body_is_no_arrow_of_its_file() {
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "#[macro_use]\nmod macros;\npub struct Root;\npub fn root() -> Root { say!() }\n",
        )
        .file(
            "src/macros.rs",
            "macro_rules! say {\n    () => {\n        $crate::Root\n    };\n}\n",
        );
    let found = tree.offenders();
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn reexports_round_a_loop_end_the_walk() {
    // Not valid Rust, but the guard must still finish on it.
    let tree = Tree::new()
        .file("src/lib.rs", "mod a;\nmod b;\n")
        .file("src/a.rs", "pub use crate::b::X;\n")
        .file("src/b.rs", "pub use crate::a::X;\n");
    let _ = tree.offenders();
}
