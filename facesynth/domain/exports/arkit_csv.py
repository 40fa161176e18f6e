"""The ``arkit-csv`` export: the Live Link Face CSV of the rig weights for Unreal's Live Link and
MetaHuman (the file itself: :mod:`facesynth.formats.livelink_face`, beside its reader). Units and
axes are in ``docs/exports.md``.
"""

from __future__ import annotations

from pathlib import Path

from facesynth.base.config import ExportSettings
from facesynth.formats import livelink_face as livelink

from .animation import Exportable
from .format import ExportFormat, ExportOptions


class ArkitCsv(ExportFormat):
    """The Live Link Face CSV of the rig weights (mapped to the 52 ARKit shapes by the rig), the
    eyes from the gaze where known and, with head motion, the head's yaw, pitch and roll; at
    ``export.arkit_fps`` (the app's 60 frames/s) unless a rate is asked."""

    name = "arkit-csv"
    carries = "weights"

    def rate(self, anim: Exportable, settings: ExportSettings) -> float:
        return settings.arkit_fps

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        rig, weights = anim.rig_weights()
        head = livelink.head_angles(anim.head()[0]) if options.head_motion else None
        eyes = livelink.eye_angles(anim.gaze) if anim.gaze is not None else None
        livelink.write(path, rig.arkit_names, rig.to_arkit(weights), anim.fps, head, eyes)
        return [path]


ARKIT_CSV = ArkitCsv()
