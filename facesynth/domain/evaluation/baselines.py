"""External and rig-based pieces of the evaluation: openfacefx as a baseline, and the rig's
head frame put into the database's normalized head frame.

openfacefx (PyPI, MIT, NumPy only) is the text-driven lip-sync a user would pick instead of
facesynth: from time-stamped phones it builds Oculus-viseme curves with its own
coarticulation, retargeted to the 52 ARKit blendshapes (its ``arkit`` preset). Here it is
given the same phone timing as the DP; its ARKit curves are sampled at the capture rate, put
through the corpus's face rig (:meth:`Rig.from_arkit`, :meth:`Rig.evaluate` at the
marker vertices of ``markers.csv``) and moved into the normalized head frame with the same
rigid transform as the clean ground truth (:func:`fit_rigid`), so that both are compared
in one frame. It is optional: :func:`openfacefx_missing` says why it cannot run.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.phonemes import PAU

#: Festival phones that are not among openfacefx's 39 ARPAbet phones -> the nearest ones.
_NEAREST_ARPABET = {"ax": "AH", "axr": "ER", "el": "L", "em": "M", "en": "N", "nx": "N"}


def openfacefx_missing() -> str | None:
    """None when openfacefx can be imported, else one sentence saying why it cannot run."""
    try:
        import openfacefx  # noqa: F401
        from openfacefx.pipeline import generate_from_alignment  # noqa: F401
        from openfacefx.retarget import PRESETS
    except ImportError as exc:
        return f"openfacefx is not installed ({exc}); pip install openfacefx (or the 'test' extra) to add it as a baseline"
    if "arkit" not in PRESETS:
        return "this openfacefx has no 'arkit' retarget preset"
    return None


def to_arpabet(phone: str) -> str:
    """A Festival phone (``aa``, ``ax``, ``pau``) as openfacefx's stress-less ARPAbet (``AA``,
    ``AH``, ``sil``)."""
    if phone == PAU:
        return "sil"
    return _NEAREST_ARPABET.get(phone, phone.upper())


def openfacefx_arkit(phones: list[str], starts: np.ndarray, ends: np.ndarray, n_frames: int, fps: float,
                     arkit_names: tuple[str, ...]) -> np.ndarray:
    """openfacefx's ARKit curves for a phone sequence (Festival names, times in s), sampled at
    frames ``f / fps`` for f < ``n_frames``: (n_frames, 52) float64 weights in ``arkit_names``
    order (channels it does not drive are 0; keys are interpolated linearly, held at the ends,
    as its own retargeting samples them)."""
    from openfacefx.alignment import PhonemeSegment
    from openfacefx.pipeline import generate_from_alignment
    from openfacefx.retarget import PRESETS, retarget

    segments = [PhonemeSegment(to_arpabet(p), float(a), float(b)) for p, a, b in zip(phones, starts, ends)]
    track = retarget(generate_from_alignment(segments, fps=fps), PRESETS["arkit"])
    t = np.arange(n_frames) / fps
    out = np.zeros((n_frames, len(arkit_names)))
    column = {n: i for i, n in enumerate(arkit_names)}
    for channel in track.channels:
        if channel.name in column and channel.keys:
            kt = np.array([k.time for k in channel.keys])
            kv = np.array([k.value for k in channel.keys])
            out[:, column[channel.name]] = np.interp(t, kt, kv)
    return out


def fit_rigid(source: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares rotation and translation (Kabsch) with ``source @ R + t ~ target``.

    source, target : (K, 3) mm, corresponding points (K >= 3, NaN rows skipped).
    Returns R (3, 3) proper rotation and t (3,) mm.
    """
    ok = ~(np.isnan(source).any(1) | np.isnan(target).any(1))
    x, y = source[ok].astype(np.float64), target[ok].astype(np.float64)
    cx, cy = x.mean(0), y.mean(0)
    u, _, vt = np.linalg.svd((x - cx).T @ (y - cy))
    d = np.sign(np.linalg.det(u @ vt))
    r = u @ np.diag([1.0, 1.0, d]) @ vt
    return r, cy - cx @ r


def rig_markers(rig, arkit: np.ndarray, vertices: np.ndarray) -> np.ndarray:
    """ARKit weights (T, 52) through the rig to marker positions (T, M, 3) mm in the rig's
    head frame; ``vertices`` (M,) the marker vertices."""
    return rig.evaluate(rig.from_arkit(arkit), vertices=vertices)
