//! The table of `docs/errata.md`, written from the errata: the counts by
//! class, the worst few in plain words, and one table per class, ranked.

use record::Lang;

use crate::erratum::{Class, Erratum};
use crate::listing::tally;
use crate::table::{ranked, worst};

/// The section's name in `docs/errata.md`, between its markers.
pub const SECTION: &str = "errata";

/// The command that checks the section (and, with `RESULTS_WRITE=1`,
/// rewrites it).
pub const COMMAND: &str = "cargo test -p errata --lib";

/// How many of the worst the page names in plain words.
pub const WORST: usize = 5;

/// The section: the counts, the worst few, then a table per class.
pub fn section() -> String {
    let mut out = format!("{}.\n\n", tally(Lang::En));
    for class in Class::ALL {
        out += &format!("- **{}**: {}.\n", class.name(), class.meaning(Lang::En));
    }
    out += "\nThe worst, in plain words:\n\n";
    for (i, erratum) in worst(WORST).iter().enumerate() {
        let effect = erratum
            .effect
            .as_ref()
            .map_or(String::new(), |e| format!(" {}", e.en));
        out += &format!(
            "{}. **{}** (`{}`, {}).{effect}\n",
            i + 1,
            erratum.title.en,
            erratum.id,
            erratum.place(Lang::En)
        );
    }
    let ranked = ranked();
    for class in Class::ALL {
        let rows: Vec<(usize, &Erratum)> = ranked
            .iter()
            .enumerate()
            .filter(|(_, e)| e.class == class)
            .map(|(i, e)| (i + 1, *e))
            .collect();
        out += &format!(
            "\n### {} ({})\n\n| # | id | place | what is written | what is right | effect | test |\n|---|---|---|---|---|---|---|\n",
            capitalised(class.name()),
            rows.len()
        );
        for (rank, e) in rows {
            out += &row(rank, e);
        }
    }
    out
}

/// One erratum as a row of the table.
fn row(rank: usize, e: &Erratum) -> String {
    let effect = e.effect.as_ref().map_or("—".to_owned(), |w| cell(&w.en));
    let tests: Vec<String> = e.tests.iter().map(|t| format!("`{t}`")).collect();
    format!(
        "| {rank} | `{}` | {} | {} | {} | {effect} | {} |\n",
        e.id,
        e.place(Lang::En),
        cell(&format!("`{}`", e.written.replace('`', "'"))),
        cell(&e.right.en),
        tests.join(", ")
    )
}

/// Text that can stand in a table cell: its bars escaped.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

fn capitalised(word: &str) -> String {
    let mut chars = word.chars();
    chars
        .next()
        .map_or(String::new(), |c| c.to_uppercase().chain(chars).collect())
}
