"""Frames from what the voice already says: live audio to the mouth at the speed of speech.

With ``stream.voice = "articulation"`` a stream whose phones would be recognised from its audio
(``"phones": "recognize"``, the default) sends each output frame as soon as the audio up to its
time plus the articulation model's look-ahead (:func:`facesynth.domain.voice.articulation.model_look_ahead_s`,
46 ms for the packaged model) has arrived, and ``stream.voice_anticipation_s`` more (0 by
default; with more, the mouth may open that far ahead of its sound, as a real mouth does before its
first syllable). The frame is decided then and never revised:

* the mouth is the voice's: the model's jawOpen (with ``stream.voice_jaw = "opening"``, the
  default, its predicted mouth opening carried into the jaw's units by the two targets' training
  means and standard deviations: on voices the model was not fitted on the opening is the better
  read, ``benchmarks/voice_speakers.py``), mouthFunnel and mouthPucker predictions
  (:class:`facesynth.domain.voice.articulation.StreamingPredictor`, frame by frame from 20 ms
  chunks, equal to the batch predictions) set those rig shapes, the jaw closing where the model's
  closure score rises above ``synthesize.voice_closure_threshold`` (by default the model's own,
  :func:`facesynth.domain.voice.fusion.closure_threshold`: a performer's model's);
* the rest of the face is the emotion's pose: the mean of the database's captured frames of the
  stream's emotion (the ``emotion`` control message changes it from the next frame), solved onto
  the built-in rig once per emotion, with its mouth shapes left to the voice (a trajectory model
  has no frames: its rest pose, whatever the emotion);
* where nobody speaks the mouth rests: the voice's shapes are scaled by its confidence over the
  last 0.25 s to the look-ahead and the anticipation, as batch fusion's
  (:mod:`facesynth.domain.voice.activity`): fully where WebRTC's voice activity detector hears
  speech (``synthesize.voice_activity``), else the speech band's loudness above a running noise
  floor (which never stands on digital silence). Batch's floor looks both ways; a stream's starts
  at its first frame, so a stream that starts in speech would take it for the noise until a
  quieter frame came: there the detector hears it, as it hears speech that stands only a few dB
  above a noisy room's hum.

No phone recogniser runs: a recognised phone settles a phone or more after it ends (300 ms and
more), long after the frames it could refine were sent, and recognition is what costs a stream
its CPU (docs/live.md). The phone-driven path (the DP on recognised phones, about a second late)
is ``stream.voice = "off"``; given phones (a TTS engine) always take it, with its guarantees.
"""

from __future__ import annotations

from collections import deque

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.domain.voice import activity
from facesynth.domain.voice.articulation import FRAME_S, HALF_WINDOW_S, StreamingPredictor, model_look_ahead_s
from facesynth.domain.voice.fusion import closure_threshold
from facesynth.model.articulation import ArticulationModel

from .phones import SAMPLE_RATE
from .synthesizer import Frame

#: The rig shapes the voice sets, by the articulation model's target of the same name.
VOICE_SHAPES = ("jawOpen", "mouthFunnel", "mouthPucker")
#: The closure score's rise (above the threshold) over which the jaw goes from open to closed.
CLOSURE_RAMP = 0.3
#: How far back from a frame's time the voice's confidence looks (s): the jaw moves through a
#: syllable's quiet parts too (batch looks 0.15 s each way).
CONFIDENCE_BACK_S = 0.25


class VoiceFrames:
    """One stream's frames from its voice. ``model``: the stream's :class:`~facesynth.domain.live.synthesizer.LiveModel`
    (its ``voice_model``, the rig and the emotions' poses); :meth:`push` takes mono float samples at
    16 kHz and returns the frames the audio so far decides; :meth:`finish` the rest.
    ``anticipation_s``: how far the mouth may move ahead of its sound (s; by default the model's
    ``stream.voice_anticipation_s``)."""

    def __init__(self, model, voice_model: ArticulationModel, synth: SynthesizeSettings, emotion: str,
                 anticipation_s: float | None = None):
        self.model = model
        self.predictor = StreamingPredictor(voice_model, model.stream.fps)
        self.columns = {name: voice_model.target_names.index(name) for name in VOICE_SHAPES
                        if name in voice_model.target_names}
        self.closure = voice_model.target_names.index("closure") if "closure" in voice_model.target_names else None
        self.threshold = closure_threshold(synth, voice_model)
        self.snr = (synth.voice_snr_none, synth.voice_snr_full)
        #: the jaw from the predicted opening (``stream.voice_jaw = "opening"``): (opening column, the
        #: opening's training mean and std, the jaw's), or None (the predicted jawOpen itself)
        self.jaw_from_opening = None
        names_y = list(voice_model.target_names)
        if getattr(model.stream, "voice_jaw", "jawOpen") == "opening" and "opening" in names_y and "jawOpen" in names_y:
            o, j = names_y.index("opening"), names_y.index("jawOpen")
            self.jaw_from_opening = (o, float(voice_model.target_mean[o]), max(float(voice_model.target_std[o]), 1e-9),
                                     float(voice_model.target_mean[j]), float(voice_model.target_std[j]))
        names = list(model.rig.shape_names)
        self.slots = {name: names.index(name) for name in self.columns if name in names}
        self.emotion = emotion
        self.sent = 0
        self.samples = 0
        self.look_ahead_s = model_look_ahead_s(voice_model)
        #: how far the mouth may move ahead of its sound (``stream.voice_anticipation_s``): each frame
        #: waits this much more audio, and its confidence hears that far past its look-ahead
        self.anticipation_s = float(model.stream.voice_anticipation_s if anticipation_s is None else anticipation_s)
        self._pending = np.zeros((0, len(voice_model.target_names)))  # predictions waiting for that audio
        self._pending_since = np.zeros(0)  # the audio (s) heard when each was predicted
        # the voice's confidence, as batch fusion's (:func:`facesynth.domain.voice.fusion.confidence`),
        # per 10 ms analysis frame of the predictor's; the recent values are kept
        self.speech = activity.SpeechFrames(synth.voice_activity)
        self._speech = np.zeros(0)  # the detector's frames not yet matched to an analysis frame
        self._powers = np.zeros(0)  # the speech band's power of the last analysis frames
        self._floor = np.inf  # what the noise floor carries from frame to frame (activity.floor_after)
        self._floor_frames = activity.FloorFrames()  # which frames it may stand on
        # enough for the confidence's reach: CONFIDENCE_BACK_S back, the anticipation ahead
        self._confidence: deque[float] = deque(maxlen=int(round((2.0 + self.anticipation_s) / FRAME_S)))
        self._heard = 0  # analysis frames whose confidence is known

    def set_emotion(self, name: str) -> None:
        """The emotion of the frames from the next one on."""
        self.emotion = name

    def weights(self, predictions: np.ndarray, confidence: np.ndarray | None = None) -> np.ndarray:
        """(k, E) rig weights for (k, Y) predictions: the emotion's pose with the voice's mouth,
        scaled by the voice's ``confidence`` (k,) 0..1 (none: 1), so that the mouth rests where
        nobody speaks."""
        base = self.model.emotion_pose(self.emotion)
        w = np.repeat(base[None], len(predictions), 0)
        share = np.ones(len(predictions)) if confidence is None else np.asarray(confidence, np.float64)
        open_share = share.copy()
        if self.closure is not None and self.threshold <= 1.0:
            open_share *= 1.0 - np.clip((predictions[:, self.closure] - self.threshold) / CLOSURE_RAMP, 0.0, 1.0)
        for name, slot in self.slots.items():
            if name == "jawOpen" and self.jaw_from_opening is not None:
                o, om, osd, jm, jsd = self.jaw_from_opening
                value = np.clip(jm + (predictions[:, o] - om) * jsd / osd, 0.0, 1.0)
            else:
                value = np.clip(predictions[:, self.columns[name]], 0.0, 1.0)
            w[:, slot] = value * (open_share if name == "jawOpen" else share)
        return w

    def _listen(self, raw: np.ndarray) -> None:
        """The confidence of the analysis frames ``raw`` (k, D) (the predictor's newest; the
        detector's frames of the same 10 ms are in, each ends before its analysis frame does)."""
        if not len(raw):
            return
        power = activity.band_power(raw)
        level = activity.band_level(power, self._powers)
        self._powers = np.concatenate([self._powers, power])[-(activity.LEVEL_FRAMES - 1):]
        speech = np.zeros(len(raw))
        known = min(len(raw), len(self._speech))  # at the audio's end: a last part-frame the detector never reads
        speech[:known], self._speech = self._speech[:known], self._speech[known:]
        admitted = self._floor_frames.admitted(self._heard, len(raw))
        floor, self._floor = activity.floor_after(level, self._heard, self._floor, admitted)
        self._confidence.extend(activity.frame_confidence(level, floor, speech, *self.snr).tolist())
        self._heard += len(raw)

    def _confidence_at(self, times: np.ndarray) -> np.ndarray:
        """(k,) the voice's confidence at ``times`` s: the highest over the analysis frames from
        :data:`CONFIDENCE_BACK_S` before each time to the last its prediction reads and the
        anticipation past it (those centred up to the look-ahead plus the anticipation less the half
        window, all heard when the frame is sent)."""
        kept = np.array(self._confidence)
        first = self._heard - len(kept)  # the analysis frame of kept[0]
        out = np.zeros(len(times))
        for k, t in enumerate(times):
            a = max(int(np.floor((t - CONFIDENCE_BACK_S) / FRAME_S + 1e-9)) - first, 0)
            reach = t + self.look_ahead_s + self.anticipation_s - HALF_WINDOW_S
            b = min(int(np.floor(reach / FRAME_S + 1e-9)) + 1 - first, len(kept))
            out[k] = kept[a:b].max() if b > a else 0.0
        return out

    def _frames(self, predictions: np.ndarray, now: float) -> list[Frame]:
        if not len(predictions):
            return []
        fps = self.model.stream.fps
        w = self.weights(predictions, self._confidence_at(np.arange(self.sent, self.sent + len(predictions)) / fps))
        arkit = self.model.arkit(w)
        markers = self.model.markers_of(w)
        frames = [Frame(self.sent + k, (self.sent + k) / fps, arkit[k], markers[k], now) for k in range(len(w))]
        self.sent += len(w)
        return frames

    def push(self, samples: np.ndarray, now: float) -> list[Frame]:
        """The frames that the audio up to ``now`` (s received, ``samples`` the newest) decides."""
        self.samples += len(samples)
        self._speech = np.concatenate([self._speech, self.speech.push(samples)])
        self._floor_frames.push(samples)
        predicted = self.predictor.push(samples)
        self._listen(self.predictor.heard)
        # a frame goes out the anticipation after its prediction's audio (the look-ahead) arrived
        heard_s = self.samples / SAMPLE_RATE
        self._pending = np.concatenate([self._pending, predicted])
        self._pending_since = np.concatenate([self._pending_since, np.full(len(predicted), heard_s)])
        ready = int(np.searchsorted(self._pending_since, heard_s - self.anticipation_s + 1e-9, side="right"))
        out, self._pending, self._pending_since = (self._pending[:ready], self._pending[ready:],
                                                   self._pending_since[ready:])
        return self._frames(out, now)

    def finish(self, now: float) -> list[Frame]:
        """End of stream: the remaining frames, as many in all as batch synthesis gives the audio (its
        capture frames down-sampled to the stream's rate; one more or less than the frames whose time
        lies within the audio, by the rounding of the two grids)."""
        rest = np.concatenate([self._pending, self.predictor.finish()])
        self._pending, self._pending_since = self._pending[:0], self._pending_since[:0]
        self._listen(self.predictor.heard)
        grid, fps = self.model.grid_fps, self.model.stream.fps
        n_capture = int(round(self.samples / SAMPLE_RATE * grid))
        total = int(np.floor((n_capture - 1) / (grid / fps))) + 1 if n_capture > 0 else 0
        want = max(total - self.sent, 0)
        if len(rest) > want:
            rest = rest[:want]
        elif len(rest) < want:  # a frame past the audio's end: its last prediction, held
            last = rest[-1:] if len(rest) else self.predictor.intercept[None]
            rest = np.concatenate([rest, np.repeat(last, want - len(rest), 0)])
        return self._frames(rest, now)
