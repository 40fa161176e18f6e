"""Text in languages other than English: its words' phones, as IPA and as the nearest English phones.

English text keeps the CMU dictionary (:mod:`facesynth.domain.speech.alignment`). A line in
another language (``align.language``, a BCP-47 tag such as ``de``, ``fr-CA``, ``cmn``) is read
by the first grapheme-to-phoneme backend of :data:`~facesynth.base.registry.G2P_BACKENDS` that
covers the language and is installed:

- ``gruut``: the gruut phonemizer and its language packs (MIT; ``pip install
  'facesynth[languages]'`` installs German, French, Spanish, Italian, Dutch, Portuguese and
  Russian), its lexicons and guesser models shipped in the packs;
- ``pinyin``: Mandarin (``cmn``, ``zh``): each character's pinyin by ``pypinyin`` (MIT),
  turned into IPA by the table here (:data:`PINYIN_INITIALS`, :data:`PINYIN_FINALS`; tones are
  left out, the face does not show them).

The user's own pronunciations come first: ``align.dictionary``, a UTF-8 file of ``word  IPA
phones`` lines (the phones separated by spaces); a ``{language}`` in its path is replaced by the
language's primary subtag (``lexicon-{language}.txt``: one file per language).

Each IPA phone then resolves to the English phone nearest in articulatory features
(:func:`facesynth.base.ipa.nearest_festival`), which the English acoustic model and the motion
database know. The backends' libraries are imported only when such a line is read.
"""

from __future__ import annotations

import importlib.util
import re
import unicodedata
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.errors import InputError
from facesynth.base.ipa import features, nearest_festival, split
from facesynth.base.phonemes import PAU, to_festival
from facesynth.base.registry import G2P_BACKENDS

#: Non-speech in a transcript ([breath], <noise>, {cough}): not words (as in the English aligner).
_NON_SPEECH = re.compile(r"\[[^\]]*\]|<[^>]*>|\{[^}]*\}")
#: Language tags read as another's: the macrolanguage ``zh`` is read as Mandarin.
_ALIASES = {"zh": "cmn"}


def primary(language: str) -> str:
    """The primary subtag of a BCP-47 tag, lower case, aliases resolved (``zh-Hans`` -> ``cmn``)."""
    tag = language.strip().replace("_", "-").lower().split("-", 1)[0]
    return _ALIASES.get(tag, tag)


def is_english(language: str) -> bool:
    """Whether ``language`` (a BCP-47 tag; empty: English) is English, read by the CMU dictionary."""
    return primary(language) in ("", "en", "eng")


@dataclass(frozen=True)
class Word:
    """One word of a line: ``text`` as written, ``ipa`` its phones (IPA), ``phones`` the nearest
    English (Festival) phone of each."""

    text: str
    ipa: tuple[str, ...]
    phones: tuple[str, ...]


def backend_for(language: str) -> str:
    """The name of the first installed G2P backend covering ``language``; an
    :class:`~facesynth.base.errors.InputError` in one sentence when none does."""
    tag = primary(language)
    covering = [e for e in G2P_BACKENDS.entries() if tag in e.facts.get("languages", ())]
    for entry in covering:
        if entry.facts["installed"](tag):
            return entry.name
    if covering:
        raise InputError(f"language {language!r}: its G2P backend ({', '.join(e.name for e in covering)}) is not "
                         "installed; install it with pip install 'facesynth[languages]'.")
    known_tags = sorted({t for e in G2P_BACKENDS.entries() for t in e.facts.get("languages", ())} | {"en"})
    raise InputError(f"language {language!r}: no G2P backend reads it; use one of {', '.join(known_tags)} "
                     "(align.language), or give the phones with --phonemes.")


def words_of(text: str, language: str, dictionary: str = "", where: str = "the text") -> list[Word]:
    """The words of ``text`` in ``language`` with their phones: the user's ``dictionary`` (a path,
    ``{language}`` replaced; empty: none) first, else the language's backend. Punctuation and
    non-speech marks are not words. Errors (one sentence, naming ``where``): a language no
    installed backend reads, a word no source pronounces, an IPA phone with no known articulation."""
    tag = primary(language)
    own = read_dictionary(Path(dictionary.replace("{language}", tag))) if dictionary else {}
    backend = G2P_BACKENDS.get(backend_for(language))
    text = _NON_SPEECH.sub(" ", unicodedata.normalize("NFC", text))
    out = []
    for written, given in backend(text, tag):
        given = own.get(written.lower(), given)
        ipa: list[str] = []
        for phone in given:
            if phone in _PAUSES:  # a lexicon's silence inside a word
                continue
            try:
                ipa += split(phone)
            except KeyError:
                raise InputError(f"{where}: the phone {phone!r} of {written!r} has no known articulation; give the "
                                 "word's pronunciation in align.dictionary with the phones of facesynth.base.ipa.") from None
        if not ipa:
            raise InputError(f"{where}: no pronunciation for {written!r} in language {language!r}; give one in "
                             "align.dictionary (lines 'word  IPA phones').")
        out.append(Word(written, tuple(ipa), tuple(nearest_festival(p) for p in ipa)))
    return out


#: Labels of silence some lexicons write among a word's phones (gruut's French ``SIL``).
_PAUSES = frozenset({"SIL", "sil", "_", "|", "‖", "#"})


def read_dictionary(path: Path) -> dict[str, tuple[str, ...]]:
    """A user pronunciation file: ``word  IPA phones`` per line (phones separated by spaces, ``#``
    starts a comment), word -> phones; the word is matched case-insensitively."""
    try:
        lines = Path(path).read_text("utf-8").splitlines()
    except FileNotFoundError:
        raise InputError(f"{path}: pronunciation dictionary not found; check align.dictionary.") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save it as UTF-8.") from None
    out: dict[str, tuple[str, ...]] = {}
    for n, line in enumerate(lines, 1):
        line = unicodedata.normalize("NFC", line.split("#", 1)[0].strip())
        if not line:
            continue
        word, *phones = line.split()
        bad = [p for p in phones if not _splits(p)]
        if not phones or bad:
            what = f"unknown IPA phone {bad[0]!r}" if bad else "no phones"
            raise InputError(f"{path}, line {n}: {what}; write 'word  IPA phones' with the phones separated by spaces.")
        out.setdefault(word.lower(), tuple(phones))
    return out


def _splits(phone: str) -> bool:
    try:
        split(phone)
    except KeyError:
        return False
    return True


# --- gruut ---------------------------------------------------------------------------------------

#: The languages of gruut's packs (primary subtags).
GRUUT_LANGUAGES = ("ar", "ca", "cs", "de", "es", "fa", "fr", "it", "lb", "nl", "pt", "ru", "sv", "sw")


def gruut_installed(tag: str) -> bool:
    """Whether gruut and its pack for ``tag`` are installed (found, not imported)."""
    return importlib.util.find_spec("gruut") is not None and importlib.util.find_spec(f"gruut_lang_{tag}") is not None


def gruut_words(text: str, tag: str) -> list[tuple[str, tuple[str, ...]]]:
    """The words of ``text`` and their IPA phones by gruut (its lexicon, else its guesser; numbers
    and abbreviations spelled out as gruut reads them), punctuation left out."""
    from gruut import sentences

    out = []
    for sentence in sentences(text, lang=tag):
        for word in sentence:
            if word.is_break or not word.is_spoken:
                continue
            phones = tuple(p for p in (word.phonemes or ()) if p not in ("|", "‖"))
            if any(ch.isalnum() for ch in word.text):
                out.append((word.text, phones))
    return out


# --- Mandarin: pinyin -> IPA ---------------------------------------------------------------------

#: Pinyin initials as IPA (aspiration left out: the face does not show it).
PINYIN_INITIALS: dict[str, tuple[str, ...]] = {
    "b": ("p",), "p": ("p",), "m": ("m",), "f": ("f",), "d": ("t",), "t": ("t",), "n": ("n",), "l": ("l",),
    "g": ("k",), "k": ("k",), "h": ("x",), "j": ("tɕ",), "q": ("tɕ",), "x": ("ɕ",),
    "zh": ("ʈʂ",), "ch": ("ʈʂ",), "sh": ("ʂ",), "r": ("ʐ",), "z": ("ts",), "c": ("ts",), "s": ("s",),
    "": (),
}
#: Pinyin finals (pypinyin's strict spelling: ``v`` for ü, ``iou``, ``uei``, ``uen``) as IPA.
#: ``i`` after z c s is the apical vowel (written ɨ here), after zh ch sh r the retroflex ɻ̩ (:func:`pinyin_ipa`).
PINYIN_FINALS: dict[str, tuple[str, ...]] = {
    "a": ("a",), "o": ("o",), "e": ("ɤ",), "i": ("i",), "u": ("u",), "v": ("y",), "ê": ("ɛ",),
    "ai": ("aɪ",), "ei": ("eɪ",), "ao": ("ɑʊ",), "ou": ("oʊ",),
    "an": ("a", "n"), "en": ("ə", "n"), "ang": ("ɑ", "ŋ"), "eng": ("ə", "ŋ"), "ong": ("ʊ", "ŋ"), "er": ("ɚ",),
    "ia": ("j", "a"), "ie": ("j", "ɛ"), "iao": ("j", "ɑʊ"), "iou": ("j", "oʊ"), "iu": ("j", "oʊ"),
    "ian": ("j", "ɛ", "n"), "in": ("i", "n"), "iang": ("j", "ɑ", "ŋ"), "ing": ("i", "ŋ"), "iong": ("j", "ʊ", "ŋ"),
    "ua": ("w", "a"), "uo": ("w", "o"), "uai": ("w", "aɪ"), "uei": ("w", "eɪ"), "ui": ("w", "eɪ"),
    "uan": ("w", "a", "n"), "uen": ("w", "ə", "n"), "un": ("w", "ə", "n"), "uang": ("w", "ɑ", "ŋ"),
    "ueng": ("w", "ə", "ŋ"),
    "ve": ("ɥ", "ɛ"), "van": ("ɥ", "ɛ", "n"), "vn": ("y", "n"),
    "n": ("n",), "ng": ("ŋ",), "m": ("m",),  # interjections (嗯, 呣)
}


def pinyin_ipa(initial: str, final: str) -> tuple[str, ...]:
    """The IPA phones of one pinyin syllable (initial and final in pypinyin's strict spelling,
    tone digits dropped); KeyError for a spelling the tables lack."""
    final = final.rstrip("012345")
    if final == "i" and initial in ("z", "c", "s"):
        rest: tuple[str, ...] = ("ɨ",)
    elif final == "i" and initial in ("zh", "ch", "sh", "r"):
        rest = ("ɻ̩",)
    else:
        rest = PINYIN_FINALS[final]
    return PINYIN_INITIALS[initial] + rest


def pinyin_installed(tag: str) -> bool:
    """Whether pypinyin is installed (found, not imported)."""
    return importlib.util.find_spec("pypinyin") is not None


_HAN = re.compile(r"[\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff]")


def pinyin_words(text: str, tag: str) -> list[tuple[str, tuple[str, ...]]]:
    """Each Chinese character of ``text`` as a word with its syllable's IPA phones (pypinyin reads
    each character in its phrase's context: 行 as xing or hang); a run of other letters is a word
    with no pronunciation (it needs the user's dictionary), punctuation is left out."""
    from pypinyin import Style, lazy_pinyin

    out: list[tuple[str, tuple[str, ...]]] = []
    for run in re.findall(r"[\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff]+|\w+", text):
        if not _HAN.match(run):
            out.append((run, ()))
            continue
        initials = lazy_pinyin(run, style=Style.INITIALS, strict=True)
        finals = lazy_pinyin(run, style=Style.FINALS_TONE3, strict=True, neutral_tone_with_five=True)
        for char, initial, final in zip(run, initials, finals):
            try:
                out.append((char, pinyin_ipa(initial, final)))
            except KeyError:
                out.append((char, ()))
    return out


def _check_tables() -> None:
    """Every IPA phone of the pinyin tables has its features (a programming error otherwise)."""
    for table in (PINYIN_INITIALS, PINYIN_FINALS):
        for phones in table.values():
            for p in phones:
                features(p)


_check_tables()

G2P_BACKENDS.register("gruut", "facesynth.domain.speech.languages:gruut_words",
                      "gruut's lexicons and guessers (MIT), one pack a language", languages=GRUUT_LANGUAGES,
                      installed=gruut_installed, needs="languages")
G2P_BACKENDS.register("pinyin", "facesynth.domain.speech.languages:pinyin_words",
                      "Mandarin: pypinyin (MIT) and facesynth's pinyin-to-IPA table", languages=("cmn",),
                      installed=pinyin_installed, needs="languages")


def ipa_phones(labels, where: str, times, language: str) -> tuple[list[str], list[str]]:
    """Phone labels written in IPA (a take's alignment in ``language``, not English, as the Montreal
    Forced Aligner's models of other languages write them), one phone per label: each label's
    nearest English (Festival) phone and its IPA, ``pau`` and ``""`` for a silence or noise label
    (``sil``, ``sp``, ``spn``, empty). ``times``: each label's start (s), named with ``where`` in
    the error for a label :mod:`facesynth.base.ipa` does not describe."""
    festival, ipa = [], []
    for label, start in zip(labels, times):
        text = unicodedata.normalize("NFC", label.strip())
        if to_festival(text) == PAU:
            festival.append(PAU)
            ipa.append("")
            continue
        try:
            features(text)
        except KeyError:
            raise InputError(f"{where}, {start:.3f} s: unknown IPA phone {label!r}; a take in language {language!r} "
                             "labels its phones in IPA (one phone per interval, as facesynth.base.ipa describes them), "
                             "or leave its alignment empty to align its transcript.") from None
        festival.append(nearest_festival(text))
        ipa.append(text)
    return festival, ipa
