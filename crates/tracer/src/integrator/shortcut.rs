//! A slide's shortcut at glass in place of a law (`Settings::glass_shortcut`),
//! so that the harness can render it beside the traced truth: the side,
//! the indices and whether Snell's law transmits stay the law's decision,
//! handed in from [`super::scatter`]; only the direction or the
//! reflectance the shortcut stands in for is replaced, by the technique's
//! own function (`techniques`), never a copy of it.

use radiometry::course::refract_001_approx;
use radiometry::snell::Incidence;
use radiometry::{Real, Vector3};
use techniques::empirical_fresnel;

use super::tracer::Tracer;
use crate::scene::GlassShortcut;

impl<V: Vector3> Tracer<'_, V> {
    /// The refracted direction: `exact` (Snell's, for `wo` at the shading
    /// normal `n` and the decided `incidence`), or the cheap form's in its
    /// place.
    pub(super) fn refracted_direction(
        &self,
        wo: V,
        n: V,
        incidence: &Incidence<V::Scalar>,
        exact: V,
    ) -> V {
        let GlassShortcut::CheapRefraction(constant) = self.settings.glass_shortcut else {
            return exact;
        };
        // As the slides apply it: the direction of travel and the normal
        // facing the light (`techniques::refraction::compare`).
        let facing = if incidence.from_inside { -n } else { n };
        let c = V::Scalar::lit(constant.value(incidence.eta_path().into()));
        refract_001_approx(-wo, facing, c)
    }

    /// The empirical form's reflectance where it stands in for the law's:
    /// light from outside the glass that Snell's law transmits; `None`
    /// elsewhere, where the chosen law decides.
    pub(super) fn shortcut_reflectance(
        &self,
        incidence: &Incidence<V::Scalar>,
    ) -> Option<V::Scalar> {
        let GlassShortcut::EmpiricalFresnel(form) = self.settings.glass_shortcut else {
            return None;
        };
        if incidence.from_inside || incidence.cos_transmitted().is_none() {
            return None;
        }
        let cos_i: f64 = incidence.abs_cos_i.into();
        Some(V::Scalar::lit(empirical_fresnel::reflectance(&form, cos_i)))
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3;
    use radiometry::course::{refract_001_approx, EmpiricalFresnel};
    use radiometry::specular;
    use techniques::empirical_fresnel;
    use techniques::refraction::Constant;

    use crate::geometry::Ray;
    use crate::integrator::{Machinery, Tracer};
    use crate::scene::{self, GlassShortcut, Material, Settings};

    /// A glass hit's lobes under each shortcut carry exactly the bits of the
    /// technique's own function at the law's decided incidence, from both
    /// sides, and the rest of the exact law's bits: the cheap refraction
    /// changes only the refracted direction (entering and leaving), the
    /// empirical form only `R` and `T` from outside; total internal
    /// reflection stays the law's.
    #[test]
    fn a_glass_shortcut_replaces_only_what_it_stands_in_for() {
        let scene = scene::parse(
            r#"{ "version": 1, "image": { "width": 4, "height": 4 },
                 "camera": { "type": "course_pinhole" },
                 "materials": { "glass": { "type": "dielectric", "eta": 1.5 } },
                 "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass" } ] }"#,
        )
        .unwrap();
        let (eta, glass) = (1.5_f32, Material::Dielectric { eta: 1.5 });
        let form = EmpiricalFresnel {
            bias: 0.05,
            scale: 0.9,
            power: 4.9,
        };
        let exact = Settings::default();
        let cheap = Settings {
            glass_shortcut: GlassShortcut::CheapRefraction(Constant::FirstOrder),
            ..exact
        };
        let empirical = Settings {
            glass_shortcut: GlassShortcut::EmpiricalFresnel(form),
            ..exact
        };
        let tracer = |s: &Settings| Tracer::new(&scene, *s, Machinery::everything(&scene, s));
        let (t_exact, t_cheap, t_empirical) = (tracer(&exact), tracer(&cheap), tracer(&empirical));
        let (mut from_inside, mut tir) = (0, 0);
        for i in 0..400 {
            let u = (i % 20) as f32 / 20.0 - 0.5;
            let v = (i / 20) as f32 / 20.0 - 0.5;
            // From outside, from near the centre outwards, and straight
            // along z from off the axis inside (grazing: total reflection).
            let (origin, target) = if i % 2 == 0 {
                (Vec3::new(0.0, 0.0, -3.0), Vec3::new(u * 2.0, v * 2.0, 0.0))
            } else if i % 4 == 3 {
                let o = Vec3::new(u * 1.9, v * 0.3, 0.0);
                (o, o + Vec3::Z)
            } else {
                (Vec3::new(u * 0.9, v * 0.9, 0.0), Vec3::new(u, v + 0.3, 1.0))
            };
            let ray = Ray::new(origin, (target - origin).normalize());
            let Some(hit) = t_exact.intersect(&ray) else {
                continue;
            };
            let (wo, n) = (-ray.direction, hit.shading_normal(ray.direction));
            let at = specular::incidence(wo, n, eta).expect("a valid interface");
            let base = t_exact.lobes(&hit, n, wo, &glass);
            let c = t_cheap.lobes(&hit, n, wo, &glass);
            let e = t_empirical.lobes(&hit, n, wo, &glass);
            assert_eq!(c.reflection, base.reflection, "{i}");
            let Some((exact_lobe, r)) = base.refraction else {
                assert!(c.refraction.is_none() && e.refraction.is_none(), "{i}");
                assert_eq!(e.reflection, base.reflection, "{i}");
                tir += 1;
                continue;
            };
            let (cheap_lobe, cheap_r) = c.refraction.expect("the law transmits");
            let facing = if at.from_inside { -n } else { n };
            let bent = refract_001_approx(-wo, facing, at.eta_path() - 1.0);
            assert_eq!(cheap_lobe.ray.direction, bent, "{i}");
            assert_eq!(cheap_lobe.ray.origin, exact_lobe.ray.origin, "{i}");
            assert_eq!((cheap_lobe.weight, cheap_r), (exact_lobe.weight, r), "{i}");
            let (_, empirical_r) = e.refraction.expect("the law transmits");
            if at.from_inside {
                from_inside += 1;
                assert_eq!(e, base, "{i}");
            } else {
                let fitted = empirical_fresnel::reflectance(&form, f64::from(at.abs_cos_i)) as f32;
                assert_eq!(empirical_r, fitted, "{i}");
                assert_eq!(e.reflection.weight, Vec3::splat(fitted), "{i}");
            }
        }
        assert!(
            from_inside > 50 && tir > 0,
            "{from_inside} inside, {tir} reflected"
        );
    }
}
