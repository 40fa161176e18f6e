"""Live Link Face CSV: the file the iPhone app records and Unreal's Live Link (and MetaHuman
animators) import. The column set, order and timecode format are the app's own, taken from the
real capture that ships with the rig (``ict_face_arkit.tsv`` lists its columns):

``Timecode,BlendShapeCount,`` the 52 ARKit blendshapes (``EyeBlinkLeft`` ... ``TongueOut``),
then ``HeadYaw,HeadPitch,HeadRoll,LeftEyeYaw,LeftEyePitch,LeftEyeRoll,RightEyeYaw,RightEyePitch,
RightEyeRoll``: 61 value columns, ``BlendShapeCount`` always 61. The timecode is
``HH:MM:SS:FF.sss``: FF the frame within the second at the file's rate (0..59 at 60 frames/s)
and ``.sss`` the sub-frame fraction; the file starts at 00:00:00:00.000.

Rotations are radians as the phone's camera sees the face, i.e. mirrored (x -> -x) from
facesynth's frame: with the head rotation ``R = Ry(a) @ Rx(b) @ Rz(c)`` (about +y, +x, +z of
facesynth's frame) ``HeadYaw = -a`` (positive: the face turns toward the subject's right, the
camera's left), ``HeadPitch = b`` (positive: the face looks down), ``HeadRoll = -c``. Eyes:
``LeftEye*`` is the eye at -x, ``RightEye*`` the eye at +x (the app's left and right are the
camera's), yaw positive toward -x and pitch positive down. This mirror convention reproduces the
eye columns of the shipped capture from its own ``EyeLook*`` weights to within 0.02 rad.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

#: The head and eye rotation columns after the blendshapes, in the app's order.
ROTATION_COLUMNS = ("HeadYaw", "HeadPitch", "HeadRoll", "LeftEyeYaw", "LeftEyePitch", "LeftEyeRoll",
                    "RightEyeYaw", "RightEyePitch", "RightEyeRoll")


def columns(arkit_names) -> list[str]:
    """The header: Timecode, BlendShapeCount, the 52 ARKit names capitalized, the 9 rotations."""
    return ["Timecode", "BlendShapeCount"] + [n[0].upper() + n[1:] for n in arkit_names] + list(ROTATION_COLUMNS)


def timecode(frame: int, fps: float) -> str:
    """``HH:MM:SS:FF.sss`` of ``frame`` at ``fps`` frames/s from 00:00:00:00.000."""
    t = frame / fps
    whole = int(np.floor(t + 1e-9))
    within = (t - whole) * fps
    ff = int(np.floor(within + 1e-6))
    sub = int(round((within - ff) * 1000))
    if sub >= 1000:
        ff, sub = ff + 1, 0
    h, rest = divmod(whole, 3600)
    m, s = divmod(rest, 60)
    return f"{h:02d}:{m:02d}:{s:02d}:{ff:02d}.{sub:03d}"


def head_angles(rotation: np.ndarray) -> np.ndarray:
    """(T, 3) radians (HeadYaw, HeadPitch, HeadRoll) of head rotations (T, 3, 3), mirrored as the
    module docstring says."""
    from scipy.spatial.transform import Rotation

    a, b, c = Rotation.from_matrix(np.asarray(rotation, np.float64)).as_euler("YXZ").T  # R = Ry(a) Rx(b) Rz(c)
    return np.stack([-a, b, -c], axis=1)


def eye_angles(gaze: np.ndarray) -> np.ndarray:
    """(T, 6) radians (LeftEyeYaw, LeftEyePitch, LeftEyeRoll, RightEyeYaw, RightEyePitch,
    RightEyeRoll) of facesynth's gaze (T, 2, 2): per eye (+x eye first) yaw toward +x, pitch up."""
    g = np.asarray(gaze, np.float64)
    zero = np.zeros(len(g))
    return np.stack([-g[:, 1, 0], -g[:, 1, 1], zero, -g[:, 0, 0], -g[:, 0, 1], zero], axis=1)


def write(path: Path, arkit_names, arkit: np.ndarray, fps: float, head: np.ndarray | None = None,
          eyes: np.ndarray | None = None) -> None:
    """Write a Live Link Face CSV.

    arkit : (T, 52) weights in [0, 1] in ``arkit_names`` order; head : optional (T, 3) radians
    (:func:`head_angles`), zeros when None; eyes : optional (T, 6) radians (:func:`eye_angles`),
    zeros when None. Values with ten decimals, as the app writes them."""
    arkit = np.clip(np.asarray(arkit, np.float64), 0.0, 1.0)
    n = len(arkit)
    head = np.zeros((n, 3)) if head is None else np.asarray(head, np.float64)
    eyes = np.zeros((n, 6)) if eyes is None else np.asarray(eyes, np.float64)
    values = np.concatenate([arkit, head, eyes], axis=1)
    count = values.shape[1]
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(",".join(columns(arkit_names)) + "\n")
        for i in range(n):
            fh.write(f"{timecode(i, fps)},{count}," + ",".join(f"{v:.10f}" for v in values[i]) + "\n")
