//! The shape of a slot of the Hungarian help table.

/// `(command path, key, Hungarian)`: the key is an argument's id, a
/// possible value as `"arg=value"`, or a command's own `"#about"`,
/// `"#long_about"` or `"#after_help"` (`crate::lang::help`).
pub(crate) type Slot = (&'static [&'static str], &'static str, &'static str);
