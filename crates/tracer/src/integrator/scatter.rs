//! The shared scatter step: what a hit's material does with light, asked
//! once per hit by every physical integrator (as pbrt's and tray_rust's
//! integrators ask the BSDF) instead of each matching on the material.
//!
//! A material is unlit (it shows a radiance), rough (lit by the lights, see
//! [`super::direct`]) or smooth; a smooth one hands over its [`Lobes`]: the
//! mirror lobe and, through a dielectric, the refracted one, each with its
//! ray and its weight. The side of the surface, the Fresnel law and the
//! radiance carried across the interface are decided here, once.

use glam::Vec3;
use radiometry::snell::Incidence;
use radiometry::{course, fresnel, radiance, specular, Real, Vector3};

use super::counts::Bounce;
use super::tracer::Tracer;
use crate::geometry::{Hit, Ray};
use crate::scene::faults::Fault;
use crate::scene::{FresnelModel, Material};
use crate::spawn;

/// What a surface does with the light that reaches it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface<V: Vector3 = Vec3> {
    /// Unlit: it shows this radiance, whatever lights it.
    Shows(V),
    /// Rough: shaded from the lights and the ambient term by its BRDF.
    Rough,
    /// Smooth: light leaves only along its [`Lobes`].
    Smooth,
}

impl<V: Vector3> Material<V> {
    /// What this material does with light at `hit`.
    pub fn surface(&self, hit: &Hit<V>) -> Surface<V> {
        match *self {
            Material::Flat { radiance } => Surface::Shows(radiance),
            Material::NormalColour => {
                let half = V::Scalar::lit(0.5);
                Surface::Shows(hit.shading * half + V::splat(half))
            }
            Material::CourseRough { .. } | Material::Lambert { .. } => Surface::Rough,
            Material::Conductor { .. } | Material::Dielectric { .. } => Surface::Smooth,
        }
    }
}

/// One way light leaves a smooth surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lobe<V: Vector3 = Vec3> {
    /// Its kind.
    pub bounce: Bounce,
    /// The secondary ray, started off the surface on the side it travels into.
    pub ray: Ray<V>,
    /// Radiance arriving along the ray times this is the radiance it
    /// carries back along the incident ray, per channel.
    pub weight: V,
    /// The fraction of the power arriving along the incident ray that
    /// leaves along this one, per channel: `R`, or through a dielectric
    /// `T` without the radiance's `1/η²` (the beam's solid angle changes,
    /// its power does not; Veach's thesis §5.2). A photon carries this.
    pub power: V,
}

/// The lobes of a smooth surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lobes<V: Vector3 = Vec3> {
    /// The mirror lobe, weighted by the Fresnel reflectance.
    pub reflection: Lobe<V>,
    /// Through a dielectric, the refracted lobe (weighted by the
    /// transmittance and the radiance's `1/η²`) and the reflectance `R`
    /// that splits the light between the two; `None` at a conductor and
    /// under total internal reflection.
    pub refraction: Option<(Lobe<V>, V::Scalar)>,
}

impl<V: Vector3> Tracer<'_, V> {
    /// The lobes of the smooth material at `hit`, seen along `wo` (towards
    /// the viewer) with `n` the hit's shading normal.
    pub(crate) fn lobes(&self, hit: &Hit<V>, n: V, wo: V, material: &Material<V>) -> Lobes<V> {
        match *material {
            Material::Dielectric { eta } => self.dielectric_lobes(hit, n, wo, eta),
            Material::Conductor {
                n: eta,
                kappa,
                ref exact,
            } => {
                let (ray, cos_i) = self.mirror_ray(hit, n, wo);
                let weight = self.conductor_fresnel(cos_i, eta, kappa, exact);
                Lobes {
                    reflection: mirror(ray, weight),
                    refraction: None,
                }
            }
            _ => unreachable!("only smooth materials have lobes"),
        }
    }

    /// A conductor's mirror lobe without its weight, the two halves of
    /// [`Tracer::lobes`] there for a caller that needs the weight later or
    /// not at all: the reflected ray, and the cosine that
    /// [`Tracer::conductor_weight`] takes. `None` for any other material.
    pub(crate) fn conductor_mirror(
        &self,
        hit: &Hit<V>,
        n: V,
        wo: V,
        material: &Material<V>,
    ) -> Option<(Ray<V>, V::Scalar)> {
        match material {
            Material::Conductor { .. } => Some(self.mirror_ray(hit, n, wo)),
            _ => None,
        }
    }

    /// A conductor's mirror-lobe weight at `cos_i` (from
    /// [`Tracer::conductor_mirror`]): the bits [`Tracer::lobes`] gives.
    pub(crate) fn conductor_weight(&self, cos_i: V::Scalar, material: &Material<V>) -> V {
        match *material {
            Material::Conductor {
                n: eta,
                kappa,
                ref exact,
            } => self.conductor_fresnel(cos_i, eta, kappa, exact),
            _ => unreachable!("only a conductor has a conductor's weight"),
        }
    }

    /// The mirror ray off the side of `n` that `wo` is on, and `cos θi`
    /// there.
    fn mirror_ray(&self, hit: &Hit<V>, n: V, wo: V) -> (Ray<V>, V::Scalar) {
        let facing = if n.dot(wo) < V::Scalar::lit(0.0) {
            -n
        } else {
            n
        };
        let ray = Ray::new(
            spawn::origin(hit, facing, self.settings.ray_offset),
            specular::reflect(wo, facing),
        );
        (ray, facing.dot(wo))
    }

    fn dielectric_lobes(&self, hit: &Hit<V>, n: V, wo: V, eta: V::Scalar) -> Lobes<V> {
        let interface = self.dielectric(specular::incidence(wo, n, eta), eta);
        let outward = if interface.incidence.from_inside {
            -n
        } else {
            n
        };
        let reflected = Ray::new(
            spawn::origin(hit, outward, self.settings.ray_offset),
            specular::reflect(wo, n),
        );
        let reflectance = interface.reflectance;
        let refraction = interface.cos_t.map(|cos_t| {
            let t = specular::refract_resolved(wo, n, &interface.incidence, cos_t);
            let lobe = Lobe {
                bounce: Bounce::Refraction,
                ray: Ray::new(
                    spawn::origin(hit, -outward, self.settings.ray_offset),
                    self.refracted_direction(wo, n, &interface.incidence, t.direction),
                ),
                weight: V::splat(self.across_interface(interface.transmittance, t.eta_path)),
                power: V::splat(interface.transmittance),
            };
            (lobe, reflectance)
        });
        Lobes {
            reflection: mirror(reflected, V::splat(reflectance)),
            refraction,
        }
    }

    /// The radiance carried across the interface per unit arriving,
    /// `T/η²` (`radiance::across_interface`); `T` alone with that law
    /// planted out (`Fault::RadianceNotScaledAcrossInterfaces`).
    fn across_interface(&self, transmitted: V::Scalar, eta_path: V::Scalar) -> V::Scalar {
        if matches!(self.fault, Some(Fault::RadianceNotScaledAcrossInterfaces)) {
            return transmitted;
        }
        radiance::across_interface(transmitted, eta_path)
    }

    /// Conductor reflectance per channel at `cos_i`, by the chosen law.
    fn conductor_fresnel(
        &self,
        cos_i: V::Scalar,
        n: [V::Scalar; 3],
        kappa: [V::Scalar; 3],
        exact: &[fresnel::Conductor<V::Scalar>; 3],
    ) -> V {
        let [r, g, b] = match self.settings.fresnel {
            // Written out rather than mapped: the three channels inline side
            // by side, where the compiler evaluates them together.
            FresnelModel::Exact => [
                exact[0].reflectance(cos_i),
                exact[1].reflectance(cos_i),
                exact[2].reflectance(cos_i),
            ],
            // Lit from outside, both forms take cos θi.
            FresnelModel::SchlickIncident | FresnelModel::SchlickRarer => {
                fresnel::schlick_rgb(cos_i, fresnel::f0_rgb(n, kappa))
            }
            FresnelModel::Course => {
                let f0 = fresnel::f0_rgb(n, kappa);
                core::array::from_fn(|c| course::fresnel_000_glsl(f0[c], cos_i))
            }
        };
        V::new(r, g, b)
    }

    /// A dielectric interface met at `incidence` (resolved once, from the
    /// directions, by [`specular::incidence`]), evaluated by the chosen
    /// law: `cos θ_t` the law decided, and its reflectance and
    /// transmittance, for the scene's `eta`. `None` in is input that
    /// describes no interface (a NaN direction).
    fn dielectric(
        &self,
        incidence: Option<Incidence<V::Scalar>>,
        eta: V::Scalar,
    ) -> Interface<V::Scalar> {
        let Some(incidence) = incidence else {
            return Interface::undefined();
        };
        let one = V::Scalar::lit(1.0);
        if let Some(r) = self.shortcut_reflectance(&incidence) {
            return Interface::new(incidence, incidence.cos_transmitted(), r, one - r);
        }
        match self.settings.fresnel {
            FresnelModel::Exact => {
                let f = fresnel::dielectric_resolved(&incidence);
                Interface::new(f.incidence, f.cos_t, f.reflectance(), f.transmittance())
            }
            FresnelModel::SchlickRarer => {
                let w = fresnel::schlick_dielectric_resolved(&incidence);
                Interface::new(w.incidence, w.cos_t(), w.reflectance, w.transmittance())
            }
            // Past the critical angle its R < 1 and no refracted lobe: the
            // rest of the light is lost, the form's error.
            FresnelModel::SchlickIncident => {
                let w = fresnel::schlick_dielectric_incident_resolved(&incidence);
                Interface::new(w.incidence, w.cos_t(), w.reflectance, w.transmittance())
            }
            // The course has no glass; its formula with the incident cosine.
            FresnelModel::Course => {
                let f0 = fresnel::f0(eta, V::Scalar::lit(0.0));
                let r = course::fresnel_000_glsl(f0, incidence.abs_cos_i);
                Interface::new(incidence, incidence.cos_transmitted(), r, one - r)
            }
        }
    }
}

/// A dielectric interface as a Fresnel law resolved it.
struct Interface<T: Real> {
    /// The side, the indices and `|cos θ_i|`.
    incidence: Incidence<T>,
    /// `cos θ_t`, or `None` under total internal reflection.
    cos_t: Option<T>,
    /// The fraction reflected.
    reflectance: T,
    /// The fraction transmitted.
    transmittance: T,
}

impl<T: Real> Interface<T> {
    fn new(incidence: Incidence<T>, cos_t: Option<T>, reflectance: T, transmittance: T) -> Self {
        Interface {
            incidence,
            cos_t,
            reflectance,
            transmittance,
        }
    }

    /// Input that describes no interface (a NaN cosine): NaN weights and no
    /// refracted lobe, as the laws return.
    fn undefined() -> Self {
        let incidence = Incidence {
            abs_cos_i: T::nan(),
            n_i: T::nan(),
            n_t: T::nan(),
            from_inside: false,
            sin_i: None,
        };
        Interface::new(incidence, None, T::nan(), T::nan())
    }
}

fn mirror<V: Vector3>(ray: Ray<V>, weight: V) -> Lobe<V> {
    Lobe {
        bounce: Bounce::Reflection,
        ray,
        weight,
        power: weight,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::{Machinery, Tracer};
    use crate::scene::{self, Settings};

    /// The hit, resolved once, hands out exactly the bits that deciding the
    /// side three times gave: the side from the cosine's sign, the law's R
    /// and T at the incidence of the directions (`specular::incidence`), and
    /// `specular::refract`'s direction and index, for each Fresnel model,
    /// from outside and from inside a glass sphere.
    #[test]
    fn a_dielectric_hit_resolved_once_gives_the_bits_of_each_law_alone() {
        let scene = scene::parse(
            r#"{ "version": 1, "image": { "width": 4, "height": 4 },
                 "camera": { "type": "course_pinhole" },
                 "materials": { "glass": { "type": "dielectric", "eta": 1.5 } },
                 "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass" } ] }"#,
        )
        .unwrap();
        let eta = 1.5_f32;
        let mut cases = 0;
        for model in [
            FresnelModel::Exact,
            FresnelModel::SchlickIncident,
            FresnelModel::SchlickRarer,
            FresnelModel::Course,
        ] {
            let settings = Settings {
                fresnel: model,
                ..Settings::default()
            };
            let tracer = Tracer::new(&scene, settings, Machinery::everything(&scene, &settings));
            for i in 0..400 {
                // Rays from outside (origin at z = −3) and from the centre
                // outwards, over a spread of angles.
                let u = (i % 20) as f32 / 20.0 - 0.5;
                let v = (i / 20) as f32 / 20.0 - 0.5;
                let (origin, target) = if i % 2 == 0 {
                    (Vec3::new(0.0, 0.0, -3.0), Vec3::new(u * 2.0, v * 2.0, 0.0))
                } else {
                    (Vec3::new(u * 0.9, v * 0.9, 0.0), Vec3::new(u, v + 0.3, 1.0))
                };
                let ray = Ray::new(origin, (target - origin).normalize());
                let Some(hit) = tracer.intersect(&ray) else {
                    continue;
                };
                let (wo, n) = (-ray.direction, hit.shading_normal(ray.direction));
                let lobes = tracer.lobes(&hit, n, wo, &Material::Dielectric { eta });
                let cos_o = n.dot(wo);
                let at = specular::incidence(wo, n, eta).expect("a valid interface");
                let (r, t) = match model {
                    FresnelModel::Exact => {
                        let f = fresnel::dielectric_resolved(&at);
                        (f.reflectance(), f.transmittance())
                    }
                    FresnelModel::SchlickRarer => {
                        let w = fresnel::schlick_dielectric_resolved(&at);
                        (w.reflectance, w.transmittance())
                    }
                    FresnelModel::SchlickIncident => {
                        let w = fresnel::schlick_dielectric_incident_resolved(&at);
                        (w.reflectance, w.transmittance())
                    }
                    FresnelModel::Course => {
                        let r = course::fresnel_000_glsl(fresnel::f0(eta, 0.0), cos_o.abs());
                        (r, 1.0 - r)
                    }
                };
                let outward = if cos_o >= 0.0 { n } else { -n };
                let offset = spawn::origin(&hit, outward, settings.ray_offset);
                assert_eq!(lobes.reflection.weight, Vec3::splat(r), "{model:?} {i}");
                assert_eq!(lobes.reflection.ray.origin, offset, "{model:?} {i}");
                let alone = specular::refract(wo, n, eta);
                assert_eq!(lobes.refraction.is_some(), alone.is_some(), "{model:?} {i}");
                if let (Some((lobe, reflectance)), Some(alone)) = (lobes.refraction, alone) {
                    assert_eq!(lobe.ray.direction, alone.direction, "{model:?} {i}");
                    let weight = radiance::across_interface(t, alone.eta_path);
                    assert_eq!(lobe.weight, Vec3::splat(weight), "{model:?} {i}");
                    assert_eq!(reflectance, r);
                }
                cases += 1;
            }
        }
        assert!(cases > 800, "{cases}");
    }
}
