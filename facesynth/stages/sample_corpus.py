"""``facesynth sample-corpus``: the built-in virtual actress's capture corpus (C3D, WAV,
TextGrid, manifest, face mesh, ground truth; :mod:`facesynth.domain.corpus.generate`), or with
``--preset facegood`` a real performer's takes shipped with facesynth (FACEGOOD's curves and
speech: :mod:`facesynth.domain.capture.facegood`), written into a folder beside the output and
renamed into place when complete."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import SampleCorpusSettings
from facesynth.domain.capture.facegood import write_corpus as write_facegood
from facesynth.domain.corpus.generate import generate
from facesynth.model.artifacts import atomic_folder


@dataclass(frozen=True)
class SampleCorpusResult:
    """What ``facesynth sample-corpus`` wrote.

    takes: takes (the actress: one C3D, WAV and TextGrid each; facegood: curves and WAV).
    frames: capture frames over all takes.
    seconds: capture length over all takes (s).
    train_phones: phone segments of the training takes (facegood: 0, recognised by ingest).
    contamination_events: marker spikes and swaps put into the capture (for prune to find).
    performer: 'virtual actress', or the real performer's corpus (facegood).
    """

    takes: int
    frames: int
    seconds: float
    train_phones: int
    contamination_events: int
    performer: str = "virtual actress"


def run(out_dir: Path, preset: str, seed: int, settings: SampleCorpusSettings | None = None,
        overwrite: bool = False) -> SampleCorpusResult:
    """Write the corpus of ``preset`` ('tiny', 'small', 'paper') made with ``seed`` into ``out_dir``,
    the actress articulating with ``settings`` (``[sample_corpus]``; None: the defaults); preset
    'facegood': FACEGOOD's takes (seed and settings do not apply)."""
    if preset == "facegood":
        with atomic_folder(out_dir, "the corpus", overwrite) as folder:
            written = write_facegood(folder)
        return SampleCorpusResult(written.takes, written.frames, written.seconds, 0, 0,
                                  "FACEGOOD's performer (one speaker, presumably Mandarin, neutral, face solved from video)")
    with atomic_folder(out_dir, "the corpus", overwrite) as folder:  # renamed into place when complete
        summary = generate(folder, preset, seed, overwrite=True, settings=settings)
    return SampleCorpusResult(summary.takes, summary.frames, summary.seconds, summary.train_phones,
                              summary.contamination_events)
