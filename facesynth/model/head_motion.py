"""The ``headmotion`` artifact: head motion synthesized from the pitch of speech (Chuang &
Bregler §5), written by ``facesynth head-motion``."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .artifacts import attr, open_artifact, read, read_strings, stamp, write_artifact, write_strings


@dataclass
class HeadMotion:
    """Head motion for one utterance, with the pitch and segments it was chosen by.

    rotation : (T, 3, 3) float32, translation : (T, 3) float32 mm at ``fps``: the head pose
        relative to the rest pose (``x -> rotation @ x + translation``, as a motion's head motion).
    pitch : (P,) float32 Hz at ``pitch_fps``, NaN where unvoiced (after cleaning).
    seg_start, seg_end : (G,) float64 s, the input's segments (voiced onset to the next).
    seg_take : G names of the captured takes chosen; seg_index : (G,) int64 segment within that
        take; seg_cost : (G,) float64 Eq. 12 node cost; seg_from, seg_to : (G,) float64 s,
        the chosen segment's span in its take.
    """

    rotation: np.ndarray
    translation: np.ndarray
    fps: float
    pitch: np.ndarray
    pitch_fps: float
    seg_start: np.ndarray
    seg_end: np.ndarray
    seg_take: list[str]
    seg_index: np.ndarray
    seg_cost: np.ndarray
    seg_from: np.ndarray
    seg_to: np.ndarray

    KIND = "headmotion"

    @classmethod
    def read(cls, path: Path) -> "HeadMotion":
        """The head motion at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            return cls(read(f, "rotation"), read(f, "translation"), float(attr(f["rotation"], "fps")),
                       read(f, "pitch"), float(attr(f["pitch"], "fps")), read(f, "segments/start"),
                       read(f, "segments/end"), read_strings(f, "segments/take"), read(f, "segments/index"),
                       read(f, "segments/cost"), read(f, "segments/take_start"), read(f, "segments/take_end"))

    def write(self, path: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``headmotion`` artifact to ``path``."""
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            r = g.create_dataset("rotation", data=self.rotation.astype(np.float32))
            r.attrs.update(fps=self.fps, convention="head pose relative to rest: x -> rotation @ x + translation")
            t = g.create_dataset("translation", data=self.translation.astype(np.float32))
            t.attrs.update(fps=self.fps, units="mm")
            p = g.create_dataset("pitch", data=self.pitch.astype(np.float32))
            p.attrs.update(fps=self.pitch_fps, units="Hz")
            s = stamp(g.create_group("segments"), "pitch-segments")
            s.create_dataset("start", data=self.seg_start.astype(np.float64)).attrs["units"] = "s"
            s.create_dataset("end", data=self.seg_end.astype(np.float64)).attrs["units"] = "s"
            write_strings(s, "take", self.seg_take)
            s.create_dataset("index", data=self.seg_index.astype(np.int64))
            s.create_dataset("cost", data=self.seg_cost.astype(np.float64))
            s.create_dataset("take_start", data=self.seg_from.astype(np.float64)).attrs["units"] = "s"
            s.create_dataset("take_end", data=self.seg_to.astype(np.float64)).attrs["units"] = "s"

    def at(self, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(rotations (T, 3, 3), translations (T, 3) mm) at ``times`` s: linear in rotation
        vector between frames, the last pose held after the end."""
        from scipy.spatial.transform import Rotation

        n = len(self.rotation)
        if n == 0:
            return np.broadcast_to(np.eye(3), (len(times), 3, 3)).copy(), np.zeros((len(times), 3))
        src = np.arange(n) / self.fps
        rv = Rotation.from_matrix(self.rotation.astype(np.float64)).as_rotvec()
        rot = np.stack([np.interp(times, src, rv[:, a]) for a in range(3)], 1)
        tr = np.stack([np.interp(times, src, self.translation[:, a]) for a in range(3)], 1)
        return Rotation.from_rotvec(rot).as_matrix(), tr
