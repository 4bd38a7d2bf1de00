//! The report: `report.json`'s record of every check, its data for the
//! figures and the references read ([`Report`]), written as JSON (the
//! exchange format the figure script reads) and as HTML for people
//! ([`to_html`]); the pipeline writes both atomically ([`crate::pipeline`]).

mod document;
mod html;

pub use document::{
    to_json, FresnelCurve, MetalSpectrum, ReferenceInfo, Report, Summary, WorstDeltaE,
    REPORT_SCHEMA,
};
pub use html::to_html;
