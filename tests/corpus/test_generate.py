"""The virtual actress must be realistic enough that the method's choices matter."""

import csv
import hashlib

import numpy as np
import pytest

from facesynth.domain.corpus.actress_mouth import (
    CHANNEL_NAMES,
    ContactSolver,
    TokenVariation,
    apply_contact,
    token_targets,
)
from facesynth.domain.corpus.generate import perform
from facesynth.domain.corpus.nonspeech import blink_times
from facesynth.domain.corpus.speech import STYLES, head_motion, lexicon, pitch, time_utterance
from facesynth.domain.corpus.statistics import bilabial_gaps, blink_events
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import LIP_GAP_MARKERS, LOWER_LIP_MARKER, build_marker_set, mesh_lip_gap
from facesynth.formats.labels import read_phone_segments, read_textgrid
from facesynth.formats.mesh import read_binding, read_mesh, read_rigid_markers
from facesynth.formats.mocap import read_mocap


@pytest.fixture(scope="module")
def rig():
    return load_face_rig()


@pytest.fixture(scope="module")
def marker_set(rig):
    return build_marker_set(rig)


def _digest(folder):
    h = hashlib.sha256()
    for p in sorted(folder.rglob("*")):
        if p.is_file():
            h.update(p.relative_to(folder).as_posix().encode())
            h.update(p.read_bytes())
    return h.hexdigest()


def _takes(corpus):
    return list(csv.DictReader(open(corpus / "manifest.csv")))


def test_same_seed_same_bytes_other_seed_other_bytes(tmp_path, tiny_corpus):
    from facesynth.domain.corpus.generate import generate

    generate(tmp_path / "a", "tiny", seed=0)
    generate(tmp_path / "b", "tiny", seed=1)
    assert _digest(tmp_path / "a") == _digest(tiny_corpus)
    assert _digest(tmp_path / "b") != _digest(tiny_corpus)


def test_the_corpus_has_every_file_the_manifest_names(tiny_corpus):
    rows = _takes(tiny_corpus)
    assert {r["emotion"] for r in rows} == {"neutral", "happy", "angry", "sad"}
    assert {r["split"] for r in rows} == {"train", "val", "test"}
    for r in rows:
        for key in ("mocap", "audio", "alignment"):
            assert (tiny_corpus / r[key]).exists()
        for suffix in (".c3d", "_head.csv", "_truth.csv"):  # the truth of every take, held out or not
            assert (tiny_corpus / "groundtruth" / f"{r['take']}{suffix}").exists()
    assert len(open(tiny_corpus / "contamination.csv").readlines()) > 1


def test_the_face_is_the_rig_and_the_markers_sit_on_it(tiny_corpus, rig):
    vertices, faces = read_mesh(tiny_corpus / "face.obj")
    assert vertices.shape == rig.neutral.shape and np.abs(vertices - rig.neutral).max() < 1e-4
    assert len(faces) == len(rig.faces)
    binding = read_binding(tiny_corpus / "markers.csv")
    assert 85 <= len(binding) <= 95
    names = read_mocap(tiny_corpus / "mocap" / "neutral_s000.c3d").names
    assert list(binding) == names
    for name in LIP_GAP_MARKERS + (LOWER_LIP_MARKER, "MC_L", "MC_R", "CHIN_C", "NOSE_TIP", "BROW_L3", "FH_C"):
        assert name in binding
    rigid = read_rigid_markers(tiny_corpus / "markers.csv")
    assert {"FH_T", "NOSE_BRIDGE", "TEMPLE_L", "TEMPLE_R"} <= set(rigid) and len(rigid) == 8
    motion = np.linalg.norm(rig.deltas, axis=2).max(axis=0)  # the most any shape moves each vertex, mm
    assert motion[[binding[n] for n in rigid]].max() < 2.0
    assert motion[binding["LLI_C"]] > 30.0
    # the inner-lip markers face each other on the closed neutral lips
    gap = np.linalg.norm(rig.neutral[binding["ULI_C"]] - rig.neutral[binding["LLI_C"]])
    assert gap < 1.0


def test_truth_reproduces_the_clean_markers(tiny_corpus, rig):
    binding = read_binding(tiny_corpus / "markers.csv")
    for take in ("neutral_s000", "sad_s004"):
        truth = read_truth(tiny_corpus / "groundtruth" / f"{take}_truth.csv")
        clean = read_mocap(tiny_corpus / "groundtruth" / f"{take}.c3d")
        assert truth.shape_names == rig.shape_names and truth.arkit_names == rig.arkit_names
        assert np.allclose(truth.arkit_weights, rig.to_arkit(truth.rig_weights), atol=1e-4)
        posed = rig.evaluate(truth.rig_weights, vertices=np.array([binding[n] for n in clean.names]))
        assert np.abs(posed - clean.positions).max() < 0.05  # mm: four decimals of weight
        assert len(truth.emotion) == len(clean.positions) and set(truth.emotion) <= {"neutral", "happy", "angry", "sad"}
        assert truth.rig_weights.min() >= 0.0 and truth.rig_weights.max() <= 1.0


def test_lips_touch_on_bilabials_and_open_on_vowels(tiny_corpus, rig, marker_set):
    closed, open_ = [], []
    for r in _takes(tiny_corpus):
        truth = read_truth(tiny_corpus / "groundtruth" / f"{r['take']}_truth.csv")
        segs = read_phone_segments(tiny_corpus / r["alignment"])
        closed += bilabial_gaps(rig, truth.rig_weights, [(s.start, s.end, s.label) for s in segs],
                                marker_set.lip_upper, marker_set.lip_lower, 120.0)
        centres = [int(0.5 * (s.start + s.end) * 120) for s in segs if s.label in ("aa", "ae", "ah", "ay", "aw")]
        if centres:
            open_ += mesh_lip_gap(rig, truth.rig_weights[centres], marker_set.lip_upper, marker_set.lip_lower).tolist()
    assert len(closed) > 20 and open_
    assert np.mean(np.array(closed) < 1.0) >= 0.95  # mm: the lips touch at the bilabial's centre
    assert np.median(open_) > 6.0


def test_lip_contact_holds_whatever_the_jaw_does(rig, marker_set):
    solver = ContactSolver(rig, marker_set.lip_pairs)
    rng = np.random.default_rng(0)
    weights = np.zeros((12, len(rig.shape_names)))
    weights[:, rig.shape_index("jawOpen")] = np.linspace(0.0, 0.5, 12)
    for name in ("mouthSmile_L", "mouthSmile_R", "mouthPucker", "mouthLowerDown_L", "mouthUpperUp_R", "browDown_L"):
        weights[:, rig.shape_index(name)] = rng.uniform(0.0, 0.3, 12)
    open_gap = mesh_lip_gap(rig, weights, marker_set.lip_upper, marker_set.lip_lower)
    closed = apply_contact(weights.copy(), np.full(12, 1.2), solver)
    gap = mesh_lip_gap(rig, closed, marker_set.lip_upper, marker_set.lip_lower)
    assert open_gap[-1] > 10.0 and gap.max() < 1.0
    # the jaw keeps its own trajectory: the lips close by mouthClose, not by shutting the jaw
    assert np.allclose(closed[:, rig.shape_index("jawOpen")], weights[:, rig.shape_index("jawOpen")])
    assert np.all(np.diff(closed[:, rig.shape_index("mouthClose")]) > 0)


def test_rounding_is_anticipated_across_consonants():
    still = TokenVariation(0.0, 0.0, 0.0, 0.0)
    pucker = CHANNEL_NAMES.index("pucker")

    def first_consonant_pucker(phones):
        n = len(phones)
        starts = np.arange(n) * 0.07
        targets, _, _ = token_targets(phones, starts, starts + 0.07, np.zeros(n), np.ones(n), np.random.default_rng(0), still)
        return targets[1, pucker]

    rounded = first_consonant_pucker(["pau", "s", "t", "r", "uw", "pau"])   # "strew": /s/ already rounds
    spread = first_consonant_pucker(["pau", "s", "t", "r", "iy", "pau"])
    blocked = first_consonant_pucker(["pau", "s", "iy", "t", "uw", "pau"])  # an unrounded vowel blocks the look-ahead
    assert rounded > 0.25 and rounded > spread + 0.1 and blocked == pytest.approx(0.0)


def test_the_same_triphone_differs_from_take_to_take(rig, marker_set):
    solver = ContactSolver(rig, marker_set.lip_pairs)
    words = ["please", "go", "home"]
    curves = []
    for seed in (1, 2):
        perf = perform(words, "neutral", np.random.default_rng(seed), rig, solver, 0.0, change_probability=0.0)
        utt = perf.utterance
        k = utt.phones.index("ow")  # /g ow h/ in both takes
        centre = int(0.5 * (utt.starts[k] + utt.ends[k]) * 120)
        curves.append(perf.weights[centre, [rig.shape_index(n) for n in ("jawOpen", "mouthPucker", "mouthLowerDown_L")]])
    assert np.abs(curves[0] - curves[1]).max() > 0.02


def test_left_and_right_differ(tiny_corpus, rig):
    ratios = []
    for r in _takes(tiny_corpus):
        w = read_truth(tiny_corpus / "groundtruth" / f"{r['take']}_truth.csv").rig_weights
        left, right = w[:, rig.shape_index("mouthLowerDown_L")], w[:, rig.shape_index("mouthLowerDown_R")]
        ratios.append(left.sum() / right.sum())
    ratios = np.array(ratios)
    assert np.abs(np.log(ratios)).mean() > 0.03 and (ratios > 1).any() and (ratios < 1).any()


def test_blinks_like_a_speaking_person(tiny_corpus, rig):
    count, seconds, lengths = 0, 0.0, []
    for r in _takes(tiny_corpus):
        w = read_truth(tiny_corpus / "groundtruth" / f"{r['take']}_truth.csv").rig_weights
        events = blink_events(w[:, rig.shape_index("eyeBlink_L")], 120.0)
        count += len(events)
        seconds += len(w) / 120.0
        lengths += [e[1] for e in events]
    assert 8.0 < 60.0 * count / seconds < 40.0
    assert 0.03 < np.median(lengths) < 0.2  # s above half closure: blinks of 100-300 ms
    # more blinks in pauses than in speech
    onsets = np.array(blink_times(6000.0, [(a, a + 1.0) for a in range(0, 6000, 10)], np.random.default_rng(0)))
    in_pause = (onsets % 10) < 1.0
    assert in_pause.sum() / 600.0 > 2.0 * (~in_pause).sum() / 5400.0


def test_emotion_changes_inside_some_sentences_and_the_phones_follow(tiny_corpus, tiny_artifacts):
    from facesynth.model.corpus import Corpus

    changed = []
    for r in _takes(tiny_corpus):
        tier = read_textgrid(tiny_corpus / r["alignment"])["emotion"]
        truth = read_truth(tiny_corpus / "groundtruth" / f"{r['take']}_truth.csv")
        assert tier[0].label == r["emotion"]
        if len(tier) > 1:
            changed.append(r["take"])
            switch = tier[1].start
            frame = int(switch * 120)
            assert truth.emotion[frame - 30] == tier[0].label and truth.emotion[frame + 30] == tier[1].label
    assert 1 <= len(changed) <= 12
    corpus = Corpus.read(tiny_artifacts["corpus"], audio=False)
    emotions = corpus.phones.emotions(corpus.takes)
    for take in changed:
        i = corpus.takes.index(take)
        rows = np.nonzero(corpus.phones.take == i)[0]
        labels = [emotions[k] for k in rows]
        assert labels[0] == corpus.takes.emotion[i] and len(set(labels)) == 2


def test_emotions_change_pose_and_timing(rig, marker_set):
    solver = ContactSolver(rig, marker_set.lip_pairs)
    words = [w for w in ["please", "go", "on", "because", "father", "has", "no", "idea"] if w in lexicon()]
    runs = {e: perform(words, e, np.random.default_rng(1), rig, solver, 0.0, change_probability=0.0)
            for e in ("happy", "angry", "sad")}
    assert runs["sad"].utterance.duration > runs["happy"].utterance.duration * 1.15

    def mean(e, name):
        return runs[e].weights[:, rig.shape_index(name)].mean()

    assert mean("happy", "mouthSmile_L") > mean("sad", "mouthSmile_L") + 0.2
    assert mean("angry", "browDown_L") > mean("happy", "browDown_L") + 0.2
    assert mean("sad", "browInnerUp_L") > mean("angry", "browInnerUp_L") + 0.2
    assert mean("happy", "cheekSquint_L") > mean("sad", "cheekSquint_L") + 0.1
    # dynamics: the sad jaw moves less than the angry one
    speed = {e: np.abs(np.diff(runs[e].weights[:, rig.shape_index("jawOpen")])).mean() for e in runs}
    assert speed["angry"] > 1.3 * speed["sad"]


def test_head_motion_follows_pitch():
    rng = np.random.default_rng(3)
    words = list(lexicon())[:12]
    utt = time_utterance(words, STYLES["angry"], rng, 0.0)
    f0, accents = pitch(utt, STYLES["angry"], 120, rng)
    rotations, _ = head_motion(f0, STYLES["angry"], 120, rng)
    nod = np.arctan2(rotations[:, 2, 1], rotations[:, 2, 2])
    lag = 12
    assert np.corrcoef(f0[:-lag], nod[lag:])[0, 1] > 0.5
    assert accents and all(0.5 <= s <= 1.0 for _, s in accents)


def test_audio_pitch_follows_the_emotion(tiny_corpus):
    from facesynth.formats.audio import read_audio

    def f0_estimate(path):
        x, rate = read_audio(path)
        x = x[len(x) // 4 : 3 * len(x) // 4]
        ac = np.correlate(x[:4000], x[:4000], "full")[3999:]
        lo, hi = rate // 400, rate // 100
        return rate / (lo + np.argmax(ac[lo:hi]))

    assert f0_estimate(tiny_corpus / "audio" / "happy_s000.wav") > f0_estimate(tiny_corpus / "audio" / "sad_s000.wav") + 25
