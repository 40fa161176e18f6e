"""``facesynth normalize``: remove head motion from the markers (paper III, Eq. 1-2).

Short gaps are filled and every frame is rigidly aligned onto a neutral closed-mouth reference
frame, fitted on the rigid markers, or a posed corpus's known head pose is removed as it is
(:mod:`facesynth.domain.head_motion.removal` says how); the per-frame rigid transform is kept,
so ``captured = R_i @ normalized + t_i`` for every marker.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import NormalizeSettings, settings_json
from facesynth.domain.head_motion.removal import normalize
from facesynth.model.corpus import Corpus
from facesynth.model.frames import HeadFrames, NormalizedFrames


@dataclass(frozen=True)
class NormalizeResult:
    """What ``facesynth normalize`` did.

    frames: capture frames normalized.
    origin_marker: the marker at the origin of the head frame.
    long_gaps: gaps too long to fill, as (take, marker, start_s, length_s); PCA projects those frames.
    rigid_markers: the markers the head pose was fitted on.
    rigid_weights: each one's weight in that fit.
    rigid_source: where the rigid markers came from: 'data' (found from the data), 'settings', 'corpus' (the
        binding, or the takes' reader), or 'known': no fit, the head pose of a posed corpus removed as it is.
    rigid_spreads_mm: with ``rigid_source`` 'data', how much each one's distances to the others vary (mm).
    warnings: what the user should know.
    """

    frames: int
    origin_marker: str
    long_gaps: list[tuple[str, str, float, float]]
    rigid_markers: list[str]
    rigid_weights: list[float]
    rigid_source: str
    rigid_spreads_mm: list[float] | None
    warnings: list[str]


def run(corpus_path: Path, out: Path, settings: NormalizeSettings, overwrite: bool = False) -> NormalizeResult:
    """Normalize ``corpus_path`` and write ``out`` (a ``normalized`` artifact)."""
    corpus = Corpus.read(corpus_path, audio=False)
    names = corpus.marker_names
    known = None
    if corpus.rest_pose is not None and corpus.known_head_rotation is not None \
            and corpus.known_head_translation is not None:
        known = (corpus.rest_pose, corpus.known_head_rotation, corpus.known_head_translation)
    n = normalize(corpus.markers, names, corpus.takes, corpus.phones, corpus.fps, settings, corpus.rigid_markers, known)
    frames = HeadFrames(n.normalized, n.reference.astype(np.float32), n.rotations.astype(np.float32),
                        n.translations.astype(np.float32), corpus.fps, names[n.origin])
    NormalizedFrames(corpus.takes, corpus.phones, names, frames, n.known_pose).write(
        out, config=settings_json(settings), inputs=[corpus_path], overwrite=overwrite)
    spreads = n.rigid.spreads
    return NormalizeResult(len(n.normalized), names[n.origin], n.long_gaps, [names[k] for k in n.rigid.indices],
                           [float(w) for w in n.weights], n.rigid.source,
                           None if spreads is None else [float(x) for x in spreads], [])
