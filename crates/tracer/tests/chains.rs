//! The chains light → delta surfaces → rough surface that `chains::find`
//! names in each course scene, by material: every scene with a mirror or
//! glass under a light that reaches it has some, the others none, and an
//! enclosure keeps a light's chains inside it.

use tracer::chains::{self, Chain};
use tracer::needs;
use tracer::scene::{self, course_scenes, Scene};

fn load(name: &str) -> Scene {
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    scene::load(std::path::Path::new(&path)).expect(name)
}

/// Each chain as `light → material → … → material`.
fn named(scene: &Scene) -> Vec<String> {
    let needs = needs::analyse(scene, &scene.settings);
    chains::find(scene, &needs)
        .iter()
        .map(|c: &Chain| {
            let mut parts = vec![format!("{} {}", c.kind, c.light)];
            parts.extend(c.via.iter().map(|&m| scene.material_names[m].clone()));
            parts.push(scene.material_names[c.to].clone());
            parts.join(" → ")
        })
        .collect()
}

/// The course scenes that have chains, and their chains; every other
/// course scene has none (the kaleidoscope's light, outside the closed
/// tube, reaches nothing inside it), so a scene added to the list with
/// chains fails here until they are written down.
const CHAINS: &[(&str, &[&str])] = &[
    ("gold_spheres", &["directional 0 → gold → green"]),
    ("kaleidoscope_lit", &["point 0 → gold → green"]),
    (
        "webgl_seven_spheres",
        &[
            "point 0 → gold → ground",
            "point 0 → gold → red",
            "point 0 → gold → green",
            "point 0 → gold → blue",
            "point 0 → silver → ground",
            "point 0 → silver → red",
            "point 0 → silver → green",
            "point 0 → silver → blue",
        ],
    ),
    (
        "glass_spheres",
        &[
            "point 0 → glass → floor",
            "point 0 → glass → wall",
            "point 0 → glass → blue",
            "point 0 → air_in_glass → floor",
            "point 0 → air_in_glass → wall",
            "point 0 → air_in_glass → blue",
        ],
    ),
    (
        "inside_water",
        &[
            "directional 0 → water → ground",
            "directional 0 → water → orange",
            "directional 0 → copper → ground",
            "directional 0 → copper → orange",
        ],
    ),
];

#[test]
fn every_course_scene_names_the_chains_it_has() {
    for (name, _) in CHAINS {
        assert!(
            course_scenes().contains(name),
            "{name} is not a course scene"
        );
    }
    for name in course_scenes() {
        let chains = CHAINS
            .iter()
            .find(|(n, _)| n == name)
            .map_or(&[][..], |(_, c)| c);
        let mut found = named(&load(name));
        let mut want: Vec<String> = chains.iter().map(|s| s.to_string()).collect();
        found.sort();
        want.sort();
        assert_eq!(found, want, "{name} (its chains are listed in CHAINS)");
    }
}

#[test]
fn a_point_light_inside_a_closed_mirror_sphere_reaches_nothing_outside() {
    let scene = scene::parse(
        r#"{
        "version": 1,
        "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" },
        "materials": {
            "gold": { "type": "conductor", "n": [0.17, 0.35, 1.5], "kappa": [3.1, 2.7, 1.9] },
            "floor": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] },
            "ball": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] }
        },
        "objects": [
            { "type": "sphere", "center": [0, 0, 5], "radius": 2, "material": "gold" },
            { "type": "sphere", "center": [0, 0, 5.5], "radius": 0.5, "material": "ball" },
            { "type": "sphere", "center": [0, 0, 20], "radius": 3, "material": "floor" }
        ],
        "lights": [ { "type": "point", "position": [0, 0, 4], "intensity": [1, 1, 1] } ]
    }"#,
    )
    .unwrap();
    // The ball inside is lit through the mirror's inside; the sphere outside is not.
    assert_eq!(named(&scene), ["point 0 → gold → ball"]);
}

#[test]
fn a_scene_of_many_mirrors_is_analysed_without_its_enclosures_and_misses_no_chain() {
    // 400 small gold spheres in a row, a floor and a point light: past the
    // test budget the enclosures are dropped, and every chain is still named.
    let spheres: Vec<String> = (0..400)
        .map(|i| format!(r#"{{ "type": "sphere", "center": [{}, 1, 5], "radius": 0.1, "material": "gold" }}"#, i as f32 * 0.3))
        .collect();
    let text = format!(
        r#"{{
        "version": 1,
        "image": {{ "width": 4, "height": 3 }},
        "camera": {{ "type": "course_pinhole" }},
        "materials": {{
            "gold": {{ "type": "conductor", "n": [0.17, 0.35, 1.5], "kappa": [3.1, 2.7, 1.9] }},
            "floor": {{ "type": "lambert", "albedo": [0.5, 0.5, 0.5] }}
        }},
        "objects": [ {}, {{ "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" }} ],
        "lights": [ {{ "type": "point", "position": [0, 5, 5], "intensity": [1, 1, 1] }} ]
    }}"#,
        spheres.join(", ")
    );
    let scene = scene::parse(&text).unwrap();
    // 400² · 400 enclosures ≫ chains::MAX_TESTS.
    assert!(400f64.powi(3) > chains::MAX_TESTS);
    assert_eq!(named(&scene), ["point 0 → gold → floor"]);
}
