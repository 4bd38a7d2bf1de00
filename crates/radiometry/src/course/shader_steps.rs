//! Steps of the course's shaders where the control flow, not a formula, is
//! wrong: each written as its listing has it, for the tests in
//! `tests/source_shader_steps.rs` to hold against what the shader itself
//! means to compute.

#[allow(unused_imports)]
use num_traits::{Float, One, Zero};

use crate::specular::reflect;
use crate::{Real, Vector3};

/// `000` lines 1560–1594, the rough branch of the gold spheres' shader (the
/// first with mirrors; the shadow shader before it, lines 1151–1185, is the
/// same branch with `weight = 1` and nothing gathered yet), per channel:
///
/// ```text
/// if (shadowHit.didHit) radiance = lightAmbient * mat.ambient;
/// else                  radiance += weight * (the lit terms);
/// ```
///
/// `radiance` is what the path has gathered so far, `weight` the product of
/// the mirrors' Fresnel factors on the way (line 1531), `ambient` is
/// `lightAmbient · mat.ambient` and `direct` the lit terms,
/// `energy · (kd cos θ + ks cos^shine δ)`, 0 where `cos θ ≤ 0`. Returns the
/// new `radiance`.
///
/// **Wrong** twice. In shadow it *assigns*: seen in a mirror, the shadowed
/// point throws away what the path gathered (the `lightAmbient` every mirror
/// adds, line 1540) and is not multiplied by `weight`, as the lit branch is
/// (lines 1577, 1589): a mirror that reflects nothing still shows it. And
/// the ambient term is there only in shadow: a lit point gets `weight ·
/// direct` alone, so near the terminator, where `kd cos θ < lightAmbient ·
/// ka`, it is darker than its own shadow. The tutorial's own sum (line 424),
/// "ambient + diffuse + specular", means `radiance + weight · (ambient +
/// direct)` with `direct = 0` in shadow.
#[inline]
pub fn rough_hit_000<T: Real>(
    radiance: [T; 3],
    weight: [T; 3],
    shadowed: bool,
    ambient: [T; 3],
    direct: [T; 3],
) -> [T; 3] {
    if shadowed {
        ambient
    } else {
        core::array::from_fn(|c| radiance[c] + weight[c] * direct[c])
    }
}

/// What the `002` fragment shader keeps of a hit (`struct Hit`, lines
/// 76–83), with the colour its shading function (lines 181–204, whose call
/// the listing elides) gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit002<V: Vector3> {
    /// `hit.position`, the point hit.
    pub position: V,
    /// `hit.normal`, the unit normal there.
    pub normal: V,
    /// The shaded colour of the hit.
    pub colour: V,
    /// `hit.material.reflectance`, the fraction `mix` takes from the reflection.
    pub reflectance: V::Scalar,
}

/// `002` lines 216–253, `main`'s reflection loop, from the primary ray's
/// direction and its hit `first`: `max_depth` (`MAX_DEPTH`) times, if the
/// current hit's reflectance `r > 0`, reflect about its normal, trace from
/// `position + normal · eps`, and `color = mix(color, color2, r)`, where
/// `color2` is the new hit's colour or, on a miss, the ray's direction (the
/// "clear colour", line 216). `trace(origin, direction)` stands for
/// `traceScene` and the elided shading call. Returns `color`.
///
/// **Wrong** twice. `mix` by the reflectance of the surface the ray leaves
/// is right at the first bounce, `(1 − r₀) c₀ + r₀ c₁`, but the second mixes
/// the whole sum so far with `c₂` by `r₁`: `(1 − r₁)((1 − r₀) c₀ + r₀ c₁) +
/// r₁ c₂`, where the recursion the text describes (the reflectance says "how
/// much the new hit contributes", line 52) is `(1 − r₀) c₀ + r₀ ((1 − r₁) c₁
/// + r₁ c₂)`: the second reflection is weighted `r₁` instead of `r₀ r₁`. And
/// on a miss `traceScene` returns false but writes only `hit.t` (line 145):
/// position, normal and material stay those of the last hit, so the next
/// pass reflects the reflected direction about the same normal, which gives
/// the incoming direction back, and traces from the old point into its own
/// surface, mixing its colour in again. The colour of a ray that has left
/// the scene then depends on `MAX_DEPTH`.
pub fn reflection_loop_002<V: Vector3>(
    direction: V,
    first: Hit002<V>,
    max_depth: usize,
    eps: V::Scalar,
    trace: impl Fn(V, V) -> Option<Hit002<V>>,
) -> V {
    let one = V::Scalar::one();
    let mut hit = first;
    let mut direction = direction;
    let mut color = first.colour;
    for _ in 0..max_depth {
        let r = hit.reflectance;
        if r > V::Scalar::zero() {
            // GLSL's reflect(I, N) = I − 2 dot(N, I) N, the law for wi = −I.
            direction = reflect(-direction, hit.normal);
            let origin = hit.position + hit.normal * eps;
            let color2 = match trace(origin, direction) {
                Some(next) => {
                    hit = next;
                    next.colour
                }
                None => direction,
            };
            color = color * (one - r) + color2 * r;
        }
    }
    color
}

/// `002` lines 181–204, the shading function (its signature elided): the
/// hit's `diffuse` colour times `s = max(0.2, dot(L, N))`, and `s = 0.2`
/// when a sphere stops the ray towards the point light `light0`
/// (`occluded`), with `L = normalize(light0 − position)` and `N` the unit
/// `normal`. Returns `color`.
///
/// **Wrong** twice. The "0.2 min. ambient contribution" (line 192) is a
/// floor, not an added ambient term: a lit point whose `cos θ` is below 0.2
/// gets exactly what its own shadow gets, and a lit point above it no
/// ambient at all. And `light0` is a point light whose light does not fall
/// off: `s` depends on the direction to the light, never on its distance,
/// where the irradiance of a point light is `I cos θ / r²`
/// ([`crate::radiance::point_irradiance`]).
pub fn shade_002<V: Vector3>(diffuse: V, position: V, normal: V, light0: V, occluded: bool) -> V {
    let floor = V::Scalar::lit(0.2);
    let to_light = (light0 - position).normalize();
    let s = if occluded {
        floor
    } else {
        floor.max(to_light.dot(normal))
    };
    diffuse * s
}

/// What `intersectMirrors` reads of `000`'s `Hit` (lines 1787–1795):
/// whether it hit, and how far along the ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MirrorHit000<T> {
    /// `hitDistance`, the ray parameter of the hit.
    pub distance: T,
    /// `didHit`.
    pub did_hit: bool,
}

/// `000` lines 1937–1979, `intersectMirrors`, for a ray from `origin` along
/// unit `direction`: the mirrors of a regular `num_sides`-gon of
/// circumradius `size` around the z axis, normals `cross(p(i+1) − p(i), z)`
/// normalised, each intersected by `intersectPlane` (lines 1909–1932: a hit
/// only where `dot(normal, dir) > 0.001` and `t > 0`), the nearest kept.
///
/// `closest_before` is what the local `Hit closestHit;` (line 1944) holds
/// before the loop: the listing never initialises it, and GLSL leaves an
/// uninitialised local undefined. `intersectScene` sets `finalHit.didHit =
/// false` first (line 1991); this function does not, and its first
/// comparison, `!closestHit.didHit || closestHit.hitDistance >
/// planeHit.hitDistance` (line 1971), reads the undefined value for every
/// ray. Passing `did_hit: false` gives what the author meant; a leftover
/// hit nearer than every mirror hides them all, and is returned as the
/// mirror hit. (A plane that `intersectPlane` leaves unwritten, erratum 7,
/// counts as a miss here.)
pub fn intersect_mirrors_000<V: Vector3>(
    origin: V,
    direction: V,
    num_sides: usize,
    size: V::Scalar,
    closest_before: MirrorHit000<V::Scalar>,
) -> MirrorHit000<V::Scalar> {
    let zero = V::Scalar::zero();
    // The listing's π, `3.141592653`, kept as written.
    #[allow(clippy::approx_constant)]
    let alpha = V::Scalar::lit(2.0 * 3.141592653) / V::Scalar::lit(num_sides as f64);
    let corner = |i: usize| {
        let angle = V::Scalar::lit(i as f64) * alpha;
        V::new(angle.cos(), angle.sin(), zero) * size
    };
    let z = V::new(zero, zero, V::Scalar::one());
    let mut closest = closest_before;
    for i in 0..num_sides {
        let (p1, p2) = (corner(i), corner(i + 1));
        let edge = p2 - p1;
        let normal = edge
            .try_normalize()
            .and_then(|e| e.cross(z).try_normalize());
        let Some(normal) = normal else { continue };
        let denom = normal.dot(direction);
        if denom <= V::Scalar::lit(0.001) {
            continue;
        }
        let t = (p1 - origin).dot(normal) / denom;
        if t > zero && (!closest.did_hit || closest.distance > t) {
            closest = MirrorHit000 {
                distance: t,
                did_hit: true,
            };
        }
    }
    closest
}
