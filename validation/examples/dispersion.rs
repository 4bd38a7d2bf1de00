//! A glass sphere of N-BK7 with dispersion: the slides' three etas and a
//! single index against the spectral answer
//! ([`validation::techniques::dispersion`] says how).
//!
//! `cargo run --release -p validation --example dispersion`
//!
//! The table is the section `dispersion` of `docs/results.md`; the
//! pictures are written to `docs/images/dispersion-*.png` by `main` only.

use std::path::Path;

use radiometry::spectrum::SAMPLES;
use techniques::dispersion::{fraunhofer_nm, CIE_RGB_PRIMARIES_NM};
use tracer::output::write_png;
use validation::techniques::dispersion::{index, measures, renders};

const COMMAND: &str = "cargo run --release -p validation --example dispersion";

fn table() -> String {
    let r = renders();
    let mut t = String::from(
        "| the sphere's index | ΔE2000 mean | ΔE2000 p99 | relative RMSE |\n|---|---:|---:|---:|\n",
    );
    let [nr, ng, nb] = CIE_RGB_PRIMARIES_NM.map(index);
    for (what, image) in [
        (
            format!("three etas ({nr:.5}, {ng:.5}, {nb:.5} at 700, 546.1, 435.8 nm)"),
            &r.three,
        ),
        (
            format!("one index, n_d = {:.5}", index(fraunhofer_nm::D)),
            &r.single,
        ),
    ] {
        let e = measures(image, &r);
        t.push_str(&format!(
            "| {what} | {:.2} | {:.2} | {:.4} |\n",
            e.delta_e_mean, e.delta_e_p99, e.rel_rmse
        ));
    }
    t.push_str(&format!(
        "\n{} of {} pixels see the sphere; the spectral answer renders it at {SAMPLES} wavelengths.\n",
        r.sphere.iter().filter(|k| k.is_some()).count(),
        r.sphere.len()
    ));
    t
}

fn pictures() {
    let r = renders();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/images");
    for (name, image) in [
        ("spectral", &r.spectral),
        ("three-etas", &r.three),
        ("single-index", &r.single),
    ] {
        write_png(&dir.join(format!("dispersion-{name}.png")), image).expect("docs/images");
    }
}

fn main() {
    let table = table();
    println!("{table}");
    results::assert_settled(&results::Section::deterministic(
        "dispersion",
        COMMAND,
        &table,
    ));
    pictures();
}

#[test]
fn committed_table_is_current() {
    results::assert_settled(&results::Section::deterministic(
        "dispersion",
        COMMAND,
        &table(),
    ));
}
