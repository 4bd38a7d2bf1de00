//! `optics errata`: the course texts' errata ranked, filtered, one shown,
//! in both languages and as JSON; an unknown id or class refused by name
//! with exit status 1.

use crate::common::{json, optics, stderr, stdout};

#[test]
fn errata_are_ranked_physics_first_and_counted() {
    let record = json(&["errata"]);
    assert_eq!(record["law"], "errata");
    let listed = record["answer"].as_array().expect("the errata");
    let classes: Vec<&str> = listed
        .iter()
        .map(|e| e["class"].as_str().unwrap())
        .collect();
    assert_eq!(classes.first(), Some(&"physics"));
    assert_eq!(classes.last(), Some(&"cosmetic"));
    let order = |c: &str| {
        ["physics", "picture", "cosmetic"]
            .iter()
            .position(|&k| k == c)
    };
    assert!(
        classes.windows(2).all(|w| order(w[0]) <= order(w[1])),
        "{classes:?}"
    );
    let counted: u64 = ["physics", "picture", "cosmetic"]
        .iter()
        .map(|c| record["details"][c].as_u64().unwrap())
        .sum();
    assert_eq!(counted as usize, listed.len());
}

#[test]
fn one_class_and_one_erratum_are_shown_in_either_language() {
    let cosmetic = json(&["errata", "--class", "cosmetic"]);
    let listed = cosmetic["answer"].as_array().unwrap();
    assert!(!listed.is_empty() && listed.iter().all(|e| e["class"] == "cosmetic"));
    let hu = stdout(&optics(&["--lang", "hu", "errata", "003-boxed-refraction"]));
    for label in [
        "hely: 003, 246. sor",
        "írva:",
        "helyesen:",
        "tesztek:",
        "eredmény: fizika",
    ] {
        assert!(hu.contains(label), "{label} not in {hu}");
    }
    for english in ["place:", "written:", "right:", "answer:", "physics"] {
        assert!(!hu.contains(english), "{english} left in {hu}");
    }
    let en = stdout(&optics(&["errata", "003-boxed-refraction"]));
    assert!(en.contains("right: `T = v/n"), "{en}");
}

#[test]
fn an_unknown_id_or_class_is_refused_by_name() {
    for (args, named) in [
        (&["errata", "003-teleport"][..], "ID: "),
        (&["errata", "--class", "severe"][..], "--class: "),
        (
            &["errata", "\u{202e}x\u{7}", "--class", "physics"][..],
            "ID: ",
        ),
    ] {
        let output = optics(args);
        assert_eq!(output.status.code(), Some(1), "{args:?}");
        let message = stderr(&output);
        assert!(
            message.contains(named) && !message.contains("panicked"),
            "{message}"
        );
    }
}
