//! Each physical decision is made once and handed on: the side of the
//! interface by `Incidence::resolve`, whether light is transmitted and at
//! which `cos θ_t` by `Incidence::cos_transmitted`, which cosine Schlick
//! takes by `schlick_dielectric_resolved`. What a law returns of those
//! decisions must be the decision itself, bit for bit, so a caller that
//! narrates or refracts from it (the `optics` calculator, the tracer) gets
//! the same numbers as the law it would otherwise call again.

use glam::{DVec3, Vec3};
use num_traits::ToPrimitive;
use proptest::prelude::*;
use radiometry::fresnel::{
    dielectric_polarized, dielectric_resolved, f0, schlick, schlick_dielectric,
    schlick_dielectric_resolved, schlick_dielectric_working, SchlickCosine,
};
use radiometry::snell::{cos_transmitted, Incidence};
use radiometry::specular::{incidence, refract, Refraction};
use radiometry::Vector3;

mod common;
use common::strategies::{relative_index_with_extremes, signed_cosine, unit_direction};

/// An optional refraction as bits, so that `-0.0` and `0.0` differ and NaN
/// equals itself.
fn bits<V: Vector3>(t: Option<Refraction<V>>) -> Option<([u64; 3], u64, u64)> {
    let wide = |x: V::Scalar| x.to_f64().map_or(u64::MAX, f64::to_bits);
    t.map(|t| {
        (
            t.direction.to_array().map(wide),
            wide(t.eta_path),
            wide(t.cos_t),
        )
    })
}

fn cos_bits(c: Option<f64>) -> Option<u64> {
    c.map(f64::to_bits)
}

/// Refraction from a Fresnel law's decision is `refract`'s, in one tier.
fn refraction_agrees<V: Vector3>(wi: V, n: V, eta: V::Scalar) -> Result<(), TestCaseError> {
    let direct = bits(refract(wi, n, eta));
    let at = incidence(wi, n, eta).expect("a valid interface");
    let exact = dielectric_resolved(&at);
    prop_assert_eq!(
        bits(exact.refraction(wi, n)),
        direct,
        "exact law at {:?}",
        wi
    );
    let working = schlick_dielectric_resolved(&at);
    prop_assert_eq!(
        bits(working.refraction(wi, n)),
        direct,
        "Schlick at {:?}",
        wi
    );
    Ok(())
}

/// An index that is sometimes exactly 1 (index-matched), besides the
/// shared distribution.
fn index_or_matched() -> impl Strategy<Value = f64> {
    prop_oneof![9 => relative_index_with_extremes(), 1 => Just(1.0)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    /// The exact law's `incidence` is `Incidence::resolve`'s, its `cos_t`
    /// is `Incidence::cos_transmitted`'s and its `eta_path` the incidence's,
    /// and the law at a resolved incidence is the law: exact equality, since
    /// one computation is handed on, not repeated.
    #[test]
    fn dielectric_fresnel_hands_back_the_incidence_and_cosine_it_decided(
        cos_i in signed_cosine(),
        eta in index_or_matched(),
    ) {
        let incidence = Incidence::resolve(cos_i, eta).expect("a valid interface");
        let f = dielectric_polarized(cos_i, eta);
        prop_assert_eq!(f.incidence, incidence);
        prop_assert_eq!(cos_bits(f.cos_t), cos_bits(cos_transmitted(cos_i, eta)));
        prop_assert_eq!(f.eta_path().to_bits(), incidence.eta_path().to_bits());
        prop_assert_eq!(dielectric_resolved(&incidence), f);
    }

    /// Schlick's working is `schlick_dielectric` bit for bit, says the
    /// cosine it took, and took the one in the rarer medium: `|cos θ_i|`
    /// entering a denser (or equal) medium, `cos θ_t` leaving one, and
    /// `R = 1` exactly under total internal reflection. Its `cos_t()` is
    /// Snell's, its `F0` the law's: exact equality throughout.
    #[test]
    fn schlick_working_is_the_law_and_names_the_cosine_it_took(
        cos_i in signed_cosine(),
        eta in index_or_matched(),
    ) {
        let working = schlick_dielectric_working(cos_i, eta).expect("a valid interface");
        let incidence = Incidence::resolve(cos_i, eta).expect("a valid interface");
        prop_assert_eq!(working, schlick_dielectric_resolved(&incidence));
        prop_assert_eq!(working.incidence, incidence);
        prop_assert_eq!(working.reflectance.to_bits(), schlick_dielectric(cos_i, eta).to_bits());
        prop_assert_eq!(cos_bits(working.cos_t()), cos_bits(cos_transmitted(cos_i, eta)));
        prop_assert_eq!(working.f0.to_bits(), f0(eta, 0.0).to_bits());
        let (expected_cosine, expected_r) = if incidence.n_t >= incidence.n_i {
            (SchlickCosine::Incident, schlick(incidence.abs_cos_i, working.f0))
        } else {
            match cos_transmitted(cos_i, eta) {
                Some(cos_t) => (SchlickCosine::Transmitted(cos_t), schlick(cos_t, working.f0)),
                None => (SchlickCosine::TotalInternalReflection, 1.0),
            }
        };
        prop_assert_eq!(working.cosine, expected_cosine);
        prop_assert_eq!(working.reflectance.to_bits(), expected_r.to_bits());
        let used = working.cosine_used().map(|c| schlick(c, working.f0));
        prop_assert_eq!(used.unwrap_or(1.0).to_bits(), expected_r.to_bits());
    }

    /// A refraction built from a Fresnel law's decision at the incidence
    /// `specular::incidence` resolved from the vectors
    /// (`DielectricFresnel::refraction`, `SchlickDielectric::refraction`,
    /// both through `refract_resolved`) is `refract`'s, bit for bit, in both
    /// tiers, total internal reflection included.
    #[test]
    fn refraction_from_the_decision_is_refract_bit_for_bit(
        wi in unit_direction(),
        n in unit_direction(),
        eta in index_or_matched(),
    ) {
        refraction_agrees::<DVec3>(wi, n, eta)?;
        let narrow = |v: DVec3| v.as_vec3();
        refraction_agrees::<Vec3>(narrow(wi), narrow(n), eta as f32)?;
    }
}

/// The decisions at the textbook cases: glass from inside at 60° is
/// totally reflected (Schlick says so and uses no cosine), at normal
/// incidence Schlick takes `cos θ_t = 1`, and entering glass the incident
/// cosine.
#[test]
fn schlick_names_its_cosine_at_the_textbook_cases() {
    let cases = [
        (-0.5, SchlickCosine::TotalInternalReflection, None),
        (-1.0, SchlickCosine::Transmitted(1.0), Some(1.0)),
        (0.5, SchlickCosine::Incident, Some(0.5)),
    ];
    for (cos_i, cosine, used) in cases {
        let working = schlick_dielectric_working(cos_i, 1.5_f64).unwrap();
        assert_eq!(
            (working.cosine, working.cosine_used()),
            (cosine, used),
            "cos_i {cos_i}"
        );
    }
    assert_eq!(schlick_dielectric_working(0.5, f64::NAN), None);
    assert!(schlick_dielectric(0.5, -1.5_f64).is_nan());
    let undefined = dielectric_polarized(f64::NAN, 1.5);
    assert!(undefined.incidence.n_i.is_nan() && undefined.eta_path().is_nan());
}
