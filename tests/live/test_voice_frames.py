"""Live frames from the voice (facesynth.domain.live.voice_frames): sent within the model's look-ahead of
their sound, equal to what the articulation model predicts from the whole audio, the emotion's
pose around the voice's mouth, and the phone-driven path when the voice is off."""

import json
import wave
from dataclasses import replace

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.live.session import Session
from facesynth.domain.live.synthesizer import SPEECH_SHAPES, LiveModel
from facesynth.domain.voice import articulation
from facesynth.model.motiondb import MotionDatabase

CHUNK = 320  # 20 ms of 16 kHz PCM, as a browser or a phone sends it


@pytest.fixture(scope="module")
def db(tiny_db):
    return MotionDatabase.read(tiny_db)


@pytest.fixture(scope="module")
def model(db, config):
    # frames from the voice (the default, named here so that the tests keep it)
    return LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), voice="articulation"),
                     config.settings("solve"))


@pytest.fixture(scope="module")
def pcm(tiny_corpus, held_out_take) -> bytes:
    with wave.open(str(tiny_corpus / "audio" / f"{held_out_take}.wav")) as w:
        return w.readframes(w.getnframes())


def _run(model, pcm: bytes, before: list[dict] = (), switch_at: int | None = None, emotion: str = "happy"):
    """Stream ``pcm`` in 20 ms chunks; returns the frame messages and, per frame, the audio
    received (s) when it was sent."""
    session = Session(model, Config.load().settings("align"), "test")
    frames, received = [], []
    for message in before:
        out = [m for m in session.control(json.dumps(message)) if m["type"] == "frame"]
        frames += out
        received += [session.time] * len(out)
    for k, a in enumerate(range(0, len(pcm), 2 * CHUNK)):
        if switch_at is not None and k == switch_at:
            session.control(json.dumps({"type": "emotion", "name": emotion}))
        out = [m for m in session.audio(pcm[a:a + 2 * CHUNK]) if m["type"] == "frame"]
        frames += out
        received += [session.time] * len(out)
    tail = session.end()
    frames += [m for m in tail if m["type"] == "frame"]
    received += [session.time] * (len(tail) - 1)
    assert tail[-1] == {"type": "end", "frames": len(frames)}
    return session, frames, np.array(received)


def test_frames_go_out_within_the_look_ahead_of_their_sound(model, pcm):
    session, frames, received = _run(model, pcm)
    assert session.recognizer is None  # no phone recogniser runs
    seconds = len(pcm) / 2 / 16000
    assert [f["index"] for f in frames] == list(range(int(np.ceil(seconds * 30))))  # batch's frame count
    times = np.array([f["time"] for f in frames])
    lag = received[:-3] - times[:-3]  # the last frames wait for the end of the audio
    look = articulation.model_look_ahead_s(model.voice_model)
    assert look <= 0.05
    assert lag.max() <= look + CHUNK / 16000 + articulation.FRAME_S + 1e-6
    assert session.hello()["voice_lookahead_s"] == pytest.approx(look, abs=1e-4)


def test_the_mouth_is_what_the_model_predicts_from_the_whole_audio(model, pcm):
    _, frames, _ = _run(model, pcm)
    samples = np.frombuffer(pcm, "<i2").astype(np.float32) / 32768.0
    vm = model.voice_model
    predicted = articulation.predict(vm, samples, 16000, len(frames), 30.0)
    names = list(model.arkit_names)
    jaw = np.array([f["arkit"][names.index("jawOpen")] for f in frames])
    funnel = np.array([f["arkit"][names.index("mouthFunnel")] for f in frames])
    said = np.clip(predicted[:, vm.target_names.index("mouthFunnel")], 0, 1)
    assert np.all(funnel <= said + 2e-4)  # the voice's confidence only scales it down
    heard = np.abs(funnel - said) <= 2e-4
    assert heard.mean() > 0.6  # where the voice is clear, the mouth is the model's
    assert np.all(funnel[:3] == 0) and np.all(jaw[:3] == 0)  # before the speech starts, the mouth rests
    open_jaw = expected_jaw(vm, predicted, model.stream.voice_jaw)
    assert np.all(jaw <= open_jaw + 2e-4)  # the closure score and the confidence only close the jaw
    assert np.corrcoef(jaw, open_jaw)[0, 1] > 0.9
    assert jaw.max() > 0.1 and jaw.min() < 0.3 * jaw.max()


def expected_jaw(vm, predicted: np.ndarray, source: str) -> np.ndarray:
    """The jaw the voice says before the closure and confidence: the predicted jawOpen, or the
    predicted opening carried into the jaw's units (``stream.voice_jaw``)."""
    j = vm.target_names.index("jawOpen")
    if source == "jawOpen":
        return np.clip(predicted[:, j], 0, 1)
    o = vm.target_names.index("opening")
    scaled = vm.target_mean[j] + (predicted[:, o] - vm.target_mean[o]) * vm.target_std[j] / vm.target_std[o]
    return np.clip(scaled, 0, 1)


def test_the_jaw_comes_from_the_opening_or_the_jaw_prediction_as_set(db, config, pcm):
    samples = np.frombuffer(pcm, "<i2").astype(np.float32) / 32768.0
    for source in ("opening", "jawOpen"):
        live = LiveModel(db, config.settings("synthesize"),
                         replace(config.settings("stream"), voice="articulation", voice_jaw=source), config.settings("solve"))
        _, frames, _ = _run(live, pcm)
        vm = live.voice_model
        predicted = articulation.predict(vm, samples, 16000, len(frames), 30.0)
        jaw = np.array([f["arkit"][list(live.arkit_names).index("jawOpen")] for f in frames])
        said = expected_jaw(vm, predicted, source)
        assert np.all(jaw <= said + 2e-4)
        assert np.corrcoef(jaw, said)[0, 1] > 0.9, source


def test_the_mouth_rests_in_steady_noise(model):
    rng = np.random.default_rng(0)
    n = 16000 * 2  # 2 s at about -40 dBFS, nobody speaking
    spectrum = np.fft.rfft(rng.normal(0, 1, n)) / np.maximum(np.arange(n // 2 + 1), 1)
    brown = np.fft.irfft(spectrum, n)
    for name, noise in (("white", rng.normal(0, 0.01, n)), ("brown (rumble)", 0.01 * brown / brown.std())):
        _, frames, _ = _run(model, (noise * 32768).astype("<i2").tobytes())
        jaw = np.array([f["arkit"][list(model.arkit_names).index("jawOpen")] for f in frames])
        assert len(frames) == 60 and jaw.max() < 0.02, name


def test_the_mouth_rests_when_a_room_is_heard_after_digital_silence(model, pcm):
    """A muted line (exact zeros) then the room's hiss: the noise floor does not stand on the
    zeros, so the hiss is the room, not a voice; the speech after it is heard as before."""
    rng = np.random.default_rng(4)
    speech = np.frombuffer(pcm, "<i2").astype(np.float64) / 32768.0
    audio = np.concatenate([np.zeros(16000), rng.normal(0, 10 ** (-45 / 20), 48000)])  # 1 s muted, 3 s hiss
    audio = np.concatenate([audio, speech + rng.normal(0, 10 ** (-45 / 20), len(speech))])
    _, frames, _ = _run(model, (audio * 32768).astype("<i2").tobytes())
    jaw = np.array([f["arkit"][list(model.arkit_names).index("jawOpen")] for f in frames])
    assert jaw[:120].max() < 0.02  # before: open up to 0.22 all through the hiss
    assert jaw[120:].max() > 0.1  # the sentence


def _run_cut_anywhere(model, pcm: bytes, seed: int) -> list[dict]:
    """The frame messages of ``pcm`` streamed in pieces of random lengths (1 to 1,500 samples)."""
    session = Session(model, Config.load().settings("align"), "test")
    rng, frames, a = np.random.default_rng(seed), [], 0
    while a < len(pcm):
        b = a + 2 * int(rng.integers(1, 1500))
        frames += [m for m in session.audio(pcm[a:b]) if m["type"] == "frame"]
        a = b
    return frames + [m for m in session.end() if m["type"] == "frame"]


def test_the_frames_do_not_depend_on_how_the_audio_is_cut(model, pcm):
    _, in_20ms, _ = _run(model, pcm)
    assert [f["arkit"] for f in _run_cut_anywhere(model, pcm, 3)] == [f["arkit"] for f in in_20ms]


def test_with_anticipation_the_mouth_opens_before_its_sound_and_the_frames_wait_for_it(model, db, config, pcm):
    """stream.voice_anticipation_s: each frame waits that much more audio, and the confidence
    hears that far ahead, so the mouth starts to open before the first syllable (a real mouth
    does); the voice's shapes are the same predictions, only rested less."""
    ahead = 0.15
    live = LiveModel(db, config.settings("synthesize"),
                     replace(config.settings("stream"), voice="articulation", voice_anticipation_s=ahead),
                     config.settings("solve"))
    _, now, _ = _run(model, pcm)
    session, later, received = _run(live, pcm)
    assert len(later) == len(now)
    look = articulation.model_look_ahead_s(live.voice_model)
    assert session.hello()["voice_lookahead_s"] == pytest.approx(look + ahead, abs=1e-4)
    lag = received[:-8] - np.array([f["time"] for f in later])[:-8]  # the last frames wait for the end
    assert lag.min() >= look + ahead - 1e-6
    assert lag.max() <= look + ahead + CHUNK / 16000 + articulation.FRAME_S + 1e-6
    names = list(live.arkit_names)
    jaw_now, jaw_later = (np.array([f["arkit"][names.index("jawOpen")] for f in fs]) for fs in (now, later))
    assert np.all(jaw_later >= jaw_now - 1e-4)  # heard as clearly or more: the same mouth, rested less
    first_now, first_later = (int(np.argmax(j > 0.01)) for j in (jaw_now, jaw_later))
    assert 2 <= first_now - first_later <= int(np.ceil(ahead * 30)) + 1  # opens before its sound (here 0.1 s)
    # and still cut anywhere, the same frames
    assert [f["arkit"] for f in _run_cut_anywhere(live, pcm, 5)] == [f["arkit"] for f in later]


def test_a_stream_that_starts_in_speech_in_a_loud_room_moves_the_mouth(db, config, pcm):
    """No quiet frame comes before the speech to tell the noise's level: the voice activity
    detector hears the speech from its first syllable, where the level alone hears it in part."""
    samples = np.frombuffer(pcm, "<i2").astype(np.float64) / 32768.0
    speech = samples[int(0.4 * 16000):]  # cut in the middle of the speech
    noisy = speech + np.random.default_rng(2).normal(0, 1.2 * speech[:24000].std(), len(speech))
    noisy_pcm = (np.clip(noisy, -1, 1) * 32767).astype("<i2").tobytes()
    jaws = {}
    for detector in (2, -1):
        live = LiveModel(db, replace(config.settings("synthesize"), voice_activity=detector),
                         replace(config.settings("stream"), voice="articulation"), config.settings("solve"))
        _, frames, _ = _run(live, noisy_pcm)
        jaws[detector] = np.array([f["arkit"][list(live.arkit_names).index("jawOpen")] for f in frames])
    vm = live.voice_model
    said = expected_jaw(vm, articulation.predict(vm, noisy.astype(np.float32), 16000, len(frames), 30.0),
                        live.stream.voice_jaw)
    speaking = slice(6, 45)  # 0.2 .. 1.5 s: after the detector's first 100 ms
    np.testing.assert_allclose(jaws[2][speaking], said[speaking], atol=2e-4)  # heard fully
    assert np.mean(jaws[-1][speaking] < said[speaking] - 0.01) > 0.3  # the level alone: in part


def test_an_emotion_switch_changes_the_face_around_the_voice_mouth(model, pcm, db):
    assert "happy" in set(db.nodes.emotion)
    _, plain, _ = _run(model, pcm)
    _, switched, _ = _run(model, pcm, switch_at=40)
    names = list(model.arkit_names)
    first = next(f["index"] for a, f in zip(plain, switched) if a["arkit"] != f["arkit"])
    assert 40 * CHUNK / 16000 * 30 - 3 <= first  # nothing before the switch changed
    mouth = [names.index(n) for n in ("jawOpen", "mouthFunnel", "mouthPucker")]
    a, b = np.array(plain[-1]["arkit"]), np.array(switched[-1]["arkit"])
    np.testing.assert_allclose(a[mouth], b[mouth])  # the voice's mouth is the same
    assert np.abs(a - b).max() > 0.01  # the face around it is the emotion's


def test_the_emotion_pose_leaves_the_speech_shapes_to_the_voice(model):
    pose = model.emotion_pose("neutral")
    rig = list(model.rig.shape_names)
    assert np.all(pose[[rig.index(n) for n in SPEECH_SHAPES if n in rig]] == 0)
    markers = model.markers_of(pose[None])[0]
    again = model.solve(markers[None], None)[0]
    np.testing.assert_allclose(again, pose, atol=0.02)  # the markers the pose makes solve back to it


def test_voice_off_streams_the_recognised_phones(model, pcm, config):
    off = LiveModel(model.db, config.settings("synthesize"), replace(config.settings("stream"), voice="off"),
                    config.settings("solve"))
    assert off.voice_model is None
    session, frames, received = _run(off, pcm)
    assert session.recognizer is not None and session.voice is None
    assert len(frames) == 70  # 2.32 s at 30 frames/s, as batch synthesis gives
    assert session.hello()["voice"] == "off"


def test_given_phones_keep_their_path(model, pcm, tiny_corpus, held_out_take):
    from facesynth.domain.speech.utterance import read_utterance

    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    phones = [{"phone": p, "start": float(a), "end": float(b)} for p, a, b in zip(utt.phones, utt.starts, utt.ends)]
    session, frames, _ = _run(model, pcm, before=[{"type": "start", "phones": "given"},
                                                  {"type": "phones", "phones": phones, "final": True}])
    assert session.voice is None and session.recognizer is None
    assert len(frames) == 70


def test_the_search_is_readied_only_for_streams_that_take_it(db, pcm, config, tiny_corpus, held_out_take):
    """A stream of audio whose frames come from the voice never runs the search, so its model does not
    compute the search's transition costs (seconds for a large database); a model whose audio takes
    the phones' path computes them at once, and given phones compute them at their first decision,
    with the frames of a model readied from the start."""
    from facesynth.domain.speech.utterance import read_utterance

    voice = LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), voice="articulation"),
                      config.settings("solve"))
    _run(voice, pcm)
    assert not voice.live.warmed
    off = LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), voice="off"),
                    config.settings("solve"))
    assert off.live.warmed
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    phones = [{"phone": p, "start": float(a), "end": float(b)} for p, a, b in zip(utt.phones, utt.starts, utt.ends)]
    given = [{"type": "start", "phones": "given"}, {"type": "phones", "phones": phones, "final": True}]
    ready = LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), voice="articulation"),
                      config.settings("solve"))
    ready.warm()
    _, lazily, _ = _run(voice, pcm, before=given)
    assert voice.live.warmed
    _, eagerly, _ = _run(ready, pcm, before=given)
    assert [f["arkit"] for f in lazily] == [f["arkit"] for f in eagerly] and len(lazily) == 70
