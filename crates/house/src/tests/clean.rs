//! A tree that keeps every rule, with the look-alikes no rule may flag.

use super::{function, lines, Tree};

/// A product file whose inline tests import from their parent and hold a
/// long test and an error text with a flag, all test code.
const PRODUCT: &str = r#"
//! Sizes (`--second` is a CSS property in a report, not a flag).

use crate::floor::Floor;

pub const REGENERATE: &str = "cargo run --release -p optics -- validate --quick";

pub fn style(second: f64) -> String {
    format!("--second:{second:.4}%")
}

pub fn args() -> [&'static str; 2] {
    ["--quiet", "--disable-pip-version-check"]
}

#[derive(Debug, thiserror::Error)]
pub enum SizeError {
    #[error("the width must be positive, got {0}")]
    Width(i64),
}

/// A command line a report shows: a Display, but of no error type.
pub struct Rerun;

impl std::fmt::Display for Rerun {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("optics validate --quick")
    }
}

pub fn floor() -> Floor {
    Floor
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, thiserror::Error)]
    #[error("a test double that mentions --flag")]
    struct DoubleError;
"#;

#[test]
fn a_clean_tree_has_no_offenders() {
    let test_fn = function("long_test", 120);
    let tree = Tree::new()
        .file(
            "src/lib.rs",
            "pub mod floor;\npub mod size;\n#[cfg(test)]\nmod tests;\n",
        )
        .file("src/floor.rs", "pub struct Floor;\n")
        .file(
            "src/size.rs",
            &format!("{PRODUCT}\n    #[test]\n    {test_fn}}}\n"),
        )
        .file(
            "src/tests.rs",
            &format!("use super::*;\nmod helpers;\n{}{test_fn}", lines(400)),
        )
        .file(
            "src/tests/helpers.rs",
            &format!("use crate::size::*;\n{}", lines(400)),
        )
        .file("tests/integration.rs", &format!("{}{test_fn}", lines(500)));
    let found = tree.offenders();
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn a_file_that_opens_with_cfg_test_is_test_code() {
    let tree = Tree::new().file("src/lib.rs", "mod checks;\n").file(
        "src/checks.rs",
        &format!("#![cfg(test)]\nuse crate::*;\n{}", lines(500)),
    );
    assert!(tree.offenders().is_empty());
}

#[test]
fn a_cfg_test_child_of_a_product_file_counts_as_test_code() {
    let tree = Tree::new()
        .file("src/lib.rs", "mod scene;\n")
        .file(
            "src/scene.rs",
            "#[cfg(all(test, unix))]\nmod tests;\npub struct Scene;\n",
        )
        .file(
            "src/scene/tests.rs",
            &format!("use super::Scene;\n{}", lines(500)),
        );
    assert!(tree.offenders().is_empty());
}

#[test]
fn a_path_attribute_is_followed_and_a_shared_file_counted_once() {
    let tree = Tree::new()
        .file(
            "benches/speed.rs",
            "#[path = \"shared/work.rs\"]\nmod work;\n",
        )
        .file(
            "examples/demo.rs",
            "#[path = \"../benches/shared/work.rs\"]\nmod work;\n",
        )
        .file("benches/shared/work.rs", &lines(401));
    let found: Vec<String> = tree.offenders().iter().map(|o| o.to_string()).collect();
    assert_eq!(found, ["benches/shared/work.rs: 401 lines (at most 400)"]);
}
