//! `optics batch`: every law round-trips, and bad lines are reported in order.

use crate::common::{assert_record_fields, batch, json, number, stderr, ROUND_TRIP};

#[test]
fn batch_results_equal_the_subcommands_json_output() {
    let input: String = ROUND_TRIP
        .iter()
        .map(|(request, _)| format!("{request}\n"))
        .collect();
    let (results, output) = batch(&input);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(results.len(), ROUND_TRIP.len());
    for ((request, args), result) in ROUND_TRIP.iter().zip(&results) {
        assert_record_fields(result);
        assert_eq!(
            *result,
            json(args),
            "batch {request} differs from optics --json {args:?}"
        );
    }
}

#[test]
fn batch_reports_a_bad_line_and_goes_on_in_order() {
    let input = [
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 1}"#,
        r#"{"law": "fresnel", "eta": "glass", "cos_i": 1}"#,
        "not json",
        "",
        r#"{"law": "teleport", "eta": 1}"#,
        r#"{"eta": 1.5}"#,
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 1, "colour": "red"}"#,
        r#"{"law": "refract", "wi": [0, 0, 0], "normal": [0, 0, 1], "eta": 1.5}"#,
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 0.5}"#,
    ]
    .join("\n");
    let (results, output) = batch(&input);
    assert_eq!(output.status.code(), Some(1), "some lines failed");
    assert!(stderr(&output).contains("7 of 9 lines gave errors"));
    assert_eq!(results.len(), 9);
    assert!((number(&results[0]["answer"]) - 0.04).abs() < 1e-15);
    // Each bad line: its kind, the field it names (null when none), and a
    // phrase of its message.
    let expected = [
        (2, "request", Some("eta"), "eta: invalid type"),
        (3, "malformed_json", None, "malformed JSON"),
        (4, "empty_line", None, "empty line"),
        (5, "unknown_law", Some("law"), "unknown law \"teleport\""),
        (6, "law_missing", Some("law"), "law: missing"),
        (7, "request", Some("colour"), "unknown field `colour`"),
        (
            8,
            "domain.zero_vector",
            Some("wi"),
            "wi must be a non-zero direction",
        ),
    ];
    for (line, kind, field, message) in expected {
        let result = &results[line - 1];
        assert_eq!(result["line"], line, "{result}");
        let error = &result["error"];
        assert_eq!(error["kind"], kind, "line {line}: {result}");
        assert_eq!(error["field"].as_str(), field, "line {line}: {result}");
        let text = error["message"]
            .as_str()
            .unwrap_or_else(|| panic!("line {line}: {result}"));
        assert!(
            text.contains(message),
            "line {line}: {text:?} lacks {message:?}"
        );
    }
    assert_eq!(results[1]["law"], "fresnel", "a request's law is kept");
    assert!(
        results[2]["law"].is_null(),
        "a line that is not JSON has none"
    );
    assert_eq!(results[8]["law"], "fresnel");
    assert!(results[8]["answer"].is_number());
}
