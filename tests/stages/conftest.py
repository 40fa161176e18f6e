"""Fixtures of the stage tests."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from facesynth.formats.labels import Segment, read_phone_segments, write_textgrid


@pytest.fixture(scope="session")
def spliced_sentence(tiny_corpus, tmp_path_factory) -> tuple[Path, list[Segment]]:
    """A new sentence made of a stretch of a training sentence between silences: its inner
    phones keep their training triphones, so context-correct nodes must exist for them. Returns
    its TextGrid and its phones (pauses included)."""
    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["split"] == "train")
    segs = [s for s in read_phone_segments(tiny_corpus / row["alignment"]) if s.label not in ("pau", "sil", "")]
    stretch = segs[3:9]
    t0 = stretch[0].start - 0.2
    out = [Segment(0.0, 0.2, "pau")] + [Segment(s.start - t0, s.end - t0, s.label) for s in stretch]
    out.append(Segment(out[-1].end, out[-1].end + 0.2, "pau"))
    path = tmp_path_factory.mktemp("spliced") / "spliced.TextGrid"
    write_textgrid(path, {"phones": out})
    return path, out
