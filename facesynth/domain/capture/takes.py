"""The takes of a capture manifest read, checked and put together into a corpus (paper III;
``facesynth ingest``).

The manifest (:mod:`.manifest`) is a CSV with the columns ``take, mocap, audio, alignment, transcript,
emotion, sentence, split, language`` and, for takes that need them, ``mapping, names, fps`` (paths
relative to the manifest); only ``take`` and ``mocap`` are required. ``mocap`` names a take of
any registered capture format (:func:`.readers.read_capture`): markers,
a Live Link Face CSV, another rig's curves (with ``mapping``, and ``names`` and ``fps`` for a
``.npy``) or a video (whose sound is the take's audio when ``audio`` is empty). Curve takes
pose ``--rig`` (the built-in rig by default); when every take was posed, their rest pose and
head pose are recorded with the markers.

A take with an empty ``alignment`` and a ``transcript`` is aligned with
:mod:`facesynth.domain.speech.alignment` (in its ``language``, a BCP-47 tag; empty:
``align.language``); one with audio and neither gets its phones recognised
from the audio (:func:`facesynth.domain.speech.recognition.recognize`, ``ingest.recognize_phones``),
as ``synthesize --audio`` does (audio in which no speech is found leaves the take without
phones, with a warning). A take without audio and alignment has no phones, and one without
audio no audio: ``normalize``, ``pca``, ``solve`` (on the normalized takes), ``rig-mesh`` and
``render`` (silent) accept such takes; ``build-db`` (and what needs a database) needs phone
timing, and ``head-motion`` audio. An empty ``emotion`` is neutral.
Phones are mapped to the Festival set; marker gaps stay NaN here.

Emotion: a take has its manifest ``emotion`` throughout, unless its TextGrid has an emotion
tier (``ingest.emotion_tiers``): then every phone has the emotion of the interval holding
its centre (labels as in the manifest, aliases allowed; an empty interval keeps the
manifest's). The per-phone emotion is what ``build-db`` gives each motion node and what
``evaluate`` asks the search for.

Rigid markers: the takes' readers may name the markers that move only with the head; the
stage prefers those a binding ``markers.csv`` next to the manifest marks (:meth:`Ingested.corpus`).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import AlignSettings, IngestSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import map_phones
from facesynth.base.progress import progress
from facesynth.domain.capture.manifest import ManifestRow
from facesynth.domain.capture.posing import CaptureTake
from facesynth.domain.capture.readers import CaptureOptions, read_capture
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.neutral import NeutralChoice
from facesynth.domain.speech.alignment import AlignmentFailed, align_robust
from facesynth.domain.speech.languages import ipa_phones, is_english
from facesynth.domain.speech.recognition import recognize
from facesynth.formats.audio import read_audio, resample
from facesynth.formats.labels import Segment, check_segments, read_phone_segments, read_textgrid
from facesynth.model.corpus import Corpus
from facesynth.model.tables import Phones, Takes

#: The sample rate recorded for a corpus none of whose takes has audio (no samples are stored).
NO_AUDIO_RATE = 16000

log = logging.getLogger(__name__)


def _segments_for(row: ManifestRow, settings: IngestSettings, align_settings: AlignSettings, samples: np.ndarray,
                  rate: int | None, where: str) -> tuple[list[Segment], list[str] | None]:
    """The take's phone segments (seconds): read from its alignment file, or its transcript
    aligned to ``samples`` (mono, ``rate`` Hz; None: the take has no audio) with ``align_settings``;
    and, for a transcript in another language than English, the IPA phone of each segment
    (:attr:`~facesynth.domain.speech.alignment.Alignment.ipa`; else None)."""
    if row.alignment is not None:
        if not row.alignment.exists():
            raise InputError(f"{where}: alignment file {row.alignment} not found; fix the manifest's alignment column.")
        return read_phone_segments(row.alignment, settings.phone_tiers), None
    if rate is None:  # read_manifest refuses such a row
        raise InputError(f"{where}: a transcript to align but no audio; give its audio or its phone timing.")
    aligned = align_robust(samples, rate, row.transcript, settings=align_settings, where=where)
    for warning in aligned.warnings:
        log.warning(warning)
    return aligned.phones, aligned.ipa


def phone_emotions(row: ManifestRow, segs: list[Segment], settings: IngestSettings) -> list[str]:
    """The emotion of every phone segment of ``row``: from its TextGrid's emotion tier at the
    phone's centre, else the manifest's emotion."""
    path = row.alignment
    if path is None or path.suffix.lower() != ".textgrid":
        return [row.emotion] * len(segs)
    tiers = {name.lower(): s for name, s in read_textgrid(path).items()}
    tier = next((tiers[n.lower()] for n in settings.emotion_tiers if n.lower() in tiers), None)
    if tier is None:
        return [row.emotion] * len(segs)
    aliases = {k.lower(): v for k, v in settings.emotion_aliases.items()}
    out = []
    for s in segs:
        centre = 0.5 * (s.start + s.end)
        interval = next((e for e in tier if e.start <= centre < e.end), None)
        label = (interval.label if interval is not None else "").strip().lower()
        if interval is None or not label:
            out.append(row.emotion)
            continue
        label = aliases.get(label, label)
        if label not in settings.emotions:
            raise InputError(f"{path}, emotion tier, {interval.start:.3f} s: unknown emotion {interval.label!r}; "
                             f"use one of {', '.join(settings.emotions)}.")
        out.append(label)
    return out


@dataclass
class Ingested:
    """Every take read (:func:`ingest`).

    markers : (F, M, 3) float32 mm; names : the M markers; fps : frames/s; takes, phones : the
    tables; audio : per take (samples, rate), a take without audio having no samples and rate
    None; rigid : the rigid markers the takes' readers name ([] for marker files); rest,
    known_rotation, known_translation : when every take was posed from curves on one rig, the
    rest pose (M, 3) and the head pose per frame ((F, 3, 3), (F, 3) mm), else None; recognized :
    the takes whose phones were recognised from their audio."""

    markers: np.ndarray
    names: list[str]
    fps: float
    takes: Takes
    phones: Phones
    audio: list[tuple[np.ndarray, int | None]]
    rigid: list[str]
    rest: np.ndarray | None
    known_rotation: np.ndarray | None
    known_translation: np.ndarray | None
    recognized: list[str]

    @property
    def missing_fraction(self) -> float:
        """The share of marker samples missing (gaps), 0 to 1."""
        return float(np.isnan(self.markers).any(axis=2).mean())

    @property
    def without_audio(self) -> list[str]:
        """The takes without audio."""
        return [self.takes.name[i] for i, (_, rate) in enumerate(self.audio) if rate is None]

    @property
    def without_phones(self) -> list[str]:
        """The takes without phone timing."""
        return [self.takes.name[i] for i in range(len(self.takes)) if not (self.phones.take == i).any()]

    def corpus(self, rigid: list[str]) -> Corpus:
        """The corpus of these takes with ``rigid`` as its rigid markers: the takes' audio resampled
        to the first take's rate (:data:`NO_AUDIO_RATE` when no take has audio) and laid end to end."""
        rate = next((r for _, r in self.audio if r is not None), NO_AUDIO_RATE)
        samples = [resample(s, r, rate) if r is not None else s for s, r in self.audio]
        audio_start = np.cumsum([0] + [len(s) for s in samples[:-1]])
        return Corpus(self.takes, self.phones, self.names, self.markers, self.fps,
                      np.concatenate(samples).astype(np.float32), audio_start,
                      np.array([len(s) for s in samples], np.int64), rate, rigid, self.rest, self.known_rotation,
                      self.known_translation)


def capture_options(settings: IngestSettings, rig: Rig | None = None) -> CaptureOptions:
    """The takes' capture options from ``[ingest]`` (a manifest row's columns override them)."""
    neutral, live_link = (NeutralChoice.parse(value, f"ingest.{key}") for key, value in
                          (("neutral", settings.neutral), ("live_link_neutral", settings.live_link_neutral)))
    for key, choice in (("neutral", neutral), ("live_link_neutral", live_link)):
        if choice.kind == "take":
            raise InputError(f"ingest.{key} {str(choice)!r}: a neutral take is named when solving "
                             "(facesynth solve --neutral take:NAME); at ingest use auto, off, frame:N or time:SECONDSs.")
    return CaptureOptions(rig=rig, mapping=Path(settings.curves_mapping) if settings.curves_mapping else None,
                          fps=settings.curves_fps or None, face_width_mm=settings.video_eye_corners_mm,
                          max_interpolated_s=settings.live_link_max_gap_s,
                          neutral=neutral, live_link_neutral=live_link)


def take_options(row: ManifestRow, defaults: CaptureOptions) -> CaptureOptions:
    """The capture options of one take: its manifest row's mapping, names and fps over ``defaults``;
    a video needs its own sound unless the row gives the audio."""
    return replace(defaults, mapping=row.mapping or defaults.mapping, names=row.names or defaults.names,
                   fps=row.fps or defaults.fps, need_audio=row.audio is None)


def _recognized(samples: np.ndarray, rate: int, align_settings: AlignSettings, where: str) -> list[Segment]:
    """The phones recognised from a take's audio; none (with a warning) when it holds no speech."""
    try:
        return list(recognize(samples, rate, settings=align_settings, where=where).phones)
    except AlignmentFailed as exc:
        log.warning("%s; the take has no phones.", str(exc).rstrip("."))
        return []


def ingest(rows: list[ManifestRow], settings: IngestSettings, align_settings: AlignSettings,
           options: CaptureOptions | None = None) -> Ingested:
    """Read and check every take (with ``options``, else those of ``settings``); a take with only
    a transcript is aligned with ``align_settings``, one with audio alone recognised (see the
    module docstring)."""
    markers, audio, starts, counts = [], [], [], []
    phone_take, phone_start, phone_end, phone_label, phone_emotion = [], [], [], [], []
    phone_ipa: list[str] = []
    names = fps = None
    options = options or capture_options(settings)
    rigid: list[str] = []
    rests, poses, recognized = [], [], []
    for i, row in enumerate(progress(rows, "ingest")):
        where = f"take {row.take!r} (manifest line {row.line})"
        for label, p in (("mocap", row.mocap), ("audio", row.audio)):
            if p is not None and not p.exists():
                raise InputError(f"{where}: {label} file {p} not found; fix the manifest's {label} column.")
        take = read_capture(row.mocap, take_options(row, options))
        own_audio = None
        if isinstance(take, CaptureTake):
            rigid = rigid or list(take.rigid)
            rests.append(take.rest)
            poses.append(take.head_pose)
            own_audio = take.audio
        else:
            rests.append(None)
            poses.append(None)
        if names is None or fps is None:  # the first take (they are set together)
            names, fps = take.names, take.fps
        elif take.names != names:
            extra = sorted(set(take.names) - set(names))
            lacking = sorted(set(names) - set(take.names))
            detail = f"extra {extra[:5]}, missing {lacking[:5]}" if extra or lacking else "same names in another order"
            raise InputError(f"{row.mocap}: marker names differ from the first take's ({detail}); every take needs the same markers.")
        elif abs(take.fps - fps) > 1e-6:
            raise InputError(f"{row.mocap}: frame rate {take.fps:g} Hz differs from the first take's {fps:g} Hz; resample the takes to one rate.")
        if np.isnan(take.positions).all():
            raise InputError(f"{row.mocap}: every marker sample is missing; the take is empty.")
        motion_s = take.positions.shape[0] / take.fps
        samples, rate = np.zeros(0, np.float32), None
        if row.audio is not None:
            samples, rate = read_audio(row.audio)
        elif own_audio is not None:  # a video's own sound
            samples, rate = own_audio
        if rate is not None:
            audio_s = len(samples) / rate
            if abs(audio_s - motion_s) > settings.max_audio_mismatch_s:
                what = f"{row.audio}: audio lasts {audio_s:.2f} s but the motion ({row.mocap})" if row.audio \
                    else f"{row.mocap}: its sound lasts {audio_s:.2f} s but its pictures"
                raise InputError(f"{what} {motion_s:.2f} s; trim or pad them to the same length (tolerance "
                                 f"{settings.max_audio_mismatch_s:g} s).")
        segs: list[Segment] = []
        ipa: list[str] | None = None
        source = str(row.alignment or row.audio or row.mocap)
        # the take's language column, else align.language
        take_align = replace(align_settings, language=row.language) if row.language else align_settings
        if row.alignment is not None or row.transcript:
            segs, ipa = _segments_for(row, settings, take_align, samples, rate, where)
            check_segments(segs, source)
        elif rate is not None and settings.recognize_phones:  # audio alone: the phones recognised from it
            segs = _recognized(samples, rate, take_align, source)
            if segs:
                recognized.append(row.take)
                check_segments(segs, source)
        if segs and segs[-1].end > motion_s + settings.max_audio_mismatch_s:
            raise InputError(f"{source}: the alignment ends at {segs[-1].end:.2f} s, after the motion ({motion_s:.2f} s); use the take's own alignment.")
        if segs and ipa is None and row.alignment is not None and not is_english(take_align.language):
            # a take's own alignment in another language: its labels are IPA
            labels, ipa = ipa_phones([s.label for s in segs], source, [s.start for s in segs], take_align.language)
        else:
            labels = map_phones([s.label for s in segs], source, [s.start for s in segs]) if segs else []
        starts.append(sum(counts))
        counts.append(take.positions.shape[0])
        markers.append(take.positions)
        audio.append((samples, rate))
        phone_take += [i] * len(segs)
        phone_start += [s.start for s in segs]
        phone_end += [s.end for s in segs]
        phone_label += labels
        phone_emotion += phone_emotions(row, segs, settings)
        phone_ipa += ipa if ipa is not None else [""] * len(segs)
    takes = Takes([r.take for r in rows], [r.emotion for r in rows], [r.sentence for r in rows],
                  [r.split for r in rows], [r.transcript for r in rows], np.array(starts), np.array(counts))
    phones = Phones(np.array(phone_take, np.int64), np.array(phone_start, np.float64), np.array(phone_end, np.float64),
                    phone_label, phone_emotion, phone_ipa if any(phone_ipa) else None)
    rest = rests[0]
    posed = rest is not None and all(r is not None and np.array_equal(r, rest) for r in rests) \
        and all(p is not None for p in poses)
    known_r = np.concatenate([p[0] for p in poses]).astype(np.float32) if posed else None  # type: ignore[index]
    known_t = np.concatenate([p[1] for p in poses]).astype(np.float32) if posed else None  # type: ignore[index]
    if names is None or fps is None:  # read_manifest refuses a manifest without takes
        raise InputError("the manifest lists no takes.")
    return Ingested(np.concatenate(markers).astype(np.float32), names, fps, takes, phones, audio, rigid,
                    rest if posed else None, known_r, known_t, recognized)


