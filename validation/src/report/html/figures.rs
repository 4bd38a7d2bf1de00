//! A figure in the page, captioned with the command that regenerates it,
//! and a card's thumbnail; either opens the figure in full when clicked.

use std::fmt::Write as _;

use super::format::escape;

/// The command that writes the report and every figure in it.
pub(super) const REGENERATE: &str = "cargo run --release -p optics -- validate";

/// A figure, named by its file and the command that regenerates it.
pub(super) fn figure(h: &mut String, file: &str) {
    let pixels = if file.contains("render_") {
        " class=pixels"
    } else {
        ""
    };
    let _ = writeln!(
        h,
        "<figure><a href=\"{0}\"><img{pixels} src=\"{0}\" alt=\"{0}\"></a><figcaption>{0}: <code>{1}</code></figcaption></figure>",
        escape(file),
        regenerates(file)
    );
}

/// A card's picture of `file`, a link to the figure in full.
pub(super) fn thumbnail(h: &mut String, file: &str) {
    let _ = write!(
        h,
        "<a href=\"{0}\"><img src=\"{0}\" alt=\"{0}\"></a>",
        escape(file)
    );
}

/// The command that draws `file`: the trade-off's plots come with its
/// records (`docs/tradeoffs/make`), every other figure with the report.
fn regenerates(file: &str) -> &'static str {
    if file
        .rsplit('/')
        .next()
        .is_some_and(|name| name.starts_with("tradeoff_"))
    {
        crate::tradeoff::checks::REGENERATE
    } else {
        REGENERATE
    }
}
