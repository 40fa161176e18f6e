"""``facesynth openfacefx``: the lip sync openfacefx makes for the phones and timing of a
synthesized motion, as rig curves (``source = "openfacefx"``) on the same rig, frame rate and
frame count, so ``facesynth render --compare`` shows the two side by side.

openfacefx (PyPI, MIT; the ``baselines`` extra) is the text-driven lip sync a user would pick
instead of facesynth, and the external baseline of ``facesynth evaluate``: from the motion's
phones (its search path) it builds its viseme curves with its own coarticulation and retargets
them to the 52 ARKit blendshapes (:func:`facesynth.domain.evaluation.baselines.openfacefx_arkit`); the rig's ARKit
table (:func:`facesynth.domain.rig.loading.arkit_to_rig`) takes them onto the rig. It has no head
motion, gaze or emotion: the curves carry none.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.evaluation.baselines import openfacefx_arkit, openfacefx_missing
from facesynth.domain.rig.loading import arkit_to_rig, load_rig
from facesynth.model.artifacts import check_output
from facesynth.model.curves import RigCurves
from facesynth.model.motion import Motion


@dataclass(frozen=True)
class OpenfacefxResult:
    """What ``facesynth openfacefx`` wrote.

    frames: frames of the curves (the motion's).
    fps: their rate (frames/s).
    phones: phones of the motion lip-synced.
    rig: the rig's name.
    """

    frames: int
    fps: float
    phones: int
    rig: str


def run(motion_path: Path, out: Path, rig_path: Path | None = None, overwrite: bool = False) -> OpenfacefxResult:
    """Write openfacefx's curves for the phones of the synthesized motion ``motion_path`` on the
    rig (built-in when ``rig_path`` is None) to ``out``."""
    check_output(out, overwrite)
    missing = openfacefx_missing()
    if missing is not None:
        raise InputError(f"{motion_path}: cannot run openfacefx: {missing}.")
    search, _ = Motion.read_search(motion_path)
    if search is None:
        raise InputError(f"{motion_path}: a captured take has no phones for openfacefx; give a motion made by "
                         f"`facesynth synthesize`.")
    motion = Motion.read(motion_path)
    rig = load_rig(rig_path, None, need_binding=False)
    names, to_rig = arkit_to_rig(rig, str(rig_path))
    arkit = openfacefx_arkit(list(search.phone), search.start, search.end, len(motion.markers), motion.fps, names)
    weights = np.clip(arkit @ to_rig, 0.0, 1.0)
    from importlib.metadata import version

    inputs = [motion_path] + ([rig_path] if rig_path is not None and Path(rig_path).is_file() else [])
    RigCurves(weights, motion.fps, list(rig.shape_names), rig.name, rig.sha256, "openfacefx",
              method=f"openfacefx {version('openfacefx')}, arkit preset, the motion's phones").write(
        out, config="{}", inputs=inputs, overwrite=overwrite)
    return OpenfacefxResult(len(weights), motion.fps, len(search.phone), rig.name)
