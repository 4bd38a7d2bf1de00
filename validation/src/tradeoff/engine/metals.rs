//! RGB against a spectrum for a scene's metals, until the tracer has a
//! spectral mode: each conductor's three-channel `n, κ` held to the
//! measured spectrum of the metal of its name, by the harness's code and
//! reference (`optics validate`'s `metals.*`,
//! [`crate::metals::three_channel_delta_e`]).

use crate::checkout::Checkout;
use crate::metals::{three_channel_delta_e, MetalLaws, MetalsReference};
use crate::tradeoff::findings::{MetalRgb, RgbOutcome};
use tracer::scene::{Material, Scene};

/// Each conductor of `scene`, in the scene's order, with its colour error
/// or why there is none (the reference read from `checkout`, or why there
/// is no checkout); nothing for a scene without metals.
pub fn rgb_against_spectrum(scene: &Scene, checkout: Result<&Checkout, &str>) -> Vec<MetalRgb> {
    let conductors: Vec<(&str, [f32; 3], [f32; 3])> = scene
        .materials
        .iter()
        .zip(&scene.material_names)
        .filter_map(|(material, name)| match material {
            Material::Conductor { n, kappa, .. } => Some((name.as_str(), *n, *kappa)),
            _ => None,
        })
        .collect();
    if conductors.is_empty() {
        return Vec::new();
    }
    let reference = checkout
        .map_err(str::to_owned)
        .and_then(|c| MetalsReference::load(&c.reference_dir()).map_err(|e| e.to_string()));
    let laws = MetalLaws::radiometry();
    conductors
        .into_iter()
        .map(|(name, n, kappa)| {
            let outcome = match &reference {
                Err(detail) => RgbOutcome::NoReference {
                    detail: detail.clone(),
                },
                Ok(reference) => reference
                    .metals
                    .iter()
                    .find(|m| m.name == name)
                    .and_then(|metal| {
                        three_channel_delta_e(&laws, metal, n.map(f64::from), kappa.map(f64::from))
                    })
                    .map_or(RgbOutcome::NoSpectrum, |pairs| RgbOutcome::Measured {
                        angles_deg: pairs.iter().map(|p| p.0).collect(),
                        delta_e: pairs.iter().map(|p| p.1).collect(),
                    }),
            };
            MetalRgb {
                material: name.to_owned(),
                outcome,
            }
        })
        .collect()
}
