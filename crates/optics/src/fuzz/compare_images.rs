//! Images for `optics compare`: a small PNG and PFMs (little- and
//! big-endian, RGB and grey) mutated byte by byte (overwritten, inserted,
//! deleted, truncated, a header number replaced), through the entry point
//! that admits an image before the reference is rendered
//! ([`crate::compare::admit`]): no panic, and every refusal names `IMAGE`.

use super::{run_and_report, runner, Coverage};
use crate::compare::admit;
use crate::compare::user_image::LENGTH_UNCHECKED;
use image::ImageEncoder;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use record::Lang;
use std::path::{Path, PathBuf};

/// The scene the images are of (8 × 6 in the file; any size is asked).
fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tracer/scenes/first_red_sphere.json")
}

/// The unmutated images: 4 × 3 pixels each, and one too wide to render.
fn seeds() -> Vec<Vec<u8>> {
    let pixels: Vec<f32> = (0..36).map(|i| i as f32 / 36.0).collect();
    let mut png = Vec::new();
    let codes: Vec<u8> = pixels
        .iter()
        .map(|&v| tracer::output::to_srgb8(v))
        .collect();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(&codes, 4, 3, image::ExtendedColorType::Rgb8)
        .expect("a 4 × 3 PNG encodes");
    let floats = |header: &str, values: &[f32], big: bool| {
        let mut bytes = header.as_bytes().to_vec();
        for v in values {
            bytes.extend_from_slice(&if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            });
        }
        bytes
    };
    vec![
        png,
        floats("PF\n4 3\n-1.0\n", &pixels, false),
        floats("PF 4 3 1\n", &pixels, true),
        floats("Pf\n4 3\n-1\n", &pixels[..12], false),
        // One column wider than the tracer renders: refused by its size.
        floats("Pf\n16385 1\n-1\n", &[0.5; 16385], false),
    ]
}

/// One change to the bytes.
#[derive(Clone, Debug)]
enum Mutation {
    Overwrite(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    Truncate(usize),
    /// The `n`-th white-space separated header field replaced.
    Field(usize, String),
    /// A float's four bytes written over the `n`-th last, both byte orders.
    Float(usize, f32, bool),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let number = prop::sample::select(vec![
        "0",
        "-0",
        "1",
        "65536",
        "4294967296",
        "99999999999999999999",
        "nan",
        "inf",
        "-1e-45",
        "1e38",
        "PF",
        "Pf",
        "P6",
        "",
        "4 3",
    ]);
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Overwrite(i, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Insert(i, b)),
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Truncate),
        (0..4usize, number).prop_map(|(i, n)| Mutation::Field(i, n.to_owned())),
        (
            0..12usize,
            prop::sample::select(vec![f32::NAN, f32::INFINITY, -f32::INFINITY, -1.0, 3e38]),
            any::<bool>()
        )
            .prop_map(|(i, v, big)| Mutation::Float(i, v, big)),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    let at = |i: usize, len: usize| i % len.max(1);
    match m {
        Mutation::Overwrite(i, b) if !bytes.is_empty() => {
            let i = at(*i, bytes.len());
            bytes[i] = *b;
        }
        Mutation::Insert(i, b) => bytes.insert(at(*i, bytes.len() + 1), *b),
        Mutation::Delete(i) if !bytes.is_empty() => {
            bytes.remove(at(*i, bytes.len()));
        }
        Mutation::Truncate(i) => bytes.truncate(at(*i, bytes.len() + 1)),
        Mutation::Field(n, text) => {
            let mut fields: Vec<&[u8]> = bytes.splitn(5, u8::is_ascii_whitespace).collect();
            if *n < fields.len().saturating_sub(1) {
                fields[*n] = text.as_bytes();
                *bytes = fields.join(&b'\n');
            }
        }
        Mutation::Float(n, v, big) if bytes.len() >= 4 * (n + 1) => {
            let at = bytes.len() - 4 * (n + 1);
            let b = if *big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            };
            bytes[at..at + 4].copy_from_slice(&b);
        }
        _ => {}
    }
}

fn check_image(bytes: &[u8], coverage: &Coverage) -> Result<(), TestCaseError> {
    match admit(Path::new("mutated"), bytes, &scene(), None) {
        Ok(_) => coverage.answer(),
        Err(error) => {
            let json = error.to_json(Lang::En);
            coverage.error(&json);
            prop_assert_eq!(&json["field"], "IMAGE", "{}", json);
            let kind = json["kind"].as_str().unwrap_or_default();
            prop_assert!(kind.starts_with("compare."), "{}", json);
        }
    }
    Ok(())
}

/// Runs the target; `Err` with the first failing case, shrunk.
fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    let seeds = seeds();
    let strategy = (0..seeds.len(), prop::collection::vec(mutation(), 1..4));
    runner(cases)
        .run(&strategy, |(seed, mutations)| {
            let mut bytes = seeds[seed].clone();
            for m in &mutations {
                apply(&mut bytes, m);
            }
            check_image(&bytes, coverage)
        })
        .map_err(|e| e.to_string())
}

#[test]
fn compare_images_keep_their_promises() {
    run_and_report("compare images", fuzz);
}

#[test]
fn compare_images_find_a_pfm_reader_that_trusts_its_header() {
    LENGTH_UNCHECKED.set(true);
    let outcome = fuzz(256, &Coverage::default());
    LENGTH_UNCHECKED.set(false);
    let failure = outcome.expect_err("the reverted fix is found");
    assert!(failure.contains("index out of bounds"), "{failure}");
}
