//! The course's shaders, step by step, where the control flow is what is
//! wrong (`radiometry::course::shader_steps`): each test names the source
//! (`000`, `002` in `shared/seeds/`) and shows, by measurement, how the step
//! as written departs from what the shader itself means to compute.

use std::cell::Cell;

use glam::DVec3;
use radiometry::course::{self, Hit002};

const EPS: f64 = f64::EPSILON;

/// `000`: `lightAmbient` (line 1353) times the green material's ambient
/// factor (line 1368).
const GREEN_AMBIENT: [f64; 3] = [0.05 * 0.8, 0.05 * 0.6, 0.05 * 0.4];

/// `000` line 1563, in shadow `radiance = lightAmbient * mat.ambient`: seen
/// in a mirror, the shadowed point replaces what the path gathered (the
/// mirror's `lightAmbient`, line 1540) and ignores the mirror's weight, so a
/// mirror reflecting nothing (weight 0) shows it as brightly as none at
/// all. The lit branch, and the tutorial's sum "ambient + diffuse +
/// specular" (line 424), add `weight ·` the surface's terms to what was
/// gathered. Exact: the assignment copies, and the sums below are of two
/// roundings each, compared with a margin of thousands of ulps.
#[test]
fn course_000_shadowed_hit_seen_in_a_mirror_discards_the_path_and_ignores_its_weight() {
    let gathered = [0.05; 3]; // one mirror bounce's lightAmbient
    for weight in [[0.0; 3], [0.5; 3], [1.0; 3]] {
        let shown = course::rough_hit_000(gathered, weight, true, GREEN_AMBIENT, [0.0; 3]);
        assert_eq!(
            shown, GREEN_AMBIENT,
            "the same whatever the mirror reflects"
        );
        for c in 0..3 {
            let meant = gathered[c] + weight[c] * GREEN_AMBIENT[c];
            assert!(shown[c] != meant && (shown[c] - meant).abs() > 1e3 * EPS);
        }
    }
    // The lit branch does weight the surface by the mirror: a black mirror
    // shows nothing more than it gathered.
    let lit = course::rough_hit_000(gathered, [0.0; 3], false, GREEN_AMBIENT, [0.3; 3]);
    assert_eq!(lit, gathered);
}

/// `000` lines 1151–1185 and 1560–1594: the ambient term only in shadow.
/// A lit point of the green material (`kd = (0.1, 0.8, 0.3)`, line 1369)
/// under the white light gets `kd cos θ` alone away from the highlight,
/// which in red is below the shadow's `0.05 · 0.8 = 0.04` wherever
/// `cos θ < 0.4`: near the terminator the lit surface is darker than its
/// own shadow, and removing the occluder darkens it. With the ambient term everywhere (line 424) lit is
/// never darker than shadowed. Margins: at `cos θ = 0.39` red is 0.039
/// against 0.04, a thousand-fold above rounding.
#[test]
fn course_000_lit_point_near_the_terminator_is_darker_than_its_shadow() {
    let kd = [0.1, 0.8, 0.3];
    let shadowed = course::rough_hit_000([0.0; 3], [1.0; 3], true, GREEN_AMBIENT, [0.0; 3]);
    for cos in [0.01, 0.1, 0.2, 0.3, 0.39] {
        let direct = kd.map(|k| k * cos);
        let lit = course::rough_hit_000([0.0; 3], [1.0; 3], false, GREEN_AMBIENT, direct);
        assert!(
            shadowed[0] - lit[0] >= 0.0009,
            "cos θ = {cos}: lit red {} vs shadowed {}",
            lit[0],
            shadowed[0]
        );
        // Meant: ambient + direct, brighter than the shadow's ambient alone.
        assert!(GREEN_AMBIENT[0] + direct[0] > shadowed[0]);
    }
    // From cos θ = 0.4 on, red is lit at least as brightly as the shadow.
    let direct = kd.map(|k| k * 0.41);
    let lit = course::rough_hit_000([0.0; 3], [1.0; 3], false, GREEN_AMBIENT, direct);
    assert!(lit[0] > shadowed[0]);
}

/// A hit of the `002` loop; its position and normal matter only to the
/// reflected direction, which the scripted trace below ignores.
fn hit(colour: DVec3, reflectance: f64) -> Hit002<DVec3> {
    Hit002 {
        position: DVec3::ZERO,
        normal: DVec3::Y,
        colour,
        reflectance,
    }
}

/// The recursion `002` describes (line 52: the reflectance says "how much
/// the new hit contributes"): `L = (1 − r) c + r L_next` along the path,
/// folded from its far end.
fn recursive_mix(path: &[Hit002<DVec3>]) -> DVec3 {
    let (last, earlier) = path.split_last().unwrap();
    earlier.iter().rev().fold(last.colour, |next, h| {
        h.colour * (1.0 - h.reflectance) + next * h.reflectance
    })
}

/// `002` line 247, `color = mix(color, color2, r)` over `MAX_DEPTH = 3`
/// passes (line 96): the red sphere (reflectance 0.1, line 135) reflects a
/// half-mirror that reflects a matte blue surface (reflectance 0, as the
/// ground's, line 155). The loop gives the blue `r₁ = 0.5`; the recursion
/// `r₀ r₁ = 0.05`: a sphere reflecting 10 % shows half of what its
/// reflection reflects. Tolerance 8ε: two `mix`es of numbers ≤ 1.
#[test]
fn course_002_second_reflection_is_weighted_by_its_own_reflectance_not_the_path_product() {
    let (r0, r1) = (0.1, 0.5);
    let (c0, c1, c2) = (
        DVec3::new(0.7, 0.0, 0.0),
        DVec3::new(0.0, 0.6, 0.0),
        DVec3::Z,
    );
    let path = [hit(c0, r0), hit(c1, r1), hit(c2, 0.0)];
    let calls = Cell::new(0);
    let scripted = |_origin: DVec3, _direction: DVec3| {
        calls.set(calls.get() + 1);
        path.get(calls.get()).copied()
    };
    let as_written =
        course::reflection_loop_002(DVec3::new(0.0, -0.6, 0.8), path[0], 3, 1e-4, scripted);
    assert_eq!(calls.get(), 2, "the matte surface ends the path");
    let written_closed = (c0 * (1.0 - r0) + c1 * r0) * (1.0 - r1) + c2 * r1;
    assert!(
        (as_written - written_closed).length() <= 8.0 * EPS,
        "{as_written}"
    );
    let meant = recursive_mix(&path);
    assert!((meant - (c0 * (1.0 - r0) + (c1 * (1.0 - r1) + c2 * r1) * r0)).length() <= 8.0 * EPS);
    assert!((as_written.z - 0.5).abs() <= 8.0 * EPS && (meant.z - 0.05).abs() <= 8.0 * EPS);
}

/// `002` lines 142–179 and 226–251: after a miss `traceScene` has written
/// only `hit.t`, and the loop carries on from the old hit. A black
/// half-mirror on the ground (y = 0, reflectance 0.5) seen at 45°: its
/// reflection leaves the scene, showing the clear colour `R` (the ray's
/// direction, line 244), so the recursion gives `0.5 R` at any depth. The
/// loop reflects `R` back into the incoming direction about the stale
/// normal, hits the same mirror from `EPS` above it and mixes its black in
/// again: `0.5 R`, `0.25 R`, `0.625 R` for `MAX_DEPTH` 1, 2, 3 (the
/// listing's 3). Tolerance 16ε: a few `mix`es and reflections of unit vectors.
#[test]
fn course_002_a_reflection_that_leaves_the_scene_is_mixed_again_with_its_own_surface() {
    let mirror = |position: DVec3| Hit002 {
        position,
        normal: DVec3::Y,
        colour: DVec3::ZERO,
        reflectance: 0.5,
    };
    // The ground mirror, hit from above; nothing else in the scene.
    let ground = |origin: DVec3, direction: DVec3| {
        (direction.y < 0.0 && origin.y > 0.0)
            .then(|| mirror(origin + direction * (-origin.y / direction.y)))
    };
    let incoming = DVec3::new(0.0, -1.0, 1.0).normalize();
    let first = ground(DVec3::new(0.0, 1.0, -1.0), incoming).unwrap();
    let sky = DVec3::new(0.0, 1.0, 1.0).normalize(); // R, the clear colour
    for (depth, factor) in [(1, 0.5), (2, 0.25), (3, 0.625)] {
        let as_written = course::reflection_loop_002(incoming, first, depth, 1e-4, ground);
        assert!(
            (as_written - sky * factor).length() <= 16.0 * EPS,
            "MAX_DEPTH {depth}: {as_written}"
        );
        let meant = recursive_mix(&[first, hit(sky, 0.0)]);
        assert!((meant - sky * 0.5).length() <= 16.0 * EPS);
    }
}

/// `000` lines 1944–1977: `intersectMirrors` starts from `Hit closestHit;`,
/// never initialised (GLSL leaves it undefined; `intersectScene` sets
/// `finalHit.didHit = false` first, line 1991), and compares every plane
/// hit with it. Its answer depends on what that memory held: clear, the
/// kaleidoscope's triangle (`numSides = 3`, size 2.5, lines 1935, 1950)
/// is found where it is; holding an earlier hit nearer than the mirrors,
/// every mirror is hidden and that leftover comes back as the mirror hit.
/// The ray: the camera (line 1807) through the image point (0.4, 0.3),
/// which meets the mirror whose outward normal is (1/2, √3/2) at
/// `t = 1.25 / (n · d)`. Tolerance 1e-9 relative: the listing's π is
/// 5.9e-10 short, which turns the mirror by about 2e-10 rad and moves `t`
/// by 2.6e-10 relative here; rounding adds a few ε.
#[test]
fn course_000_mirror_search_depends_on_an_uninitialised_hit() {
    let origin = DVec3::new(0.0, 0.0, -2.0);
    let direction = (DVec3::new(0.4, 0.3, 0.0) - origin).normalize();
    let search = |before| course::intersect_mirrors_000(origin, direction, 3, 2.5, before);
    let clear = search(course::MirrorHit000 {
        distance: 0.0,
        did_hit: false,
    });
    let normal = DVec3::new(0.5, 3f64.sqrt() / 2.0, 0.0);
    let expected = 1.25 / normal.dot(direction);
    assert!(clear.did_hit);
    assert!(
        (clear.distance / expected - 1.0).abs() <= 1e-9,
        "{clear:?} vs {expected}"
    );
    let leftover = course::MirrorHit000 {
        distance: 0.5,
        did_hit: true,
    };
    assert_eq!(search(leftover), leftover, "the mirrors are hidden");
}

/// `002` line 193, "Phong shading with 0.2 min. ambient contribution",
/// `s = max(0.2, dot(L, N))`: a floor, not an added term. A lit point
/// whose light comes in at `cos θ = 0.1` is shown exactly as its own shadow
/// (line 198, `s = 0.2`), and a point lit head-on gets its diffuse colour
/// with no ambient added, where "ambient + diffuse" gives `0.2 + cos θ`.
/// Exact: one product by the same factor on both sides.
#[test]
fn course_002_ambient_floor_is_a_max_not_an_added_term() {
    let red = DVec3::new(0.7, 0.0, 0.0); // the first sphere, line 134
    let light = |cos: f64| DVec3::new((1.0 - cos * cos).sqrt(), cos, 0.0) * 10.0;
    let grazing = course::shade_002(red, DVec3::ZERO, DVec3::Y, light(0.1), false);
    let shadowed = course::shade_002(red, DVec3::ZERO, DVec3::Y, light(0.1), true);
    assert_eq!(grazing, shadowed, "lit at cos θ = 0.1 and in shadow");
    let head_on = course::shade_002(red, DVec3::ZERO, DVec3::Y, DVec3::Y * 10.0, false);
    assert_eq!(head_on, red, "no ambient added to a lit point");
    let added = red * (0.2 + 1.0);
    assert!((added - head_on).length() > 0.1, "{added} vs {head_on}");
}

/// `002` lines 186–193: the point light `light0` sets only the direction
/// `L`; nothing divides by the distance. Two points on one normal, 1 m and
/// 2 m below the light, are shaded alike, where the inverse-square law
/// (`radiometry::radiance::point_irradiance`) gives the nearer four times
/// the irradiance. Tolerance 4ε on the law's ratio: two divisions by a
/// squared distance that is exact here.
#[test]
fn course_002_point_light_does_not_fall_off_with_distance() {
    use radiometry::radiance::point_irradiance;
    let grey = DVec3::splat(0.6); // the ground, line 154
    let light = DVec3::new(0.0, 4.0, 0.0);
    let (near, far) = (DVec3::new(0.0, 3.0, 0.0), DVec3::new(0.0, 2.0, 0.0));
    let shown_near = course::shade_002(grey, near, DVec3::Y, light, false);
    let shown_far = course::shade_002(grey, far, DVec3::Y, light, false);
    assert_eq!(
        shown_near, shown_far,
        "the course's shading ignores distance"
    );
    let e = |p| {
        point_irradiance(1.0, light, p, DVec3::Y)
            .unwrap()
            .irradiance
    };
    let ratio = e(near) / e(far);
    assert!((ratio - 4.0).abs() <= 4.0 * EPS * 4.0, "{ratio}");
}

/// `002` lines 230–247: the reflection is mixed in by the material's
/// constant `reflectance`, whatever the angle. A half-mirror seen head-on
/// and at 85° from its normal mixes in the same share of what it reflects,
/// where the Fresnel reflectance of glass (`n = 1.5`) is 4 % head-on and
/// several times that at 85°. Exact for the course's mix: the same
/// arithmetic at both angles; the law's values within 1e−12 of the
/// references `radiometry::fresnel::dielectric` is checked against.
#[test]
fn course_002_reflection_is_weighted_alike_at_every_angle() {
    use radiometry::fresnel::dielectric;
    let mirror = |_: DVec3| Hit002 {
        position: DVec3::ZERO,
        normal: DVec3::Y,
        colour: DVec3::new(0.2, 0.2, 0.2),
        reflectance: 0.5,
    };
    let beyond = Hit002 {
        position: DVec3::new(0.0, 10.0, 0.0),
        normal: -DVec3::Y,
        colour: DVec3::new(1.0, 0.0, 0.0),
        reflectance: 0.0,
    };
    let grazing = 85.0_f64.to_radians();
    let shown: Vec<DVec3> = [-DVec3::Y, DVec3::new(grazing.sin(), -grazing.cos(), 0.0)]
        .into_iter()
        .map(|d| course::reflection_loop_002(d, mirror(d), 1, 1e-4, |_, _| Some(beyond)))
        .collect();
    assert_eq!(shown[0], shown[1], "the same mix head-on and at 85°");
    let (head_on, at_85): (f64, f64) = (dielectric(1.0, 1.5), dielectric(grazing.cos(), 1.5));
    assert!((head_on - 0.04).abs() < 1e-12, "{head_on}");
    assert!(at_85 > 5.0 * head_on, "{at_85}");
}
