//! The environment maps' round trips, and the slides' cube-map example.

use glam::DVec3;
use techniques::envmap::cube::{CubeTexel, Face};
use techniques::envmap::lat_long::LatLong;
use techniques::envmap::sphere::SphereTexel;
use techniques::envmap::Direction;
use techniques::refraction;

use crate::check::Check;

/// How far a direction may come back from its texel, radians: a few
/// roundings of the lat-long's and the cube's trigonometry and division.
pub const ENVMAP_ROUND_TRIP: f64 = 16.0 * f64::EPSILON;

/// How far a direction may come back from its sphere-map texel, radians:
/// `32 ε / m` (`m = 2 n_z`), the map's own stretch towards the picture's
/// rim, capped at `4 √ε` (the bound the techniques crate's tests use).
pub fn sphere_round_trip(m: f64) -> f64 {
    (32.0 * f64::EPSILON / m).min(4.0 * f64::EPSILON.sqrt())
}

/// The three environment maps: direction → texel (u, v) → direction over
/// 4096 directions spread evenly on the sphere and the axes, the diagonals
/// and the lat-long's seam; and the slides' example `(−3.2, 5.1, −8.4)`
/// on the −Z face at `u = 29/42`, `v = 11/56`.
pub fn check_envmap() -> Check {
    let mut check = Check::new(
        "techniques.envmap.round_trip",
        [
            "Environment maps (lat-long, cube, sphere): a direction back from its texel",
            "Környezeti térképek (lat-long, kocka, gömb): egy irány vissza a texeléből",
        ],
        [
            "the direction itself; the slides' cube-map example worked by hand (−Z, u = 29/42, v = 11/56)",
            "maga az irány; a diák kockatérkép-példája kézzel kiszámolva (−Z, u = 29/42, v = 11/56)",
        ],
        [&format!(
            "{ENVMAP_ROUND_TRIP:.2e} rad (lat-long, cube), 32 ε / m rad up to 4 √ε (sphere, m = |r + e|), the example to 4 ε"
        ), &format!("{ENVMAP_ROUND_TRIP:.2e} rad (lat-long, kocka), 32 ε / m rad legfeljebb 4 √ε-ig (gömb, m = |r + e|), a példa 4 ε-ig")],
    );
    for v in directions() {
        let Ok(r) = Direction::new(v) else {
            check.fail(format!("{v}: refused as a direction"));
            continue;
        };
        check.cases += 1;
        let at = format!("{v}");
        lat_long_and_cube_back(&mut check, r, &at);
        sphere_back(&mut check, r, &at);
    }
    for map in ["lat-long", "cube"] {
        if let Some(m) = check.worst(&format!("{map}: angle back (rad)")) {
            if !(m.worst <= ENVMAP_ROUND_TRIP) {
                check.fail(format!("{map}: {} comes back {:e} rad off", m.at, m.worst));
            }
        }
    }
    slides_example(&mut check);
    check
}

/// The directions sent round the maps: 4096 spread evenly on the sphere
/// (a golden-angle spiral), then the axes, the diagonals and the
/// lat-long's seam.
fn directions() -> impl Iterator<Item = DVec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let spread = (0..4096).map(move |i| {
        let z = 1.0 - (f64::from(i) + 0.5) / 2048.0;
        let r = (1.0 - z * z).sqrt();
        let (sin, cos) = (golden * f64::from(i)).sin_cos();
        DVec3::new(r * cos, r * sin, z)
    });
    let special = [
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
        DVec3::ONE,
        DVec3::new(1.0, -1.0, 1.0),
        DVec3::new(-1.0, -1.0, -1.0),
        DVec3::new(1.0, 0.0, 0.5),
        DVec3::new(1.0, -1e-300, 0.5),
        DVec3::new(1.0, 1.0, 0.0),
    ];
    spread.chain(special)
}

/// The angle between two directions, radians.
fn angle(a: Direction, b: Direction) -> f64 {
    refraction::angle_between(a.get(), b.get())
}

/// `r` (written `at`) back from its lat-long and its cube texel: the
/// angles measured, held to [`ENVMAP_ROUND_TRIP`] over all directions.
fn lat_long_and_cube_back(check: &mut Check, r: Direction, at: &str) {
    let lat = LatLong::from_direction(r);
    match LatLong::from_uv(lat.u(), lat.v()) {
        Ok(back) => check.measure_in_both(
            [
                "lat-long: angle back (rad)",
                "lat-long: a visszakapott irány szöge (rad)",
            ],
            angle(r, back.direction()),
            at,
        ),
        Err(e) => check.fail(format!("lat-long {at}: its own texel refused: {e:?}")),
    }
    let cube = CubeTexel::from_direction(r);
    match CubeTexel::from_uv(cube.face(), cube.u(), cube.v()) {
        Ok(back) => check.measure_in_both(
            [
                "cube: angle back (rad)",
                "kocka: a visszakapott irány szöge (rad)",
            ],
            angle(r, back.direction()),
            at,
        ),
        Err(e) => check.fail(format!("cube {at}: its own texel refused: {e:?}")),
    }
}

/// `r` (written `at`) back from its sphere-map texel, within
/// [`sphere_round_trip`] of its stretch; on the rim, `(0, 0, −1)` alone.
fn sphere_back(check: &mut Check, r: Direction, at: &str) {
    match SphereTexel::from_direction(r) {
        SphereTexel::Disc(texel) => match SphereTexel::from_uv(texel.u(), texel.v()) {
            Ok(back) => {
                let off = angle(r, back.direction());
                check.measure_in_both(
                    [
                        "sphere: angle back (rad)",
                        "gömb: a visszakapott irány szöge (rad)",
                    ],
                    off,
                    at,
                );
                if !(off <= sphere_round_trip(texel.m())) {
                    check.fail(format!(
                        "sphere: {at} comes back {off:e} rad off (m = {})",
                        texel.m()
                    ));
                }
            }
            Err(e) => check.fail(format!("sphere {at}: its own texel refused: {e:?}")),
        },
        SphereTexel::Rim => {
            if angle(r, SphereTexel::Rim.direction()) != 0.0 {
                check.fail(format!(
                    "sphere {at}: on the rim, which holds (0, 0, −1) alone"
                ));
            }
        }
    }
}

/// The slides' cube-map example: `(−3.2, 5.1, −8.4)` on the −Z face at
/// `u = 29/42`, `v = 11/56`, worked by hand, to 4 ε.
fn slides_example(check: &mut Check) {
    let example = CubeTexel::from_direction(
        Direction::new(DVec3::new(-3.2, 5.1, -8.4)).expect("a direction"),
    );
    check.cases += 1;
    let off = (example.u() - 29.0 / 42.0)
        .abs()
        .max((example.v() - 11.0 / 56.0).abs());
    check.measure_in_both(
        [
            "the slides' example: |uv − worked by hand|",
            "a diák példája: |uv − kézzel számolt|",
        ],
        off,
        "(−3.2, 5.1, −8.4)",
    );
    if example.face() != Face::NegativeZ || !(off <= 4.0 * f64::EPSILON) {
        check.fail(format!(
            "the slides' example: {:?} u = {}, v = {}; by hand −Z, 29/42, 11/56",
            example.face(),
            example.u(),
            example.v()
        ));
    }
}
