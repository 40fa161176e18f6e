"""The compact key-shape trajectory model (Huang et al. §5.4): training, Eq. 7's solve, synthesis
through the CLI, evaluation, and bad input."""

import dataclasses
import json
import logging

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.methods import MethodSettings
from facesynth.domain.methods.trajectory import (
    dense_system,
    duration_weights,
    effective_lambda,
    frame_targets,
    pooled,
    solve,
    synthesize_path,
)
from facesynth.domain.speech.utterance import read_utterance
from facesynth.model.motion import Motion
from facesynth.model.trajectory import TrajectoryModel
from facesynth.stages import synthesize


@pytest.fixture(scope="module")
def model(tiny_trajectory):
    return TrajectoryModel.read(tiny_trajectory)


def _problem(seed, t=40, k=5):
    rng = np.random.default_rng(seed)
    means = rng.uniform(0, 1, (t, k))
    variances = rng.uniform(0.01, 0.2, (t, k))
    d = rng.uniform(0.3, 1.0, t)
    return means, variances, d


@pytest.mark.parametrize("seed, lam", [(0, 10.0), (1, 0.5), (2, 160.0), (3, 0.0)])
def test_the_banded_solve_equals_a_dense_solve_of_eq_7(seed, lam):
    means, variances, d = _problem(seed)
    a, b = dense_system(means, variances, d, lam)
    reference = np.linalg.solve(a, b).reshape(means.shape)
    x = solve(means, d[:, None] / variances, lam)
    assert np.abs(x - reference).max() < 1e-9


def test_one_frame_and_no_frames_are_solved():
    means, variances, d = _problem(4, t=1)
    assert np.allclose(solve(means, d[:, None] / variances, 10.0), means)
    assert solve(np.zeros((0, 3)), np.ones((0, 3)), 10.0).shape == (0, 3)


def test_duration_normalization_deemphasizes_long_phones():
    w = duration_weights([(0, 2), (2, 10)], 10)
    assert np.allclose(w[:2], 0.8) and np.allclose(w[2:], 0.2)
    assert np.allclose(duration_weights([(0, 5)], 5), 0.2)  # floored at 1 / T
    assert np.allclose(duration_weights([(0, 2), (2, 10)], 10, normalize=False), 1.0)
    assert effective_lambda(10.0, 120.0, 30.0) == pytest.approx(160.0)


def test_pooling_gives_the_moments_of_the_pooled_samples():
    rng = np.random.default_rng(0)
    a, b = rng.normal(1, 2, (50, 3)), rng.normal(-1, 0.5, (150, 3))
    mean, var = pooled(np.stack([a.mean(0), b.mean(0)]), np.stack([a.var(0), b.var(0)]), np.array([50, 150]))
    both = np.concatenate([a, b])
    assert np.allclose(mean, both.mean(0)) and np.allclose(var, both.var(0))


def test_the_model_holds_phone_and_pair_gaussians_of_training_frames(model):
    assert model.count == int(model.keyshapes.shape[0]) >= 4
    assert len(set(model.keyshape_emotion)) >= 2  # one joint set over the emotions
    assert "pau" in model.phones and (model.tokens >= 1).all() and (model.samples >= model.tokens).all()
    assert (model.means >= 0).all() and (model.variances > 0).all()
    assert (model.pair_tokens >= model.min_tokens).all()
    assert set(model.pair_phone) <= set(model.phones)
    assert model.means.dtype == np.float32 and model.fps == 120.0
    # the back-projection of all-zero weights is the rest pose, of a unit weight the key-shape
    assert np.allclose(model.markers(np.zeros((1, model.count)))[0], model.reference)
    assert np.allclose(model.markers(np.eye(model.count)), model.keyshapes, atol=1e-4)


def test_lambda_to_zero_passes_through_the_phone_means_at_phone_centres(model, tiny_corpus, held_out_take):
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    path = synthesize_path(model, utt.phones, utt.emotions, utt.starts, utt.ends, smoothness=1e-9, smoothness_fps=30.0,
                           fps=0.0)
    targets = path.targets
    for a, b in targets.ranges:
        if b > a:
            c = (a + b - 1) // 2
            assert np.abs(path.weights[c] - targets.means[c]).max() < 1e-6


def test_a_larger_lambda_gives_a_smoother_path(model, tiny_corpus, held_out_take):
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")

    def roughness(lam):
        path = synthesize_path(model, utt.phones, utt.emotions, utt.starts, utt.ends, smoothness=lam,
                               smoothness_fps=30.0, fps=0.0)
        return float((np.diff(path.weights, axis=0) ** 2).sum())

    values = [roughness(lam) for lam in (0.1, 1.0, 10.0, 100.0)]
    assert all(b < a for a, b in zip(values, values[1:]))


def _synth(model_path, tg, out, config, **kw):
    return synthesize.run(model_path, out, MethodSettings.of(config), config.settings("ingest"),
                          config.settings("align"), method="trajectory", phones_path=tg, **kw)


def test_synthesis_writes_a_motion_that_deform_reads_and_is_deterministic(tiny_trajectory, tiny_corpus, held_out_take, config,
                                                                         tmp_path):
    from facesynth.stages import deform

    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    (tmp_path / "e.txt").write_text("0 100 sad\n")
    _synth(tiny_trajectory, tg, tmp_path / "a.h5", config, emotions_path=tmp_path / "e.txt")
    _synth(tiny_trajectory, tg, tmp_path / "b.h5", config, emotions_path=tmp_path / "e.txt")
    a, b = Motion.read(tmp_path / "a.h5"), Motion.read(tmp_path / "b.h5")
    assert a.source == "synthesis" and a.fps == 30 and a.capture_fps == 120
    assert np.array_equal(a.markers, b.markers) and np.isfinite(a.markers).all()
    search, provenance = Motion.read_search(tmp_path / "a.h5")
    assert search.method == "trajectory" and (search.node == -1).all() and (provenance.source_frame == -1).all()
    assert set(search.emotion) == {"sad"}
    with h5py.File(tmp_path / "a.h5") as f:
        assert f["keyshape_weights"].shape[0] == len(f["markers_capture"]) and (f["keyshape_weights"][()] >= -1e-6).all()
    deform.run(tmp_path / "a.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", tmp_path / "anim.h5",
               config.settings("deform"))
    assert (tmp_path / "anim.h5").stat().st_size > 0
    # with the audio, the voice's loudness moves the mouth, and the motion records the settings it used
    _synth(tiny_trajectory, tg, tmp_path / "loud.h5", config, emotions_path=tmp_path / "e.txt",
           audio=tiny_corpus / "audio" / f"{held_out_take}.wav")
    loud = Motion.read(tmp_path / "loud.h5")
    assert np.abs(loud.markers - a.markers).max() > 0.1
    with h5py.File(tmp_path / "a.h5") as f, h5py.File(tmp_path / "loud.h5") as g:
        plain, with_audio = json.loads(f.attrs["config"]), json.loads(g.attrs["config"])
    loudness_keys = {k for k in with_audio if k.startswith("synthesize.")}
    assert "synthesize.loudness_weight" in loudness_keys and not any(k.startswith("synthesize.") for k in plain)
    assert {k: v for k, v in with_audio.items() if k not in loudness_keys} == plain


def _textgrid(path, phones):
    """A one-tier TextGrid of (phone, start, end) intervals."""
    items = "".join(f'        intervals [{i + 1}]:\n            xmin = {a}\n            xmax = {b}\n            text = "{p}"\n'
                    for i, (p, a, b) in enumerate(phones))
    path.write_text('File type = "ooTextFile"\nObject class = "TextGrid"\n\nxmin = 0\n'
                    f'xmax = {phones[-1][2]}\ntiers? <exists>\nsize = 1\nitem []:\n    item [1]:\n'
                    '        class = "IntervalTier"\n        name = "phones"\n        xmin = 0\n'
                    f'        xmax = {phones[-1][2]}\n        intervals: size = {len(phones)}\n' + items)
    return path


def test_an_unseen_phone_falls_back_to_its_viseme_class_with_a_warning(model, caplog):
    spoken = [p for p in model.phones if p != "pau"]
    have = set(model.phones)
    from facesynth.base.phonemes import VISEME_GROUPS

    group = next(g for g in VISEME_GROUPS if any(p in have for p in g) and any(p not in have for p in g))
    unseen = next(p for p in group if p not in have)
    phones = ["pau", spoken[0], unseen, "pau"]
    with caplog.at_level(logging.WARNING, logger="facesynth.domain.methods.trajectory"):
        t = frame_targets(model, phones, ["neutral"] * 4, np.array([0, 0.2, 0.4, 0.6]), np.array([0.2, 0.4, 0.6, 0.8]),
                          120.0)
    assert unseen in t.fallbacks and f"/{unseen}/" in caplog.text
    assert t.used[2].startswith("viseme:")


def test_a_phone_of_a_class_the_model_lacks_is_refused(model):
    from facesynth.base.phonemes import VISEME_GROUPS

    have = set(model.phones)
    group = next((g for g in VISEME_GROUPS if not any(p in have for p in g)), None)
    reduced = dataclasses.replace(model, phones=[p for p in model.phones if p not in ("th", "dh")],
                                  means=model.means[[i for i, p in enumerate(model.phones) if p not in ("th", "dh")]])
    phone = group[0] if group else "th"
    use = model if group else reduced
    with pytest.raises(InputError, match=rf"phone /{phone}/ is not in the trajectory model and neither is any phone"):
        frame_targets(use, ["pau", phone], ["neutral"] * 2, np.array([0, 0.2]), np.array([0.2, 0.4]), 120.0)


def test_a_zero_length_phone_is_refused_by_the_core(model):
    with pytest.raises(InputError, match=r"phone 2 /aa/ at 0.200 s has no duration"):
        frame_targets(model, ["pau", "aa", "pau"], ["neutral"] * 3, np.array([0, 0.2, 0.2]), np.array([0.2, 0.2, 0.5]),
                      120.0)


def test_bad_input_exits_1_with_one_sentence_and_writes_nothing(tiny_trajectory, tiny_db, tiny_corpus, held_out_take, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    out = tmp_path / "m.h5"
    runner = CliRunner()
    # a model of the wrong kind
    r = runner.invoke(main, ["synthesize", "--method", "trajectory", str(tiny_db), "--phonemes", str(tg), "-o", str(out)])
    assert r.exit_code == 1 and "trajectory" in r.output and "Traceback" not in r.output and not out.exists()
    # a zero-length phone (the label reader names it)
    bad = _textgrid(tmp_path / "zero.TextGrid", [("pau", 0.0, 0.2), ("aa", 0.2, 0.2), ("m", 0.2, 0.5)])
    r = runner.invoke(main, ["synthesize", "--method", "trajectory", str(tiny_trajectory), "--phonemes", str(bad), "-o", str(out)])
    assert r.exit_code == 1 and "segment 'aa' ends at or before it starts" in r.output and not out.exists()
    # constraints have no meaning without nodes
    (tmp_path / "c.txt").write_text("1 3\n")
    r = runner.invoke(main, ["synthesize", "--method", "trajectory", str(tiny_trajectory), "--phonemes", str(tg),
                             "--constraints", str(tmp_path / "c.txt"), "-o", str(out)])
    assert r.exit_code == 2 and "the trajectory method takes none" in r.output and not out.exists()
    # the database where a model is expected, and the reverse
    r = runner.invoke(main, ["synthesize", str(tiny_trajectory), "--phonemes", str(tg), "-o", str(out)])
    assert r.exit_code == 1 and "motiondb" in r.output and not out.exists()
    r = runner.invoke(main, ["train-trajectory", str(tiny_db), "--keyshapes", str(tiny_db), "-o", str(out)])
    assert r.exit_code == 1 and "keyshapes" in r.output and not out.exists()


def test_the_cli_trains_and_synthesizes(tiny_db, tiny_corpus, held_out_take, tiny_trajectory, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    ks = tiny_trajectory.parent / "keyshapes.h5"
    r = CliRunner().invoke(main, ["fit-method", "trajectory", str(tiny_db), "--keyshapes", str(ks), "-o", str(tmp_path / "t.h5")])
    assert r.exit_code == 0 and "trajectory model:" in r.output
    # the deprecated name does the same, saying so
    r = CliRunner().invoke(main, ["train-trajectory", str(tiny_db), "--keyshapes", str(ks), "-o", str(tmp_path / "u.h5")])
    assert r.exit_code == 0 and "deprecated" in r.output and "fit-method trajectory" in r.output
    assert (tmp_path / "u.h5").exists()
    r = CliRunner().invoke(main, ["synthesize", "--method", "trajectory", str(tmp_path / "t.h5"), "--phonemes", str(tg),
                                  "-o", str(tmp_path / "m.h5"), "--set", "trajectory.smoothness=5"])
    assert r.exit_code == 0 and "by the trajectory method" in r.output
    with h5py.File(tmp_path / "m.h5") as f:
        assert f.attrs["source"] == "synthesis" and f["path"].attrs["method"] == "trajectory"


def test_evaluate_lists_the_trajectory_method(tiny_db, tiny_artifacts, tiny_trajectory, config, tmp_path):
    from facesynth.stages import evaluate

    quick = dataclasses.replace(config.settings("evaluate"), bootstrap_resamples=100)  # the intervals' width is not tested here
    s = evaluate.run(tiny_db, tiny_artifacts["corpus"], tmp_path / "report", quick,
                     MethodSettings.of(config), config.settings("normalize"), models=[tiny_trajectory])
    assert "trajectory" in s.methods and np.isfinite(s.methods["trajectory"]["rms_mm"])
    assert "dp_minus.rms_mm" in s.methods["trajectory"]["figures"]
    assert "| trajectory |" in (tmp_path / "report" / "table.md").read_text()


def test_evaluate_refuses_a_model_of_another_database(tiny_artifacts, tiny_trajectory, config, tmp_path):
    from facesynth.stages import build_db, evaluate

    other = tmp_path / "other_db.h5"
    build_db.run(tiny_artifacts["pca"], other, dataclasses.replace(config.settings("build_db"), dsc_samples=6))
    with pytest.raises(InputError, match="was trained on another database"):
        evaluate.run(other, tiny_artifacts["corpus"], tmp_path / "report", config.settings("evaluate"),
                     MethodSettings.of(config), config.settings("normalize"), models=[tiny_trajectory])
    assert not (tmp_path / "report").exists()
