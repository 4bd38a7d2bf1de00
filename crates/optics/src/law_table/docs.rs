//! The table of laws in `docs/cli.md`, written from the law table: each
//! law's request name, its command line and fields, and what it answers.

use super::schema::{self, Field, Kind};
use super::table::{command_words, LAWS};

/// The section's name in `docs/cli.md`, between its markers.
pub const SECTION: &str = "laws";

/// The command that checks the table (and, with `RESULTS_WRITE=1`,
/// rewrites it).
pub const COMMAND: &str = "cargo test -p optics --lib law_table";

/// One row per law: `law` | the command | its fields | what it answers.
pub fn table() -> String {
    let mut out = String::from(
        "| `law` in a request and its record | command | fields (`[optional]`) | what it answers |\n\
         |---|---|---|---|\n",
    );
    for &law in LAWS {
        let command = schema::command(law).expect("every law has its subcommand");
        let about = command
            .get_about()
            .map(|a| a.to_string())
            .unwrap_or_default();
        let fields: Vec<String> = schema::fields(law).iter().map(field).collect();
        out += &format!(
            "| `{law}` | `optics {}` | {} | {about} |\n",
            command_words(law).join(" "),
            fields.join(" ")
        );
    }
    out
}

/// A field as the table shows it: `eta`, `[kappa]`, `wi [x, y, z]`,
/// `model exact|schlick-incident|schlick-rarer|course`.
fn field(field: &Field) -> String {
    let shape = match &field.kind {
        Kind::Number => String::new(),
        Kind::Vector => " [x, y, z]".to_owned(),
        Kind::List => " [c, …]".to_owned(),
        Kind::Choice(names) => format!(" {}", names.join("\\|")),
    };
    if field.required {
        format!("`{}{shape}`", field.name)
    } else {
        format!("`[{}{shape}]`", field.name)
    }
}
