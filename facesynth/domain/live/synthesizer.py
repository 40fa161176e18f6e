"""The live core: phones arrive one by one (with their times), node decisions are taken with a
bounded look-ahead, and frames are sent once, in order, never revised.

Decisions (``stream.method``): the member of the method family streamed is asked for its live
form (:meth:`facesynth.domain.methods.Method.live`, :mod:`facesynth.domain.methods.live`): a source
shared by the streams and, per stream, a stepper that takes the member's decisions for the known
phones, says how far the committed ones fix the frames and renders them. A member without a live
form says why (its ``not_live``), and ``stream.method`` offers only the members registered with
``streams=True``. Of the built-in members:

- ``dp``: the exact DP of paper Algorithm 1 over a sliding window. When phones are known up to
  step K and steps ``[0, c)`` are committed, the DP runs on steps ``[c - 1, K]`` with step
  ``c - 1`` pinned to its committed node (Eq. 10's blocking penalty), so the transition into
  the window is costed exactly; steps ``c .. K - L`` (L = ``stream.lookahead_phones``) of its
  optimal path are committed. It is a fixed-lag decision: exact within its window, and equal
  to the whole-utterance DP when the look-ahead covers the utterance (tested); with a shorter
  look-ahead a committed step cannot be changed by what comes after the window
  (``benchmarks/live_stream.py`` measures how often the paths differ).
- ``greedy``: Cao et al.'s greedy tiling (:class:`facesynth.domain.search.greedy.Greedy`) of the
  uncommitted spoken phones, its first run tied to the last committed node; steps older than
  the look-ahead are committed.
- ``trajectory``: the key-shape trajectory model (Huang et al. §5.4, a ``trajectory`` artifact
  instead of a database). At each decision Eq. 7 is solved on the model's capture grid over the
  capture frames after the last one a sent frame used, up to the end of the known phones, with
  that frame fixed (:func:`facesynth.domain.methods.trajectory.solve`'s ``before``), and down-sampled to
  the output rate as batch synthesis down-samples: the path is a Gauss-Markov chain, so this is
  the exact minimizer of Eq. 6 given what was sent and the phones known, and batch synthesis's
  frames when the look-ahead covers the utterance (tested). Frames before the first uncommitted
  phone are sent. One difference from batch synthesis: Eq. 6's duration normalization divides
  by the frames known at the decision, since the utterance's length is not known yet.

Frames (``dp`` and ``greedy``): the committed path is rendered as batch synthesis renders a path
(:func:`facesynth.domain.search.synthesis.render_path`: time-warp, the join smoothing of VII-B, pauses
regenerated, Eq. 11, down-sampling). A frame is sent only when nothing uncommitted can change
it: it must lie before the first uncommitted phone by more than the join smoothing's reach
(``smoothing_half_window`` capture frames; none when that phone is a pause, since joins next to
a pause are not smoothed), and before a committed pause that is last (a pause is interpolated
toward the next phone's first frame: its frames wait for that phone). A pause whose next phone is
not decided yet does not hold its frames back longer than ``stream.pause_wait_s``: those frames
go out that long after their audio, easing from the last frame sent toward the rest pose (a
cosine over ``synthesize.pause_rest_ramp_s``, as batch synthesis eases into a long pause), and
once the next phone is decided the pause's remaining frames are batch's, plus the difference
between the last frame sent and batch's frame, fading linearly to nothing at the pause's end.
Only the frames of such a pause differ from batch synthesis of the same path.
Only a window of recent phones is re-rendered at each decision, starting two spoken phones
before the first unsent frame, so the work per decision does not grow with the stream.

Rig curves: the markers of each batch of sent frames are solved onto the built-in rig with
the direct facial solve (:func:`facesynth.domain.retarget.solve.solve_curves`, the ``[solve]``
settings), the last sent frame prepended so that consecutive batches join, and mapped to the
52 ARKit weights (:meth:`facesynth.domain.rig.face.Rig.to_arkit`).
"""

from __future__ import annotations

import time
from collections import deque
from dataclasses import dataclass, field, replace

import numpy as np

from facesynth.base.config import SolveSettings, StreamSettings, SynthesizeSettings, TrajectorySettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain import methods
from facesynth.domain.methods import MethodSettings
from facesynth.domain.methods.live import LiveStepper
from facesynth.domain.retarget.solve import FacePriors, solve_curves
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.loading import builtin_rig, marker_map
from facesynth.domain.voice.fusion import articulation_model
from facesynth.model.motiondb import MotionDatabase

#: The rig shapes that speak: the voice sets jawOpen, mouthFunnel and mouthPucker, and an emotion's
#: pose (:meth:`LiveModel.emotion_pose`) leaves these at 0, keeping its smile, frown and stretch.
SPEECH_SHAPES = ("jawOpen", "jawForward", "jawLeft", "jawRight", "mouthClose", "mouthFunnel", "mouthPucker",
                 "mouthLeft", "mouthRight", "mouthLowerDown_L", "mouthLowerDown_R", "mouthUpperUp_L", "mouthUpperUp_R",
                 "mouthPress_L", "mouthPress_R", "mouthRollLower", "mouthRollUpper", "mouthShrugLower",
                 "mouthShrugUpper")


@dataclass
class Frame:
    """One output frame: ``index`` on the output grid (time = index / fps, s), the 52 ARKit
    weights in [0, 1] (``Rig.arkit_names`` order), the markers ((M, 3) float32 mm, head
    frame) and ``ready_at``: the stream time (s of audio received) when the frame was decided."""

    index: int
    time: float
    arkit: np.ndarray
    markers: np.ndarray
    ready_at: float


class LiveModel:
    """What every stream of one source shares (read once): the member's live source
    (:class:`~facesynth.domain.methods.live.LiveSource`: for ``dp`` and ``greedy`` the database and
    its dense transition costs, computed when a stream first needs them (:meth:`warm`), for
    ``trajectory`` its model) and the facial solve's basis.

    source : the member's source as read (a :class:`MotionDatabase`, or a fitted model);
    settings : the :class:`~facesynth.domain.methods.MethodSettings` (or ``[synthesize]`` alone,
    with ``trajectory`` the trajectory method's section; the packaged defaults for the rest): the
    search and post-processing settings (the output rate is taken from ``stream``); solve : the
    facial solve's.
    """

    def __init__(self, source, settings: SynthesizeSettings | MethodSettings, stream: StreamSettings,
                 solve: SolveSettings, trajectory: TrajectorySettings | None = None):
        if not isinstance(settings, MethodSettings):
            given = {"trajectory": trajectory} if trajectory is not None else {}
            settings = MethodSettings.packaged(synthesize=settings, **given)
        synth = settings.synthesize
        self.stream = stream
        self.solve_settings = solve
        self.synth = replace(synth, output_fps=stream.fps, postprocess="deng", use_opencl=False)
        #: the member's live form (its decisions, the frames they fix, their rendering)
        self.live = methods.get(stream.method).live(source, settings.replace(synthesize=self.synth))
        self.db: MotionDatabase | None = self.live.db  # None for a member that streams from a fitted model
        self.marker_names, self.reference = self.live.marker_names, self.live.reference
        #: frames/s of the grid phones are placed on and the path is made on (the capture rate)
        self.grid_fps = self.live.grid_fps
        self.emotions = self.live.emotions
        #: (M, 3) mm: where silences settle
        self.rest_markers = self.live.rest_markers
        rig = self.rig = builtin_rig()
        self.face = load_face_rig()
        self.marker_map = marker_map(rig, self.marker_names, self.reference, self.live.what)
        self.basis = rig.deltas[:, self.marker_map.vertices]
        #: the articulation model frames come from when the phones would be recognised
        #: (``stream.voice = "articulation"``, :mod:`facesynth.domain.live.voice_frames`), else None
        self.voice_model = articulation_model(synth.articulation_model) if stream.voice == "articulation" else None
        if self.voice_model is not None and "jawOpen" not in self.voice_model.target_names:
            raise InputError(f"synthesize.articulation_model {synth.articulation_model or '(packaged)'} predicts no "
                             "jawOpen, which live frames move the jaw by; fit it on a capture whose markers the rig "
                             "binds (fit-articulation --binding), or set stream.voice = \"off\".")
        self._poses: dict[str, np.ndarray] = {}
        if self.voice_model is None:  # every stream of audio takes the phones' path: ready it now
            self.warm()

    def warm(self) -> None:
        """Prepare now what the first stream of phones would wait for (the search's transition
        costs, :meth:`~facesynth.domain.methods.live.LiveSource.warm`); a stream whose frames come
        from its voice alone needs none of it."""
        self.live.warm()

    @property
    def arkit_names(self) -> tuple[str, ...]:
        """The 52 ARKit names of :attr:`Frame.arkit`, in Live Link Face order."""
        return self.face.arkit_names

    def solve(self, markers: np.ndarray, previous: tuple[np.ndarray, np.ndarray] | None) -> np.ndarray:
        """(T, E) rig weights for markers (T, M, 3) mm. ``previous`` (the last sent frame's markers
        (M, 3) and rig weights (E,)) is solved with them for continuity and dropped; its weights
        start the iterations."""
        frames = markers if previous is None else np.concatenate([previous[0][None], markers])
        disp = self.marker_map.displacements(frames, self.reference)
        w, _, _ = solve_curves(disp, self.basis, smooth=self.solve_settings.smooth, ridge=self.solve_settings.ridge,
                               iterations=self.solve_settings.iterations, tolerance=self.solve_settings.tolerance,
                               initial=None if previous is None else previous[1],
                               priors=FacePriors.of_rig(self.face.shape_names, self.solve_settings))
        return w if previous is None else w[1:]

    def markers_of(self, weights: np.ndarray) -> np.ndarray:
        """(T, M, 3) float32 mm markers of rig weights (T, E): the reference, the bound markers moved
        by the rig's shapes at their vertices, carried back into the motion's frame and units."""
        mm = self.marker_map
        rig_disp = np.tensordot(np.asarray(weights, np.float64), self.basis, axes=(1, 0))  # (T, B, 3) rig units
        out = np.repeat(np.asarray(self.reference, np.float64)[None], len(rig_disp), 0)
        out[:, mm.columns] += rig_disp @ mm.rotation / mm.scale
        return out.astype(np.float32)

    def emotion_pose(self, emotion: str) -> np.ndarray:
        """(E,) rig weights of ``emotion``'s pose without the speech: the source's pose of that
        emotion (:meth:`~facesynth.domain.methods.live.LiveSource.emotion_markers`: the mean of a
        database's captured frames of it, the rest pose for a trajectory model) solved onto the
        rig, its speech shapes (:data:`SPEECH_SHAPES`) at 0. Computed once per emotion."""
        if emotion not in self._poses:
            markers = self.live.emotion_markers(emotion)
            weights = self.solve(np.asarray(markers, np.float32)[None], None)[0]
            names = list(self.rig.shape_names)
            weights[[names.index(n) for n in SPEECH_SHAPES if n in names]] = 0.0
            self._poses[emotion] = weights
        return self._poses[emotion]

    def arkit(self, weights: np.ndarray) -> np.ndarray:
        """(T, 52) ARKit weights in [0, 1] (:attr:`arkit_names` order) for rig weights (T, E)."""
        return np.clip(self.face.to_arkit(weights), 0.0, 1.0)


@dataclass
class LiveSynthesizer:
    """One stream: phones in (:meth:`add_phone`), frames out, each frame once and in order.

    The phone list tiles the stream from 0 s; a phone is (Festival name, start s, end s) and must
    start where the previous one ended (a gap is filled with a pause by :meth:`add_phone`).
    Adjacent pauses are merged, as batch synthesis merges them.
    """

    model: LiveModel
    emotion: str = "neutral"
    phones: list[str] = field(default_factory=list)
    ipa: list[str] = field(default_factory=list)  # per phone: the IPA it stands for in another language, else ""
    starts: list[float] = field(default_factory=list)
    ends: list[float] = field(default_factory=list)
    emotions: list[str] = field(default_factory=list)
    committed: list[int] = field(default_factory=list)
    sent: int = 0                      # output frames sent so far
    finished: bool = False
    phones_complete: bool = False      # every phone of the utterance is known (a TTS engine said so)
    decision_s: deque = field(default_factory=lambda: deque(maxlen=100000))  # wall time of the recent decisions
    _last: tuple[np.ndarray, np.ndarray] | None = None   # the last sent frame's markers and rig weights
    _open_pause: int | None = None     # the step of a pause whose frames went out before its next phone was decided
    _pause_left: tuple[int, np.ndarray] | None = None  # the open pause's starting frame: (index, (M, 3) markers)
    _silence_growing: bool = False     # the last phone is a pause from :meth:`extend_silence`: its end is not known
    stepper: LiveStepper = field(init=False)  # the member's decisions and frames for this stream

    def __post_init__(self):
        self.stepper = self.model.live.stepper()
        self.set_emotion(self.emotion)

    def set_emotion(self, name: str) -> None:
        """The emotion of the phones that arrive from now on (a control message); one of the
        database's emotions."""
        if name not in self.model.emotions:
            raise InputError(f"emotion {name!r} is not in the motion database; use one of {', '.join(self.model.emotions)}.")
        self.emotion = name

    @property
    def known_until(self) -> float:
        """End of the last known phone, s."""
        return self.ends[-1] if self.ends else 0.0

    def add_phone(self, phone: str, start: float, end: float, ipa: str = "") -> None:
        """Append a phone (Festival name, seconds; ``ipa``: the IPA phone it stands for in a
        stream in another language, matched by its features, ``synthesize.phone_match``). A start
        after the last end is preceded by a pause; a start before it is moved to it (the
        recogniser's boundaries can shift by a frame); a phone that ends no later than the last
        end is ignored."""
        if self.finished:
            raise InputError("the stream has ended; start a new stream for the next utterance.")
        if self.phones_complete:
            raise InputError("the utterance's phones were declared complete; no phone can be added.")
        last = self.known_until
        if end <= last + 1e-9:
            return
        if start > last + 1e-6:
            self._append(PAU, last, start)
        self._append(phone, max(start, last), end, ipa)
        self._silence_growing = False

    def extend_silence(self, until: float) -> None:
        """The audio up to ``until`` (s) is silence, though the phone after it is not known yet
        (a TTS engine sends no phone for it): a pause up to there, whose end may grow."""
        if until > self.known_until + 1e-9:
            self.add_phone(PAU, self.known_until, until)
            self._silence_growing = True

    def _append(self, phone: str, start: float, end: float, ipa: str = "") -> None:
        if phone == PAU and self.phones and self.phones[-1] == PAU:
            self.ends[-1] = end  # one silence is one step (batch merges them likewise)
            return
        self.phones.append(phone)
        self.ipa.append(ipa)
        self.starts.append(start)
        self.ends.append(end)
        self.emotions.append(self.emotion)

    def step(self, now: float) -> list[Frame]:
        """Take the decisions the known phones allow and return the frames that became final;
        ``now`` is the stream time (s of audio received), recorded in each frame."""
        t0 = time.perf_counter()
        lookahead = 0 if self.phones_complete else self.model.stream.lookahead_phones
        self._decide(len(self.phones) - lookahead)
        frames = self._emit(now)
        self.decision_s.append(time.perf_counter() - t0)
        return frames

    def finish(self, now: float) -> list[Frame]:
        """End of stream: commit every known phone and send the remaining frames."""
        if self.finished:
            return []
        self._decide(len(self.phones))
        self.finished = True
        return self._emit(now)

    # -- decisions -------------------------------------------------------------------------

    def _decide(self, upto: int) -> None:
        """Commit steps up to (not including) ``upto``: the member's decisions (its stepper's)."""
        if upto > len(self.committed):
            self.committed.extend(self.stepper.decide(self, upto))

    # -- frames ----------------------------------------------------------------------------

    def _final_frames(self) -> int:
        """How many output frames depend on committed steps only.

        The capture frames of step t start at ``round(starts[t] * fps)`` (:func:`frame_ranges`).
        With steps ``[0, c)`` committed, the member's stepper says up to which capture frame they
        fix the frames (:meth:`~facesynth.domain.methods.live.LiveStepper.final_limit`: for the
        searches, a committed pause at ``c - 1`` waits for the next step's first frame, a spoken
        step for the join blend's reach). An output frame takes the capture frame under it (and
        the next one when the rates are not in a whole ratio)."""
        c = len(self.committed)
        if c == 0:
            return 0
        if self.phones_complete and c == len(self.phones):
            return self._total_frames()
        limit = self.stepper.final_limit(self)
        ratio = self.model.grid_fps / self.model.stream.fps
        if abs(ratio - round(ratio)) > 1e-9:
            limit -= 1  # the down-sampling interpolates with the next capture frame
        return max(0, int(np.ceil(limit / ratio - 1e-9)))

    def _emit(self, now: float) -> list[Frame]:
        if self.finished:
            n_final = self._total_frames()
        else:
            n_final = self._final_frames()
            if self._open_pause is not None and n_final <= self._output_range(self._open_pause)[1]:
                n_final = self.sent  # the frame after the open pause is not final yet: the pause goes on easing
        frames = []
        if n_final > self.sent:
            markers = self._render(self.sent, n_final)
            if self._open_pause is not None:
                markers = self._close_pause(markers, n_final)
            frames += self._send(markers, now)
        if not self.finished:
            provisional = self._pause_frames(now)
            if len(provisional):
                frames += self._send(provisional, now)
        return frames

    def _send(self, markers: np.ndarray, now: float) -> list[Frame]:
        """Solve the rig for ``markers`` (T, M, 3), the next T output frames, and send them."""
        fps = self.model.stream.fps
        weights = self.model.solve(markers, self._last)
        arkit = self.model.arkit(weights)
        frames = [Frame(self.sent + k, (self.sent + k) / fps, arkit[k], markers[k], now) for k in range(len(markers))]
        self.sent += len(markers)
        self._last = (markers[-1], weights[-1])
        return frames

    def _output_range(self, step: int) -> tuple[int, int]:
        """Output frames [first, stop) of ``step``: those whose capture frame lies in the step's
        capture frames (:func:`~facesynth.domain.postprocess.concatenation.frame_ranges`' rounding)."""
        grid = self.model.grid_fps
        ratio = grid / self.model.stream.fps
        a = int(round(self.starts[step] * grid))
        b = int(round(self.ends[step] * grid))
        return int(np.ceil(a / ratio - 1e-9)), int(np.ceil(b / ratio - 1e-9))

    def _pause_frames(self, now: float) -> np.ndarray:
        """Frames of the pause the first unsent frame lies in, when they may not wait for the
        pause's next phone: (T, M, 3) mm sent ``stream.pause_wait_s`` after their audio, easing
        from the last frame sent toward the rest pose (a cosine over ``synthesize.pause_rest_ramp_s``).
        The pause's own node does not matter (its frames are regenerated), so it need not be
        committed; every frame before it must have been sent."""
        if not self.phones:
            return np.zeros((0,), np.float32)
        fps = self.model.stream.fps
        p = self._open_pause
        if p is None:
            p = max(0, int(np.searchsorted(np.array(self.starts), self.sent / fps + 1e-9, side="right")) - 1)
            while p > 0 and self._output_range(p)[0] > self.sent:
                p -= 1
            while p + 1 < len(self.phones) and self._output_range(p)[1] <= self.sent:
                p += 1
        first, last = self._output_range(p)
        if self.phones[p] != PAU or not first <= self.sent < last:
            return np.zeros((0,), np.float32)
        # frames whose audio arrived at least `wait` ago and, where the pause's end is known, at
        # least `wait` before it, so that its last frames can still lead into the next phone
        wait = self.model.stream.pause_wait_s
        growing = self._silence_growing and p == len(self.phones) - 1
        until = min(now - wait, self.ends[p] - (0.0 if growing else wait))
        n = min(last, int(np.floor(until * fps + 1e-9)) + 1) - self.sent
        if n <= 0:
            return np.zeros((0,), np.float32)
        if self._open_pause is None:
            self._open_pause = p
            # the frame the pause leaves from: the last one sent, or rest before the first phone
            self._pause_left = (self.sent - 1, self._last[0] if self._last is not None else self.model.rest_markers)
        assert self._pause_left is not None
        k0, left = self._pause_left
        settle = self.model.synth.pause_rest_ramp_s
        u = np.clip((np.arange(self.sent, self.sent + n) - k0) / (settle * fps), 0.0, 1.0)
        u = (1 - np.cos(np.pi * u)) / 2
        rest = self.model.rest_markers
        return (left[None] * (1 - u[:, None, None]) + rest[None] * u[:, None, None]).astype(np.float32)

    def _close_pause(self, markers: np.ndarray, stop: int) -> np.ndarray:
        """The rendered frames of the open pause in ``markers`` (output frames [sent, stop), which
        reach past the pause unless the stream has ended), joined to the frames already sent:
        batch's frames plus the step from the last frame sent to batch's next, fading linearly
        to nothing at the pause's end (the frame after it, or the end of the stream)."""
        p = self._open_pause
        assert p is not None and self._last is not None
        self._open_pause = self._pause_left = None
        n = min(self._output_range(p)[1], stop) - self.sent
        if n <= 0:
            return markers
        out = markers.copy()
        fade = (1 - np.arange(1, n + 1) / (n + 1))[:, None, None]
        out[:n] += (self._last[0] - markers[0])[None] * fade
        return out

    def _total_frames(self) -> int:
        """Frames batch synthesis gives the whole utterance (its down-sampling of the capture frames)."""
        grid = self.model.grid_fps
        if not self.phones:
            return 0
        n_capture = int(round(self.ends[-1] * grid))
        ratio = grid / self.model.stream.fps
        return int(np.floor((n_capture - 1) / ratio)) + 1 if n_capture > 0 else 0

    def _render(self, first: int, stop: int) -> np.ndarray:
        """Markers (stop - first, M, 3) mm of output frames [first, stop), rendered by the member's stepper."""
        return self.stepper.render(self, first, stop)
