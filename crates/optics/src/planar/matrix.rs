//! A 4 × 4 matrix for people and for JSON: its rounding cleaned block by
//! block, one line of working, a record's detail or answer, its overflow.

use crate::error::{ErrorKind, Result};
use crate::input::Via;
use glam::{DMat4, DVec4};
use record::{number, Answer, Record};
use serde_json::Value;

/// How far below the largest entry of its block (the 3 × 3 part, the last
/// column, the last row) an entry is rounding. The reflection matrix is
/// three 4 × 4 products of a rotation built from a quaternion, each entry
/// off by a few ε of the block's size; 64 ε leaves room for them and is far
/// below the six digits printed.
pub const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// `x`, or 0 where it is within [`ROUNDING`] of `size` (and −0 as 0). An
/// infinite `x` stays, for the overflow checks after it to find.
pub(super) fn clean(x: f64, size: f64) -> f64 {
    if x.is_finite() && x.abs() <= ROUNDING * size {
        0.0
    } else {
        x
    }
}

/// `m` with its rounding cleaned, block by block: the 3 × 3 part, the last
/// column and the last row each against their own largest entry.
pub fn cleaned(m: DMat4) -> DMat4 {
    let largest = |cells: &mut dyn Iterator<Item = f64>| cells.fold(0.0f64, |a, x| a.max(x.abs()));
    let linear = largest(&mut (0..3).flat_map(|c| (0..3).map(move |r| m.col(c)[r])));
    let last_column = largest(&mut (0..3).map(|r| m.col(3)[r]));
    let last_row = largest(&mut (0..4).map(|c| m.col(c)[3]));
    let mut out = m;
    for c in 0..4 {
        for r in 0..4 {
            let size = match (r, c) {
                (3, _) => last_row,
                (_, 3) => last_column,
                _ => linear,
            };
            out.col_mut(c)[r] = clean(m.col(c)[r], size);
        }
    }
    out
}

/// `M (x, w)` with the rounding of the product cleaned: each component is
/// off by a few ε of `|M| (|x| + |w|)`.
pub fn cleaned_product(m: &DMat4, h: DVec4) -> DVec4 {
    let size = m.to_cols_array().iter().fold(0.0f64, |a, x| a.max(x.abs()))
        * h.abs().max_element().max(1.0);
    (*m * h).map(|x| clean(x, size))
}

/// The matrix's rows, for JSON.
fn rows(m: &DMat4) -> Vec<[f64; 4]> {
    (0..4).map(|i| m.row(i).to_array()).collect()
}

/// The matrix on one line of working: `[(a, b, c, d), …]`, by rows.
pub fn inline(m: &DMat4) -> String {
    let rows: Vec<String> = rows(m)
        .iter()
        .map(|row| {
            let cells: Vec<String> = row.iter().map(|&x| number(x)).collect();
            format!("({})", cells.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

/// A homogeneous vector for people: `(x, y, z, w)`.
pub fn vector4(h: DVec4) -> String {
    let cells: Vec<String> = h.to_array().iter().map(|&x| number(x)).collect();
    format!("({})", cells.join(", "))
}

/// A matrix as a record's detail: its rows.
pub fn matrix_detail(m: &DMat4) -> Value {
    rows(m)
        .iter()
        .map(|row| Value::from(row.to_vec()))
        .collect()
}

/// The matrix (cleaned) as the record's answer: its rows, and for people
/// one a line.
pub(super) fn matrix_answer(record: &mut Record, m: &DMat4) {
    let m = cleaned(*m);
    let text = rows(&m)
        .iter()
        .map(|row| {
            let cells: Vec<String> = row.iter().map(|&x| number(x)).collect();
            format!("  ({})", cells.join(", "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    let list = rows(&m)
        .iter()
        .map(|row| Value::from(row.to_vec()))
        .collect();
    record.set_answer(Answer::List(list), Some(format!("M =\n{text}")));
}

/// `m`, or the overflow of finite inputs whose products are not.
pub(super) fn finite_matrix(m: DMat4, via: Via, inputs: &[&str]) -> Result<DMat4> {
    if m.is_finite() {
        return Ok(m);
    }
    let inputs = inputs.iter().map(|field| via.name(field)).collect();
    Err(ErrorKind::Overflow {
        quantity: "M",
        inputs,
    }
    .into())
}
