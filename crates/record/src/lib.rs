//! What a command of the suite says: its [`Record`] (the inputs, the
//! working step by step, the answer and the notes), shown as text in a
//! [`Lang`] or as one JSON object, and the [`say!`] macro that writes a
//! line in both languages side by side; and [`english`], which finds
//! English left in a Hungarian text.
//!
//! This is the ground floor the features and the front ends share: it
//! imports nothing of the suite, so a library can build the record a
//! command prints without knowing the command.
//!
//! ```
//! use record::{Answer, Lang, Record};
//!
//! let mut record = Record::new("fresnel", "Normal-incidence reflectance".into(), "");
//! record.set_answer(Answer::Number(0.04), None);
//! assert!(serde_json::to_string(&record).unwrap().contains("\"answer\":0.04"));
//! assert_eq!(Lang::Hu.pick("reflectance", "reflexió"), "reflexió");
//! ```

#![warn(missing_docs)]

pub mod english;
mod lang;
mod record;

pub use lang::Lang;
pub use record::*;
