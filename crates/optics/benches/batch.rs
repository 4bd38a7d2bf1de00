//! Throughput of `optics batch`: JSON Lines requests evaluated per second,
//! parsing, solving (with the working, and for exact Fresnel also without
//! it, as `--no-steps` does), and writing the JSON results.
//!
//! `cargo bench -p optics --bench batch`; criterion prints elements/s, the
//! lines per second (one element is one line).

use criterion::measurement::WallTime;
use criterion::{criterion_group, BatchSize, BenchmarkGroup, Criterion, Throughput};
use optics::batch::{self, BatchArgs};
use record::Lang;

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
                r#"{{"law": "fresnel", "eta": 0.17, "kappa": 3.1, "cos_i": {t}, "model": "schlick-incident"}}"#
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

/// `count` exact-Fresnel requests, dielectric, from both sides.
fn fresnel_requests(count: usize) -> String {
    let mut text = String::new();
    for i in 0..count {
        let t = (i as f64 + 0.5) / count as f64;
        let (eta, cos_i) = (
            1.0 + t,
            2.0 * ((i * 7919) % count) as f64 / count as f64 - 1.0,
        );
        text.push_str(&format!(
            "{{\"law\": \"fresnel\", \"eta\": {eta:.6}, \"cos_i\": {cos_i:.6}}}\n"
        ));
    }
    text
}

const LINES: usize = 100_000;

/// Runs `input` (`LINES` lines) through `optics batch` with `args`.
fn bench_lines(group: &mut BenchmarkGroup<WallTime>, name: &str, input: &str, args: &BatchArgs) {
    group.bench_function(name, |b| {
        b.iter_batched(
            || input.as_bytes(),
            |bytes| {
                let (read, failed) = batch::run(args, bytes, std::io::sink(), Lang::En).unwrap();
                assert_eq!((read, failed), (LINES, 0));
            },
            BatchSize::SmallInput,
        )
    });
}

fn batch_throughput(c: &mut Criterion) {
    let with_steps = BatchArgs {
        block: 16384,
        no_steps: false,
    };
    let no_steps = BatchArgs {
        no_steps: true,
        ..with_steps
    };
    let mut group = c.benchmark_group("batch");
    group.throughput(Throughput::Elements(LINES as u64));
    group.sample_size(10);
    let mixed = requests(LINES);
    bench_lines(&mut group, "mixed_laws_100k_lines", &mixed, &with_steps);
    let fresnel = fresnel_requests(LINES);
    bench_lines(
        &mut group,
        "fresnel_exact_100k_lines",
        &fresnel,
        &with_steps,
    );
    bench_lines(
        &mut group,
        "fresnel_exact_100k_lines_no_steps",
        &fresnel,
        &no_steps,
    );
    group.finish();
}

criterion_group!(benches, batch_throughput);

fn main() {
    results::criterion::main(benches, record);
}

/// The section `batch-throughput` of `docs/results.md`.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let rows = [
        (
            "mixed_laws_100k_lines",
            "mixed: fresnel exact and Schlick, refract, shade, each with its working",
        ),
        (
            "fresnel_exact_100k_lines",
            "exact Fresnel, dielectric, with its working",
        ),
        (
            "fresnel_exact_100k_lines_no_steps",
            "exact Fresnel, dielectric, `--no-steps`",
        ),
    ];
    let ids: Vec<String> = rows.iter().map(|(id, _)| format!("batch/{id}")).collect();
    let mut table = String::from(
        "| requests (parsing and writing included) | lines per second | 10⁶ lines |\n|---|---|---|\n",
    );
    for ((_, what), estimate) in rows.iter().zip(run.estimates(&ids)?) {
        let per_second = estimate
            .per_second()
            .expect("the bench declares its throughput");
        table.push_str(&format!(
            "| {what} | {:.0} thousand | {:.2} s |\n",
            per_second / 1e3,
            1e6 / per_second
        ));
    }
    Ok(results::Section::measured(
        "batch-throughput",
        "cargo bench -p optics --bench batch",
        &table,
    ))
}
