//! An image that could not be written: the file, and why. The English is
//! the tracer's `Display`, the Hungarian an exhaustive `match` over its
//! kinds.

use record::Lang;
use safe_io::WriteError;
use tracer::output::OutputError;

/// An image that could not be written, in `lang`.
pub(super) fn output(error: &OutputError, lang: Lang) -> String {
    match lang {
        Lang::En => error.to_string(),
        Lang::Hu => output_hu(error),
    }
}

/// An image that could not be written, in Hungarian.
fn output_hu(error: &OutputError) -> String {
    match error {
        OutputError::Write(WriteError::Io { path, source }) => {
            format!("a(z) {path} nem írható: {source}")
        }
        OutputError::Write(WriteError::NoDirectory { path, dir }) => {
            format!("a(z) {path} nem írható: a(z) {dir} könyvtár nem létezik")
        }
        OutputError::Write(WriteError::Unwritable { dir, source }) => {
            format!("a(z) {dir} könyvtárba nem írható fájl: {source}")
        }
        OutputError::Write(WriteError::NotARegularFile { path }) => {
            format!("a(z) {path} létezik, és nem közönséges fájl; nem íródik felül")
        }
        OutputError::Write(WriteError::IsAnInput { path, input }) => {
            format!("a(z) {path} azonos a beolvasott {input} fájllal; más kimenetet kell megadni")
        }
        OutputError::PfmIsPng { path } => {
            format!("{path}: a PNG nevét kell megadni (a PFM mellé kerül)")
        }
        OutputError::NotPng { path } => {
            format!("{path}: a kép PNG-ként íródik ki (mellé a PFM): .png végű nevet kell megadni")
        }
        OutputError::Png { path, source } => {
            format!("a(z) {path} nem kódolható PNG-ként: {source}")
        }
    }
}
