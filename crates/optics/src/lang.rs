//! Texts in the suite's two languages ([`record::Lang`]) that are not
//! errors: what the tracer's needs analysis found. The errors' texts are
//! the kinds' own (`crate::error`).

pub mod needs;
