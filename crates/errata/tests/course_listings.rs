//! Errata of the course texts that are in the letters of a listing, not in
//! a law: each test reads the lines the table points at and shows what is
//! there, so it fails once the text is put right.

use errata::Text;

/// The lines of a course text, from `shared/seeds/` beside the checkout.
fn lines(text: Text) -> Vec<String> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/seeds")
        .join(text.file_name());
    let body = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    body.lines().map(str::to_owned).collect()
}

/// `003` lines 199, 202 and 265: inside the C-like listings the minus of
/// `n – one`, `one – F0` and `1 – cosa * cosa` is an en dash (U+2013),
/// which no shader compiler reads as an operator; the ASCII minus of the
/// same line 265 (`1 - (`) shows what was meant. No other line of the
/// chapter's code has one.
#[test]
fn course_003_code_minus_signs_are_en_dashes() {
    let text = lines(Text::Textbook);
    let mut in_code = false;
    let mut dashed = Vec::new();
    for (i, line) in text.iter().enumerate() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
        } else if in_code && line.contains('\u{2013}') {
            dashed.push(i + 1);
        }
    }
    assert_eq!(dashed, [199, 202, 265]);
    assert!(text[264].contains("1 - ("), "{}", text[264]);
}

/// `002`: `Sphere spheres;` (line 127) declares one sphere, indexed as an
/// array of seven (lines 159–161); `struct Ray` (lines 64–68) has
/// `origin` and `direction`, yet line 237 writes `ray.depth`; and line 242
/// is an `if` with no statement before its `else` (line 243). None of the
/// three compiles.
#[test]
fn course_002_listing_declares_one_sphere_and_a_field_ray_lacks() {
    let text = lines(Text::WebGl);
    assert_eq!(text[126].trim(), "Sphere spheres;");
    assert!(text[160].contains("spheres[i]"), "{}", text[160]);
    let ray: Vec<&str> = text[63..68].iter().map(|l| l.trim()).collect();
    assert!(ray.iter().all(|l| !l.contains("depth")), "{ray:?}");
    assert_eq!(text[236].trim(), "ray.depth += 1;");
    assert_eq!(text[241].trim(), "if (traceScene(ray, hit))");
    assert_eq!(text[242].trim(), "else");
}

/// `000` lines 624 and 871: the first full shaders add `lightAmbient`
/// alone, where the tutorial's snippet (line 449) adds `lightAmbient *
/// mat.ambient`; between the snippet and the shadow shader (line 1154) no
/// line reads a material's `ambient`, though the shaders declare it
/// (lines 490, 731).
#[test]
fn course_000_early_shaders_add_the_ambient_without_the_material() {
    let text = lines(Text::Tutorial);
    assert!(
        text[448].contains("lightAmbient * mat.ambient"),
        "{}",
        text[448]
    );
    for line in [624, 871] {
        assert_eq!(
            text[line - 1].trim(),
            "totalRadiance += lightAmbient;",
            "line {line}"
        );
    }
    for line in [490, 731] {
        assert!(
            text[line - 1].trim().starts_with("vec3 ambient;"),
            "line {line}"
        );
    }
    let read = (449..1153)
        .filter(|&i| text[i].contains(".ambient"))
        .count();
    assert_eq!(
        read, 0,
        "a material's ambient read between lines 450 and 1153"
    );
}
