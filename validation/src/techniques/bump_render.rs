//! Bump mapping in a render: what the technique changes and what it
//! cannot (`crates/tracer/scenes/bump_sphere.json`, two clay spheres, the
//! left one bumped, over a floor under one point light).

use std::path::Path;

use techniques::bump::HeightField;
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{self, IntegratorKind, Scene};

use super::figure::strip;
use crate::check::Check;
use crate::renders::RenderFigure;

/// The least share of the bumped sphere's pixels whose shading the bumps
/// must change: its lit side (about half its disc) changes almost
/// everywhere, the side lit by the ambient term alone not at all.
pub const CHANGED_SHARE: f64 = 1.0 / 3.0;

/// The scene, `bump_sphere.json`, rendered by Whitted.
pub fn bump_scene() -> Scene {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/tracer/scenes/bump_sphere.json");
    let mut scene = scene::load(&path).expect("the bump scene");
    scene.settings.integrator = IntegratorKind::Whitted;
    scene
}

/// The scene rendered, and which object each pixel's primary ray meets.
pub fn render(scene: &Scene) -> (Image, Vec<Option<u32>>) {
    let job = RenderJob::with_settings(scene.clone(), scene.settings).expect("renderable");
    let hits = job.first_hits();
    (job.render(None, &|_| {}).expect("rendered").image, hits)
}

/// The scene with every bump field replaced by `field` (`None`: none).
fn with_bumps(scene: &Scene, field: Option<HeightField>) -> Scene {
    let mut s = scene.clone();
    for bump in s.bumps.iter_mut().filter(|b| b.is_some()) {
        *bump = field;
    }
    s
}

fn same_bits(a: glam::Vec3, b: glam::Vec3) -> bool {
    a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits)
}

/// What a bump render measures, in English and in Hungarian.
const QUANTITIES: [[&str; 2]; 4] = [
    [
        "flat field: pixels changed",
        "sík mező: megváltozott képpontok",
    ],
    [
        "silhouette: pixels whose first object changed",
        "körvonal: képpontok, amelyeknek első tárgya megváltozott",
    ],
    [
        "off the bumped sphere: pixels changed",
        "a buckás gömbön kívül: megváltozott képpontok",
    ],
    [
        "on the bumped sphere: share of pixels changed",
        "a buckás gömbön: a megváltozott képpontok aránya",
    ],
];

/// The bump-mapped scene against the same scene smooth: a flat field
/// renders bit for bit as none; which object each pixel sees (the
/// silhouettes) is the same to the pixel; the shading changes on the
/// bumped sphere (at more than [`CHANGED_SHARE`] of its pixels) and
/// nowhere else, so the shadows on the floor are the smooth sphere's.
/// `scene` is [`bump_scene`] in the suite, `render` is [`render`] (a
/// parameter, so that a renderer whose bumps move the surface can be
/// shown to be caught).
pub fn check_bump_render(
    scene: &Scene,
    render: fn(&Scene) -> (Image, Vec<Option<u32>>),
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let mut check = Check::new(
        "techniques.bump.render",
        [
            "Bump mapping in a render: shading changes, silhouettes and shadows do not",
            "Buckaleképzés egy képen: az árnyalás változik, a körvonalak és az árnyékok nem",
        ],
        [
            "the same scene without its bump field (Whitted, bump_sphere.json)",
            "ugyanaz a jelenet a buckatere nélkül (Whitted, bump_sphere.json)",
        ],
        [&format!(
            "exact: a flat field changes no bit, the first object seen changes at no pixel, no \
             pixel off the bumped sphere changes; more than {CHANGED_SHARE:.3} of the bumped sphere's pixels change"
        ), &format!("pontos: egy sík mező egyetlen bitet sem változtat, az elsőként látott tárgy egy képpontban sem változik, a buckás gömbön kívül egy képpont sem változik; a buckás gömb képpontjainak több mint {CHANGED_SHARE:.3} része megváltozik")],
    );
    let (smooth, smooth_hits) = render(&with_bumps(scene, None));
    let (flat, _) = render(&with_bumps(scene, Some(HeightField::Flat)));
    let (bumped, bumped_hits) = render(scene);
    figures.push(strip("techniques_bump.png", &bumped, &smooth, 2));
    let bumped_objects: Vec<u32> = (0..scene.bumps.len() as u32)
        .filter(|&i| scene.bumps[i as usize].is_some())
        .collect();
    check.cases = smooth.pixels.len();
    let flat_changed = (0..smooth.pixels.len())
        .filter(|&p| !same_bits(flat.pixels[p], smooth.pixels[p]))
        .count();
    let outline_moved = smooth_hits
        .iter()
        .zip(&bumped_hits)
        .filter(|(a, b)| a != b)
        .count();
    let (mut on, mut changed_on, mut changed_off) = (0usize, 0usize, 0usize);
    for (p, hit) in smooth_hits.iter().enumerate() {
        let changed = !same_bits(bumped.pixels[p], smooth.pixels[p]);
        if hit.is_some_and(|o| bumped_objects.contains(&o)) {
            on += 1;
            changed_on += usize::from(changed);
        } else {
            changed_off += usize::from(changed);
        }
    }
    let share = changed_on as f64 / on.max(1) as f64;
    let values = [
        flat_changed as f64,
        outline_moved as f64,
        changed_off as f64,
        share,
    ];
    let at = format!("{} × {}", scene.width, scene.height);
    for (name, value) in QUANTITIES.into_iter().zip(values) {
        check.measure_in_both(name, value, &at);
    }
    if flat_changed > 0 {
        check.fail(format!("a flat field changes {flat_changed} pixels"));
    }
    if outline_moved > 0 {
        check.fail(format!(
            "the bumps move the silhouette at {outline_moved} pixels"
        ));
    }
    if changed_off > 0 {
        check.fail(format!(
            "the bumps change {changed_off} pixels off the bumped sphere (its shadow, the floor)"
        ));
    }
    if !(share > CHANGED_SHARE) {
        check.fail(format!(
            "the bumps change {changed_on} of the bumped sphere's {on} pixels, not more than {CHANGED_SHARE:.3}"
        ));
    }
    check
}
