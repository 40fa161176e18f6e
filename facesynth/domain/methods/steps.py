"""The steps every command that synthesizes shares, whatever the method (``synthesize``, ``batch``,
``evaluate``, ``tune``): reading the utterance, emotion names, the memory check, and the motion of
a method without motion nodes.

**The utterance** (:func:`read_utterance`): the phone timing of a TextGrid or ``.lab`` file, or the
speech aligned to its transcript, or recognised when there is none (:mod:`facesynth.domain.speech.recognition`).
**One transcript-mismatch policy**: when the alignment finds that a given transcript seems to lack
words the speech holds (or to say more than it), the motion is still made and the finding is a
warning (logged, and returned in :attr:`UtteranceInput.warnings`, which ``batch`` lists in its
summary). The motion follows the speech as far as the transcript covers it, and the user sees
where it does not; failing would only withhold a usable result. Audio with no speech at all, or
too short for its text, is still an error (:class:`~facesynth.domain.speech.alignment.AlignmentFailed`).

**Emotion names** (:func:`emotion_name`): case-insensitive, aliases too (``ingest.emotion_aliases``,
matched case-insensitively), as ``ingest`` reads a manifest.

**Limits**: readers ask :func:`facesynth.base.limits.current`; a command puts its ``[limits]`` in force
with :func:`facesynth.base.limits.using` (``batch`` carries them to its worker processes in the job).
**Memory**: :func:`synthesize` refuses work the method estimates to need more memory than is
available (:func:`facesynth.base.limits.require_memory`) before doing it.
"""

from __future__ import annotations

import dataclasses
import json
import logging
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from facesynth.base.config import AlignSettings, IngestSettings, settings_json
from facesynth.base.errors import InputError, UsageError
from facesynth.base.limits import require_memory
from facesynth.domain.postprocess.concatenation import downsample, frame_ranges
from facesynth.domain.search.constraints import read_constraints
from facesynth.domain.speech.alignment import Alignment
from facesynth.domain.speech.recognition import align_or_recognize
from facesynth.domain.speech.utterance import (
    Utterance,
    apply_emotions,
    emotion_name,
    given_spans,
    set_emotions,
    utterance,
)
from facesynth.domain.speech.utterance import read_utterance as read_phone_file
from facesynth.domain.voice import fusion
from facesynth.formats.audio import read_audio
from facesynth.model.head_motion import HeadMotion
from facesynth.model.motion import Motion, Provenance, SearchPath
from facesynth.model.motiondb import MotionDatabase

from . import Method, MethodSettings, Synthesis, SynthesisSummary

log = logging.getLogger(__name__)

#: The ``[synthesize]`` settings of the voice step (:mod:`facesynth.domain.voice.fusion`), recorded by a motion made with
#: the audio by a method whose own section is another.
VOICE_SETTINGS = ("loudness_weight", "loudness_smoothing_s", "loudness_lip_markers", "pinned_phones",
                  "voice_recognized", "voice_given", "articulation_model", "voice_weight", "voice_opening_map",
                  "voice_rounding_weight", "voice_closure_threshold", "voice_closing_threshold",
                  "voice_trust_window_s", "voice_trust_low", "voice_trust_high", "voice_snr_none", "voice_snr_full",
                  "voice_pin_recognized")


class DatabaseMethod(Method):
    """A member that reads the motion database itself (nothing to fit)."""

    def read(self, path: Path) -> MotionDatabase:
        return MotionDatabase.read(path)

__all__ = ["UtteranceInput", "emotion_name", "read_utterance", "constraints_for", "synthesize", "recorded_config",
           "check_memory", "frame_motion"]


@dataclass
class UtteranceInput:
    """An utterance read for synthesis: ``utterance``; ``alignment``, the
    :class:`~facesynth.domain.speech.alignment.Alignment` when it was aligned or recognised from audio (its phones
    and words, ``method``, ``recognized``), else None; ``warnings``, sentences for the user;
    ``audio``, the speech ((n,) float32 mono, rate Hz) when it was given, else None."""

    utterance: Utterance
    alignment: Alignment | None = None
    warnings: list[str] = field(default_factory=list)
    audio: tuple[np.ndarray, int] | None = None

    @property
    def recognized(self) -> bool:
        """Whether the phones were recognised from the audio (no transcript, no phones given)."""
        return self.alignment is not None and bool(self.alignment.recognized)


def read_utterance(ingest: IngestSettings, *, phones_path: Path | None = None, audio: Path | None = None,
                   text: str | None = None, align: AlignSettings | None = None, emotions_path: Path | None = None,
                   emotion: str | None = None, samples: tuple[np.ndarray, int] | None = None,
                   where: str | None = None, phones: Utterance | None = None,
                   spans: Sequence[tuple[float, float, str]] | None = None) -> UtteranceInput:
    """The utterance: phones from ``phones_path`` (or ``phones``, an utterance made in memory,
    which is copied, not changed), or ``audio`` aligned to ``text`` (recognised when
    ``text`` is None) with ``align``; ``samples`` ((n,) float32, rate Hz) when the audio is already
    read. With both ``phones_path`` and ``audio``, the phones are the file's (refused when they end
    more than ``ingest.max_audio_mismatch_s`` after the audio) and the audio is read for its
    loudness (:mod:`facesynth.domain.speech.loudness`). Emotions from the span file
    ``emotions_path`` (or ``spans``, (start_s, end_s, emotion) triples), or one ``emotion`` name for
    every phone, or neutral. ``where`` names the audio in messages (default its path)."""
    if phones_path is not None and phones is not None:
        raise TypeError("read_utterance: give the phones as a file or as an utterance, not both")
    if (phones_path is not None or phones is not None) and text is not None:
        raise UsageError("--text is aligned to --audio; with the phones given by --phonemes, leave out --text.")
    if sum(x is not None for x in (emotions_path, emotion, spans)) > 1:
        raise UsageError("give one emotion for the whole utterance or an emotions file, not both.")
    aligned = None
    warnings: list[str] = []
    data: np.ndarray | None = None
    rate = 0
    if audio is not None:

        data, rate = samples if samples is not None else read_audio(audio)
    if phones_path is not None or phones is not None:
        if phones_path is not None:
            utt = read_phone_file(phones_path, ingest.phone_tiers)
        else:
            assert phones is not None
            utt = dataclasses.replace(phones, emotions=list(phones.emotions))
        if data is not None:
            end, audio_s = float(utt.ends[-1]), len(data) / rate
            if end > audio_s + ingest.max_audio_mismatch_s:
                timing = phones_path if phones_path is not None else "given"
                raise InputError(f"the phone timing {timing} ends at {end:.2f} s, after the audio {audio} "
                                 f"({audio_s:.2f} s, ingest.max_audio_mismatch_s = {ingest.max_audio_mismatch_s:g} s "
                                 "allowed); give the phone timing of this audio.")
    elif audio is not None:

        if align is None:
            raise TypeError("read_utterance: aligning audio needs the [align] settings")
        assert data is not None
        aligned = align_or_recognize(data, rate, text, settings=align, where=where or str(audio))
        if aligned.recognized:
            log.info("%s: recognised: %s", where or audio, aligned.recognized)
        warnings = list(aligned.warnings)
        for warning in warnings:  # the one mismatch policy: a warning, never a failure
            log.warning(warning)
        segs = aligned.phones
        utt = utterance([s.label for s in segs], [s.start for s in segs], [s.end for s in segs], ipa=aligned.ipa)
    elif text is not None:
        raise UsageError("--text says what --audio says; give --audio too (or the phones with --phonemes).")
    else:
        raise UsageError("give the utterance's phones with --phonemes, or the speech with --audio (and --text).")
    if emotions_path is not None:
        apply_emotions(utt, emotions_path, ingest.emotions, ingest.emotion_aliases)
    elif spans is not None:
        set_emotions(utt, given_spans(spans), ingest.emotions, ingest.emotion_aliases)
    elif emotion is not None:
        name = emotion_name(emotion, ingest.emotions, ingest.emotion_aliases, where or "the emotion")
        utt.emotions = [name] * len(utt)
    return UtteranceInput(utt, aligned, warnings, None if data is None else (data, rate))


def constraints_for(method: Method, source, path: Path | None, utt: Utterance) -> dict[int, int]:
    """The motion-node constraints of ``path`` for ``utt`` ({phone index: node}); refused in one
    sentence for a method that takes none, before the file is read."""
    if path is None:
        return {}
    method.refuse_constraints({0: 0})
    return read_constraints(path, utt, source.nodes.phone)


def synthesize(method: Method, source, utt: Utterance, settings: MethodSettings, constraints: dict[int, int] | None = None,
               *, prepared=None, source_where: str = "the source", where: str = "the utterance",
               audio: tuple[np.ndarray, int] | None = None, recognized: bool = False) -> Synthesis:
    """``method``'s motion of ``utt`` from ``source``, after the memory check (its message names
    ``source_where``; the method's own messages name the utterance, ``where``). With the
    utterance's ``audio`` ((n,) mono samples, rate Hz), the mouth then takes what the voice says
    (:mod:`facesynth.domain.voice.fusion`: its articulation or its loudness, by whether the
    phones were ``recognized`` from that audio); a motion without the lip markers is left as it
    is, and the summary's ``warnings`` say so."""
    method.refuse_constraints(constraints)
    check_memory(method, source, utt, settings, source_where)
    result = method.synthesize(source, utt, settings, constraints, prepared=prepared, where=where)
    if audio is not None:
        t0 = time.perf_counter()
        result.motion, done, warning = fusion.apply(result.motion, *audio, utt.starts, utt.ends, list(utt.phones),
                                                   settings.synthesize, recognized=recognized)
        phases = {**result.summary.phases, "voice_s": time.perf_counter() - t0}
        result.summary = dataclasses.replace(result.summary, voice=done.path, phases=phases)
        if warning is not None:
            log.warning("%s: %s", where, warning)
            result.summary = dataclasses.replace(result.summary, warnings=result.summary.warnings + (warning,))
    return result


def recorded_config(method: Method, settings: MethodSettings, with_audio: bool) -> str:
    """The ``config`` a motion made by ``method`` records (JSON): its settings section, and, with
    the audio given to a method whose section is not ``[synthesize]`` (``trajectory``), the
    settings of the voice step that moved its mouth as ``synthesize.<name>`` keys."""
    section = method.recorded_settings(settings)
    config = json.loads(settings_json(section))
    if with_audio and section is not settings.synthesize:
        s = settings.synthesize
        for name in VOICE_SETTINGS:
            value = getattr(s, name)
            config[f"synthesize.{name}"] = list(value) if isinstance(value, tuple) else value
    return json.dumps(config, sort_keys=True)


@dataclass
class Synthesized:
    """A motion made and what its artifact records.

    motion: the :class:`~facesynth.model.motion.Motion` (with its search path and provenance).
    summary: what the method reports about it.
    config: the JSON its artifact records as ``config`` (:func:`recorded_config`).
    """

    motion: Motion
    summary: SynthesisSummary
    config: str


def synthesize_utterance(member: Method, source, read: UtteranceInput, settings: MethodSettings,
                         constraints: dict[int, int] | None = None, *, head: HeadMotion | None = None,
                         source_where: str = "the source", where: str = "the utterance") -> Synthesized:
    """What ``facesynth synthesize`` and :func:`facesynth.synthesize` make: ``member``'s motion of
    the utterance ``read`` from ``source`` (its database or fitted model, read), after the shared
    checks (:func:`synthesize`, with the utterance's audio), with ``head``'s head motion instead of
    the source's when given. Messages name ``source_where`` and ``where``."""
    result = synthesize(member, source, read.utterance, settings, constraints, source_where=source_where,
                        where=where, audio=read.audio, recognized=read.recognized)
    motion = result.motion
    if head is not None:
        motion.head_rotation, motion.head_translation = head.at(np.arange(len(motion.markers)) / motion.fps)
    return Synthesized(motion, result.summary, recorded_config(member, settings, read.audio is not None))


def write_motion(made: Synthesized, out: Path, records: list[dict], *, overwrite: bool = False) -> None:
    """Write the ``motion`` artifact of ``made`` at ``out``, recording ``records`` (the inputs'
    :func:`~facesynth.model.artifacts.input_record`, in :func:`motion_inputs`' order)."""
    made.motion.write(out, config=made.config, records=records, overwrite=overwrite)


def motion_inputs(source: Path | None, phones: Path | None = None, emotions: Path | None = None,
                  constraints: Path | None = None, audio: Path | None = None, head_motion: Path | None = None,
                  articulation_model: str = "") -> list[Path]:
    """The files a synthesized motion records as its inputs, in this order; the ones not given are
    left out. ``articulation_model``: ``synthesize.articulation_model``, recorded with the audio
    (a performer's own voice model; the packaged one, empty, is part of facesynth)."""
    model = Path(articulation_model) if audio is not None and articulation_model else None
    return [Path(p) for p in (source, phones, emotions, constraints, audio, head_motion, model) if p is not None]


def check_memory(method: Method, source, utt: Utterance, settings: MethodSettings, where: str) -> None:
    """Refuse (one sentence naming ``where``, the source) when ``method``'s synthesis of ``utt``
    needs more memory than is available."""
    need = method.memory_estimate(source, utt, settings)
    if need:
        require_memory(need, method.memory_what(source, utt), where)


def frame_motion(name: str, utt: Utterance, markers_capture: np.ndarray, coefficients: np.ndarray | None,
                 capture_fps: float, output_fps: float, marker_names: list[str], reference: np.ndarray,
                 node_phone: list[str], node_emotion: list[str], device: str):
    """The ``motion`` of a method without motion nodes (``mean``, ``coarticulation``), fields as the
    searches write them: markers_capture (F, M, 3) mm at ``capture_fps``, down-sampled to
    ``output_fps``; coefficients (F, K) or None; ``path/node`` and the provenance's node, take and
    source frame -1 (no node, no source frame), ``node_phone`` / ``node_emotion`` what the method
    used for each phone, the cost terms zero; ``provenance.step`` the input phone of each frame.
    The head does not move (identity rotation, zero translation)."""
    ranges = frame_ranges(utt.starts, utt.ends, capture_fps)
    n_capture = len(markers_capture)
    step = np.zeros(n_capture, np.int64)
    for t, (a, b) in enumerate(ranges):
        step[a:b] = t
    u = len(utt)
    zeros = np.zeros(u, np.float32)
    path = SearchPath(np.full(u, -1, np.int64), list(utt.phones), list(utt.emotions), list(node_phone),
                      list(node_emotion), np.asarray(utt.starts, float), np.asarray(utt.ends, float),
                      {"tc": zeros, "oc": zeros.copy(), "emp": zeros.copy(), "block": zeros.copy()}, 0.0, 0, name,
                      device, f"the {name} method computes each frame on the host")
    none = np.full(n_capture, -1, np.int64)
    provenance = Provenance(none, none.copy(), [], none.copy(), step, np.zeros(n_capture, bool), capture_fps)
    markers = downsample(np.asarray(markers_capture, np.float32), capture_fps, output_fps)
    n_out = len(markers)
    rotation = np.repeat(np.eye(3, dtype=np.float32)[None], n_out, axis=0)
    return Motion(markers, output_fps, np.asarray(markers_capture, np.float32), capture_fps, list(marker_names),
                  np.asarray(reference, np.float32), rotation, np.zeros((n_out, 3), np.float32),
                  None if coefficients is None else np.asarray(coefficients, np.float32), path, provenance)


def chosen_method(method: str | None, synth) -> str:
    """The member ``synthesize``, ``batch`` and ``tune`` run: ``method`` (``--method``), else
    ``synthesize.method``; where that is ``dp``, the deprecated ``synthesize.search`` still picks
    the greedy search (``synth``: the ``[synthesize]`` settings)."""
    name = method or synth.method
    return synth.search if name == "dp" else name


def deprecated_search(method: str | None, search: str | None, synth, configured: bool) -> tuple[str, list[str]]:
    """The member a command line with the deprecated ``--search`` (``search``) or a configured
    ``synthesize.search`` (``configured``: given in a ``--config`` file or a ``--set``) runs, and
    the warnings naming the new names. ``--search`` is ``--method``'s old name for the two
    searches; with ``--method dp`` (or none) it picks the search, as before."""
    warnings = []
    if configured:
        warnings.append(f"synthesize.search is deprecated and will go in a later release; set synthesize.method = "
                        f"\"{synth.search}\" instead.")
    if search is None:
        return chosen_method(method, synth), warnings
    warnings.append(f"`--search` is deprecated and will go in a later release; use `--method {search}`.")
    if method not in (None, "dp"):
        raise UsageError(f"--search chooses how the motion database is searched; the {method} method does not "
                         "take it: drop --search or use --method dp.")
    return search, warnings
