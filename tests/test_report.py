"""``benchmarks/report.py``: its collection and aggregation on tiny made-up outputs (the
report itself runs the whole pipeline and is not part of the test suite)."""

import importlib.util
import json
from pathlib import Path

import pytest

SPEC = importlib.util.spec_from_file_location("report", Path(__file__).resolve().parents[1] / "benchmarks" / "report.py")
report = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(report)


def overall(rms, lips=1.0):
    return {"sentences": 2, "rms_mm": rms, "err_mm2": rms**2, "velocity_rms_mm_s": 90.0, "lip_closure_rate": lips,
            "lip_closure_rate_capture": 1.0, "min_lip_gap_mm": 0.1, "emotion_agreement": 1.0, "non_captured_joins": 7}


def metrics(dp_rms, base_rms):
    rows = lambda rms: [{"take": "happy_s001", "emotion": "happy", "frames": 100, "err_mm2": rms**2},  # noqa: E731
                        {"take": "sad_s001", "emotion": "sad", "frames": 300, "err_mm2": rms**2}]
    return {m: {"overall": overall(r), "per_emotion": {"happy": overall(r), "sad": overall(r)}, "per_sentence": rows(r)}
            for m, r in (("dp", dp_rms), ("baseline", base_rms))}


def fake_seed(seed, dp_rms, dp_cost):
    rows = lambda dp_rms_s: [{"search": s, "seconds": 0.001 * (i + 1), "jumps": 3, "eq4_cost": dp_cost if s.startswith("DP") else 10.0,  # noqa: E731
                              "rms_mm": dp_rms_s if s.startswith("DP") else 1.5} for i, s in enumerate(report.SEARCHES)]
    return {"seed": seed, "seconds": {k: 1.0 + seed for k in report.STAGES + ("tune",)}, "corpus": {"bytes": 2_000_000},
            "evaluate": metrics(dp_rms, 2.0), "evaluate_tuned": metrics(dp_rms - 0.1, 2.0),
            "prune": {"precision": 0.9, "recall": 1.0}, "pca_explained": 0.98,
            "search": {"tables": [{"rows": rows(1.0)}, {"rows": rows(2.0)}]},
            "tune": {"validation_before": 1.5, "validation_after": 1.4, "alphas": {}, "budget": 4},
            "nodes": 100, "nodes_kept": 95}


def test_summarize_gives_mean_spread_and_t_interval():
    s = report.summarize([1.0, 2.0, 3.0])
    assert (s["mean"], s["std"], s["min"], s["max"], s["n"]) == (2.0, 1.0, 1.0, 3.0, 3)
    # t(0.975, 2 degrees of freedom) = 4.3027; half-width 4.3027 * 1 / sqrt(3) = 2.4841
    assert s["ci"] == pytest.approx([2.0 - 2.4841, 2.0 + 2.4841], abs=1e-4)
    one = report.summarize([5.0])
    assert one["std"] is None and one["ci"] is None


def test_bootstrap_is_deterministic_and_brackets_the_pooled_value():
    rows = [{"frames": f, "dp_err_mm2": d, "baseline_err_mm2": b}
            for f, d, b in ((100, 1.0, 4.0), (200, 1.5, 3.0), (300, 0.5, 2.0), (100, 2.0, 5.0))]
    a, b = report.bootstrap_sentences(rows, resamples=500), report.bootstrap_sentences(rows, resamples=500)
    assert a == b
    # pooled: sqrt((100*1 + 200*1.5 + 300*0.5 + 100*2) / 700) = sqrt(750 / 700)
    assert a["dp_rms_mm"]["value"] == pytest.approx((750 / 700) ** 0.5)
    for key in ("dp_rms_mm", "baseline_rms_mm", "difference_mm"):
        lo, hi = a[key]["ci"]
        assert lo <= a[key]["value"] <= hi
    assert a["difference_mm"]["ci"][0] > 0  # the baseline is worse on every sentence


def test_seed_figures_and_aggregate_over_seeds():
    raws = [fake_seed(0, 1.0, 5.0), fake_seed(1, 1.2, 20.0)]
    f = report.seed_figures(raws[0])
    assert f["eval.gain_mm"] == pytest.approx(1.0)
    assert f["tune.test_before"] == pytest.approx(1.0) and f["tune.test_after"] == pytest.approx(0.81)
    assert f["search.dp_lowest_cost"] == 1.0 and f["search.dp_lowest_rms"] == 0.5  # DP 1.0 and 2.0 against 1.5
    assert f["pca.explained_pct"] == pytest.approx(98.0) and f["corpus.megabytes"] == 2.0
    assert report.seed_figures(raws[1])["search.dp_lowest_cost"] == 0.0  # cost 20 against 10
    agg = report.aggregate(raws)
    q = agg["quality"]["eval.dp.rms_mm"]
    assert q["per_seed"] == [1.0, 1.2] and q["mean"] == pytest.approx(1.1) and q["ci"][0] < 1.1 < q["ci"][1]
    assert agg["sentences"]["sentences"] == 4
    assert agg["seed_timings_s"]["stage.ingest"]["per_seed"] == [1.0, 2.0]
    assert agg["tune"][1]["test_after"] == pytest.approx(1.1**2)
    json.dumps(agg)  # everything is plain JSON


def test_markdown_has_every_section():
    agg = report.aggregate([fake_seed(0, 1.0, 5.0), fake_seed(1, 1.2, 5.0)])
    host = {"processor": "Some CPU", "cores": 2, "usable_cores": 2, "memory_gb": 8.0, "load_average_1min": 0.1,
            "copy_bandwidth_gb_s": 10.0, "opencl": {"device": "cpu", "platform": "PoCL"}}
    phrase = {"phones": 14, "dp_s": 0.06, "read_floor_s": 0.07, "ratio_to_read": 0.86, "read_gb_per_s": 20.0,
              "paper_gpu_s": 50.8, "identical_to_reference": True, "numpy_s": 0.6, "numpy_to_opencl": 10.0}
    startup = {"repeats": 5, "command_to_file_written_s": {"min": 1.1, "median": 1.2},
               "ratio_to_read_floor": {"min": 3.5, "median": 3.8}, "read_floor_s": {"min": 0.3, "median": 0.31}}
    speed = {"dp_table_v": {"nodes": 5548, "matrix_bytes": 123_000_000, "phrases": [phrase]},
             "synthesize_startup": startup,
             "isomap_s": 40.0, "make_demo_s": 80.0,
             "render": {"frames": 300, "video_fps": 30.0, "triangles": 13400, "wall_s": 6.0, "frames_per_s": 50.0,
                        "times_real_time": 1.67}}
    text = report.markdown({"seeds": [0, 1], "preset": "paper", "tune_evaluations": 4, "report_s": 600.0,
                            "host": host, "speed": speed, **agg})
    for heading in ("## Host", "## Quality over 2 seeds", "## Tuning", "## Searches compared", "## Speed"):
        assert heading in text
    assert "| RMS marker error, DP (default weights) | mm | 1.100 |" in text
    assert "| 14 | 0.060 | 0.070 | 0.86 | 20.0 | 0.600 | 10.0 |" in text
    assert "3.50 times (median 3.80) the read floor" in text


def test_method_tables_carry_the_figures_with_intervals():
    cell = {"value": 1.5, "low": 1.2, "high": 1.9}
    ev = metrics(1.0, 2.0)
    ev["dp"]["figures"] = {"rms_clean_mm": cell}
    ev["baseline"]["figures"] = {"rms_clean_mm": cell, "dp_minus.rms_clean_mm": {"value": -0.5, "low": -0.7, "high": -0.3}}
    ev["figures_meta"] = {"skipped": {"openfacefx": "not installed"}}
    methods = report.method_figures([{"seed": 0, "evaluate": ev}])
    assert methods[0]["figures"]["baseline"]["dp_minus.rms_clean_mm"]["value"] == -0.5
    text = "\n".join(report.method_tables(methods))
    assert "| dp | 1.500 [1.200, 1.900] |" in text and "| dp − baseline | -0.500 [-0.700, -0.300] |" in text
    assert "openfacefx not run" in text


def test_publish_replaces_only_the_report_between_its_markers(tmp_path):
    results = tmp_path / "results.md"
    report.publish(results, "## The report\n\nold figures\n")
    assert results.read_text().startswith("# Results\n\n" + report.REPORT_BEGIN + "\n## The report\n")
    hand = "# Results\n\nWritten by hand: 0.27 [0.23, 0.30].\n\n"
    results.write_text(hand + results.read_text().split("\n\n", 1)[1] + "\nAfter, by hand.\n")
    report.publish(results, "## The report\n\nnew figures\n")
    text = results.read_text()
    assert text.startswith(hand + report.REPORT_BEGIN) and text.endswith(report.REPORT_END + "\n\nAfter, by hand.\n")
    assert "new figures" in text and "old figures" not in text
