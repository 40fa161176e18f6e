"""Where a motion-node constraint can go (paper VI-A): the definitions that
``facesynth suggest`` lists and the Isomap constraint page highlights.

For a *constrained time* ``T_c`` inside the spoken phone ``c`` of an utterance, its *relative
time* is ``t_c = (T_c - start_c) / (end_c - start_c)`` in [0, 1]. Every node of that phone
is a candidate; its *time-correct* frame is the node's frame at relative time ``t_c``,
rounded to the nearest captured frame (``floor(t_c * (count - 1) + 0.5)`` frames after the
node's first). A node is *context-correct* when it has the input phone's triphone context
``prev-phone+next`` (``pau`` at a silence or the utterance's ends, as the database stores it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motiondb import Nodes


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
