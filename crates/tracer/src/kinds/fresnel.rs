//! Which Fresnel law, by name: the models, and the bare `schlick` that
//! names neither of Schlick's two forms and is refused where it is settled.

use std::fmt;

use serde::{Deserialize, Serialize};

/// Which Fresnel law: the smooth materials' in a render, and the law
/// `optics fresnel --model` evaluates (exact by default in both). Schlick's
/// approximation comes in two forms, each named by the cosine it takes at
/// a dielectric; at a conductor, lit from outside, both take `cos θ_i`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum FresnelModel {
    /// The exact equations (`radiometry::fresnel::conductor_rgb`, `dielectric`).
    #[cfg_attr(feature = "clap", value(help = "The exact Fresnel equations"))]
    #[default]
    Exact,
    /// Schlick's approximation with the cosine of incidence from either
    /// side, as the course and most renderers write it: it misses total
    /// internal reflection (`radiometry::fresnel::schlick_rgb`,
    /// `schlick_dielectric_incident`).
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Schlick's approximation at cos θi, as the course writes it: misses total internal reflection"
        )
    )]
    SchlickIncident,
    /// Schlick's approximation with the cosine in the rarer medium, `cos θ_t`
    /// from the denser side, as Schlick states it: total internal
    /// reflection right (`radiometry::fresnel::schlick_rgb`,
    /// `schlick_dielectric`).
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Schlick's approximation at the rarer medium's cosine: total internal reflection right"
        )
    )]
    SchlickRarer,
    /// The course shader's reversed form, `F0 + (1 − F0) cos⁵θ`
    /// (`radiometry::course::fresnel_000_glsl`): isolates that one erratum
    /// in an otherwise physical render.
    #[cfg_attr(
        feature = "clap",
        value(help = "The course shader's reversed form, for measuring that erratum alone")
    )]
    Course,
}

impl FresnelModel {
    /// Schlick's two forms, the hint where the bare name is refused.
    pub const SCHLICK_FORMS: [FresnelModel; 2] =
        [FresnelModel::SchlickIncident, FresnelModel::SchlickRarer];
}

impl fmt::Display for FresnelModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FresnelModel::Exact => "exact",
            FresnelModel::SchlickIncident => "schlick-incident",
            FresnelModel::SchlickRarer => "schlick-rarer",
            FresnelModel::Course => "course",
        })
    }
}

/// A Fresnel law as a scene file, a flag or a request names it: a model,
/// or the bare `schlick`, which named one form in some places and the other
/// elsewhere before the two were told apart. It is read, so that whoever
/// settles the name refuses it naming the field and both forms, rather
/// than any input silently changing meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FresnelName {
    /// One of the models.
    Model(FresnelModel),
    /// `schlick`, which names no form.
    UnnamedSchlick,
}

impl FresnelName {
    /// The bare name refused.
    pub const UNNAMED_SCHLICK: &'static str = "schlick";

    /// The model named; `None` for the bare `schlick`.
    pub fn model(self) -> Option<FresnelModel> {
        match self {
            FresnelName::Model(model) => Some(model),
            FresnelName::UnnamedSchlick => None,
        }
    }
}

impl Default for FresnelName {
    fn default() -> Self {
        FresnelName::Model(FresnelModel::default())
    }
}

impl From<FresnelModel> for FresnelName {
    fn from(model: FresnelModel) -> Self {
        FresnelName::Model(model)
    }
}

impl fmt::Display for FresnelName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FresnelName::Model(model) => model.fmt(f),
            FresnelName::UnnamedSchlick => f.write_str(Self::UNNAMED_SCHLICK),
        }
    }
}

impl Serialize for FresnelName {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for FresnelName {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Name;
        impl serde::de::Visitor<'_> for Name {
            type Value = FresnelName;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("the name of a Fresnel model")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<FresnelName, E> {
                if name == FresnelName::UNNAMED_SCHLICK {
                    return Ok(FresnelName::UnnamedSchlick);
                }
                let name = serde::de::value::StrDeserializer::<E>::new(name);
                FresnelModel::deserialize(name).map(FresnelName::Model)
            }
        }
        deserializer.deserialize_str(Name)
    }
}

#[cfg(feature = "clap")]
impl clap::ValueEnum for FresnelName {
    fn value_variants<'a>() -> &'a [Self] {
        static NAMES: std::sync::LazyLock<Vec<FresnelName>> = std::sync::LazyLock::new(|| {
            let models = FresnelModel::value_variants().iter().copied();
            models
                .map(FresnelName::Model)
                .chain([FresnelName::UnnamedSchlick])
                .collect()
        });
        &NAMES
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        match self {
            FresnelName::Model(model) => model.to_possible_value(),
            // Read, to be refused with the forms named; not offered.
            FresnelName::UnnamedSchlick => {
                Some(clap::builder::PossibleValue::new(Self::UNNAMED_SCHLICK).hide(true))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every model reads back from the name it is written as, in JSON, and
    /// the bare `schlick` reads as itself, never as a model.
    #[test]
    fn each_name_reads_as_what_it_names() {
        use FresnelModel::*;
        for model in [Exact, SchlickIncident, SchlickRarer, Course] {
            let json = serde_json::to_string(&model).unwrap();
            assert_eq!(json, format!("\"{model}\""));
            let name: FresnelName = serde_json::from_str(&json).unwrap();
            assert_eq!(name.model(), Some(model));
        }
        let bare: FresnelName = serde_json::from_str("\"schlick\"").unwrap();
        assert_eq!(bare, FresnelName::UnnamedSchlick);
        assert!(serde_json::from_str::<FresnelName>("\"schlik\"").is_err());
        assert!(serde_json::from_str::<FresnelModel>("\"schlick\"").is_err());
    }
}
