//! A camera path's conductor bounces not weighed yet: each one's Fresnel
//! weight and the Russian roulette after it, applied in order where the
//! path's throughput is next used.
//!
//! A mirror bounce adds nothing to a path's sum. If the path ends before
//! a vertex that does (held by the mirror tube, [`crate::trap`], or out of
//! depth at a mirror), the weights of its last mirror bounces are never
//! needed; in the lit kaleidoscope that is about half of all the
//! conductor Fresnel evaluations. Applied later, in the same order, each
//! weight and each roulette step is the same operation on the same
//! numbers, so the throughput keeps its bits; and a path the roulette
//! ends at a bounce ends with the sum it had there, as nothing was added
//! after it. Only its ray counts differ: the rays traced past that bounce
//! before the roulette was settled.

use glam::Vec3;

use super::tracer::Tracer;
use crate::sampler::Slot1d;
use crate::scene::Material;

/// The most bounces held before they are settled at once.
const CAPACITY: usize = 16;

/// One conductor bounce not weighed yet: `cos θi` at its hit, its
/// material, and the slot of the roulette played after it.
type Bounce<'m> = (f32, &'m Material, Slot1d);

/// The conductor bounces of a path since its throughput was last used.
/// Its room is laid out at the first bounce held: most paths meet no
/// conductor, and every path starts a `Pending`.
pub(super) struct Pending<'m> {
    bounces: Option<[Option<Bounce<'m>>; CAPACITY]>,
    len: usize,
}

impl<'m> Pending<'m> {
    /// No bounce pending.
    pub(super) fn new() -> Self {
        Pending {
            bounces: None,
            len: 0,
        }
    }

    /// Holds a conductor bounce at `cos_i` off `material`, with its
    /// roulette slot; full, the throughput `beta` is settled at once
    /// ([`Pending::settle`]), and `None` where the roulette ended the path.
    pub(super) fn push(&mut self, tracer: &Tracer, bounce: Bounce<'m>, beta: Vec3) -> Option<Vec3> {
        self.bounces.get_or_insert([None; CAPACITY])[self.len] = Some(bounce);
        self.len += 1;
        if self.len == CAPACITY {
            return self.settle(tracer, beta);
        }
        Some(beta)
    }

    /// `beta` with every pending bounce's weight and roulette applied in
    /// order, and none left pending; `None` where the roulette ended the
    /// path at one of them.
    #[inline]
    pub(super) fn settle(&mut self, tracer: &Tracer, beta: Vec3) -> Option<Vec3> {
        match (self.len, &self.bounces) {
            (0, _) | (_, None) => Some(beta),
            (len, Some(bounces)) => {
                self.len = 0;
                weigh(tracer, &bounces[..len], beta)
            }
        }
    }
}

/// `beta` with `bounces`' weights and roulettes applied in order; `None`
/// where the roulette ended the path at one of them.
fn weigh(tracer: &Tracer, bounces: &[Option<Bounce>], mut beta: Vec3) -> Option<Vec3> {
    for (cos_i, material, number) in bounces.iter().flatten() {
        beta *= tracer.conductor_weight(*cos_i, material);
        beta = roulette(beta, *number, tracer.settings.throughput_cutoff)?;
    }
    Some(beta)
}

/// Russian roulette on the throughput `beta` after a bounce: below
/// `cutoff` it survives with probability `peak / cutoff` (its number
/// drawn from `number` only then) and carries `1 / probability`, so the
/// estimate stays unbiased. `None` where the path ends (and where `beta`
/// carries nothing).
pub(super) fn roulette(beta: Vec3, number: Slot1d, cutoff: f32) -> Option<Vec3> {
    let peak = beta.max_element();
    if peak <= 0.0 {
        return None;
    }
    if peak < cutoff {
        let survive = peak / cutoff;
        if number.value() >= survive {
            return None;
        }
        return Some(beta / survive);
    }
    Some(beta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::Machinery;
    use crate::rng::Pcg32;
    use crate::sampler::Sampler;
    use crate::scene::{self, Settings};

    /// Settled later, a path's conductor bounces give the throughput's
    /// bits, and the roulette's verdict, of weighing each at once: 4000
    /// runs of 1 to 40 bounces (past [`CAPACITY`], so settled midway too)
    /// off the course's gold and a grey conductor at random cosines, under
    /// a cutoff of 0.5 so that the roulette ends some and scales others.
    #[test]
    fn settling_later_gives_the_bits_and_the_roulette_of_weighing_at_once() {
        let scene = scene::parse(
            r#"{ "version": 1, "image": { "width": 4, "height": 4 },
                 "camera": { "type": "course_pinhole" },
                 "materials": {
                   "gold": { "type": "conductor", "n": [0.17, 0.35, 1.5], "kappa": [3.1, 2.7, 1.9] },
                   "grey": { "type": "conductor", "n": [1.2, 1.2, 1.2], "kappa": [0.4, 0.4, 0.4] } },
                 "objects": [ { "type": "sphere", "center": [0, 0, 5], "radius": 1, "material": "gold" } ] }"#,
        )
        .unwrap();
        let settings = Settings {
            throughput_cutoff: 0.5,
            ..Settings::default()
        };
        let tracer = Tracer::new(&scene, settings, Machinery::everything(&scene, &settings));
        let mut rng = Pcg32::new(3, 5);
        let (mut ended, mut survived) = (0, 0);
        for run in 0..4000_u32 {
            let mut sample = Sampler::for_pixel(1, run as u64).sample(0);
            let bounces: Vec<Bounce> = (0..1 + rng.next_u32() % 40)
                .map(|_| {
                    let material = &scene.materials[(rng.next_u32() % 2) as usize];
                    (rng.next_f32().max(1e-3), material, sample.take_1d())
                })
                .collect();
            let mut at_once = Some(Vec3::ONE);
            for &(cos_i, material, number) in &bounces {
                at_once = at_once.and_then(|beta| {
                    let beta = beta * tracer.conductor_weight(cos_i, material);
                    roulette(beta, number, settings.throughput_cutoff)
                });
            }
            let mut pending = Pending::new();
            let mut later = Some(Vec3::ONE);
            for &bounce in &bounces {
                later = later.and_then(|beta| pending.push(&tracer, bounce, beta));
            }
            let later = later.and_then(|beta| pending.settle(&tracer, beta));
            match (at_once, later) {
                (None, None) => ended += 1,
                (Some(a), Some(b)) => {
                    assert_eq!(
                        a.to_array().map(f32::to_bits),
                        b.to_array().map(f32::to_bits),
                        "run {run}"
                    );
                    survived += 1;
                }
                _ => panic!("run {run}: at once {at_once:?}, later {later:?}"),
            }
        }
        assert!(
            ended > 100 && survived > 100,
            "ended {ended}, survived {survived}"
        );
    }
}
