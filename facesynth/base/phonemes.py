"""The phone set: Festival's English phones, their visemes (paper Table VI) and aliases.

Phones are stored everywhere as Festival names (``aa``, ``ax``, ``pau``...). CMU/ARPAbet
labels (``AH0``, ``IY1``) and Sphinx labels (``SIL``, ``+NSN+``) are mapped on input.
"""

from __future__ import annotations

import gzip
import re
from functools import lru_cache
from importlib import resources

from .errors import InputError

PAU = "pau"

#: Paper Table VI: the 15 viseme categories. The table's "yl" is the glide /y/; Festival's
#: ``axr`` (r-coloured schwa) is not in the table and is grouped with ``er``; ``nx``
#: (flap) with the alveolars.
VISEME_GROUPS: tuple[tuple[str, ...], ...] = (
    ("pau",),
    ("r",),
    ("k", "g", "ng"),
    ("ae", "ax", "ah", "aa"),
    ("f", "v"),
    ("ch", "sh", "jh"),
    ("ao", "y", "iy", "ih", "ay", "aw"),
    ("ow", "oy"),
    ("n", "d", "t", "l", "nx"),
    ("ey", "eh", "el", "em", "en", "er", "axr"),
    ("th", "dh"),
    ("s", "z", "zh"),
    ("b", "p", "m"),
    ("hh",),
    ("w", "uw", "uh"),
)

#: Festival phone -> viseme index (0 is /pau/).
VISEME_OF: dict[str, int] = {p: i for i, group in enumerate(VISEME_GROUPS) for p in group}

#: Every phone facesynth accepts, in a fixed order (index = phone id in artifacts).
PHONES: tuple[str, ...] = tuple(sorted(VISEME_OF))
PHONE_ID: dict[str, int] = {p: i for i, p in enumerate(PHONES)}

VOWELS = frozenset("aa ae ah ao aw ax axr ay eh el em en er ey ih iy ow oy uh uw".split())

#: Typical duration (s) of a phone in read English speech: inherent durations after Klatt (1979),
#: rounded: diphthongs longest, schwa, approximants and /hh/ (aspiration, short in connected
#: speech) shortest. The one table of phone durations: the virtual actress's speech and the
#: alignment's duration model both read it (:func:`typical_duration`).
TYPICAL_DURATION_S: dict[str, float] = {
    **dict.fromkeys(("aw", "ay", "oy", "ey", "ow"), 0.150),
    **dict.fromkeys(VOWELS - {"aw", "ay", "oy", "ey", "ow", "ax"}, 0.105),
    "ax": 0.060,
    **dict.fromkeys(("p", "b", "t", "d", "k", "g"), 0.075),
    **dict.fromkeys(("s", "sh", "z", "zh", "ch", "jh"), 0.100),
    **dict.fromkeys(("f", "v", "th", "dh"), 0.085),
    **dict.fromkeys(("m", "n", "ng"), 0.065),
}
#: The duration of a phone the table does not list (approximants, /hh/, syllabic nasals).
OTHER_DURATION_S = 0.060


def typical_duration(phone: str) -> float:
    """Typical duration (s) of a Festival phone in read English speech (:data:`TYPICAL_DURATION_S`)."""
    return TYPICAL_DURATION_S.get(phone, OTHER_DURATION_S)


_ARPABET = {
    "AA": "aa", "AE": "ae", "AH": "ah", "AO": "ao", "AW": "aw", "AX": "ax", "AXR": "axr",
    "AY": "ay", "B": "b", "CH": "ch", "D": "d", "DH": "dh", "EH": "eh", "EL": "el",
    "EM": "em", "EN": "en", "ER": "er", "EY": "ey", "F": "f", "G": "g", "HH": "hh",
    "IH": "ih", "IY": "iy", "JH": "jh", "K": "k", "L": "l", "M": "m", "N": "n", "NG": "ng",
    "NX": "nx", "OW": "ow", "OY": "oy", "P": "p", "R": "r", "S": "s", "SH": "sh", "T": "t",
    "TH": "th", "UH": "uh", "UW": "uw", "V": "v", "W": "w", "Y": "y", "Z": "z", "ZH": "zh",
}
#: Labels that mean silence or non-speech: Sphinx, HTK, TIMIT and Praat conventions.
_SILENCES = {"sil", "sp", "pau", "h#", "<sil>", "", "spn", "nsn", "sil>", "<s>", "</s>", "#", "br", "ns"}


def to_festival(label: str) -> str | None:
    """Map one phone label to a Festival phone, or None if it is not a known phone.

    CMU stress digits are dropped, except that unstressed ``AH0`` becomes the schwa ``ax``;
    silence and noise labels (``SIL``, ``sp``, ``+NSN+``, ``[noise]``) become ``pau``.
    """
    raw = label.strip()
    low = raw.lower().strip("+[]")
    if low in _SILENCES or raw.startswith("+") or raw.startswith("["):
        return PAU
    if low in VISEME_OF:
        return low
    match = re.fullmatch(r"([A-Za-z]+)([012])?", raw)
    if not match:
        return None
    base, stress = match.group(1).upper(), match.group(2)
    if base == "AH" and stress == "0":
        return "ax"
    return _ARPABET.get(base)


def viseme(phone: str) -> int:
    """Viseme index (Table VI) of a Festival phone."""
    return VISEME_OF[phone]


def map_phones(labels, where: str, times=None) -> list[str]:
    """Map a sequence of labels to Festival phones; an unknown one is an error naming ``where``.

    ``times`` (seconds, same length) lets the message say when the phone occurs.
    """
    out = []
    for i, label in enumerate(labels):
        phone = to_festival(label)
        if phone is None:
            at = f", {times[i]:.3f} s" if times is not None else ""
            raise InputError(
                f"{where}{at}: unknown phone {label!r}; use Festival or CMU (ARPAbet) phone names."
            )
        out.append(phone)
    return out


@lru_cache(maxsize=1)
def _cmudict_lines() -> list[str]:
    data = resources.files("facesynth").joinpath("data/cmudict.dict.gz").read_bytes()
    return gzip.decompress(data).decode("utf-8").splitlines()


def _parse(lines, wanted: set[str] | None) -> dict[str, tuple[tuple[str, ...], ...]]:
    words: dict[str, list[tuple[str, ...]]] = {}
    for line in lines:
        head = line.split(" ", 1)[0]
        word = head.split("(", 1)[0] if head.endswith(")") else head
        if wanted is not None and word not in wanted:
            continue
        body = line.split("#", 1)[0].split()
        if len(body) > 1:
            words.setdefault(word, []).append(tuple(body[1:]))
    return {w: tuple(p) for w, p in words.items()}


@lru_cache(maxsize=1)
def cmudict() -> dict[str, tuple[tuple[str, ...], ...]]:
    """The CMU Pronouncing Dictionary (with stress digits): word -> pronunciations.

    Shipped with the package (BSD licence, ``facesynth/data/cmudict.LICENSE``).
    """
    return _parse(_cmudict_lines(), None)


def pronunciations(words) -> dict[str, tuple[tuple[str, ...], ...]]:
    """The CMU dictionary entries of just these words (much faster than the whole), in the
    dictionary's order."""
    return dict(_pronunciations_of(frozenset(words)))


@lru_cache(maxsize=16)
def _pronunciations_of(words: frozenset[str]) -> dict[str, tuple[tuple[str, ...], ...]]:
    """:func:`pronunciations`, kept for the last few sets of words (an alignment looks its words
    up more than once)."""
    return _parse(_cmudict_lines(), set(words))
