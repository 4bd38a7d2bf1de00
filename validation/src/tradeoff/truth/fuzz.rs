//! The truth cache's reader ([`read_cached`]) on cache entries mutated byte
//! by byte: a whole entry of the course's `shadow` at 8 × 6 (its PFM and
//! its record), each file overwritten, cut, lengthened, a header number or
//! a radiance replaced (NaN, infinity), a size past `usize` or of the same byte count, the record's
//! key, size or noise changed. The promises: the unmutated entry is read;
//! nothing panics; an entry read has the job's size, the key asked and
//! only finite numbers, else the refusal says why.

use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use serde_json::json;
use tracer::job::{Overrides, RenderJob};
use tracer::render::Image;

use super::{read_cached, Stale, FINITE_UNCHECKED};

const KEY: &str = "00000000000000aa";

fn job() -> RenderJob {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/tracer/scenes/shadow.json");
    let overrides = Overrides {
        width: Some(8),
        height: Some(6),
        ..Overrides::default()
    };
    RenderJob::load(&path, &overrides).unwrap()
}

/// The unmutated entry: a PFM of the job's size and its record.
fn entry() -> (Vec<u8>, Vec<u8>) {
    let image = Image {
        width: 8,
        height: 6,
        pixels: (0..48).map(|i| Vec3::splat(i as f32 / 48.0)).collect(),
    };
    let pfm = tracer::output::pfm_bytes(&image);
    let record = json!({
        "settings": {}, "spp": 64, "seconds": 1.0, "noise_relative": 0.01, "noise": 0.001,
        "cached": false, "key": KEY, "file": "shadow-aa.pfm"
    });
    (pfm, serde_json::to_vec(&record).unwrap())
}

/// One change to one of the two files.
#[derive(Clone, Debug)]
enum Mutation {
    Overwrite(bool, usize, u8),
    Insert(bool, usize, u8),
    Truncate(bool, usize),
    /// The PFM's `n`-th header field replaced.
    Header(usize, &'static str),
    /// The `n`-th last radiance replaced.
    Radiance(usize, f32),
    /// A record field replaced.
    Field(&'static str, serde_json::Value),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let number = prop::sample::select(vec![
        "0",
        "1",
        "8",
        "6",
        "7 6",
        "8 6",
        "6 8",
        "48 1",
        "12 4",
        "4294967295",
        "4294967295 4294967295",
        "65536 65536",
        "-1.0",
        "1.0",
        "nan",
        "PF",
        "Pf",
        "",
    ]);
    let value = prop::sample::select(vec![
        json!(null),
        json!("ffffffffffffffff"),
        json!(KEY),
        json!(-1.0),
        json!(1e308),
        json!("0.001"),
        json!([]),
    ]);
    let field = prop::sample::select(vec!["key", "noise", "spp", "settings", "file"]);
    prop_oneof![
        (any::<bool>(), any::<usize>(), any::<u8>())
            .prop_map(|(f, i, b)| Mutation::Overwrite(f, i, b)),
        (any::<bool>(), any::<usize>(), any::<u8>())
            .prop_map(|(f, i, b)| Mutation::Insert(f, i, b)),
        (any::<bool>(), any::<usize>()).prop_map(|(f, i)| Mutation::Truncate(f, i)),
        (0..3usize, number).prop_map(|(n, t)| Mutation::Header(n, t)),
        (
            0..144usize,
            prop::sample::select(vec![f32::NAN, f32::INFINITY, -f32::INFINITY, -1.0, 3e38])
        )
            .prop_map(|(n, v)| Mutation::Radiance(n, v)),
        (field, value).prop_map(|(f, v)| Mutation::Field(f, v)),
    ]
}

fn apply((pfm, meta): &mut (Vec<u8>, Vec<u8>), m: &Mutation) {
    let at = |i: usize, len: usize| i % len.max(1);
    match m {
        Mutation::Overwrite(f, i, b) => {
            let bytes = if *f { pfm } else { meta };
            if !bytes.is_empty() {
                let i = at(*i, bytes.len());
                bytes[i] = *b;
            }
        }
        Mutation::Insert(f, i, b) => {
            let bytes = if *f { pfm } else { meta };
            bytes.insert(at(*i, bytes.len() + 1), *b);
        }
        Mutation::Truncate(f, i) => {
            let bytes = if *f { pfm } else { meta };
            bytes.truncate(at(*i, bytes.len() + 1));
        }
        Mutation::Header(n, text) => {
            let lines: Vec<&[u8]> = pfm.splitn(4, |b| *b == b'\n').collect();
            if *n < lines.len().saturating_sub(1) {
                let mut lines: Vec<Vec<u8>> = lines.into_iter().map(<[u8]>::to_vec).collect();
                lines[*n] = text.as_bytes().to_vec();
                *pfm = lines.join(&b'\n');
            }
        }
        Mutation::Radiance(n, v) if pfm.len() >= 4 * (n + 1) => {
            let at = pfm.len() - 4 * (n + 1);
            pfm[at..at + 4].copy_from_slice(&v.to_le_bytes());
        }
        Mutation::Field(name, value) => {
            if let Ok(serde_json::Value::Object(mut record)) = serde_json::from_slice(meta) {
                record.insert((*name).to_owned(), value.clone());
                *meta = serde_json::to_vec(&record).unwrap();
            }
        }
        _ => {}
    }
}

/// Runs the target; `Err` with the first failing case, shrunk. Prints
/// how many entries were read and how many refused, by reason.
fn fuzz(cases: u32) -> Result<(), String> {
    let tally = std::sync::Mutex::new(std::collections::BTreeMap::<String, usize>::new());
    let job = job();
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    let rng = proptest::test_runner::TestRng::deterministic_rng(
        proptest::test_runner::RngAlgorithm::ChaCha,
    );
    let strategy = prop::collection::vec(mutation(), 1..4);
    TestRunner::new_with_rng(config, rng)
        .run(&strategy, |mutations| {
            let mut files = entry();
            for m in &mutations {
                apply(&mut files, m);
            }
            match read_cached(&files.0, &files.1, KEY, &job) {
                Ok((image, record)) => {
                    *tally.lock().unwrap().entry("read".into()).or_default() += 1;
                    prop_assert_eq!((image.width, image.height), (8, 6));
                    prop_assert_eq!(record.key.as_str(), KEY);
                    prop_assert!(record.noise.is_finite() && record.noise >= 0.0);
                    prop_assert!(
                        image.pixels.iter().all(|p| p.is_finite()),
                        "a radiance not finite was read"
                    );
                }
                Err(stale) => {
                    let why = format!("{stale:?}");
                    let why = why.split([' ', '{']).next().unwrap_or_default().to_owned();
                    *tally.lock().unwrap().entry(why).or_default() += 1;
                    prop_assert!(!stale.to_string().is_empty());
                }
            }
            Ok(())
        })
        .map_err(|e| e.to_string())?;
    println!("  {:?}", tally.lock().unwrap());
    Ok(())
}

#[test]
fn the_truth_cache_reads_its_own_entry() {
    let (pfm, meta) = entry();
    assert!(read_cached(&pfm, &meta, KEY, &job()).is_ok());
    assert!(matches!(
        read_cached(&pfm, &meta, "other", &job()),
        Err(Stale::Key { .. })
    ));
}

/// The cases: `OPTICS_FUZZ_CASES`, as every fuzz target, else 512.
#[test]
fn truth_cache_entries_keep_their_promises() {
    let cases = std::env::var("OPTICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(512);
    let start = std::time::Instant::now();
    fuzz(cases).unwrap();
    println!(
        "truth cache: {cases} cases in {:.1} s",
        start.elapsed().as_secs_f64()
    );
}

#[test]
fn truth_cache_entries_find_a_reader_that_takes_a_radiance_not_finite() {
    FINITE_UNCHECKED.set(true);
    let outcome = fuzz(512);
    FINITE_UNCHECKED.set(false);
    let failure = outcome.expect_err("the reverted check is found");
    assert!(failure.contains("not finite was read"), "{failure}");
}
