//! The failures of the `harness` feature's commands in both languages:
//! one exhaustive `match` over [`HarnessKind`], each family's own text in
//! its own file.

use record::{say, Lang};

use crate::error::harness::CHECKOUT_FLAG;
use crate::error::HarnessKind;

use super::budget::budget;
use super::checkout::checkout;
use super::compare::compare;
use super::jobs::jobs;
use super::pipeline::{pipeline, tool};

impl HarnessKind {
    /// The failure's message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            HarnessKind::Checkout(error) => checkout(error, None, lang),
            HarnessKind::CheckoutWithFlag(error) => checkout(error, Some(CHECKOUT_FLAG), lang),
            HarnessKind::Pipeline(error) => pipeline(error, lang),
            HarnessKind::ChecksFailed { failed, checks } => say!(
                lang,
                "{failed} of {checks} checks failed",
                "{checks} ellenőrzésből {failed} sikertelen"
            ),
            HarnessKind::Compare(error) => compare(error, lang),
            HarnessKind::TruthIsBlack { file } => say!(
                lang,
                "SCENE {}: its physical render is black: no light reaches the camera (a scene without lights shows only the course's ambient term), so there is no light transport to trade",
                "SCENE {}: fizikai képe fekete: semmi fény nem jut a kamerába (fényforrás nélküli jelenetben csak a kurzus ambiens tagja látszik), így nincs mit fényterjedésben elcserélni",
                file.display()
            ),
            HarnessKind::NoPlotPython { python } => say!(
                lang,
                "the Pareto plot needs the checkout's Python environment and there is none at {} (`optics validate` creates it once; --no-plot skips the plot): nothing was written",
                "a Pareto-ábrához a munkapéldány Python-környezete kell, de a(z) {} nem létezik (az `optics validate` egyszer létrehozza; a --no-plot kihagyja az ábrát): semmi sem íródott ki",
                python.display()
            ),
            HarnessKind::Plot(error) => say!(
                lang,
                "the Pareto plot cannot be drawn, so nothing was written (--no-plot skips it): {}",
                "a Pareto-ábra nem rajzolható, így semmi sem íródott ki (a --no-plot kihagyja): {}",
                tool(error, lang)
            ),
            HarnessKind::Budget(error) => budget(error, lang),
            HarnessKind::Jobs(error) => jobs(error, lang),
        }
    }
}
