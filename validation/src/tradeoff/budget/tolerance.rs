//! A tolerance in words, as the budget's record and its errors write it.

/// A tolerance as people write it: the shorter of its plain and its
/// scientific form, each the shortest that reads back the same (`0.05`,
/// `1e-7`, not `0.0000001`).
pub fn written(tolerance: f64) -> String {
    let (plain, scientific) = (format!("{tolerance}"), format!("{tolerance:e}"));
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}
