//! The verdict on a shortcut: whether it is seen against the scene's own
//! settings' render (ΔE2000 p99 against [`JUST_NOTICEABLE`]) and whether it
//! is faster (its time against [`WORTH_IT`] of theirs).

use record::Lang;
use serde::{Deserialize, Serialize};

/// A ΔE2000 of 1 is the just-noticeable difference: a shortcut whose 99th
/// percentile against the scene's own settings' render stays within this
/// is not seen.
pub const JUST_NOTICEABLE: f64 = 1.0;

/// A shortcut is worth it where it is not seen and costs at most this
/// share of the scene's own settings' time.
pub const WORTH_IT: f64 = 0.9;

/// What a shortcut is, read against the scene's own settings by the rule
/// of [`JUST_NOTICEABLE`] and [`WORTH_IT`]; decided once, when the sweep is
/// measured, and carried in the record.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Not seen, and faster: the shortcut is worth taking.
    WorthIt,
    /// Not seen, and no faster.
    Unseen,
    /// Faster, and seen: a trade.
    Trade,
    /// Seen, and no faster.
    Worse,
}

impl Verdict {
    /// The verdict on a shortcut whose render lies `delta_e_p99` (ΔE2000,
    /// 99th percentile) from the scene's own settings' render and takes
    /// `seconds` against their `base_seconds`.
    pub fn of(delta_e_p99: f64, seconds: f64, base_seconds: f64) -> Self {
        let seen = !(delta_e_p99 <= JUST_NOTICEABLE);
        let faster = seconds <= WORTH_IT * base_seconds;
        match (seen, faster) {
            (false, true) => Verdict::WorthIt,
            (false, false) => Verdict::Unseen,
            (true, true) => Verdict::Trade,
            (true, false) => Verdict::Worse,
        }
    }

    /// The verdict in words, the shortcut worth taking in bold (Markdown).
    pub fn words(self) -> &'static str {
        match self {
            Verdict::WorthIt => "**worth it** (not seen, faster)",
            _ => self.plain(),
        }
    }

    /// The verdict in plain words.
    pub fn plain(self) -> &'static str {
        self.said(Lang::En)
    }

    /// The verdict in plain words, in `lang`.
    pub fn said(self, lang: Lang) -> &'static str {
        let [en, hu] = match self {
            Verdict::WorthIt => [
                "worth it (not seen, faster)",
                "megéri (nem látható, gyorsabb)",
            ],
            Verdict::Unseen => ["not seen, no faster", "nem látható, nem gyorsabb"],
            Verdict::Trade => ["faster, seen", "gyorsabb, látható"],
            Verdict::Worse => ["seen, no faster", "látható, nem gyorsabb"],
        };
        lang.pick(en, hu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule at its edges: ΔE p99 1 is not seen, 1.01 is; 0.9× the
    /// time is faster, 0.91× is not; a NaN ΔE is seen.
    #[test]
    fn a_shortcut_is_worth_it_when_not_seen_and_faster() {
        assert_eq!(Verdict::of(1.0, 0.9, 1.0), Verdict::WorthIt);
        assert_eq!(Verdict::of(1.0, 0.91, 1.0), Verdict::Unseen);
        assert_eq!(Verdict::of(1.01, 0.5, 1.0), Verdict::Trade);
        assert_eq!(Verdict::of(5.0, 2.0, 1.0), Verdict::Worse);
        assert_eq!(Verdict::of(f64::NAN, 0.5, 1.0), Verdict::Trade);
    }
}
