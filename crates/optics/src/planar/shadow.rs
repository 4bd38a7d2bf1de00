//! `optics shadow-matrix`: the slides' shadow matrix of a point light on
//! a plane, its special case `y = 0`, and where it puts one vertex.

use super::matrix::{
    clean, cleaned, cleaned_product, finite_matrix, inline, matrix_answer, matrix_detail, vector4,
};
use super::plane::{narrate_plane, PlaneArgs};
use crate::error::{ErrorKind, Result};
use crate::input::{Vec3Arg, Via};
use glam::{DMat4, DVec3, DVec4};
use record::{number, vector, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;
use techniques::planar::{
    light_on_plane, project_shadow, shadow_matrix, shadow_matrix_y0, Plane, Shadow,
};

/// The matrix that flattens a scene onto a plane along the rays of a
/// point light, and where it puts one vertex.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "The slides' shadow matrix of a point light l onto n · x + d = 0: column vectors, M (x, y, z, 1),
divided by its w. With --vertex, the outcome says whether a shadow falls there (cast), or the
matrix puts a point where none falls (beyond_plane, behind_light), or the line from the light
never meets the plane (parallel). A light on the plane (n · l + d = 0) makes the matrix
singular: every vertex goes to the light (degenerate).

Example:
  optics shadow-matrix --light 0,4,0 --plane-point 0,0,0 --plane-normal 0,1,0 --vertex 1,2,0"
)]
pub struct ShadowMatrixArgs {
    /// The point light's position.
    #[arg(long, allow_hyphen_values = true)]
    pub light: Vec3Arg,
    /// A point of the plane.
    #[arg(long, allow_hyphen_values = true)]
    pub plane_point: Vec3Arg,
    /// The plane's normal (any length but zero).
    #[arg(long, allow_hyphen_values = true)]
    pub plane_normal: Vec3Arg,
    /// A vertex to project onto the plane.
    #[arg(long, allow_hyphen_values = true)]
    pub vertex: Option<Vec3Arg>,
}

impl ShadowMatrixArgs {
    fn plane(&self) -> PlaneArgs {
        PlaneArgs {
            plane_point: self.plane_point,
            plane_normal: self.plane_normal,
        }
    }

    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let light = via.point("light", self.light)?;
        let plane = self.plane().plane(via)?;
        let vertex = self.vertex.map(|v| vertex(via, v)).transpose()?;
        let title = say!(
            lang,
            "Shadow matrix of a point light",
            "Pontfényforrás árnyékmátrixa"
        );
        let mut record = Record::new(Self::LAW, title, "").with_steps(steps);
        record.input("light", self.light.0);
        self.plane().inputs(&mut record);
        if let Some(v) = self.vertex {
            record.input("vertex", v.0);
        }
        narrate_plane(&mut record, lang, &plane);
        let m = finite_matrix(shadow_matrix(light, &plane), via, &["light", "plane_point"])?;
        record.step(|| {
            say!(
                lang,
                "M = (n · l + d) I − (l, 1)(n, d)ᵀ, with n · l + d = {} (the light's height above the plane)",
                "M = (n · l + d) I − (l, 1)(n, d)ᵀ, ahol n · l + d = {} (a fény magassága a sík fölött)",
                number(plane.distance(light))
            )
        });
        if light_on_plane(light, &plane) {
            record.step(|| {
                say!(
                    lang,
                    "n · l + d = 0: the light lies on the plane; M = −(l, 1)(n, d)ᵀ has rank 1 and sends every vertex off the plane to the light: no shadow (degenerate)",
                    "n · l + d = 0: a fény a síkon van; M = −(l, 1)(n, d)ᵀ egyrangú, minden síkon kívüli csúcsot a fénybe visz: nincs árnyék (degenerate)"
                )
            });
            record.detail("matrix", "degenerate");
        }
        if plane.normal() == DVec3::Y && plane.d() == 0.0 {
            let slides = shadow_matrix_y0(light);
            record.step(|| {
                say!(
                    lang,
                    "the plane is y = 0: the slides' special case [(l_y, −l_x, 0, 0), (0, 0, 0, 0), (0, −l_z, l_y, 0), (0, −1, 0, l_y)] = {}",
                    "a sík az y = 0: a diák különleges esete [(l_y, −l_x, 0, 0), (0, 0, 0, 0), (0, −l_z, l_y, 0), (0, −1, 0, l_y)] = {}",
                    inline(&cleaned(slides))
                )
            });
            record.detail("slides_y0", matrix_detail(&cleaned(slides)));
        }
        matrix_answer(&mut record, &m);
        if let Some(v) = vertex {
            let (image, shadow) = shadow_of(&m, light, &plane, v, via)?;
            record.step(|| format!("M (v, 1) = {}", vector4(image)));
            narrate_shadow(&mut record, lang, shadow);
        }
        Ok(record)
    }
}

/// `M (v, 1)` and the shadow of `v`, or the overflow of finite inputs
/// whose products are not: `v − l`, `M v`, or `p = M v / w` where a line
/// nearly parallel to the plane meets it beyond `f64`. (`project_shadow`
/// would read the first two as `Parallel`.)
fn shadow_of(
    m: &DMat4,
    light: DVec3,
    plane: &Plane,
    v: DVec3,
    via: Via,
) -> Result<(DVec4, Shadow)> {
    let image = cleaned_product(m, v.extend(1.0));
    let shadow = project_shadow(light, plane, v);
    let point = match shadow {
        Shadow::Cast(p) | Shadow::BeyondPlane(p) | Shadow::BehindLight(p) => Some(p),
        Shadow::Parallel | Shadow::LightOnPlane => None,
    };
    let finite =
        (v - light).is_finite() && image.is_finite() && point.is_none_or(|p| p.is_finite());
    if finite {
        return Ok((image, shadow));
    }
    let inputs = ["light", "plane_point", "vertex"].map(|f| via.name(f));
    Err(ErrorKind::Overflow {
        quantity: "p",
        inputs: inputs.to_vec(),
    }
    .into())
}

/// The vertex, checked where it enters.
#[cfg(not(test))]
fn vertex(via: Via, v: Vec3Arg) -> Result<DVec3> {
    Ok(via.point("vertex", v)?)
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the check of `--vertex`, as
    /// before it, for the technique-flags fuzz target to find: a NaN
    /// vertex then reaches `project_shadow`, which answers `Parallel`.
    pub(crate) static UNCHECKED_VERTEX: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn vertex(via: Via, v: Vec3Arg) -> Result<DVec3> {
    if UNCHECKED_VERTEX.get() {
        return Ok(v.dvec3());
    }
    Ok(via.point("vertex", v)?)
}

/// A point of the plane with its rounding cleaned against its own size.
fn cleaned_point(p: DVec3) -> [f64; 3] {
    let size = p.abs().max_element();
    p.to_array().map(|x| clean(x, size))
}

fn narrate_shadow(record: &mut Record, lang: Lang, shadow: Shadow) {
    let (outcome, point) = match shadow {
        Shadow::Cast(p) => ("cast", Some(p)),
        Shadow::BeyondPlane(p) => ("beyond_plane", Some(p)),
        Shadow::BehindLight(p) => ("behind_light", Some(p)),
        Shadow::Parallel => ("parallel", None),
        Shadow::LightOnPlane => ("degenerate", None),
    };
    let shown = point.map(|p| vector(cleaned_point(p)));
    let shown = shown.as_deref().unwrap_or_default();
    record.step(|| match shadow {
        Shadow::Cast(_) => say!(
            lang,
            "p = {}: the vertex lies between the light and the plane, its shadow falls here (cast)",
            "p = {}: a csúcs a fény és a sík között van, az árnyéka ide esik (cast)",
            shown
        ),
        Shadow::BeyondPlane(_) => say!(
            lang,
            "p = {}: the vertex lies beyond the plane, seen from the light; the matrix puts it here, but no shadow falls (beyond_plane)",
            "p = {}: a csúcs a fényből nézve a síkon túl van; a mátrix ide vetíti, de árnyék nem esik ide (beyond_plane)",
            shown
        ),
        Shadow::BehindLight(_) => say!(
            lang,
            "p = {}: the plane lies behind the light, seen from the vertex; the matrix puts an \"anti-shadow\" here (behind_light)",
            "p = {}: a sík a csúcsból nézve a fény mögött van; a mátrix ide „anti-árnyékot” vetít (behind_light)",
            shown
        ),
        Shadow::Parallel => say!(
            lang,
            "w = 0: the line from the light through the vertex is parallel to the plane (or the vertex is the light): no point (parallel)",
            "w = 0: a fényből a csúcson át húzott egyenes párhuzamos a síkkal (vagy a csúcs maga a fény): nincs vetület (parallel)"
        ),
        Shadow::LightOnPlane => say!(
            lang,
            "the light lies on the plane: M (v, 1) is a multiple of (l, 1), the light itself; no shadow (degenerate)",
            "a fény a síkon van: M (v, 1) az (l, 1) többszöröse, maga a fény; nincs árnyék (degenerate)"
        ),
    });
    record.detail("outcome", outcome);
    if let Some(p) = point {
        record.detail("point", cleaned_point(p));
    }
}
