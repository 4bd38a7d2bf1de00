//! Throughput of `optics batch`: JSON Lines requests evaluated per second,
//! parsing, solving with the working, and writing the JSON results.
//!
//! `cargo bench -p optics --bench batch`; criterion prints elements/s, the
//! lines per second (one element is one line).

use criterion::{criterion_group, BatchSize, Criterion, Throughput};
use optics::batch::{self, BatchArgs};
use optics::lang::Lang;

/// `count` requests cycling through the laws, with varying inputs.
fn requests(count: usize) -> String {
    let mut text = String::new();
    for i in 0..count {
        let t = i as f64 / count as f64;
        let line = match i % 4 {
            0 => format!(
                r#"{{"law": "fresnel", "eta": {}, "cos_i": {}}}"#,
                1.0 + t,
                2.0 * t - 1.0
            ),
            1 => format!(
                r#"{{"law": "fresnel", "eta": 0.17, "kappa": 3.1, "cos_i": {t}, "model": "schlick"}}"#
            ),
            2 => format!(
                r#"{{"law": "refract", "wi": [0, {t}, 1], "normal": [0, 0, 1], "eta": 1.5}}"#
            ),
            _ => format!(
                r#"{{"law": "shade", "normal": [0, 0, 1], "light_dir": [0, {t}, 1], "view_dir": [1, 0, 1], "radiance": 5, "kd": 0.2, "ks": 0.5, "shine": 20}}"#
            ),
        };
        text.push_str(&line);
        text.push('\n');
    }
    text
}

fn batch_throughput(c: &mut Criterion) {
    const LINES: usize = 100_000;
    let input = requests(LINES);
    let args = BatchArgs {
        block: 16384,
        no_steps: false,
    };
    let mut group = c.benchmark_group("batch");
    group.throughput(Throughput::Elements(LINES as u64));
    group.sample_size(10);
    group.bench_function("mixed_laws_100k_lines", |b| {
        b.iter_batched(
            || input.as_bytes(),
            |bytes| {
                let (read, failed) = batch::run(&args, bytes, std::io::sink(), Lang::En).unwrap();
                assert_eq!((read, failed), (LINES, 0));
            },
            BatchSize::SmallInput,
        )
    });
    group.finish();
}

criterion_group!(benches, batch_throughput);

fn main() {
    results::criterion::main(benches, record);
}

/// The section `batch-throughput` of `docs/results.md`.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let per_second = run.estimates(&["batch/mixed_laws_100k_lines".into()])?[0]
        .per_second()
        .expect("the bench declares its throughput");
    let table = format!(
        "| requests | lines per second | 10⁶ lines |\n|---|---|---|\n\
         | mixed: fresnel exact and Schlick, refract, shade, each with its working; parsing and writing included | {:.0} thousand | {:.1} s |\n",
        per_second / 1e3,
        1e6 / per_second
    );
    Ok(results::Section::measured(
        "batch-throughput",
        "cargo bench -p optics --bench batch",
        &table,
    ))
}
