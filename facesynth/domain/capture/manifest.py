"""The capture manifest ``facesynth ingest`` reads: a CSV with one take a row.

Its columns are ``take, mocap, audio, alignment, transcript, emotion, sentence, split, language``
and, for takes that need them, ``mapping, names, fps`` (paths relative to the manifest); only
``take`` and ``mocap`` are required (docs/inputs.md). An empty ``emotion`` is neutral (aliases
from ``ingest.emotion_aliases``), an empty ``split`` train.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import IngestSettings
from facesynth.base.errors import InputError
from facesynth.formats.video import SUFFIXES as VIDEO_SUFFIXES

REQUIRED_COLUMNS = ("take", "mocap")
SPLITS = ("train", "val", "test")


@dataclass
class ManifestRow:
    """One take of the manifest (``line``: its line number, for messages), paths resolved."""

    line: int
    take: str
    mocap: Path
    audio: Path | None
    alignment: Path | None
    transcript: str
    emotion: str
    sentence: str
    split: str
    mapping: Path | None = None
    names: Path | None = None
    fps: float | None = None
    language: str = ""


def read_manifest(path: Path, settings: IngestSettings) -> list[ManifestRow]:
    """Parse and check the manifest; every problem names the manifest line."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: manifest not found; check the path.")
    base = path.parent
    with open(path, encoding="utf-8-sig", newline="") as fh:
        reader = csv.DictReader(fh)
        columns = set(reader.fieldnames or [])
        missing = [c for c in REQUIRED_COLUMNS if c not in columns]
        if missing:
            raise InputError(f"{path}: the manifest lacks the column(s) {', '.join(missing)}; see docs/inputs.md for its columns.")
        rows, seen = [], set()
        aliases = {k.lower(): v for k, v in settings.emotion_aliases.items()}
        for line, raw in enumerate(reader, 2):
            where = f"{path}, line {line}"
            take = (raw.get("take") or "").strip()
            if not take:
                raise InputError(f"{where}: empty 'take' name; give every take a unique name.")
            if take in seen:
                raise InputError(f"{where}: take {take!r} appears twice; take names must be unique.")
            seen.add(take)
            emotion = (raw.get("emotion") or "").strip().lower() or "neutral"
            emotion = aliases.get(emotion, emotion)
            if emotion not in settings.emotions:
                raise InputError(f"{where}: unknown emotion {raw.get('emotion')!r}; use one of {', '.join(settings.emotions)}.")
            split = (raw.get("split") or "train").strip().lower() or "train"
            if split not in SPLITS:
                raise InputError(f"{where}: unknown split {split!r}; use train, val or test.")
            alignment = (raw.get("alignment") or "").strip()
            transcript = (raw.get("transcript") or "").strip()
            audio = (raw.get("audio") or "").strip()
            mocap = (raw.get("mocap") or "").strip()
            if not mocap:
                raise InputError(f"{where}: take {take!r} has no mocap file; give its marker file in the mocap column.")
            if transcript and not alignment and not audio and Path(mocap).suffix.lower() not in VIDEO_SUFFIXES:
                raise InputError(f"{where}: take {take!r} has a transcript to align but no audio; give its audio, "
                                 f"or its phone timing in the alignment column, or leave the transcript empty.")
            mapping = (raw.get("mapping") or "").strip()
            names = (raw.get("names") or "").strip()
            fps_text = (raw.get("fps") or "").strip()
            try:
                fps = float(fps_text) if fps_text else None
            except ValueError:
                fps = None
            if fps_text and (fps is None or not 0 < fps <= 2000):
                raise InputError(f"{where}: the fps {fps_text!r} is not a frame rate; give frames per second (e.g. 30).")
            rows.append(ManifestRow(
                line, take, base / mocap, base / audio if audio else None,
                base / alignment if alignment else None, transcript, emotion,
                (raw.get("sentence") or take).strip(), split,
                base / mapping if mapping else None, base / names if names else None, fps,
                (raw.get("language") or "").strip(),
            ))
    if not rows:
        raise InputError(f"{path}: the manifest lists no takes.")
    return rows
