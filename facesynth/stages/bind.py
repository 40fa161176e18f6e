"""``facesynth bind``: a user's own capture placed on a rig, written as the binding CSV that
``solve``, ``rig-mesh``, ``deform`` and ``ingest`` read (``marker,vertex,rigid``, plus
``residual_mm`` and ``flagged`` for the user to check).

One frame is fitted to the rig's surface by :func:`facesynth.domain.retarget.bind.bind_markers`:
``bind.frame``, else the take's most typical frame (:func:`facesynth.domain.geometry.rigid.typical_frame`,
the face it holds most; ``normalize`` takes the same frame as its reference when no silence is
marked); markers the capture shows riding on the jaw take vertices the rig's ``jawOpen``
carries, and markers that do not, vertices it does not (:func:`facesynth.domain.retarget.bind.jaw_sides`).
The rigid flags are the markers whose mutual distances vary least over the whole take
(:func:`facesynth.domain.geometry.rigid.find_rigid_markers`, with ``normalize.rigid_max_spread_mm``), so
that ``ingest`` records them when the CSV is saved as ``markers.csv`` beside the manifest and
``normalize`` fits the head pose on them; a take with too few markers seen for that gets no
rigid flags (and no jaw sides), with a note.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import BindSettings, NormalizeSettings
from facesynth.base.errors import InputError
from facesynth.domain.capture.readers import CaptureOptions, read_capture
from facesynth.domain.geometry.rigid import fill_gaps, find_rigid_markers, head_pose, typical_frame
from facesynth.domain.retarget.bind import AXES, bind_markers, jaw_sides
from facesynth.domain.rig.loading import load_rig_mesh
from facesynth.formats.mesh import write_binding
from facesynth.model.artifacts import atomic_path, check_output


@dataclass(frozen=True)
class BindResult:
    """What ``facesynth bind`` placed.

    rig: the rig's name.
    frame: the capture frame fitted (0-based).
    markers: markers bound.
    unbound: markers not seen in that frame, left out.
    residual_mm: each bound marker's distance from its vertex (mm), by name.
    flagged: the markers farther than ``max_residual_mm`` from the rig's surface, in capture order.
    residual_median_mm, residual_p95_mm: the median and 95th percentile of those distances (mm).
    scale: the similarity's scale from capture millimetres to rig units.
    start: which start of the closest-point fit won.
    rigid: the rigid (head) markers found from the data.
    rigid_spreads_mm: how much each one's distances to the others vary (mm).
    shared_vertices: markers that share their vertex with another.
    max_residual_mm: bind.max_residual_mm, the flagging distance (mm).
    notes: what the user should check.
    """

    rig: str
    frame: int
    markers: int
    unbound: list[str]
    residual_mm: dict[str, float]
    flagged: list[str]
    residual_median_mm: float
    residual_p95_mm: float
    scale: float
    start: str
    rigid: list[str]
    rigid_spreads_mm: list[float]
    shared_vertices: int
    max_residual_mm: float
    notes: list[str]


def run(capture: Path, out: Path, settings: BindSettings, normalize_settings: NormalizeSettings,
        rig_path: Path | None = None, up: str | None = None, forward: str | None = None,
        overwrite: bool = False) -> BindResult:
    """Bind the markers of ``capture`` (any capture a manifest may name: markers, or a video's tracked
    landmarks) to the rig and write the CSV ``out``."""
    check_output(out, overwrite)
    if (up is None) != (forward is None):
        raise InputError("give both --up and --forward (the capture's axes), or neither to find them from the data.")
    for label, axis in (("--up", up), ("--forward", forward)):
        if axis is not None and axis not in AXES:
            raise InputError(f"{label} {axis!r} is not an axis; use one of {', '.join(AXES)}.")
    if up is not None and forward is not None and up[1] == forward[1]:
        raise InputError(f"--up {up} and --forward {forward} lie on one axis; give two perpendicular axes.")
    take = read_capture(Path(capture), CaptureOptions(need_audio=False))
    positions = take.positions
    frame = settings.frame if settings.frame >= 0 else typical_frame(positions)
    if frame >= len(positions):
        raise InputError(f"{capture}: bind.frame {frame} is beyond the take's {len(positions)} frames; choose a frame "
                         f"from 0 to {len(positions) - 1}.")
    rig_name, neutral, faces, jaw_motion = load_rig_mesh(rig_path)
    notes = []
    try:
        rigid_idx, spreads = find_rigid_markers(positions, max_spread_mm=normalize_settings.rigid_max_spread_mm,
                                                min_markers=normalize_settings.rigid_min_markers)
    except ValueError as exc:
        rigid_idx, spreads = np.zeros(0, np.int64), np.zeros(0)
        notes.append(f"no rigid markers found ({exc}); name them in the CSV's rigid column")
    try:
        allowed = None
        if jaw_motion is not None and len(rigid_idx):  # markers kept on their side of the jaw (see jaw_sides)
            filled = positions.astype(np.float64)
            for m in range(filled.shape[1]):
                filled[:, m], _ = fill_gaps(filled[:, m], normalize_settings.max_gap_frames)
            rest = filled[frame]
            if not np.isnan(rest[rigid_idx]).any():
                aligned, _, _, _ = head_pose(filled, rest, rigid_idx)
                allowed = jaw_sides(aligned - rest, jaw_motion)
        binding = bind_markers(positions[frame], take.names, neutral, faces, max_residual_mm=settings.max_residual_mm,
                               up=up, forward=forward, keep=settings.keep, iterations=settings.iterations,
                               frame_index=frame, allowed=allowed)
    except ValueError as exc:
        raise InputError(f"{capture}: {exc}; choose a frame that sees the face's markers with --frame.") from None
    rigid = {take.names[i] for i in rigid_idx}
    residual = dict(zip(binding.names, binding.residual_mm.tolist()))
    flagged = {n for n, f in zip(binding.names, binding.flagged) if f}
    with atomic_path(out, overwrite) as tmp:
        write_binding(tmp, dict(zip(binding.names, binding.vertices.tolist())), rigid, residual, flagged)
    shared = len(binding.vertices) - len(np.unique(binding.vertices))
    return BindResult(rig_name, frame, len(binding.names), binding.unbound, residual,
                      sorted(flagged, key=binding.names.index), float(np.median(binding.residual_mm)),
                      float(np.percentile(binding.residual_mm, 95)), binding.fit.scale, binding.fit.start,
                      [take.names[i] for i in rigid_idx], [float(x) for x in spreads], shared,
                      settings.max_residual_mm, notes)

