//! Texts in the suite's two languages ([`record::Lang`]) that are not
//! errors: what the tracer's needs analysis found, and the command line's
//! help in Hungarian (`help`, from the table `help_hu`). The errors' texts
//! are the kinds' own (`crate::error`).

pub(crate) mod help;
mod help_hu;
pub mod needs;
#[cfg(test)]
mod tests;
