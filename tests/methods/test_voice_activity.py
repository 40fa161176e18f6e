"""Whether someone speaks (facesynth.domain.voice.activity): WebRTC's detector hears speech and not
steady noise, reads a stream in chunks as the whole audio, and hears speech in a noisy room that
the level alone hears only in part; digital silence neither holds the noise floor down nor fools
the detector."""

import csv

import numpy as np
import pytest
import soundfile as sf

from facesynth.domain.voice import activity, articulation, fusion


@pytest.fixture(scope="module")
def speech(tiny_corpus) -> np.ndarray:
    """The held-out take's voice (16 kHz): 0.33 s of silence, 1.9 s of speech, silence."""
    take = next(r["take"] for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["split"] == "test")
    x, rate = sf.read(tiny_corpus / "audio" / f"{take}.wav")
    return articulation.to_analysis_rate(x, rate)


def steady_noises(seconds: float = 3.0) -> dict[str, np.ndarray]:
    """Noises at about -40 dBFS that nobody speaks in: white, brown (rumble) and a 60 Hz hum."""
    rng = np.random.default_rng(0)
    n = int(seconds * 16000)
    spectrum = np.fft.rfft(rng.normal(0, 1, n)) / np.maximum(np.arange(n // 2 + 1), 1)
    brown = np.fft.irfft(spectrum, n)
    return {"white": rng.normal(0, 0.01, n), "brown": 0.01 * brown / brown.std(),
            "hum": 0.014 * np.sin(2 * np.pi * 60 * np.arange(n) / 16000)}


def test_the_detector_hears_speech_and_not_steady_noise(speech):
    flags = activity.speech_frames(speech, 2, len(speech) // 160)
    assert flags[40:200].mean() > 0.9  # the speech
    assert flags[:30].sum() == 0  # the silence before it
    for name, noise in steady_noises().items():
        assert activity.speech_frames(noise, 2, 300).sum() == 0, name
        assert activity.speech_frames(noise, -1, 300).sum() == 0, name


def test_the_detector_reads_a_stream_in_chunks_as_the_whole(speech):
    whole = activity.speech_frames(speech, 2, len(speech) // 160)
    stream = activity.SpeechFrames(2)
    rng = np.random.default_rng(1)
    parts, a = [], 0
    while a < len(speech):
        b = a + int(rng.integers(1, 700))
        parts.append(stream.push(speech[a:b]))
        a = b
    np.testing.assert_array_equal(np.concatenate(parts), whole)
    # its first frames are its noise model settling: a noise's first 70 ms would read as speech
    assert not activity.speech_frames(speech[5000:], 2, 100)[:activity.VAD_WARMUP_FRAMES].any()
    assert activity.speech_frames(speech[5000:], 2, 100)[activity.VAD_WARMUP_FRAMES:].all()
    padded = activity.speech_frames(speech[:1000], 2, 10)
    assert len(padded) == 10 and not padded[6:].any()  # past the last whole 10 ms: not speech


def test_the_band_level_of_a_stream_in_pieces_is_the_whole(speech):
    raw = articulation.frame_features(speech, 16000)
    power = activity.band_power(raw)
    whole = activity.band_level(power)
    for k in (1, 2, 57):
        np.testing.assert_allclose(np.concatenate([activity.band_level(power[:k]),
                                                   activity.band_level(power[k:], power[:k])]), whole, rtol=1e-12)
    # the level is the speech band's: a 60 Hz hum as loud as the speech reads far quieter
    hum = articulation.frame_features(0.1 * np.sin(2 * np.pi * 60 * np.arange(16000) / 16000), 16000)
    assert activity.band_level(activity.band_power(hum))[20:80].max() < np.median(whole[40:200]) - 3


def test_speech_in_a_loud_room_is_heard_where_the_level_hears_it_in_part(speech):
    noisy = speech + np.random.default_rng(2).normal(0, 1.2 * speech[6000:30000].std(), len(speech))
    raw = articulation.frame_features(noisy, 16000)
    times = np.arange(int(len(noisy) / 16000 * 30)) / 30
    level_alone = fusion.confidence(raw, times, 0.5, 1.5, None)
    with_detector = fusion.confidence(raw, times, 0.5, 1.5, activity.speech_frames(noisy, 2, len(raw)))
    assert level_alone[15:60].mean() < 0.8
    assert with_detector[15:60].min() == 1.0
    assert np.all(with_detector >= level_alone)


def _hiss_after_zeros(seconds_zero: float = 1.0, seconds_hiss: float = 3.0) -> np.ndarray:
    """A muted line (exact zeros) then a room's hiss at -45 dBFS, at 16 kHz."""
    hiss = np.random.default_rng(5).normal(0, 10 ** (-45 / 20), int(seconds_hiss * 16000))
    return np.concatenate([np.zeros(int(seconds_zero * 16000)), hiss])


def test_a_room_heard_after_digital_silence_is_not_a_voice():
    x = _hiss_after_zeros()
    raw = articulation.frame_features(x, 16000)
    times = np.arange(120) / 30
    speech = activity.speech_frames(x, 2, len(raw))
    assert not speech.any()  # the detector's 70 ms after the zeros are not taken
    heard = fusion.confidence(raw, times, 0.5, 1.5, speech, activity.floor_frames(x, len(raw)))
    assert heard.max() == 0.0
    # a floor standing on the zeros (and on the frames that read part of them) hears all the hiss
    assert fusion.confidence(raw, times, 0.5, 1.5, speech)[40:].min() == 1.0
    # the frames whose level reads any of the zeros are left out: those of the first second and
    # the next 4 (3 frames of level, half a window each); the analysis's padding after the end is not
    # the audio's and leaves the last frames in
    admitted = activity.floor_frames(x, len(raw))
    assert not admitted[:104].any() and admitted[104:].all()
    np.testing.assert_array_equal(activity.floor_frames(x[16000:], 300), np.ones(300, bool))
    # the 6 ms of zeros a decoder leaves at a file's start (GRID's clips) are not a silenced line
    decoded = np.concatenate([np.zeros(3 * activity.SILENCE_BLOCK), x[16000:]])
    assert activity.floor_frames(decoded, 300).all()
    # 10 ms of zeros are: the frames whose level reads their fifth block (frames 0..4) are left out
    muted = activity.floor_frames(np.concatenate([np.zeros(160), x[16000:]]), 300)
    np.testing.assert_array_equal(np.flatnonzero(~muted), [0, 1, 2, 3, 4])


def test_speech_between_digital_silences_is_heard(speech):
    """The actress's sentence between exact zeros: the floor stands on its own quietest frames,
    and the speech is heard all through."""
    raw = articulation.frame_features(speech, 16000)
    times = np.arange(int(len(speech) / 16000 * 30)) / 30
    c = fusion.confidence(raw, times, 0.5, 1.5, activity.speech_frames(speech, 2, len(raw)),
                          activity.floor_frames(speech, len(raw)))
    sound = np.flatnonzero(np.abs(speech) >= activity.SILENCE_AMPLITUDE) / 16000
    inside = (times > sound[0] + 0.05) & (times < sound[-1] - 0.05)
    assert c[inside].min() == 1.0 and c[times < sound[0] - 0.2].max() == 0.0


def test_the_floor_frames_of_a_stream_in_pieces_are_the_whole(speech):
    x = np.concatenate([speech, _hiss_after_zeros(0.5, 1.0), np.zeros(700)])
    count = articulation.frame_count(len(x))
    whole = activity.floor_frames(x, count)
    frames, parts, done, a = activity.FloorFrames(), [], 0, 0
    rng = np.random.default_rng(6)
    while a < len(x):
        b = min(a + int(rng.integers(1, 900)), len(x))
        frames.push(x[a:b])
        a = b
        ready = min((a - articulation.WIN // 2) // articulation.HOP + 1, count)  # frames whose samples are in
        if ready > done:
            parts.append(frames.admitted(done, ready - done))
            done = ready
    parts.append(frames.admitted(done, count - done))
    np.testing.assert_array_equal(np.concatenate(parts), whole)
    assert 0 < whole.mean() < 1
