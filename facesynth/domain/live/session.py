"""One live stream, independent of its transport: audio bytes and control messages in, frame
messages (JSON-ready dicts) out.

Control messages (JSON objects, docs/live.md):

- ``{"type": "start", "phones": "recognize" | "given", "emotion": name, "markers": bool,
  "language": "en"}``: optional, before any audio; ``given`` means the client sends the phone
  timings (a TTS engine) and the audio is not recognised: each phone must arrive within
  ``stream.pause_wait_s`` of its start, or the audio before it is taken as a pause (the phone
  then starts where the pause ends). A ``language`` (a BCP-47 tag) other than English says the
  given phones are IPA symbols (``"y"``, ``"ʁ"``, ``"ɔ̃"``; ``"sil"`` a pause), each played by its
  articulatory nearest English phone; recognised audio is a phone loop in every language.
- ``{"type": "phones", "phones": [{"phone": "HH", "start": 0.10, "end": 0.16}, ...], "final": false}``:
  phone timings in stream seconds, in order (``given`` mode); ``"final": true`` says they are
  the utterance's last, so nothing waits for a look-ahead past them.
- ``{"type": "emotion", "name": "happy"}``: the emotion of the phones from now on.
- ``{"type": "end"}``: the audio is complete; the remaining frames are sent.

Audio: 16-bit little-endian mono PCM at 16 kHz, in chunks of any size.
"""

from __future__ import annotations

import json
import re

import numpy as np

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.speech.languages import is_english
from facesynth.domain.voice.articulation import model_look_ahead_s

from .phones import SAMPLE_RATE, PhoneRecognizer, given_phones
from .synthesizer import Frame, LiveModel, LiveSynthesizer
from .voice_frames import VoiceFrames

#: A BCP-47 tag as a start message's ``language`` may give it (``en``, ``fr-CA``, ``cmn``, ``zh_Hans``).
_LANGUAGE_TAG = re.compile(r"[A-Za-z]{2,3}(?:[-_][A-Za-z0-9]{1,8})*")

#: Decimals of the weights and markers in a frame message.
DECIMALS = 4


class Session:
    """A stream's state. ``where`` names the stream in error messages."""

    def __init__(self, model: LiveModel, align: AlignSettings, where: str = "stream"):
        self.model, self.align, self.where = model, align, where
        self.synth = LiveSynthesizer(model)
        self.mode = "recognize"
        self.markers = False
        self.language = "en"  # the start message's: given phones in another language are IPA
        self.recognizer: PhoneRecognizer | None = None
        self.voice: VoiceFrames | None = None  # frames from the voice (recognize mode, stream.voice)
        self.samples = 0
        self._odd = b""
        self.started = False

    @property
    def time(self) -> float:
        """Seconds of audio received."""
        return self.samples / SAMPLE_RATE

    @property
    def sent(self) -> int:
        """Frames sent so far."""
        return self.voice.sent if self.voice is not None else self.synth.sent

    def hello(self) -> dict:
        """The first message a client gets: what the frames hold."""
        voice = self.model.voice_model
        return {"type": "hello", "fps": self.model.stream.fps, "method": self.model.stream.method,
                "lookahead_phones": self.model.stream.lookahead_phones, "sample_rate": SAMPLE_RATE,
                "voice": self.model.stream.voice,
                "voice_lookahead_s": None if voice is None else
                round(model_look_ahead_s(voice) + self.model.stream.voice_anticipation_s, 4),
                "arkit_names": list(self.model.arkit_names), "marker_names": list(self.model.marker_names),
                "emotions": self.model.emotions}

    def audio(self, pcm: bytes) -> list[dict]:
        """Audio bytes in; frame messages out."""
        if self.synth.finished:
            raise InputError(f"{self.where}: audio after 'end'; open a new stream for the next utterance.")
        self.started = True
        data = self._odd + pcm
        whole = len(data) - len(data) % 2
        self._odd = data[whole:]
        self.samples += whole // 2
        if self.mode == "recognize" and self.model.voice_model is not None:
            if self.voice is None:
                self.voice = VoiceFrames(self.model, self.model.voice_model, self.model.synth, self.synth.emotion)
            samples = np.frombuffer(data[:whole], "<i2").astype(np.float32) / 32768.0
            return self._frames(self.voice.push(samples, self.time))
        if self.mode == "recognize":
            if self.recognizer is None:
                self.recognizer = PhoneRecognizer(self.align, self.model.stream.recognition_hold,
                                                  self.model.stream.recognition_restart_s)
            for phone in self.recognizer.feed(data[:whole]):
                self.synth.add_phone(*phone)
        elif not self.synth.phones_complete:
            # given phones: audio that no phone has covered for stream.pause_wait_s is silence, so
            # its frames need not wait for the engine's next phone
            self.synth.extend_silence(self.time - self.model.stream.pause_wait_s)
        return self._frames(self.synth.step(self.time))

    def control(self, text: str) -> list[dict]:
        """A JSON control message in; frame messages out (``end``) or none."""
        try:
            message = json.loads(text)
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            reason = exc.msg if isinstance(exc, json.JSONDecodeError) else "not UTF-8 text"
            raise InputError(f"{self.where}: a text message must be a JSON object ({reason}).") from None
        if not isinstance(message, dict) or not isinstance(message.get("type"), str):
            raise InputError(f"{self.where}: a control message must be a JSON object with a 'type'.")
        kind = message["type"]
        if kind == "start":
            if self.started:
                raise InputError(f"{self.where}: 'start' must come before any audio or phones.")
            mode = message.get("phones", "recognize")
            if mode not in ("recognize", "given"):
                raise InputError(f"{self.where}: 'phones' of 'start' is 'recognize' or 'given', not {mode!r}.")
            self.mode = mode
            self.markers = bool(message.get("markers", False))
            if "language" in message:  # given phones are then IPA (audio is recognised as phones anyway)
                language = message["language"]
                if not isinstance(language, str) or not _LANGUAGE_TAG.fullmatch(language.strip()):
                    raise InputError(f"{self.where}: 'language' of 'start' must be a BCP-47 tag like en, de, fr or "
                                     f"cmn, not {language!r}.")
                self.language = language.strip()
            if "emotion" in message:
                self.synth.set_emotion(str(message["emotion"]))
            return []
        if kind == "emotion":
            self.synth.set_emotion(str(message.get("name")))
            if self.voice is not None:
                self.voice.set_emotion(self.synth.emotion)
            return []
        if kind == "phones":
            if self.mode != "given":
                raise InputError(f"{self.where}: phone timings need {{\"type\": \"start\", \"phones\": \"given\"}} first.")
            self.started = True
            for phone in given_phones(message.get("phones"), f"{self.where}, phones message",
                                      ipa=not is_english(self.language)):
                self.synth.add_phone(*phone)
            if message.get("final") is True:
                self.synth.phones_complete = True
            return self._frames(self.synth.step(self.time))
        if kind == "end":
            return self.end()
        raise InputError(f"{self.where}: unknown message type {kind!r}; use start, phones, emotion or end.")

    def end(self) -> list[dict]:
        """End of the stream: the remaining phones and frames."""
        if self.synth.finished:
            return []
        if self.voice is not None or (self.mode == "recognize" and self.model.voice_model is not None):
            self.synth.finished = True
            frames = self.voice.finish(self.time) if self.voice is not None else []
            return self._frames(frames) + [{"type": "end", "frames": self.sent}]
        if self.recognizer is not None:
            for phone in self.recognizer.end():
                self.synth.add_phone(*phone)
        # the phones cover the audio, as batch recognition tiles them
        if self.time > self.synth.known_until and not self.synth.phones_complete:
            self.synth.add_phone(PAU, self.synth.known_until, self.time)
        return self._frames(self.synth.finish(self.time)) + [{"type": "end", "frames": self.synth.sent}]

    def _frames(self, frames: list[Frame]) -> list[dict]:
        out = []
        for f in frames:
            msg = {"type": "frame", "index": f.index, "time": round(f.time, 6),
                   "arkit": np.round(f.arkit.astype(np.float64), DECIMALS).tolist()}
            if self.markers:
                msg["markers"] = np.round(f.markers.astype(np.float64), 2).reshape(-1).tolist()
            out.append(msg)
        return out
