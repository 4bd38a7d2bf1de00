//! Measures how far Schlick's approximation strays from the exact Fresnel
//! equations, per material, over every angle of incidence.
//!
//! Run: `cargo run --release -p radiometry --example schlick_error`
//!
//! The bounds asserted by the test `schlick_stays_within_measured_bound` are
//! this program's output, rounded up. The table is the section
//! `schlick-accuracy` of `docs/results.md`: the program (and `cargo test`,
//! which builds it as a test) fails when the committed copy differs, and
//! rewrites it under `RESULTS_WRITE=1`.

use radiometry::fresnel::{
    conductor, dielectric, f0, schlick, schlick_dielectric, schlick_dielectric_incident,
};

/// Where a material's worst error occurs and how large it is.
struct Worst {
    abs_error: f64,
    theta_deg: f64,
    exact: f64,
    approx: f64,
}

fn worst(exact: impl Fn(f64) -> f64, approx: impl Fn(f64) -> f64) -> Worst {
    const STEPS: usize = 90_000; // 0.001° apart
    let mut w = Worst {
        abs_error: 0.0,
        theta_deg: 0.0,
        exact: 0.0,
        approx: 0.0,
    };
    for k in 0..=STEPS {
        let theta = std::f64::consts::FRAC_PI_2 * k as f64 / STEPS as f64;
        let c = theta.cos();
        let (e, a) = (exact(c), approx(c));
        if (e - a).abs() > w.abs_error {
            w = Worst {
                abs_error: (e - a).abs(),
                theta_deg: theta.to_degrees(),
                exact: e,
                approx: a,
            };
        }
    }
    w
}

results::deterministic_example!(
    "schlick-accuracy",
    "cargo run --release -p radiometry --example schlick_error",
    table
);

fn table() -> String {
    let mut table = String::from(
        "| material | light arrives | Schlick form | max \\|F_schlick − F_exact\\| | at θ_i | exact | Schlick |\n|---|---|---|---|---|---|---|\n",
    );
    let mut row = |name: &str, side: &str, form: &str, w: Worst| {
        table += &format!(
            "| {name} | {side} | {form} | {:.4} | {:.2}° | {:.4} | {:.4} |\n",
            w.abs_error, w.theta_deg, w.exact, w.approx
        );
    };
    for (name, eta) in [("water", 1.333), ("glass", 1.5), ("diamond", 2.42)] {
        let f0 = f0(eta, 0.0);
        row(
            name,
            "outside",
            "cos θ_i (both forms)",
            worst(|c| dielectric(c, eta), |c| schlick(c, f0)),
        );
        row(
            name,
            "inside",
            "cos θ_i (`schlick-incident`, the course's)",
            worst(
                |c| dielectric(-c, eta),
                |c| schlick_dielectric_incident(-c, eta),
            ),
        );
        row(
            name,
            "inside",
            "cos θ_t (`schlick-rarer`)",
            worst(|c| dielectric(-c, eta), |c| schlick_dielectric(-c, eta)),
        );
    }
    let metals = [
        ("gold R (course)", 0.17, 3.1),
        ("gold G (course)", 0.35, 2.7),
        ("gold B (course)", 1.5, 1.9),
        ("silver", 0.15, 3.6),
        ("copper", 0.27, 3.4),
        ("aluminium", 1.2, 7.0),
    ];
    for (name, n, kappa) in metals {
        let f0 = f0(n, kappa);
        row(
            name,
            "outside",
            "cos θ_i, F0(n, κ)",
            worst(|c| conductor(c, n, kappa), |c| schlick(c, f0)),
        );
    }
    table
}
