import json

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.evaluation import held_out as evaluation
from facesynth.domain.evaluation.bootstrap import paired_difference, resamples
from facesynth.domain.search import tuning
from facesynth.domain.speech.utterance import Utterance
from facesynth.stages import tune


def test_report_has_numbers_per_method_and_plots(tiny_db, tiny_artifacts, tmp_path):
    r = CliRunner().invoke(main, ["evaluate", str(tiny_db), "--heldout", str(tiny_artifacts["corpus"]), "-o", str(tmp_path / "rep"),
                                  "--set", "evaluate.bootstrap_resamples=100"])  # point values and files are tested, not the intervals
    assert r.exit_code == 0, r.output
    m = json.loads((tmp_path / "rep" / "metrics.json").read_text())
    assert set(m) >= {"dp", "mean_per_phone", "meta"}
    for method in ("dp", "mean_per_phone"):
        overall = m[method]["overall"]
        assert overall["sentences"] == 4 and overall["rms_mm"] > 0
        assert overall["total_err_mm2"] == pytest.approx(sum(s["err_mm2"] for s in m[method]["per_sentence"]))
        assert set(m[method]["per_emotion"]) == {"neutral", "happy", "angry", "sad"}
    index = (tmp_path / "rep" / "index.html").read_text()
    pngs = list((tmp_path / "rep").glob("*.png"))
    assert len(pngs) == 4 and all(p.name in index for p in pngs)
    # the report and the printed output end with the recommendation, the one its own intervals give
    sentence = m["figures_meta"]["recommendation"]["sentence"]
    figures = {row: m[row]["figures"] for row in m if isinstance(m[row], dict) and "figures" in m[row]}
    draws = resamples(4, 100, 0)  # the report's resamples: 4 sentences, 100 draws, evaluate.seed

    def difference(key, other, best):  # from the per-sentence errors the report lists
        stat = evaluation.FIGURES[key][1]
        return paired_difference(stat(m[other]["per_sentence"]), stat(m[best]["per_sentence"]), 4, draws)

    assert sentence == evaluation.recommend(figures, difference=difference).sentence
    assert sentence.startswith("Recommended for this database: ")
    assert r.output.rstrip("\n").splitlines()[-1] == sentence
    assert (tmp_path / "rep" / "table.md").read_text().rstrip("\n").splitlines()[-1] == sentence
    assert index.rstrip().endswith(f"<p><b>{sentence}</b></p>")


def test_evaluate_scores_the_methods_it_is_asked_for(tiny_db, tiny_artifacts, tmp_path):
    r = CliRunner().invoke(main, ["evaluate", str(tiny_db), "--heldout", str(tiny_artifacts["corpus"]), "-o", str(tmp_path / "rep"),
                                  "--set", "evaluate.bootstrap_resamples=100", "--set", "evaluate.methods=['mean']"])
    assert r.exit_code == 0, r.output
    m = json.loads((tmp_path / "rep" / "metrics.json").read_text())
    # dp always (the paired differences are dp minus each), the mean method with its per-phone variant
    assert set(m) - {"figures_meta", "meta"} == {"dp", "mean", "mean_per_phone", "capture"}
    assert "\nmean: RMS" in r.output
    assert m["figures_meta"]["recommendation"]["method"] in ("dp", "mean")


def test_metrics_worked_by_hand():
    settings = Config.load().settings("evaluate")
    names = ["ULI_C", "LLI_C", "X"]
    truth = np.zeros((10, 3, 3))
    truth[:, 1, 1] = -5.0  # lips 5 mm apart ...
    truth[4:6, 1, 1] = 0.0  # ... closed on the /p/
    syn = truth.copy()
    syn[:, 2, 0] += 2.0  # one marker 2 mm off everywhere
    utt = Utterance(["aa", "p", "aa"], np.array([0.0, 0.04, 0.06]), np.array([0.04, 0.06, 0.1]), ["neutral"] * 3)
    m = evaluation.sentence_metrics(syn, truth, utt, 100.0, names, settings)
    assert m.err_mm2 == pytest.approx(4.0 / 3.0)  # Eq. 13: (2 mm)^2 on one of three markers
    assert m.velocity_rms_mm_s == pytest.approx(0.0)
    assert m.bilabials == 1 and m.lip_closure_rate == 1.0 and m.min_lip_gap_mm == 0.0


def test_missing_split_and_markers_are_named(tiny_db, tiny_artifacts):
    c = Config.load(None, ("evaluate.lip_markers=['NOPE', 'LLI_C']",))
    with pytest.raises(InputError, match="marker 'NOPE' is not in the database"):
        evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], c.settings("evaluate"), c.settings("synthesize"), c.settings("normalize"))


def test_tune_writes_weights_synthesize_accepts(tiny_db, tiny_artifacts, tmp_path):
    c = Config.load(None, ("tune.starts=2", "tune.max_evaluations=8"))
    out = tmp_path / "tuned.toml"
    s = tune.run(tiny_db, tiny_artifacts["corpus"], out, c.settings("tune"), c.settings("synthesize"),
                 c.settings("build_db"), c.settings("normalize"))
    t = s.tuning
    assert t.validation_err_after <= t.validation_err_before  # the search starts from the current weights
    assert t.test_err_after is not None and t.test_sentences == 4
    tuned = Config.load(out).settings("synthesize")
    assert tuned.alpha1 == pytest.approx(t.weights["alpha1"]) and 0 < tuned.alpha4 < 1
    assert "validation error" in out.read_text()


def test_vector_round_trip():
    s = Config.load().settings("synthesize")
    back = tuning.from_vector(tuning.to_vector(s), s)
    for k in tuning.ALPHAS:
        assert getattr(back, k) == pytest.approx(getattr(s, k))


def test_gaps_in_the_capture_are_left_out_of_the_error():
    settings = Config.load().settings("evaluate")
    names = ["ULI_C", "LLI_C", "X"]
    truth = np.zeros((6, 3, 3))
    syn = truth + 1.0
    truth[2:4, 2] = np.nan  # a long gap the normalizer could not fill
    utt = Utterance(["aa"], np.array([0.0]), np.array([0.06]), ["neutral"])
    m = evaluation.sentence_metrics(syn, truth, utt, 100.0, names, settings)
    assert m.err_mm2 == pytest.approx(3.0)  # every seen marker is off by (1, 1, 1) mm; the gap is skipped, not NaN


def test_a_fitted_model_is_given_with_model_and_the_old_option_warns(tiny_db, tiny_artifacts, tiny_trajectory, tmp_path):
    """--model gives any fitted member's model (its kind names the member); --trajectory, its old
    name, still works and says so; a file that is no fitted model is refused naming what to give."""
    base = ["evaluate", str(tiny_db), "--heldout", str(tiny_artifacts["corpus"]), "--set", "evaluate.bootstrap_resamples=100",
            "--set", "evaluate.methods=['trajectory']"]
    r = CliRunner().invoke(main, base + ["--model", str(tiny_trajectory), "-o", str(tmp_path / "new")])
    assert r.exit_code == 0, r.output
    assert "deprecated" not in r.output and "\ntrajectory: RMS" in r.output
    old = CliRunner().invoke(main, base + ["--trajectory", str(tiny_trajectory), "-o", str(tmp_path / "old")])
    assert old.exit_code == 0, old.output
    assert "warning: `--trajectory` is deprecated" in old.output and "`--model`" in old.output
    new_m, old_m = (json.loads((tmp_path / d / "metrics.json").read_text()) for d in ("new", "old"))
    assert new_m["trajectory"]["overall"] == old_m["trajectory"]["overall"]
    bad = CliRunner().invoke(main, base + ["--model", str(tiny_db), "-o", str(tmp_path / "bad")])
    assert bad.exit_code == 1 and "is a motiondb artifact, not a fitted model" in bad.output
    assert "fit-method" in bad.output and not (tmp_path / "bad").exists()


def test_rows_of_earlier_reports_read_under_their_names_now():
    old = {"dp": 1, "baseline": 2, "baseline_emotion": 3, "dominance": 4, "dominance_emotion": 5, "meta": {}}
    assert evaluation.current_rows(old) == {"dp": 1, "mean_per_phone": 2, "mean": 3, "coarticulation_per_phone": 4,
                                            "coarticulation": 5, "meta": {}}
    new = {"dp": 1, "mean": 3}
    assert evaluation.current_rows(new) == new
