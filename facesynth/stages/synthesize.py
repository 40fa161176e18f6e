"""``facesynth synthesize``: expressive speech motion for an utterance by any member of the method
family (:mod:`facesynth.domain.methods`): by default the paper's DP search of the motion-node database
(paper VI and VII-B; the search and post-processing are :mod:`facesynth.domain.search.synthesis`), or
greedy, the mean pose, or a fitted model (``trajectory``: Huang et al. §5.4; ``coarticulation``:
Cohen-Massaro) read from its own artifact. The utterance, its emotions, the memory check and the
transcript-mismatch policy are the shared core's (:mod:`facesynth.domain.methods.steps`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import AlignSettings, IngestSettings, SynthesizeSettings
from facesynth.domain import methods
from facesynth.domain.methods import MethodSettings, SynthesisSummary, steps
from facesynth.domain.methods.search import memory_estimate as memory_estimate  # the DP's estimate, where it always was
from facesynth.model.artifacts import check_output, input_records_in_background
from facesynth.model.head_motion import HeadMotion


@dataclass(frozen=True)
class SynthesizeResult:
    """What ``facesynth synthesize`` made.

    method: the member of the method family that made it.
    summary: what the method reports about the motion
        (:class:`~facesynth.domain.methods.SynthesisSummary`: phones, frames, what the source
        had nothing of, the search's cost and joins, the trajectory method's energy, the
        method's warnings and the seconds of its phases).
    reading_warnings: what reading the utterance warned about (e.g. a transcript that does not
        match the speech).
    load_s, hash_wait_s, write_s: seconds reading the source, waiting for the inputs' sha256
        (hashed on another thread meanwhile) and writing.
    """

    method: str
    summary: SynthesisSummary
    reading_warnings: list[str]
    load_s: float
    hash_wait_s: float
    write_s: float

    @property
    def warnings(self) -> list[str]:
        """Every warning: the utterance's reading's, then the method's."""
        return self.reading_warnings + list(self.summary.warnings)


def run(source_path: Path, out: Path, settings: SynthesizeSettings | MethodSettings, ingest_settings: IngestSettings,
        align_settings: AlignSettings, *, method: str | None = None,
        phones_path: Path | None = None, emotions_path: Path | None = None, constraints_path: Path | None = None,
        audio: Path | None = None, text: str | None = None, head_motion_path: Path | None = None,
        overwrite: bool = False) -> SynthesizeResult:
    """Synthesize the utterance (phones from ``phones_path``, or ``audio`` aligned to ``text``) with
    its emotions (and, for ``dp``, its constraints) by ``method`` (a member's name; default
    ``synthesize.method``) from ``source_path`` (the motion database, or the method's fitted
    model), and write ``out`` (a ``motion`` artifact). ``settings``: the :class:`MethodSettings`, or
    ``[synthesize]`` alone (the packaged defaults for the rest). ``head_motion_path`` (a
    ``headmotion`` artifact, see ``facesynth head-motion``) replaces the head motion of the output
    (the source takes' for the searches, none for the others).

    The steps are the ones :mod:`facesynth.api` calls (:func:`steps.synthesize_utterance`,
    :func:`steps.write_motion`, :func:`steps.motion_inputs`), so the command and the API write the
    same artifact."""
    settings = method_settings(settings)
    member = methods.get(steps.chosen_method(method, settings.synthesize))
    if constraints_path is not None:
        member.refuse_constraints({0: 0})
    check_output(out, overwrite)
    head = HeadMotion.read(head_motion_path) if head_motion_path is not None else None
    t0 = time.perf_counter()
    source = member.read(source_path)
    load_s = time.perf_counter() - t0
    # hashed from here, while the method runs: the source's record comes from the file just
    # validated (not opened again), and a source replaced meanwhile is refused
    records = input_records_in_background(steps.motion_inputs(source_path, phones_path, emotions_path, constraints_path,
                                                             audio, head_motion_path,
                                                             settings.synthesize.articulation_model))
    read = steps.read_utterance(ingest_settings, phones_path=phones_path, audio=audio, text=text, align=align_settings,
                               emotions_path=emotions_path)
    constraints = steps.constraints_for(member, source, constraints_path, read.utterance)
    made = steps.synthesize_utterance(member, source, read, settings, constraints, head=head,
                                     source_where=str(source_path), where=str(phones_path or audio))
    t0 = time.perf_counter()
    input_records = records()
    hash_wait_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    steps.write_motion(made, out, input_records, overwrite=overwrite)
    write_s = time.perf_counter() - t0
    return SynthesizeResult(member.name, made.summary, list(read.warnings), load_s, hash_wait_s, write_s)


def method_settings(settings: SynthesizeSettings | MethodSettings) -> MethodSettings:
    """``settings`` as the :class:`MethodSettings` (``[synthesize]`` alone: the packaged defaults for the rest)."""
    return MethodSettings.packaged(synthesize=settings) if isinstance(settings, SynthesizeSettings) else settings
