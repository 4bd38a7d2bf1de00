//! `optics quiz`: the course's quiz answered with the printed answers checked.

use crate::common::{assert_record_fields, json, number, optics, stderr, stdout, ROUND_TRIP};

// The course's quiz (`003`, "Kvíz"): the printed answers are 2.77 %, 2.4,
// 5.74° and 2.5; question 1 marks statements 1–5 true. Tolerances: the exact
// values are 1/36, 12/5, asin(1/10) and 5/2; 1e-12 covers the rounding of a
// dozen operations on numbers of order 1.

#[test]
fn quiz_seed_answers_every_question_with_correct_rounding() {
    let quiz = json(&["quiz", "seed"]);
    assert_record_fields(&quiz);
    let questions = quiz["details"]["questions"].as_array().expect("questions");
    assert_eq!(questions.len(), 5);

    let q1 = &questions[0];
    let verdicts: Vec<bool> = q1["answer"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_bool().unwrap())
        .collect();
    assert_eq!(
        verdicts,
        [true, false, true, true, true, false, false, false, false]
    );
    assert_eq!(
        q1["details"]["agrees_with_printed"], false,
        "statement 2 is printed true"
    );
    assert!(q1["notes"][0].as_str().unwrap().contains("irradiance"));

    let q2 = &questions[1];
    assert!((number(&q2["answer"]) - 1.0 / 36.0).abs() < 1e-12);
    assert_eq!(q2["details"]["agrees_with_printed"], false);
    let note = q2["notes"][0].as_str().unwrap();
    assert!(
        note.contains("truncated") && note.contains("2.78"),
        "{note}"
    );

    let q3 = &questions[2];
    assert!((number(&q3["answer"]) - 2.4).abs() < 1e-12);
    assert_eq!(q3["unit"], "W/(sr m^2)");
    assert_eq!(q3["details"]["agrees_with_printed"], true);

    let q4 = &questions[3];
    assert!((number(&q4["answer"]) - 0.1f64.asin().to_degrees()).abs() < 1e-12);
    assert_eq!(q4["unit"], "deg");
    assert_eq!(q4["details"]["agrees_with_printed"], true);

    let q5 = &questions[4];
    assert!((number(&q5["answer"]) - 2.5).abs() < 1e-12);
    assert_eq!(q5["details"]["agrees_with_printed"], true);
}

#[test]
fn quiz_seed_text_shows_the_working_and_the_corrected_rounding() {
    let output = optics(&["quiz", "seed"]);
    assert!(output.status.success());
    let text = stdout(&output);
    for expected in [
        "Question 1",
        "2.78 %",
        "the printed answer 2.77 % is truncated instead of rounded",
        "L_ref = f_r · E = 0.6 · 4 = 2.4",
        "θc = arcsin(0.1) = 5.73917°",
        "cos δ = N · H = 0.707107",
        "L_ref = f_r · E = 0.625 · 4 = 2.5",
    ] {
        assert!(text.contains(expected), "missing {expected:?} in\n{text}");
    }
}

#[test]
fn quiz_list_names_every_solver_with_an_example() {
    let text = stdout(&optics(&["quiz"]));
    for name in ["seed", "f0", "lambert", "critical-angle", "blinn-phong"] {
        assert!(
            text.contains(&format!("optics quiz {name}")),
            "no example for {name}"
        );
    }
}

#[test]
fn quiz_solvers_match_the_seed_answers() {
    // The quiz's exercises with the flags of ROUND_TRIP below; the last
    // passes ks = 1.41421356, √2 to 9 digits, so its 2.5 holds to 1e-8.
    let expected = [
        ("f0", 1.0 / 36.0, 1e-12),
        ("lambert", 2.4, 1e-12),
        ("critical_angle", 0.1f64.asin().to_degrees(), 1e-12),
        ("blinn_phong", 2.5, 1e-8),
    ];
    for (law, value, tolerance) in expected {
        let (_, args) = ROUND_TRIP
            .iter()
            .find(|(request, _)| request.contains(&format!("\"{law}\"")))
            .expect("a request for every quiz law");
        let record = json(args);
        assert_eq!(record["law"], law);
        assert!(
            (number(&record["answer"]) - value).abs() < tolerance,
            "{law}: {record}"
        );
    }
    let (_, lambert) = ROUND_TRIP
        .iter()
        .find(|(request, _)| request.contains("\"lambert\""))
        .expect("a request of the quiz's Lambert");
    let lambert = json(lambert);
    let steps = lambert["steps"].to_string();
    assert!(
        steps.contains("light_dir has length 5: normalised to (0, 0.6, 0.8)"),
        "{steps}"
    );
}

#[test]
fn hungarian_output_speaks_the_course_language() {
    let text = stdout(&optics(&["--lang", "hu", "quiz", "seed"]));
    for expected in [
        "1. kérdés",
        "eredmény",
        "csonkolva, nem kerekítve",
        "teljes visszaverődés",
    ] {
        assert!(text.contains(expected), "missing {expected:?}");
    }
    // The statements of question 1 are quoted as the course prints them.
    assert!(text.contains("A törésmutató a két közegbeli fénysebességek arányával egyezik meg."));
    let refused = optics(&["--lang", "hu", "fresnel", "--eta", "-1", "--cos-i", "0.5"]);
    assert_eq!(
        stderr(&refused).trim(),
        "hiba: --eta: pozitív törésmutatónak kell lennie, kapott érték: -1"
    );
    let english = stdout(&optics(&["quiz", "seed"]));
    assert!(!english.contains("kérdés"));
}

/// The tokens of a line of working that carry its mathematics: numbers,
/// symbols and formulas, without the Hungarian suffix a number takes
/// (`4-szeres`, `90°-ot`) or the punctuation around it.
fn mathematics(line: &str) -> Vec<String> {
    // A statement of question 1 is quoted as each language prints it (the
    // Hungarian verbatim from the course); only its reason is the suite's.
    let reason = match line.split_once(" — ") {
        Some((_, why)) => why,
        None => line,
    };
    let mut tokens: Vec<String> = reason
        .split_whitespace()
        .map(|token| token.trim_matches(|c: char| "(),;:.".contains(c)))
        .map(|token| match token.rsplit_once('-') {
            Some((head, suffix)) if !head.is_empty() && suffix.chars().all(char::is_alphabetic) => {
                head
            }
            _ => token,
        })
        .map(|token| token.trim_matches(|c: char| "(),;:.".contains(c)))
        // A lone `=` is a word ("equals" in a sentence), not a quantity.
        .filter(|token| *token != "=")
        .filter(|token| {
            token
                .chars()
                .any(|c| c.is_ascii_digit() || "_/=²·ΦθδκπΔ°₁₂⁺".contains(c))
        })
        .map(str::to_owned)
        .collect();
    tokens.sort();
    tokens
}

/// `optics <args>` in English and in Hungarian, line by line.
fn both_languages(args: &[&str]) -> Vec<(String, String)> {
    let english = stdout(&optics(args));
    let mut hungarian_args = vec!["--lang", "hu"];
    hungarian_args.extend_from_slice(args);
    let hungarian = stdout(&optics(&hungarian_args));
    let (en, hu): (Vec<&str>, Vec<&str>) = (english.lines().collect(), hungarian.lines().collect());
    assert_eq!(en.len(), hu.len(), "{english}\n---\n{hungarian}");
    en.into_iter()
        .zip(hu)
        .map(|(e, h)| (e.to_owned(), h.to_owned()))
        .collect()
}

#[test]
fn hungarian_working_has_the_numbers_symbols_and_formulas_of_the_english() {
    // Every line of the working, each note and each reason says the same in
    // both languages: the same numbers, units, symbols and formulas (exact
    // token equality; the numbers are printed by the same formatter).
    let exercises: [&[&str]; 5] = [
        &["quiz", "seed"],
        &[
            "quiz",
            "critical-angle",
            "--n",
            "1.5",
            "--n-outside",
            "1.33",
        ],
        &[
            "quiz",
            "lambert",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,-4",
            "--view-dir",
            "1,2,3",
            "--radiance",
            "5",
            "--kd",
            "0.6",
        ],
        &[
            "quiz",
            "blinn-phong",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,4",
            "--view-dir",
            "0,-4,-3",
            "--radiance",
            "5",
            "--ks",
            "1",
            "--shine",
            "3",
        ],
        &[
            "quiz",
            "blinn-phong",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,4",
            "--view-dir",
            "0,4,3",
            "--radiance",
            "5",
            "--ks",
            "1.41421356",
            "--shine",
            "3",
        ],
    ];
    for args in exercises {
        for (en, hu) in both_languages(args) {
            assert_eq!(mathematics(&en), mathematics(&hu), "\n{en}\n{hu}");
        }
    }
}

#[test]
fn a_working_step_computes_the_formula_it_names_when_a_direction_is_below_the_surface() {
    // The course's BRDFs vanish when the light or the viewer is at or below
    // the surface (N · L ≤ 0 or N · V ≤ 0): the step says so and why, and
    // names no formula of kd whose value it does not print.
    let below = [
        (
            ["lambert", "--light-dir", "0,3,-4", "--view-dir", "1,2,3"],
            "f_r = 0: the light is at or below the surface",
        ),
        (
            ["lambert", "--light-dir", "0,3,4", "--view-dir", "1,2,-3"],
            "f_r = 0: the viewer is at or below the surface (N · V = -0.801784 ≤ 0)",
        ),
        (
            [
                "blinn-phong",
                "--light-dir",
                "0,3,4",
                "--view-dir",
                "0,-4,-3",
            ],
            "f_r = 0: the viewer is at or below the surface (N · V = -0.6 ≤ 0)",
        ),
        (
            ["blinn-phong", "--light-dir", "0,1,0", "--view-dir", "0,1,0"],
            "f_r = 0: the light is at or below the surface",
        ),
    ];
    for (exercise, step) in below {
        let mut args = vec!["quiz"];
        args.extend_from_slice(&exercise);
        args.extend_from_slice(&["--normal", "0,0,1", "--radiance", "5", "--kd", "0.6"]);
        if exercise[0] == "blinn-phong" {
            args.extend_from_slice(&["--ks", "1", "--shine", "3"]);
        }
        let record = json(&args);
        assert_eq!(number(&record["answer"]), 0.0, "{record}");
        assert_eq!(number(&record["details"]["brdf"]), 0.0, "{record}");
        let steps: Vec<&str> = record["steps"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s.as_str().unwrap())
            .collect();
        assert!(steps.iter().any(|s| s.starts_with(step)), "{steps:#?}");
        assert!(
            !steps.iter().any(|s| s.starts_with("f_r = kd")),
            "a step names kd and prints 0: {steps:#?}"
        );
    }
}

#[test]
fn critical_angle_names_the_outside_medium_it_was_given() {
    // Into air (the quiz) the normal points towards the air; into water
    // (n_out = 1.33) there is no air to point to.
    let water = json(&[
        "quiz",
        "critical-angle",
        "--n",
        "1.5",
        "--n-outside",
        "1.33",
    ]);
    let steps = water["steps"].to_string();
    assert!(!steps.contains("air"), "{steps}");
    assert!(
        steps.contains("towards the outside medium (n_out = 1.33)"),
        "{steps}"
    );
    let air = json(&["quiz", "critical-angle", "--n", "10"]);
    assert!(air["steps"].to_string().contains("towards the air"));
}

#[test]
fn quiz_seed_says_the_directional_light_is_given_as_a_radiance_but_is_an_irradiance() {
    // Questions 3 and 5 print the light as 5 W/m^2/st; the laws take 5 W/m²
    // on a surface facing it, which is what makes the answers W/(sr m²).
    let quiz = json(&["quiz", "seed"]);
    for q in [2, 4] {
        let question = &quiz["details"]["questions"][q];
        assert_eq!(number(&question["inputs"]["radiance"]), 5.0);
        assert_eq!(question["unit"], "W/(sr m^2)");
        let notes = question["notes"].to_string();
        assert!(
            notes.contains("5 W/m^2/st") && notes.contains("surface facing it, W/m²"),
            "question {}: {notes}",
            q + 1
        );
    }
}

/// The Lambert exercise needs no view direction (it does not enter a
/// Lambert surface's radiance from above): without `--view-dir` the
/// answer is the quiz's 2.4, the same as with any direction above.
#[test]
fn the_lambert_exercise_needs_no_view_direction() {
    let base = [
        "quiz",
        "lambert",
        "--normal",
        "0,0,1",
        "--light-dir",
        "0,3,4",
        "--radiance",
        "5",
        "--kd",
        "0.6",
    ];
    let without = json(&base);
    assert_eq!(number(&without["answer"]), 2.4);
    assert!(without["steps"]
        .to_string()
        .contains("no view direction is needed"));
    let with = json(&[&base[..], &["--view-dir", "1,2,3"]].concat());
    assert_eq!(without["answer"], with["answer"]);
}
