//! What the tracer's needs analysis found, in the chosen language: the kinds
//! of light and why a light is skipped. Each is an exhaustive `match` over
//! the tracer's enums, so a new kind or reason has no English-only text.

use tracer::chains::Chain;
use tracer::needs::{LightKind, Unused};
use tracer::scene::{Material, Scene};

use record::Lang;

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

/// A material's kind, as a chain names it.
pub fn material_kind(material: &Material, lang: Lang) -> &'static str {
    match (material, lang) {
        (Material::Flat { .. }, Lang::En) => "flat",
        (Material::NormalColour, Lang::En) => "normal_colour",
        (Material::CourseRough { .. }, Lang::En) => "course_rough",
        (Material::Lambert { .. }, Lang::En) => "lambert",
        (Material::Conductor { .. }, Lang::En) => "conductor",
        (Material::Dielectric { .. }, Lang::En) => "dielectric",
        (Material::Flat { .. }, Lang::Hu) => "egyszínű",
        (Material::NormalColour, Lang::Hu) => "normálszín",
        (Material::CourseRough { .. }, Lang::Hu) => "érdes (a kurzusé)",
        (Material::Lambert { .. }, Lang::Hu) => "Lambert-féle",
        (Material::Conductor { .. }, Lang::Hu) => "vezető",
        (Material::Dielectric { .. }, Lang::Hu) => "üveg",
    }
}

/// A chain as `point light 0 → conductor 'gold' → lambert 'floor'`.
pub fn chain(chain: &Chain, scene: &Scene, lang: Lang) -> String {
    let light = match lang {
        Lang::En => format!("{} light {}", light_kind(chain.kind, lang), chain.light),
        Lang::Hu => format!("{} {}", chain.light, light_kind(chain.kind, lang)),
    };
    let surface = |m: usize| {
        format!(
            "{} '{}'",
            material_kind(&scene.materials[m], lang),
            scene.material_names[m]
        )
    };
    std::iter::once(light)
        .chain(chain.via.iter().map(|&m| surface(m)))
        .chain(std::iter::once(surface(chain.to)))
        .collect::<Vec<_>>()
        .join(" → ")
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
