"""facesynth.domain.speech.alignment: the fallbacks, the transcript-mismatch check, non-speech marks and
user pronunciations, on the tiny sample corpus's speech (exact timing known)."""

import csv
import dataclasses

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.speech.alignment import (
    AlignmentFailed,
    align_robust,
    longest_voiced_pause,
    non_speech_marks,
    normalize_text,
    voice_activity,
    voicing,
)
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import Segment
from facesynth.stages import align


@pytest.fixture(scope="module")
def take(tiny_corpus):
    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    samples, rate = read_audio(tiny_corpus / row["audio"])
    return samples, rate, row["transcript"]


def test_non_speech_marks_are_not_words():
    text = "[breath] Hello <noise> there, {cough} world [laugh]"
    assert normalize_text(text) == ["hello", "there", "world"]
    assert non_speech_marks(text) == ["[breath]", "<noise>", "{cough}", "[laugh]"]


def test_marked_non_speech_aligns_as_pause(take, config):
    samples, rate, text = take
    result = align_robust(samples, rate, f"[breath] {text} [laugh]", settings=config.settings("align"))
    assert [w.label for w in result.words] == text.split()
    assert result.phones[0].label == "pau" and result.phones[-1].label == "pau"


def test_every_method_tiles_the_audio_with_the_words_in_order(take, config):
    samples, rate, text = take
    duration = len(samples) / rate
    for method in ("pocketsphinx", "wide-beam", "duration"):
        settings = dataclasses.replace(config.settings("align"), methods=(method,))
        result = align_robust(samples, rate, text, settings=settings)
        assert result.method == method
        assert [w.label for w in result.words] == text.split()
        assert result.phones[0].start == 0 and result.phones[-1].end == pytest.approx(duration, abs=0.01)
        assert all(a.end == pytest.approx(b.start) for a, b in zip(result.phones, result.phones[1:]))


def test_a_failing_method_falls_back_to_the_next_and_says_why(take, config):
    samples, rate, text = take
    # a tiny-corpus sentence has no pause long enough to cut at: chunks fails, the duration model places the words
    settings = dataclasses.replace(config.settings("align"), methods=("chunks", "duration"))
    result = align_robust(samples, rate, text, settings=settings)
    assert result.method == "duration" and result.attempts == ["chunks: no silence to cut at"]


def test_a_transcript_lacking_words_is_flagged(take, config):
    samples, rate, text = take
    first = text.split()[0]
    result = align_robust(samples, rate, first, settings=config.settings("align"), where="x.wav")
    assert result.mismatch and result.voiced_pause_s > config.settings("align").max_voiced_pause_s
    assert all(w.startswith("x.wav: ") for w in result.warnings)
    assert any("the transcript may lack words" in w for w in result.warnings)


def test_a_wrong_text_timed_by_durations_is_flagged(take, config):
    samples, rate, text = take
    settings = dataclasses.replace(config.settings("align"), methods=("duration",))
    assert not align_robust(samples, rate, text, settings=settings).mismatch
    result = align_robust(samples, rate, "the", settings=settings, where="x.wav")
    assert result.mismatch and "x.wav: the audio has" in result.warnings[0]
    assert "the text may not be what is said" in result.warnings[0]
    assert not align_robust(samples, rate, text, settings=config.settings("align")).mismatch


def test_audio_too_short_for_its_text_is_refused(take, config):
    samples, rate, text = take
    with pytest.raises(AlignmentFailed, match=r"x.wav: the audio lasts 0.25 s, too short for its text's \d+ phones"):
        align_robust(samples[: rate // 4], rate, text, settings=config.settings("align"), where="x.wav")


def test_no_words_and_unknown_words_are_input_errors(take, config):
    samples, rate, _ = take
    with pytest.raises(InputError, match="has no words"):
        align_robust(samples, rate, " ,. ", settings=config.settings("align"))
    with pytest.raises(InputError, match="no pronunciation for 'zorblat'"):
        align_robust(samples, rate, "zorblat", settings=config.settings("align"))


def test_a_dict_word_the_dictionary_already_has_is_added_beside_it(tiny_corpus, take, config, tmp_path):
    _, _, text = take
    word = text.split()[0]
    d = tmp_path / "extra.dict"
    d.write_text(f"{word}  L AE F\n{word}  L AA F\n")  # one already known, one new
    out = tmp_path / "a.TextGrid"
    summary = align.run(tiny_corpus / "audio" / "neutral_s001.wav", text, out, config.settings("align"), dict_path=d)
    assert summary.phones > 0 and out.exists()


def test_voice_activity_and_the_longest_voiced_pause(config):
    settings = config.settings("align")
    rate = settings.sample_rate
    t = np.arange(rate) / rate
    audio = np.zeros(2 * rate, np.float32)
    audio[rate // 2: rate] = 0.3 * np.sin(2 * np.pi * 200 * t[: rate // 2])  # voice from 0.5 s to 1.0 s
    active = voice_activity(audio, settings)
    assert active.shape == (200,) and active[55:95].all() and not active[:45].any() and not active[105:].any()
    hop = 1 / settings.frame_rate
    phones = [Segment(0, 0.7, "pau"), Segment(0.7, 1.0, "aa"), Segment(1.0, 2.0, "pau")]
    length, at = longest_voiced_pause(phones, active, hop)
    assert length == pytest.approx(0.2, abs=0.02) and at == pytest.approx(0.5, abs=0.02)


def test_a_text_of_non_speech_only_is_one_pause(take, config):
    samples, rate, _ = take
    result = align_robust(samples, rate, "[laugh] <breath>", settings=config.settings("align"))
    assert result.method == "non-speech" and [p.label for p in result.phones] == ["pau"] and not result.words


def test_voicing_tells_a_vowel_from_noise(config):
    settings = config.settings("align")
    rate = settings.sample_rate
    t = np.arange(rate // 2) / rate
    vowel = 0.3 * np.sign(np.sin(2 * np.pi * 150 * t))  # a buzz at 150 Hz
    noise = 0.3 * np.random.default_rng(0).standard_normal(rate // 2)
    voiced = voicing(np.concatenate([vowel, noise]).astype(np.float32), settings)
    assert voiced[5:45].mean() > 0.9 and voiced[55:95].mean() < 0.1
