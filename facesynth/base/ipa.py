"""Phones by their articulation: IPA symbols, their articulatory features, the visemes the features
imply, and the nearest English (Festival) phone of any phone.

A motion database captured in English holds Festival phones (:mod:`facesynth.base.phonemes`); a
line in another language arrives as IPA phones (:mod:`facesynth.domain.speech.languages`). Each
IPA phone is described by its features (:class:`Features`: place, manner, voicing, vowel height,
backness, rounding, nasality, length), and every phone resolves to the English phone nearest in
those features (:func:`nearest_festival`), the distance weighted by what the face shows
(:data:`WEIGHTS`: lip closure, lower lip to teeth, rounding and jaw height most). English phones are
their own nearest phone, so an English line is unchanged. A diphthong is described by its start
and its end; a monophthong's end is its start.

The features imply the visemes of docs/methods.md ("Phones by their articulation"):
:func:`visemes`.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass, replace
from functools import lru_cache

#: Place of articulation, front of the mouth (0, the lips) to the back (1, the glottis): the
#: scale the distance measures the tongue's (or lips') constriction on.
PLACES: dict[str, float] = {
    "bilabial": 0.0, "labiodental": 0.1, "dental": 0.25, "alveolar": 0.35, "postalveolar": 0.45,
    "retroflex": 0.5, "alveolopalatal": 0.55, "palatal": 0.65, "velar": 0.8, "uvular": 0.9,
    "pharyngeal": 0.95, "glottal": 1.0,
}
MANNERS = ("stop", "nasal", "fricative", "affricate", "approximant", "lateral", "trill", "tap", "vowel")


@dataclass(frozen=True)
class Features:
    """One phone's articulation. Consonants: ``place`` (a :data:`PLACES` name), ``manner`` (one
    of :data:`MANNERS` but ``vowel``), ``voiced``, ``rounded`` (lip rounding, /w/), ``rhotic``.
    Vowels (``manner`` ``vowel``): ``height`` (0 close .. 1 open: the jaw), ``backness`` (0
    front .. 1 back), ``rounded``, ``rhotic`` (r-coloured), and for a diphthong its end
    (``end_height``, ``end_backness``, ``end_rounded``; a monophthong's end is its start).
    Both: ``nasal`` (a nasal vowel; a nasal stop has ``manner`` nasal), ``long``."""

    manner: str
    place: str = "palatal"
    voiced: bool = True
    height: float = 0.0
    backness: float = 0.0
    rounded: bool = False
    nasal: bool = False
    long: bool = False
    rhotic: bool = False
    end_height: float | None = None
    end_backness: float | None = None
    end_rounded: bool | None = None

    @property
    def vowel(self) -> bool:
        return self.manner == "vowel"

    def end(self) -> Features:
        """The features at the phone's end (a diphthong's second part; else the phone itself)."""
        if self.end_height is None:
            return self
        return replace(self, height=self.end_height, backness=self.end_backness or 0.0,
                       rounded=bool(self.end_rounded), end_height=None, end_backness=None, end_rounded=None)


def _c(place: str, manner: str, voiced: bool = False, **kw) -> Features:
    return Features(manner, place, voiced, **kw)


def _v(height: float, backness: float, rounded: bool = False, **kw) -> Features:
    return Features("vowel", "palatal", True, height, backness, rounded, **kw)


def _d(a: Features, b: Features) -> Features:
    return replace(a, end_height=b.height, end_backness=b.backness, end_rounded=b.rounded)


#: The IPA phones the table describes: the consonants and vowels that the G2P backends emit for
#: the languages facesynth reads (gruut's, and the Mandarin table), and English's.
IPA: dict[str, Features] = {
    # stops
    "p": _c("bilabial", "stop"), "b": _c("bilabial", "stop", True),
    "t": _c("alveolar", "stop"), "d": _c("alveolar", "stop", True),
    "ʈ": _c("retroflex", "stop"), "ɖ": _c("retroflex", "stop", True),
    "c": _c("palatal", "stop"), "ɟ": _c("palatal", "stop", True),
    "k": _c("velar", "stop"), "g": _c("velar", "stop", True), "ɡ": _c("velar", "stop", True),
    "q": _c("uvular", "stop"), "ʔ": _c("glottal", "stop"),
    # nasals
    "m": _c("bilabial", "nasal", True), "ɱ": _c("labiodental", "nasal", True),
    "n": _c("alveolar", "nasal", True), "ɳ": _c("retroflex", "nasal", True),
    "ɲ": _c("palatal", "nasal", True), "ŋ": _c("velar", "nasal", True), "ɴ": _c("uvular", "nasal", True),
    # fricatives
    "ɸ": _c("bilabial", "fricative"), "β": _c("bilabial", "fricative", True),
    "f": _c("labiodental", "fricative"), "v": _c("labiodental", "fricative", True),
    "θ": _c("dental", "fricative"), "ð": _c("dental", "fricative", True),
    "s": _c("alveolar", "fricative"), "z": _c("alveolar", "fricative", True),
    "ʃ": _c("postalveolar", "fricative"), "ʒ": _c("postalveolar", "fricative", True),
    "ʂ": _c("retroflex", "fricative"), "ʐ": _c("retroflex", "fricative", True),
    "ɕ": _c("alveolopalatal", "fricative"), "ʑ": _c("alveolopalatal", "fricative", True),
    "ç": _c("palatal", "fricative"), "ʝ": _c("palatal", "fricative", True),
    "x": _c("velar", "fricative"), "ɣ": _c("velar", "fricative", True),
    "χ": _c("uvular", "fricative"), "ʁ": _c("uvular", "fricative", True, rhotic=True),
    "ħ": _c("pharyngeal", "fricative"), "ʕ": _c("pharyngeal", "fricative", True),
    "h": _c("glottal", "fricative"), "ɦ": _c("glottal", "fricative", True),
    # affricates
    "ts": _c("alveolar", "affricate"), "dz": _c("alveolar", "affricate", True),
    "tʃ": _c("postalveolar", "affricate"), "dʒ": _c("postalveolar", "affricate", True),
    "ʈʂ": _c("retroflex", "affricate"), "ɖʐ": _c("retroflex", "affricate", True),
    "tɕ": _c("alveolopalatal", "affricate"), "dʑ": _c("alveolopalatal", "affricate", True),
    "pf": _c("labiodental", "affricate"),
    # approximants, laterals, rhotics
    "ʋ": _c("labiodental", "approximant", True), "ɹ": _c("alveolar", "approximant", True, rhotic=True),
    "ɻ": _c("retroflex", "approximant", True, rhotic=True), "j": _c("palatal", "approximant", True),
    "ɥ": _c("palatal", "approximant", True, rounded=True), "w": _c("velar", "approximant", True, rounded=True),
    "ʍ": _c("velar", "approximant", rounded=True), "ɰ": _c("velar", "approximant", True),
    "l": _c("alveolar", "lateral", True), "ɫ": _c("alveolar", "lateral", True), "ɭ": _c("retroflex", "lateral", True),
    "ʎ": _c("palatal", "lateral", True), "ʟ": _c("velar", "lateral", True),
    "r": _c("alveolar", "trill", True, rhotic=True), "ɾ": _c("alveolar", "tap", True, rhotic=True),
    "ʀ": _c("uvular", "trill", True, rhotic=True),
    # vowels: height 0 close .. 1 open, backness 0 front .. 1 back
    "i": _v(0.0, 0.0), "y": _v(0.0, 0.0, True), "ɨ": _v(0.0, 0.5), "ʉ": _v(0.0, 0.5, True),
    "ɯ": _v(0.0, 1.0), "u": _v(0.0, 1.0, True),
    "ɪ": _v(0.15, 0.1), "ʏ": _v(0.15, 0.1, True), "ʊ": _v(0.15, 0.9, True),
    "e": _v(0.3, 0.0), "ø": _v(0.3, 0.0, True), "ɘ": _v(0.3, 0.5), "ɵ": _v(0.3, 0.5, True),
    "ɤ": _v(0.3, 1.0), "o": _v(0.3, 1.0, True),
    "ə": _v(0.5, 0.5), "ɚ": _v(0.5, 0.5, rhotic=True), "ɝ": _v(0.55, 0.5, rhotic=True),
    "ɛ": _v(0.6, 0.0), "œ": _v(0.6, 0.0, True), "ɜ": _v(0.6, 0.5), "ɞ": _v(0.6, 0.5, True),
    "ʌ": _v(0.6, 0.7), "ɔ": _v(0.6, 1.0, True),
    "æ": _v(0.8, 0.0), "ɐ": _v(0.8, 0.5),
    "a": _v(1.0, 0.2), "ɶ": _v(1.0, 0.0, True), "ä": _v(1.0, 0.5), "ɑ": _v(1.0, 1.0), "ɒ": _v(1.0, 1.0, True),
}
# English's diphthongs (and those the backends write as one symbol)
for _name, (_a, _b) in {"aɪ": ("a", "ɪ"), "aʊ": ("a", "ʊ"), "ɔɪ": ("ɔ", "ɪ"), "eɪ": ("e", "ɪ"),
                        "oʊ": ("o", "ʊ"), "əʊ": ("ə", "ʊ"), "ɑʊ": ("ɑ", "ʊ"), "ɔʏ": ("ɔ", "ʏ"),
                        "aɛ": ("a", "ɛ"), "aɔ": ("a", "ɔ"), "ɛɪ": ("ɛ", "ɪ"), "œy": ("œ", "y")}.items():
    IPA[_name] = _d(IPA[_a], IPA[_b])

#: Festival (English) phones as IPA (General American), each described by :data:`IPA`.
FESTIVAL_IPA: dict[str, str] = {
    "aa": "ɑ", "ae": "æ", "ah": "ʌ", "ao": "ɔ", "aw": "aʊ", "ax": "ə", "axr": "ɚ", "ay": "aɪ",
    "b": "b", "ch": "tʃ", "d": "d", "dh": "ð", "eh": "ɛ", "el": "l", "em": "m", "en": "n", "er": "ɝ",
    "ey": "eɪ", "f": "f", "g": "ɡ", "hh": "h", "ih": "ɪ", "iy": "i", "jh": "dʒ", "k": "k", "l": "l",
    "m": "m", "n": "n", "ng": "ŋ", "nx": "ɾ", "ow": "oʊ", "oy": "ɔɪ", "p": "p", "r": "ɹ", "s": "s",
    "sh": "ʃ", "t": "t", "th": "θ", "uh": "ʊ", "uw": "u", "v": "v", "w": "w", "y": "j", "z": "z",
    "zh": "ʒ",
}

#: The English phones a foreign phone may resolve to: the 39 phones of the CMU dictionary (and so
#: of the recogniser's acoustic model), the schwa ``ax`` being CMU's unstressed ``AH0``.
TARGETS: tuple[str, ...] = (
    "aa", "ae", "ah", "ao", "aw", "ax", "ay", "b", "ch", "d", "dh", "eh", "er", "ey", "f", "g", "hh",
    "ih", "iy", "jh", "k", "l", "m", "n", "ng", "ow", "oy", "p", "r", "s", "sh", "t", "th", "uh",
    "uw", "v", "w", "y", "z", "zh",
)

#: The weights of the feature distance (:func:`distance`): what the face shows matters most. Lip
#: closure (a bilabial stop, nasal or fricative) and the lower lip to the teeth (labiodental) 4 each;
#: rounding 3 (at the start and at the end of a vowel); a vowel against a consonant 3; the jaw
#: (vowel height) 2; the tongue's place 1.5 (on the front-to-back scale of :data:`PLACES`); the
#: manner (stop, nasal, fricative, affricate, approximant, lateral, rhotic) 1 each, 0.5 between
#: obstruents (stop, fricative, affricate) and between glides (approximant, tap, trill); backness 1;
#: nasality and voicing 0.5 (barely visible); length 0.25.
WEIGHTS: dict[str, float] = {
    "closure": 4.0, "labiodental": 4.0, "rounded": 3.0, "vowel": 3.0, "height": 2.0, "place": 1.5,
    "manner": 1.0, "rhotic": 1.0, "backness": 1.0, "nasal": 0.5, "voiced": 0.5, "long": 0.25,
}

_LENGTH = "ːˑ"
_NASAL = "\u0303"  # combining tilde
#: Marks that do not change the articulation the face shows: stress, syllabic, aspiration,
#: tie bars, non-syllabic, dental/apical, release, tones and breaks.
_IGNORED = set("ˈˌ\u0329\u030d\u032f\u0361\u035c\u032a\u033a\u033b\u031a\u0325\u030a\u0324\u0330ʰʲʷˠˀ̚.‿|‖-") | set(
    "˥˦˧˨˩0123456789")


def closure(f: Features) -> bool:
    """The lips close, or nearly (bilabial stops, nasals and fricatives: Spanish /β/ between vowels)."""
    return not f.vowel and f.place == "bilabial" and f.manner in ("stop", "nasal", "fricative")


def labiodental(f: Features) -> bool:
    """The lower lip touches the upper teeth."""
    return not f.vowel and f.place == "labiodental"


def distance(a: Features, b: Features) -> float:
    """The weighted feature distance of two phones (:data:`WEIGHTS`); 0 for equal features. Vowels
    are compared at their start and their end (a diphthong against a monophthong differs at one)."""
    w = WEIGHTS
    d = w["vowel"] * (a.vowel != b.vowel)
    d += w["nasal"] * (a.nasal != b.nasal) + w["long"] * (a.long != b.long) + w["rhotic"] * (a.rhotic != b.rhotic)
    if a.vowel and b.vowel:
        for x, y in ((a, b), (a.end(), b.end())):
            d += 0.5 * (w["height"] * abs(x.height - y.height) + w["backness"] * abs(x.backness - y.backness)
                        + w["rounded"] * (x.rounded != y.rounded))
        return d
    d += w["closure"] * (closure(a) != closure(b)) + w["labiodental"] * (labiodental(a) != labiodental(b))
    d += w["rounded"] * (a.rounded != b.rounded) + w["voiced"] * (a.voiced != b.voiced)
    if not a.vowel and not b.vowel:
        d += w["place"] * abs(PLACES[a.place] - PLACES[b.place]) + w["manner"] * _manner_distance(a, b)
    return d


def _manner_distance(a: Features, b: Features) -> float:
    if a.manner == b.manner:
        return 0.0
    pair = {a.manner, b.manner}
    # an affricate is a stop and a fricative, and stops and fricatives of one place are each
    # other's allophones (Spanish b/β, g/ɣ); trills, taps and approximants are all sonorant glides
    if pair <= {"stop", "fricative", "affricate"}:
        return 0.5
    if pair <= {"trill", "tap", "approximant"}:
        return 0.5
    return 1.0


def features(phone: str) -> Features:
    """The features of an IPA phone (length and nasality marks and the marks of ``_IGNORED``
    read, so an affricate's tie bar too; a sequence of vowel symbols not in :data:`IPA` read as a
    diphthong of its first and last). Raises KeyError for a symbol the table lacks (:func:`split`
    reads a sequence of phones)."""
    return _features(unicodedata.normalize("NFD", phone))


@lru_cache(maxsize=4096)
def _features(phone: str) -> Features:
    if phone in IPA:
        return IPA[phone]
    nasal = _NASAL in phone
    long = any(c in phone for c in _LENGTH)
    core = "".join(c for c in phone if c not in _IGNORED and c not in _LENGTH and c != _NASAL)
    core = unicodedata.normalize("NFC", core)
    if core in IPA:
        base = IPA[core]
    elif core and all(ch in IPA and IPA[ch].vowel for ch in core):
        base = _d(IPA[core[0]], IPA[core[-1]]) if len(core) > 1 else IPA[core]
    else:
        raise KeyError(phone)
    return replace(base, nasal=base.nasal or nasal, long=base.long or long)


def split(phone: str) -> tuple[str, ...]:
    """``phone`` as phones :func:`features` describes: itself when it does, else its symbols
    split into the longest described pieces, each with the marks that follow it (gruut writes
    Spanish /we/ as one ``we``); KeyError when no split describes every piece."""
    if known(phone):
        return (phone,)
    text = unicodedata.normalize("NFD", phone)
    pieces: list[str] = []
    i = 0
    while i < len(text):
        for j in range(len(text), i, -1):
            end = j
            while end < len(text) and (unicodedata.combining(text[end]) or text[end] in _IGNORED or text[end] in _LENGTH):
                end += 1
            piece = unicodedata.normalize("NFC", text[i:end])
            if known(piece) and (j - i > 1 or text[i] not in _IGNORED):
                pieces.append(piece)
                i = end
                break
        else:
            raise KeyError(phone)
    return tuple(pieces)


def known(phone: str) -> bool:
    """Whether :func:`features` describes ``phone``."""
    try:
        features(phone)
    except KeyError:
        return False
    return True


@lru_cache(maxsize=4096)
def nearest_festival(phone: str) -> str:
    """The English (Festival) phone nearest ``phone`` (IPA) in features: one of :data:`TARGETS`
    (ties go to the first in that order). An English phone's IPA gives that phone back."""
    f = features(phone)
    for name in TARGETS:
        if FESTIVAL_IPA[name] == phone:
            return name
    return min(TARGETS, key=lambda name: distance(f, features(FESTIVAL_IPA[name])))


#: The viseme columns of :func:`visemes`, in order.
VISEME_COLUMNS = ("lips closed", "lower lip to teeth", "rounded", "spread", "jaw")


def visemes(phone: str) -> dict[str, object]:
    """What the face shows for ``phone`` (IPA), derived from its features: lips closed (bilabial
    stop, nasal or fricative), lower lip to the teeth (labiodental), rounded (rounding), spread (an
    unrounded front vowel or palatal glide), and the jaw's opening: ``closed``, ``close``,
    ``mid`` or ``open`` (a vowel's height; a consonant's jaw is close, a closure's closed)."""
    f = features(phone)
    closed = closure(f)
    spread = (not f.rounded) and ((f.vowel and f.backness <= 0.2 and f.height < 0.7) or (f.manner == "approximant"
                                                                                          and f.place == "palatal"))
    if closed:
        jaw = "closed"
    elif not f.vowel or f.height < 0.25:
        jaw = "close"
    elif f.height < 0.7:
        jaw = "mid"
    else:
        jaw = "open"
    return {"lips closed": closed, "lower lip to teeth": labiodental(f), "rounded": f.rounded, "spread": spread,
            "jaw": jaw}


def describe(phone: str) -> str:
    """``phone``'s features in words: "voiceless palatal fricative", "close front rounded vowel"."""
    f = features(phone)
    if not f.vowel:
        words = ["voiced" if f.voiced else "voiceless", f.place, f.manner]
        if f.rounded:
            words.insert(1, "rounded")
        return " ".join(words)

    def quality(g: Features) -> str:
        height = ("close" if g.height < 0.1 else "near-close" if g.height < 0.25 else "close-mid" if g.height < 0.45
                  else "mid" if g.height < 0.55 else "open-mid" if g.height < 0.7 else "near-open" if g.height < 0.9
                  else "open")
        back = "front" if g.backness < 0.25 else "central" if g.backness < 0.75 else "back"
        return f"{height} {back} {'rounded' if g.rounded else 'unrounded'}"

    words = [quality(f)]
    if f.end_height is not None:
        words = [f"{quality(f)} to {quality(f.end())}"]
    words += ["nasal"] * f.nasal + ["long"] * f.long + ["r-coloured"] * f.rhotic
    return " ".join(words) + (" diphthong" if f.end_height is not None else " vowel")


#: The phones of docs/methods.md's table besides English's: those of the languages the G2P
#: backends read that English lacks.
FOREIGN_EXAMPLES = tuple("y ø œ ʏ ɤ ɨ a e o ɛ̃ ɔ̃ ɑ̃ ɸ β ç ʝ x ɣ χ ʁ ʂ ʐ ʈʂ ɕ tɕ ts pf ɲ ʎ ɾ r ɥ ɻ̩".split())


def viseme_table() -> str:
    """The Markdown table of docs/methods.md: each English phone and each of
    :data:`FOREIGN_EXAMPLES`, its features in words, its nearest English phone and its visemes."""
    head = ("IPA", "features", "English phone") + VISEME_COLUMNS
    rows = [f"| {' | '.join(head)} |", "|" + "---|" * len(head)]
    for phone in [FESTIVAL_IPA[t] for t in TARGETS] + list(FOREIGN_EXAMPLES):
        v = visemes(phone)
        cells = [phone, describe(phone), f"`{nearest_festival(phone)}`"]
        cells += ["yes" if v[c] is True else "" if v[c] is False else str(v[c]) for c in VISEME_COLUMNS]
        rows.append(f"| {' | '.join(cells)} |")
    return "\n".join(rows)


@lru_cache(maxsize=65536)
def phone_distance(a: str, b: str) -> float:
    """:func:`distance` of two IPA phones (their :func:`features`); 0 for phones of equal features."""
    return distance(features(a), features(b))


def festival_phone_ipa(phone: str) -> str:
    """The IPA of a Festival phone (:data:`FESTIVAL_IPA`); KeyError for another name."""
    return FESTIVAL_IPA[phone]


def match_level(d: float, same_viseme: float, scale: float) -> float:
    """The phone-matching cost (paper Table II) of a phone ``d`` further in features
    (:func:`distance`) than the nearest (or the same) phone, as a fraction of Table II's cost of
    another viseme: 0 at ``d`` 0, else ``same_viseme + (1 - same_viseme) * d / scale``, at most 1. ``same_viseme`` is Table II's
    discount for a node of the same viseme (``synthesize.alpha4``), so any other phone costs at
    least what Table II's rule 2 charges, and a phone ``scale`` or more further (one visible
    contrast: rounding, or a vowel against a consonant, weighs 3, :data:`WEIGHTS`) costs what rule 3
    charges.
    Table II is the case of a distance that is 0 for the same phone, near 0 within a viseme and at
    least ``scale`` between visemes."""
    if d <= 0.0:
        return 0.0
    return min(1.0, same_viseme + (1.0 - same_viseme) * d / scale)


def nearest_phone(phone: str, candidates, ipa_of=festival_phone_ipa) -> str:
    """The one of ``candidates`` (names; ``ipa_of`` gives each one's IPA, Festival names by
    default) nearest the IPA phone ``phone`` in features (:func:`distance`); ties go to the first
    in the order given. ValueError when there is no candidate."""
    names = list(candidates)
    if not names:
        raise ValueError("nearest_phone: no candidate phones")
    return min(names, key=lambda name: phone_distance(phone, ipa_of(name)))
