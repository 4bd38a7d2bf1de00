//! A line diff of two texts, for the message of a section that no longer
//! matches its committed copy.

/// The lines of `old` and `new` as a unified listing: unchanged lines
/// prefixed by two spaces, removed ones by `- `, added ones by `+ `, from a
/// longest common subsequence of lines (sections are a few dozen lines, so
/// the quadratic table is small).
pub fn lines(old: &str, new: &str) -> String {
    let (a, b): (Vec<&str>, Vec<&str>) = (old.lines().collect(), new.lines().collect());
    // common[i][j]: length of the longest common subsequence of a[i..], b[j..].
    let mut common = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for i in (0..a.len()).rev() {
        for j in (0..b.len()).rev() {
            common[i][j] = if a[i] == b[j] {
                common[i + 1][j + 1] + 1
            } else {
                common[i + 1][j].max(common[i][j + 1])
            };
        }
    }
    let (mut i, mut j, mut out) = (0, 0, String::new());
    while i < a.len() || j < b.len() {
        if i < a.len() && j < b.len() && a[i] == b[j] {
            out += &format!("  {}\n", a[i]);
            (i, j) = (i + 1, j + 1);
        } else if j == b.len() || (i < a.len() && common[i + 1][j] >= common[i][j + 1]) {
            out += &format!("- {}\n", a[i]);
            i += 1;
        } else {
            out += &format!("+ {}\n", b[j]);
            j += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::lines;

    #[test]
    fn a_changed_line_shows_as_removed_and_added() {
        let diff = lines(
            "| a | 1.00 |\n| b | 2.00 |\n",
            "| a | 1.00 |\n| b | 2.01 |\n",
        );
        assert_eq!(diff, "  | a | 1.00 |\n- | b | 2.00 |\n+ | b | 2.01 |\n");
    }

    #[test]
    fn equal_texts_have_no_marked_line() {
        let diff = lines("x\ny\n", "x\ny\n");
        assert!(diff.lines().all(|l| l.starts_with("  ")), "{diff}");
    }

    #[test]
    fn added_and_removed_lines_at_either_end() {
        assert_eq!(lines("a\nb\n", "b\nc\n"), "- a\n  b\n+ c\n");
    }
}
