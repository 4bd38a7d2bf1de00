//! `optics batch`: JSON Lines in, JSON Lines out.
//!
//! Each input line is one request, `{"law": "fresnel", "eta": 1.5, ...}`,
//! with the fields of the matching subcommand's flags (`--cos-i` is
//! `cos_i`, vectors are `[x, y, z]`). Each output line is the record that
//! subcommand prints with `--json`, in input order; a line that cannot be
//! evaluated yields `{"line": N, "law": ..., "error": {"kind": ...,
//! "field": ..., "message": ...}}` and the rest go on, whatever the line
//! holds (bytes that are not UTF-8 included). Lines are evaluated in
//! parallel in blocks; the output order is the input order whatever the
//! thread count.

use crate::error::{Error, ErrorKind, Result};
use crate::input::Via;
use crate::lang::Lang;
use crate::laws::{FresnelArgs, ReflectArgs, RefractArgs, ShadeArgs};
use crate::quiz::{BlinnPhongArgs, CriticalAngleArgs, F0Args, LambertArgs};
use crate::record::Record;
use rayon::prelude::*;
use serde::de::DeserializeOwned;
use serde_json::{json, Map, Value};
use std::io::{BufRead, Write};

#[derive(clap::Args, Debug)]
#[command(
    after_help = r#"Requests are JSON objects, one per line; "law" is one of:
  fresnel, refract, reflect, shade, f0, lambert, critical_angle, blinn_phong
and the other fields are the subcommand's flags with '_' for '-' and vectors as [x, y, z].

Example:
  printf '%s\n' '{"law": "fresnel", "eta": 1.5, "cos_i": 0.3}' \
                '{"law": "refract", "wi": [0, 0.6, 0.8], "normal": [0, 0, 1], "eta": 1.5}' | optics batch

Exit status: 0 when every line was evaluated, 1 when any line gave an error object."#
)]
pub struct BatchArgs {
    /// Lines evaluated together in parallel before their results are written.
    #[arg(long, default_value_t = 16384, value_parser = clap::value_parser!(u32).range(1..))]
    pub block: u32,
}

/// The laws a request may name, in the order `--help` lists them.
pub const LAWS: [&str; 8] = [
    "fresnel",
    "refract",
    "reflect",
    "shade",
    "f0",
    "lambert",
    "critical_angle",
    "blinn_phong",
];

/// Evaluates one request.
pub fn evaluate(request: Map<String, Value>, law: &str, lang: Lang) -> Result<Record> {
    fn parse<T: DeserializeOwned>(fields: Map<String, Value>) -> Result<T> {
        serde_path_to_error::deserialize(Value::Object(fields)).map_err(|e| {
            let path = e.path().to_string();
            let message = e.inner().to_string();
            let path = (path != ".").then_some(path);
            ErrorKind::Request { path, message }.into()
        })
    }
    let via = Via::Json;
    Ok(match law {
        "fresnel" => parse::<FresnelArgs>(request)?.solve(via, lang)?,
        "refract" => parse::<RefractArgs>(request)?.solve(via, lang)?,
        "reflect" => parse::<ReflectArgs>(request)?.solve(via, lang)?,
        "shade" => parse::<ShadeArgs>(request)?.solve(via, lang)?,
        "f0" => parse::<F0Args>(request)?.solve(via, lang)?,
        "lambert" => parse::<LambertArgs>(request)?.solve(via, lang)?,
        "critical_angle" => parse::<CriticalAngleArgs>(request)?.solve(via, lang)?,
        "blinn_phong" => parse::<BlinnPhongArgs>(request)?.solve(via, lang)?,
        other => {
            let law = other.to_owned();
            return Err(ErrorKind::UnknownLaw { law }.into());
        }
    })
}

/// A request line taken apart: the law it names and its other fields.
fn request(text: &str) -> Result<(String, Map<String, Value>), (Value, Error)> {
    let refuse = |law: Value, kind: ErrorKind| Err((law, Error::from(kind)));
    if text.trim().is_empty() {
        return refuse(Value::Null, ErrorKind::EmptyLine);
    }
    let mut request = match serde_json::from_str::<Value>(text) {
        Ok(Value::Object(map)) => map,
        Ok(_) => return refuse(Value::Null, ErrorKind::NotAnObject),
        Err(e) => return refuse(Value::Null, ErrorKind::MalformedJson(e)),
    };
    match request.remove("law") {
        Some(Value::String(law)) => Ok((law, request)),
        Some(other) => refuse(other, ErrorKind::LawNotString),
        None => refuse(Value::Null, ErrorKind::LawMissing),
    }
}

/// One input line to one output line (without the newline), and whether it
/// was evaluated. A line that fails gives `{"line", "law", "error"}`, the
/// error as [`Error::to_json`] writes it.
pub fn line(number: usize, text: &str, lang: Lang) -> (String, bool) {
    let outcome = request(text).and_then(|(law, fields)| {
        let record = evaluate(fields, &law, lang);
        let json = record.and_then(|r| {
            serde_json::to_string(&r)
                .map_err(ErrorKind::Encode)
                .map_err(Error::from)
        });
        json.map_err(|error| (Value::String(law), error))
    });
    match outcome {
        Ok(json) => (json, true),
        Err((law, error)) => (failed_line(number, law, &error, lang), false),
    }
}

fn failed_line(number: usize, law: Value, error: &Error, lang: Lang) -> String {
    json!({ "line": number, "law": law, "error": error.to_json(lang) }).to_string()
}

/// A line as read: its text, or the bytes that are not UTF-8 and the
/// 1-based column of the first byte that is not.
type Text = std::result::Result<String, usize>;

/// [`line`] for a line as read: bytes that are not UTF-8 are that line's
/// error, and the lines around it go on.
fn read_line(number: usize, text: &Text, lang: Lang) -> (String, bool) {
    match text {
        Ok(text) => line(number, text, lang),
        Err(column) => {
            let error = Error::from(ErrorKind::NotUtf8 { column: *column });
            (failed_line(number, Value::Null, &error, lang), false)
        }
    }
}

#[cfg(test)]
thread_local! {
    /// A fault for the fuzz targets to find: bytes that are not UTF-8 stop
    /// the whole run, as a reader of `String` lines does.
    pub(crate) static NOT_UTF8_STOPS_THE_RUN: std::cell::Cell<bool> =
        const { std::cell::Cell::new(false) };
}

/// The next line of `input` (number `number`), without its `\n` or
/// `\r\n`; `None` at the end. Only the reader itself failing is an error.
fn next_line(input: &mut impl BufRead, number: usize) -> Result<Option<Text>> {
    let mut bytes = Vec::new();
    let read = input.read_until(b'\n', &mut bytes);
    let read = read.map_err(|source| ErrorKind::ReadLine {
        line: number,
        source,
    })?;
    if read == 0 {
        return Ok(None);
    }
    if bytes.last() == Some(&b'\n') {
        bytes.pop();
        if bytes.last() == Some(&b'\r') {
            bytes.pop();
        }
    }
    let text = String::from_utf8(bytes).map_err(|e| e.utf8_error().valid_up_to() + 1);
    #[cfg(test)]
    if text.is_err() && NOT_UTF8_STOPS_THE_RUN.get() {
        let source = std::io::Error::from(std::io::ErrorKind::InvalidData);
        let line = number;
        return Err(ErrorKind::ReadLine { line, source }.into());
    }
    Ok(Some(text))
}

/// Streams `input` to `output`; returns how many lines were read and how
/// many of them gave errors. Lines are held only as they arrive, however
/// large the block.
pub fn run(
    args: &BatchArgs,
    mut input: impl BufRead,
    mut output: impl Write,
    lang: Lang,
) -> Result<(usize, usize)> {
    let block = args.block as usize;
    let (mut read, mut failed) = (0usize, 0usize);
    loop {
        let mut texts = Vec::new();
        while texts.len() < block {
            match next_line(&mut input, read + texts.len() + 1)? {
                Some(text) => texts.push(text),
                None => break,
            }
        }
        if texts.is_empty() {
            break;
        }
        let results: Vec<(String, bool)> = texts
            .par_iter()
            .enumerate()
            .map(|(i, text)| read_line(read + i + 1, text, lang))
            .collect();
        for (json, ok) in &results {
            let written = output.write_all(json.as_bytes());
            written
                .and_then(|()| output.write_all(b"\n"))
                .map_err(ErrorKind::Write)?;
            failed += usize::from(!ok);
        }
        read += texts.len();
    }
    output.flush().map_err(ErrorKind::Write)?;
    Ok((read, failed))
}
