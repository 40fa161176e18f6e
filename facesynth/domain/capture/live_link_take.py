"""Live Link Face takes (the CSV Epic's iPhone app records: 52 ARKit curves, head rotations,
timecodes) as a capture take of markers: the file is read by
:func:`facesynth.formats.livelink_face.read` (columns, timecodes, resampling to the timecode
rate), the curves pose the rig and its surface is recorded
(:func:`facesynth.domain.capture.posing.pose_markers`); the head rotations (``HeadYaw``,
``HeadPitch``, ``HeadRoll``, radians as the phone's camera sees the face) turn the markers
about the head's centre and become the take's head motion. The app records no head translation.
"""

from __future__ import annotations

import logging
from pathlib import Path

from facesynth.domain.rig.face import load_face_rig
from facesynth.formats import livelink_face

from .posing import CaptureTake, posed_take
from .readers import CaptureOptions, CaptureReader

log = logging.getLogger(__name__)


def read_live_link_take(path: Path, options: CaptureOptions) -> CaptureTake:
    """The Live Link Face CSV at ``path`` as markers of ``options.rig`` (None: the built-in rig
    and the virtual actress's markers) at its timecode rate (``options.fps``, else found from the
    timecodes); see the module docstring."""
    take = livelink_face.read(path, load_face_rig().arkit_names, options.fps, options.max_interpolated_s)
    head = None if take.head is None else livelink_face.head_rotations(take.head)
    for note in take.notes:
        log.warning("%s: %s.", path, note)
    return posed_take(take.arkit, take.fps, options.rig, head, "live-link-face", take.notes, options.live_link_neutral,
                      str(path))


def _recognizes(path: Path, options: CaptureOptions) -> bool:
    return livelink_face.is_live_link_face(path)


#: The registered reader (:mod:`facesynth.domain.capture`).
READER = CaptureReader(read_live_link_take, _recognizes)
