"""The articulation model fitted on a performer's own capture with its audio (``facesynth
fit-articulation``): what the voice says about this performer's mouth, for the fusion of
:mod:`facesynth.domain.voice.fusion` and for live frames.

Per take of an ingested capture (its ``corpus``: the audio; its ``normalized`` frames: the
markers in the head frame), at :data:`FIT_FPS` frames/s:

* ``opening``: the inner-lip gap (mm) between ``synthesize.loudness_lip_markers``;
* ``closure`` and ``closing``: the closure scores made of that opening
  (:func:`facesynth.domain.voice.articulation.closure_target`: every closure, and the closings
  within speech);
* ``jawOpen``, ``mouthFunnel``, ``mouthPucker``: the rig's weights of the take solved onto the
  built-in rig (the direct facial solve, ``[solve]`` settings; its markers bound by the rig's own
  binding or ``binding``), when the markers are bound; a capture whose markers the rig does not
  bind gets the opening and closure targets alone (the fusion then leaves the rounding to the
  phones).

The fit is :func:`facesynth.domain.voice.articulation.fit` with its defaults (10 offsets,
-250..+20 ms; ridge; running normalization), deterministic. The packaged model is this fit on
FACEGOOD's calibration takes, through ``benchmarks/voice_articulation.py`` (which reads FACEGOOD's
own curves instead of a solve).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SolveSettings
from facesynth.base.errors import InputError
from facesynth.domain.retarget import facial_solve
from facesynth.domain.rig.face import Rig
from facesynth.domain.speech.loudness import lip_gaps
from facesynth.domain.voice import articulation
from facesynth.model.articulation import ArticulationModel
from facesynth.model.corpus import Corpus
from facesynth.model.frames import NormalizedFrames

#: The frame rate the targets are fitted at (the closure scores' rate, :data:`facesynth.domain.voice.fusion.CLOSURE_FIT_FPS`).
FIT_FPS = 30.0
#: The rig shapes fitted as targets where the markers are bound (ARKit names of the built-in rig).
RIG_TARGETS = ("jawOpen", "mouthFunnel", "mouthPucker")
#: The fewest frames (at :data:`FIT_FPS`) of a take with audio that it is fitted on.
MIN_FRAMES = 10


@dataclass(frozen=True)
class PerformerTakes:
    """The takes a model is fitted on: ``takes`` (:class:`~facesynth.domain.voice.articulation.Take`
    per take with audio), the ``names`` of the targets, the take ``names_used`` and ``seconds`` of
    audio, and whether the rig's curves are among the targets (``solved``)."""

    takes: list[articulation.Take]
    names: tuple[str, ...]
    names_used: list[str]
    seconds: float
    solved: bool


def performer_takes(corpus: Corpus, normalized: NormalizedFrames, rig: Rig, solve: SolveSettings,
                    lips: tuple[str, ...], *, takes: list[str] | None = None, where: str = "the capture",
                    normalized_where: str = "the normalized frames") -> PerformerTakes:
    """The targets and voice features of every take of ``corpus`` with audio (or of ``takes``, each
    of which must have audio), from its ``normalized`` frames (the same takes; checked) solved onto
    ``rig``. Messages name ``where`` (the corpus) and ``normalized_where``."""
    names = list(corpus.takes.name)
    if list(normalized.takes.name) != names:
        raise InputError(f"{normalized_where}: it holds other takes than {where} "
                         f"({', '.join(normalized.takes.name[:3])}... against {', '.join(names[:3])}...); "
                         "give the normalized artifact made from this corpus.")
    missing = [m for m in lips if m not in corpus.marker_names]
    if missing:
        raise InputError(f"{where}: no marker {missing[0]!r}; set synthesize.loudness_lip_markers to the capture's "
                         "upper and lower inner-lip markers.")
    wanted = names if takes is None else list(takes)
    unknown = [t for t in wanted if t not in names]
    if unknown:
        raise InputError(f"{where}: no take {unknown[0]!r}; it has {', '.join(names[:5])}.")
    bound = sum(m in rig.binding for m in corpus.marker_names) >= 3
    target_names = ("opening", "closure", "closing") + (RIG_TARGETS if bound else ())
    out, used, seconds = [], [], 0.0
    for name in wanted:
        i = names.index(name)
        a, n = int(corpus.audio_start[i]), int(corpus.audio_count[i])
        motion = facial_solve.take_motion(normalized, name, FIT_FPS, str(normalized_where))
        frames = min(len(motion.markers), int(np.floor(n / corpus.sample_rate * FIT_FPS)))
        if frames < MIN_FRAMES:
            if takes is not None:  # a take asked for by name is fitted on or refused, never dropped
                raise InputError(f"{where}: take {name!r} has {n / corpus.sample_rate:.2f} s of audio with its "
                                 f"frames (at least {MIN_FRAMES / FIT_FPS:.2f} s needed); leave it out of --takes.")
            continue
        samples = corpus.audio[a:a + n]
        opening = lip_gaps(motion.markers[:frames], list(motion.marker_names), tuple(lips)).astype(np.float64)
        columns = [opening, articulation.closure_target(opening, FIT_FPS),
                   articulation.closure_target(opening, FIT_FPS, kind="closing")]
        if bound:
            weights = facial_solve.solve(motion, rig, solve, f"{where}, take {name}").curves.weights[:frames]
            shape_names = list(rig.shape_names)
            columns += [weights[:, shape_names.index(s)].astype(np.float64) for s in RIG_TARGETS]
        out.append(articulation.Take(articulation.frame_features(samples, corpus.sample_rate),
                                     np.stack(columns, 1), FIT_FPS))
        used.append(name)
        seconds += n / corpus.sample_rate
    if not out:
        raise InputError(f"{where}: no take has {MIN_FRAMES / FIT_FPS:.2f} s or more of audio with its frames to fit "
                         "the voice's articulation on; ingest the capture with its audio (the manifest's audio column).")
    return PerformerTakes(out, target_names, used, seconds, bound)


def fit_performer(data: PerformerTakes, prior: ArticulationModel | None = None,
                  prior_strength: float = 0.0) -> tuple[ArticulationModel, dict[str, float]]:
    """The model fitted on ``data`` (adapted from the general model ``prior`` with
    ``prior_strength``, :func:`facesynth.domain.voice.articulation.fit`), and per target its
    Pearson r on the takes it was fitted on (in-sample: how much of each target the voice explains
    at best)."""
    model = articulation.fit(data.takes, data.names, prior=prior, prior_strength=prior_strength)
    predicted = np.concatenate([articulation.predict_raw(model, t.raw, t.times_s) for t in data.takes])
    real = np.concatenate([t.targets for t in data.takes])
    r = {}
    for j, name in enumerate(data.names):
        known = np.isfinite(real[:, j])  # a capture's gaps are left out, as the fit leaves them out
        a, b = predicted[known, j] - predicted[known, j].mean(), real[known, j] - real[known, j].mean()
        d = float(np.sqrt((a * a).sum() * (b * b).sum()))
        r[name] = float((a * b).sum() / d) if d > 0 else float("nan")
    return model, r
