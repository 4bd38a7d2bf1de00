use super::*;

fn band(low: f64, high: f64) -> TimingNoise {
    TimingNoise {
        labels: vec!["filter box".to_string()],
        ratios: [low, high],
    }
}

#[test]
fn a_timing_band_whose_ends_print_alike_is_one_number() {
    // 0.951 and 0.954 both print as 0.95 at the prose's two decimals.
    for lang in [Lang::En, Lang::Hu] {
        let one = timing(&band(0.951, 0.954), lang);
        assert_eq!(one.matches("0.95").count(), 1, "{one}");
        assert!(!one.contains("to 0.95") && !one.contains("0.95–"), "{one}");
    }
}

#[test]
fn a_timing_band_names_both_its_ends() {
    let en = timing(&band(0.93, 1.04), Lang::En);
    assert!(en.contains("took 0.93× to 1.04× its time"), "{en}");
    let hu = timing(&band(0.93, 1.04), Lang::Hu);
    assert!(hu.contains("0.93–1.04-szeresét"), "{hu}");
}

#[test]
fn the_report_words_each_sweep_s_findings_as_docs_tradeoffs_md_does() {
    // The report is written in English, whatever the command's language.
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let docs = std::fs::read_to_string(root.join("docs/tradeoffs.md")).unwrap();
    let dir = root.join(crate::tradeoff::checks::DIR);
    let records = crate::tradeoff::checks::read(&dir).unwrap();
    assert!(!records.is_empty(), "no record in {}", dir.display());
    for (file, record) in records {
        let record = record.unwrap();
        let findings = record.findings.as_ref().expect("findings recorded");
        let paragraph = format!(
            "**What the numbers say.** {}\n",
            sentences(findings, Lang::En).join(" ")
        );
        assert!(
            docs.contains(&paragraph),
            "{}: the report's words are not docs/tradeoffs.md's: {paragraph}",
            file.display()
        );
    }
}
