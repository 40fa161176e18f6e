"""The new utterance a synthesis request speaks: its phones with their times and an emotion per
phone, read from a phones file or given, with its emotion spans (formats in ``docs/inputs.md``)."""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.base.ipa import festival_phone_ipa, nearest_phone
from facesynth.base.phonemes import PAU, map_phones
from facesynth.formats.labels import Segment, check_segments, read_phone_segments, read_text, read_textgrid

log = logging.getLogger(__name__)


@dataclass
class Utterance:
    """The input phone sequence: Festival phones with times (s) and an emotion per phone.

    ``ipa``: for a line in another language than English, the phone each step pronounces (IPA,
    :mod:`facesynth.base.ipa`; ``""`` at pauses), of which ``phones`` holds the nearest English
    phone; None for English (each step is its Festival phone). The search matches these phones
    by their features (``synthesize.phone_match``)."""

    phones: list[str]
    starts: np.ndarray
    ends: np.ndarray
    emotions: list[str]
    ipa: list[str] | None = None

    def __len__(self) -> int:
        return len(self.phones)

    def index_at(self, time_s: float) -> int | None:
        """The step whose phone spans ``time_s`` (seconds), or None."""
        hits = np.nonzero((self.starts <= time_s) & (time_s < self.ends))[0]
        return int(hits[0]) if len(hits) else None


def utterance(phones, starts, ends, emotions=None, ipa=None) -> Utterance:
    """An Utterance with adjacent pauses merged: one silence is one step of the search. ``ipa``:
    each phone's IPA (:attr:`Utterance.ipa`, same length as ``phones``) or None."""
    emotions = list(emotions) if emotions is not None else ["neutral"] * len(phones)
    given = list(ipa) if ipa is not None else [""] * len(phones)
    out_p, out_s, out_e, out_m, out_i = [], [], [], [], []
    for p, a, b, m, q in zip(phones, starts, ends, emotions, given):
        if out_p and p == PAU and out_p[-1] == PAU:
            out_e[-1] = b
            continue
        out_p.append(p)
        out_s.append(a)
        out_e.append(b)
        out_m.append(m)
        out_i.append("" if p == PAU else q)
    return Utterance(out_p, np.array(out_s, float), np.array(out_e, float), out_m, out_i if ipa is not None else None)


def read_utterance(phones_path: Path, tier_names=("phones",)) -> Utterance:
    """The utterance of a TextGrid (first tier of ``tier_names``) or ``.lab`` file, in the Festival set."""
    return _of_segments(read_phone_segments(phones_path, tier_names), str(phones_path))


def phones_utterance(phones, where: str = "the phones given") -> Utterance:
    """The utterance of ``phones``, (phone, start_s, end_s) triples in time order (Festival or
    CMU/ARPAbet names, seconds), checked as a phone file is (sorted, no overlap, within the
    limits) and mapped to the Festival set; messages name ``where``."""
    segs = []
    for i, item in enumerate(phones):
        try:
            label, start, end = item
            segs.append(Segment(float(start), float(end), str(label)))
        except (TypeError, ValueError):
            raise InputError(f"{where}, item {i}: expected (phone, start_s, end_s), got {item!r}.") from None
    check_segments(segs, where)
    return _of_segments(segs, where)


def _of_segments(segs, where: str) -> Utterance:
    labels = map_phones([s.label for s in segs], where, [s.start for s in segs])
    return utterance(labels, [s.start for s in segs], [s.end for s in segs])


def emotion_name(raw: str, emotions, aliases, where: str) -> str:
    """The emotion called ``raw`` (case-insensitive, aliases too: ``ingest.emotion_aliases``); an
    InputError naming ``where`` and the known emotions otherwise."""
    name = raw.strip().lower()
    name = {k.lower(): v for k, v in aliases.items()}.get(name, name)
    if name not in emotions:
        raise InputError(f"{where}: unknown emotion {raw!r}; use one of {', '.join(emotions)}.")
    return name


def apply_emotions(utt: Utterance, path: Path, emotions, aliases) -> None:
    """Set each phone's emotion from a span file (``start_s end_s emotion`` per line) or a
    TextGrid tier named ``emotions``. A phone takes the span holding its midpoint; spans
    may not overlap; phones outside every span stay neutral. A span entirely outside the
    utterance is an InputError (times are seconds); one that holds no phone's midpoint is
    warned about, since it changes nothing."""
    path = Path(path)
    spans: list[tuple[float, float, str, str]] = []
    if path.suffix.lower() == ".textgrid":
        tiers = read_textgrid(path)
        tier = next((tiers[k] for k in tiers if k.lower() in ("emotions", "emotion")), None)
        if tier is None:
            raise InputError(f"{path}: no tier named 'emotions'; add one with intervals labelled by emotion.")
        for s in tier:
            if s.label.strip():
                spans.append((s.start, s.end, s.label, f"{path}, tier 'emotions', {s.start:.3f} s"))
    else:
        if not path.exists():
            raise InputError(f"{path}: emotion file not found; check the --emotions path.")
        for n, line in enumerate(read_text(path, "emotion file").splitlines(), 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = line.split()
            try:
                start, end, label = float(parts[0]), float(parts[1]), parts[2]
            except (ValueError, IndexError):
                raise InputError(f"{path}, line {n}: expected 'start_s end_s emotion', got {line!r}.") from None
            spans.append(_span(start, end, label, f"{path}, line {n}"))
    set_emotions(utt, spans, emotions, aliases)


def given_spans(spans, where: str = "the emotion spans given") -> list[tuple[float, float, str, str]]:
    """Emotion spans given as (start_s, end_s, emotion) triples, checked as a span file's lines
    are, each with the place messages name (``where``, item i)."""
    out = []
    for i, item in enumerate(spans):
        try:
            start, end, label = item
            out.append(_span(float(start), float(end), str(label), f"{where}, item {i}"))
        except (TypeError, ValueError):
            raise InputError(f"{where}, item {i}: expected (start_s, end_s, emotion), got {item!r}.") from None
    return out


def _span(start: float, end: float, label: str, where: str) -> tuple[float, float, str, str]:
    if not (math.isfinite(start) and math.isfinite(end)):
        raise InputError(f"{where}: the span {start:g} to {end:g} s must be finite seconds.")
    if end <= start:
        raise InputError(f"{where}: the span ends at or before it starts.")
    return (start, end, label, where)


def set_emotions(utt: Utterance, spans: list[tuple[float, float, str, str]], emotions, aliases) -> None:
    """Set each phone's emotion from ``spans`` ((start_s, end_s, emotion, where) each) by the rules
    of :func:`apply_emotions`."""
    spans = sorted(spans)
    for (_, a1, _, wa), (b0, _, _, wb) in zip(spans, spans[1:]):
        if b0 < a1 - 1e-9:
            raise InputError(f"{wb}: emotion span overlaps the one at {wa.split(', ', 1)[1]}; make spans disjoint.")
    first, last = float(utt.starts[0]), float(utt.ends[-1])
    for s, e, _, where in spans:
        if e <= first or s >= last:
            raise InputError(f"{where}: the emotion span {s:g} to {e:g} s lies outside the utterance "
                             f"({first:.3f} to {last:.3f} s); give its start and end in seconds within it.")
    names = [(s, e, emotion_name(lab, emotions, aliases, where), where) for s, e, lab, where in spans]
    mids = 0.5 * (utt.starts + utt.ends)
    for s, e, name, where in names:
        held = (s <= mids) & (mids < e)
        if not held.any():
            log.warning(f"{where}: the emotion span {s:g} to {e:g} s holds no phone's midpoint, so it changes nothing; "
                        "widen it to cover the phones meant.")
        for k in np.nonzero(held)[0]:
            utt.emotions[k] = name


def stand_in_phones(utt: Utterance, have, phone_match: str = "unseen") -> list[str]:
    """The phone each step of ``utt`` is looked up by in a fitted model or database whose
    phones (Festival names) are ``have``: its own phone when ``have`` holds it; else, for a step
    pronounced in another language (:attr:`Utterance.ipa`), or for every step under
    ``phone_match`` ``features``, the phone of ``have`` nearest its IPA in articulatory features
    (:func:`facesynth.base.ipa.nearest_phone`; ``synthesize.phone_match`` ``viseme`` never);
    else its own phone (the model's own fallback, by viseme, covers it). Pauses stay ``pau``."""
    known = sorted(set(have) - {PAU})
    out = []
    for t, p in enumerate(utt.phones):
        q = utt.ipa[t] if utt.ipa is not None else ""
        if p == PAU or p in have or not known or phone_match == "viseme" or (not q and phone_match != "features"):
            out.append(p)
        else:
            out.append(nearest_phone(q or festival_phone_ipa(p), known))
    return out
