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
//!
//! Whether a line's working is written is decided once, where the line is
//! read (module `request`): its own `"steps"`, else `--no-steps`. Each block is
//! read into one buffer, and each share of it is written into one buffer
//! of output, both kept from block to block, so that memory stays flat
//! however many lines pass.

pub(crate) mod request;

use crate::error::{Error, ErrorKind, Result};
use crate::input::Via;
use record::Lang;
use record::Steps;

use serde_json::{json, Value};
use std::io::{BufRead, Read, Write};
use std::ops::Range;

/// `optics batch`'s flags.
#[derive(clap::Args, Debug)]
#[command(after_help = after_help())]
pub struct BatchArgs {
    /// Lines evaluated together in parallel before their results are written.
    #[arg(long, default_value_t = 16384, value_parser = clap::value_parser!(u32).range(1..))]
    pub block: u32,
    /// Skip the working: each record's "steps" is [] (a request's own "steps" overrides this).
    #[arg(long)]
    pub no_steps: bool,
}

/// `optics batch --help`'s closing text: the laws a request may name, from
/// the law table, and examples.
fn after_help() -> String {
    let laws = crate::law_table::LAWS.join(", ");
    format!(
        r#"Requests are JSON objects, one per line; "law" is one of:
  {laws}
and the other fields are the subcommand's flags with '_' for '-' and vectors as [x, y, z].
A request's "steps": true or false overrides --no-steps for that line.

Examples:
  printf '%s\n' '{{"law": "fresnel", "eta": 1.5, "cos_i": 0.3}}' \
                '{{"law": "refract", "wi": [0, 0.6, 0.8], "normal": [0, 0, 1], "eta": 1.5}}' | optics batch
  printf '%s\n' '{{"law": "fresnel", "eta": 1.5, "cos_i": 0.3}}' \
                '{{"law": "f0", "n": 1.5, "steps": true}}' | optics batch --no-steps

Exit status: 0 when every line was evaluated, 1 when any line gave an error object."#
    )
}

impl BatchArgs {
    /// The working wanted of a line that does not say.
    fn steps(&self) -> Steps {
        Steps::from_wanted(!self.no_steps)
    }
}

/// One input line to one output line, without the newline, appended to
/// `out`; whether it was evaluated. `steps` is the working wanted unless
/// the line says. A line that fails gives `{"line", "law", "error"}`, the
/// error as [`Error::to_json`] writes it.
pub fn line(number: usize, text: &str, lang: Lang, steps: Steps, out: &mut Vec<u8>) -> bool {
    let request = request::typed(text, steps).map_or_else(|| request::general(text, steps), Ok);
    let start = out.len();
    let written = request.and_then(|request| {
        let record = request.law.solve(Via::Json, lang, request.steps);
        let json = record.and_then(|record| {
            serde_json::to_writer(&mut *out, &record)
                .map_err(ErrorKind::Encode)
                .map_err(Error::from)
        });
        json.map_err(|error| (Value::String(request.name.into_owned()), error))
    });
    match written {
        Ok(()) => true,
        Err((law, error)) => {
            out.truncate(start);
            failed_line(number, law, &error, lang, out);
            false
        }
    }
}

fn failed_line(number: usize, law: Value, error: &Error, lang: Lang, out: &mut Vec<u8>) {
    let json = json!({ "line": number, "law": law, "error": error.to_json(lang) });
    // A `Value` has string keys only, and writing into memory cannot fail.
    let _ = serde_json::to_writer(out, &json);
}

/// The most bytes a line may hold, without its newline: a request is an
/// object of a few numbers, a few hundred bytes. A longer line is skipped
/// to its newline without being held, so a stream that never ends a line
/// (`optics batch < /dev/zero`) is one error, not all of memory.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// The text a block holds before it is evaluated, whatever `--block`:
/// with [`MAX_LINE_BYTES`], what bounds the memory of lines read.
const MAX_BLOCK_BYTES: usize = 64 << 20;

/// A line as read: where its text lies in the block, or why it was not.
type Text = std::result::Result<Range<usize>, Unread>;

/// Why a line's text is not in the block.
#[derive(Clone, Copy)]
enum Unread {
    /// The 1-based column of its first byte that is not UTF-8.
    NotUtf8(usize),
    /// Longer than [`MAX_LINE_BYTES`].
    TooLong,
}

/// The lines of one block: their text, one after another, and where each lies.
#[derive(Default)]
struct Block {
    text: String,
    lines: Vec<Text>,
    /// The bytes of the line being read.
    bytes: Vec<u8>,
}

#[cfg(test)]
thread_local! {
    /// A fault for the fuzz targets to find: bytes that are not UTF-8 stop
    /// the whole run, as a reader of `String` lines does.
    pub(crate) static NOT_UTF8_STOPS_THE_RUN: std::cell::Cell<bool> =
        const { std::cell::Cell::new(false) };
}

impl Block {
    /// Reads up to `lines` lines of `input` into the block, in place of
    /// those it held, the first of them number `first`.
    fn fill(&mut self, input: &mut impl BufRead, lines: usize, first: usize) -> Result<()> {
        self.text.clear();
        self.lines.clear();
        while self.lines.len() < lines
            && self.text.len() < MAX_BLOCK_BYTES
            && self.read_line(input, first + self.lines.len())?
        {}
        Ok(())
    }

    /// Reads the next line of `input` (number `number`) into the block,
    /// without its `\n` or `\r\n`; `false` at the end. Only the reader
    /// itself failing is an error.
    fn read_line(&mut self, input: &mut impl BufRead, number: usize) -> Result<bool> {
        let failed = |source| ErrorKind::ReadLine {
            line: number,
            source,
        };
        self.bytes.clear();
        // At most the longest line and its `\r\n`.
        let most = MAX_LINE_BYTES as u64 + 2;
        let read = input.by_ref().take(most).read_until(b'\n', &mut self.bytes);
        if read.map_err(failed)? == 0 {
            return Ok(false);
        }
        let mut bytes = &self.bytes[..];
        let ended = bytes.ends_with(b"\n");
        if let Some(line) = bytes.strip_suffix(b"\n") {
            bytes = line.strip_suffix(b"\r").unwrap_or(line);
        }
        let text = if bytes.len() > MAX_LINE_BYTES {
            if !ended {
                skip_line(input).map_err(failed)?;
            }
            Err(Unread::TooLong)
        } else {
            match std::str::from_utf8(bytes) {
                Ok(line) => {
                    let start = self.text.len();
                    self.text.push_str(line);
                    Ok(start..self.text.len())
                }
                Err(e) => Err(Unread::NotUtf8(e.valid_up_to() + 1)),
            }
        };
        #[cfg(test)]
        if matches!(text, Err(Unread::NotUtf8(_))) && NOT_UTF8_STOPS_THE_RUN.get() {
            let source = std::io::Error::from(std::io::ErrorKind::InvalidData);
            let line = number;
            return Err(ErrorKind::ReadLine { line, source }.into());
        }
        self.lines.push(text);
        Ok(true)
    }
}

/// Consumes `input` to the end of the line, holding none of it.
fn skip_line(input: &mut impl BufRead) -> std::io::Result<()> {
    loop {
        let buffer = input.fill_buf()?;
        if buffer.is_empty() {
            return Ok(());
        }
        match buffer.iter().position(|&b| b == b'\n') {
            Some(i) => {
                input.consume(i + 1);
                return Ok(());
            }
            None => {
                let all = buffer.len();
                input.consume(all);
            }
        }
    }
}

/// Lines evaluated by one task, into one buffer of output.
const SHARE: usize = 256;

/// The output of one share of a block, kept from block to block.
#[derive(Default)]
struct Share {
    out: Vec<u8>,
    failed: usize,
}

impl Share {
    /// Evaluates `lines` of `block`, the first of them number `first`.
    fn evaluate(&mut self, block: &Block, lines: &[Text], first: usize, lang: Lang, steps: Steps) {
        self.out.clear();
        self.failed = 0;
        for (i, text) in lines.iter().enumerate() {
            let number = first + i;
            let ok = match text {
                Ok(range) => line(
                    number,
                    &block.text[range.clone()],
                    lang,
                    steps,
                    &mut self.out,
                ),
                Err(unread) => {
                    let kind = match *unread {
                        Unread::NotUtf8(column) => ErrorKind::NotUtf8 { column },
                        Unread::TooLong => ErrorKind::LineTooLong {
                            limit: MAX_LINE_BYTES,
                        },
                    };
                    let error = Error::from(kind);
                    failed_line(number, Value::Null, &error, lang, &mut self.out);
                    false
                }
            };
            self.out.push(b'\n');
            self.failed += usize::from(!ok);
        }
    }
}

/// Streams `input` to `output`; returns how many lines were read and how
/// many of them gave errors. Lines are held only as they arrive, however
/// large the block. While one block is evaluated the one before it is
/// written and the next is read, and a reader that fails ends the run after
/// the blocks before it are written.
pub fn run(
    args: &BatchArgs,
    mut input: impl BufRead,
    mut output: impl Write,
    lang: Lang,
) -> Result<(usize, usize)> {
    let (block_lines, steps) = (args.block as usize, args.steps());
    let (mut read, mut failed) = (0usize, 0usize);
    let (mut block, mut next) = (Block::default(), Block::default());
    // The shares of the block being evaluated, and those of the block
    // before it, being written meanwhile (the first `pending` of them).
    let (mut shares, mut evaluated): (Vec<Share>, Vec<Share>) = (Vec::new(), Vec::new());
    let mut pending = 0;
    block.fill(&mut input, block_lines, 1)?;
    while !block.lines.is_empty() {
        let count = block.lines.len().div_ceil(SHARE);
        if shares.len() < count {
            shares.resize_with(count, Share::default);
        }
        let after = read + block.lines.len();
        let (wrote, filled) = rayon::in_place_scope(|scope| {
            let lines = block.lines.chunks(SHARE);
            for (i, (share, lines)) in shares.iter_mut().zip(lines).enumerate() {
                let (block, first) = (&block, read + i * SHARE + 1);
                scope.spawn(move |_| share.evaluate(block, lines, first, lang, steps));
            }
            let wrote = write_shares(&mut output, &evaluated[..pending]);
            (wrote, next.fill(&mut input, block_lines, after + 1))
        });
        failed += wrote?;
        std::mem::swap(&mut shares, &mut evaluated);
        pending = count;
        if let Err(error) = filled {
            write_shares(&mut output, &evaluated[..pending])?;
            return Err(error);
        }
        read = after;
        std::mem::swap(&mut block, &mut next);
    }
    failed += write_shares(&mut output, &evaluated[..pending])?;
    output.flush().map_err(ErrorKind::Write)?;
    Ok((read, failed))
}

/// Writes the output of `shares` in order; how many of their lines failed.
fn write_shares(output: &mut impl Write, shares: &[Share]) -> Result<usize> {
    let mut failed = 0;
    for share in shares {
        output.write_all(&share.out).map_err(ErrorKind::Write)?;
        failed += share.failed;
    }
    Ok(failed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{BufReader, Read};

    /// `count` exact-Fresnel lines, the k-th at `cos_i = k / 100`.
    fn lines(count: usize) -> String {
        (1..=count)
            .map(|k| format!("{{\"law\": \"fresnel\", \"eta\": 1.5, \"cos_i\": 0.{k:02}}}\n"))
            .collect()
    }

    fn cosines(output: &[u8]) -> Vec<f64> {
        String::from_utf8_lossy(output)
            .lines()
            .map(|l| {
                serde_json::from_str::<Value>(l).expect("a record")["inputs"]["cos_i"]
                    .as_f64()
                    .expect("cos_i")
            })
            .collect()
    }

    #[test]
    fn blocks_are_written_in_the_order_read_while_the_next_is_evaluated() {
        for block in [1, 2, 3, 7, 16384] {
            let mut output = Vec::new();
            let args = BatchArgs {
                block,
                no_steps: true,
            };
            let (read, failed) = run(&args, lines(7).as_bytes(), &mut output, Lang::En).unwrap();
            assert_eq!((read, failed), (7, 0), "block {block}");
            let expected: Vec<f64> = (1..=7).map(|k| k as f64 / 100.0).collect();
            assert_eq!(cosines(&output), expected, "block {block}");
        }
    }

    /// Gives its bytes, then fails.
    struct FailsAfter(std::io::Cursor<Vec<u8>>);

    impl Read for FailsAfter {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            match self.0.read(buf)? {
                0 => Err(std::io::Error::other("the disk went away")),
                n => Ok(n),
            }
        }
    }

    #[test]
    fn a_reader_that_fails_ends_the_run_after_the_blocks_before_it_are_written() {
        // The lines of the block being read when the reader fails are
        // lost; every block before it is written, in order.
        for (block, complete) in [(1, 5), (2, 4), (16384, 0)] {
            let input = BufReader::with_capacity(
                16,
                FailsAfter(std::io::Cursor::new(lines(5).into_bytes())),
            );
            let mut output = Vec::new();
            let args = BatchArgs {
                block,
                no_steps: true,
            };
            let error = run(&args, input, &mut output, Lang::En).expect_err("the reader fails");
            assert!(
                matches!(error.kind(), ErrorKind::ReadLine { line: 6, .. }),
                "{error:?}"
            );
            let expected: Vec<f64> = (1..=complete).map(|k| k as f64 / 100.0).collect();
            assert_eq!(cosines(&output), expected, "block {block}");
        }
    }
}
