//! Each rule shown to fail by a planted offender.
