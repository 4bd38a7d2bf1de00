//! The course's ray tracers, built only from the laws of the `radiometry` crate.
