"""The ``mean`` method: the mean pose of each (phone, emotion) placed at each phone's centre and
interpolated linearly, the rest pose in pauses. The means are those of the database's node frames
(the mean PCA frame of every node of that phone and emotion; a pair the database lacks takes the
phone's nodes of every emotion, an unseen phone its viseme's nodes, else every node). It reads the
motion database directly: nothing is fitted. ``evaluate`` also scores the per-phone variant
(:func:`mean_pose_coefficients` with ``by_emotion=False``, the ``mean_per_phone`` row).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from facesynth.base.phonemes import PAU, viseme
from facesynth.domain.postprocess.concatenation import frame_ranges
from facesynth.domain.search.synthesis import unseen_phones
from facesynth.domain.speech.utterance import stand_in_phones

from . import MethodSettings, Synthesis, SynthesisSummary
from .steps import DatabaseMethod, frame_motion


def mean_pose_coefficients(db, utt, by_emotion: bool = True, phone_match: str = "unseen") -> np.ndarray:
    """PCA coefficients (T, K) float64 at the capture rate of the per-(phone, emotion) (or, without
    ``by_emotion``, per-phone) mean poses at phone centres, linearly interpolated. db : a
    MotionDatabase; utt : an Utterance. A phone of another language the database lacks takes the
    phone nearest it in features (``phone_match``: ``synthesize.phone_match``,
    :func:`~facesynth.domain.speech.utterance.stand_in_phones`)."""
    phones = np.array(db.nodes.phone)
    emotions = np.array(db.nodes.emotion)
    means: dict[tuple[str, str], np.ndarray] = {}
    rest = db.model.project(db.reference[None])[0].astype(np.float64)

    def mean_pose(p: str, emotion: str) -> np.ndarray:
        key = (p, emotion if by_emotion else "")
        if key not in means:
            sel = np.nonzero(phones == p)[0]
            if by_emotion and (emotions[sel] == emotion).any():
                sel = sel[emotions[sel] == emotion]
            if len(sel) == 0:  # an unseen phone: its viseme's nodes, else every node
                sel = np.nonzero(db.nodes.viseme == viseme(p))[0]
                sel = sel if len(sel) else np.arange(len(phones))
            rows = np.concatenate([np.arange(db.nodes.frame_start[k], db.nodes.frame_start[k] + db.nodes.frame_count[k]) for k in sel])
            means[key] = db.coeffs[rows].astype(np.float64).mean(0)
        return means[key]

    ranges = frame_ranges(utt.starts, utt.ends, db.fps)
    total = ranges[-1][1]
    centres = np.array([(a + b - 1) / 2.0 for a, b in ranges])
    looked_up = stand_in_phones(utt, set(db.nodes.phone), phone_match)
    poses = np.stack([rest if p == PAU else mean_pose(p, e) for p, e in zip(looked_up, utt.emotions)])
    frames = np.arange(total)
    return np.stack([np.interp(frames, centres, poses[:, k]) for k in range(poses.shape[1])], 1)


def mean_pose_markers(db, utt, by_emotion: bool = True) -> np.ndarray:
    """The markers (T, M, 3) float32 mm at the capture rate of :func:`mean_pose_coefficients`."""
    return db.model.reconstruct(mean_pose_coefficients(db, utt, by_emotion))


class MeanMethod(DatabaseMethod):
    """The per-(phone, emotion) mean pose; source: the motion database."""

    name = "mean"
    not_live = ("each phone's frames lean toward the next phone's centre pose, placed where that phone "
                "ends; stream dp or greedy, which read the same database")

    def ablations(self, db, settings: MethodSettings) -> dict[str, Callable[[Any], np.ndarray]]:
        """``mean_per_phone``: the per-phone mean pose (every emotion pooled)."""
        return {"mean_per_phone": lambda utt: mean_pose_markers(db, utt, by_emotion=False)}

    def synthesize(self, source, utt, settings: MethodSettings, constraints=None, *, prepared=None,
                   where: str = "the utterance") -> Synthesis:
        """The mean poses of ``utt`` from ``source`` (a MotionDatabase); the summary's ``unseen``
        names the phones the database has no node of."""
        self.refuse_constraints(constraints)
        coeffs = mean_pose_coefficients(source, utt, by_emotion=True, phone_match=settings.synthesize.phone_match)
        have = set(zip(source.nodes.phone, source.nodes.emotion))
        used = [e if (p, e) in have else "" for p, e in zip(utt.phones, utt.emotions)]
        motion = frame_motion(self.name, utt, source.model.reconstruct(coeffs), coeffs, source.fps,
                              settings.synthesize.output_fps, source.marker_names, source.reference, list(utt.phones),
                              [e if p != PAU else "" for p, e in zip(utt.phones, used)], "cpu (NumPy)")
        return Synthesis(motion, SynthesisSummary(len(utt), len(motion.markers),
                                                  unseen_phones(utt, source, settings.synthesize.phone_match)))
