"""The members' live forms: what ``facesynth stream`` asks a member for (:meth:`Method.live
<facesynth.domain.methods.Method.live>`), so that the live synthesizer
(:mod:`facesynth.domain.live.synthesizer`) takes no decision by a member's name.

A :class:`LiveSource` is what every stream of one source shares (read once): the markers' names
and reference, the grid the path is made on, the emotions, the rest pose. Each stream opens its
own :class:`LiveStepper`, which takes the member's decisions for the known phones, says how far
the committed ones fix the frames, and renders them:

- ``dp``, ``greedy`` (:class:`facesynth.domain.methods.search.SearchLive`): the motion database, its dense transition costs
  (Table I, (N, N) float32) and, for ``greedy``, Cao et al.'s greedy search. ``dp`` runs the exact
  DP of Algorithm 1 on the steps after the committed ones, the last committed step pinned to its
  node (Eq. 10's blocking penalty); ``greedy`` tiles the uncommitted spoken phones, its first run
  tied to the last committed node. Frames are rendered as batch synthesis renders a path
  (:func:`facesynth.domain.search.synthesis.render_path`) from two spoken phones before the first
  unsent frame; a frame waits for the join smoothing's reach after the committed steps.
- ``trajectory`` (:class:`facesynth.domain.methods.trajectory.TrajectoryLive`): Eq. 7 solved on the model's capture grid over the
  capture frames after the last one a sent frame used, up to the end of the known phones, with
  that frame fixed, and down-sampled to the output rate as batch synthesis down-samples (Eq. 6's
  duration normalization divides by the frames known at the decision, since the utterance's
  length is not known yet).

The times are seconds, markers (T, M, 3) float32 mm in the head frame.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, Protocol

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.errors import InputError


class Track(Protocol):
    """What a stream knows (:class:`facesynth.domain.live.synthesizer.LiveSynthesizer`): the phones
    (Festival names, and the IPA phone each stands for in another language, else "") with their
    start and end (s) and emotion, and the committed steps' nodes (-1
    where the member has none)."""

    phones: list[str]
    ipa: list[str]
    starts: list[float]
    ends: list[float]
    emotions: list[str]
    committed: list[int]


class LiveStepper(ABC):
    """One stream's decisions and frames (its own state: a stepper is opened per stream)."""

    @abstractmethod
    def decide(self, track: Track, upto: int) -> list[int]:
        """The nodes of steps ``[len(track.committed), upto)`` (-1 for members without nodes)."""

    @abstractmethod
    def final_limit(self, track: Track) -> int:
        """The capture-grid frame before which nothing uncommitted can change a frame (with at
        least one step committed, not every phone of a complete utterance)."""

    @abstractmethod
    def render(self, track: Track, first: int, stop: int) -> np.ndarray:
        """Markers (stop - first, M, 3) float32 mm of output frames [first, stop) of the committed steps."""


class LiveSource(ABC):
    """What every stream of one member's source shares (read once).

    what: the source in messages ('the motion database'); db: the motion database when the member
    streams from one, else None; marker_names, reference ((M, 3) mm); grid_fps: frames/s of the grid
    the path is made on (the capture rate); emotions: those the source knows; rest_markers: (M, 3)
    float32 mm, where silences settle; fps: the output rate (frames/s); synth: the search and
    post-processing settings the frames are rendered with."""

    what: str
    db: Any = None
    marker_names: list[str]
    reference: np.ndarray
    grid_fps: float
    emotions: list[str]
    rest_markers: np.ndarray
    fps: float
    synth: SynthesizeSettings

    def emotion_markers(self, emotion: str) -> np.ndarray:
        """(M, 3) float32 mm: the source's pose of ``emotion`` without the speech (the rest pose
        where the source has no frames of it)."""
        return self.rest_markers

    def warm(self) -> None:
        """Prepare now what the first stream of phones would otherwise wait for (nothing by default)."""
        return None

    @property
    def warmed(self) -> bool:
        """Whether nothing is left for :meth:`warm` to prepare."""
        return True

    @abstractmethod
    def stepper(self) -> LiveStepper:
        """A new stream's stepper."""


def wrong_source(method: str, wanted: str, make: str) -> InputError:
    """The error for a source of another kind than the member streams from."""
    return InputError(f"stream.method {method!r} streams from {wanted}: give the output of {make}.")
