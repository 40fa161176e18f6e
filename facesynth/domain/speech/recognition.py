"""Phones from speech alone, for audio that comes without a transcript (pocketsphinx's bundled
US English models; offline and deterministic).

:func:`align_or_recognize` is what the commands call: a text, when given, is force-aligned
(:func:`facesynth.domain.speech.alignment.align_robust`) and the audio is not recognised at all; without a
text the phones are recognised by one of two modes (``align.recognition``):

- ``words`` (the default): word recognition with pocketsphinx's English language model and
  dictionary, then forced alignment of the recognised words with the fallbacks of a given text
  (``align.methods``). The phones are the dictionary's pronunciations of the recognised words,
  so a misheard word still gives a well-formed English phone sequence.
- ``phones``: phone-loop decoding (pocketsphinx's ``allphone`` search with its phonetic
  trigram model ``en-us-phone.lm.bin``): the phones and their timing straight from the
  acoustic model, with no dictionary (and so no stress: every ``AH`` stays ``ah``, never the
  schwa ``ax``) and no words.

Each tries pocketsphinx's default beams first and, when they find nothing, the wide beam of
``align.wide_beam``. Audio with no voice activity, or in which neither beam recognises a
word (or a phone), is refused with one sentence: there is nothing to animate.
``benchmarks/recognition_accuracy.py`` measures both modes against the text-given alignment
(see docs/inputs.md).
"""

from __future__ import annotations

import os
import re

import numpy as np

from facesynth.base.config import AlignSettings
from facesynth.base.phonemes import PAU, to_festival
from facesynth.formats.audio import resample
from facesynth.formats.labels import Segment

from .alignment import Alignment, AlignmentFailed, align_robust, pcm16, tile, voice_activity
from .languages import is_english

#: The recognition modes of ``align.recognition``.
MODES = ("words", "phones")


def align_or_recognize(samples: np.ndarray, rate: int, text: str | None, *, settings: AlignSettings,
                       extra: dict | None = None, where: str = "audio") -> Alignment:
    """The phones of mono ``samples`` ((n,) float32 in [-1, 1] at ``rate`` Hz): ``text``
    force-aligned when it is given (even empty: an explicit text with no words is an error),
    else recognised by ``settings.recognition`` (see the module docstring). The result's
    ``recognized`` is empty for a given text, else the recognised words (or phones)."""
    if text is not None:
        return align_robust(samples, rate, text, settings=settings, extra=extra, where=where)
    return recognize(samples, rate, settings=settings, extra=extra, where=where)


def recognize(samples: np.ndarray, rate: int, *, settings: AlignSettings, extra: dict | None = None,
              where: str = "audio") -> Alignment:
    """Recognise the phones of ``samples`` ((n,) float32 mono at ``rate`` Hz) with
    ``settings.recognition``. Returns an :class:`~facesynth.domain.speech.alignment.Alignment` whose phones
    tile the audio (Festival phones, seconds), whose ``method`` is ``words/<alignment method>``
    or ``phones`` and whose ``recognized`` holds what was recognised. Raises
    :class:`~facesynth.domain.speech.alignment.AlignmentFailed` when the audio holds no speech."""
    audio = resample(np.asarray(samples, np.float32), rate, settings.sample_rate)
    duration = len(audio) / settings.sample_rate
    if not voice_activity(audio, settings).any():
        raise AlignmentFailed(_no_speech(where, "it has no voice activity"))
    # in another language than English the word recogniser would invent English words: phones only
    if settings.recognition == "phones" or not is_english(settings.language):
        phones, attempts = _recognize_phones(audio, settings)
        if not phones:
            raise AlignmentFailed(_no_speech(where, "the phone recogniser found no phone"))
        recognized = " ".join(s.label for s in phones if s.label != PAU)
        return Alignment(tile(phones, duration), [], "phones", attempts, recognized=recognized)
    words, attempts = _recognize_words(audio, settings)
    if not words:
        raise AlignmentFailed(_no_speech(where, "the word recogniser found no word"))
    recognized = " ".join(words)
    # the recognised words are aligned to the audio as given at its own rate (align_robust resamples)
    result = align_robust(samples, rate, recognized, settings=settings, extra=extra, where=where)
    result.method = f"words/{result.method}"
    result.attempts = attempts + result.attempts
    result.recognized = recognized
    return result


def _no_speech(where: str, reason: str) -> str:
    return f"{where}: no speech was found ({reason}); check that the file holds speech, or give what is said as a text."


def _decode(audio: np.ndarray, settings: AlignSettings, beam: float | None, **options):
    """Run a pocketsphinx decoder built with ``options`` (and ``beam`` for every beam, None:
    its defaults) over ``audio`` (float32 at ``settings.sample_rate``); returns the decoder and
    its segments as (label, first frame, end frame)."""
    import pocketsphinx

    options.update(samprate=settings.sample_rate, frate=settings.frame_rate, loglevel="FATAL", dither=False)
    if beam is not None:
        options.update(beam=beam, wbeam=beam, pbeam=beam, maxhmmpf=-1)
    decoder = pocketsphinx.Decoder(**options)
    decoder.start_utt()
    decoder.process_raw(pcm16(audio), full_utt=True)
    decoder.end_utt()
    return decoder, [(seg.word, seg.start_frame, seg.end_frame + 1) for seg in decoder.seg() or ()]


def _with_beams(settings: AlignSettings, attempt) -> tuple[list, list[str]]:
    """``attempt(beam)`` with the default beams, then, when it finds nothing, the wide beam."""
    attempts = []
    for name, beam in (("default beam", None), ("wide beam", settings.wide_beam)):
        found = attempt(beam)
        if found:
            return found, attempts
        attempts.append(f"recognition with the {name}: nothing recognised")
    return [], attempts


def _recognize_words(audio: np.ndarray, settings: AlignSettings) -> tuple[list[str], list[str]]:
    """The words pocketsphinx's language model recognises in ``audio``, fillers (``<s>``,
    ``<sil>``, ``[NOISE]``) left out and alternative pronunciations (``word(2)``) named by
    their word; and why each beam found none."""

    def attempt(beam):
        decoder, segments = _decode(audio, settings, beam)
        words = [re.sub(r"\(\d+\)$", "", w) for w, _, _ in segments]
        return [w for w in words if not w.startswith(("<", "[", "+")) and decoder.lookup_word(w) is not None]

    return _with_beams(settings, attempt)


def phone_loop_model() -> str:
    """The path of pocketsphinx's bundled phonetic trigram model (``en-us-phone.lm.bin``), the
    ``allphone`` search's model for file and live recognition."""
    import pocketsphinx

    return os.path.join(pocketsphinx.get_model_path(), "en-us", "en-us-phone.lm.bin")


def _recognize_phones(audio: np.ndarray, settings: AlignSettings) -> tuple[list[Segment], list[str]]:
    """Phone-loop decoding of ``audio``: Festival phone segments (seconds; silences and noises
    as ``pau``), and why each beam found no phone."""
    model = phone_loop_model()
    frame = 1.0 / settings.frame_rate

    def attempt(beam):
        _, segments = _decode(audio, settings, beam, lm=None, allphone=model, bestpath=True)
        phones = [Segment(a * frame, b * frame, to_festival(label) or PAU) for label, a, b in segments]
        return phones if any(s.label != PAU for s in phones) else []

    return _with_beams(settings, attempt)
