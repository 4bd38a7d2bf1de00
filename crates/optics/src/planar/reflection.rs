//! `optics reflection-matrix`: the slides' `M = F⁻¹ S(1, −1, 1) F` of a
//! plane, each factor in numbers, and `M` applied to a point or a
//! direction.

use super::matrix::{
    clean, cleaned, cleaned_product, finite_matrix, inline, matrix_answer, matrix_detail, vector4,
};
use super::plane::{finite_point, narrate_plane, PlaneArgs};
use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use glam::{DMat4, DVec3};
use radiometry::domain::Direction;
use record::{number, vector, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;
use techniques::planar::{reflection, Plane};

/// The matrix that mirrors a scene in a plane.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "The slides' M = F⁻¹ S(1, −1, 1) F, F = R(n → y) T(−p): column vectors, M (x, y, z, 1).
With --point, M (p, 1): the point's mirror image (a light's position goes so too); with
--direction, M (w, 0): a direction (a directional light's) mirrored, untranslated.

Example:
  optics reflection-matrix --plane-point 0,1,0 --plane-normal 0,1,0 --point 2,3,4   (the floor y = 1)"
)]
pub struct ReflectionMatrixArgs {
    /// A point of the plane.
    #[arg(long, allow_hyphen_values = true)]
    pub plane_point: Vec3Arg,
    /// The plane's normal (any length but zero).
    #[arg(long, allow_hyphen_values = true)]
    pub plane_normal: Vec3Arg,
    /// A point (a light's position) to mirror.
    #[arg(long, allow_hyphen_values = true)]
    pub point: Option<Vec3Arg>,
    /// A direction (a directional light's) to mirror; any length but zero.
    #[arg(long, allow_hyphen_values = true)]
    pub direction: Option<Vec3Arg>,
}

impl ReflectionMatrixArgs {
    fn plane(&self) -> PlaneArgs {
        PlaneArgs {
            plane_point: self.plane_point,
            plane_normal: self.plane_normal,
        }
    }

    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let plane = self.plane().plane(via)?;
        let point = finite_point(via, "point", self.point)?;
        let direction = self
            .direction
            .map(|w| via.direction("direction", w))
            .transpose()?;
        let title = say!(
            lang,
            "Reflection matrix of a plane",
            "Sík tükrözési mátrixa"
        );
        let mut record = Record::new(Self::LAW, title, "").with_steps(steps);
        self.plane().inputs(&mut record);
        if let Some(p) = self.point {
            record.input("point", p.0);
        }
        if let Some(w) = self.direction {
            record.input("direction", w.0);
        }
        narrate_plane(&mut record, lang, &plane);
        let factors = reflection(&plane);
        let m = finite_matrix(factors.matrix, via, &["plane_point"])?;
        let [to_floor, mirror, from_floor] =
            [factors.to_floor, factors.mirror, factors.from_floor].map(cleaned);
        narrate_factors(&mut record, lang, [&to_floor, &mirror, &from_floor], &m);
        if let Some(p) = point {
            mirror_point(&mut record, (via, lang), &plane, &m, p)?;
        }
        if let Some(w) = direction {
            mirror_direction(&mut record, lang, &m, &w);
        }
        matrix_answer(&mut record, &m);
        record
            .detail("normal", plane.normal().to_array())
            .detail("d", plane.d())
            .detail("to_floor", matrix_detail(&to_floor))
            .detail("from_floor", matrix_detail(&from_floor));
        Ok(record)
    }
}

/// The three factors of `M = F⁻¹ S F`, cleaned, and the check of `det M`.
fn narrate_factors(record: &mut Record, lang: Lang, factors: [&DMat4; 3], m: &DMat4) {
    let [to_floor, mirror, from_floor] = factors;
    record.step(|| {
        say!(
            lang,
            "F = R(n → (0, 1, 0)) T(−p) moves the plane onto y = 0: F = {}",
            "F = R(n → (0, 1, 0)) T(−p) az y = 0 síkba viszi a síkot: F = {}",
            inline(to_floor)
        )
    });
    record.step(|| {
        say!(
            lang,
            "S(1, −1, 1) mirrors y = 0: S = {}",
            "S(1, −1, 1) az y = 0 síkra tükröz: S = {}",
            inline(mirror)
        )
    });
    record.step(|| {
        say!(
            lang,
            "F⁻¹ moves y = 0 back onto the plane: F⁻¹ = {}; M = F⁻¹ S F",
            "F⁻¹ visszaviszi az y = 0 síkot a síkra: F⁻¹ = {}; M = F⁻¹ S F",
            inline(from_floor)
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
}

/// `M (p, 1)`: the point's mirror image, with where it lies about the plane.
fn mirror_point(
    record: &mut Record,
    (via, lang): (Via, Lang),
    plane: &Plane,
    m: &DMat4,
    p: DVec3,
) -> Result<()> {
    let image = cleaned_product(m, p.extend(1.0));
    record.step(|| {
        say!(
            lang,
            "M (p, 1) = {}: p's mirror image (a point light goes so); n · x + d goes from {} to {}",
            "M (p, 1) = {}: p tükörképe (így kerül át a pontfényforrás is); n · x + d értéke {} helyett {}",
            vector4(image),
            number(plane.distance(p)),
            number(clean(
                plane.distance(image.truncate()),
                image.abs().max_element() + plane.d().abs()
            ))
        )
    });
    record.detail("point_image", image.truncate().to_array());
    if !image.is_finite() {
        return Err(overflow(via, "M p", &["plane_point", "point"]));
    }
    Ok(())
}

/// `M (w, 0)`: a direction mirrored, untranslated.
fn mirror_direction(record: &mut Record, lang: Lang, m: &DMat4, w: &Direction) {
    let image = cleaned_product(m, w.unit.extend(0.0));
    record.step(|| {
        say!(
            lang,
            "M (w, 0) = {}, w = {} normalised: w − 2 (n · w) n, the law of reflection, untranslated",
            "M (w, 0) = {}, w = {} normalizálva: w − 2 (n · w) n, a visszaverődés törvénye, eltolás nélkül",
            vector4(image),
            vector(w.unit.to_array())
        )
    });
    record.detail("direction_image", image.truncate().to_array());
}

/// The overflow of a product of finite inputs.
fn overflow(via: Via, quantity: &'static str, inputs: &[&str]) -> crate::error::Error {
    let inputs = inputs.iter().map(|field| via.name(field)).collect();
    crate::error::ErrorKind::Overflow { quantity, inputs }.into()
}
