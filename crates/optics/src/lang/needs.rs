//! What the tracer's needs analysis found, in the chosen language: the kinds
//! of light and why a light is skipped. Each is an exhaustive `match` over
//! the tracer's enums, so a new kind or reason has no English-only text.

use tracer::needs::{LightKind, Unused};

use super::Lang;

/// A light's kind, as `inspect` and `render` name it.
pub fn light_kind(kind: LightKind, lang: Lang) -> &'static str {
    match (kind, lang) {
        (_, Lang::En) => match kind {
            LightKind::Directional => "directional",
            LightKind::Point => "point",
        },
        (LightKind::Directional, Lang::Hu) => "irányfény",
        (LightKind::Point, Lang::Hu) => "pontfény",
    }
}

/// Why a light lights nothing in the scene.
pub fn unused(reason: Unused, lang: Lang) -> &'static str {
    match (reason, lang) {
        (_, Lang::En) => match reason {
            Unused::EmitsNothing => "it emits nothing",
            Unused::NothingShaded => "no surface is shaded from lights",
            Unused::OutsideClosedTube => {
                "the closed mirror tube around the camera keeps its light out"
            }
        },
        (Unused::EmitsNothing, Lang::Hu) => "nem sugároz semmit",
        (Unused::NothingShaded, Lang::Hu) => "egyetlen felületet sem árnyalnak fények",
        (Unused::OutsideClosedTube, Lang::Hu) => {
            "a kamerát körülvevő zárt tükörcső kívül tartja a fényét"
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn english_is_the_tracers_own_text() {
        for kind in [LightKind::Directional, LightKind::Point] {
            assert_eq!(light_kind(kind, Lang::En), kind.to_string());
        }
        for reason in [
            Unused::EmitsNothing,
            Unused::NothingShaded,
            Unused::OutsideClosedTube,
        ] {
            assert_eq!(unused(reason, Lang::En), reason.to_string());
            assert_ne!(unused(reason, Lang::Hu), unused(reason, Lang::En));
        }
    }
}
