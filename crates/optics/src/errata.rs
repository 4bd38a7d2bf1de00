//! `optics errata`: the course texts' errata, ranked by class, or one by
//! its id. The listing and the ranking are the `errata` crate's; this
//! file reads the arguments and prints the record.

use crate::error::{self, ErrorKind};
use crate::ui::Ui;
use record::{Lang, Record};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics errata                              (every erratum, physics first)
  optics errata --class physics
  optics --lang hu errata 003-boxed-refraction   (what is right, in Hungarian)
  optics --json errata --class cosmetic      (one JSON object; the errata under answer)

Classes: physics (wrong physics a student would learn), picture (changes the
picture a listing or shader draws), cosmetic (typesetting, rounding, names).
The table is crates/errata/errata.json; docs/errata.md is written from it.")]
pub struct ErrataArgs {
    /// One erratum's id, as the listing shows it (`003-boxed-refraction`);
    /// without it, every erratum, ranked.
    pub id: Option<String>,
    /// Only the errata of this class: physics, picture or cosmetic (or
    /// fizika, kép, kozmetikai).
    #[arg(long)]
    pub class: Option<String>,
}

pub fn run(args: &ErrataArgs, ui: &Ui) -> error::Result<()> {
    ui.show(&record(args, ui.lang)?)
}

/// The record `optics errata` prints for `args`: one erratum when an id is
/// given, else the ranking (of one class when `--class` is given); an
/// unknown id or class is an error naming its argument.
pub fn record(args: &ErrataArgs, lang: Lang) -> error::Result<Record> {
    let class = args
        .class
        .as_deref()
        .map(::errata::parse_class)
        .transpose()
        .map_err(ErrorKind::Errata)?;
    Ok(match &args.id {
        Some(id) => ::errata::listing::one(id, lang).map_err(ErrorKind::Errata)?,
        None => ::errata::listing::ranking(class, lang),
    })
}
