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
