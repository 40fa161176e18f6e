"""Synthesis (paper VI and VII-B): search the motion-node database for an utterance and turn
the chosen path into marker motion.

The constrained DP of Algorithm 1 (or Cao et al.'s greedy search) picks one node per input
phone minimizing Eq. 4; the path is concatenated, smoothed, time-warped to the input timing
at the capture rate, back-projected with Eq. 11 and down-sampled to the output rate. Every
output frame keeps its provenance (node, take, source frame).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.errors import UsageError
from facesynth.base.ipa import festival_phone_ipa, nearest_phone, phone_distance
from facesynth.base.jit import worth
from facesynth.base.opencl import device_record, use_opencl
from facesynth.base.phonemes import PAU, viseme
from facesynth.domain.geometry.rotations import follow_sources
from facesynth.domain.postprocess.cao import blend_jumps, learned_cutoffs, lowpass
from facesynth.domain.postprocess.concatenation import Concatenated, concatenate, downsample
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motion import Motion, Provenance, SearchPath
from facesynth.model.motiondb import MotionDatabase, Nodes

from .costs import StepCosts, path_terms, step_costs
from .dp import DpResult, OpenCLDp, dp_numpy
from .dp_numba import dp_numba
from .greedy import Greedy, anime_graph, cluster_graph, motion_features
from .pairs import transition_costs
from .pruned import dp_pruned


def unseen_phones(utt: Utterance, db: MotionDatabase, phone_match: str = "viseme") -> dict[str, str]:
    """Input phones with no node, and how the search will cover them. Under ``phone_match``
    (``synthesize.phone_match``) ``unseen``, a phone pronounced in another language
    (:attr:`Utterance.ipa`; under ``features`` every phone) is named by its IPA when no node's
    phone has its features, covered by the nodes nearest it in features."""
    have = set(db.nodes.phone)
    have_vis = {viseme(p) for p in have}
    node_ipa = set(db.nodes.ipa or ()) - {""}
    if db.nodes.ipa is None or not all(db.nodes.ipa):
        node_ipa |= {festival_phone_ipa(p) for p in have}
    out: dict[str, str] = {}
    for t, p in enumerate(utt.phones):
        q = utt.ipa[t] if utt.ipa is not None else ""
        if p == PAU:
            continue
        if phone_match != "viseme" and (q or phone_match == "features"):
            ipa = q or festival_phone_ipa(p)
            if (q or p) not in out and node_ipa and all(phone_distance(ipa, r) > 0 for r in node_ipa):
                nearest = nearest_phone(ipa, sorted(node_ipa), ipa_of=str)
                out[q or p] = f"the nodes nearest it in articulatory features (/{nearest}/ first; synthesize.phone_match)"
            continue
        if p in have or p in out:
            continue
        out[p] = "nodes of the same viseme (Table II rule 2)" if viseme(p) in have_vis else "any node (Table II rule 3)"
    return out


def greedy_search(db: MotionDatabase, tc, utt: Utterance, steps: StepCosts, settings: SynthesizeSettings):
    """Cao et al.'s GreedyMatching; returns a DpResult-like record with the Eq. 4 cost of its path."""
    if settings.greedy_clusters > 0:
        features = motion_features(db.coeffs, db.nodes.frame_start, db.nodes.frame_count)
        graph = cluster_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc, features, settings.greedy_clusters)
    else:
        graph = anime_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc)
    result = Greedy(graph, db.nodes.viseme, db.nodes.emotion, tc, settings.alpha6 * settings.pnt).search(utt.phones, utt.emotions)
    terms = path_terms(result.path, tc, steps)
    cost = float(sum(v.astype(np.float64).sum() for v in terms.values()))
    graph_kind = f"{settings.greedy_clusters} clusters" if settings.greedy_clusters else "unclustered"
    return DpResult(cost, result.path, np.zeros((0, 0), np.float32)), (f"greedy ({graph_kind})", "the greedy method")


def search(tc, steps: StepCosts, settings: SynthesizeSettings, *, while_running: Callable[[], None] | None = None,
           timings: dict[str, float] | None = None):
    """Run the DP over ``tc`` (a :class:`~facesynth.domain.search.pairs.TransitionCosts`); returns
    (DpResult, (device, why that device), fraction of pair costs computed). ``synthesize.dp``
    picks the exact pruned DP or the dense reference (the full matrix assembled, then
    Algorithm 1 on it); both give the same path and cost. ``while_running`` is host work to
    do while a dense OpenCL search runs; ``timings`` gets ``opencl_setup_s`` (context, kernel,
    buffers, and for the dense DP the matrix)."""
    if settings.dp == "pruned":
        if tc.opencl:
            t0 = time.perf_counter()
            tc.device  # noqa: B018 (the property builds the kernels and uploads the features)
            if timings is not None:
                timings["opencl_setup_s"] = time.perf_counter() - t0
        # The host work overlaps the search on a thread: the search waits on the device and on
        # NumPy, both of which release the GIL.
        helper = threading.Thread(target=while_running) if while_running is not None else None
        if helper is not None:
            helper.start()
        try:
            result, stats = dp_pruned(tc, steps.total)
        finally:
            if helper is not None:
                helper.join()
        return result, device_record(settings.use_opencl), stats.fraction
    if not tc.opencl:
        dense, obs = tc.dense(), steps.total
        if not worth(1e-9 * dense.size * len(obs)):  # NumPy's time per min-plus term here
            return dp_numpy(dense, obs), device_record(settings.use_opencl), 1.0

        return dp_numba(dense, obs), device_record(settings.use_opencl), 1.0
    t0 = time.perf_counter()
    runner = OpenCLDp(tc.panels())
    if timings is not None:
        timings["opencl_setup_s"] = time.perf_counter() - t0
    return runner.run(steps.total, while_running), device_record(settings.use_opencl), 1.0


def table_iv_weight(settings: SynthesizeSettings):
    """The Table IV smoothing weight of a phone (high, low or intermediate) under ``settings``."""
    def weight(phone: str) -> float:
        if phone in settings.high_phones:
            return settings.weight_high
        if phone in settings.low_phones:
            return settings.weight_low
        return settings.weight_intermediate
    return weight


def captured_runs(nodes: Nodes) -> list[slice]:
    """Frames of each maximal run of captured-linked nodes (no pause, no pruned node inside)."""
    runs = []
    for k in np.nonzero(nodes.pre < 0)[0]:
        last = k
        while nodes.suc[last] >= 0:
            last = nodes.suc[last]
        runs.append(slice(int(nodes.frame_start[k]), int(nodes.frame_start[last] + nodes.frame_count[last])))
    return runs


def cao_joins(db: MotionDatabase, path: np.ndarray, phones: list[str]):
    """Cao et al.'s blending across jumps and learned low-pass (``synthesize.postprocess = "cao"``)."""
    take_range = np.array([(db.takes.frames(t).start, db.takes.frames(t).stop) for t in db.nodes.take])

    def joins(out: np.ndarray, ranges) -> np.ndarray:
        changed = blend_jumps(out, ranges, path, phones, db.nodes.phone, db.nodes.frame_start, db.nodes.frame_count,
                              db.nodes.pre, take_range, db.coeffs)
        out[:] = lowpass(out, learned_cutoffs(db.coeffs, captured_runs(db.nodes), db.fps), db.fps)
        return changed
    return joins


@dataclass(frozen=True)
class RenderedPath:
    """A node path turned into motion (VII-B, :func:`render_path`).

    concatenated: the concatenated, smoothed coefficients at the capture rate ((F, K)) with each
        frame's node, source frame and input phone (-1 node and source frame where silence was
        regenerated).
    markers_capture: (F, M, 3) float32 markers in mm at the database's capture rate (Eq. 11).
    markers: (T, M, 3) float32 markers in mm at ``synthesize.output_fps``.
    non_captured_joins: joins between consecutive spoken phones whose nodes were not captured one
        after the other.
    take: (F,) int64 the take of each capture-rate frame's node, -1 for regenerated silence.
    head_rotation: (T, 3, 3) rotation matrices of the source frames' head motion, relative to their
        takes, at the output rate.
    head_translation: (T, 3) mm, the same head motion's translation, at the output rate.
    """

    concatenated: Concatenated
    markers_capture: np.ndarray
    markers: np.ndarray
    non_captured_joins: int
    take: np.ndarray
    head_rotation: np.ndarray
    head_translation: np.ndarray


@dataclass(frozen=True)
class SearchTimings:
    """Seconds spent in each phase of :func:`synthesize`.

    device_choice_s: choosing the device (the first time in a process).
    steps_s: the step costs (Eq. 5-10 per input phone).
    search_s: the search itself (without ``opencl_setup_s``).
    postprocess_s: concatenation, smoothing, Eq. 11 and down-sampling (:func:`render_path`).
    transition_s: the transition costs (reading the per-node features); None when they were given.
    opencl_setup_s: the OpenCL set-up (context, kernel, buffers; for the dense DP the matrix);
        None when the search ran without it.
    """

    device_choice_s: float
    steps_s: float
    search_s: float
    postprocess_s: float
    transition_s: float | None = None
    opencl_setup_s: float | None = None

    def phases(self) -> dict[str, float]:
        """The phases that ran, field name -> seconds, in the order they ran."""
        order = ("device_choice_s", "transition_s", "steps_s", "opencl_setup_s", "search_s", "postprocess_s")
        return {name: getattr(self, name) for name in order if getattr(self, name) is not None}


@dataclass(frozen=True)
class SearchSynthesis:
    """What :func:`synthesize` made: the chosen path and its motion.

    path: (U,) int64 the motion node chosen for each input phone.
    cost: the path's Eq. 4 cost (COST* of Algorithm 1).
    terms: cost term ("tc", "oc", "emp", "block") -> (U,) float32 its value at each step
        (:func:`~facesynth.domain.search.costs.path_terms`; the ``path/terms`` the motion stores).
    device: where the search ran; device_reason: why that device.
    pairs_fraction: the fraction of the dense DP's pair costs the search computed (None for the
        greedy search).
    timings: seconds of each phase.
    rendered: the path turned into motion (:func:`render_path`).
    """

    path: np.ndarray
    cost: float
    terms: dict[str, np.ndarray]
    device: str
    device_reason: str
    pairs_fraction: float | None
    timings: SearchTimings
    rendered: RenderedPath


def synthesize(db: MotionDatabase, utt: Utterance, constraints: dict[int, int], settings: SynthesizeSettings,
               tc=None) -> SearchSynthesis:
    """Search and post-process: everything ``motion.h5`` stores, and the seconds of each phase
    (:class:`SearchTimings`). ``tc`` is a :class:`~facesynth.domain.search.pairs.TransitionCosts`
    (made from ``db`` when None)."""
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    on_device = use_opencl(settings.use_opencl)
    timings["device_choice_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    if tc is None:
        tc = transition_costs(db, settings, on_device)
        timings["transition_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    steps = step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, constraints, settings, utt.ipa,
                       db.nodes.ipa)
    timings["steps_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    if settings.search == "greedy":
        if constraints:
            raise UsageError("motion-node constraints need the DP search (Eq. 10); drop --constraints or use --search dp.")
        result, device = greedy_search(db, tc, utt, steps, settings)
        fraction = None
    else:
        result, device, fraction = search(tc, steps, settings, timings=timings)
    timings["search_s"] = time.perf_counter() - t0 - timings.get("opencl_setup_s", 0.0)
    path = result.path
    for t, node in constraints.items():  # Eq. 10 guarantees this; a failure is a bug
        assert path[t] == node, f"constraint at step {t} not met"
    t0 = time.perf_counter()
    terms = path_terms(path, tc, steps)
    rendered = render_path(db, utt, path, settings)
    timings["postprocess_s"] = time.perf_counter() - t0
    return SearchSynthesis(path, result.cost, terms, device[0], device[1], fraction, SearchTimings(**timings), rendered)


def render_path(db: MotionDatabase, utt: Utterance, path: np.ndarray, settings: SynthesizeSettings) -> RenderedPath:
    """VII-B for a given node path: concatenate, smooth, regenerate pauses, Eq. 11, down-sample."""
    rest = db.model.project(db.reference[None])[0]
    cat = concatenate(
        path, utt.phones, utt.starts, utt.ends, db.nodes.frame_start, db.nodes.frame_count, db.nodes.pre,
        db.nodes.phone, db.coeffs, rest, db.fps, half_window=settings.smoothing_half_window,
        lam=settings.smoothing_lambda, weight_of=table_iv_weight(settings), interpolation=settings.silence_interpolation,
        joins=cao_joins(db, path, utt.phones) if settings.postprocess == "cao" else None, method=settings.join_smoothing,
        pinned=frozenset(settings.pinned_phones), rest_after=int(round(settings.pause_rest_min_s * db.fps)),
        rest_ramp=max(1, int(round(settings.pause_rest_ramp_s * db.fps))),
    )
    markers = db.model.reconstruct(cat.coeffs)
    joins = sum(1 for t in range(len(path) - 1)
                if utt.phones[t] != PAU and utt.phones[t + 1] != PAU and db.nodes.pre[path[t + 1]] != path[t])
    take = np.where(cat.node >= 0, db.nodes.take[np.maximum(cat.node, 0)], -1)
    # the head motion of the source frames only, relative to their takes
    used = np.unique(cat.source_frame[cat.source_frame >= 0])
    sources = np.where(cat.source_frame >= 0, np.searchsorted(used, cat.source_frame), -1)
    head_r, head_t = follow_sources(sources, *db.head_relative(used))
    return RenderedPath(cat, markers, downsample(markers, db.fps, settings.output_fps), joins, take,
                        downsample(head_r, db.fps, settings.output_fps), downsample(head_t, db.fps, settings.output_fps))


def as_motion(db: MotionDatabase, utt: Utterance, res: SearchSynthesis, settings: SynthesizeSettings) -> Motion:
    """The ``motion`` artifact's contents for a :func:`synthesize` result."""
    out = res.rendered
    cat = out.concatenated
    path = SearchPath(res.path, list(utt.phones), list(utt.emotions), [db.nodes.phone[j] for j in res.path],
                      [db.nodes.emotion[j] for j in res.path], utt.starts, utt.ends, res.terms, res.cost,
                      out.non_captured_joins, settings.search, res.device, res.device_reason)
    provenance = Provenance(cat.node, out.take, db.takes.name, cat.source_frame, cat.step, cat.smoothed, db.fps)
    return Motion(out.markers, settings.output_fps, out.markers_capture, db.fps, db.marker_names, db.reference,
                  out.head_rotation, out.head_translation, cat.coeffs, path, provenance)
