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
-250..+20 ms; ridge; running normalization), deterministic. The packaged model is that fit on
many speakers (``benchmarks/voice_speakers.py --fit-only``, docs/real-speech.md), which reads
each source's own mouth curves instead of a solve.

**Held out, take by take** (:func:`held_out_takes`, two takes or more): each take is predicted by
the model fitted on the others (:func:`facesynth.domain.voice.articulation.fit_leaving_each_out`:
adapting the packaged model, from each take's sums, so that many takes cost little more than
one fit), which says how well the voice reads this performer's mouth on
audio the model never heard (the fit's own r says how well it fits). The same predictions choose
the voice's own closures: the threshold of its closure score (:data:`CLOSURE_THRESHOLDS`) whose
closures (:func:`facesynth.domain.voice.fusion.closure_frames`) best meet the captured ones
(:func:`facesynth.domain.voice.articulation.closure_frames_of`, within :data:`CLOSURE_TOLERANCE`
frames; the best F1), provided at least :data:`MIN_CLOSURE_PRECISION` of them are right. The
model carries it (``closure_threshold``) and ``synthesize.voice_closure_threshold = -1``, the
default, takes it: a performer's own voice closes the lips where its held-out takes say it can,
where a general model's closure score fires where the lips of voices it never heard stay open
(docs/real-speech.md), and the packaged model carries none.
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
from facesynth.domain.voice.fusion import closure_frames
from facesynth.model.articulation import ArticulationModel
from facesynth.model.corpus import Corpus
from facesynth.model.frames import NormalizedFrames

#: The frame rate the targets are fitted at (the closure scores' rate, :data:`facesynth.domain.voice.fusion.CLOSURE_FIT_FPS`).
FIT_FPS = 30.0
#: The rig shapes fitted as targets where the markers are bound (ARKit names of the built-in rig).
RIG_TARGETS = ("jawOpen", "mouthFunnel", "mouthPucker")
#: The fewest frames (at :data:`FIT_FPS`) of a take with audio that it is fitted on.
MIN_FRAMES = 10
#: The closure score's thresholds tried for the voice's own closures (0.20, 0.25, ..., 0.90).
CLOSURE_THRESHOLDS = tuple(round(0.2 + 0.05 * k, 2) for k in range(15))
#: A closure of the voice meets a captured one within this many frames at :data:`FIT_FPS` (100 ms,
#: as the benchmarks count them).
CLOSURE_TOLERANCE = 3
#: The voice's own closures are taken only where at least this share of them meet a captured closure.
MIN_CLOSURE_PRECISION = 0.5


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
    return model, pearson_per_target([articulation.predict_raw(model, t.raw, t.times_s) for t in data.takes],
                                     [t.targets for t in data.takes], data.names)


def pearson_per_target(predicted: list[np.ndarray], real: list[np.ndarray], names) -> dict[str, float]:
    """Per target of ``names``, Pearson r between the predictions and the real targets of every
    take ((T, Y) each), pooled over the takes' frames; a capture's gaps (NaN) are left out, as
    the fit leaves them out; NaN where either side is constant."""
    p, y = np.concatenate(predicted), np.concatenate(real)
    r = {}
    for j, name in enumerate(names):
        known = np.isfinite(y[:, j])
        a, b = p[known, j] - p[known, j].mean(), y[known, j] - y[known, j].mean()
        d = float(np.sqrt((a * a).sum() * (b * b).sum()))
        r[name] = float((a * b).sum() / d) if d > 0 else float("nan")
    return r


@dataclass(frozen=True)
class HeldOutTakes:
    """Each take predicted by the model fitted on the other takes, pooled (module docstring):
    ``r`` per target; the voice's closures at ``closure_threshold`` (None: no threshold makes
    :data:`MIN_CLOSURE_PRECISION` of its closures right, and the voice makes none) or, without one,
    at the threshold of the best F1: of the ``closures`` captured, the share met (``recall``), and
    the share of the voice's closures that met one (``precision``)."""

    r: dict[str, float]
    closure_threshold: float | None
    closures: int
    recall: float
    precision: float


def closures_met(real: list[np.ndarray], voice: list[np.ndarray], tolerance: int) -> tuple[int, int, int, int]:
    """(captured closures met, captured closures, the voice's closures that met one, the voice's
    closures), over takes: per take the closure frames (K,) of the capture and of the voice,
    met within ``tolerance`` frames."""
    met = right = 0
    for r, v in zip(real, voice):
        m, k = articulation.match_closures(r, v, tolerance)
        met, right = met + m, right + k
    return met, sum(len(r) for r in real), right, sum(len(v) for v in voice)


def held_out_takes(data: PerformerTakes, prior: ArticulationModel | None = None,
                   prior_strength: float = 0.0) -> HeldOutTakes | None:
    """What the fit of :func:`fit_performer` does on takes it did not see (module docstring), or
    None with fewer than two takes."""
    if len(data.takes) < 2:
        return None
    models = articulation.fit_leaving_each_out(data.takes, data.names, prior=prior, prior_strength=prior_strength)
    predicted = [articulation.predict_raw(model, take.raw, take.times_s) for model, take in zip(models, data.takes)]
    r = pearson_per_target(predicted, [t.targets for t in data.takes], data.names)
    o, c = data.names.index("opening"), data.names.index("closure")
    real = []
    for t in data.takes:  # a capture's gaps bridged, so that a gap is no closure
        x, known = t.targets[:, o], np.isfinite(t.targets[:, o])
        real.append(articulation.closure_frames_of(np.interp(np.arange(len(x)), np.flatnonzero(known), x[known])
                                                   if known.any() else np.zeros(0)))
    rows = []  # (threshold, recall, precision, captured closures)
    for threshold in CLOSURE_THRESHOLDS:
        met, real_count, right, count = closures_met(
            real, [closure_frames(p[:, c], FIT_FPS, threshold) for p in predicted], CLOSURE_TOLERANCE)
        rows.append((threshold, met / max(real_count, 1), right / max(count, 1), real_count))

    def f1(row):
        return 2 * row[1] * row[2] / (row[1] + row[2]) if row[1] + row[2] > 0 else 0.0

    right_enough = [row for row in rows if row[2] >= MIN_CLOSURE_PRECISION]
    threshold, recall, precision, real_count = max(right_enough or rows, key=f1)  # the lowest threshold on a tie
    return HeldOutTakes(r, threshold if right_enough else None, real_count, recall, precision)
