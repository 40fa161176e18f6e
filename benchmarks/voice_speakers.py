"""The audio path on voices it was not fitted on: every articulation model is fitted on some
speakers and scored on the others (leave one speaker out), with intervals that resample speakers.
Prints JSON.

Data (real voices only are scored; ``--work`` caches everything per utterance):

- ``--facegood DIR``: FACEGOOD's seven takes of one performer (laid out as for
  ``benchmarks/real_speech_lipsync.py``; speaker ``facegood/shirley``, Mandarin, ARKit-like
  curves: the mouth opening, jawOpen, mouthFunnel, mouthPucker).
- ``--speech-data DIR``: any number of sources laid out as ``<source>/<speaker>/<utt>.wav`` with
  ``<utt>.npz`` (``times`` s, ``opening``, optional ``jaw`` and ``rounding``, any unit; an
  optional ``<utt>.TextGrid`` with the spoken phones makes the given-phones modes scoreable),
  a source read once its ``READY-<source>`` file exists in DIR. ``speakers.json`` (optional:
  a list of ``{"source", "speaker", "sex", "language", ...}``) labels the speakers; a source
  ``facegood`` there is skipped when ``--facegood`` is given (read with all its channels).
- ``--synthetic N``: N synthetic speakers made from the training speakers' voices by
  :mod:`facesynth.domain.voice.synthetic` (vocal-tract length, pitch, microphone): training only, never
  scored (they teach invariance; they are no evidence).

Per held-out speaker (every real speaker in turn), the articulation model is fitted on every other
real speaker (plus the synthetic speakers made of *their* voices), with the settings of
:func:`facesynth.domain.voice.articulation.fit` (``--variant`` changes them, below), every
training speaker weighing alike however long it was heard (``--speaker-weights equal``; ``sources``:
every source alike, its speakers alike within it; ``frames``: each frame alike, as the releases
before last fitted). The targets
of each training speaker are its curves mapped so that its 5th..95th percentiles fall on FACEGOOD's
(the units live frames use); a curve a source lacks is left out of that target's fit.

Modes scored on the held-out speaker's utterances (its first ``--score-seconds``), all from the same phones recognised from the
audio (facesynth's own, as ``synthesize --audio`` recognises them) and the same motion the DP made
from them on the built-in actress's database (``small`` preset, seed 0), at 30 frames/s:

- ``default``: ``synthesize --audio`` as configured (``synthesize.voice_recognized`` and its
  settings), the fold's model as ``synthesize.articulation_model``; the voice step is
  :func:`facesynth.domain.voice.fusion.apply` run on the DP's motion, as ``synthesize`` runs it.
- ``articulation``, ``loudness``, ``phones``: the same with ``voice_recognized`` =
  articulation, loudness (the release before), off (the recognised phones alone).
- ``given_articulation``, ``given_loudness``, ``given_phones``: where the utterance comes with its
  spoken phones (a TextGrid) or its text (``--texts``; a GRID clip's from its file name, which
  spells its sentence), the same modes of ``synthesize.voice_given`` on those phones (the text
  aligned to the audio, as ``synthesize --audio --text``); ``given_packaged``: the articulation
  path with the packaged model (as ``packaged`` below).
- ``openfacefx``: openfacefx on the recognised phones (its inner-lip gap on the built-in rig).
- ``energy``: the loudness alone (log RMS, 0.1 s); ``voice``: the fold model's predicted opening;
  ``voice_jaw``: its predicted jawOpen.
- ``live``: the mouth ``stream`` sends with ``stream.voice = "articulation"``
  (:class:`facesynth.domain.live.voice_frames.VoiceFrames`, 20 ms chunks, the fold's model), as its
  inner-lip gap; ``live_jaw``: its jawOpen weight; ``live_packaged``, ``live_packaged_jaw``: the same
  with the packaged model.
- ``live_phones``: the mouth ``stream`` sends with ``stream.voice = "off"`` (the phones
  pocketsphinx's phone loop recognises as the audio arrives, through the live DP), its inner-lip
  gap; ``live_default``: ``live_packaged`` or ``live_phones``, as ``stream.voice`` is configured.
- ``live anticipation=S``, ``live_packaged anticipation=S`` (``--live-anticipation``): ``live`` and
  ``live_packaged`` with ``stream.voice_anticipation_s = S`` (each frame S later, its mouth free to
  move S ahead of its sound).
- ``default_jaw``, ``packaged_jaw``, ``phones_jaw``: the ARKit jawOpen an export (Live Link, an ARKit
  CSV) carries for ``default``, ``packaged`` and ``phones``: the motion solved onto the built-in rig
  (``solve``'s settings); ``openfacefx_jaw``: openfacefx's own jawOpen. Scored against the real
  mouth opening, as every mode.
- ``packaged``: ``default`` with the packaged model (within-speaker on the speakers it was fitted
  on; with ``--packaged-folds`` such a speaker is scored by the packaged fit refitted without it).

Features (``--features``, with ``--no-chain``; ``benchmarks/voice_features.py`` compares the runs):
``mel`` as shipped; ``envelope`` the bands of the cepstrally liftered envelope (no pitch);
``delta`` the bands' slopes (no channel); ``vtln`` each voice's spectrum read at its vocal-tract
warp against the fold's training voices (``--warp-per utterance`` or ``speaker``).

Scores: Pearson r of each mode's mouth opening against the real one in windows of about
``--window-s`` (an utterance shorter than a window is one window; frames where the real curve is
unknown are left out), averaged per speaker; pooled = the mean over speakers (each speaker
counts once), with a 95% bootstrap interval that resamples speakers (2000 resamples, seed 0), and
paired differences (default minus each mode) on the same resamples. With fewer than three
scored speakers there is no interval (``null``). Closures (``closures``, and within
``never_heard_by_packaged``): the deep minima of the real mouth opening and of each mode's, as
``benchmarks/real_speech_lipsync.py`` finds them (the curve scaled to its 5th..95th percentiles,
minima below ``--closure-depth`` standing out by ``--closure-prominence``), met within
``--closure-tolerance-frames``; recall = the real closures met, precision = the mode's closures
met, each summed over the speakers' scored utterances, with intervals resampling speakers (EMA
sensors and tracked lips: these minima are the lips closing or nearly).

    python benchmarks/voice_speakers.py --facegood FACEGOOD_DIR [--speech-data DIR] --work WORK \\
        [--synthetic 4] [--variant NAME] [--texts benchmarks/voice_texts.json] > benchmarks/voice_speakers.json
"""

from __future__ import annotations

import argparse
import functools
import hashlib
import json
import sys
import time
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import Config, settings_json
from facesynth.base.errors import InputError
from facesynth.base.hashing import sha256_of
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.speech.loudness import envelope, lip_gaps
from facesynth.domain.voice import articulation as A
from facesynth.domain.voice import tract
from facesynth.formats.audio import read_audio

sys.path.insert(0, str(Path(__file__).resolve().parent))

import real_speech_lipsync as bench  # noqa: E402  (its loaders, database and openfacefx)

FPS = bench.FPS
#: The model's targets (as benchmarks/voice_articulation.py; the fusion reads opening, closure,
#: closing, mouthFunnel, mouthPucker; live frames jawOpen, mouthFunnel, mouthPucker).
TARGETS = ("opening", "closure", "closing", "jawOpen", "mouthFunnel", "mouthPucker")
#: Every mode, in table order (module docstring).
MODES = ("default", "articulation", "loudness", "phones", "openfacefx", "energy", "voice", "voice_jaw", "live",
         "live_jaw", "live_packaged", "live_packaged_jaw", "live_phones", "live_default",
         "packaged", "default_jaw", "packaged_jaw", "phones_jaw", "openfacefx_jaw", "given_default", "given_articulation", "given_loudness", "given_phones", "given_packaged")
#: The exported jaw of a voice mode against the phones' and openfacefx's (paired differences).
JAW_PAIRS = {lead: ((lead, "phones_jaw"), (lead, "openfacefx_jaw"), (lead, live))
             for lead, live in (("default_jaw", "live_jaw"), ("packaged_jaw", "live_packaged_jaw"))}
FACEGOOD_SPEAKER = "facegood/shirley"
#: FACEGOOD's takes used for no choice (docs/real-speech.md).
FACEGOOD_FAIR = ("1114_2_04", "1114_2_05", "1114_3_15")
#: Settings of the voice step only (not of the phones' motion the cache holds).
VOICE_STEP_SETTINGS = ("loudness_weight", "loudness_smoothing_s", "voice_recognized", "voice_given",
                       "voice_snr_none", "voice_snr_full", "voice_activity", "articulation_model", "voice_weight",
                       "voice_rounding_weight", "voice_closure_threshold", "voice_closing_threshold",
                       "voice_trust_window_s", "voice_trust_low", "voice_trust_high", "voice_pin_recognized",
                       "articulation_prior")


@dataclass
class Utt:
    """One utterance of a real speaker: audio, the real curves (n,) at FPS (NaN where unknown)."""

    source: str
    speaker: str
    name: str
    wav: Path
    samples: np.ndarray
    rate: int
    n: int
    real: dict[str, np.ndarray]
    given_phones: Path | None = None
    #: what it says (``--texts``; GRID's from its file name): the text-and-audio modes align to it
    text: str | None = None
    #: a real voice (scored) or the virtual actress's synthetic one (training only)
    real_voice: bool = True
    raw: np.ndarray = field(default_factory=lambda: np.zeros((0, A.N_FEATURES), np.float32))
    #: raw features of synthetic speakers saying it (:func:`synthetic_features`)
    synthetic: list[np.ndarray] = field(default_factory=list)

    @property
    def key(self) -> str:
        return f"{self.speaker}/{self.name}"


# ---------------------------------------------------------------- data

def facegood_utterances(data: Path) -> list[Utt]:
    """FACEGOOD's takes as utterances of one speaker, the takes used for no choice first (the
    actress and the loudness step were calibrated on 1114_2_01..03; a capped score reads the others)."""
    names, table = bench.channel_names(data), bench.read_table()
    out = []
    for wav in sorted((data / "wav").glob("*.wav"), key=lambda p: (p.stem not in FACEGOOD_FAIR, p.stem)):
        take = wav.stem
        values = np.asarray(bench.load_npy(data / "bs_value_npy" / f"bs_value_{take}.npy"), np.float64)
        samples, rate = read_audio(wav)
        n = min(len(values), int(np.floor(len(samples) / rate * FPS)))
        curves = bench.real_curves(values, names, table)
        real = {c: curves[c][:n] for c in ("opening", "jawOpen", "mouthFunnel", "mouthPucker")}
        out.append(Utt("facegood", FACEGOOD_SPEAKER, take, wav, samples, rate, n, real))
    return out


#: Sources prepared apart that hold more recordings of another source's corpus and speakers
#: (``benchmarks/speaker_data.py``: ``grid_more`` holds more GRID clips of ``grid``'s speakers): their
#: utterances count as that source's, so a speaker left out is left out with all its clips.
SAME_CORPUS = {"grid_more": "grid"}


def speech_data_utterances(root: Path, skip: tuple[str, ...] = (), only: list[str] | None = None) -> list[Utt]:
    """The utterances of every source of ``root`` whose READY-<source> marker exists (those of ``only``
    where given; never those of ``skip``), a source of :data:`SAME_CORPUS` as its corpus's."""
    out = []
    for ready in sorted(root.glob("READY-*")):
        folder = ready.name[len("READY-"):]
        source = SAME_CORPUS.get(folder, folder)
        if source in skip or folder in skip or (only is not None and source not in only and folder not in only):
            continue
        for npz in sorted((root / folder).glob("*/*.npz")):
            wav = npz.with_suffix(".wav")
            if not wav.exists():
                continue
            with np.load(npz, allow_pickle=False) as z:
                times = np.asarray(z["times"], np.float64)
                curves = {"opening": z["opening"]}
                if "jaw" in z.files:
                    curves["jawOpen"] = z["jaw"]
                if "rounding" in z.files:
                    curves["mouthPucker"] = z["rounding"]
            samples, rate = read_audio(wav)
            if samples.ndim > 1:
                samples = samples.mean(1)
            n = int(np.floor(len(samples) / rate * FPS))
            t = np.arange(n) / FPS
            real = {}
            for c, v in curves.items():
                v = np.asarray(v, np.float64)
                ok = np.isfinite(v)
                if ok.sum() < 3:
                    continue
                x = np.interp(t, times[ok], v[ok])
                x[(t < times[ok][0] - 0.5 / FPS) | (t > times[ok][-1] + 0.5 / FPS)] = np.nan
                real[c] = x
            if "opening" not in real or n < 10:
                continue
            given = npz.with_suffix(".TextGrid")
            out.append(Utt(source, f"{source}/{npz.parent.name}", npz.stem, wav, samples, rate, n, real,
                           given if given.exists() else None))
    return out


#: GRID's sentences are its file names: command, colour, preposition, letter, digit, adverb
#: (Cooke et al. 2006), one letter each (the digit a number, z for zero).
GRID_WORDS = ({"b": "bin", "l": "lay", "p": "place", "s": "set"}, {"b": "blue", "g": "green", "r": "red", "w": "white"},
              {"a": "at", "b": "by", "i": "in", "w": "with"}, None,
              {**{str(i): w for i, w in enumerate("zero one two three four five six seven eight nine".split())}, "z": "zero"},
              {"a": "again", "n": "now", "p": "please", "s": "soon"})


def grid_text(name: str) -> str | None:
    """What a GRID clip says, from its name (``bbaf2n`` -> "bin blue at f two now"; a prefix before
    the last ``_`` is ignored); None for a name that is not a GRID sentence code."""
    code = name.rsplit("_", 1)[-1].lower()
    if len(code) != 6:
        return None
    words = []
    for ch, table in zip(code, GRID_WORDS):
        if table is None:
            if not ch.isalpha():
                return None
            words.append(ch)
        elif ch in table:
            words.append(table[ch])
        else:
            return None
    return " ".join(words)


def actress_utterances(work: Path, lip_markers) -> list[Utt]:
    """The built-in actress's takes (``small`` preset, seed 0: the benchmark's database corpus) as the
    training-only speaker ``actress``: her synthetic voice, her inner-lip gap as the opening."""
    from facesynth.domain.retarget import facial_solve
    from facesynth.model.corpus import Corpus
    from facesynth.model.frames import NormalizedFrames

    corpus, normalized = Corpus.read(work / "corpus.h5"), NormalizedFrames.read(work / "normalized.h5")
    out = []
    for i, name in enumerate(corpus.takes.name):
        a, count = int(corpus.audio_start[i]), int(corpus.audio_count[i])
        if count == 0:
            continue
        motion = facial_solve.take_motion(normalized, name, FPS, "the actress's frames")
        samples = np.asarray(corpus.audio[a:a + count], np.float64)
        n = min(len(motion.markers), int(np.floor(count / corpus.sample_rate * FPS)))
        gap = lip_gaps(motion.markers[:n], list(motion.marker_names), tuple(lip_markers)).astype(np.float64)
        out.append(Utt("actress", "actress", name, work / "corpus.h5", samples, corpus.sample_rate, n,
                       {"opening": gap}, real_voice=False))
    return out


def reference_ranges(utts: list[Utt]) -> dict[str, tuple[float, float]]:
    """{target: (p5, p95)} of FACEGOOD's curves: the units every speaker's targets are mapped to."""
    out = {}
    for c in ("opening", "jawOpen", "mouthFunnel", "mouthPucker"):
        v = np.concatenate([u.real[c] for u in utts if c in u.real])
        out[c] = tuple(float(q) for q in np.nanpercentile(v, [5, 95]))
    return out


def speaker_targets(utts: list[Utt], ref: dict[str, tuple[float, float]]) -> list[np.ndarray]:
    """Per utterance of one speaker, its (n, len(TARGETS)) targets: each curve mapped so that the
    speaker's 5th..95th percentiles land on ``ref``'s; the closure scores made of the opening."""
    scale = {}
    for c, (lo, hi) in ref.items():
        v = [u.real[c] for u in utts if c in u.real]
        if v:
            a, b = np.nanpercentile(np.concatenate(v), [5, 95])
            scale[c] = (a, b, lo, hi)
    out = []
    for u in utts:
        cols = []
        for c in TARGETS:
            if c in ("closure", "closing"):
                cols.append(A.closure_target(u.real["opening"], FPS, kind=c))
            elif c in u.real and c in scale and scale[c][1] > scale[c][0]:
                a, b, lo, hi = scale[c]
                cols.append(lo + (u.real[c] - a) * (hi - lo) / (b - a))
            else:
                cols.append(np.full(u.n, np.nan))
        out.append(np.stack(cols, 1))
    return out


# ---------------------------------------------------------------- the chain, cached per utterance

def _digest(*parts: bytes) -> str:
    return hashlib.sha256(b"\0".join(parts)).hexdigest()[:16]


#: ``--set`` overrides of the run (``SECTION.KEY=VALUE``), in every setting the run reads.
OVERRIDES: list[str] = []


@functools.lru_cache(maxsize=1)
def _phones_config() -> Config:
    """The settings the phones' motion is made with: the voice step off (read once per run)."""
    return Config.load(overrides=(*OVERRIDES, "synthesize.voice_recognized=off", "synthesize.voice_given=off"))


def phones_motion(db_path: Path, u: Utt, work: Path, given: bool = False):
    """(Motion of the DP on the phones, (starts, ends, phones)) of ``u``: its phones recognised from the
    audio as ``synthesize --audio`` does (or its given phones), the motion without the voice step;
    cached in ``work`` by the audio, the settings and the database."""
    import facesynth
    from facesynth.model.motion import Motion

    folder = work / "utts" / u.key
    folder.mkdir(parents=True, exist_ok=True)
    config = _phones_config()
    tag = ("text" if u.text else "given") if given else "recognized"
    # the voice step's settings do not change the phones' motion (the voice is off here)
    synth = {k: v for k, v in json.loads(settings_json(config.settings("synthesize"))).items()
             if k not in VOICE_STEP_SETTINGS}
    said = (u.text.encode() if u.text else u.given_phones.read_bytes()) if given else b""  # type: ignore[union-attr]
    digest = _digest(u.wav.read_bytes(), said, tag.encode(),
                     json.dumps(synth, sort_keys=True).encode(),
                     settings_json(config.settings("align")).encode(), sha256_of(db_path).encode())
    motion_file, phones_file = folder / f"motion.{tag}.{digest}.h5", folder / f"phones.{tag}.{digest}.json"
    if not motion_file.exists() or not phones_file.exists():
        if given and u.text:  # synthesize --audio --text: the phones aligned to what is said
            utt = facesynth.utterance_from_audio(u.wav, text=u.text, config=config)
        elif given:
            utt = facesynth.utterance_from_phones(u.given_phones, audio=u.wav, config=config)
        else:
            utt = facesynth.utterance_from_audio(u.wav, config=config)
        facesynth.synthesize(db_path, utt, config=config, output=motion_file, overwrite=True)
        phones_file.write_text(json.dumps({"starts": [float(x) for x in utt.starts], "ends": [float(x) for x in utt.ends],
                                           "phones": list(utt.phones)}))
    p = json.loads(phones_file.read_text())
    return Motion.read(motion_file), (np.array(p["starts"]), np.array(p["ends"]), list(p["phones"]))


def voice_motion(motion, u: Utt, phones, settings, model_path: Path, recognized: bool, path: str, **changes):
    """``motion`` after the voice step ``path`` with the model at ``model_path`` (and the synthesize
    settings ``changes``), as ``synthesize`` runs it."""
    from facesynth.domain.voice import fusion

    s = replace(settings, articulation_model=str(model_path), voice_recognized=path, voice_given=path, **changes)
    moved, _, _ = fusion.apply(motion, u.samples, u.rate, phones[0], phones[1], phones[2], s, recognized=recognized)
    return moved


def voice_step(motion, u: Utt, phones, settings, model_path: Path, recognized: bool, path: str, **changes):
    """The mouth opening (n,) of ``motion`` after the voice step (:func:`voice_motion`)."""
    return opening_of(voice_motion(motion, u, phones, settings, model_path, recognized, path, **changes), settings, u.n)


def solved_jaw(motion, rig, solve_settings, n: int) -> np.ndarray:
    """The ARKit jawOpen (n,) at FPS that ``solve`` and an ARKit export (Live Link, a CSV) give
    ``motion`` on the built-in ``rig`` (bound to the actress's markers)."""
    from facesynth.domain.retarget.solve import solve_motion

    weights, _, _ = solve_motion(motion, rig, solve_settings, "the benchmark's motion")
    arkit = np.clip(rig.to_arkit(weights), 0.0, 1.0)
    return bench.fit_length(arkit[:, list(rig.arkit_names).index("jawOpen")], n)


def sweep_point(point: str, settings) -> tuple[str, dict]:
    """(mode name, synthesize settings to change) of one ``--sweep`` point: ``LOW:HIGH:WEIGHT`` (the
    trust's thresholds and the voice's weight) or ``KEY=VALUE,...`` (any voice-step setting, the
    value read as that setting's type)."""
    if "=" not in point:
        low, high, weight = (float(x) for x in point.split(":"))
        return f"trust {point}", {"voice_trust_low": low, "voice_trust_high": high, "voice_weight": weight}
    changes = {}
    for item in point.split(","):
        key, value = (x.strip() for x in item.split("=", 1))
        if not (key.startswith("voice_") or key in VOICE_STEP_SETTINGS) or not hasattr(settings, key):
            raise SystemExit(f"--sweep {point}: {key} is not a setting of synthesize's voice step")
        kind = type(getattr(settings, key))
        changes[key] = (value.lower() == "true") if kind is bool else kind(value)
    return f"set {point}", changes


def opening_of(motion, settings, n: int) -> np.ndarray:
    """The inner-lip gap (n,) mm of a motion at FPS."""
    if motion.fps != FPS:
        raise SystemExit(f"the motion is at {motion.fps} frames/s; the benchmark needs synthesize.output_fps = {FPS:g}")
    gap = lip_gaps(motion.markers, list(motion.marker_names), tuple(settings.loudness_lip_markers))
    return bench.fit_length(gap, n)


def live_curves(live_model, model, u: Utt, settings, lip_markers,
                anticipation_s: float | None = None) -> dict[str, np.ndarray]:
    """The mouth ``stream`` sends from ``u``'s audio (20 ms chunks) with ``model`` (and
    ``stream.voice_anticipation_s = anticipation_s``; None: as configured): {live: its inner-lip
    gap, live_jaw: its jawOpen weight}, (n,) each at FPS."""
    from facesynth.domain.live.voice_frames import VoiceFrames
    from facesynth.formats.audio import resample

    x = np.asarray(u.samples, np.float64)
    if u.rate != A.RATE:
        x = resample(x, u.rate, A.RATE)
    vf = VoiceFrames(live_model, model, settings, "neutral", anticipation_s)
    frames, step = [], A.RATE // 50
    for a in range(0, len(x), step):
        frames += vf.push(x[a:a + step].astype(np.float32), (a + step) / A.RATE)
    frames += vf.finish(len(x) / A.RATE)
    markers = np.stack([f.markers for f in frames])
    names = list(live_model.marker_names)
    gap = lip_gaps(markers, names, tuple(lip_markers))
    jaw = np.array([f.arkit[list(live_model.arkit_names).index("jawOpen")] for f in frames])
    return {"live": bench.fit_length(gap, u.n), "live_jaw": bench.fit_length(jaw, u.n)}


def live_phones_curve(live_model, align, u: Utt, lip_markers) -> np.ndarray:
    """The inner-lip gap (n,) at FPS of the mouth ``stream`` sends with ``stream.voice = "off"``
    (``live_model`` built so: the phones pocketsphinx's phone loop recognises as the audio arrives,
    through the live DP) from ``u``'s audio alone, fed to a
    :class:`facesynth.domain.live.session.Session` in 20 ms chunks of 16-bit PCM as a client sends it."""
    from facesynth.domain.live.session import SAMPLE_RATE, Session
    from facesynth.formats.audio import resample

    x = np.asarray(u.samples, np.float64)
    if u.rate != SAMPLE_RATE:
        x = resample(x, u.rate, SAMPLE_RATE)
    pcm = (np.clip(x, -1.0, 1.0) * 32767.0).astype("<i2").tobytes()
    session = Session(live_model, align, u.key)
    session.control(json.dumps({"type": "start", "markers": True}))
    messages, step = [], 2 * SAMPLE_RATE // 50
    for a in range(0, len(pcm), step):
        messages += session.audio(pcm[a:a + step])
    messages += session.end()
    markers = np.array([m["markers"] for m in messages if m["type"] == "frame"]).reshape(-1, len(live_model.marker_names), 3)
    gap = lip_gaps(markers, list(live_model.marker_names), tuple(lip_markers))
    return bench.fit_length(gap, u.n)


# ---------------------------------------------------------------- scoring

def scored_utterances(utts: list[Utt], seconds: float) -> list[Utt]:
    """A speaker's first utterances, up to the first that reaches ``seconds`` of audio in all."""
    chosen, total = [], 0.0
    for u in utts:
        if total >= seconds:
            break
        chosen.append(u)
        total += u.n / FPS
    return chosen


def window_scores(method: np.ndarray, real: np.ndarray, n: int, window_s: float) -> list[float]:
    """Pearson r per window (about ``window_s``; one window for a shorter utterance) on the frames
    where the real curve is known."""
    out = []
    for a, b in bench.windows(n, FPS, window_s):
        m, r = method[a:b], real[a:b]
        ok = np.isfinite(m) & np.isfinite(r)
        out.append(bench.pearson(m[ok], r[ok]) if ok.sum() >= 10 else float("nan"))
    return out


def closure_counts(method: np.ndarray, real: np.ndarray, depth: float, prominence: float, tolerance: int) -> np.ndarray:
    """(4,) int: the real mouth's closures (:func:`real_speech_lipsync.closure_events` of ``real``
    (n,), its unknown frames at its median) met by one of ``method``'s (n,) within ``tolerance``
    frames, the real closures, the method's closures met by a real one, the method's closures."""
    ok = np.isfinite(real)
    if ok.sum() < 10:
        return np.zeros(4, np.int64)
    rc = bench.closure_events(np.where(ok, real, np.median(real[ok])), depth, prominence)
    mc = bench.closure_events(method, depth, prominence)
    hit_real, hit_method = bench.match_closures(rc, mc, tolerance)
    return np.array([hit_real, len(rc), hit_method, len(mc)], np.int64)


def summarize_closures(counts: dict[str, dict[str, np.ndarray]], resample_count: int, seed: int) -> dict:
    """Per mode, over the speakers of ``counts`` ({speaker: {mode: (4,) closure_counts summed over
    its scored utterances}}): recall (the real closures met) and precision (the mode's closures met),
    each the sum over speakers of hits over totals, with a 95% interval resampling speakers."""
    speakers = sorted(counts)
    modes = [m for m in counts[speakers[0]] if all(m in counts[s] for s in speakers)] if speakers else []
    idx = resamples(len(speakers), resample_count, seed)
    out = {}
    for m in modes:
        c = np.array([counts[s][m] for s in speakers], np.float64)
        cells = {name: interval(bench.ratio_statistic(c[:, h], c[:, t]), len(speakers), idx)
                 for name, h, t in (("recall", 0, 1), ("precision", 2, 3))}
        out[m] = {name: {k: round(float(v), 4) for k, v in cell.items()} for name, cell in cells.items()}
        out[m]["real_closures"], out[m]["closures"] = int(c[:, 1].sum()), int(c[:, 3].sum())
    return out


def summarize(per_speaker: dict[str, dict[str, list[float]]], resample_count: int, seed: int,
              lead: str = "default", pairs: tuple[tuple[str, str], ...] = ()) -> dict:
    """Per speaker the mean window r of every mode; pooled, the mean over speakers with a 95%
    interval over resampled speakers, and the paired differences of ``lead`` against every mode
    (and of each of ``pairs``, first minus second)."""
    speakers = sorted(per_speaker)
    extra = sorted({m for s in speakers for m in per_speaker[s] if m not in MODES})  # the sweep's points
    modes = [m for m in (*MODES, *extra) if all(m in per_speaker[s] for s in speakers)]
    table = {m: np.array([np.nanmean(per_speaker[s][m]) if np.isfinite(per_speaker[s][m]).any() else np.nan
                          for s in speakers]) for m in modes}
    k = len(speakers)
    idx = resamples(k, resample_count, seed)

    def stat(v):
        return lambda i: float(np.nanmean(v[i])) if np.isfinite(v[i]).any() else float("nan")

    def rounded(d):
        return {a: (None if b is None or not np.isfinite(b) else round(float(b), 4)) for a, b in d.items()}

    pooled, paired = {}, {}
    for m, v in table.items():
        cell = interval(stat(v), k, idx)
        pooled[m] = rounded(cell if k >= 3 else {**cell, "low": None, "high": None})
    lead = lead if lead in table else "voice"
    for a, b in [(lead, m) for m in table if m != lead] + [p for p in pairs if p[0] in table and p[1] in table]:
        cell = paired_difference(stat(table[a]), stat(table[b]), k, idx)
        paired[f"{a} - {b}"] = rounded(cell if k >= 3 else {**cell, "low": None, "high": None})
    if "given_default" in table:  # the text-and-audio default against the other given modes
        for m in ("given_articulation", "given_loudness", "given_phones", "given_packaged", "default"):
            if m in table:
                cell = paired_difference(stat(table["given_default"]), stat(table[m]), k, idx)
                paired[f"given_default - {m}"] = rounded(cell if k >= 3 else {**cell, "low": None, "high": None})
    # modes only some speakers have (given phones): pooled over those speakers
    partial = {}
    for m in MODES:
        if m in modes:
            continue
        have = [s for s in speakers if m in per_speaker[s]]
        if have:
            partial[m] = {"speakers": len(have),
                          "mean": round(float(np.nanmean([np.nanmean(per_speaker[s][m]) for s in have])), 4)}
    return {"speakers": k, "r": pooled, "paired": paired, "partial": partial,
            "per_speaker": {s: {m: round(float(np.nanmean(per_speaker[s][m])), 4) for m in per_speaker[s]}
                            for s in speakers}}


# ---------------------------------------------------------------- folds

#: How the speakers of a fit are weighed (``--speaker-weights``): "equal" every speaker counts alike
#: (each frame weighs 1 / its speaker's seconds), "sources" every source alike and its speakers
#: alike within it (a source of eleven short clips counts as much as one performer), "frames"
#: every frame alike (a speaker heard for 49 minutes outweighs one heard for 3 s a thousand times).
SPEAKER_WEIGHTS = ("equal", "sources", "frames")


def fit_fold(train: dict[str, list[Utt]], ref, variant: str, synthetic: int | dict[str, int],
             seed: int, feature_names: tuple[str, ...] = A.FEATURE_NAMES,
             speaker_weights: str = "equal") -> A.ArticulationModel:
    """The model fitted on the speakers ``train`` ({speaker: utterances}) with ``variant``'s settings
    (and ``synthetic`` synthetic speakers made from each one's voice: a count, or one per speaker),
    on the utterances' raw features ``u.raw`` whose columns are ``feature_names``, the speakers
    weighed as ``speaker_weights`` says (:data:`SPEAKER_WEIGHTS`; a synthetic voice weighs as the
    real one it was made of)."""
    if speaker_weights not in SPEAKER_WEIGHTS:
        raise ValueError(f"speaker_weights {speaker_weights!r}: one of {', '.join(SPEAKER_WEIGHTS)}")
    pairs = [(u, y) for speaker in sorted(train) for u, y in zip(train[speaker], speaker_targets(train[speaker], ref))]
    counts = synthetic if isinstance(synthetic, dict) else {s: synthetic for s in train}
    known = np.array([np.isfinite(np.concatenate([y[:, j] for _, y in pairs])).any() for j in range(len(TARGETS))])
    jaw, opening = TARGETS.index("jawOpen"), TARGETS.index("opening")
    if not known[jaw]:  # no training speaker has a jaw channel: the jaw from the opening, in the jaw's units
        lo, hi = ref["jawOpen"]
        a, b = ref["opening"]
        for _, y in pairs:
            y[:, jaw] = lo + (y[:, opening] - a) * (hi - lo) / (b - a)
        known[jaw] = True
    names = tuple(t for t, k in zip(TARGETS, known) if k)  # a target no training speaker has is not predicted
    weight = {s: 1.0 if speaker_weights == "frames" else FPS / sum(u.n for u in v) for s, v in train.items()}
    if speaker_weights == "sources":
        per_source = Counter(v[0].source for v in train.values())
        weight = {s: w / per_source[train[s][0].source] for s, w in weight.items()}
    takes = [A.Take(u.raw, y[:, known], FPS, weight[u.speaker]) for u, y in pairs]
    for u, y in pairs:
        takes += [A.Take(raw, y[:, known], FPS, weight[u.speaker])
                  for raw in synthetic_features(u, counts.get(u.speaker, 0), seed)]
    return A.fit(takes, names, feature_names=feature_names, **VARIANTS[variant])


def synthetic_features(u: Utt, count: int, seed: int) -> list[np.ndarray]:
    """The raw features (K, D) of ``count`` synthetic speakers saying ``u`` (each voice drawn by
    :func:`facesynth.domain.voice.synthetic.random_voice` from a generator seeded by ``seed``, the
    utterance's name and the speaker's number), made once per run."""
    from facesynth.domain.voice import synthetic

    while len(u.synthetic) < count:
        i = len(u.synthetic)
        key = int.from_bytes(hashlib.sha256(f"{seed}/{u.key}/{i}".encode()).digest()[:8], "little")
        voice = synthetic.random_voice(np.random.default_rng(key))
        u.synthetic.append(A.frame_features(synthetic.transform(u.samples, u.rate, voice), u.rate))
    return u.synthetic[:count]


def curve_files(u: Utt) -> list[Path]:
    """The files of ``u``'s curves (FACEGOOD's .npy, a source's .npz), beside its audio."""
    if u.source == "facegood":
        return [u.wav.parent.parent / "bs_value_npy" / f"bs_value_{u.name}.npy"]
    return [u.wav.with_suffix(".npz")]


def write_packaged(by_speaker: dict[str, list[Utt]], sources: list[str], ref, variant: str, synthetic: int, seed: int,
                   out: Path, balance: bool = True, speaker_weights: str = "equal") -> dict:
    """Fit the model on every utterance of ``sources`` (those that may ship) and write it to ``out``,
    recording each file it learned from by name and sha256; returns what it was fitted on."""
    train = {s: v for s, v in by_speaker.items() if v[0].source in sources and v[0].real_voice}
    if not train:
        raise SystemExit(f"--ship-sources {','.join(sources)}: no speaker of those sources was read")
    seconds = {sp: sum(u.n for u in v) / FPS for sp, v in train.items()}
    # each speaker heard for about as long as the longest-heard one (at most 20 voices of each):
    # its own voice and synthetic voices made of it, so that one long-recorded speaker does not
    # make the model hers
    counts = {sp: synthetic + min(20, max(0, int(np.ceil(max(seconds.values()) / sec)) - 1 - synthetic))
              for sp, sec in seconds.items()} if balance else {sp: synthetic for sp in train}
    model = fit_fold(train, ref, variant, counts, seed, speaker_weights=speaker_weights)
    records = []
    for speaker in sorted(train):
        for u in train[speaker]:
            prefix = "FACEGOOD" if u.source == "facegood" else speaker
            for path in [u.wav, *curve_files(u)]:
                name = f"{prefix}/{path.parent.name}/{path.name}" if u.source == "facegood" else f"{prefix}/{path.name}"
                records.append({"name": name, "sha256": sha256_of(path),
                                "seconds": round(u.n / FPS, 2) if path == u.wav else None})
    model.fitted_on = records
    settings = {"variant": variant, **VARIANTS[variant], "synthetic_voices_per_speaker": counts, "seed": seed,
                "speaker_weights": speaker_weights, "speakers": sorted(train), "targets_in_units_of": FACEGOOD_SPEAKER,
                "offsets_s": [float(x) for x in model.offsets_s], "pool": model.pool, "alpha": model.alpha,
                "normalization": model.normalization, "tau_s": model.tau_s, "expand": model.expand}
    model.write(out, config=json.dumps(settings, sort_keys=True), inputs=[], overwrite=True)
    return {"speakers": sorted(train), "files": len(records),
            "seconds": round(sum(u.n for v in train.values() for u in v) / FPS, 1), "targets": list(model.target_names),
            "synthetic_voices_per_speaker": counts, "speaker_weights": speaker_weights}


#: Fit settings tried (item: features that do not carry the speaker); "default" is what ships.
#: "aheadN": the context read on to +N ms, past what live can wait for (batch could; it gains only
#: on clips whose sound lags their video, docs/real-speech.md "Fifth round").
VARIANTS: dict[str, dict] = {
    "default": {},
    "utterance": {"normalization": "utterance"},
    "alpha0.3": {"alpha": 0.3},
    "alpha3": {"alpha": 3.0},
    "alpha10": {"alpha": 10.0},
    "tau1": {"tau_s": 1.0},
    "tau10": {"tau_s": 10.0},
    "ahead50": {"offsets_s": (-0.25, -0.2, -0.15, -0.12, -0.09, -0.06, -0.04, -0.02, 0.0, 0.02, 0.05)},
    "ahead100": {"offsets_s": (-0.25, -0.2, -0.15, -0.12, -0.09, -0.06, -0.04, -0.02, 0.0, 0.02, 0.05, 0.1)},
    "ahead150": {"offsets_s": (-0.25, -0.2, -0.15, -0.12, -0.09, -0.06, -0.04, -0.02, 0.0, 0.02, 0.05, 0.1, 0.15)},
    "ahead250": {"offsets_s": (-0.25, -0.2, -0.15, -0.12, -0.09, -0.06, -0.04, -0.02, 0.0, 0.02, 0.05, 0.1, 0.15,
                               0.2, 0.25)},
}


#: Voice features tried (item: features that do not carry the speaker; "mel" is what ships):
#: "envelope" the mel bands of the cepstrally liftered log envelope (no pitch harmonics);
#: "delta" the mel bands replaced by their slopes over +-2 frames (a channel's constant and slow
#: colouring gone); "vtln" every utterance's spectrum warped toward the training voices' vocal tract
#: (:func:`facesynth.domain.voice.articulation.estimate_warp` of its long-term envelope against the
#: fold's training speakers' mean, fitted and scored alike); "envelope+vtln" both.
#: "pitch-warp" the warp from the voice's median pitch against the training voices' (formants scale
#: with pitch across speakers: :func:`facesynth.domain.voice.tract.pitch_warp`).
FEATURES = ("mel", "envelope", "delta", "vtln", "envelope+vtln", "pitch-warp")


def mel_deltas(mel: np.ndarray) -> np.ndarray:
    """(K, B) float32 regression slopes of (K, B) log-mel frames over +-2 frames (ends repeated)."""
    p = np.concatenate([mel[:1], mel[:1], mel, mel[-1:], mel[-1:]])
    return ((p[3:-1] - p[1:-3]) + 2.0 * (p[4:] - p[:-4])).astype(np.float32) / 10.0


def utterance_features(u: Utt, features: str, warp: float, cache: dict) -> np.ndarray:
    """(K, D) raw features of ``u`` as ``features`` (:data:`FEATURES`) computes them, at ``warp``."""
    key = (u.key, features, round(warp, 3))
    if key not in cache:
        raw = A.frame_features(u.samples, u.rate, envelope="envelope" in features, warp=warp)
        if features == "delta":
            raw[:, :A.N_MELS] = mel_deltas(raw[:, :A.N_MELS])
        cache[key] = raw
    return cache[key]


def fold_reference(by_speaker: dict[str, list[Utt]], ltes: dict[str, np.ndarray | None], train: list[str]) -> np.ndarray:
    """(G,) the mean long-term envelope (on ``WARP_GRID``) of the training speakers, each speaker once."""
    step = int(round(tract.MAX_LOG_WARP / 0.01))
    per = []
    for s in train:
        v = [ltes[u.key] for u in by_speaker[s] if u.real_voice and ltes.get(u.key) is not None]
        if v:
            per.append(np.mean(v, 0)[step:step + len(tract.WARP_GRID)])
    return np.mean(per, 0)


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--facegood", type=Path, default=None, help="FACEGOOD's folder (see real_speech_lipsync.py)")
    ap.add_argument("--speech-data", type=Path, default=None, help="a folder of sources (module docstring)")
    ap.add_argument("--work", type=Path, required=True, help="cache: database, phones, motions, fold models")
    ap.add_argument("--variant", default="default", choices=sorted(VARIANTS))
    ap.add_argument("--features", default="mel", choices=FEATURES,
                    help="the voice features the fold models read (mel: as shipped; --no-chain only for others)")
    ap.add_argument("--actress", action="store_true",
                    help="train every fold on the built-in actress's takes too (her synthetic voice; never scored)")
    ap.add_argument("--synthetic", type=int, default=0, help="synthetic speakers per fold (training only)")
    ap.add_argument("--speakers", default=None, help="comma-separated speakers to score (default: all)")
    ap.add_argument("--warp-per", default="utterance", choices=("utterance", "speaker"),
                    help="--features vtln: each utterance's own warp, or one per speaker from all its utterances")
    ap.add_argument("--texts", type=Path, default=None,
                    help='a JSON {"<source>/<speaker>/<utt>": "what it says"}: the text-and-audio modes '
                         '(given_*) on those utterances (GRID\'s texts come from its file names)')
    ap.add_argument("--no-chain", action="store_true", help="score the voice model alone (no synthesis)")
    ap.add_argument("--folds", default="speaker", choices=("speaker", "source"),
                    help="leave out one speaker at a time, or one whole source (its microphone, language, setting)")
    ap.add_argument("--reuse-folds", action="store_true",
                    help="read each fold's model from --work where an earlier run with the same data wrote it")
    ap.add_argument("--no-live", action="store_true", help="leave out the live modes (the slowest)")
    ap.add_argument("--live-anticipation", default="",
                    help="comma-separated seconds: the live modes with stream.voice_anticipation_s at each "
                         "(modes 'live anticipation=S', 'live_packaged anticipation=S')")
    ap.add_argument("--sweep", default="",
                    help="semicolon-separated points, each LOW:HIGH:WEIGHT (synthesize.voice_trust_low, "
                         "voice_trust_high and voice_weight: mode 'trust LOW:HIGH:WEIGHT') or KEY=VALUE,... of "
                         "synthesize's voice-step settings (mode 'set KEY=VALUE,...'): the articulation mode with each")
    ap.add_argument("--score-seconds", type=float, default=60.0,
                    help="score each held-out speaker on its first utterances up to this many seconds (all are fitted on)")
    ap.add_argument("--sources", default=None, help="comma-separated sources of --speech-data to read (default: all READY)")
    ap.add_argument("--model-out", type=Path, default=None,
                    help="also write the model fitted on every speaker of --ship-sources here (the packaged model)")
    ap.add_argument("--ship-sources", default="facegood,grid",
                    help="the sources whose licences let a model fitted on them ship (for --model-out)")
    ap.add_argument("--fit-only", action="store_true", help="only write --model-out (no speaker is scored)")
    ap.add_argument("--speaker-weights", default="equal", choices=SPEAKER_WEIGHTS,
                    help="equal: every training speaker counts alike (as the packaged model is fitted); sources: "
                         "every source alike, its speakers alike within it; frames: every frame alike, a "
                         "long-recorded speaker outweighing the others (the release before last)")
    ap.add_argument("--no-balance", action="store_true",
                    help="--model-out: no synthetic voices to give each speaker as long as the longest-heard one")
    ap.add_argument("--packaged-folds", action="store_true",
                    help="score a speaker of --ship-sources with the packaged fit refitted without it (as --model-out "
                         "fits it), not the packaged model that heard it")
    ap.add_argument("--sweep-packaged", action="store_true",
                    help="the --sweep points with the packaged model too (modes 'packaged trust ...')")
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                    help="a setting other than the defaults for the whole run (e.g. synthesize.voice_opening_map=percentiles)")
    ap.add_argument("--window-s", type=float, default=10.0)
    ap.add_argument("--closure-depth", type=float, default=0.25,
                    help="a closure: a minimum of a mouth opening scaled to its 5th..95th percentiles below this")
    ap.add_argument("--closure-prominence", type=float, default=0.25, help="... standing out by this")
    ap.add_argument("--closure-tolerance-frames", type=int, default=3, help="closures this near meet")
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    args.no_chain = args.no_chain or args.fit_only
    started = time.perf_counter()
    utts = (facegood_utterances(args.facegood) if args.facegood else []) + \
        (speech_data_utterances(args.speech_data, ("facegood",) if args.facegood else (),
                                args.sources.split(",") if args.sources else None) if args.speech_data else [])
    if not utts:
        raise SystemExit("no utterances: give --facegood and/or --speech-data (with READY-<source> markers)")
    texts = json.loads(args.texts.read_text()) if args.texts else {}
    for u in utts:
        u.text = texts.get(u.key) or (grid_text(u.name) if u.source == "grid" else None)
    OVERRIDES[:] = args.set
    config = Config.load(overrides=tuple(args.set))
    _phones_config()  # read now: the settings of the whole run
    settings = config.settings("synthesize")
    lip_markers = config.settings("evaluate").lip_markers
    args.work.mkdir(parents=True, exist_ok=True)
    if args.actress or not args.no_chain:
        bench.build_database(args.work)
    if args.actress:
        utts += actress_utterances(args.work, settings.loudness_lip_markers)
    if args.features != "mel" and not args.no_chain:
        raise SystemExit(f"--features {args.features}: the packaged chain reads mel features; give --no-chain")
    feature_cache: dict = {}
    for u in utts:
        u.raw = utterance_features(u, args.features, 1.0, feature_cache)
    ltes = {u.key: tract.long_term_envelope(u.samples, u.rate) for u in utts} if "vtln" in args.features else {}
    pitches = {u.key: tract.median_pitch(u.samples, u.rate) for u in utts} if args.features == "pitch-warp" else {}
    warps: dict[str, list[float]] = {}
    by_speaker: dict[str, list[Utt]] = {}
    for u in utts:
        by_speaker.setdefault(u.speaker, []).append(u)
    labels = {}
    if args.speech_data and (args.speech_data / "speakers.json").exists():
        listed = json.loads((args.speech_data / "speakers.json").read_text())
        if isinstance(listed, list):  # [{source, speaker, sex, language, ...}]
            listed = {f"{SAME_CORPUS.get(x['source'], x['source'])}/{x['speaker']}": x for x in listed}
        labels = {k: {f: v[f] for f in ("sex", "language", "may_ship") if f in v} for k, v in listed.items()}
    ref = reference_ranges([u for u in utts if u.speaker == FACEGOOD_SPEAKER] or utts)
    real = sorted({u.speaker for u in utts if u.real_voice})
    ship_sources = args.ship_sources.split(",")

    def fit_packaged() -> dict | None:
        """The packaged model written to --model-out (what it was fitted on), or None without it."""
        return write_packaged(by_speaker, ship_sources, ref, args.variant, args.synthetic, args.seed, args.model_out,
                              not args.no_balance, args.speaker_weights) if args.model_out else None

    if args.fit_only:  # the packaged model alone: nothing is scored
        if not args.model_out:
            raise SystemExit("--fit-only writes the packaged model: give --model-out")
        return {"benchmark": "voice_speakers", "packaged_model_fitted_on": fit_packaged()}
    scored = args.speakers.split(",") if args.speakers else real
    db = rig = solve_rig = solve_settings = lip_vertices = live_model = phones_live_model = None
    stream = config.settings("stream")
    if not args.no_chain:
        from facesynth.domain.live.synthesizer import LiveModel
        from facesynth.domain.rig.face import load_face_rig
        from facesynth.domain.rig.loading import load_rig
        from facesynth.formats.mesh import read_binding
        from facesynth.model.motiondb import MotionDatabase

        db = bench.build_database(args.work)
        rig = load_face_rig()
        binding = read_binding(args.work / "corpus" / "markers.csv")
        lip_vertices = np.array([binding[m] for m in lip_markers])
        database = MotionDatabase.read(db)
        live_model = LiveModel(database, settings, stream, config.settings("solve"))
        solve_rig, solve_settings = load_rig(None, None), config.settings("solve")
        phones_live_model = LiveModel(database, settings, replace(stream, voice="off"), config.settings("solve"))
    packaged = bench.ARTICULATION_MODEL
    packaged_model = A.ArticulationModel.read(packaged)
    per_speaker: dict[str, dict[str, list[float]]] = {}
    closures_of: dict[str, dict[str, np.ndarray]] = {}
    skipped: list[dict] = []
    timing = {}
    fold_models: dict[str, tuple[A.ArticulationModel, Path]] = {}
    for speaker in scored:
        t0 = time.perf_counter()
        # the speakers left out with this one: itself, or its whole source (--folds source)
        fold = speaker if args.folds == "speaker" else by_speaker[speaker][0].source
        tag = args.variant if args.features == "mel" else f"{args.variant}.{args.features}" + \
            (f".per-{args.warp_per}" if "warp" in args.features or "vtln" in args.features else "")
        cached = args.work / "folds" / f"{tag}.s{args.synthetic}.{args.speaker_weights}.{fold.replace('/', '+')}.h5"
        if fold not in fold_models and args.reuse_folds and cached.exists():
            fold_models[fold] = (A.ArticulationModel.read(cached), cached)
        if args.features == "pitch-warp":  # every utterance warped by its pitch against this fold's training voices
            def pitch_of(names: list[Utt]) -> float | None:
                v = [pitches[x.key] for x in names if pitches.get(x.key) is not None]
                return float(np.median(v)) if v else None
            trained = [pitch_of(v) for s, v in by_speaker.items() if v[0].real_voice
                       and (s if args.folds == "speaker" else v[0].source) != fold]
            reference_pitch = float(np.median([p for p in trained if p is not None]))
            for u in utts:
                p = pitch_of(by_speaker[u.speaker]) if args.warp_per == "speaker" else pitches[u.key]
                w = round(tract.pitch_warp(p, reference_pitch), 2)
                u.raw = utterance_features(u, args.features, w, feature_cache)
                if u.speaker == speaker:
                    warps.setdefault(speaker, []).append(w)
        if "vtln" in args.features:  # every utterance warped toward this fold's training voices
            reference = fold_reference(by_speaker, ltes, [s for s, v in by_speaker.items()
                                                          if (s if args.folds == "speaker" else v[0].source) != fold])
            for u in utts:
                lte = ltes[u.key]
                if args.warp_per == "speaker":  # one warp per speaker, from all its utterances (an enrolment)
                    v = [ltes[x.key] for x in by_speaker[u.speaker] if ltes.get(x.key) is not None]
                    lte = np.mean(v, 0) if v else None
                w = round(tract.estimate_warp(lte, reference), 2)
                u.raw = utterance_features(u, args.features, w, feature_cache)
                if u.speaker == speaker:
                    warps.setdefault(speaker, []).append(w)
        if fold not in fold_models:
            train = {s: v for s, v in by_speaker.items()
                     if (s if args.folds == "speaker" else v[0].source) != fold}
            if not train:
                raise SystemExit(f"{fold} holds every speaker: leaving it out leaves nothing to fit on")
            model = fit_fold(train, ref, args.variant, args.synthetic, args.seed, speaker_weights=args.speaker_weights)
            model_path = cached
            model_path.parent.mkdir(parents=True, exist_ok=True)
            model.write(model_path, config=json.dumps({"held_out": fold, "variant": args.variant,
                                                      "speaker_weights": args.speaker_weights}), inputs=[],
                        overwrite=True)
            fold_models[fold] = (model, model_path)
        model, model_path = fold_models[fold]
        scores: dict[str, list[float]] = {}
        closures: dict[str, np.ndarray] = {}
        for u in scored_utterances(by_speaker[speaker], args.score_seconds):
            predicted = A.predict_raw(model, u.raw, np.arange(u.n) / FPS)
            curves = {"voice": predicted[:, model.column("opening")], "voice_jaw": predicted[:, model.column("jawOpen")],
                      "energy": envelope(u.samples, u.rate, u.n, FPS, 0.1)}
            if not args.no_chain:
                try:
                    motion, phones = phones_motion(db, u, args.work)
                except InputError as exc:  # synthesize --audio refuses it too (no speech found): not scored
                    why = str(exc).replace(str(u.wav), u.key).split(";")[0]  # no folder of this machine
                    skipped.append({"utterance": u.key, "why": why})
                    continue
                curves["phones"] = opening_of(motion, settings, u.n)
                moved = {"off": motion}  # the motion of each voice path, the fold's model
                for mode in ("articulation", "loudness"):
                    moved[mode] = voice_motion(motion, u, phones, settings, model_path, True, mode)
                    curves[mode] = opening_of(moved[mode], settings, u.n)
                for point in filter(None, args.sweep.split(";")):
                    name, changes = sweep_point(point, settings)
                    for tag, path in (("", model_path), ("packaged ", packaged)) if args.sweep_packaged else (("", model_path),):
                        curves[f"{tag}{name}"] = voice_step(motion, u, phones, settings, path, True, "articulation",
                                                            **changes)
                curves["default"] = curves[settings.voice_recognized] if settings.voice_recognized != "off" \
                    else curves["phones"]
                shipped_path = packaged
                if args.packaged_folds and u.source in ship_sources:  # the packaged fit, this speaker left out
                    shipped_path = (args.work / "folds" /
                                    f"packaged-minus.{args.speaker_weights}.{speaker.replace('/', '+')}.h5")
                    if not shipped_path.exists():
                        write_packaged({s: v for s, v in by_speaker.items() if s != speaker}, ship_sources, ref,
                                       args.variant, args.synthetic, args.seed, shipped_path, not args.no_balance,
                                       args.speaker_weights)
                default_motion = moved[settings.voice_recognized]
                shipped_motion = default_motion if shipped_path == model_path else \
                    voice_motion(motion, u, phones, settings, shipped_path, True, settings.voice_recognized)
                curves["packaged"] = opening_of(shipped_motion, settings, u.n)
                # the jaw an ARKit export carries: the motion solved onto the built-in rig
                curves["phones_jaw"] = solved_jaw(motion, solve_rig, solve_settings, u.n)
                curves["default_jaw"] = solved_jaw(default_motion, solve_rig, solve_settings, u.n)
                curves["packaged_jaw"] = curves["default_jaw"] if shipped_motion is default_motion else \
                    solved_jaw(shipped_motion, solve_rig, solve_settings, u.n)
                from facesynth.base.phonemes import PAU  # noqa: F401  (segments as openfacefx reads them)
                from facesynth.formats.labels import Segment

                segs = [Segment(float(a), float(b), p) for a, b, p in zip(*phones)]
                ofx = bench.openfacefx_method(segs, u.n, rig, lip_vertices)
                curves["openfacefx"], curves["openfacefx_jaw"] = ofx["opening"], ofx["jawOpen"]
                if not args.no_live:
                    curves.update(live_curves(live_model, model, u, settings, settings.loudness_lip_markers))
                    shipped = live_curves(live_model, packaged_model, u, settings, settings.loudness_lip_markers)
                    curves["live_packaged"], curves["live_packaged_jaw"] = shipped["live"], shipped["live_jaw"]
                    curves["live_phones"] = live_phones_curve(phones_live_model, config.settings("align"), u,
                                                              settings.loudness_lip_markers)
                    curves["live_default"] = curves["live_packaged" if stream.voice == "articulation" else "live_phones"]
                    for ahead in filter(None, args.live_anticipation.split(",")):
                        for tag, m in (("live", model), ("live_packaged", packaged_model)):
                            curves[f"{tag} anticipation={float(ahead):g}"] = live_curves(
                                live_model, m, u, settings, settings.loudness_lip_markers, float(ahead))["live"]
                if u.given_phones is not None or u.text:
                    gm, gp = phones_motion(db, u, args.work, given=True)
                    curves["given_phones"] = opening_of(gm, settings, u.n)
                    for mode in ("articulation", "loudness"):
                        curves[f"given_{mode}"] = voice_step(gm, u, gp, settings, model_path, False, mode)
                    curves["given_default"] = curves[f"given_{settings.voice_given}"] \
                        if settings.voice_given != "off" else curves["given_phones"]
                    curves["given_packaged"] = voice_step(gm, u, gp, settings, shipped_path, False, "articulation")
            for mode, curve in curves.items():
                scores.setdefault(mode, []).extend(window_scores(curve, u.real["opening"], u.n, args.window_s))
                closures.setdefault(mode, np.zeros(4, np.int64))
                closures[mode] += closure_counts(curve, u.real["opening"], args.closure_depth,
                                                 args.closure_prominence, args.closure_tolerance_frames)
        if scores.get("voice"):
            per_speaker[speaker] = scores
            closures_of[speaker] = closures
        timing[speaker] = round(time.perf_counter() - t0, 1)
    packaged_fit = fit_packaged()
    summary = summarize(per_speaker, args.resamples, args.seed, pairs=JAW_PAIRS["default_jaw"])
    # what ships, on the speakers of the sources the packaged model was not fitted on
    unheard = {s: v for s, v in per_speaker.items() if by_speaker[s][0].source not in ship_sources}
    summary["never_heard_by_packaged"] = summarize(
        unheard, args.resamples, args.seed, lead="packaged",
        pairs=(("live_default", "packaged"), ("live_default", "live_phones"), ("live_packaged", "live_phones"),
               ("live_phones", "phones"), *JAW_PAIRS["packaged_jaw"])) if unheard and not args.no_chain else None
    if summary["never_heard_by_packaged"]:
        del summary["never_heard_by_packaged"]["per_speaker"]  # in per_speaker above
        summary["never_heard_by_packaged"]["closures"] = summarize_closures(
            {s: v for s, v in closures_of.items() if s in unheard}, args.resamples, args.seed)
    summary["closures"] = summarize_closures(closures_of, args.resamples, args.seed)
    return {"benchmark": "voice_speakers", "folds": args.folds, "variant": args.variant, "fit": VARIANTS[args.variant],
            "speaker_weights": args.speaker_weights,
            "features": args.features, "warp_per": args.warp_per if "vtln" in args.features or "warp" in args.features else None,
            "warps": {s: [round(float(np.mean(w)), 3), round(float(np.min(w)), 3), round(float(np.max(w)), 3)]
                      for s, w in sorted(warps.items())},
            "synthetic_speakers": args.synthetic,
            "settings": {**({"overrides": args.set} if args.set else {}),
                         "voice_recognized": settings.voice_recognized, "voice_given": settings.voice_given,
                         "window_s": args.window_s, "resamples": args.resamples, "seed": args.seed, "fps": FPS},
            "data": {s: {"utterances": len(v), "seconds": round(sum(u.n for u in v) / FPS, 1),
                         **labels.get(s, {})} for s, v in sorted(by_speaker.items())},
            "skipped": skipped, "packaged_model_fitted_on": packaged_fit, **summary, "seconds": {"per_speaker": timing, "total": round(time.perf_counter() - started, 1)}}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
