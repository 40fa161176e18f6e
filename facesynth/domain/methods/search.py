"""The search members, ``dp`` and ``greedy``: the motion-node database searched for the utterance
(paper VI, Algorithm 1; Cao et al.'s greedy search), the path concatenated, smoothed and
back-projected (VII-B). The search itself is :mod:`facesynth.domain.search`; these classes put it in
the family: the database is the source, nothing is fitted, the transition costs are the work
shared between utterances (:meth:`SearchMethod.prepare`).
"""

from __future__ import annotations

import dataclasses

from facesynth.base.opencl import use_opencl
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.synthesis import as_motion, synthesize, unseen_phones

from . import MethodSettings, Synthesis, SynthesisSummary
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


class DpMethod(SearchMethod):
    name = "dp"
    takes_constraints = True
    tunable = True
    search = "dp"


class GreedyMethod(SearchMethod):
    name = "greedy"
    tunable = True
    search = "greedy"
