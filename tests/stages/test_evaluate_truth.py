"""The honest evaluation: clean ground truth in the right frame, closure timing, join
smoothness, the emotion classifier, bootstrap intervals and the openfacefx baseline."""

import json

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.cli import main
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.evaluation import baselines, bootstrap
from facesynth.domain.evaluation import held_out as evaluation
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motiondb import MotionDatabase


@pytest.fixture(scope="module")
def tiny_sentences(tiny_db, tiny_artifacts, tiny_corpus):
    c = Config.load()
    db = MotionDatabase.read(tiny_db)
    folder = evaluation.TruthFolder.open(tiny_corpus, db.marker_names, c.settings("normalize"))
    return db, folder, evaluation.heldout(tiny_artifacts["corpus"], db, "test", c.settings("normalize"), folder)


def test_clean_truth_is_in_the_normalized_head_frame_of_the_capture(tiny_sentences):
    db, _, sentences = tiny_sentences
    for s in sentences:
        assert s.clean.shape == s.truth.shape
        # the same frame and reference: the noisy capture differs from its clean truth by noise
        # and normalization error (millimetres), not by a head pose (centimetres)
        rms = np.sqrt(np.nanmean(np.sum((s.truth - s.clean) ** 2, axis=2)))
        assert rms < 3.0, (s.take, rms)
        # the rigid markers sit on the reference's
        rigid = [db.marker_names.index(n) for n in ("NOSE_BRIDGE",)]
        assert np.abs(s.clean[:, rigid].mean(0) - db.reference[rigid]).max() < 3.0


def test_a_method_that_outputs_the_truth_scores_zero(tiny_sentences):
    db, folder, sentences = tiny_sentences
    settings = Config.load().settings("evaluate")
    s = sentences[0]
    m = evaluation.clean_metrics(s.clean, s.clean, s.utterance, db.fps, db.marker_names, settings)
    assert m.err_clean_mm2 == 0.0 and m.velocity_ms_clean == 0.0 and m.mouth_r == pytest.approx(1.0)
    assert np.array_equal(m.onsets, m.onsets_clean, equal_nan=True)
    # the rig path openfacefx takes (weights -> rig -> markers -> normalized head frame) gives
    # the clean truth back from the truth's own rig weights (written with four decimals)
    truth = read_truth(folder.folder / "groundtruth" / f"{s.take}_truth.csv")
    rig = load_face_rig()
    posed = rig.evaluate(truth.rig_weights, vertices=folder.vertices(db.marker_names))
    r, t = s.to_reference
    assert np.abs(posed @ r + t - s.clean).max() < 0.05


def test_closure_timing_on_hand_made_gaps():
    fps = 100.0
    gap = np.full(30, 6.0)
    gap[12:15] = 0.5  # closes 2 frames into the /p/ (frames 10..19)
    gap[25:27] = 1.2  # the /m/ (frames 20..29) only gets to 1.2 mm
    tokens = [(10, 20), (20, 30)]
    on = evaluation.closure_onsets(gap, tokens, fps, 1.0)
    assert on[0] == pytest.approx(0.02) and np.isnan(on[1])
    on = evaluation.closure_onsets(gap, tokens, fps, 1.5)
    assert on[0] == pytest.approx(0.02) and on[1] == pytest.approx(0.05)
    utt = Utterance(["aa", "p", "m"], np.array([0.0, 0.1, 0.2]), np.array([0.1, 0.2, 0.3]), ["neutral"] * 3)
    assert evaluation.bilabial_frames(utt, fps, 30) == tokens


def test_closure_delay_and_rate_figures():
    rows = [{"_onsets": np.array([0.02, np.nan]), "_onsets_clean": np.array([0.01, 0.03])},
            {"_onsets": np.array([0.05]), "_onsets_clean": np.array([0.02])}]
    idx = np.arange(2)
    assert evaluation._closure_rate(rows, idx) == pytest.approx(2 / 3)
    assert evaluation._closure_delay(rows, idx) == pytest.approx(1000 * (0.01 + 0.03) / 2)


def test_second_differences_at_joins():
    x = np.zeros((10, 1, 3))
    x[5:, 0, 0] = 2.0  # a 2 mm step between frames 4 and 5: the join is at frame 5
    d2 = evaluation.second_differences(x, np.array([5]))
    assert sorted(d2) == pytest.approx([2.0, 2.0])
    assert evaluation.second_differences(x, np.array([2])).max() == 0.0


def test_bootstrap_interval_on_known_data():
    rng = np.random.default_rng(1)
    data = rng.normal(10.0, 2.0, 400)
    index = bootstrap.resamples(len(data), 2000, seed=0)
    ci = bootstrap.interval(lambda i: float(data[i].mean()), len(data), index)
    assert ci["value"] == pytest.approx(data.mean())
    half = 1.96 * data.std(ddof=1) / np.sqrt(len(data))  # the normal-theory half width, about 0.2
    assert ci["low"] == pytest.approx(data.mean() - half, abs=0.05) and ci["high"] == pytest.approx(data.mean() + half, abs=0.05)
    # paired: B = A + 0.5 on every sentence, so the difference is exactly -0.5 on every resample
    other = data + 0.5
    d = bootstrap.paired_difference(lambda i: float(data[i].mean()), lambda i: float(other[i].mean()), len(data), index)
    assert d["value"] == pytest.approx(-0.5) and d["low"] == pytest.approx(-0.5) and d["high"] == pytest.approx(-0.5)
    nan = bootstrap.interval(lambda i: float("nan"), 5, bootstrap.resamples(5, 100, 0))
    assert nan == {"value": None, "low": None, "high": None}


def test_the_classifier_beats_chance_on_captured_held_out_frames(tiny_sentences):
    db, _, sentences = tiny_sentences
    clf = evaluation.EmotionClassifier(db, 20000, seed=0)
    correct = frames = 0
    for s in sentences:
        asked = evaluation.frame_emotions(s.utterance, db.fps, len(s.clean))
        correct += int(np.sum(clf.predict(s.clean) == asked))
        frames += len(s.clean)
    assert correct / frames > 1.5 / len(clf.emotions)


def test_phones_map_to_openfacefx_arpabet():
    assert baselines.to_arpabet("pau") == "sil"
    assert baselines.to_arpabet("ax") == "AH" and baselines.to_arpabet("aa") == "AA" and baselines.to_arpabet("nx") == "N"
    r, t = baselines.fit_rigid(np.eye(3) * 5, np.eye(3) * 5 + 1.0)
    assert np.allclose(r, np.eye(3)) and np.allclose(t, 1.0)


def test_openfacefx_through_the_rig_closes_the_lips_on_bilabials(tiny_sentences):
    why = baselines.openfacefx_missing()
    if why is not None:
        pytest.skip(why)
    db, folder, sentences = tiny_sentences
    rig = load_face_rig()
    utt = Utterance(["pau", "aa", "m", "aa", "pau"], np.array([0.0, 0.2, 0.45, 0.6, 0.9]),
                    np.array([0.2, 0.45, 0.6, 0.9, 1.1]), ["neutral"] * 5)
    arkit = baselines.openfacefx_arkit(utt.phones, utt.starts, utt.ends, 132, 120.0, rig.arkit_names)
    assert arkit.shape == (132, 52) and arkit.min() >= 0.0 and arkit.max() <= 1.0
    markers = evaluation.openfacefx_baseline(db, utt, rig, folder.vertices(db.marker_names), sentences[0].to_reference)
    gap = evaluation.lip_gaps(markers, db.marker_names, ("ULI_C", "LLI_C"))
    assert gap[60:70].max() > gap[55:72].min() + 3.0  # open on /aa/, closer on /m/
    assert gap[int(0.5 * 120)] < gap[int(0.32 * 120)]


def test_evaluate_with_truth_writes_figures_with_intervals(tiny_db, tiny_artifacts, tiny_corpus, tmp_path):
    r = CliRunner().invoke(main, ["evaluate", str(tiny_db), "--heldout", str(tiny_artifacts["corpus"]), "--truth", str(tiny_corpus),
                                  "--set", "evaluate.bootstrap_resamples=200", "-o", str(tmp_path / "rep")])
    assert r.exit_code == 0, r.output
    m = json.loads((tmp_path / "rep" / "metrics.json").read_text())
    methods = {"dp", "greedy", "mean", "mean_per_phone", "coarticulation", "coarticulation_per_phone", "capture", "clean"}
    assert methods <= set(m)
    assert ("openfacefx" in m) == (baselines.openfacefx_missing() is None)
    assert m["clean"]["figures"]["rms_clean_mm"]["value"] == 0.0
    f = m["dp"]["figures"]
    for key in ("rms_clean_mm", "rms_mm", "velocity_rms_clean_mm_s", "mouth_r", "closure_rate", "join_d2_p99", "emotion_accuracy"):
        assert f[key]["low"] <= f[key]["value"] <= f[key]["high"], key
    assert "dp_minus.rms_clean_mm" in m["mean"]["figures"]
    table = (tmp_path / "rep" / "table.md").read_text()
    assert "dp − greedy" in table and "RMS vs clean truth" in table
