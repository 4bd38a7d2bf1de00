//! The rasteriser-side techniques of `001` (the `techniques` crate)
//! against the answers they stand in for: N-BK7's Sellmeier index against
//! Schott's data sheet, the traced prism against the analytic minimum
//! deviation, the slides' cheap refraction and fitted empirical Fresnel
//! form against the exact laws, and the projected shadow against the
//! tracer's own ray–plane intersection. Their measured errors are the
//! report's numbers for the techniques.

use glam::DVec3;
use radiometry::course::EmpiricalFresnel;
use techniques::dispersion::prism::{Passage, Prism};
use techniques::dispersion::{fraunhofer_nm, Sellmeier};
use techniques::empirical_fresnel::{self, AngleGrid, Interface, SUITE};
use techniques::envmap::cube::{CubeTexel, Face};
use techniques::envmap::lat_long::LatLong;
use techniques::envmap::sphere::SphereTexel;
use techniques::envmap::Direction;
use techniques::planar::{self, Plane, Shadow};
use techniques::refraction::{self, Constant, Side};

use serde::Serialize;

use crate::check::Check;

/// The techniques' curves, for the report's figure (`techniques.png`):
/// what their checks measured, one value per degree.
#[derive(Clone, Debug, Default, Serialize)]
pub struct TechniqueCurves {
    /// The cheap refraction's angle from Snell's law, per medium and
    /// constant.
    pub refraction: Vec<RefractionCurve>,
    /// The fitted empirical Fresnel form beside the exact law and Schlick.
    pub fresnel_fits: Vec<FitCurve>,
}

/// One medium and constant of the cheap refraction.
#[derive(Clone, Debug, Serialize)]
pub struct RefractionCurve {
    /// Medium and constant, in words.
    pub label: String,
    /// Angle of incidence, degrees.
    pub angle_deg: Vec<f64>,
    /// The angle between the cheap and the exact ray, degrees.
    pub error_deg: Vec<f64>,
}

/// One interface's reflectance by the exact law, the fitted form and
/// Schlick.
#[derive(Clone, Debug, Serialize)]
pub struct FitCurve {
    /// The interface.
    pub label: String,
    /// Angle of incidence, degrees.
    pub angle_deg: Vec<f64>,
    /// The exact law.
    pub exact: Vec<f64>,
    /// The fitted form, clamped as the slide clamps it.
    pub fitted: Vec<f64>,
    /// Schlick's approximation.
    pub schlick: Vec<f64>,
    /// The fitted parameters `(bias, scale, power)`.
    pub form: [f64; 3],
}

/// The interfaces whose fits the figure draws.
const DRAWN_FITS: [&str; 3] = ["glass", "water", "gold G"];

/// Schott's N-BK7 data sheet: the indices it prints (five decimals) at the
/// Fraunhofer lines (SCHOTT AG, Optical Glass Data Sheets, glass code
/// 517642.251).
pub const N_BK7_DATA_SHEET: [(&str, f64, f64); 4] = [
    ("n_F", fraunhofer_nm::F, 1.52238),
    ("n_e", fraunhofer_nm::E, 1.51872),
    ("n_d", fraunhofer_nm::D, 1.51680),
    ("n_C", fraunhofer_nm::C, 1.51432),
];

/// Half a unit in the data sheet's last printed digit.
pub const DATA_SHEET_ABS: f64 = 5e-6;

/// The Sellmeier index against the data sheet.
pub fn check_sellmeier(glass: &Sellmeier) -> Check {
    let mut check = Check::new(
        "techniques.dispersion.n_bk7",
        "N-BK7's refractive index by the Sellmeier equation at the Fraunhofer lines",
        "Schott's N-BK7 data sheet (five printed decimals)",
        &format!("within {DATA_SHEET_ABS:e}, half a unit in the last printed digit"),
    );
    for (line, nm, printed) in N_BK7_DATA_SHEET {
        check.cases += 1;
        let Some(n) = glass.index_at(nm) else {
            check.fail(format!("{line} ({nm} nm): no index"));
            continue;
        };
        let err = (n - printed).abs();
        check.measure("|Sellmeier − data sheet|", err, &format!("{line}, {nm} nm"));
        if !(err <= DATA_SHEET_ABS) {
            check.fail(format!(
                "{line} ({nm} nm): {n:.7}, the data sheet {printed}"
            ));
        }
    }
    check
}

/// How close the traced symmetric passage comes to the analytic minimum
/// deviation, radians: a few ulps of the angles involved.
pub const PRISM_ABS: f64 = 1e-12;

/// A 60° prism of `glass` across the visible: the ray traced at the
/// symmetric incidence with the radiometry refraction law deviates by the
/// analytic `2 asin(n sin(A/2)) − A`, and rays 0.01 rad to either side
/// deviate more; the spread between the F and C lines measured.
pub fn check_prism(glass: &Sellmeier) -> Check {
    let mut check = Check::new(
        "techniques.dispersion.prism",
        "A 60° prism: the traced deviation at symmetric incidence is the analytic minimum deviation",
        "δ_min = 2 asin(n sin(A/2)) − A (Snell's law at both faces of a symmetric passage)",
        &format!("within {PRISM_ABS:e} rad; any other incidence deviates more"),
    );
    let prism = Prism::new(60f64.to_radians()).expect("60° is an apex angle");
    let deviation = |n: f64, theta: f64| match prism.trace(n, theta) {
        Some(Passage::Emerges { deviation, .. }) => Some(deviation),
        _ => None,
    };
    for nm in (400..=700).step_by(25).map(f64::from) {
        check.cases += 1;
        let (Some(n), at) = (glass.index_at(nm), format!("{nm} nm")) else {
            check.fail(format!("{nm} nm: no index"));
            continue;
        };
        let (Some(theta), Some(analytic)) =
            (prism.symmetric_incidence(n), prism.minimum_deviation(n))
        else {
            check.fail(format!("{at}: no symmetric passage for n = {n}"));
            continue;
        };
        let Some(traced) = deviation(n, theta) else {
            check.fail(format!("{at}: the symmetric ray does not emerge"));
            continue;
        };
        check.measure("|traced − analytic| (rad)", (traced - analytic).abs(), &at);
        if !((traced - analytic).abs() <= PRISM_ABS) {
            check.fail(format!("{at}: traced {traced}, analytic {analytic}"));
        }
        for other in [theta - 0.01, theta + 0.01] {
            if deviation(n, other).is_some_and(|d| d <= traced) {
                check.fail(format!(
                    "{at}: incidence {other} rad deviates no more than the minimum"
                ));
            }
        }
    }
    let spread = [fraunhofer_nm::F, fraunhofer_nm::C]
        .map(|nm| glass.index_at(nm).and_then(|n| prism.minimum_deviation(n)));
    if let [Some(f), Some(c)] = spread {
        check.measure(
            "F − C spread of the minimum deviation (°)",
            (f - c).to_degrees(),
            "",
        );
    }
    check
}

/// The slides' cheap refraction `t = normalize(−c n + i)` against Snell's
/// law entering water (their `c = 1`) and glass, and the first-order
/// `c = η − 1`: the worst angle between the two rays over 0° to 89°. The
/// check is the identity the erratum rests on: with `c = 1` the cheap ray
/// bends to exactly half the incidence angle.
pub fn check_cheap_refraction(curves: &mut Vec<RefractionCurve>) -> Check {
    let mut check = Check::new(
        "techniques.refraction.cheap",
        "The slides' cheap refraction against Snell's law, entering water and glass",
        "Snell's law in vector form (radiometry::specular::refract)",
        "c = 1 bends by exactly half the incidence angle (to 1e-12 rad); the angles from Snell's law measured",
    );
    for (medium, eta) in [("water", 1.33), ("glass", 1.5)] {
        for (name, constant) in [
            ("c = 1", refraction::SLIDES_WATER),
            ("c = η − 1", Constant::FirstOrder),
        ] {
            let mut curve = RefractionCurve {
                label: format!("into {medium}, {name}"),
                angle_deg: Vec::new(),
                error_deg: Vec::new(),
            };
            for degree in 0..90 {
                let theta = f64::from(degree).to_radians();
                check.cases += 1;
                let Some(compared) = refraction::compare_at(theta, Side::Outside, eta, constant)
                else {
                    check.fail(format!("{medium}, {name}, {degree}°: no comparison"));
                    continue;
                };
                let Some(error) = compared.error() else {
                    check.fail(format!(
                        "{medium}, {name}, {degree}°: total internal reflection entering"
                    ));
                    continue;
                };
                check.measure(
                    &format!("into {medium}, {name}: angle from Snell's law (°)"),
                    error.to_degrees(),
                    &format!("{degree}°"),
                );
                curve.angle_deg.push(f64::from(degree));
                curve.error_deg.push(error.to_degrees());
                if let (refraction::Comparison::Refracts { cheap, .. }, Constant::Fixed(_)) =
                    (compared, constant)
                {
                    let bend = refraction::angle_between(
                        -refraction::in_plane(theta, Side::Outside),
                        cheap,
                    );
                    if !((bend - theta / 2.0).abs() <= 1e-12) {
                        check.fail(format!(
                            "{medium}, {degree}°: c = 1 bends {bend} rad, not half of {theta}"
                        ));
                    }
                }
            }
            curves.push(curve);
        }
    }
    check
}

/// The slides' empirical Fresnel form fitted to the exact law of each of
/// the suite's interfaces, beside Schlick: the fit's family holds
/// Schlick's curve, so its RMS can be no larger unless the fit failed.
pub fn check_empirical_fresnel(curves: &mut Vec<FitCurve>) -> Check {
    let mut check = Check::new(
        "techniques.empirical_fresnel.fit",
        "The slides' bias + scale (1 + I·N)^power fitted to the exact Fresnel law, beside Schlick",
        "the exact dielectric and conductor laws (radiometry), every 0.1° from 0° to 90°",
        "the fit's RMS no larger than Schlick's (Schlick is one member of the form's family)",
    );
    for (name, interface) in SUITE {
        check.cases += 1;
        match empirical_fresnel::compare(interface, &AngleGrid::TENTH_OF_A_DEGREE) {
            Ok(c) => {
                check.measure("fitted form: RMS error", c.fit.errors.rms, name);
                check.measure("fitted form: largest error", c.fit.errors.max, name);
                check.measure("Schlick: RMS error", c.schlick.rms, name);
                check.measure("Schlick: largest error", c.schlick.max, name);
                if DRAWN_FITS.contains(&name) {
                    curves.push(fit_curve(name, interface, &c.fit.form));
                }
                if !(c.fit.errors.rms <= c.schlick.rms) {
                    check.fail(format!(
                        "{name}: the fit's RMS {:.3e} exceeds Schlick's {:.3e}",
                        c.fit.errors.rms, c.schlick.rms
                    ));
                }
            }
            Err(e) => check.fail(format!("{name}: the fit failed: {e:?}")),
        }
    }
    check
}

/// `interface`'s exact reflectance, its fitted `form` and Schlick, one
/// value per degree.
fn fit_curve(name: &str, interface: Interface, form: &EmpiricalFresnel<f64>) -> FitCurve {
    let angle_deg: Vec<f64> = (0..=90).map(f64::from).collect();
    let at = |f: &dyn Fn(f64) -> f64| -> Vec<f64> {
        angle_deg.iter().map(|a| f(a.to_radians().cos())).collect()
    };
    FitCurve {
        label: name.to_owned(),
        exact: at(&|c| interface.reflectance(c)),
        fitted: at(&|c| empirical_fresnel::reflectance(form, c)),
        schlick: at(&|c| interface.schlick(c)),
        form: [form.bias, form.scale, form.power],
        angle_deg,
    }
}

/// The projected shadow against the tracer: over a grid of lights, planes
/// and vertices, the matrix's point is where the tracer's ray from the
/// light through the vertex meets the plane (`tracer::geometry::Plane`, in
/// `f32`), and it is `Cast` exactly when the vertex lies before that hit; where the
/// matrix puts the point behind the light, the ray misses the plane.
pub fn check_projected_shadow() -> Check {
    const RELATIVE: f64 = 1e-4;
    let mut check = Check::new(
        "techniques.planar.shadow",
        "The slides' projected-shadow matrix against the tracer's ray–plane intersection",
        "tracer::geometry::Plane::intersect (f32) on the ray from the light through the vertex",
        &format!("the points within {RELATIVE:e} of the distance, relative; Cast exactly when the vertex comes first"),
    );
    let normals = [
        DVec3::Y,
        DVec3::new(0.3, 1.0, -0.2),
        DVec3::new(-1.0, 0.5, 0.4),
    ];
    for (k, normal) in normals.into_iter().enumerate() {
        let plane = Plane::through(DVec3::new(0.0, -1.0, 0.0), normal).expect("a plane");
        let traced_plane = tracer::geometry::Plane {
            point: plane.point().as_vec3(),
            normal: plane.normal().as_vec3(),
            material: 0,
        };
        for light in [DVec3::new(0.0, 4.0, 0.0), DVec3::new(2.0, 3.0, -1.0)] {
            for vertex in [
                DVec3::new(0.3, 1.0, 0.2),
                DVec3::new(-1.5, 0.5, 2.0),
                DVec3::new(1.0, 2.5, -0.5),
            ] {
                check.cases += 1;
                let at = format!("plane {k}, light {light}, vertex {vertex}");
                let towards = (vertex - light).as_vec3().normalize();
                let ray = tracer::geometry::Ray::new(light.as_vec3(), towards);
                let hit = traced_plane.intersect(&ray, 0.0);
                match (planar::project_shadow(light, &plane, vertex), hit) {
                    (Shadow::Cast(p) | Shadow::BeyondPlane(p), Some(hit)) => {
                        let traced = hit.point.as_dvec3();
                        let distance = (traced - light).length();
                        let err = (p - traced).length() / distance.max(1.0);
                        check.measure("|matrix − traced| / distance", err, &at);
                        if !(err <= RELATIVE) {
                            check.fail(format!(
                                "{at}: the matrix puts it at {p}, the ray at {traced}"
                            ));
                        }
                        let first = (vertex - light).length() < distance;
                        let cast = matches!(
                            planar::project_shadow(light, &plane, vertex),
                            Shadow::Cast(_)
                        );
                        if first != cast {
                            check.fail(format!("{at}: Cast is {cast}, the vertex first {first}"));
                        }
                    }
                    // The line meets the plane behind the light, or never:
                    // the ray from the light through the vertex misses it.
                    (Shadow::BehindLight(_) | Shadow::Parallel, None) => {}
                    (outcome, hit) => check.fail(format!(
                        "{at}: {outcome:?}, but the ray hits at {:?}",
                        hit.map(|h| h.point)
                    )),
                }
            }
        }
    }
    check
}

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
        "Environment maps (lat-long, cube, sphere): a direction back from its texel",
        "the direction itself; the slides' cube-map example worked by hand (−Z, u = 29/42, v = 11/56)",
        &format!(
            "{ENVMAP_ROUND_TRIP:.2e} rad (lat-long, cube), 32 ε / m rad up to 4 √ε (sphere, m = |r + e|), the example to 4 ε"
        ),
    );
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let spread = (0..4096).map(|i| {
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
    let angle = |a: Direction, b: Direction| refraction::angle_between(a.get(), b.get());
    for v in spread.chain(special) {
        let Ok(r) = Direction::new(v) else {
            check.fail(format!("{v}: refused as a direction"));
            continue;
        };
        check.cases += 1;
        let at = format!("{v}");
        let lat = LatLong::from_direction(r);
        match LatLong::from_uv(lat.u(), lat.v()) {
            Ok(back) => check.measure(
                "lat-long: angle back (rad)",
                angle(r, back.direction()),
                &at,
            ),
            Err(e) => check.fail(format!("lat-long {at}: its own texel refused: {e:?}")),
        }
        let cube = CubeTexel::from_direction(r);
        match CubeTexel::from_uv(cube.face(), cube.u(), cube.v()) {
            Ok(back) => check.measure("cube: angle back (rad)", angle(r, back.direction()), &at),
            Err(e) => check.fail(format!("cube {at}: its own texel refused: {e:?}")),
        }
        match SphereTexel::from_direction(r) {
            SphereTexel::Disc(texel) => match SphereTexel::from_uv(texel.u(), texel.v()) {
                Ok(back) => {
                    let off = angle(r, back.direction());
                    check.measure("sphere: angle back (rad)", off, &at);
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
    for map in ["lat-long", "cube"] {
        if let Some(m) = check.worst(&format!("{map}: angle back (rad)")) {
            if !(m.worst <= ENVMAP_ROUND_TRIP) {
                check.fail(format!("{map}: {} comes back {:e} rad off", m.at, m.worst));
            }
        }
    }
    let example = CubeTexel::from_direction(
        Direction::new(DVec3::new(-3.2, 5.1, -8.4)).expect("a direction"),
    );
    check.cases += 1;
    let off = (example.u() - 29.0 / 42.0)
        .abs()
        .max((example.v() - 11.0 / 56.0).abs());
    check.measure(
        "the slides' example: |uv − worked by hand|",
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
    check
}

/// Every technique's check, and the curves they measured; `glass` the
/// dispersing glass (N-BK7 in the suite; a parameter so that a wrong one
/// can be shown to be caught).
pub fn check_all(glass: &Sellmeier) -> (Vec<Check>, TechniqueCurves) {
    let mut curves = TechniqueCurves::default();
    let checks = vec![
        check_envmap(),
        check_sellmeier(glass),
        check_prism(glass),
        check_cheap_refraction(&mut curves.refraction),
        check_empirical_fresnel(&mut curves.fresnel_fits),
        check_projected_shadow(),
    ];
    (checks, curves)
}
