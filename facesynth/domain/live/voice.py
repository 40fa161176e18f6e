"""Frames from what the voice already says: live audio to the mouth at the speed of speech.

With ``stream.voice = "articulation"`` a stream whose phones would be recognised from its audio
(``"phones": "recognize"``, the default) sends each output frame as soon as the audio up to its
time plus the articulation model's look-ahead (:func:`facesynth.domain.speech.articulation.model_look_ahead_s`,
46 ms for the packaged model) has arrived. The frame is decided then and never revised:

* the mouth is the voice's: the model's jawOpen, mouthFunnel and mouthPucker predictions
  (:class:`facesynth.domain.speech.articulation.StreamingPredictor`, frame by frame from 20 ms
  chunks, equal to the batch predictions) set those rig shapes, the jaw closing where the model's
  closure score rises above ``synthesize.voice_closure_threshold``;
* the rest of the face is the emotion's pose: the mean of the database's captured frames of the
  stream's emotion (the ``emotion`` control message changes it from the next frame), solved onto
  the built-in rig once per emotion, with its mouth shapes left to the voice.

No phone recogniser runs: a recognised phone settles a phone or more after it ends (300 ms and
more), long after the frames it could refine were sent, and recognition is what costs a stream
its CPU (docs/live.md). The phone-driven path (the DP on recognised phones, about a second late)
is ``stream.voice = "off"``; given phones (a TTS engine) always take it, with its guarantees.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.domain.speech.articulation import StreamingPredictor, model_look_ahead_s
from facesynth.model.articulation import ArticulationModel

from .core import Frame

#: The rig shapes the voice sets, by the articulation model's target of the same name.
VOICE_SHAPES = ("jawOpen", "mouthFunnel", "mouthPucker")
#: The closure score's rise (above the threshold) over which the jaw goes from open to closed.
CLOSURE_RAMP = 0.3


class VoiceFrames:
    """One stream's frames from its voice. ``model``: the stream's :class:`~facesynth.domain.live.core.LiveModel`
    (its ``voice_model``, the rig and the emotions' poses); :meth:`push` takes mono float samples at
    16 kHz and returns the frames the audio so far decides; :meth:`finish` the rest."""

    def __init__(self, model, voice_model: ArticulationModel, synth: SynthesizeSettings, emotion: str):
        self.model = model
        self.predictor = StreamingPredictor(voice_model, model.stream.fps)
        self.columns = {name: voice_model.target_names.index(name) for name in VOICE_SHAPES
                        if name in voice_model.target_names}
        self.closure = voice_model.target_names.index("closure") if "closure" in voice_model.target_names else None
        self.threshold = synth.voice_closure_threshold
        names = list(model.rig.shape_names)
        self.slots = {name: names.index(name) for name in self.columns if name in names}
        self.emotion = emotion
        self.sent = 0
        self.look_ahead_s = model_look_ahead_s(voice_model)
        self._last: np.ndarray | None = None

    def set_emotion(self, name: str) -> None:
        """The emotion of the frames from the next one on."""
        self.emotion = name

    def weights(self, predictions: np.ndarray) -> np.ndarray:
        """(k, E) rig weights for (k, Y) predictions: the emotion's pose with the voice's mouth."""
        base = self.model.emotion_pose(self.emotion)
        w = np.repeat(base[None], len(predictions), 0)
        open_share = np.ones(len(predictions))
        if self.closure is not None and self.threshold <= 1.0:
            open_share = 1.0 - np.clip((predictions[:, self.closure] - self.threshold) / CLOSURE_RAMP, 0.0, 1.0)
        for name, slot in self.slots.items():
            value = np.clip(predictions[:, self.columns[name]], 0.0, 1.0)
            w[:, slot] = value * open_share if name == "jawOpen" else value
        return w

    def _frames(self, predictions: np.ndarray, now: float) -> list[Frame]:
        if not len(predictions):
            return []
        w = self.weights(predictions)
        arkit = self.model.arkit(w)
        markers = self.model.markers_of(w)
        fps = self.model.stream.fps
        frames = [Frame(self.sent + k, (self.sent + k) / fps, arkit[k], markers[k], now) for k in range(len(w))]
        self.sent += len(w)
        return frames

    def push(self, samples: np.ndarray, now: float) -> list[Frame]:
        """The frames that the audio up to ``now`` (s received, ``samples`` the newest) decides."""
        return self._frames(self.predictor.push(samples), now)

    def finish(self, now: float) -> list[Frame]:
        """End of stream: the remaining frames, up to the audio's end."""
        return self._frames(self.predictor.finish(), now)
