"""Phone-level forced alignment of speech to its text with pocketsphinx, with fallbacks so that
every line gets an alignment or a clear reason.

pocketsphinx's English acoustic model and dictionary ship in its PyPI wheel, so alignment
runs offline. Its dictionary has no stress marks, so each aligned word's stressed
pronunciation is looked up in the CMU dictionary (or the user's ``--dict``) to turn
unstressed AH into the schwa ``ax``; silences become ``pau``.

:func:`align_robust` tries, in the order of ``align.methods``:

- ``pocketsphinx``: forced alignment with the default beams;
- ``wide-beam``: the same with every beam widened to ``align.wide_beam`` (emotional or
  unusual voices fall off the default beam: "Failed to stop utterance processing");
- ``chunks``: the audio cut at silences of at least ``align.min_silence_s``, the words
  shared among the chunks in proportion to their expected and the chunks' voiced
  durations, each chunk aligned on its own (with both beams);
- ``duration``: no acoustic search: the words' phones laid over the voiced span of the
  audio with typical phone durations, scaled to fill it (falsetto or whispered speech that
  the acoustic model cannot follow at all).

The first that places every word is kept and named in the result. Audio without a text is
recognised first (:mod:`facesynth.domain.speech.recognition`), then its words aligned the same way. The duration model places
any text, so a result timed by durations is also checked against the text's typical
duration: speech more than ``align.max_rate_ratio`` times longer or shorter is warned about. When pocketsphinx places
the first words and cannot go on (the rest of a line whispered, or trailing off), the rest
get typical durations over the voice after them, and the method is named
``pocketsphinx+durations`` (or ``wide-beam+durations``). A transcript that does
not match the speech shows as long stretches of voice activity labelled ``pau``; the
longest is measured and reported as a warning above ``align.max_voiced_pause_s``.
Non-speech marked in the transcript (``[breath]``, ``[laugh]``, ``<noise>``, ``{cough}``)
is not a word: the aligner places it as pause.

A text in another language (``align.language``) is read by its G2P backend
(:mod:`facesynth.domain.speech.languages`), each phone mapped to the nearest English phone by its
articulation; its words enter the English acoustic model's dictionary under names of their own
with those phones, and are aligned by the same methods (cross-language forced alignment). The
word tier names the words as written.
"""

from __future__ import annotations

import logging
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.base.ipa import nearest_festival
from facesynth.base.phonemes import PAU, pronunciations, to_festival, typical_duration
from facesynth.domain.speech.languages import Word, is_english, primary, read_dictionary, words_of
from facesynth.formats.audio import resample
from facesynth.formats.labels import Segment

log = logging.getLogger(__name__)

_WORD = re.compile(r"[a-z0-9']+")
#: Non-speech in a transcript: [breath], [laugh], <noise>, {cough}: aligned as pause.
_NON_SPEECH = re.compile(r"\[[^\]]*\]|<[^>]*>|\{[^}]*\}")

#: Every method :func:`align_robust` knows, in its default order.
METHODS = ("pocketsphinx", "wide-beam", "chunks", "duration")


def non_speech_marks(text: str) -> list[str]:
    """The non-speech marks of a transcript (``[breath]``, ``<noise>``, ``{cough}``), in order."""
    return _NON_SPEECH.findall(text)


def normalize_text(text: str) -> list[str]:
    """Lower-case words with punctuation and non-speech marks removed (apostrophes kept)."""
    text = _NON_SPEECH.sub(" ", text)
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


@dataclass
class Alignment:
    """What :func:`align_robust` found for one recording.

    ``phones``: Festival phone segments (seconds) tiling [0, duration], silences as ``pau``;
    ``words``: the spoken words' segments (seconds); ``method``: the method that placed every
    word (one of :data:`METHODS`, ``+durations`` when the last words got typical durations;
    for recognised speech ``words/`` before it, or ``phones``); ``attempts``: why each earlier
    method was not used;
    ``voiced_pause_s``: the longest stretch of voice activity (s) inside a ``pau`` segment;
    ``warnings``: sentences for the user (a transcript that seems to lack words);
    ``recognized``: empty for a given text; for audio alone (:mod:`facesynth.domain.speech.recognition`) the
    recognised words, or phones, that were aligned;
    ``ipa``: for words given in another language (:func:`align_pronounced`), the IPA phone each
    segment of ``phones`` pronounces (``""`` at pauses); None otherwise.
    """

    phones: list[Segment]
    words: list[Segment]
    method: str
    attempts: list[str] = field(default_factory=list)
    voiced_pause_s: float = 0.0
    voiced_pause_at_s: float = 0.0
    warnings: list[str] = field(default_factory=list)
    recognized: str = ""
    ipa: list[str] | None = None

    @property
    def mismatch(self) -> bool:
        """True when the alignment labels a long stretch of speech as pause (see the warning)."""
        return bool(self.warnings)


class AlignmentFailed(InputError):
    """No method placed every word of the text on the speech; the message says why."""


class _MethodFailed(Exception):
    """One method could not place every word (internal: the next method is tried)."""


def align_samples(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None = None,
                  where: str = "audio") -> list[Segment]:
    """Align mono ``samples`` at ``rate`` Hz to ``text`` with the ``[align]`` settings. Returns
    Festival phone segments (seconds) tiling [0, duration] (silences as ``pau``); warnings are
    logged."""
    result = align_robust(samples, rate, text, settings=settings, extra=extra, where=where)
    for warning in result.warnings:
        log.warning(warning)
    return result.phones


def align_words(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None = None,
                where: str = "audio") -> tuple[list[Segment], list[Segment]]:
    """Like :func:`align_samples`, also returning the word segments."""
    result = align_robust(samples, rate, text, settings=settings, extra=extra, where=where)
    for warning in result.warnings:
        log.warning(warning)
    return result.phones, result.words


def align_robust(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None = None,
                 where: str = "audio") -> Alignment:
    """Align ``samples`` ((n,) float32 in [-1, 1], mono, ``rate`` Hz) to ``text`` by the first of
    ``settings.methods`` that places every word (see the module docstring).

    Raises :class:`~facesynth.base.errors.InputError` for text without words or with words that
    have no pronunciation (a ``--dict`` fixes it), and :class:`AlignmentFailed` when the audio
    is too short for the text or no method places every word.
    """
    if not is_english(settings.language):
        return _align_language(samples, rate, text, settings=settings, extra=extra, where=where)
    extra = extra or {}
    if settings.dictionary:  # the user's IPA pronunciations, as the nearest English phones (--dict's first)
        own = read_dictionary(Path(settings.dictionary.replace("{language}", primary(settings.language) or "en")))
        extra = {**{w: [_arpabet(tuple(nearest_festival(p) for p in ipa))] for w, ipa in own.items()}, **extra}
    words = normalize_text(text)
    marks = non_speech_marks(text)
    if not words and marks:  # only non-speech ("[laugh]"): all of it is pause
        duration = len(samples) / rate
        return Alignment([Segment(0.0, round(duration, 4), PAU)], [], "non-speech")
    if not words:
        raise InputError(f"{where}: the text to align has no words.")
    decoder = _decoder(settings, extra, None)
    unknown = sorted({w for w in words if decoder.lookup_word(w) is None})
    if unknown:
        raise InputError(
            f"{where}: no pronunciation for {', '.join(repr(w) for w in unknown)}; "
            "give one in a file passed with --dict (lines like 'word  W ER D')."
        )
    audio = resample(np.asarray(samples, np.float32), rate, settings.sample_rate)
    duration = len(audio) / settings.sample_rate
    hop = 1.0 / settings.frame_rate
    active = voice_activity(audio, settings)
    voiced = voicing(audio, settings)
    prons = _pronunciation_table(words, extra, decoder)
    n_phones = sum(len(prons[w]) for w in words)
    voiced_s = float(active.sum()) * hop
    needed = n_phones * settings.min_phone_s
    if duration < needed:
        raise AlignmentFailed(
            f"{where}: the audio lasts {duration:.2f} s, too short for its text's {n_phones} phones (at least "
            f"{needed:.2f} s at {1e3 * settings.min_phone_s:.0f} ms a phone); "
            "check that the audio and the text belong together."
        )
    attempts: list[str] = []
    for method in settings.methods:
        try:
            filled = 0
            if method == "pocketsphinx":  # the decoder that looked the words up, not yet used for audio
                fresh, decoder = decoder, None
                phones, word_segs, filled = _pocketsphinx(audio, words, settings, extra, None, prons, active, fresh)
            elif method == "wide-beam":
                phones, word_segs, filled = _pocketsphinx(audio, words, settings, extra, settings.wide_beam, prons,
                                                          active)
            elif method == "chunks":
                phones, word_segs = _chunks(audio, words, active, settings, extra, prons)
            else:
                phones, word_segs = _duration_model(words, prons, active, hop)
        except _MethodFailed as exc:
            attempts.append(f"{method}: {exc}")
            continue
        phones = tile(phones, duration)
        # each non-speech mark of the text explains one voiced pause (a laugh is voiced)
        longest, at = longest_voiced_pause(phones, active & voiced, hop, skip=len(marks))
        # words after the last one the search placed, given typical durations: named in the method
        result = Alignment(phones, word_segs, f"{method}+durations" if filled else method, attempts, longest, at)
        expected = sum(typical_duration(p) for w in words for p in prons[w])
        # a marked non-speech event may add up to max_voiced_pause_s of sound
        allowed = settings.max_rate_ratio * expected + len(marks) * settings.max_voiced_pause_s
        # an acoustic alignment shows a wrong text as speech aligned as pause (below); timing by
        # typical durations places any text, so there the amount of speech is checked instead
        by_duration = filled or method == "duration"
        if by_duration and (voiced_s > allowed or duration * settings.max_rate_ratio < expected):
            result.warnings.append(
                f"{where}: the audio has {voiced_s:.2f} s of speech where its text's {n_phones} phones typically "
                f"take {expected:.2f} s (more than align.max_rate_ratio = {settings.max_rate_ratio:g} times off); "
                "the text may not be what is said."
            )
        if longest > settings.max_voiced_pause_s:
            result.warnings.append(
                f"{where}: {longest:.2f} s of speech at {at:.2f} s is aligned as pause "
                f"(over align.max_voiced_pause_s = {settings.max_voiced_pause_s:g} s); "
                "the transcript may lack words that are spoken there."
            )
        if attempts:
            log.info("%s: aligned by %s after %s", where, method, "; ".join(attempts))
        return result
    raise AlignmentFailed(f"{where}: no alignment method placed every word ({'; '.join(attempts)}); "
                          "check that the text matches the speech.")


def _arpabet(phones) -> tuple[str, ...]:
    """Festival phones as the CMU dictionary's ARPAbet (the schwa as unstressed ``AH0``)."""
    return tuple("AH0" if p == "ax" else p.upper() for p in phones)


def _align_language(samples: np.ndarray, rate: int, text: str, *, settings: AlignSettings, extra: dict | None,
                    where: str) -> Alignment:
    """:func:`align_robust` of a text in ``settings.language`` (not English): each word as a
    decoder word of its own (``w0x``, ``w1x``, ...: names no English word has) pronounced by the
    nearest English phones of its IPA phones, aligned as English, the word tier relabelled."""
    if extra:
        raise InputError(f"{where}: --dict gives English (ARPAbet) pronunciations; for language "
                         f"{settings.language!r} give 'word  IPA phones' lines in align.dictionary.")
    words = words_of(text, settings.language, settings.dictionary, where)
    return align_pronounced(samples, rate, words, settings=settings, marks=non_speech_marks(text), where=where)


def align_pronounced(samples: np.ndarray, rate: int, words: list[Word], *, settings: AlignSettings,
                     marks: list[str] | None = None, where: str = "audio") -> Alignment:
    """:func:`align_robust` of words whose pronunciations are given (``words``: each with its IPA
    phones and their nearest English phones, as :func:`~facesynth.domain.speech.languages.words_of`
    gives them), in ``samples`` ((n,) float32 in [-1, 1], mono, ``rate`` Hz): each word a decoder
    word of its own (``w0x``, ``w1x``, ...: names no English word has) pronounced by its English
    phones, aligned as English by ``settings.methods``, the word tier relabelled with the words'
    text. ``marks``: the text's non-speech marks (``[laugh]``), each explaining one voiced pause."""
    names: dict[tuple[str, ...], str] = {}
    own: dict[str, list[tuple[str, ...]]] = {}
    written: dict[str, str] = {}
    keys = []
    for word in words:
        arpabet = _arpabet(word.phones)
        key = names.setdefault((word.text.lower(),) + arpabet, f"w{len(names)}x")
        own[key] = [arpabet]
        written.setdefault(key, word.text)
        keys.append(key)
    english = replace(settings, language="en", dictionary="")  # the words are already pronounced
    result = align_robust(samples, rate, " ".join(keys + list(marks or [])), settings=english, extra=own, where=where)
    result.words = [Segment(w.start, w.end, written.get(w.label, w.label)) for w in result.words]
    result.ipa = pronounced_ipa(result.phones, words)
    return result


def pronounced_ipa(phones: list[Segment], words: list[Word]) -> list[str] | None:
    """The IPA phone of each of ``phones`` (aligned Festival segments, pauses ``pau``): the spoken
    phones in order are the words' nearest English phones in order, so each takes its word's IPA
    phone (``""`` at pauses). None when the spoken phones are not exactly the words' (then the
    line is matched by its English phones alone)."""
    spoken = [(p, q) for w in words for p, q in zip(w.phones, w.ipa)]
    out: list[str] = []
    k = 0
    for seg in phones:
        if seg.label == PAU:
            out.append("")
            continue
        if k >= len(spoken) or spoken[k][0] != seg.label:
            return None
        out.append(spoken[k][1])
        k += 1
    return out if k == len(spoken) else None


def voice_activity(audio: np.ndarray, settings: AlignSettings) -> np.ndarray:
    """Frames of ``audio`` ((n,) float32 at ``settings.sample_rate``) with speech-like energy:
    (n_frames,) bool, one frame per ``1 / settings.frame_rate`` s. A frame is active when its
    RMS level (dB) is within ``activity_range_db`` of the loudest frames (99th percentile) and
    ``activity_floor_db`` above the noise floor (5th percentile)."""
    hop = int(round(settings.sample_rate / settings.frame_rate))
    n = max(len(audio) // hop, 1)
    frames = np.zeros(n * hop, np.float64)
    frames[: min(len(audio), n * hop)] = audio[: n * hop]
    rms = np.sqrt(np.mean(frames.reshape(n, hop) ** 2, axis=1) + 1e-12)
    db = 20 * np.log10(rms)
    loud, floor = np.percentile(db, 99), np.percentile(db, 5)
    return (db > loud - settings.activity_range_db) & (db > floor + settings.activity_floor_db)


def voicing(audio: np.ndarray, settings: AlignSettings, threshold: float = 0.5) -> np.ndarray:
    """Frames of ``audio`` ((n,) float32 at ``settings.sample_rate``) that are periodic like voiced
    speech: (n_frames,) bool, one frame per ``1 / settings.frame_rate`` s. A frame is voiced
    when the normalized autocorrelation of the 32 ms window starting at it peaks above
    ``threshold`` at a lag of a 60-400 Hz pitch (breath, friction and noise do not)."""
    rate = settings.sample_rate
    hop = int(round(rate / settings.frame_rate))
    width = int(round(0.032 * rate))
    n = max(len(audio) // hop, 1)
    padded = np.zeros(n * hop + width, np.float64)
    padded[: len(audio)] = audio
    index = np.arange(n)[:, None] * hop + np.arange(width)[None, :]
    frames = padded[index] * np.hanning(width)[None, :]
    frames -= frames.mean(axis=1, keepdims=True)
    size = 1 << int(np.ceil(np.log2(2 * width)))
    spectrum = np.fft.rfft(frames, size, axis=1)
    r = np.fft.irfft(np.abs(spectrum) ** 2, size, axis=1)[:, :width]
    lo, hi = int(rate / 400), int(rate / 60)
    peak = r[:, lo:hi].max(axis=1)
    return peak > threshold * np.maximum(r[:, 0], 1e-12)


def longest_voiced_pause(phones: list[Segment], active: np.ndarray, hop: float, skip: int = 0,
                         bridge_s: float = 0.2) -> tuple[float, float]:
    """The longest stretch of active frames (``active`` (n_frames,) bool, ``hop`` s a frame) inside
    a ``pau`` segment of ``phones``: (its length in s, its start in s); (0, 0) when none. Runs
    less than ``bridge_s`` apart are one stretch (the unvoiced consonants and closures inside
    speech). The ``skip`` longest pauses' stretches are left out (non-speech the transcript marks)."""
    gap = int(round(bridge_s / hop))
    found = []
    for s in phones:
        if s.label != PAU:
            continue
        a, b = int(np.ceil(s.start / hop)), int(np.floor(s.end / hop))
        runs = _runs(active[a:b])
        if not runs:
            continue
        merged = [list(runs[0])]
        for start, stop in runs[1:]:
            if start - merged[-1][1] < gap:
                merged[-1][1] = stop
            else:
                merged.append([start, stop])
        start, stop = max(merged, key=lambda r: r[1] - r[0])
        found.append(((stop - start) * hop, (a + start) * hop))
    found.sort(key=lambda x: -x[0])
    best, at = found[skip] if len(found) > skip else (0.0, 0.0)
    return round(best, 3), round(at, 3)


def pcm16(audio: np.ndarray) -> bytes:
    """``audio`` ((n,) float in [-1, 1], clipped) as the 16-bit little-endian PCM pocketsphinx reads."""
    return (np.clip(audio, -1, 1) * 32767).astype(np.int16).tobytes()


def _decoder(settings: AlignSettings, extra: dict, beam: float | None):
    """A pocketsphinx decoder with the user's pronunciations added (as alternatives of a word the
    dictionary already has: ``word(2)``, ``word(3)``, ...)."""
    import pocketsphinx

    options: dict[str, object] = dict(lm=None, samprate=settings.sample_rate, frate=settings.frame_rate,
                                      loglevel="FATAL")
    if beam is not None:
        options.update(beam=beam, wbeam=beam, pbeam=beam, maxhmmpf=-1)
    decoder = pocketsphinx.Decoder(**options)
    for word, prons in extra.items():
        for pron in prons:
            name, k = word, 1
            while decoder.lookup_word(name) is not None:
                if decoder.lookup_word(name).split() == list(_strip(pron)):
                    break
                k += 1
                name = f"{word}({k})"
            else:
                decoder.add_word(name, " ".join(_strip(pron)), True)
    return decoder


def _pronunciation_table(words: list[str], extra: dict, decoder) -> dict[str, tuple[str, ...]]:
    """One Festival pronunciation per word (the user's first, else CMU's first, else pocketsphinx's)."""
    stressed = pronunciations(words)
    out = {}
    for w in dict.fromkeys(words):
        pron = (list(extra.get(w, [])) + list(stressed.get(w, ())) or [tuple(decoder.lookup_word(w).split())])[0]
        out[w] = tuple(p for p in (to_festival(x) for x in pron) if p and p != PAU)
    return out


def _pocketsphinx(audio: np.ndarray, words: list[str], settings: AlignSettings, extra: dict, beam: float | None,
                  prons: dict | None = None, active: np.ndarray | None = None, decoder=None
                  ) -> tuple[list[Segment], list[Segment], int]:
    """Forced alignment of ``audio`` (float32 at ``settings.sample_rate``) to ``words``; raises
    :class:`_MethodFailed` when pocketsphinx fails or places fewer words. When the words it
    placed are a prefix (the search stopped short, calling the last words silence), the rest
    is aligned to the audio after them, and so on while each try places a word; when a try
    places none, and ``prons`` and ``active`` (the voice activity of ``audio``'s frames) are
    given, the rest get typical durations over the voiced frames after the placed words. When
    the words are placed but their phones cannot be ("Failed to set up sub-word alignment"),
    each word's phones share its span by typical durations. ``decoder``: one that
    :func:`_decoder` made with the same ``extra`` and ``beam`` and that has only looked words up
    (None: one is made). Returns (phones, words, how many words got durations instead of an acoustic alignment)."""
    if decoder is None:
        decoder = _decoder(settings, extra, beam)
    pcm = pcm16(audio)
    frame = 1.0 / settings.frame_rate
    word_pass = None
    try:
        decoder.set_align_text(" ".join(words))
        for k in range(2):  # first pass: word alignment; second: phone alignment
            decoder.start_utt()
            decoder.process_raw(pcm, full_utt=True)
            decoder.end_utt()
            if k == 0:
                word_pass = [(seg.word, seg.start_frame, seg.end_frame + 1) for seg in decoder.seg() or ()]
                decoder.set_alignment()
        alignment = decoder.get_alignment()
    except RuntimeError as exc:
        # "Failed to set up sub-word alignment": the words were placed, their phones were not
        if not word_pass or prons is None:
            raise _MethodFailed(str(exc)) from None
        timed, timed_words = _phones_by_duration(word_pass, prons, frame)
        placed = [w.label for w in timed_words]
        if placed != words:
            raise _MethodFailed(f"{exc}; placed {len(placed)} of {len(words)} words") from None
        return timed, timed_words, len(words)
    if alignment is None:
        raise _MethodFailed("no path")
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
    placed = [w.label for w in word_segments]
    if placed == words:
        return segments, word_segments, 0
    rest = words[len(placed):]
    if placed and placed == words[: len(placed)]:
        cut = word_segments[-1].end
        piece = audio[int(round(cut * settings.sample_rate)):]
        rest_active = active[int(round(cut / frame)):] if active is not None else None
        try:
            tail, tail_words, filled = _pocketsphinx(piece, rest, settings, extra, beam, prons, rest_active)
        except _MethodFailed:
            if prons is None or rest_active is None:
                raise
            tail, tail_words = _duration_model(rest, prons, rest_active, frame)
            filled = len(rest)
        kept = [s for s in segments if s.end <= cut + 1e-6]
        return (kept + [Segment(s.start + cut, s.end + cut, s.label) for s in tail],
                word_segments + [Segment(w.start + cut, w.end + cut, w.label) for w in tail_words], filled)
    raise _MethodFailed(f"placed {len(placed)} of {len(words)} words")


def _phones_by_duration(word_pass: list[tuple[str, int, int]], prons: dict, frame: float
                        ) -> tuple[list[Segment], list[Segment]]:
    """Phone segments for pocketsphinx's word segmentation ((word, first frame, end frame)),
    each word's phones sharing its span in proportion to their typical durations."""
    segments, word_segments = [], []
    for name, a, b in word_pass:
        name = re.sub(r"\(\d+\)$", "", name)
        start, end = a * frame, b * frame
        if name.startswith("<") or name.startswith("[") or name not in prons or not prons[name]:
            segments.append(Segment(start, end, PAU))
            continue
        word_segments.append(Segment(start, end, name))
        d = np.array([typical_duration(p) for p in prons[name]])
        edges = start + (end - start) * np.concatenate([[0.0], np.cumsum(d)]) / d.sum()
        segments += [Segment(float(x), float(y), p) for x, y, p in zip(edges[:-1], edges[1:], prons[name])]
    return segments, word_segments


def _runs(active: np.ndarray) -> list[tuple[int, int]]:
    """(start, stop) frame ranges of the runs of True in ``active``."""
    edges = np.diff(np.concatenate([[0], active.astype(np.int8), [0]]))
    return list(zip(np.nonzero(edges == 1)[0].tolist(), np.nonzero(edges == -1)[0].tolist()))


def _chunks(audio: np.ndarray, words: list[str], active: np.ndarray, settings: AlignSettings, extra: dict,
            prons: dict) -> tuple[list[Segment], list[Segment]]:
    """Cut at silences of at least ``min_silence_s``, share the words among the chunks by
    expected duration and align each chunk on its own (default beam, then the wide one)."""
    hop = 1.0 / settings.frame_rate
    gap = int(round(settings.min_silence_s / hop))
    runs = _runs(active)
    if not runs:
        raise _MethodFailed("no voice activity")
    chunks = [list(runs[0])]
    for a, b in runs[1:]:
        if a - chunks[-1][1] >= gap:
            chunks.append([a, b])
        else:
            chunks[-1][1] = b
    if len(chunks) < 2:
        raise _MethodFailed("no silence to cut at")
    voiced = np.array([b - a for a, b in chunks], float)
    share = np.cumsum(voiced) / voiced.sum()
    expected = np.array([sum(typical_duration(p) for p in prons[w]) for w in words])
    middle = (np.cumsum(expected) - expected / 2) / expected.sum()
    owner = np.searchsorted(share, middle)
    phones: list[Segment] = []
    word_segs: list[Segment] = []
    margin = int(round(0.1 / hop))
    n_frames = len(active)
    for c, (a, b) in enumerate(chunks):
        mine = [w for w, o in zip(words, owner) if o == c]
        if not mine:
            continue
        lo = a - margin if c == 0 else max(a - margin, (chunks[c - 1][1] + a) // 2)
        hi = b + margin if c == len(chunks) - 1 else min(b + margin, (b + chunks[c + 1][0]) // 2)
        lo, hi = max(lo, 0), min(hi, n_frames)
        piece = audio[int(lo * hop * settings.sample_rate): int(hi * hop * settings.sample_rate)]
        for beam in (None, settings.wide_beam):
            try:
                p, w, _ = _pocketsphinx(piece, mine, settings, extra, beam)
                break
            except _MethodFailed as exc:
                reason = str(exc)
        else:
            raise _MethodFailed(f"chunk {c + 1} of {len(chunks)}: {reason}")
        t0 = lo * hop
        phones += [Segment(s.start + t0, s.end + t0, s.label) for s in p]
        word_segs += [Segment(s.start + t0, s.end + t0, s.label) for s in w]
    return phones, word_segs


def _duration_model(words: list[str], prons: dict, active: np.ndarray, hop: float) -> tuple[list[Segment], list[Segment]]:
    """Each word's phones with typical durations, laid end to end over the voiced frames
    (silences longer than 0.25 s between them are skipped and stay pause) and scaled to fill them."""
    runs = [r for r in _runs(active)]
    if not runs:
        raise _MethodFailed("no voice activity")
    merged = [list(runs[0])]
    for a, b in runs[1:]:
        if (a - merged[-1][1]) * hop < 0.25:
            merged[-1][1] = b
        else:
            merged.append([a, b])
    spans = np.array(merged, float) * hop  # (k, 2) seconds
    lengths = spans[:, 1] - spans[:, 0]
    cum = np.concatenate([[0.0], np.cumsum(lengths)])
    sequence = [(w, p) for w in words for p in prons[w]]
    durations = np.array([typical_duration(p) for _, p in sequence])
    bounds = np.concatenate([[0.0], np.cumsum(durations)]) * cum[-1] / durations.sum()

    def real(t: float, left: bool) -> float:
        """Voiced time -> real time; a boundary on a span's edge belongs to the span on its ``left``."""
        k = int(np.searchsorted(cum, t, side="left" if left else "right")) - 1
        k = min(max(k, 0), len(lengths) - 1)
        return float(spans[k, 0] + (t - cum[k]))

    phones, word_segs = [], []
    i = 0
    for w in words:
        first = i
        for _ in prons[w]:
            phones.append(Segment(real(bounds[i], False), real(bounds[i + 1], True), sequence[i][1]))
            i += 1
        word_segs.append(Segment(phones[first].start, phones[i - 1].end, w))
    return phones, word_segs


def tile(segments: list[Segment], duration: float) -> list[Segment]:
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


