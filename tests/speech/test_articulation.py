"""The voice's articulation (facesynth.domain.voice.articulation) and its ``articulation``
artifact, on audio and arrays made here: streaming equals batch, the model round-trips bit for
bit and checks clean, a fit recovers a known linear map, and everything is deterministic."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from facesynth.base.errors import ArtifactError, InputError
from facesynth.domain.voice import articulation as A
from facesynth.model import check
from facesynth.model.articulation import ArticulationModel

RATE = A.RATE
FPS = 30.0


def speechlike(seconds: float, seed: int = 0) -> np.ndarray:
    """(n,) float32 at 16 kHz: syllables of a voiced buzz (120 Hz pulses through two resonances)
    with noise bursts, after a quarter second of silence."""
    from scipy.signal import lfilter

    rng = np.random.default_rng(seed)
    n = int(seconds * RATE)
    t = np.arange(n) / RATE
    buzz = (np.sin(2 * np.pi * 120 * t) > 0.95).astype(float)
    out = np.zeros(n)
    for f in (700, 1200):
        r = np.exp(-np.pi * 100 / RATE)
        out += lfilter([1.0], [1.0, -2 * r * np.cos(2 * np.pi * f / RATE), r * r], buzz)
    env = np.clip(np.sin(2 * np.pi * 3.0 * t), 0, None) ** 2
    hiss = rng.normal(0, 0.05, n) * (np.sin(2 * np.pi * 1.5 * t + 1) > 0.9)
    x = out / np.abs(out).max() * 0.5 * env + hiss
    x[: RATE // 4] = 0.0
    return x.astype(np.float32)


def fitted(**kw) -> tuple[ArticulationModel, np.ndarray]:
    x = speechlike(6.0)
    raw = A.frame_features(x, RATE)
    n = int(6.0 * FPS)
    env = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
    targets = np.stack([np.exp(env), -env], 1)
    return A.fit([A.Take(raw, targets, FPS)], ("opening", "mouthFunnel"), **kw), x


def test_features_shape_and_silence():
    x = speechlike(1.0)
    raw = A.frame_features(x, RATE)
    assert raw.shape == (A.frame_count(len(x)), A.N_FEATURES) == (100, 40) and raw.dtype == np.float32
    assert np.isfinite(raw).all()
    assert raw[5, A.I_LOG_RMS] == pytest.approx(0.5 * np.log(A.POWER_FLOOR), abs=1e-3)  # digital silence
    assert raw[5, A.I_VOICING] == 0


@pytest.mark.parametrize("chunk", [320, 33, 4000])
def test_streaming_features_equal_batch(chunk):
    x = speechlike(1.3)
    s = A.StreamingFeatures()
    out = [s.push(x[a:a + chunk]) for a in range(0, len(x), chunk)] + [s.finish()]
    np.testing.assert_allclose(np.concatenate(out), A.frame_features(x, RATE), atol=1e-4, rtol=1e-4)


def test_running_normalization_continues_across_chunks():
    rng = np.random.default_rng(1)
    raw = rng.normal(size=(700, A.N_FEATURES)).astype(np.float32)
    raw[:, A.I_LOG_RMS] = rng.normal(-3, 1, 700)
    norm = A.Normalizer(mode="running", tau_s=0.5)
    z = norm.apply(raw)
    st = A.RunningState.start(norm)
    np.testing.assert_allclose(np.concatenate([st.update(norm, raw[:300]), st.update(norm, raw[300:])]), z, atol=1e-5)


def test_ridge_recovers_a_linear_map():
    rng = np.random.default_rng(2)
    x = rng.normal(size=(2000, 5))
    w = np.array([[1.0], [-2.0], [0.5], [0.0], [3.0]])
    coef, intercept = A.ridge(x, x @ w + 4.0, 1e-8)
    np.testing.assert_allclose(coef, w, atol=1e-5)
    np.testing.assert_allclose(intercept, [4.0], atol=1e-5)



def test_a_row_of_weight_two_counts_as_the_row_twice():
    """Weighted ridge (means, deviations, error and penalty all weighed) equals ridge on the rows
    repeated as many times as their weights, with and without a prior."""
    rng = np.random.default_rng(3)
    x = rng.normal(size=(300, 4))
    y = x @ rng.normal(size=(4, 2)) + rng.normal(size=(300, 2))
    weights = rng.integers(1, 4, 300)
    repeated = np.repeat(np.arange(300), weights)
    prior, prior_std = rng.normal(size=(4, 2)), np.array([0.5, 2.0])
    for kw in ({}, {"prior": prior, "prior_std": prior_std, "strength": 0.7}):
        coef, intercept = A.ridge(x, y, 0.3, weights=weights, **kw)
        coef2, intercept2 = A.ridge(x[repeated], y[repeated], 0.3, **kw)
        np.testing.assert_allclose(coef, coef2, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(intercept, intercept2, rtol=1e-9, atol=1e-12)
    plain = A.ridge(x, y, 0.3)
    np.testing.assert_array_equal(A.ridge(x, y, 0.3, weights=np.full(300, 5.0))[0].round(10), plain[0].round(10))


def test_a_take_weighing_two_counts_as_the_take_twice():
    """Take weights are relative: a short take of weight 2 beside a long one fits as the short take
    given twice, and the target's mean and spread are weighed alike."""
    a, b = speechlike(4.0, seed=0), speechlike(2.0, seed=1)
    takes = []
    for x in (a, b):
        raw = A.frame_features(x, RATE)
        n = int(len(x) / RATE * FPS)
        env = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
        takes.append(A.Take(raw, np.exp(env)[:, None], FPS))
    weighed = A.fit([takes[0], dataclasses.replace(takes[1], weight=2.0)], ("opening",))
    twice = A.fit([takes[0], takes[1], takes[1]], ("opening",))
    np.testing.assert_allclose(weighed.coef, twice.coef, rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(weighed.intercept, twice.intercept, rtol=1e-6)
    np.testing.assert_allclose(weighed.target_mean, twice.target_mean, rtol=1e-9)
    np.testing.assert_allclose(weighed.target_std, twice.target_std, rtol=1e-9)
    assert not np.allclose(weighed.coef, A.fit(takes, ("opening",)).coef, rtol=1e-3)
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(InputError, match="take 1: weight"):
            A.fit([takes[0], dataclasses.replace(takes[1], weight=bad)], ("opening",))


def test_fit_recovers_a_known_linear_relation_of_the_context():
    """Targets made as a linear map of the model's own context: the fit finds that map's curves."""
    x = speechlike(6.0)
    raw = A.frame_features(x, RATE)
    times = np.arange(int(6.0 * FPS)) / FPS
    probe = A.fit([A.Take(raw, np.zeros((len(times), 1)), FPS)], ("t",), alpha=1e-9)
    ctx = A.design(probe, raw, times).astype(np.float64)
    width = A.N_FEATURES + A.N_EXPANDED  # context columns per offset, offset-major
    assert ctx.shape[1] == len(A.DEFAULT_OFFSETS_S) * width
    w = np.zeros((ctx.shape[1], 1))
    w[A.I_LOG_RMS], w[9 * width + A.I_VOICING] = 0.3, -0.2  # loudness at -250 ms, voicing at +20 ms
    y = ctx @ w + 0.5
    model = A.fit([A.Take(raw, y, FPS)], ("t",), alpha=1e-9)
    np.testing.assert_allclose(A.predict_raw(model, raw, times), y, atol=1e-3)


def test_model_predicts_what_it_learned_and_is_deterministic():
    model, x = fitted()
    again, _ = fitted()
    for f in dataclasses.fields(model):
        a, b = getattr(model, f.name), getattr(again, f.name)
        assert np.array_equal(a, b) if isinstance(a, np.ndarray) else a == b, f.name
    pred = A.predict(model, x, RATE, 180, FPS)
    assert pred.shape == (180, 2)
    assert np.array_equal(pred, A.predict(again, x, RATE, 180, FPS))
    raw = A.frame_features(x, RATE)
    env = np.interp(np.arange(180) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
    assert np.corrcoef(pred[:, 1], -env)[0, 1] > 0.95
    assert A.model_look_ahead_s(model) == pytest.approx(0.046)


@pytest.mark.parametrize("chunk", [320, 33, 4000])
def test_streaming_predictions_equal_batch_and_respect_the_look_ahead(chunk):
    model, x = fitted()
    sp = A.StreamingPredictor(model, FPS)
    outs, emitted_at = [], []
    for a in range(0, len(x), chunk):
        o = sp.push(x[a:a + chunk])
        outs.append(o)
        emitted_at += [(a + len(x[a:a + chunk])) / RATE] * len(o)
    outs.append(sp.finish())
    stream = np.concatenate(outs)
    assert len(stream) == int(np.ceil(len(x) / RATE * FPS))  # every frame whose time is within the audio
    np.testing.assert_allclose(stream, A.predict(model, x, RATE, len(stream), FPS), atol=1e-5)
    lag = np.array(emitted_at) - np.arange(len(emitted_at)) / FPS
    look = A.model_look_ahead_s(model)
    assert lag.min() >= look - A.FRAME_S / 2 - 1e-9  # offsets round to analysis frames
    assert lag.max() <= look + chunk / RATE + A.FRAME_S + 1 / FPS


def test_streaming_refuses_utterance_normalization_and_other_rates():
    model, _ = fitted(normalization="utterance")
    with pytest.raises(InputError, match="whole audio"):
        A.StreamingPredictor(model, FPS)
    with pytest.raises(InputError, match="16000 Hz"):
        A.StreamingPredictor(fitted()[0], FPS, rate=44100)


def test_round_trip_is_bit_exact_and_checks_clean(tmp_path):
    model, x = fitted()
    path = tmp_path / "articulation.h5"
    model.write(path, config="{}", inputs=[])
    again = ArticulationModel.read(path)
    for f in dataclasses.fields(model):
        if f.name == "inputs":
            continue
        a, b = getattr(model, f.name), getattr(again, f.name)
        if isinstance(a, np.ndarray):
            assert a.dtype == b.dtype and np.array_equal(a, b), f.name
        else:
            assert a == b, f.name
    assert np.array_equal(A.predict(again, x, RATE, 180, FPS), A.predict(model, x, RATE, 180, FPS))
    report = check.check_file(path)
    assert report.problems == []
    assert report.lines() == [f"{path}: ok (articulation, schema 1)"]


def test_model_of_other_features_is_refused():
    model, x = fitted()
    with pytest.raises(ArtifactError, match="other voice features"):
        A.predict(dataclasses.replace(model, hop=80), x, RATE, 10, FPS)


def test_a_benchmark_may_append_feature_columns_that_the_product_refuses():
    """Columns after the voice features (a benchmark's trial) are learned from, and a model of them
    never runs where facesynth computes the features itself."""
    x = speechlike(6.0)
    raw = A.frame_features(x, RATE)
    n = int(6.0 * FPS)
    extra = np.sin(2 * np.pi * 0.7 * np.arange(len(raw)) * A.FRAME_S)[:, None].astype(np.float32)
    target = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, extra[:, 0])
    names = A.FEATURE_NAMES + ("trial",)
    with_extra = np.concatenate([raw, extra], 1)
    model = A.fit([A.Take(with_extra, np.stack([target, -target], 1), FPS)], ("opening", "mouthFunnel"),
                  feature_names=names, alpha=0.01)
    assert tuple(model.feature_names) == names
    predicted = A.predict_raw(model, with_extra, np.arange(n) / FPS)[:, 0]
    assert np.corrcoef(predicted, target)[0, 1] > 0.99  # the appended column is what it learned
    with pytest.raises(ArtifactError, match="other voice features"):
        A.predict(model, x, RATE, n, FPS)
    with pytest.raises(InputError, match="first"):
        A.fit([A.Take(with_extra, np.zeros((n, 1)), FPS)], ("opening",), feature_names=("trial",) + A.FEATURE_NAMES)


def test_fit_refuses_mismatched_targets():
    raw = A.frame_features(speechlike(1.0), RATE)
    with pytest.raises(InputError, match="expected"):
        A.fit([A.Take(raw, np.zeros((30, 3)), FPS)], ("opening",))


def test_a_target_some_takes_lack_is_fitted_on_the_takes_that_have_it():
    """A source without a jaw channel (NaN) still teaches the opening; the jaw is fitted on the
    takes that have it, exactly as a fit on those takes alone fits it."""
    a, b = speechlike(6.0, seed=0), speechlike(6.0, seed=1)
    takes = []
    for k, x in enumerate((a, b)):
        raw = A.frame_features(x, RATE)
        n = int(6.0 * FPS)
        env = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
        jaw = 0.5 * env if k == 0 else np.full(n, np.nan)  # the second take has no jaw
        takes.append(A.Take(raw, np.stack([np.exp(env), jaw], 1), FPS))
    both = A.fit(takes, ("opening", "jawOpen"))
    x = [A.design(both, t.raw, t.times_s).astype(np.float64) for t in takes]  # the fit's own context
    jaw, jaw0 = A.ridge(x[0], takes[0].targets[:, 1:], both.alpha)  # the jaw: from the first take alone
    np.testing.assert_allclose(both.coef[:, 1:], jaw, rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(both.intercept[1:], jaw0, rtol=1e-6, atol=1e-9)
    opening, _ = A.ridge(np.concatenate(x), np.concatenate([t.targets[:, :1] for t in takes]), both.alpha)
    np.testing.assert_allclose(both.coef[:, :1], opening, rtol=1e-6, atol=1e-9)  # the opening: from both
    assert np.isfinite(both.coef).all() and np.isfinite(both.target_std).all()
    with pytest.raises(InputError, match="jawOpen"):
        A.fit(takes[1:], ("opening", "jawOpen"))  # no take has a jaw: refused, naming it


def test_a_prior_pulls_the_fit_toward_the_general_model():
    """fit-articulation's adaptation: strength 0 is the performer's fit alone, a strong prior keeps
    the general model's predictions (in the performer's units), and between lies between."""
    general, x = fitted()
    y = speechlike(6.0, seed=5)
    raw = A.frame_features(y, RATE)
    n = int(6.0 * FPS)
    env = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
    own = np.stack([np.sin(np.arange(n) / 7.0) * 3.0, 10.0 * env], 1)  # another relation, other units
    take = A.Take(raw, own, FPS)
    alone = A.fit([take], ("opening", "mouthFunnel"))
    zero = A.fit([take], ("opening", "mouthFunnel"), prior=general, prior_strength=0.0)
    assert np.array_equal(alone.coef, zero.coef)
    times = take.times_s
    said = A.predict_raw(general, raw, times)
    r = {}
    for s in (0.1, 1e4):
        adapted = A.fit([take], ("opening", "mouthFunnel"), prior=general, prior_strength=s)
        assert np.array_equal(adapted.feature_mean, general.feature_mean)  # the prior's columns
        r[s] = np.corrcoef(A.predict_raw(adapted, raw, times)[:, 0], said[:, 0])[0, 1]
    r0 = np.corrcoef(A.predict_raw(alone, raw, times)[:, 0], said[:, 0])[0, 1]
    assert r[1e4] > 0.99 and r0 < r[0.1] < r[1e4]  # the opening: as strong as the prior is


def test_leaving_each_take_out_equals_fitting_the_others():
    """fit-articulation's held-out takes: each model of :func:`fit_leaving_each_out` (from the sums of
    every take less the left-out one's) is :func:`fit` on the other takes, adapting a prior or not,
    with takes of other weights and a target one take lacks; a fold left without that target is
    refused as :func:`fit` refuses it."""
    general, _ = fitted()
    takes = []
    for k in range(4):
        x = speechlike(3.0 + k, seed=10 + k)
        raw = A.frame_features(x, RATE)
        n = int(len(x) / RATE * FPS)
        env = np.interp(np.arange(n) / FPS, np.arange(len(raw)) * A.FRAME_S, raw[:, A.I_LOG_RMS])
        funnel = -env + 0.1 * np.sin(np.arange(n) / (3.0 + k)) if k != 2 else np.full(n, np.nan)
        takes.append(A.Take(raw, np.stack([np.exp(env) * (1 + 0.2 * k), funnel], 1), FPS, weight=1.0 + 0.5 * k))
    names = ("opening", "mouthFunnel")
    for prior, strength in ((general, 3.0), (None, 0.0)):
        models = A.fit_leaving_each_out(takes, names, prior=prior, prior_strength=strength)
        assert len(models) == len(takes)
        for i, model in enumerate(models):
            want = A.fit(takes[:i] + takes[i + 1:], names, prior=prior, prior_strength=strength)
            for field_name in ("coef", "intercept", "target_mean", "target_std", "feature_mean", "feature_std"):
                got, expected = getattr(model, field_name), getattr(want, field_name)
                np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max(), err_msg=field_name)
    lacking = [dataclasses.replace(t, targets=np.stack([t.targets[:, 0], np.full(len(t.targets), np.nan)], 1))
               if i else t for i, t in enumerate(takes[:2])]  # only the first take has the funnel
    with pytest.raises(InputError, match="mouthFunnel"):
        A.fit_leaving_each_out(lacking, names, prior=general, prior_strength=3.0)
    with pytest.raises(InputError, match="two takes"):
        A.fit_leaving_each_out(takes[:1], names, prior=general, prior_strength=3.0)
