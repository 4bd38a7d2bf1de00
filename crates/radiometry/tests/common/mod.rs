//! What the law tests share: the proptest strategies, named after what they
//! produce.

pub mod strategies;
