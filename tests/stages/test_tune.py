"""``facesynth tune``: the search vector, the Nelder-Mead search on the tiny corpus and its report."""

import csv
import dataclasses

import numpy as np
import pytest

from facesynth import evaluation
from facesynth.config import Config
from facesynth.errors import InputError
from facesynth.stages import tune

#: A budget small enough for the tiny corpus: the initial simplex (7 points) and a step or two.
BUDGET = ("tune.max_evaluations=6", "tune.starts=1")


def _settings(*overrides):
    c = Config.load(None, BUDGET + overrides)
    return c.settings("tune"), c.settings("synthesize"), c.settings("evaluate"), c.settings("normalize")


def _splits(tiny_corpus):
    rows = list(csv.DictReader(open(tiny_corpus / "manifest.csv", encoding="utf-8")))
    return {split: {r["take"] for r in rows if r["split"] == split} for split in ("train", "val", "test")}


# --- the search vector -------------------------------------------------------------------------


def test_vector_is_logs_and_a_logit():
    s = dataclasses.replace(Config.load().settings("synthesize"), alpha1=1.0, alpha2=np.e, alpha3=0.5,
                            alpha4=0.75, alpha5=np.e**2, alpha6=4.0)
    v = tune.to_vector(s)
    # log 1, log e, log 0.5, logit 0.75 = log(0.75 / 0.25) = log 3, log e^2, log 4
    np.testing.assert_allclose(v, [0.0, 1.0, np.log(0.5), np.log(3.0), 2.0, np.log(4.0)], rtol=0, atol=1e-12)


def test_round_trip_keeps_every_alpha_and_the_other_settings():
    s = dataclasses.replace(Config.load().settings("synthesize"), alpha1=1.75, alpha2=0.00123, alpha3=0.856,
                            alpha4=0.552, alpha5=9.37, alpha6=1.54, pnt=123.0, search="greedy")
    back = tune.from_vector(tune.to_vector(s), s)
    for name in tune.ALPHAS:
        assert getattr(back, name) == pytest.approx(getattr(s, name), rel=1e-12), name
    # only the alphas move: PNT sets their scale and is not tuned
    assert dataclasses.replace(back, **{n: getattr(s, n) for n in tune.ALPHAS}) == s


@pytest.mark.parametrize("logit", [-800.0, -40.0, -5.0, 0.0, 5.0, 37.0, 40.0])
def test_alpha4_stays_inside_zero_one_for_any_search_vector(logit):
    s = Config.load().settings("synthesize")
    v = tune.to_vector(s)
    v[3] = logit
    a4 = tune.from_vector(v, s).alpha4
    assert 0.0 < a4 < 1.0  # Table II, rule 2: a discount; 1.0 would be refused by Config.load
    assert a4 > 0.5 if logit > 0 else (a4 < 0.5 if logit < 0 else a4 == 0.5)


def test_a_moved_vector_moves_the_alphas_as_logs():
    s = Config.load().settings("synthesize")
    v = tune.to_vector(s)
    moved = tune.from_vector(v + np.log(2.0) * np.array([1, 0, -1, 0, 0, 1]), s)
    assert moved.alpha1 == pytest.approx(2 * s.alpha1) and moved.alpha3 == pytest.approx(s.alpha3 / 2)
    assert moved.alpha6 == pytest.approx(2 * s.alpha6)
    assert (moved.alpha2, moved.alpha4, moved.alpha5) == pytest.approx((s.alpha2, s.alpha4, s.alpha5))


# --- tuning on the tiny corpus -----------------------------------------------------------------


@pytest.fixture(scope="module")
def tuned(tiny_db, tiny_artifacts, tmp_path_factory):
    """One tune run with the tiny budget, the progress calls it made and the TOML it wrote."""
    settings = _settings()
    calls = []
    out = tmp_path_factory.mktemp("tune") / "tuned.toml"
    summary = tune.run(tiny_db, tiny_artifacts["corpus"], out, *settings, progress_fn=lambda n, e: calls.append((n, e)))
    return summary, calls, out


def test_tuned_validation_error_is_never_above_the_start(tuned):
    summary, calls, _ = tuned
    assert summary["validation_sentences"] == 4 and summary["test_sentences"] == 4
    assert 0 < summary["validation_err_after"] <= summary["validation_err_before"]
    # the first evaluation is the current weights; the reported best is the least of every evaluation
    assert calls[0][1] == summary["validation_err_before"]
    assert summary["validation_err_after"] == min(e for _, e in calls)
    assert [n for n, _ in calls] == list(range(1, summary["evaluations"] + 1))
    assert summary["evaluations"] <= 6  # tune.max_evaluations, shared by the starts


def test_written_toml_loads_back_and_reproduces_the_weights(tuned):
    summary, _, out = tuned
    text = out.read_text(encoding="utf-8")
    assert f"{summary['validation_err_before']:.4f} -> {summary['validation_err_after']:.4f}" in text
    assert f"{summary['test_err_before']:.4f} -> {summary['test_err_after']:.4f}" in text
    loaded = Config.load(out)
    assert {k: getattr(loaded.settings("synthesize"), k) for k in tune.ALPHAS} == summary["alphas"]  # exact: repr
    # only the alphas are written: every other setting, PNT included, stays at its default
    default = Config.load().settings("synthesize")
    assert dataclasses.replace(loaded.settings("synthesize"), **{k: getattr(default, k) for k in tune.ALPHAS}) == default


def test_test_error_is_the_error_on_the_test_takes(tuned, tiny_db, tiny_artifacts):
    summary, _, out = tuned
    _, synth, ev, norm = _settings()
    test_ev = dataclasses.replace(ev, split="test")
    before, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], test_ev, synth, norm, with_baseline=False)
    after, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], test_ev, Config.load(out).settings("synthesize"),
                                   norm, with_baseline=False)
    assert summary["test_err_before"] == pytest.approx(before["dp"]["overall"]["err_mm2"], rel=1e-9)
    assert summary["test_err_after"] == pytest.approx(after["dp"]["overall"]["err_mm2"], rel=1e-9)
    val_ev = dataclasses.replace(ev, split="val")
    on_val, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], val_ev, synth, norm, with_baseline=False)
    assert summary["validation_err_before"] == pytest.approx(on_val["dp"]["overall"]["err_mm2"], rel=1e-9)
    assert summary["test_err_before"] != pytest.approx(summary["validation_err_before"])  # two different sets


def test_the_search_sees_validation_takes_only(tiny_db, tiny_artifacts, tiny_corpus, monkeypatch):
    splits = _splits(tiny_corpus)
    seen = []
    real = evaluation.evaluate

    def spy(*args, sentences=None, **kwargs):
        seen.append({s.take for s in sentences})
        return real(*args, sentences=sentences, **kwargs)

    monkeypatch.setattr(tune, "evaluate", spy)
    summary = tune.tune(tiny_db, tiny_artifacts["corpus"], *_settings(), progress_fn=None)
    assert splits["val"] and splits["test"] and not splits["val"] & splits["test"]
    # every search evaluation, then the test error before and after: the test takes only twice, at the end
    assert seen[:-2] == [splits["val"]] * summary["evaluations"]
    assert seen[-2:] == [splits["test"]] * 2


def test_same_seed_same_result_with_random_starts(tiny_db, tiny_artifacts, monkeypatch):
    real = evaluation.evaluate

    def run(seed):
        tried = []

        def spy(db_path, corpus, settings, synth, *args, **kwargs):
            tried.append(tuple(getattr(synth, k) for k in tune.ALPHAS))
            return real(db_path, corpus, settings, synth, *args, **kwargs)

        monkeypatch.setattr(tune, "evaluate", spy)
        summary = tune.tune(tiny_db, tiny_artifacts["corpus"],
                            *_settings("tune.starts=2", "tune.max_evaluations=8", f"tune.seed={seed}"))
        summary.pop("seconds")
        return summary, tried

    (first, tried_first), (again, tried_again), (_, tried_other) = run(3), run(3), run(4)
    assert first == again and tried_first == tried_again
    assert first["evaluations"] <= 8
    # the first start is the current weights whatever the seed; the second is drawn from the seed
    current = tuple(getattr(_settings()[1], k) for k in tune.ALPHAS)
    assert tried_first[0] == tried_other[0] == pytest.approx(current, rel=1e-12)
    assert set(tried_first) != set(tried_other)


@pytest.mark.parametrize("name", tune.ALPHAS)
def test_non_positive_alphas_are_refused_by_name(tiny_db, tiny_artifacts, name):
    t, synth, ev, norm = _settings()
    zero = dataclasses.replace(synth, **{name: 0.0})
    with pytest.raises(InputError, match=rf"synthesize\.{name} must be positive to tune it \(got 0\.0\)"):
        tune.tune(tiny_db, tiny_artifacts["corpus"], t, zero, ev, norm)


def test_refusal_comes_before_any_file_is_read(tmp_path):
    t, synth, ev, norm = _settings()
    negative = dataclasses.replace(synth, alpha2=-1.0)
    # the database does not exist: the settings are checked first
    with pytest.raises(InputError, match=r"synthesize\.alpha2 must be positive"):
        tune.tune(tmp_path / "missing.h5", tmp_path / "missing_corpus.h5", t, negative, ev, norm)


def test_existing_output_is_kept_without_overwrite(tiny_db, tiny_artifacts, tmp_path):
    from facesynth.errors import OutputExistsError

    out = tmp_path / "tuned.toml"
    out.write_text("# mine\n", encoding="utf-8")
    with pytest.raises(OutputExistsError):
        tune.run(tiny_db, tiny_artifacts["corpus"], out, *_settings())
    assert out.read_text(encoding="utf-8") == "# mine\n"
