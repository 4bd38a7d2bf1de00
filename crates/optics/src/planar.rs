//! `optics reflection-matrix` and `optics shadow-matrix`: the slides'
//! 4 × 4 matrices of a plane (`techniques::planar`), with the working.
//!
//! The inputs are checked here, where they enter: every component finite,
//! the normal not zero. `techniques::planar::project_shadow` reads a NaN
//! light or vertex, and a product that overflowed, as `Parallel`; neither
//! reaches it from here.

use crate::error::{ErrorKind, Result};
use crate::input::{Vec3Arg, Via};
use crate::lang::{say, Lang};
use crate::record::{number, vector, Answer, Record, Steps};
use glam::{DMat4, DVec3};
use serde_json::Value;
use techniques::planar::{project_shadow, reflection_matrix, shadow_matrix, Plane, Shadow};

/// A plane, by a point of it and its normal.
#[derive(clap::Args, Clone, Debug)]
pub struct PlaneArgs {
    /// A point of the plane.
    #[arg(long, allow_hyphen_values = true)]
    pub plane_point: Vec3Arg,
    /// The plane's normal (any length but zero).
    #[arg(long, allow_hyphen_values = true)]
    pub plane_normal: Vec3Arg,
}

impl PlaneArgs {
    /// The plane, its flags checked once.
    fn plane(&self, via: Via) -> Result<Plane> {
        let point = via.point("plane_point", self.plane_point)?;
        let normal = via.direction("plane_normal", self.plane_normal)?;
        Ok(Plane::through(point, normal.unit)
            .expect("the point and normal were validated by radiometry::domain above"))
    }

    fn inputs(&self, record: &mut Record) {
        record
            .input("plane_point", self.plane_point.0)
            .input("plane_normal", self.plane_normal.0);
    }
}

/// The plane's equation, the first line of both matrices' working.
fn narrate_plane(record: &mut Record, lang: Lang, plane: &Plane) {
    record.step(|| {
        say!(
            lang,
            "plane n · x + d = 0: n = {}, d = −n · p = {}",
            "sík: n · x + d = 0, n = {}, d = −n · p = {}",
            vector(plane.normal().to_array()),
            number(plane.d())
        )
    });
}

/// The matrix as the record's answer: its rows, and for people one a line.
fn matrix_answer(record: &mut Record, m: &DMat4) {
    // `+ 0.0` writes a −0 (a zero times a negative coordinate) as 0.
    let rows: Vec<[f64; 4]> = (0..4).map(|i| (m.row(i) + 0.0).to_array()).collect();
    let text = rows
        .iter()
        .map(|row| {
            let cells: Vec<String> = row.iter().map(|&x| number(x)).collect();
            format!("  ({})", cells.join(", "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    let list = rows.iter().map(|row| Value::from(row.to_vec())).collect();
    record.set_answer(Answer::List(list), Some(format!("M =\n{text}")));
}

/// `m`, or the overflow of finite inputs whose products are not.
fn finite_matrix(m: DMat4, via: Via, inputs: &[&str]) -> Result<DMat4> {
    if m.is_finite() {
        return Ok(m);
    }
    let inputs = inputs.iter().map(|field| via.name(field)).collect();
    Err(ErrorKind::Overflow {
        quantity: "M",
        inputs,
    }
    .into())
}

/// The matrix that mirrors a scene in a plane.
#[derive(clap::Args, Clone, Debug)]
#[command(
    allow_negative_numbers = true,
    after_help = "The slides' M = F⁻¹ S(1, −1, 1) F, F = R(n → y) T(−p): column vectors, M (x, y, z, 1).

Example:
  optics reflection-matrix --plane-point 0,1,0 --plane-normal 0,1,0   (the floor y = 1)"
)]
pub struct ReflectionMatrixArgs {
    #[command(flatten)]
    pub plane: PlaneArgs,
}

impl ReflectionMatrixArgs {
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let plane = self.plane.plane(via)?;
        let title = say!(
            lang,
            "Reflection matrix of a plane",
            "Sík tükrözési mátrixa"
        );
        let mut record = Record::new("reflection_matrix", title, "").with_steps(steps);
        self.plane.inputs(&mut record);
        narrate_plane(&mut record, lang, &plane);
        let m = finite_matrix(reflection_matrix(&plane), via, &["plane_point"])?;
        record.step(|| {
            say!(
                lang,
                "F = R(n → (0, 1, 0)) T(−p) moves the plane onto y = 0; M = F⁻¹ S(1, −1, 1) F",
                "F = R(n → (0, 1, 0)) T(−p) az y = 0 síkba viszi a síkot; M = F⁻¹ S(1, −1, 1) F"
            )
        });
        record.step(|| {
            say!(
                lang,
                "check: det M = {} (a mirror turns handedness)",
                "ellenőrzés: det M = {} (a tükrözés megfordítja a sodrásirányt)",
                number(m.determinant())
            )
        });
        matrix_answer(&mut record, &m);
        record
            .detail("normal", plane.normal().to_array())
            .detail("d", plane.d());
        Ok(record)
    }
}

/// The matrix that flattens a scene onto a plane along the rays of a
/// point light, and where it puts one vertex.
#[derive(clap::Args, Clone, Debug)]
#[command(
    allow_negative_numbers = true,
    after_help = "The slides' shadow matrix of a point light l onto n · x + d = 0: column vectors, M (x, y, z, 1),
divided by its w. With --vertex, the outcome says whether a shadow falls there (cast), or the
matrix puts a point where none falls (beyond_plane, behind_light), or the line from the light
never meets the plane (parallel).

Example:
  optics shadow-matrix --light 0,4,0 --plane-point 0,0,0 --plane-normal 0,1,0 --vertex 1,2,0"
)]
pub struct ShadowMatrixArgs {
    /// The point light's position.
    #[arg(long, allow_hyphen_values = true)]
    pub light: Vec3Arg,
    #[command(flatten)]
    pub plane: PlaneArgs,
    /// A vertex to project onto the plane.
    #[arg(long, allow_hyphen_values = true)]
    pub vertex: Option<Vec3Arg>,
}

impl ShadowMatrixArgs {
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let light = via.point("light", self.light)?;
        let plane = self.plane.plane(via)?;
        let vertex = self.vertex.map(|v| vertex(via, v)).transpose()?;
        let title = say!(
            lang,
            "Shadow matrix of a point light",
            "Pontfényforrás árnyékmátrixa"
        );
        let mut record = Record::new("shadow_matrix", title, "").with_steps(steps);
        record.input("light", self.light.0);
        self.plane.inputs(&mut record);
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
        matrix_answer(&mut record, &m);
        if let Some(v) = vertex {
            let (image, shadow) = shadow_of(&m, light, &plane, v, via)?;
            record.step(|| {
                format!(
                    "M (v, 1) = ({}, {}, {}, {})",
                    number(image.x),
                    number(image.y),
                    number(image.z),
                    number(image.w)
                )
            });
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
) -> Result<(glam::DVec4, Shadow)> {
    let image = *m * v.extend(1.0);
    let shadow = project_shadow(light, plane, v);
    let point = match shadow {
        Shadow::Cast(p) | Shadow::BeyondPlane(p) | Shadow::BehindLight(p) => Some(p),
        Shadow::Parallel => None,
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

fn narrate_shadow(record: &mut Record, lang: Lang, shadow: Shadow) {
    let (outcome, point) = match shadow {
        Shadow::Cast(p) => ("cast", Some(p)),
        Shadow::BeyondPlane(p) => ("beyond_plane", Some(p)),
        Shadow::BehindLight(p) => ("behind_light", Some(p)),
        Shadow::Parallel => ("parallel", None),
    };
    record.step(|| match shadow {
        Shadow::Cast(p) => say!(
            lang,
            "p = {}: the vertex lies between the light and the plane, its shadow falls here (cast)",
            "p = {}: a csúcs a fény és a sík között van, az árnyéka ide esik (cast)",
            vector(p.to_array())
        ),
        Shadow::BeyondPlane(p) => say!(
            lang,
            "p = {}: the vertex lies beyond the plane, seen from the light; the matrix puts it here, but no shadow falls (beyond_plane)",
            "p = {}: a csúcs a fényből nézve a síkon túl van; a mátrix ide vetíti, de árnyék nem esik ide (beyond_plane)",
            vector(p.to_array())
        ),
        Shadow::BehindLight(p) => say!(
            lang,
            "p = {}: the plane lies behind the light, seen from the vertex; the matrix puts an \"anti-shadow\" here (behind_light)",
            "p = {}: a sík a csúcsból nézve a fény mögött van; a mátrix ide „anti-árnyékot” vetít (behind_light)",
            vector(p.to_array())
        ),
        Shadow::Parallel => say!(
            lang,
            "w = 0: the line from the light through the vertex is parallel to the plane (or the vertex is the light): no point (parallel)",
            "w = 0: a fényből a csúcson át húzott egyenes párhuzamos a síkkal (vagy a csúcs maga a fény): nincs vetület (parallel)"
        ),
    });
    record.detail("outcome", outcome);
    if let Some(p) = point {
        record.detail("point", (p + 0.0).to_array());
    }
}
