//! Every subcommand's `--help` shows an example.

use crate::common::{optics, stdout};

#[test]
fn every_subcommand_has_help_with_an_example() {
    let subcommands: &[&[&str]] = &[
        &["quiz"],
        &["quiz", "seed"],
        &["quiz", "f0"],
        &["quiz", "lambert"],
        &["quiz", "critical-angle"],
        &["quiz", "blinn-phong"],
        &["fresnel"],
        &["refract"],
        &["reflect"],
        &["shade"],
        &["envmap"],
        &["reflection-matrix"],
        &["shadow-matrix"],
        &["batch"],
        &["render"],
        &["inspect"],
        &["validate"],
    ];
    for sub in subcommands {
        let mut args = sub.to_vec();
        args.push("--help");
        let output = optics(&args);
        assert!(output.status.success(), "optics {args:?}");
        let text = stdout(&output);
        assert!(
            text.contains("Example") && text.contains("optics "),
            "no example in optics {args:?}:\n{text}"
        );
    }
}
