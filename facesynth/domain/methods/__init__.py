"""Synthesis methods as one family: every way facesynth makes motion from an utterance.

A method turns an utterance (:class:`~facesynth.domain.speech.utterance.Utterance`: phones with times in
seconds and an emotion per phone, and, for the DP alone, motion-node constraints) into a
:class:`~facesynth.model.motion.Motion` with the same fields and provenance whatever the method:
markers at the output rate and at the capture rate, the per-phone path (``path.method`` names the
method; ``path.node`` the chosen motion nodes, -1 where the method has none) and per capture-rate
frame the input phone it belongs to (``provenance.step``).

A method reads one *source* artifact: the motion database itself (``dp``, ``greedy``, ``mean``:
no fitting) or a model fitted on a database's training takes and written as its own artifact
(``trajectory``, ``coarticulation``: ``facesynth fit-method``). The members:

========================  ============  ============================================================
name                      source        what it does
========================  ============  ============================================================
``dp``                    motiondb      the paper's constrained DP search (Algorithm 1, Eq. 4-10)
``greedy``                motiondb      Cao et al.'s greedy search over the same database and costs
``trajectory``            trajectory    Huang et al.'s smooth key-shape path through per-(phone,
                                        emotion) Gaussians (Eq. 6-7)
``coarticulation``        coarticul.    a Cohen-Massaro dominance model per (phone, emotion)
``mean``                  motiondb      the per-(phone, emotion) mean pose at phone centres,
                                        interpolated linearly
========================  ============  ============================================================

Adding a member: a subclass of :class:`Method` in its own module, and one registration line
below (:data:`facesynth.base.registry.METHODS`), which with the class declares everything the
commands need of it: its settings section (fact ``settings``), its source or fitted artifact
(``fitted``, ``source_kind``), its evaluation (:meth:`Method.evaluation_source`,
:meth:`Method.ablations`; its report row is its name) and its live behaviour (:meth:`Method.live`
with ``streams=True``, or :attr:`Method.not_live`). ``synthesize --method``, ``evaluate``,
``batch``, ``tune``, ``stream``, ``fit-method`` (a fitted member), ``--set`` and the docs' tables
then offer it. The shared steps around a method (reading the utterance, emotion names, the
memory check) are :mod:`facesynth.domain.methods.steps`; the live forms' interface is
:mod:`facesynth.domain.methods.live`.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

from facesynth.base.config import Config, EvaluateSettings, SynthesizeSettings
from facesynth.base.errors import UsageError
from facesynth.base.registry import METHODS

from .live import LiveSource


class NotEvaluable(Exception):
    """A member ``evaluate`` cannot score on this database; the message says what to give."""


class MethodSettings:
    """The settings sections the members read, by section name: ``synthesize`` (every member's
    output rate; the searches' costs and post-processing) and each registered member's own section
    (its registration's fact ``settings``: ``trajectory``, ``coarticulation``, a new member's).
    ``settings.trajectory`` is that section's frozen dataclass; :meth:`replace` gives a copy with
    other sections. Immutable."""

    __slots__ = ("_sections",)

    def __init__(self, sections: Mapping[str, Any] | None = None, /, **named: Any) -> None:
        merged = {**dict(sections or {}), **named}
        if "synthesize" not in merged:
            raise ValueError("MethodSettings needs the [synthesize] section")  # a caller's bug
        object.__setattr__(self, "_sections", merged)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        sections = object.__getattribute__(self, "_sections")
        if name not in sections:
            raise AttributeError(f"no [{name}] section among the method settings ({', '.join(sections)})")
        return sections[name]

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("MethodSettings is immutable; use .replace(section=...)")

    def __reduce__(self):  # pickled to batch's workers
        return (MethodSettings, (dict(self._sections),))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, MethodSettings) and self._sections == other._sections

    def __hash__(self) -> int:
        return hash(tuple(sorted(self._sections.items())))

    def __repr__(self) -> str:
        return f"MethodSettings({', '.join(f'{k}={v!r}' for k, v in self._sections.items())})"

    @property
    def synthesize(self) -> SynthesizeSettings:
        """``[synthesize]``: every member's output rate, the searches' costs and post-processing."""
        return self._sections["synthesize"]

    def section(self, name: str) -> Any:
        """The section called ``name``'s frozen dataclass."""
        return getattr(self, name)

    def sections(self) -> dict[str, Any]:
        """Every section held, by name."""
        return dict(self._sections)

    def replace(self, **sections: Any) -> "MethodSettings":
        """A copy with the sections ``sections`` (``synthesize=...``) instead."""
        return MethodSettings(self._sections, **sections)

    @staticmethod
    def names() -> tuple[str, ...]:
        """The sections the members read: ``synthesize`` and every registered member's own."""
        return tuple(dict.fromkeys(["synthesize"] + [e.facts["settings"] for e in METHODS.entries()
                                                     if e.facts.get("settings")]))

    @classmethod
    def of(cls, config) -> "MethodSettings":
        """The sections of a :class:`~facesynth.base.config.Config` (a command reading them declares
        ``METHOD_SECTIONS`` among its ``reads``, :mod:`facesynth.base.pipeline`)."""
        return cls({name: config.settings(name) for name in cls.names()})

    @classmethod
    def packaged(cls, **given) -> "MethodSettings":
        """The packaged defaults, with the sections ``given`` (``synthesize=...``) instead (for
        library callers and commands that read only some sections)."""
        defaults = Config.load()
        return cls({name: given.get(name) or defaults.settings(name) for name in cls.names()})


@dataclass(frozen=True)
class SynthesisSummary:
    """What a method reports about the motion it made.

    phones: phones of the utterance.
    frames: frames of the motion at the output rate.
    unseen: what the source has nothing of (a phone, or '/aa/ in sad' for a (phone, emotion)
        pair) -> what covered it.
    warnings: sentences for the user (e.g. the voice could not move the mouth).
    voice: what the utterance's voice did to the mouth (:mod:`facesynth.domain.voice.fusion`): ``articulation``,
        ``loudness``, or ``off`` (no audio, or the step was off or could not run).
    cost, joins, device: the searches' path cost (Eq. 4), joins between nodes not captured one
        after the other, and where the search ran; None for the other methods.
    energy, lam: the trajectory method's Eq. 6 energy and its smoothness weight lambda; None for
        the other methods.
    fallbacks: the trajectory method's phones covered by their viseme class's pooled Gaussian ->
        that class.
    phases: phase name (``search_s``...) -> seconds it took (the searches'
        :meth:`~facesynth.domain.search.synthesis.SearchTimings.phases`).
    """

    phones: int
    frames: int
    unseen: dict[str, str] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    cost: float | None = None
    joins: int | None = None
    device: str | None = None
    energy: float | None = None
    lam: float | None = None
    fallbacks: dict[str, str] = field(default_factory=dict)
    phases: dict[str, float] = field(default_factory=dict)
    voice: str = "off"


@dataclass(frozen=True)
class FitSummary:
    """What a fitted member reports about its fit (:meth:`Method.fit`).

    fit_rms_mm: RMS per marker of the model's fit to the training frames (mm).
    labels: (phone, emotion) types of a coarticulation model; None for the trajectory model.
    keyshapes, phones, pairs, samples: a trajectory model's key-shapes, phones with a Gaussian,
        (phone, emotion) pairs with their own Gaussian and training frames; None for coarticulation.
    """

    fit_rms_mm: float
    labels: int | None = None
    keyshapes: int | None = None
    phones: int | None = None
    pairs: int | None = None
    samples: int | None = None


@dataclass
class Synthesis:
    """A method's result: the motion and ``summary``, what the method reports about it."""

    motion: Any
    summary: SynthesisSummary


class Method(ABC):
    """One member of the family. Subclasses set the class attributes and :meth:`synthesize`;
    fitted members also :meth:`fit`; members that stream :meth:`live`.

    What a member declares, where it is defined (its registration's facts and this class):

    - its settings section (fact ``settings``; :attr:`section`), which :class:`MethodSettings`,
      ``--set`` and the commands running members read;
    - its source: the motion database or its fitted artifact (facts ``fitted``, ``source_kind``);
    - its evaluation source (:meth:`evaluation_source`), the settings ``evaluate`` runs it with
      (:meth:`for_evaluation`) and its report rows: its name, and its :meth:`ablations`;
    - its live behaviour: :meth:`live` (with the fact ``streams``), or :attr:`not_live`, the reason
      it does not stream.

    ``takes_constraints``: accepts motion-node constraints; ``tunable``: ``facesynth tune`` can
    tune its weights."""

    name: ClassVar[str]
    takes_constraints: ClassVar[bool] = False
    tunable: ClassVar[bool] = False
    #: Why ``facesynth stream`` cannot run the member (members without :meth:`live`).
    not_live: ClassVar[str] = "it has no live form"

    @property
    def section(self) -> str:
        """The settings section the member reads besides ``[synthesize]``'s output rate (its
        registration's ``settings``; ``synthesize`` when it names none)."""
        return str(METHODS.entry(self.name).facts.get("settings", "synthesize"))

    @property
    def summary(self) -> str:
        """One line on what the member does (its registration's)."""
        return METHODS.entry(self.name).summary

    @property
    def fitted(self) -> bool:
        """Whether the member's source is a model made by ``facesynth fit-method``."""
        return bool(METHODS.entry(self.name).facts.get("fitted", False))

    @property
    def source_kind(self) -> str:
        """The artifact kind the member reads: ``motiondb``, or its fitted model's kind."""
        return str(METHODS.entry(self.name).facts.get("source_kind", "motiondb"))

    @abstractmethod
    def read(self, path: Path):
        """The method's source artifact at ``path`` (a motion database, or its fitted model)."""

    def fit(self, db, settings: MethodSettings, *, keyshapes=None, where: str = "the database"):
        """A model of ``db``'s training takes (fitted members); returns (model, :class:`FitSummary`)."""
        raise UsageError(f"the {self.name} method reads the motion database itself and has nothing to fit; "
                         f"fit one of {', '.join(fitted_names())}.")

    def evaluation_source(self, db, settings: MethodSettings, given: Mapping[str, Any], where: str):
        """The source ``facesynth evaluate`` scores this member from on ``db``: the database itself,
        or for a fitted member the model given for it (``given[name]``) or else one fitted now on
        ``db``'s training takes. :class:`NotEvaluable` (with the reason) when it cannot be scored."""
        if not self.fitted:
            return db
        model = given.get(self.name)
        return model if model is not None else self.fit(db, settings, where=where)[0]

    def for_evaluation(self, settings: MethodSettings, evaluate: EvaluateSettings) -> MethodSettings:
        """The settings ``facesynth evaluate`` runs the member with (``settings`` unless the member
        takes some of ``[evaluate]``)."""
        return settings

    def ablations(self, db, settings: MethodSettings) -> dict[str, Callable[[Any], Any]]:
        """Variants ``evaluate`` scores beside the member on ``db``: {report row: utterance ->
        markers (T, M, 3) mm at the capture rate}; none by default."""
        return {}

    def live(self, source, settings: MethodSettings) -> LiveSource:
        """The member's live form on ``source`` (:mod:`facesynth.domain.methods.live`), which
        ``facesynth stream`` runs; a member that does not stream says why (:attr:`not_live`)."""
        raise UsageError(f"the {self.name} method does not stream: {self.not_live}; use one of "
                         f"{', '.join(live_names())}.")

    def fit_settings(self, settings: MethodSettings):
        """The settings section a fitted model records as its ``config`` (fitted members): the
        member's own."""
        return settings.section(self.section)

    def prepare(self, source, settings: MethodSettings):
        """Work that depends only on the source and settings, done once for many utterances
        (the searches' transition costs); passed back to :meth:`synthesize` as ``prepared``."""
        return None

    def memory_estimate(self, source, utt, settings: MethodSettings) -> float:
        """Bytes the synthesis of ``utt`` needs beyond the source (checked before the work)."""
        return 0.0

    def recorded_settings(self, settings: MethodSettings):
        """The settings section a motion made by this method records as its ``config``."""
        return settings.synthesize

    def memory_what(self, source, utt) -> str:
        """The work :meth:`memory_estimate` sizes, as the memory check's message names it."""
        return f"the {self.name} method for {len(utt)} phones"

    def refuse_constraints(self, constraints) -> None:
        """One sentence when constraints are given to a method that takes none."""
        if constraints and not self.takes_constraints:
            raise UsageError(f"motion-node constraints need the DP search (Eq. 10); the {self.name} method takes "
                             "none: drop --constraints or use --method dp.")

    @abstractmethod
    def synthesize(self, source, utt, settings: MethodSettings, constraints: dict[int, int] | None = None, *,
                   prepared=None, where: str = "the utterance") -> Synthesis:
        """The motion of ``utt`` (constraints: {phone index: node}, DP only)."""


def names() -> tuple[str, ...]:
    """Every member's name, in report order."""
    return METHODS.names()


def fitted_names() -> tuple[str, ...]:
    """The members whose source is a model made by ``facesynth fit-method``."""
    return tuple(e.name for e in METHODS.entries() if e.facts.get("fitted"))


def live_names() -> tuple[str, ...]:
    """The members ``facesynth stream`` runs (registered with ``streams=True``: a :meth:`Method.live`)."""
    return tuple(e.name for e in METHODS.entries() if e.facts.get("streams"))


def reader_of(kind: str) -> str | None:
    """The fitted member whose model is an artifact of ``kind`` (its ``source_kind``), or None."""
    return next((e.name for e in METHODS.entries() if e.facts.get("fitted") and e.facts.get("source_kind") == kind),
                None)


def get(name: str) -> Method:
    """The member called ``name``; a usage error naming the members for another name."""
    return METHODS.get(name)()


# The members, in the order reports list them: name, "module:class", summary, and what the
# commands need to know before importing them: ``settings`` (the settings section it reads),
# ``fitted`` and its model's ``source_kind`` (made by ``facesynth fit-method``), ``streams``
# (``facesynth stream`` runs its :meth:`Method.live`), and for ``evaluate``: ``searches`` (a path of
# motion nodes, whose joins are scored) and ``simplicity`` (the recommendation prefers the lowest
# among tied members). Its report row is its name.
METHODS.register("dp", "facesynth.domain.methods.search:DpMethod",
                 "the paper's constrained DP search of the motion database (Algorithm 1, Eq. 4-10)",
                 settings="synthesize", streams=True, searches=True, simplicity=4)
METHODS.register("greedy", "facesynth.domain.methods.search:GreedyMethod",
                 "Cao et al.'s greedy search of the same database with the same costs",
                 settings="synthesize", streams=True, searches=True, simplicity=3)
METHODS.register("trajectory", "facesynth.domain.methods.trajectory:TrajectoryMethod",
                 "Huang et al.'s smooth key-shape path through per-(phone, emotion) Gaussians (Eq. 6-7)",
                 settings="trajectory", fitted=True, source_kind="trajectory", streams=True, simplicity=2)
METHODS.register("coarticulation", "facesynth.domain.methods.coarticulation:CoarticulationMethod",
                 "a Cohen-Massaro dominance model per (phone, emotion), fitted on the training takes",
                 settings="coarticulation", fitted=True, source_kind="coarticulation", simplicity=1)
METHODS.register("mean", "facesynth.domain.methods.mean:MeanMethod",
                 "the per-(phone, emotion) mean pose at phone centres, interpolated linearly",
                 settings="synthesize", simplicity=0)
