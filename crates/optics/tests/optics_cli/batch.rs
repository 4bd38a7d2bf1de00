//! `optics batch`: every law round-trips, and bad lines are reported in order.

use crate::common::{assert_record_fields, batch, batch_bytes, json, number, stderr, ROUND_TRIP};

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

#[test]
fn a_line_that_is_not_utf8_is_its_own_error_and_the_rest_go_on() {
    let input = b"{\"law\":\"f0\",\"n\":1.5}\n\xff\xfe\n{\"law\":\"f0\",\"n\":1.5}\r\nab\xc3\n";
    let (results, output) = batch_bytes(&[], &[], input);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert!(stderr(&output).contains("2 of 4 lines gave errors"));
    assert_eq!(results.len(), 4, "one record per line");
    for good in [&results[0], &results[2]] {
        assert!((number(&good["answer"]) - 0.04).abs() < 1e-15, "{good}");
    }
    for (bad, line, column) in [(&results[1], 2, 1), (&results[3], 4, 3)] {
        assert_eq!(bad["line"], line, "{bad}");
        assert_eq!(bad["error"]["kind"], "not_utf8", "{bad}");
        let message = bad["error"]["message"].as_str().unwrap();
        assert!(message.contains(&format!("column {column}")), "{message}");
    }
}

#[test]
fn a_block_of_four_billion_lines_is_held_only_as_lines_arrive() {
    let request = "{\"law\":\"f0\",\"n\":1.5}\n".repeat(3);
    let (results, output) = batch_bytes(&[], &["--block", "4294967295"], request.as_bytes());
    assert!(
        output.status.success(),
        "{:?}: {}",
        output.status,
        stderr(&output)
    );
    assert_eq!(results.len(), 3);
}

/// Each output line of `optics batch [args]` on the ROUND_TRIP requests,
/// one per law of `optics::law_table::LAWS`, with the given line endings.
fn round_trip_records(args: &[&str], extra: &str) -> Vec<serde_json::Value> {
    let laws: Vec<&str> = ROUND_TRIP
        .iter()
        .map(|(request, _)| {
            let law = &serde_json::from_str::<serde_json::Value>(request).unwrap()["law"];
            optics::law_table::LAWS
                .iter()
                .copied()
                .find(|&name| law == name)
                .expect("a law of the batch")
        })
        .collect();
    let in_order: Vec<&str> = optics::law_table::LAWS
        .iter()
        .copied()
        .filter(|law| laws.contains(law))
        .collect();
    assert_eq!(laws, in_order, "one request per law, in the table's order");
    let input: String = ROUND_TRIP
        .iter()
        .map(|(request, _)| format!("{}{extra}}}\n", request.trim_end_matches('}')))
        .collect();
    let (results, output) = batch_bytes(&[], args, input.as_bytes());
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(results.len(), ROUND_TRIP.len());
    results
}

/// The record without its working, as text: numbers as written, so equal
/// text is equal bits (each number is written in the shortest form that
/// reads back to it).
fn without_steps(record: &serde_json::Value) -> String {
    let mut record = record.clone();
    record.as_object_mut().unwrap().remove("steps");
    record.to_string()
}

#[test]
fn no_steps_gives_empty_steps_and_the_same_numbers_for_every_law() {
    let with = round_trip_records(&[], "");
    let without = round_trip_records(&["--no-steps"], "");
    for (with, without) in with.iter().zip(&without) {
        assert!(!with["steps"].as_array().unwrap().is_empty(), "{with}");
        assert_eq!(without["steps"], serde_json::json!([]), "{without}");
        assert_eq!(without_steps(with), without_steps(without));
    }
}

#[test]
fn a_lines_own_steps_overrides_no_steps_either_way() {
    let with = round_trip_records(&[], "");
    let skipped = round_trip_records(&[], r#", "steps": false"#);
    let wanted = round_trip_records(&["--no-steps"], r#", "steps": true"#);
    for ((with, skipped), wanted) in with.iter().zip(&skipped).zip(&wanted) {
        assert_eq!(skipped["steps"], serde_json::json!([]), "{skipped}");
        assert_eq!(wanted, with, "a line's steps: true against --no-steps");
        assert_eq!(without_steps(with), without_steps(skipped));
    }
}

#[test]
fn a_steps_that_is_not_a_boolean_is_refused_naming_the_field() {
    let input = [
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 0.3, "steps": "yes"}"#,
        r#"{"law": "f0", "steps": 1, "n": 1.5}"#,
        r#"{"steps": null, "law": "critical_angle", "n": 10}"#,
    ]
    .join("\n");
    let (results, output) = batch(&input);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let laws = ["fresnel", "f0", "critical_angle"];
    for ((result, law), given) in
        results
            .iter()
            .zip(laws)
            .zip(["string \"yes\"", "integer `1`", "null"])
    {
        assert_eq!(result["law"], law, "{result}");
        let error = &result["error"];
        assert_eq!(error["kind"], "request", "{result}");
        assert_eq!(error["field"], "steps", "{result}");
        let message = error["message"].as_str().unwrap();
        let expected = format!("steps: invalid type: {given}, expected a boolean");
        assert_eq!(message, expected, "{result}");
    }
}

#[test]
fn a_key_given_twice_is_refused_naming_it_and_the_rest_go_on() {
    // Keeping either value would answer a question the line does not ask
    // unambiguously: `eta` 1.5 or 2.
    let input = [
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 0.3, "eta": 2}"#,
        r#"{"law": "f0", "n": 1.5, "law": "f0"}"#,
        r#"{"law": "f0", "n": 1.5, "steps": true, "steps": true}"#,
        r#"{"eta": 1.5, "eta": 1.5, "law": "fresnel", "cos_i": 0.3}"#,
        r#"{"law": "f0", "n": 1.5}"#,
    ]
    .join("\n");
    let (results, output) = batch(&input);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert_eq!(results.len(), 5);
    for (result, field) in results.iter().zip(["eta", "law", "steps", "eta"]) {
        let error = &result["error"];
        assert_eq!(error["kind"], "request", "{result}");
        assert_eq!(error["field"], field, "{result}");
        let message = error["message"].as_str().unwrap();
        assert_eq!(message, format!("{field}: {}", safe_io::json::TWICE));
    }
    assert_eq!(results[4]["answer"], 0.04, "the next line is evaluated");
}

#[test]
fn a_line_past_the_length_limit_is_one_error_and_the_rest_go_on() {
    let most = optics::batch::MAX_LINE_BYTES;
    // A request padded with white space to `len` bytes.
    let padded = |len: usize| {
        let head = r#"{"law": "f0", "n": 1.5"#;
        format!("{head}{}}}", " ".repeat(len - head.len() - 1))
    };
    let mut input = Vec::new();
    for line in [
        padded(most),
        padded(most + 1),
        r#"{"law": "f0", "n": 1.5}"#.into(),
    ] {
        input.extend_from_slice(line.as_bytes());
        input.extend_from_slice(b"\r\n");
    }
    // A line that never ends: skipped to the end of the input.
    input.extend(std::iter::repeat_n(b'x', 3 * most));
    let (results, output) = batch_bytes(&[], &["--no-steps"], &input);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert_eq!(results.len(), 4, "one record per line");
    for (i, result) in results.iter().enumerate() {
        assert_eq!(result["line"].as_u64().map_or(i + 1, |n| n as usize), i + 1);
        match i {
            0 | 2 => assert_eq!(result["answer"], 0.04, "{result}"),
            _ => assert_eq!(result["error"]["kind"], "line_too_long", "{result}"),
        }
    }
}

/// A request line that spells NaN or an infinity is malformed JSON, and
/// says why, as a scene file does: JSON numbers are finite. Other
/// malformed lines get no such hint.
#[test]
fn a_line_spelling_nan_says_json_numbers_are_finite() {
    let (records, _) = batch(
        "{\"law\":\"fresnel\",\"eta\":NaN,\"cos_i\":1}\n\
         {\"law\":\"fresnel\",\"eta\":-Infinity,\"cos_i\":1}\n\
         {\"law\":\"fresnel\",\"eta\":1.5,\n",
    );
    for record in &records[..2] {
        assert_eq!(record["error"]["kind"], "malformed_json", "{record}");
        let message = record["error"]["message"].as_str().unwrap();
        assert!(
            message.contains("NaN and Infinity are not numbers"),
            "{message}"
        );
    }
    let message = records[2]["error"]["message"].as_str().unwrap();
    assert!(!message.contains("NaN"), "{message}");
}

/// A request naming the bare `schlick` is refused naming its `model` and
/// both forms, and the lines after it go on; each named form answers.
#[test]
fn a_bare_schlick_model_is_refused_naming_the_field_and_the_rest_go_on() {
    let input = [
        r#"{"law": "fresnel", "eta": 1.5, "theta_i_deg": 120, "model": "schlick"}"#,
        r#"{"law": "fresnel", "eta": 1.5, "theta_i_deg": 120, "model": "schlick-incident"}"#,
        r#"{"law": "fresnel", "eta": 1.5, "theta_i_deg": 120, "model": "schlick-rarer"}"#,
    ]
    .join("\n");
    let (results, output) = batch(&input);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let error = &results[0]["error"];
    assert_eq!(error["kind"], "schlick_form_unnamed", "{}", results[0]);
    assert_eq!(error["field"], "model", "{}", results[0]);
    let message = error["message"].as_str().unwrap();
    assert!(
        message.starts_with("model: \"schlick\" names neither"),
        "{message}"
    );
    // Inside glass at 60°: the incident form misses total internal
    // reflection (0.07, to 1e-12), the rarer-medium form gives 1.
    assert!(
        (number(&results[1]["answer"]) - 0.07).abs() <= 1e-12,
        "{}",
        results[1]
    );
    assert_eq!(number(&results[2]["answer"]), 1.0, "{}", results[2]);
}
