"""Where MediaPipe Face Mesh's 478 landmarks lie on the built-in rig, shipped with facesynth
(``facesynth/data/face_mesh_builtin.csv``), so that a filmed take is solved on the built-in rig
without ``facesynth bind``.

Face Mesh's landmarks have a fixed meaning (landmark 13 is always the upper inner lip's centre),
so one binding serves every video. It was made once from the rig by
``scripts/face_mesh_binding.py``: the virtual actress (the built-in rig) rendered frontally by
``facesynth render`` and the video bound by ``facesynth bind VIDEO --rig builtin --up +y
--forward +z``, what a user runs for a rig of their own. The file is the binding CSV ``bind``
writes (``marker,vertex,rigid,residual_mm,flagged``; markers ``MP000`` ... ``MP477``).
"""

from __future__ import annotations

import dataclasses
from functools import lru_cache
from importlib import resources

from facesynth.formats.mesh import read_binding

from .face import Rig, builtin_rig_sha256

#: The shipped binding (in ``facesynth/data``).
BINDING_FILE = "face_mesh_builtin.csv"
#: Face Mesh's landmarks with the iris points (``refine_landmarks``).
LANDMARKS = 478


def face_mesh_names() -> list[str]:
    """The 478 marker names of a filmed take, ``MP000`` ... ``MP477`` (MediaPipe's indices)."""
    return [f"MP{i:03d}" for i in range(LANDMARKS)]


@lru_cache(maxsize=1)
def _shipped() -> tuple[tuple[str, int], ...]:
    with resources.as_file(resources.files("facesynth").joinpath(f"data/{BINDING_FILE}")) as path:
        return tuple(read_binding(path).items())


def face_mesh_binding() -> dict[str, int]:
    """The shipped binding: Face Mesh marker name -> built-in rig vertex (0-based)."""
    return dict(_shipped())


def is_face_mesh(marker_names: list[str]) -> bool:
    """Whether ``marker_names`` are a filmed take's (Face Mesh's 478 landmarks)."""
    return list(marker_names) == face_mesh_names()


def bound_for(rig: Rig, marker_names: list[str]) -> Rig:
    """``rig``, or, when it is the built-in rig, none of ``marker_names`` is bound on it and they
    are Face Mesh's, the built-in rig bound by the shipped binding (a user's own rig, or a
    binding the user gave, is kept)."""
    if rig.sha256 == builtin_rig_sha256() and is_face_mesh(marker_names) \
            and not any(m in rig.binding for m in marker_names):
        return dataclasses.replace(rig, binding=face_mesh_binding())
    return rig
