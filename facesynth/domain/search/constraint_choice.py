"""Where a motion-node constraint can go (paper VI-A): the definitions that
``facesynth suggest`` lists and the Isomap constraint page highlights.

For a *constrained time* ``T_c`` inside the spoken phone ``c`` of an utterance, its *relative
time* is ``t_c = (T_c - start_c) / (end_c - start_c)`` in [0, 1]. Every node of that phone
is a candidate; its *time-correct* frame is the node's frame at relative time ``t_c``,
rounded to the nearest captured frame (``floor(t_c * (count - 1) + 0.5)`` frames after the
node's first). A node is *context-correct* when it has the input phone's triphone context
``prev-phone+next`` (``pau`` at a silence or the utterance's ends, as the database stores it).

:func:`suggest` ranks the candidates by the best total cost (Eq. 4) of the whole utterance when
the phone is constrained to each: ``phi_c(j) + psi_c(j) - obs_c(j)``, where ``phi`` is the
forward DP of Algorithm 1 and ``psi`` the same DP run backwards (transposed TC, reversed steps),
both pruned and exact, without an N x N matrix.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.search.costs import step_costs
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.pruned import backward_pruned, dp_pruned
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motiondb import MotionDatabase, Nodes


def triphone(phones: list[str], c: int) -> tuple[str, str]:
    """The previous and next phone of step ``c`` of an utterance (``pau`` at its ends)."""
    return (phones[c - 1] if c > 0 else PAU), (phones[c + 1] if c + 1 < len(phones) else PAU)


def spoken_step_at(utt: Utterance, at_s: float, where: str) -> int:
    """The step of the spoken phone sounding at ``at_s`` (s); an InputError naming ``where``
    (the phones file) when the time lies outside the utterance or in a pause."""
    c = utt.index_at(at_s)
    if c is None:
        raise InputError(f"{where}: {at_s:.3f} s is outside the utterance (0 to {utt.ends[-1]:.3f} s).")
    if utt.phones[c] == PAU:
        raise InputError(f"{where}: {at_s:.3f} s falls in a pause, whose frames are interpolated; pick a time in a spoken phone.")
    return c


def relative_time(utt: Utterance, c: int, at_s: float) -> float:
    """``t_c``: where ``at_s`` (s) lies inside step ``c``, 0 at its start, 1 at its end."""
    return float((at_s - utt.starts[c]) / (utt.ends[c] - utt.starts[c]))


def time_correct_offset(rel: float, count: np.ndarray | int) -> np.ndarray:
    """The time-correct frame of nodes of ``count`` frames at relative time ``rel``: frames
    after each node's first (int64, same shape as ``count``)."""
    return np.floor(rel * (np.asarray(count, np.int64) - 1) + 0.5).astype(np.int64)


def time_correct_take_frame(nodes: Nodes, take_frame_start: np.ndarray, node: int, rel: float) -> int:
    """The time-correct frame of ``node`` at relative time ``rel`` as a frame index inside the
    node's take (0 at the take's first frame); ``take_frame_start`` (takes,) int64 is each
    take's first global frame."""
    start = int(nodes.frame_start[node]) - int(take_frame_start[int(nodes.take[node])])
    return start + int(time_correct_offset(rel, int(nodes.frame_count[node])))


def context_correct(nodes: Nodes, phones: list[str], c: int) -> np.ndarray:
    """(N,) bool: the nodes of step ``c``'s phone with its triphone context."""
    prev_p, next_p = triphone(phones, c)
    return ((np.array(nodes.phone) == phones[c]) & (np.array(nodes.prev_phone) == prev_p)
            & (np.array(nodes.next_phone) == next_p))


def context_name(phones: list[str], c: int) -> str:
    """Step ``c``'s triphone context as ``prev-phone+next``."""
    prev_p, next_p = triphone(phones, c)
    return f"{prev_p}-{phones[c]}+{next_p}"


@dataclass(frozen=True)
class ContextStep:
    """A spoken phone of the utterance with at least one context-correct node: its ``index`` (step),
    ``phone``, triphone ``context`` ('prev-phone+next') and mid time ``time_s`` (s)."""

    index: int
    phone: str
    context: str
    time_s: float


def context_correct_steps(phones: list[str], starts: np.ndarray, ends: np.ndarray,
                          db_contexts: set[tuple[str, str, str]]) -> list[ContextStep]:
    """The spoken steps of an utterance that have at least one context-correct node."""
    out = []
    for c, phone in enumerate(phones):
        if phone == PAU:
            continue
        prev_p, next_p = triphone(phones, c)
        if (prev_p, phone, next_p) in db_contexts:
            out.append(ContextStep(c, phone, context_name(phones, c), round(0.5 * (float(starts[c]) + float(ends[c])), 3)))
    return out


@dataclass
class Suggestion:
    """A node to constrain the phone at the asked time to: its emotion, take, triphone context
    (and whether it matches), the time-correct frame (an integer frame index inside the
    node's take), the best total cost of the utterance through it and that cost above the
    unconstrained optimum.
    """

    node: int
    emotion: str
    take: str
    context: str
    context_correct: bool
    time_correct_frame: int     # frame index inside the node's take (0 = the take's first frame)
    cost: float                 # best total cost of the utterance through this node
    extra: float                # cost above the unconstrained optimum


@dataclass(frozen=True)
class Suggestions:
    """The nodes to constrain the phone at the asked time to (:func:`suggest`).

    index: the phone's step in the utterance.
    phone: the phone.
    relative_time: where the time falls within the phone, 0 (start) to 1 (end).
    context: its triphone context, 'prev-phone+next'.
    optimum: the cost of the unconstrained optimum (the DP's).
    optimal_node: the node the optimum uses at this step.
    context_correct_at: every spoken phone of the utterance that has context-correct nodes.
    rows: the phone's nodes ranked by the best total cost through them, best first.
    """

    index: int
    phone: str
    relative_time: float
    context: str
    optimum: float
    optimal_node: int
    context_correct_at: list[ContextStep]
    rows: list[Suggestion]


def suggest(db: MotionDatabase, utt: Utterance, at_s: float, constraints: dict[int, int], settings: SynthesizeSettings,
            opencl: bool, *, where: str, db_where: str) -> Suggestions:
    """The nodes of the spoken phone of ``utt`` at ``at_s`` (s) ranked by the best total cost of
    the utterance through them, best first (paper VI-A), with the phone's description;
    ``constraints`` (step -> node) hold elsewhere, the transition costs run on OpenCL with
    ``opencl``. ``where`` names the phones file and ``db_where`` the database in messages."""
    c = spoken_step_at(utt, at_s, where)
    phone = utt.phones[c]
    candidates = np.nonzero(np.array(db.nodes.phone) == phone)[0]
    if len(candidates) == 0:
        raise InputError(f"{db_where}: the database has no node of /{phone}/ to suggest.")
    rel = relative_time(utt, c, at_s)
    correct = context_correct(db.nodes, utt.phones, c)
    tc = transition_costs(db, settings, opencl)
    obs = step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, constraints, settings).total
    # The optimum, and every node's best cost up to step c and from step c on: the values the
    # dense DP forwards and backwards would give, computed exactly without an N x N matrix.
    forward, _ = dp_pruned(tc, obs)
    up_to, _ = dp_pruned(tc, obs[: c + 1], keep_last=True)
    from_here, _ = backward_pruned(tc, obs, c)
    through = up_to.phi[c].astype(np.float64) + from_here - obs[c]
    out = []
    for j in candidates:
        take = int(db.nodes.take[j])
        ctx = f"{db.nodes.prev_phone[j]}-{phone}+{db.nodes.next_phone[j]}"
        out.append(Suggestion(int(j), db.nodes.emotion[j], db.takes.name[take], ctx, bool(correct[j]),
                              time_correct_take_frame(db.nodes, db.takes.frame_start, int(j), rel),
                              float(through[j]), max(0.0, float(through[j] - forward.cost))))
    out.sort(key=lambda s: (s.cost, s.node))
    contexts = set(zip(db.nodes.prev_phone, db.nodes.phone, db.nodes.next_phone))
    return Suggestions(c, phone, rel, context_name(utt.phones, c), forward.cost, int(forward.path[c]),
                       context_correct_steps(utt.phones, utt.starts, utt.ends, contexts), out)
