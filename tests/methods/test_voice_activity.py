"""Whether someone speaks (facesynth.domain.voice.activity): WebRTC's detector hears speech and not
steady noise, reads a stream in chunks as the whole audio, and hears speech in a noisy room that
the level alone hears only in part."""

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
