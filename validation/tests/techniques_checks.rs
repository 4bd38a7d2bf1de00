//! `optics validate`'s checks of the slides' techniques: they pass with
//! the suite's N-BK7, a glass a hair off Schott's coefficients fails the
//! data-sheet check, and each rendered check fails with its technique or
//! its scene broken on purpose.

use techniques::bump::HeightField;
use techniques::dispersion::SELLMEIER_N_BK7;
use techniques::empirical_fresnel::{compare, AngleGrid, WATER};
use techniques::refraction::Constant;
use tracer::geometry::Object;
use tracer::render::Image;
use tracer::scene::{GlassShortcut, Scene};
use validation::techniques::dispersion::three_etas;
use validation::techniques::envmap_vs_traced::{self, Comparison, Resolution, Surroundings};
use validation::techniques::{
    bump_scene, check_all, check_bump_render, check_cheap_refraction_render,
    check_dispersion_render, check_distance, check_empirical_fresnel_render,
    check_planar_reflection, check_planar_shadow, check_self_reflection, check_sellmeier,
    mirror_scene, render_with_hits, shadow_scene,
};

#[test]
fn every_technique_check_passes() {
    let mut figures = Vec::new();
    let (checks, curves) = check_all(&SELLMEIER_N_BK7, &mut figures);
    assert_eq!(curves.refraction.len(), 4);
    assert_eq!(curves.fresnel_fits.len(), 3);
    assert_eq!(curves.envmap_distance.len(), 2);
    assert_eq!(checks.len(), 14);
    assert_eq!(figures.len(), 8);
    for check in &checks {
        assert!(check.passed(), "{}: {:?}", check.id, check.failures);
    }
    // The slides' c = 1 into water: 10.6° from Snell's law at its worst (59°).
    let cheap = checks
        .iter()
        .find(|c| c.id == "techniques.refraction.cheap")
        .unwrap();
    let worst = cheap
        .worst("into water, c = 1: angle from Snell's law (°)")
        .unwrap();
    assert!((worst.worst - 10.63).abs() < 0.01, "{worst:?}");
}

#[test]
fn a_glass_off_schotts_coefficients_fails_the_data_sheet() {
    let mut glass = SELLMEIER_N_BK7;
    // B1 off by 2e-5 of itself moves n_d by 7e-6, past the printed digits
    // at the e, d and C lines (n_F moves by less).
    glass.b[0] *= 1.0 + 2e-5;
    let check = check_sellmeier(&glass);
    assert!(!check.passed());
    assert_eq!(check.failures.len(), 3, "{:?}", check.failures);
}

/// The three etas with red and blue taken from each other's render.
fn red_and_blue_swapped(scene: &Scene) -> Image {
    let mut image = three_etas(scene);
    for p in &mut image.pixels {
        std::mem::swap(&mut p.x, &mut p.z);
    }
    image
}

#[test]
fn three_etas_with_red_and_blue_swapped_fail_the_dispersion_render() {
    let check = check_dispersion_render(red_and_blue_swapped);
    assert!(!check.passed());
    assert!(
        check.failures[0].contains("no closer than one index"),
        "{:?}",
        check.failures
    );
}

/// The map's surroundings left at one distance while the check moves
/// them: the error cannot fall.
fn surroundings_never_moved(kind: Surroundings, _d: f64, r: Resolution) -> Comparison {
    envmap_vs_traced::one_sphere(kind, 8.0, r)
}

#[test]
fn surroundings_that_never_move_fail_the_distance_check() {
    let check = check_distance(surroundings_never_moved, &mut Vec::new(), &mut Vec::new());
    assert!(!check.passed());
    assert!(
        check.failures.iter().any(|f| f.contains("does not fall")),
        "{:?}",
        check.failures
    );
}

/// A lone mirror where the check asks for two: nothing for the map to
/// miss.
fn one_mirror_for_two(kind: Surroundings, d: f64, r: Resolution) -> Comparison {
    envmap_vs_traced::one_sphere(kind, d, r)
}

#[test]
fn a_lone_mirror_fails_the_self_reflection_check() {
    let check = check_self_reflection(one_mirror_for_two, &mut Vec::new());
    assert!(!check.passed(), "{:?}", check.metrics);
}

/// A renderer whose bumps move the surface (displacement, not bump
/// mapping): each sphere with a sine field grown by its amplitude.
fn displaced(scene: &Scene) -> (Image, Vec<Option<u32>>) {
    let mut scene = scene.clone();
    for (object, bump) in scene.objects.iter_mut().zip(&scene.bumps) {
        if let (Object::Sphere(s), Some(HeightField::Sine { amplitude, .. })) = (object, bump) {
            s.radius += *amplitude as f32;
        }
    }
    render_with_hits(&scene)
}

#[test]
fn bumps_that_move_the_surface_fail_the_bump_render_check() {
    let check = check_bump_render(&bump_scene(), displaced, &mut Vec::new());
    assert!(!check.passed());
    assert!(
        check.failures.iter().any(|f| f.contains("silhouette")),
        "{:?}",
        check.failures
    );
}

/// The floor's reflection matrix with its flip left out (the identity):
/// the second pass draws the objects where they are.
#[test]
fn a_reflection_matrix_without_the_flip_fails_the_planar_reflection_check() {
    let check = check_planar_reflection(
        &mirror_scene(80, 60),
        glam::DMat4::IDENTITY,
        &mut Vec::new(),
    );
    assert!(!check.passed(), "{:?}", check.metrics);
}

/// The shadow matrix of a light moved up by half a metre.
#[test]
fn a_shadow_matrix_from_the_wrong_light_fails_the_planar_shadow_check() {
    let moved = |light: glam::DVec3, plane: &techniques::planar::Plane| {
        techniques::planar::shadow_matrix(light + glam::DVec3::new(0.0, 0.5, 0.0), plane)
    };
    let check = check_planar_shadow(&shadow_scene(80, 60), moved, &mut Vec::new());
    assert!(!check.passed(), "{:?}", check.metrics);
}

#[test]
fn a_cheap_refraction_left_out_fails_its_render_check() {
    let mut figures = Vec::new();
    let check = check_cheap_refraction_render(GlassShortcut::None, &mut figures);
    assert!(!check.passed());
    assert!(check.failures[0].contains("at the rim"), "{check:?}");
}

#[test]
fn the_slides_c_of_one_fails_the_cheap_refraction_render_check() {
    let mut figures = Vec::new();
    let slides = GlassShortcut::CheapRefraction(Constant::Fixed(1.0));
    let check = check_cheap_refraction_render(slides, &mut figures);
    assert!(!check.passed());
    assert!(check.failures[0].contains("at the centre"), "{check:?}");
}

#[test]
fn a_form_fitted_to_water_fails_the_glass_empirical_fresnel_render_check() {
    let mut figures = Vec::new();
    let water = compare(WATER, &AngleGrid::TENTH_OF_A_DEGREE)
        .unwrap()
        .fit
        .form;
    let check = check_empirical_fresnel_render(water, &mut figures);
    assert!(!check.passed());
    assert!(check.failures[0].contains("outside"), "{check:?}");
}
