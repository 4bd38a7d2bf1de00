"""The sampler comparison's arithmetic and its refusals."""
import sampler_variance as sv


def pair(before, after):
    return {"before": {"variance": before[0], "seconds": before[1]},
            "after": {"variance": after[0], "seconds": after[1]}}


def test_efficiency_ratio_is_before_variance_times_time_over_after():
    # A quarter of the variance at twice the time: twice the efficiency.
    r = sv.ratios([pair((4.0, 1.0), (1.0, 2.0))])
    assert r["variance"]["median"] == 0.25
    assert r["time"]["median"] == 2.0
    assert r["efficiency"]["median"] == 2.0


def test_ratios_are_the_median_and_range_over_pairs():
    r = sv.ratios([pair((1.0, 1.0), (v, 1.0)) for v in (0.5, 0.2, 0.3)])
    assert (r["variance"]["median"], r["variance"]["min"], r["variance"]["max"]) == (0.3, 0.2, 0.5)


def test_a_missing_build_is_refused_by_its_flag(tmp_path, capsys):
    missing = str(tmp_path / "no-such-optics")
    assert sv.main(["--before", missing, "--after", missing, "--out", str(tmp_path / "o.json")]) == 1
    assert "--before" in capsys.readouterr().err
    assert not (tmp_path / "o.json").exists()
