"""``facesynth align``: phone-level forced alignment of speech to its text (see
:mod:`facesynth.domain.speech.alignment`: pocketsphinx with fallbacks), or, without a text, phones
recognised from the speech alone (:mod:`facesynth.domain.speech.recognition`), written as a TextGrid with
phone and word tiers (no word tier when phones were recognised without words)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.speech.alignment import read_pronunciations
from facesynth.domain.speech.recognition import align_or_recognize
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import write_textgrid
from facesynth.model.artifacts import atomic_path, check_output


@dataclass(frozen=True)
class AlignResult:
    """What ``facesynth align`` did.

    phones: phones placed, pauses not counted.
    seconds: the end of the last segment (s), the length of the aligned speech.
    method: the method that placed the words (``align.methods``: pocketsphinx, a wider beam, ...).
    attempts: why each earlier method was not used, in order.
    warnings: e.g. a transcript that seems to lack words.
    recognized: what was recognised from the speech; empty when the text was given.
    """

    phones: int
    seconds: float
    method: str
    attempts: list[str]
    warnings: list[str]
    recognized: str


def run(audio_path: Path, text: str | None, out: Path, settings: AlignSettings, dict_path: Path | None = None,
        overwrite: bool = False) -> AlignResult:
    """Align ``text`` to the speech of ``audio_path`` (``text`` None: recognise it, by
    ``settings.recognition``) and write ``out`` (a TextGrid with phone and word tiers)."""
    check_output(out, overwrite)
    samples, rate = read_audio(audio_path)
    extra = read_pronunciations(dict_path) if dict_path else {}
    result = align_or_recognize(samples, rate, text, extra=extra, settings=settings, where=str(audio_path))
    segments = result.phones
    tiers = {"phones": segments, "words": result.words} if result.words else {"phones": segments}
    with atomic_path(out, overwrite) as tmp:
        write_textgrid(tmp, tiers, segments[-1].end)
    return AlignResult(sum(s.label != PAU for s in segments), segments[-1].end, result.method, result.attempts,
                       result.warnings, result.recognized)


def read_transcript(path: Path) -> str:
    """The text of a transcript file (UTF-8)."""
    try:
        return Path(path).read_text("utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: transcript file not found.") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save the transcript as UTF-8.") from None
