//! The card for the course texts: their errata counted by class, the
//! worst three in plain words, and where the rest are (`docs/errata.md`).

use std::fmt::Write as _;

use super::format::escape;
use record::Lang;

/// How many of the worst errata the card names.
const WORST: usize = 3;

/// The card, after the areas' cards.
pub(super) fn course_texts_card(h: &mut String) {
    let _ = write!(
        h,
        "<div class=card id=course-texts><h3><a href=\"docs/errata.md\">Course texts</a></h3>\
         <p>{}<br>worst:</p><ol class=small>",
        escape(&errata::listing::tally(Lang::En))
    );
    for erratum in errata::worst(WORST) {
        let _ = write!(
            h,
            "<li>{} <span class=small>({})</span></li>",
            escape(&erratum.title.en),
            escape(&erratum.place(Lang::En))
        );
    }
    h.push_str("</ol><p class=small>All of them, with what is right, in <code>docs/errata.md</code>.</p></div>\n");
}
