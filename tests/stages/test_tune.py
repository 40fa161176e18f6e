"""``facesynth tune``: the search on the tiny corpus, what it reads and its report."""

import csv
import dataclasses

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.domain.evaluation import held_out as evaluation
from facesynth.domain.search import tuning
from facesynth.stages import tune

#: A budget small enough for the tiny corpus: the initial simplex (7 points) and a step or two.
BUDGET = ("tune.max_evaluations=6", "tune.starts=1")


def _settings(*overrides):
    c = Config.load(None, BUDGET + overrides)
    return c.settings("tune"), c.settings("synthesize"), c.settings("build_db"), c.settings("normalize")


def _splits(tiny_corpus):
    rows = list(csv.DictReader(open(tiny_corpus / "manifest.csv", encoding="utf-8")))
    return {split: {r["take"] for r in rows if r["split"] == split} for split in ("train", "val", "test")}


# --- tuning on the tiny corpus -----------------------------------------------------------------


@pytest.fixture(scope="module")
def tuned(tiny_db, tiny_artifacts, tmp_path_factory):
    """One tune run with the tiny budget, the progress calls it made and the TOML it wrote."""
    settings = _settings()
    calls = []
    out = tmp_path_factory.mktemp("tune") / "tuned.toml"
    summary = tune.run(tiny_db, tiny_artifacts["corpus"], out, *settings,
                       progress_fn=lambda n, total, e, best: calls.append((n, total, e, best)))
    return summary, calls, out


def test_tuned_validation_error_is_never_above_the_start(tuned):
    summary, calls, _ = tuned
    assert summary.tuning.validation_sentences == 4 and summary.tuning.test_sentences == 4
    assert 0 < summary.tuning.validation_err_after <= summary.tuning.validation_err_before
    # the first evaluation is the start; the reported best is the least of every evaluation
    assert calls[0][2] == summary.tuning.validation_err_before
    assert summary.tuning.validation_err_after == min(c[2] for c in calls)
    assert [c[0] for c in calls] == list(range(1, summary.tuning.evaluations + 1))
    # one overall count: the weight budget plus the fit lengths and windows, the best so far with it
    budget = 6 + len(tuning.FIT_LENGTHS) - 1 + len(tuning.WINDOWS) - 1
    assert {c[1] for c in calls} == {budget} and summary.tuning.evaluations <= budget
    assert [c[3] for c in calls] == list(np.minimum.accumulate([c[2] for c in calls]))


def test_written_toml_loads_back_and_reproduces_the_weights(tuned):
    summary, _, out = tuned
    text = out.read_text(encoding="utf-8")
    assert f"{summary.tuning.validation_err_before:.4f} -> {summary.tuning.validation_err_after:.4f}" in text
    assert f"{summary.tuning.test_err_before:.4f} [" in text and f"-> {summary.tuning.test_err_after:.4f} [" in text
    loaded = Config.load(out)
    assert {k: getattr(loaded.settings("synthesize"), k) for k in tuning.WEIGHTS} == summary.tuning.weights  # exact: repr
    assert loaded.settings("synthesize").smoothing_half_window == summary.tuning.smoothing_half_window
    assert loaded.settings("build_db").boundary_fit_frames == summary.tuning.boundary_fit_frames
    # only those are written: every other setting stays at its default
    default = Config.load().settings("synthesize")
    moved = {k: getattr(default, k) for k in tuning.WEIGHTS + ("smoothing_half_window",)}
    assert dataclasses.replace(loaded.settings("synthesize"), **moved) == default


def test_test_error_is_the_error_on_the_test_takes(tuned, tiny_db, tiny_artifacts):
    summary, _, out = tuned
    _, synth, build, norm = _settings()
    ev = Config.load().settings("evaluate")
    test_ev = dataclasses.replace(ev, split="test")
    before, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], test_ev, synth, norm, with_baseline=False)
    assert summary.tuning.test_err_before == pytest.approx(before["dp"]["overall"]["err_mm2"], rel=1e-9)
    lo, hi = summary.tuning.test_ci_before
    assert lo <= summary.tuning.test_err_before <= hi
    if summary.tuning.boundary_fit_frames == build.boundary_fit_frames:  # the database's features are the tuned ones
        after, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], test_ev, Config.load(out).settings("synthesize"),
                                       norm, with_baseline=False)
        assert summary.tuning.test_err_after == pytest.approx(after["dp"]["overall"]["err_mm2"], rel=1e-9)
    val_ev = dataclasses.replace(ev, split="val")
    on_val, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], val_ev, synth, norm, with_baseline=False)
    assert summary.tuning.validation_err_before == pytest.approx(on_val["dp"]["overall"]["err_mm2"], rel=1e-9)
    assert summary.tuning.test_err_before != pytest.approx(summary.tuning.validation_err_before)  # two different sets


def _spy_synthesize(monkeypatch, seen):
    real = tuning.synthesize

    def spy(db, utt, constraints, settings, tc=None):
        seen.append((utt, settings))
        return real(db, utt, constraints, settings, tc=tc)

    monkeypatch.setattr(tuning, "synthesize", spy)


def test_the_search_sees_validation_takes_only(tiny_db, tiny_artifacts, tiny_corpus, monkeypatch):
    splits = _splits(tiny_corpus)
    t, synth, build, norm = _settings()
    seen = []
    _spy_synthesize(monkeypatch, seen)
    real_heldout = tune.heldout
    takes_of = {}

    def heldout(corpus, db, split, settings):
        out = real_heldout(corpus, db, split, settings)
        for s in out:
            takes_of[id(s.utterance)] = (split, s.take)
        return out

    monkeypatch.setattr(tune, "heldout", heldout)
    summary = tune.tune(tiny_db, tiny_artifacts["corpus"], t, synth, build, norm, progress_fn=None)
    assert splits["val"] and splits["test"] and not splits["val"] & splits["test"]
    splits_seen = [takes_of[id(utt)][0] for utt, _ in seen]
    # every searched path is of a validation take until the end, then the test takes: before and after
    first_test = splits_seen.index("test")
    assert set(splits_seen[:first_test]) == {"val"} and set(splits_seen[first_test:]) == {"test"}
    assert {takes_of[id(utt)][1] for utt, _ in seen[:first_test]} == splits["val"]
    assert {takes_of[id(utt)][1] for utt, _ in seen[first_test:]} == splits["test"]
    assert summary.tuning.evaluations >= 1


def test_same_seed_same_result_with_random_starts(tiny_db, tiny_artifacts, monkeypatch):
    def run(seed):
        seen = []
        _spy_synthesize(monkeypatch, seen)
        summary = tune.tune(tiny_db, tiny_artifacts["corpus"],
                            *_settings("tune.starts=2", "tune.max_evaluations=8", f"tune.seed={seed}"))
        summary = dataclasses.replace(summary, seconds=0.0)
        tried = []
        for _, s in seen:
            w = tuple(getattr(s, k) for k in tuning.WEIGHTS)
            if not tried or tried[-1] != w:
                tried.append(w)
        return summary, tried

    (first, tried_first), (again, tried_again), (_, tried_other) = run(3), run(3), run(4)
    assert first == again and tried_first == tried_again
    # the first start is the current weights whatever the seed; the second is drawn from the seed
    current = tuple(getattr(_settings()[1], k) for k in tuning.WEIGHTS)
    assert tried_first[0] == tried_other[0] == pytest.approx(current, rel=1e-12)
    assert set(tried_first) != set(tried_other)


def test_nothing_better_writes_the_start_with_a_warning(tiny_db, tiny_artifacts, tmp_path, monkeypatch):
    """A search that finds nothing better (here: every candidate but the start scores worse)
    writes the start settings and says so."""
    real = tuning.Objective.errors
    calls = {"n": 0}

    def worse(self, s, fit, sentences, tag):
        out = real(self, s, fit, sentences, tag)
        calls["n"] += 1
        return out if (tag == "test" or calls["n"] == 1) else out + 100.0

    monkeypatch.setattr(tuning.Objective, "errors", worse)
    out = tmp_path / "tuned.toml"
    t, synth, build, norm = _settings()
    summary = tune.run(tiny_db, tiny_artifacts["corpus"], out, t, synth, build, norm)
    assert not summary.tuning.improved and summary.tuning.warnings
    assert summary.tuning.validation_err_after == summary.tuning.validation_err_before
    loaded = Config.load(out)
    assert {k: getattr(loaded.settings("synthesize"), k) for k in tuning.WEIGHTS} == pytest.approx(
        {k: getattr(synth, k) for k in tuning.WEIGHTS}, rel=1e-12)
    assert "# warning: no setting tried beat the start" in out.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", tuning.WEIGHTS)
def test_non_positive_alphas_are_refused_by_name(tiny_db, tiny_artifacts, name):
    t, synth, build, norm = _settings()
    zero = dataclasses.replace(synth, **{name: 0.0})
    with pytest.raises(InputError, match=rf"synthesize\.{name} must be positive to tune it \(got 0\.0\)"):
        tune.tune(tiny_db, tiny_artifacts["corpus"], t, zero, build, norm)


def test_refusal_comes_before_any_file_is_read(tmp_path):
    t, synth, build, norm = _settings()
    negative = dataclasses.replace(synth, alpha2=-1.0)
    # the database does not exist: the settings are checked first
    with pytest.raises(InputError, match=r"synthesize\.alpha2 must be positive"):
        tune.tune(tmp_path / "missing.h5", tmp_path / "missing_corpus.h5", t, negative, build, norm)


def test_existing_output_is_kept_without_overwrite(tiny_db, tiny_artifacts, tmp_path):
    from facesynth.base.errors import OutputExistsError

    out = tmp_path / "tuned.toml"
    out.write_text("# mine\n", encoding="utf-8")
    with pytest.raises(OutputExistsError):
        tune.run(tiny_db, tiny_artifacts["corpus"], out, *_settings())
    assert out.read_text(encoding="utf-8") == "# mine\n"
