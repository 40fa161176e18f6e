"""``facesynth suggest``: motion nodes to constrain a phone to (paper VI-A).

For the phone sounding at time ``T_c`` (relative time ``t_c`` inside it), every node of
that phone is a candidate. For each the command reports its *time-correct* frame (the
node's frame at relative time ``t_c``, interpolated), whether it is *context-correct*
(same triphone context as the input phone), and the best total cost (Eq. 4) of the whole
utterance when the phone is constrained to it: ``phi_c(j) + psi_c(j) - obs_c(j)``, where
``phi`` is the forward DP of Algorithm 1 and ``psi`` the same DP run backwards (transposed
TC, reversed steps). Best first.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..config import IngestSettings, SynthesizeSettings
from ..errors import InputError
from ..opencl import use_opencl
from ..phonemes import PAU
from ..model.motiondb import MotionDatabase
from ..search.costs import step_costs
from ..search.dp import dp_numpy, dp_opencl
from ..search.synthesis import prepare


@dataclass
class Suggestion:
    """A node to constrain the phone at the asked time to: its emotion, take, triphone context
    (and whether it matches), the time-correct frame (fractional database frame), the best total
    cost of the utterance through it and that cost above the unconstrained optimum.
    """

    node: int
    emotion: str
    take: str
    context: str
    context_correct: bool
    time_correct_frame: float   # frame index in the database (fractional: interpolated)
    cost: float                 # best total cost of the utterance through this node
    extra: float                # cost above the unconstrained optimum


def suggest(db_path: Path, phones_path: Path, at_s: float, settings: SynthesizeSettings, ingest_settings: IngestSettings,
            emotions_path: Path | None = None, constraints_path: Path | None = None) -> tuple[dict, list[Suggestion]]:
    """Nodes of the phone at ``at_s`` (s) ranked by the best total cost through them (forward and
    backward DP, paper VI-A); returns the phone's description and the ranked suggestions.
    """
    db = MotionDatabase.read(db_path)
    utt, constraints = prepare(db, phones_path, emotions_path, constraints_path, ingest_settings)
    c = utt.index_at(at_s)
    if c is None:
        raise InputError(f"{phones_path}: {at_s:.3f} s is outside the utterance (0 to {utt.ends[-1]:.3f} s).")
    phone = utt.phones[c]
    if phone == PAU:
        raise InputError(f"{phones_path}: {at_s:.3f} s falls in a pause, whose frames are interpolated; pick a time in a spoken phone.")
    candidates = np.nonzero(np.array(db.nodes.phone) == phone)[0]
    if len(candidates) == 0:
        raise InputError(f"{db_path}: the database has no node of /{phone}/ to suggest.")
    rel = (at_s - utt.starts[c]) / (utt.ends[c] - utt.starts[c])
    prev_p = utt.phones[c - 1] if c > 0 else PAU
    next_p = utt.phones[c + 1] if c + 1 < len(utt) else PAU
    tc = db.transition(settings)
    obs = step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, constraints, settings).total
    run = dp_opencl if use_opencl(settings.use_opencl) else dp_numpy
    forward = run(tc, obs)
    backward = run(np.ascontiguousarray(tc.T), obs[::-1].copy())
    through = forward.phi[c].astype(np.float64) + backward.phi[len(utt) - 1 - c] - obs[c]
    out = []
    for j in candidates:
        start, count = int(db.nodes.frame_start[j]), int(db.nodes.frame_count[j])
        ctx = f"{db.nodes.prev_phone[j]}-{phone}+{db.nodes.next_phone[j]}"
        out.append(Suggestion(int(j), db.nodes.emotion[j], db.takes.name[db.nodes.take[j]], ctx,
                              db.nodes.prev_phone[j] == prev_p and db.nodes.next_phone[j] == next_p,
                              start + rel * (count - 1), float(through[j]), max(0.0, float(through[j] - forward.cost))))
    out.sort(key=lambda s: (s.cost, s.node))
    info = {"phone": phone, "index": c, "relative_time": rel, "context": f"{prev_p}-{phone}+{next_p}",
            "optimum": forward.cost, "optimal_node": int(forward.path[c])}
    return info, out


def table(rows: list[Suggestion], top: int, context_only: bool) -> list[str]:
    """Tab-separated lines of ``facesynth suggest``: a header, then the best ``top`` rows
    (only context-correct ones with ``context_only``)."""
    lines = ["rank\tnode\temotion\ttake\tcontext\tcontext_correct\ttime_correct_frame\tcost\textra_cost"]
    shown = [r for r in rows if r.context_correct or not context_only][:top]
    for rank, r in enumerate(shown, 1):
        lines.append(f"{rank}\t{r.node}\t{r.emotion}\t{r.take}\t{r.context}\t{'yes' if r.context_correct else 'no'}\t"
                     f"{r.time_correct_frame:.2f}\t{r.cost:.2f}\t{r.extra:.2f}")
    return lines
