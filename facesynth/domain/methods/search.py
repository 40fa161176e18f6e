"""The search members, ``dp`` and ``greedy``: the motion-node database searched for the utterance
(paper VI, Algorithm 1; Cao et al.'s greedy search), the path concatenated, smoothed and
back-projected (VII-B). The search itself is :mod:`facesynth.domain.search`; these classes put it in
the family: the database is the source, nothing is fitted, the transition costs are the work
shared between utterances (:meth:`SearchMethod.prepare`). Both stream (:class:`SearchLive`: a
fixed-lag DP over a sliding window, or the greedy tiling of the uncommitted phones).
"""

from __future__ import annotations

import dataclasses
import threading

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.opencl import use_opencl
from facesynth.base.phonemes import PAU
from facesynth.domain.search.costs import step_costs
from facesynth.domain.search.dp import dp_numpy
from facesynth.domain.search.greedy import Greedy, anime_graph, cluster_graph, motion_features
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.synthesis import as_motion, render_path, synthesize, unseen_phones
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motiondb import MotionDatabase

from . import MethodSettings, Synthesis, SynthesisSummary
from .live import LiveSource, LiveStepper, Track, wrong_source
from .steps import DatabaseMethod


def memory_estimate(nodes: int, phones: int, dp: str = "dense", feature_bytes: int = 0) -> float:
    """Bytes the search needs. The dense DP (``dp = "dense"``): the (N, N) float32 transition
    matrix (twice, while it is assembled panel-major) and per phone a row of float64 costs and
    int32 backpointers. The pruned DP: the per-node transition features (``feature_bytes``)
    three times (read, on the device, in the device's layout) and per phone and node the
    float32 observation costs, accumulated costs and their step's work arrays (12 bytes)."""
    if dp == "pruned":
        return 3.0 * feature_bytes + 12.0 * phones * nodes
    return 2.0 * 4 * nodes * nodes + 12.0 * phones * nodes


class SearchMethod(DatabaseMethod):
    """A search of the motion database with ``search`` (``synthesize.search`` is set to it)."""

    search = "dp"

    def settings_of(self, settings: MethodSettings):
        """The ``[synthesize]`` section with this member's search."""
        s = settings.synthesize
        return s if s.search == self.search else dataclasses.replace(s, search=self.search)

    def prepare(self, source, settings: MethodSettings):
        """The transition costs of the database for these settings (on the device the settings choose)."""
        s = self.settings_of(settings)
        return transition_costs(source, s, use_opencl(s.use_opencl))

    def memory_estimate(self, source, utt, settings: MethodSettings) -> float:
        s = self.settings_of(settings)
        return memory_estimate(len(source.nodes), len(utt), s.dp, source.feature_bytes())

    def memory_what(self, source, utt) -> str:
        return f"the search over {len(source.nodes)} motion nodes for {len(utt)} phones"

    def synthesize(self, source, utt, settings: MethodSettings, constraints=None, *, prepared=None,
                   where: str = "the utterance") -> Synthesis:
        """Search ``source`` (a MotionDatabase) for ``utt``; the summary holds the path's ``cost``
        (Eq. 4), ``joins`` (non-captured), the ``device``, the ``unseen`` phones and the seconds of
        each phase (:func:`facesynth.domain.search.synthesis.synthesize`)."""
        self.refuse_constraints(constraints)
        s = self.settings_of(settings)
        res = synthesize(source, utt, dict(constraints or {}), s, tc=prepared)
        motion = as_motion(source, utt, res, s)
        return Synthesis(motion, SynthesisSummary(len(utt), len(res.rendered.markers), unseen_phones(utt, source, s.phone_match),
                                                  cost=res.cost, joins=res.rendered.non_captured_joins,
                                                  device=res.device, phases=res.timings.phases()))

    def live(self, source, settings: MethodSettings) -> "SearchLive":
        """This search on ``source`` (a MotionDatabase), decided with a bounded look-ahead."""
        return SearchLive(source, settings.synthesize, self.search)


class DpMethod(SearchMethod):
    name = "dp"
    takes_constraints = True
    tunable = True
    search = "dp"


class GreedyMethod(SearchMethod):
    name = "greedy"
    tunable = True
    search = "greedy"


class SearchLive(LiveSource):
    """A search member live (``search``: ``dp`` or ``greedy``) on a motion database."""

    what = "the motion database"

    def __init__(self, db, synth: SynthesizeSettings, search: str):
        if not isinstance(db, MotionDatabase):
            raise wrong_source(search, "a motion database", "`facesynth build-db` (or `prune`)")
        self.db, self.synth, self.search = db, synth, search
        self.fps = float(synth.output_fps)
        self.marker_names, self.reference = list(db.marker_names), db.reference
        self.grid_fps = float(db.fps)  # the capture grid, where the path is rendered
        self.tc = transition_costs(db, synth, False)
        self._dense: np.ndarray | None = None
        self._dense_lock = threading.Lock()
        self.emotions = sorted(set(db.nodes.emotion))
        self.greedy: Greedy | None = None
        if search == "greedy":
            if synth.greedy_clusters > 0:
                features = motion_features(db.coeffs, db.nodes.frame_start, db.nodes.frame_count)
                graph = cluster_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc, features, synth.greedy_clusters)
            else:
                graph = anime_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc)
            self.greedy = Greedy(graph, db.nodes.viseme, db.nodes.emotion, self.dense, synth.alpha6 * synth.pnt)
        rest_coeffs = db.model.project(db.reference[None])[0]
        #: (M, 3) mm: the rest pose as the PCA model reconstructs it (where silences settle)
        self.rest_markers = db.model.reconstruct(rest_coeffs[None])[0].astype(np.float32)

    @property
    def dense(self) -> np.ndarray:
        """(N, N) float32 transition costs between the database's N nodes, read-only (streams on
        several threads share it): computed at first use (seconds for a database of thousands of
        nodes), which a stream whose frames come from its voice alone never makes, or by
        :meth:`warm`."""
        if self._dense is None:
            with self._dense_lock:
                if self._dense is None:
                    self._dense = np.ascontiguousarray(self.tc.dense(), np.float32)
        return self._dense

    def warm(self) -> None:
        """Compute the transition costs now, so that no stream waits for them."""
        _ = self.dense

    @property
    def warmed(self) -> bool:
        return self._dense is not None

    def emotion_markers(self, emotion: str) -> np.ndarray:
        """The mean of the database's captured frames of ``emotion``."""
        db = self.db
        assert db is not None
        frames = [np.arange(a, a + n) for a, n, e in zip(db.nodes.frame_start, db.nodes.frame_count, db.nodes.emotion)
                  if e == emotion]
        if not frames:
            return self.rest_markers
        mean = np.asarray(db.coeffs)[np.concatenate(frames)].mean(0)
        return db.model.reconstruct(mean[None])[0].astype(np.float32)

    def stepper(self) -> LiveStepper:
        return _SearchStepper(self)


class _SearchStepper(LiveStepper):
    def __init__(self, live: SearchLive):
        self.live = live

    def decide(self, track: Track, upto: int) -> list[int]:
        live, c = self.live, len(track.committed)
        db = live.db
        assert db is not None
        first = max(0, c - 1)
        phones, emotions, ipa = track.phones[first:], track.emotions[first:], track.ipa[first:]
        if live.greedy is not None:
            path = _greedy(live.greedy, phones, emotions, track.committed[-1] if c else -1, pinned=c > 0)
        else:
            constraints = {0: track.committed[-1]} if c else {}
            steps = step_costs(phones, emotions, db.nodes.phone, db.nodes.emotion, constraints, live.synth, ipa,
                               db.nodes.ipa)
            path = dp_numpy(live.dense, steps.total).path
        offset = c - first
        return [int(n) for n in path[offset: offset + upto - c]]

    def final_limit(self, track: Track) -> int:
        """A committed pause at ``c - 1`` is interpolated toward the next step's first frame, so
        frames stop at its first; otherwise at step c's first, less the blend's reach
        (``smoothing_half_window`` frames) when step c is spoken or not yet known (joins next to a
        pause are not smoothed)."""
        c, grid = len(track.committed), self.live.grid_fps
        if track.phones[c - 1] == PAU:
            return int(round(track.starts[c - 1] * grid))
        limit = int(round(track.ends[c - 1] * grid))
        if c == len(track.phones) or track.phones[c] != PAU:
            limit -= self.live.synth.smoothing_half_window
        return limit

    def render(self, track: Track, first: int, stop: int) -> np.ndarray:
        """Renders the committed steps from two spoken phones before the step of frame ``first``."""
        db, fps = self.live.db, self.live.fps
        assert db is not None
        c = len(track.committed)
        k = max(0, int(np.searchsorted(np.array(track.starts[:c]), first / fps, side="right")) - 1)
        spoken = 0
        while k > 0 and spoken < 2:
            k -= 1
            if track.phones[k] != PAU:
                spoken += 1
        while k > 0 and track.phones[k] == PAU:
            k -= 1
        # shift the window to start on a whole capture frame, so its frame grid is batch's grid
        ratio = db.fps / fps
        if abs(ratio - round(ratio)) < 1e-9:  # a whole number of output frames: the grids agree
            shift_frames = int(round(track.starts[k] * db.fps)) // int(round(ratio)) * int(round(ratio))
        else:
            shift_frames = 0  # no common grid: render from the start
        shift = shift_frames / db.fps
        utt = Utterance(track.phones[k:c], np.array(track.starts[k:c]) - shift, np.array(track.ends[k:c]) - shift,
                        track.emotions[k:c])
        out = render_path(db, utt, np.array(track.committed[k:c]), self.live.synth).markers
        base = int(round(shift * fps))
        lo, hi = first - base, stop - base
        if lo < 0 or hi > len(out):
            raise AssertionError(f"render window [{lo}, {hi}) outside its {len(out)} frames")  # a bug, not input
        return out[lo:hi].astype(np.float32)


def _greedy(greedy: Greedy, phones: list[str], emotions: list[str], before: int, pinned: bool) -> np.ndarray:
    """Greedy tiling of ``phones`` by ``greedy`` (the first pinned to ``before`` when ``pinned``)."""
    start = 1 if pinned else 0
    nodes = np.full(len(phones), -1, np.int64)
    if pinned:
        nodes[0] = before
    t = start
    while t < len(phones):
        if phones[t] == PAU:  # a pause's frames are regenerated: any node will do; keep the last
            nodes[t] = before if before >= 0 else 0
            t += 1
            continue
        end = t
        while end < len(phones) and phones[end] != PAU:
            end += 1
        animes = greedy.tile(phones[t:end], emotions[t:end], before)
        nodes[t:end] = greedy.g.node[animes]
        before = int(nodes[end - 1])
        t = end
    return nodes
