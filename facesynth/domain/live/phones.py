"""Phones as they become known during a stream.

- :class:`PhoneRecognizer`: pocketsphinx's live phone-loop decoding (the ``allphone`` search
  with the phonetic trigram model, as ``align.recognition = "phones"`` configures it for files,
  :mod:`facesynth.domain.speech.recognition`), fed 16 kHz mono 16-bit PCM as it arrives. Its partial
  hypothesis revises its last phones as more audio comes in, so the last
  ``stream.recognition_hold`` phones stay provisional; the others are final and passed on.
  The decoder's utterance is ended and a new one started in a silence (0.3 s or more) once it is
  ``stream.recognition_restart_s`` long, so a stream of hours costs no more per chunk than a
  sentence (each step reads the utterance's segments, and the decoder's tables grow with it).
- :func:`given_phones`: the phone timings a TTS engine gives as it speaks (a JSON control
  message), checked and mapped to the Festival set (IPA phones of another language to their
  articulatory nearest English phones, :func:`facesynth.base.ipa.nearest_festival`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.base.ipa import nearest_festival
from facesynth.base.phonemes import PAU, map_phones, to_festival
from facesynth.domain.speech.recognition import phone_loop_model

#: The sample rate live audio arrives at (Hz): 16-bit little-endian mono PCM.
SAMPLE_RATE = 16000
#: The silence (s) the recogniser must be in before it starts a new utterance: longer than a stop's closure.
RESTART_SILENCE_S = 0.3


@dataclass
class PhoneRecognizer:
    """Live phone-loop decoding of a PCM stream; :meth:`feed` returns the phones that became
    final, as (Festival phone, start s, end s), silences and noises as ``pau``."""

    settings: AlignSettings
    hold: int = 2
    restart_s: float = 20.0

    def __post_init__(self):
        import pocketsphinx

        if self.settings.sample_rate != SAMPLE_RATE:
            raise InputError(f"align.sample_rate is {self.settings.sample_rate} Hz; live recognition reads "
                             f"{SAMPLE_RATE} Hz audio, so set it to {SAMPLE_RATE}.")
        self.decoder = pocketsphinx.Decoder(lm=None, allphone=phone_loop_model(), samprate=SAMPLE_RATE,
                                            frate=self.settings.frame_rate, loglevel="FATAL", dither=False)
        self.decoder.start_utt()
        self.samples = 0
        self.utterance_start = 0   # recogniser frame of the stream where the decoder's utterance began
        self.accepted_frames = 0   # recogniser frames of the stream already passed on
        self._pending = b""
        self.ended = False

    @property
    def time(self) -> float:
        """Seconds of audio received."""
        return self.samples / SAMPLE_RATE

    def feed(self, pcm: bytes) -> list[tuple[str, float, float]]:
        """Decode ``pcm`` (16-bit little-endian mono at 16 kHz; an odd trailing byte is kept for
        the next chunk) and return the phones that became final."""
        data = self._pending + pcm
        whole = len(data) - len(data) % 2
        self._pending = data[whole:]
        if whole:
            self.decoder.process_raw(data[:whole], full_utt=False)
            self.samples += whole // 2
        segments = self._segments()
        out = self._final(segments[: len(segments) - self.hold])
        frames_now = self.samples * self.settings.frame_rate // SAMPLE_RATE
        if (frames_now - self.utterance_start >= self.restart_s * self.settings.frame_rate and segments
                and (to_festival(segments[-1][0]) or PAU) == PAU
                and segments[-1][2] - segments[-1][1] >= RESTART_SILENCE_S * self.settings.frame_rate):
            # in a silence: end the decoder's utterance (its last phones become final) and start another
            self.decoder.end_utt()
            out += self._final(self._segments())
            if self.accepted_frames < frames_now:  # audio the decoder had not placed yet: silence
                frame = 1.0 / self.settings.frame_rate
                out.append((PAU, self.accepted_frames * frame, frames_now * frame))
                self.accepted_frames = frames_now
            self.decoder.start_utt()
            self.utterance_start = self.accepted_frames
        return out

    def end(self) -> list[tuple[str, float, float]]:
        """End of the audio: every remaining phone is final."""
        if self.ended:
            return []
        self.decoder.end_utt()
        self.ended = True
        return self._final(self._segments())

    def _segments(self) -> list[tuple[str, int, int]]:
        """The decoder's current segments: (label, first frame, end frame) in stream frames."""
        off = self.utterance_start
        return [(s.word, s.start_frame + off, s.end_frame + 1 + off) for s in self.decoder.seg() or ()]

    def _final(self, segments) -> list[tuple[str, float, float]]:
        """Pass on ``segments`` (final ones) not passed on yet, tiling from the last one passed on."""
        frame = 1.0 / self.settings.frame_rate
        out = []
        for label, a, b in segments:
            if b <= self.accepted_frames:
                continue  # passed on already (its boundaries may have moved since: kept as sent)
            start = max(a, self.accepted_frames)
            out.append((to_festival(label) or PAU, start * frame, b * frame))
            self.accepted_frames = b
        return out


def given_phones(items, where: str, ipa: bool = False) -> list[tuple[str, float, float, str]]:
    """Phone timings of a control message: a list of ``{"phone": name, "start": s, "end": s}``
    (CMU/ARPAbet with or without stress digits, or Festival names; with ``ipa``, a stream in
    another language, IPA symbols, each standing as its articulatory nearest English phone and
    matched by its features in the search, as batch does), in time order:
    ``(festival_phone, start_s, end_s, ipa_phone)`` tuples (``ipa_phone`` "" for English and
    pauses)."""
    if not isinstance(items, list):
        raise InputError(f"{where}: 'phones' must be a list of {{\"phone\", \"start\", \"end\"}} objects.")
    names: list[str] = []
    starts: list[float] = []
    ends: list[float] = []
    for k, item in enumerate(items):
        if not isinstance(item, dict) or not isinstance(item.get("phone"), str):
            raise InputError(f"{where}: phone {k} must be an object with a 'phone' name and 'start' and 'end' times.")
        a, b = _seconds(item.get("start")), _seconds(item.get("end"))
        if a is None or b is None or not 0 <= a < b:
            raise InputError(f"{where}: phone {k} ({item['phone']!r}) needs finite times with 0 <= start < end, in seconds.")
        if starts and a < ends[-1] - 1e-6:
            raise InputError(f"{where}: phone {k} ({item['phone']!r}) starts at {a:.3f} s, before the previous phone "
                             f"ends ({ends[-1]:.3f} s); send phones in time order without overlap.")
        names.append(item["phone"])
        starts.append(a)
        ends.append(b)
    if not ipa:
        return [(label, a, b, "") for label, a, b in zip(map_phones(names, where, starts), starts, ends)]
    labels = _ipa_phones(names, where, starts)
    return [(label, a, b, "" if label == PAU else name.strip())
            for label, name, a, b in zip(labels, names, starts, ends)]


#: Names a stream in another language may give a pause (IPA has no symbol for silence).
_IPA_PAUSES = frozenset({"", "_", "sil", "sp", "pau"})


def _ipa_phones(names: list[str], where: str, starts: list[float]) -> list[str]:
    """IPA phones as their nearest English (Festival) phones; a name of :data:`_IPA_PAUSES` is a pause."""
    out = []
    for name, start in zip(names, starts):
        if name.strip() in _IPA_PAUSES:
            out.append(PAU)
            continue
        try:
            out.append(nearest_festival(name.strip()))
        except KeyError:
            raise InputError(f"{where}, {start:.3f} s: {name!r} is not an IPA phone facesynth knows; "
                             "send IPA symbols (docs/methods.md), or 'sil' for a pause.") from None
    return out


def _seconds(value) -> float | None:
    """``value`` of a control message as a time in seconds: a finite number (not a bool), else None."""
    if isinstance(value, (int, float)) and not isinstance(value, bool) and np.isfinite(value):
        return float(value)
    return None
