//! The names of the laws a batch request may name: vocabulary, imported by
//! the batch reader and by the error texts that list them, and importing
//! nothing.

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
