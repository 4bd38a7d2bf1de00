//! `optics envmap`: where a reflected direction is looked up in the
//! slides' environment maps (`techniques::envmap`), with the working.
//!
//! Every number comes from the `techniques` crate; the working narrates
//! what it decided (the face, the pole, the rim) and never decides again.

use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use crate::laws::note_normalized;
use glam::DVec3;
use record::{number, vector, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;
use serde_json::{json, Map, Value};
use techniques::envmap::cube::CubeTexel;
use techniques::envmap::lat_long::LatLong;
use techniques::envmap::sphere::SphereTexel;
use techniques::envmap::Direction;

/// Which map to look the direction up in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MapChoice {
    /// The cube map: the face and (u, v) on it.
    Cube,
    /// The latitude–longitude map: (u, v) and the angles ρ, φ.
    LatLong,
    /// The sphere map: (u, v), m and the sphere's normal.
    Sphere,
    /// All three.
    #[default]
    All,
}

impl MapChoice {
    fn name(self) -> &'static str {
        match self {
            MapChoice::Cube => "cube",
            MapChoice::LatLong => "lat-long",
            MapChoice::Sphere => "sphere",
            MapChoice::All => "all",
        }
    }

    fn includes(self, map: MapChoice) -> bool {
        self == MapChoice::All || self == map
    }
}

/// Where a reflected direction is looked up in an environment map.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "--dir is the reflected direction r, pointing away from the surface into the surroundings
(any length). For the sphere map it is in eye space: the viewer looks down −z.

Examples:
  optics envmap --dir -3.2,5.1,-8.4 --map cube     (the slides' example: the −Z face)
  optics envmap --dir 1,1,0"
)]
pub struct EnvmapArgs {
    /// The reflected direction r (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub dir: Vec3Arg,
    /// The map: cube, lat-long, sphere or all.
    #[arg(long, value_enum, default_value_t)]
    #[serde(default)]
    pub map: MapChoice,
}

impl EnvmapArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let given = via.direction("dir", self.dir)?;
        let title = say!(lang, "Environment map lookup", "Környezeti térkép címzése");
        let mut record = Record::new(Self::LAW, title, "").with_steps(steps);
        record
            .input("dir", self.dir.0)
            .input("map", self.map.name());
        note_normalized(&mut record, lang, "dir", &given);
        let r = Direction::from(given);
        let (mut answer, mut text) = (Map::new(), Vec::new());
        let mut add = |key: &str, (line, value): (String, Value)| {
            text.push(line);
            answer.insert(key.to_owned(), value);
        };
        if self.map.includes(MapChoice::Cube) {
            add("cube", cube(&mut record, lang, self.dir.dvec3(), r));
        }
        if self.map.includes(MapChoice::LatLong) {
            add("lat_long", lat_long(&mut record, lang, r));
        }
        if self.map.includes(MapChoice::Sphere) {
            add("sphere", sphere(&mut record, lang, r));
        }
        record
            .detail("direction", r.get().to_array())
            .set_answer(Answer::Object(answer), Some(text.join("; ")));
        Ok(record)
    }
}

/// The cube map's working, on the vector as given: the ratios are the
/// same for any length, and these are the numbers a student divides. The
/// answer's line and its JSON.
fn cube(record: &mut Record, lang: Lang, given: DVec3, r: Direction) -> (String, Value) {
    let texel = CubeTexel::from_direction(r);
    let face = texel.face();
    let f = face.frame();
    let axis = ["x", "y", "z"];
    let (major, s_c, t_c) = (
        given[f.axis],
        f.s_sign * given[f.s_axis],
        f.t_sign * given[f.t_axis],
    );
    record.step(|| {
        say!(
            lang,
            "cube: the largest |component| is r_{} = {} (ties: z over y over x): the {} face",
            "kocka: a legnagyobb abszolút értékű komponens r_{} = {} (egyenlőségnél z, majd y, majd x): a {} lap",
            axis[f.axis],
            number(major),
            face.name()
        )
    });
    let signed =
        |sign: f64, k: usize| format!("{}r_{}", if sign < 0.0 { "−" } else { "" }, axis[k]);
    record.step(|| {
        say!(
            lang,
            "OpenGL 4.6 Table 8.19 on {}: s_c = {} = {}, t_c = {} = {}, |m_a| = {}",
            "OpenGL 4.6, 8.19. táblázat, {} lap: s_c = {} = {}, t_c = {} = {}, |m_a| = {}",
            face.name(),
            signed(f.s_sign, f.s_axis),
            number(s_c),
            signed(f.t_sign, f.t_axis),
            number(t_c),
            number(major.abs())
        )
    });
    record.step(|| {
        format!(
            "u = (s_c/|m_a| + 1)/2 = {}, v = (t_c/|m_a| + 1)/2 = {}",
            number(texel.u()),
            number(texel.v())
        )
    });
    back(record, lang, texel.direction());
    let line = say!(
        lang,
        "cube: {} face, u = {}, v = {}",
        "kocka: {} lap, u = {}, v = {}",
        face.name(),
        number(texel.u()),
        number(texel.v())
    );
    let value = json!({ "face": face.name(), "u": texel.u(), "v": texel.v() });
    (line, value)
}

fn lat_long(record: &mut Record, lang: Lang, r: Direction) -> (String, Value) {
    let texel = LatLong::from_direction(r);
    record.step(|| {
        say!(
            lang,
            "lat-long: ρ = arccos(−r_z) = {} rad ({}°), from −z",
            "szélességi–hosszúsági: ρ = arccos(−r_z) = {} rad ({}°), −z-től mérve",
            number(texel.rho()),
            number(texel.rho().to_degrees())
        )
    });
    record.step(|| {
        if texel.is_pole() {
            say!(
                lang,
                "a pole: every φ names it; φ = 0 by convention",
                "pólus: minden φ ezt az irányt adja; megállapodás szerint φ = 0"
            )
        } else {
            say!(
                lang,
                "φ = atan2(r_y, r_x) in [0, 2π) = {} rad ({}°) (the slides' arctan(r_y/r_x) covers half the circle)",
                "φ = atan2(r_y, r_x) a [0, 2π) tartományban = {} rad ({}°) (a diák arctan(r_y/r_x) képlete csak a kör felét fedi le)",
                number(texel.phi()),
                number(texel.phi().to_degrees())
            )
        }
    });
    record.step(|| {
        format!(
            "u = φ/2π = {}, v = ρ/π = {}",
            number(texel.u()),
            number(texel.v())
        )
    });
    back(record, lang, texel.direction());
    let line = say!(
        lang,
        "lat-long: u = {}, v = {}",
        "szélességi–hosszúsági: u = {}, v = {}",
        number(texel.u()),
        number(texel.v())
    );
    let value = json!({ "u": texel.u(), "v": texel.v(), "phi": texel.phi(), "rho": texel.rho() });
    (line, value)
}

fn sphere(record: &mut Record, lang: Lang, r: Direction) -> (String, Value) {
    let texel = SphereTexel::from_direction(r);
    let SphereTexel::Disc(disc) = texel else {
        record.step(|| say!(
            lang,
            "sphere: r = (0, 0, −1), straight away from the viewer: m = 0 and n = (r + e)/m has no value; the view grazes the sphere's silhouette, and every point of the map's rim stores this direction",
            "gömbtérkép: r = (0, 0, −1), a nézőtől egyenesen el: m = 0, n = (r + e)/m nem létezik; a nézősugár a gömb körvonalát súrolja, és a térkép teljes pereme ezt az irányt tárolja"
        ));
        return sphere_answer(lang, &texel);
    };
    record.step(|| {
        say!(
            lang,
            "sphere: e = (0, 0, 1) towards the viewer; m = √(r_x² + r_y² + (r_z + 1)²) = {} (unit r {})",
            "gömbtérkép: e = (0, 0, 1) a néző felé; m = √(r_x² + r_y² + (r_z + 1)²) = {} (egységnyi r = {})",
            number(disc.m()),
            vector(r.get().to_array())
        )
    });
    record.step(|| {
        format!(
            "n = (r_x/m, r_y/m, (r_z + 1)/m) = {}",
            vector(disc.normal().to_array())
        )
    });
    record.step(|| {
        format!(
            "u = (n_x + 1)/2 = {}, v = (n_y + 1)/2 = {}",
            number(disc.u()),
            number(disc.v())
        )
    });
    back(record, lang, texel.direction());
    sphere_answer(lang, &texel)
}

/// The map's way back, which the texel gives: the check a student can
/// make by hand.
fn back(record: &mut Record, lang: Lang, r: Direction) {
    record.step(|| {
        say!(
            lang,
            "back from the texel, to rounding: r = {}",
            "a texelből vissza, kerekítésnyi eltéréssel: r = {}",
            vector(r.get().to_array())
        )
    });
}

/// The sphere map's answer line and JSON: the point of the disc, or the rim.
fn sphere_answer(lang: Lang, texel: &SphereTexel) -> (String, Value) {
    match texel {
        SphereTexel::Disc(t) => (
            say!(
                lang,
                "sphere: u = {}, v = {}, m = {}",
                "gömbtérkép: u = {}, v = {}, m = {}",
                number(t.u()),
                number(t.v()),
                number(t.m())
            ),
            json!({
                "outcome": "disc",
                "u": t.u(),
                "v": t.v(),
                "m": t.m(),
                "normal": t.normal().to_array(),
            }),
        ),
        SphereTexel::Rim => (
            say!(
                lang,
                "sphere: the rim (m = 0), every point of it",
                "gömbtérkép: a perem (m = 0), annak minden pontja"
            ),
            json!({ "outcome": "rim", "m": 0.0 }),
        ),
    }
}
