"""``facesynth ingest``: a manifest of takes -> the ``corpus`` artifact (paper III).

The manifest (:mod:`facesynth.domain.capture.manifest`) names takes of any registered capture
format; they are read, aligned or recognised and checked by :mod:`facesynth.domain.capture.takes`
(which says how). Curve takes pose ``--rig`` (the built-in rig by default).

Rigid markers: when a binding ``markers.csv`` with a ``rigid`` column lies next to the
manifest (the sample corpus writes one), the markers it marks are recorded in the corpus
(``rigid``) as the set ``normalize`` fits the head pose on; else those the takes' reader names.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import AlignSettings, IngestSettings, settings_json
from facesynth.domain.capture.manifest import read_manifest
from facesynth.domain.capture.takes import capture_options, ingest
from facesynth.domain.rig.loading import load_rig
from facesynth.formats.mesh import read_rigid_markers
from facesynth.model.artifacts import check_output


@dataclass(frozen=True)
class IngestResult:
    """What ``facesynth ingest`` read.

    takes, frames, markers, phones: counts (takes, capture frames, markers per frame, phone segments).
    fps: the capture's frame rate (Hz).
    missing_fraction: the share of marker samples missing (gaps), 0 to 1.
    rigid_markers: the markers the binding file (markers.csv), or the takes' reader, flags rigid.
    without_audio: the takes without audio (head-motion needs it).
    without_phones: the takes without phone timing (left out of the database).
    recognized: the takes whose phones were recognised from their audio.
    posed: every take was posed from curves (its rest pose and head pose recorded).
    """

    takes: int
    frames: int
    markers: int
    phones: int
    fps: float
    missing_fraction: float
    rigid_markers: list[str]
    without_audio: list[str]
    without_phones: list[str]
    recognized: list[str]
    posed: bool



def run(manifest: Path, out: Path, settings: IngestSettings, align_settings: AlignSettings,
        overwrite: bool = False, rig_path: Path | None = None, binding: Path | None = None) -> IngestResult:
    """Read the takes of ``manifest`` and write ``out`` (a ``corpus`` artifact); curve takes pose
    the rig ``rig_path`` with the markers of ``binding`` (neither: the built-in rig and the
    virtual actress's markers; a binding alone: the built-in rig)."""
    check_output(out, overwrite)
    rig = None if rig_path is None and binding is None else load_rig(rig_path, binding)
    rows = read_manifest(manifest, settings)
    got = ingest(rows, settings, align_settings, capture_options(settings, rig))
    markers_csv = manifest.parent / "markers.csv"
    rigid = [n for n in read_rigid_markers(markers_csv) if n in got.names] if markers_csv.is_file() else got.rigid
    got.corpus(rigid).write(out, config=settings_json(settings), inputs=[manifest], overwrite=overwrite)
    return IngestResult(len(got.takes), int(got.markers.shape[0]), len(got.names), len(got.phones), got.fps,
                        got.missing_fraction, rigid, got.without_audio, got.without_phones, got.recognized,
                        got.rest is not None)
