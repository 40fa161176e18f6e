"""``facesynth suggest``: motion nodes to constrain a phone to (paper VI-A).

For the phone sounding at time ``T_c`` (relative time ``t_c`` inside it), every node of
that phone is a candidate. For each the command reports its *time-correct* frame (the
node's frame at relative time ``t_c``, rounded to the nearest captured frame and given as
a frame index inside the node's take, 0 at the take's first frame), whether it is
*context-correct* (the same triphone context ``prev-phone+next`` as the input phone, with
``pau`` at a silence or the utterance's ends, as the database stores it), and the best
total cost (Eq. 4) of the whole utterance when the phone is constrained to it:
``phi_c(j) + psi_c(j) - obs_c(j)``, where ``phi`` is the forward DP of Algorithm 1 and
``psi`` the same DP run backwards (transposed TC, reversed steps). Best first.
The definitions and the ranking live in :mod:`facesynth.domain.search.constraint_choice`,
which ``facesynth isomap page`` shares to highlight the same nodes on the phone's Isomap.

Context-correct nodes exist only where the input shares a triphone with a training
sentence; the sample corpus designs its sentences to cover new diphones, so a held-out
sentence shares few. The description returned with the suggestions lists the phones of the
utterance that have context-correct nodes, so a caller can point the user at them.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import IngestSettings, SynthesizeSettings
from facesynth.base.opencl import use_opencl
from facesynth.domain import methods
from facesynth.domain.methods import steps
from facesynth.domain.search import constraint_choice
from facesynth.domain.search.constraint_choice import Suggestion, Suggestions
from facesynth.model.motiondb import MotionDatabase

HEADER = "rank\tnode\temotion\ttake\tcontext\tcontext_correct\ttime_correct_take_frame\tcost\textra_cost"


@dataclass(frozen=True)
class SuggestResult:
    """What ``facesynth suggest`` found.

    suggestions: the phone at the asked time, its nodes ranked best first and where the
        utterance has context-correct nodes.
    """

    suggestions: Suggestions


def suggest(db_path: Path, phones_path: Path, at_s: float, settings: SynthesizeSettings, ingest_settings: IngestSettings,
            emotions_path: Path | None = None, constraints_path: Path | None = None) -> SuggestResult:
    """Nodes of the phone at ``at_s`` (s) ranked by the best total cost through them (forward and
    backward DP, paper VI-A), with the phone's description."""
    db = MotionDatabase.read(db_path)
    utt = steps.read_utterance(ingest_settings, phones_path=phones_path, emotions_path=emotions_path).utterance
    constraints = steps.constraints_for(methods.get("dp"), db, constraints_path, utt)
    return SuggestResult(constraint_choice.suggest(db, utt, at_s, constraints, settings, use_opencl(settings.use_opencl),
                                                   where=str(phones_path), db_where=str(db_path)))


def shown(rows: list[Suggestion], top: int, context_only: bool) -> list[Suggestion]:
    """The rows ``facesynth suggest`` lists: the best ``top`` (only context-correct ones with
    ``context_only``)."""
    return [r for r in rows if r.context_correct or not context_only][:top]


def table(rows: list[Suggestion], top: int, context_only: bool) -> list[str]:
    """Tab-separated lines of ``facesynth suggest``: a header, then the best ``top`` rows
    (only context-correct ones with ``context_only``); the first row after the header is
    the best."""
    lines = [HEADER]
    for rank, r in enumerate(shown(rows, top, context_only), 1):
        lines.append(f"{rank}\t{r.node}\t{r.emotion}\t{r.take}\t{r.context}\t{'yes' if r.context_correct else 'no'}\t"
                     f"{r.time_correct_frame}\t{r.cost:.2f}\t{r.extra:.2f}")
    return lines


def elsewhere(found: Suggestions, limit: int = 5) -> str:
    """Where the utterance has context-correct nodes, as a phrase for messages."""
    steps = found.context_correct_at
    if not steps:
        return "no phone of this utterance shares its triphone context with a database node"
    listed = ", ".join(f"{s.time_s:g} s /{s.phone}/ ({s.context})" for s in steps[:limit])
    more = f" and {len(steps) - limit} more" if len(steps) > limit else ""
    return f"phones with context-correct nodes: {listed}{more}"


def no_context_message(found: Suggestions, at_s: float) -> str:
    """The sentence (without its full stop) saying that no node has the asked phone's triphone context."""
    return (f"no node of /{found.phone}/ has the context {found.context} of the phone at {at_s:g} s; "
            f"{elsewhere(found)}")



def use_line(at_s: float, best: Suggestion, constraints_path: Path | None) -> str:
    """The shell line that adds the best suggestion to a constraints file (``TIMEs NODE``)."""
    target = constraints_path if constraints_path is not None else "constraints.txt"
    redirect = ">>" if constraints_path is not None else ">"
    return f'echo "{at_s:g}s {best.node}" {redirect} {target}'
