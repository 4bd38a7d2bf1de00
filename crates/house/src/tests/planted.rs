//! One planted offender per rule, each required to be found and named.

use super::{function, lines, path, Tree};
use crate::{Place, Rule};

#[test]
fn a_file_over_400_lines_is_found_and_one_of_400_is_not() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod long;\nmod full;\n")
        .file("src/long.rs", &lines(401))
        .file("src/full.rs", &lines(400));
    let found = tree.offenders();
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].rule, Rule::LongFile);
    assert_eq!(
        found[0].place,
        Place::File {
            path: path("src/long.rs"),
            lines: 401
        }
    );
    assert_eq!(found[0].to_string(), "src/long.rs: 401 lines (at most 400)");
}

#[test]
fn examples_and_benches_are_product_and_undeclared_files_too() {
    let tree = Tree::new()
        .file("src/lib.rs", "")
        .file("src/orphan.rs", &lines(401))
        .file("examples/demo.rs", &lines(401))
        .file("benches/speed.rs", &lines(401));
    let found: Vec<String> = tree.offenders().iter().map(|o| o.to_string()).collect();
    assert_eq!(
        found,
        [
            "benches/speed.rs: 401 lines (at most 400)",
            "examples/demo.rs: 401 lines (at most 400)",
            "src/orphan.rs: 401 lines (at most 400)",
        ]
    );
}

#[test]
fn a_function_over_80_lines_is_found_and_one_of_80_is_not() {
    let method = function("long", 81).replace('\n', "\n    ");
    let tree = Tree::new().file(
        "src/lib.rs",
        &format!(
            "{}{}pub struct S;\nimpl S {{\n    {method}}}\n",
            function("planted", 81),
            function("fits", 80)
        ),
    );
    let found: Vec<String> = tree.offenders().iter().map(|o| o.to_string()).collect();
    assert_eq!(
        found,
        [
            "src/lib.rs:1: fn planted is 81 lines (at most 80)",
            "src/lib.rs:164: fn S::long is 81 lines (at most 80)",
        ]
    );
}

#[test]
fn a_two_file_circle_is_found_with_both_files() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod a;\nmod b;\n")
        .file("src/a.rs", "use crate::b::B;\npub struct A;\n")
        .file(
            "src/b.rs",
            "pub struct B;\npub fn a() -> crate::a::A { crate::a::A }\n",
        );
    let found = tree.offenders();
    assert_eq!(tree.rules(), [Rule::ImportCircle], "{found:?}");
    assert_eq!(
        found[0].to_string(),
        "import circle of 2 files: src/a.rs src/b.rs"
    );
}

#[test]
fn a_path_inside_a_macro_call_is_an_import() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod a;\nmod b;\n")
        .file("src/a.rs", "pub use crate::b::B;\npub const A: u8 = 1;\n")
        .file(
            "src/b.rs",
            "pub struct B;\npub fn show() -> String { format!(\"{}\", crate::a::A) }\n",
        );
    assert_eq!(tree.rules(), [Rule::ImportCircle]);
}

#[test]
fn a_child_importing_from_its_parent_is_an_upward_import() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod scene;\npub struct Ui;\n")
        .file("src/scene/mod.rs", "mod error;\npub const MAX: u8 = 1;\n")
        .file("src/scene/error.rs", "use super::MAX;\nuse crate::Ui;\n");
    let found: Vec<String> = tree.offenders().iter().map(|o| o.to_string()).collect();
    assert_eq!(
        found,
        [
            "src/scene/error.rs:1: imports `super::MAX` from its ancestor src/scene/mod.rs",
            "src/scene/error.rs:2: imports `crate::Ui` from its ancestor src/lib.rs",
        ]
    );
}

#[test]
fn a_parent_reexporting_a_child_that_imports_it_back_is_also_a_circle() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod scene;\n")
        .file(
            "src/scene.rs",
            "mod error;\npub use error::Error;\npub const MAX: u8 = 1;\n",
        )
        .file(
            "src/scene/error.rs",
            "pub struct Error;\nfn max() -> u8 { super::MAX }\n",
        );
    assert_eq!(tree.rules(), [Rule::ImportCircle, Rule::UpwardImport]);
}

const LIBRARY_ERRORS: &str = r#"
#[derive(Debug, thiserror::Error)]
pub enum CheckoutError {
    #[error("no checkout found: pass --checkout DIR")]
    NotFound,
}

pub enum ErrorKind { TooExpensive }

impl std::fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "past the limit without \
             --allow-expensive"
        )
    }
}

pub struct NoReference;

impl std::fmt::Display for NoReference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("--lambert measures the scene so")
    }
}

pub fn reference() -> Result<u8, NoReference> {
    Err(NoReference)
}
"#;

#[test]
fn a_library_error_naming_a_flag_is_found_in_each_form() {
    let tree = Tree::new().file("src/lib.rs", LIBRARY_ERRORS);
    let found: Vec<String> = tree.offenders().iter().map(|o| o.to_string()).collect();
    assert_eq!(
        found,
        [
            "src/lib.rs:4: the text of CheckoutError::NotFound names the flag --checkout",
            "src/lib.rs:15: the text of ErrorKind names the flag --allow-expensive",
            "src/lib.rs:24: the text of NoReference names the flag --lambert",
        ]
    );
}

#[test]
fn a_front_end_may_name_its_flags() {
    let tree = Tree::new()
        .file("Cargo.toml", "[workspace]\n")
        .file("crates/optics/Cargo.toml", "[package]\nname = \"optics\"\n")
        .file("crates/optics/src/lib.rs", LIBRARY_ERRORS)
        .file(
            "crates/library/Cargo.toml",
            "[package]\nname = \"library\"\n",
        )
        .file("crates/library/src/lib.rs", LIBRARY_ERRORS);
    let found = tree.offenders();
    assert_eq!(found.len(), 3, "{found:?}");
    assert!(found.iter().all(|o| matches!(
        &o.place,
        Place::Text { path, .. } if path.starts_with("crates/library")
    )));
}
