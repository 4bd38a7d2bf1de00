//! The card for the course texts: their errata counted by class, the
//! worst three in plain words, and where the rest are (`docs/errata.md`).

use std::fmt::Write as _;

use super::format::escape;
use record::Lang;

/// How many of the worst errata the card names.
const WORST: usize = 3;

/// The card, after the areas' cards, in `lang`.
pub(super) fn course_texts_card(h: &mut String, lang: Lang) {
    let _ = write!(
        h,
        "<div class=card id=course-texts><h3><a href=\"docs/errata.md\">{}</a></h3>\
         <p>{}<br>{}</p><ol class=small>",
        lang.pick("Course texts", "A kurzus szövegei"),
        escape(&errata::listing::tally(lang)),
        lang.pick("worst:", "a legsúlyosabbak:")
    );
    for erratum in errata::worst(WORST) {
        let _ = write!(
            h,
            "<li>{} <span class=small>({})</span></li>",
            escape(erratum.title.pick(lang)),
            escape(&erratum.place(lang))
        );
    }
    let _ = writeln!(
        h,
        "</ol><p class=small>{}</p></div>",
        lang.pick(
            "All of them, with what is right, in <code>docs/errata.md</code>.",
            "Mind, a helyes változattal együtt: <code>docs/errata.md</code>."
        )
    );
}
