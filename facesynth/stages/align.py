"""``facesynth align``: phone-level forced alignment of speech to its text (see
:mod:`facesynth.alignment`), written as a TextGrid with phone and word tiers."""

from __future__ import annotations

from pathlib import Path

from ..alignment import align_words, read_pronunciations
from ..artifacts import atomic_path
from ..config import AlignSettings
from ..errors import InputError
from ..formats.audio import read_audio
from ..formats.labels import write_textgrid
from ..phonemes import PAU


def run(audio_path: Path, text: str, out: Path, settings: AlignSettings, dict_path: Path | None = None,
        overwrite: bool = False) -> dict:
    """Align ``text`` to the speech of ``audio_path`` and write ``out`` (a TextGrid with phone and
    word tiers); returns the number of phones and the duration (s).
    """
    samples, rate = read_audio(audio_path)
    extra = read_pronunciations(dict_path) if dict_path else {}
    segments, words = align_words(samples, rate, text, extra=extra, settings=settings, where=str(audio_path))
    with atomic_path(out, overwrite) as tmp:
        write_textgrid(tmp, {"phones": segments, "words": words}, segments[-1].end)
    return {"phones": sum(s.label != PAU for s in segments), "seconds": segments[-1].end}


def read_transcript(path: Path) -> str:
    """The text of a transcript file (UTF-8)."""
    try:
        return Path(path).read_text("utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: transcript file not found.") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save the transcript as UTF-8.") from None
