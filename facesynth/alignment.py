"""Phone-level forced alignment of speech to its text with pocketsphinx.

pocketsphinx's English acoustic model and dictionary ship in its PyPI wheel, so alignment
runs offline. Its dictionary has no stress marks, so each aligned word's stressed
pronunciation is looked up in the CMU dictionary (or the user's ``--dict``) to turn
unstressed AH into the schwa ``ax``; silences become ``pau``.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .config import AlignSettings
from .errors import InputError
from .formats.audio import resample
from .formats.labels import Segment
from .phonemes import PAU, pronunciations, to_festival

_WORD = re.compile(r"[a-z0-9']+")


def normalize_text(text: str) -> list[str]:
    """Lower-case words with punctuation removed (apostrophes kept)."""
    return [w.strip("'") for w in _WORD.findall(text.lower()) if w.strip("'")]


def read_pronunciations(path: Path) -> dict[str, list[tuple[str, ...]]]:
    """A user pronunciation file in CMU format: ``WORD  PH1 PH2 ...`` per line (stress digits optional)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: pronunciation file not found; check the --dict path.")
    out: dict[str, list[tuple[str, ...]]] = {}
    for n, line in enumerate(path.read_text("utf-8").splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        word, *phones = line.split()
        word = re.sub(r"\(\d+\)$", "", word.lower())
        if not phones or any(to_festival(p) is None for p in phones):
            raise InputError(f"{path}, line {n}: {line!r} is not 'word PH1 PH2 ...' with ARPAbet phones.")
        out.setdefault(word, []).append(tuple(p.upper() for p in phones))
    return out


def _strip(phones) -> tuple[str, ...]:
    return tuple(re.sub(r"\d", "", p).upper() for p in phones)


def _stressed(word: str, sphinx_phones: tuple[str, ...], extra: dict, stressed: dict) -> tuple[str, ...]:
    """The stressed pronunciation of ``word`` whose phones match what was aligned."""
    for pron in list(extra.get(word, [])) + list(stressed.get(word, ())):
        if _strip(pron) == sphinx_phones:
            return tuple(pron)
    return sphinx_phones


def align_samples(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None = None,
                  where: str = "audio") -> list[Segment]:
    """Align mono ``samples`` at ``rate`` Hz to ``text`` with the ``[align]`` settings. Returns
    Festival phone segments (seconds) tiling [0, duration] (silences as ``pau``)."""
    return align_words(samples, rate, text, extra=extra, settings=settings, where=where)[0]


def align_words(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None = None,
                where: str = "audio",
                retry_tail: bool = True) -> tuple[list[Segment], list[Segment]]:
    """Like :func:`align_samples`, also returning the word segments."""
    import pocketsphinx

    extra = extra or {}
    words = normalize_text(text)
    if not words:
        raise InputError(f"{where}: the text to align has no words.")
    decoder = pocketsphinx.Decoder(lm=None, samprate=settings.sample_rate, frate=settings.frame_rate, loglevel="FATAL")
    for word, prons in extra.items():
        for k, pron in enumerate(prons):
            decoder.add_word(word if k == 0 else f"{word}({k + 1})", " ".join(_strip(pron)), True)
    unknown = sorted({w for w in words if decoder.lookup_word(w) is None})
    if unknown:
        raise InputError(
            f"{where}: no pronunciation for {', '.join(repr(w) for w in unknown)}; "
            "give one in a file passed with --dict (lines like 'word  W ER D')."
        )
    audio = resample(samples.astype(np.float32), rate, settings.sample_rate)
    pcm = (np.clip(audio, -1, 1) * 32767).astype(np.int16).tobytes()
    try:
        decoder.set_align_text(" ".join(words))
        for _ in range(2):  # first pass: word alignment; second: phone alignment
            decoder.start_utt()
            decoder.process_raw(pcm, full_utt=True)
            decoder.end_utt()
            if _ == 0:
                decoder.set_alignment()
        alignment = decoder.get_alignment()
    except RuntimeError as exc:
        raise InputError(f"{where}: forced alignment failed ({exc}); check that the text matches the speech.") from None
    if alignment is None:
        raise InputError(f"{where}: forced alignment found no path; check that the text matches the speech.")
    frame = 1.0 / settings.frame_rate
    stressed = pronunciations(words)
    segments: list[Segment] = []
    word_segments: list[Segment] = []
    for word in alignment:
        name = re.sub(r"\(\d+\)$", "", word.name)
        phones = [p for p in word]
        start, end = word.start * frame, (word.start + word.duration) * frame
        if name.startswith("<") or name.startswith("[") or not phones:
            segments.append(Segment(start, end, PAU))
            continue
        word_segments.append(Segment(start, end, name))
        pron = _stressed(name, tuple(p.name for p in phones), extra, stressed)
        for p, label in zip(phones, pron):
            segments.append(Segment(p.start * frame, (p.start + p.duration) * frame, to_festival(label) or PAU))
    duration = len(audio) / settings.sample_rate
    placed = [w.label for w in word_segments]
    if placed != words:
        # The search sometimes stops short of the end, calling the last words silence. If the
        # words it placed are a prefix, align the rest to the audio after them, once.
        rest = words[len(placed):]
        cut = word_segments[-1].end if word_segments else 0.0
        if placed == words[: len(placed)] and placed and retry_tail:
            start = int(round(cut * settings.sample_rate))
            try:
                tail, tail_words = align_words(audio[start:], settings.sample_rate, " ".join(rest), extra=extra,
                                               settings=settings, where=where, retry_tail=False)
            except InputError:
                tail = None
            if tail is not None:
                kept = [s for s in segments if s.end <= cut + 1e-6]
                shifted = [Segment(s.start + cut, s.end + cut, s.label) for s in tail]
                moved = [Segment(w.start + cut, w.end + cut, w.label) for w in tail_words]
                return _tile(kept + shifted, duration), word_segments + moved
        lost = [w for w in words if w not in set(placed)] or rest
        raise InputError(
            f"{where}: forced alignment could not place {', '.join(repr(w) for w in lost) or 'every word'}; "
            "check that the text matches the speech."
        )
    return _tile(segments, duration), word_segments


def _tile(segments: list[Segment], duration: float) -> list[Segment]:
    """Merge adjacent pauses and fill gaps so segments cover [0, duration] without overlap."""
    out: list[Segment] = []
    cursor = 0.0
    for s in segments:
        start = max(s.start, cursor)
        if start > cursor + 1e-6:
            out.append(Segment(cursor, start, PAU))
        end = max(s.end, start + 1e-3)
        out.append(Segment(start, end, s.label))
        cursor = end
    if duration > cursor + 1e-6:
        out.append(Segment(cursor, duration, PAU))
    merged: list[Segment] = []
    for s in out:
        if merged and merged[-1].label == PAU and s.label == PAU:
            merged[-1] = Segment(merged[-1].start, s.end, PAU)
        else:
            merged.append(s)
    return [Segment(round(s.start, 4), round(s.end, 4), s.label) for s in merged]


