//! The record's schema: its name, its version, and the names of the fixed
//! error measures it carries.

/// The record's schema name; its version is [`SCHEMA_VERSION`].
pub const SCHEMA: &str = "optics.tradeoff";
/// The version of [`SCHEMA`]: raised when a field changes meaning or goes.
pub const SCHEMA_VERSION: u32 = 2;

/// The version before [`SCHEMA_VERSION`], still read: its `fresnel`
/// setting `schlick` (and the label `fresnel schlick`) named Schlick's
/// rarer-medium form, now `schlick-rarer` ([`super::record::upgrade`]).
pub const SCHLICK_UNNAMED_VERSION: u32 = 1;

/// The fixed error measures, by their names in the record.
pub const MEASURES: [&str; 4] = ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"];
