"""The virtual actress must be realistic enough that the method's choices matter."""

import hashlib

import numpy as np

from facesynth.corpus.face import LIP_GAP_MARKERS, P, Rig, build_face_model
from facesynth.corpus.generate import generate
from facesynth.corpus.speech import STYLES, articulation, lexicon, time_utterance
from facesynth.formats.labels import read_phone_segments
from facesynth.formats.mocap import read_mocap


def _digest(folder):
    h = hashlib.sha256()
    for p in sorted(folder.rglob("*")):
        if p.is_file():
            h.update(p.relative_to(folder).as_posix().encode())
            h.update(p.read_bytes())
    return h.hexdigest()


def test_same_seed_same_bytes_other_seed_other_bytes(tmp_path, tiny_corpus):
    generate(tmp_path / "a", "tiny", seed=0)
    generate(tmp_path / "b", "tiny", seed=1)
    assert _digest(tmp_path / "a") == _digest(tiny_corpus)
    assert _digest(tmp_path / "b") != _digest(tiny_corpus)


def test_the_corpus_has_every_file_the_manifest_names(tiny_corpus):
    import csv

    rows = list(csv.DictReader(open(tiny_corpus / "manifest.csv")))
    assert {r["emotion"] for r in rows} == {"neutral", "happy", "angry", "sad"}
    assert {r["split"] for r in rows} == {"train", "val", "test"}
    for r in rows:
        for key in ("mocap", "audio", "alignment"):
            assert (tiny_corpus / r[key]).exists()
        if r["split"] == "test":
            assert (tiny_corpus / "groundtruth" / f"{r['take']}.c3d").exists()
    assert (tiny_corpus / "face.obj").exists() and (tiny_corpus / "markers.csv").exists()
    assert len(open(tiny_corpus / "contamination.csv").readlines()) > 1


def _lip_gap(positions, names):
    i, j = (names.index(n) for n in LIP_GAP_MARKERS)
    return np.linalg.norm(positions[:, i] - positions[:, j], axis=1)


def test_lips_close_on_bilabials_and_open_on_vowels(tiny_corpus):
    gaps = {"bilabial": [], "open": []}
    for gt in sorted((tiny_corpus / "groundtruth").glob("*.c3d")):
        take = read_mocap(gt)
        segs = read_phone_segments(tiny_corpus / "labels" / f"{gt.stem}.TextGrid")
        gap = _lip_gap(take.positions, take.names)
        for s in segs:
            centre = int(0.5 * (s.start + s.end) * take.fps)
            if s.label in ("p", "b", "m"):
                gaps["bilabial"].append(gap[centre])
            elif s.label in ("aa", "ae", "ah", "ay", "aw"):
                gaps["open"].append(gap[centre])
    assert gaps["bilabial"] and gaps["open"]
    assert max(gaps["bilabial"]) < 1.0  # mm: the lips touch
    assert np.median(gaps["open"]) > 6.0


def test_coarticulation_makes_context_matter():
    rng = np.random.default_rng(0)
    style = STYLES["neutral"]
    a = time_utterance(["moon"], style, rng, 0.0)   # m uw n: rounded context
    b = time_utterance(["meat"], style, rng, 0.0)   # m iy t: spread context
    pa, pb = articulation(a, style, 120, rng), articulation(b, style, 120, rng)
    ma = int(0.5 * (a.starts[1] + a.ends[1]) * 120)
    mb = int(0.5 * (b.starts[1] + b.ends[1]) * 120)
    assert pa[ma, P["round"]] > pb[mb, P["round"]] + 0.2  # the /m/ anticipates the vowel
    assert pa[ma, P["close"]] > 0.95 and pb[mb, P["close"]] > 0.95


def test_emotions_change_pose_and_timing():
    rng = np.random.default_rng(0)
    words = ["please", "go", "on", "because", "father", "has", "no", "idea"]
    words = [w for w in words if w in lexicon()]
    happy = time_utterance(words, STYLES["happy"], np.random.default_rng(1), 0.0)
    sad = time_utterance(words, STYLES["sad"], np.random.default_rng(1), 0.0)
    assert sad.duration > happy.duration * 1.15
    face = build_face_model()
    rig = Rig(face.vertices[face.marker_vertices], face.lower[face.marker_vertices])
    ph = articulation(happy, STYLES["happy"], 120, rng)
    ps = articulation(sad, STYLES["sad"], 120, rng)
    mc = face.marker_names.index("MC_L")
    assert rig.evaluate(ph)[:, mc, 1].mean() - rig.evaluate(ps)[:, mc, 1].mean() > 4.0  # smile vs frown


def test_head_motion_follows_pitch(tiny_corpus):
    from facesynth.corpus.speech import head_motion, pitch

    rng = np.random.default_rng(3)
    words = list(lexicon())[:12]
    utt = time_utterance(words, STYLES["angry"], rng, 0.0)
    f0 = pitch(utt, STYLES["angry"], 120, rng)
    rotations, _ = head_motion(f0, STYLES["angry"], 120, rng)
    nod = np.arctan2(rotations[:, 2, 1], rotations[:, 2, 2])
    lag = 12
    assert np.corrcoef(f0[:-lag], nod[lag:])[0, 1] > 0.5


def test_audio_pitch_follows_the_emotion(tiny_corpus):
    from facesynth.formats.audio import read_audio

    def f0_estimate(path):
        x, rate = read_audio(path)
        x = x[len(x) // 4 : 3 * len(x) // 4]
        ac = np.correlate(x[:4000], x[:4000], "full")[3999:]
        lo, hi = rate // 400, rate // 100
        return rate / (lo + np.argmax(ac[lo:hi]))

    assert f0_estimate(tiny_corpus / "audio" / "happy_s000.wav") > f0_estimate(tiny_corpus / "audio" / "sad_s000.wav") + 25
