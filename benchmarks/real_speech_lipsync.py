"""Lip-sync on real speech: how well the synthesized mouth follows a real speaker's, per take.
Prints JSON (and writes a markdown table with ``--out``).

Data: recordings of real speech with the speaker's face solved at the same time. The one
public set used so far is FACEGOOD's Audio2Face training data (MIT; github.com/FACEGOOD/
FACEGOOD-Audio2Face, ``code/train/wav/`` and ``code/train/bs_value/``): seven takes, 11
minutes, of one performer (presumably Mandarin), with 116 blendshape curves solved from video
at 30 frames/s. ``--data`` is a folder laid out as::

    wav/<take>.wav                     the take's speech
    bs_value_npy/bs_value_<take>.npy   (frames, 116) curves in 0..1 at 30 frames/s, frame 0 = audio time 0
    shirley_1015_bs_name.npy           the 116 channel names in the column order of bs_value

The recordings (21 MB) are not shipped; FACEGOOD's table from its channels to the 52 ARKit
shapes is (``benchmarks/data/facegood_arkit.tsv``, converted from its
``Voice2Face_blendshape2ARkit.xlsx``; MIT, ``benchmarks/data/FACEGOOD.LICENSE``).

Real curves (FACEGOOD's table): ``jawOpen`` = ``mouth_stretch_c``, ``mouthFunnel`` and
``mouthPucker`` = the max of their part-shapes, ``mouthPress`` = the mean of
``mouthPressLeft/Right``, ``mouthClose`` = ``mouth_chew_c`` (which never moves in these takes,
so its r is reported as undefined). The real **mouth opening** is ``mouth_stretch_c +
mouth_oh_c``: the two channels that open the jaw in FACEGOOD's rig (unrounded and rounded);
``mouth_oh_c`` has no ARKit counterpart in the table but is the second most active channel.

Methods, all at 30 frames/s on the take's whole length, no lag (none is searched):

- ``facesynth``: ``facesynth synthesize --audio TAKE.wav`` (audio alone: the phones recognised
  inside, the same phones :func:`phones_from_audio` finds) on a database built once from the
  built-in actress (``small`` preset, seed 0, cached in ``--work``), then ``facesynth solve``
  onto the built-in rig: facesynth as it ships for audio alone, the mouth taking the voice's
  articulation (``synthesize.voice_recognized``, the packaged articulation model). Mouth
  opening = its inner-lip gap (``evaluate.lip_markers``); channels = the solve's curves.
- ``facesynth_loudness``: ``synthesize --phonemes PHONES --audio TAKE.wav``, the same phones
  given as a file, with ``synthesize.voice_given = "loudness"``: the voice's loudness alone moves
  the mouth, as audio alone did before the articulation model.
- ``facesynth_phones``: the same from the phones alone (no ``--audio``).
- ``voice``: the packaged articulation model's own curves from the audio: the voice alone, no
  phones, no motion. The packaged model is now fitted on all seven takes (and GRID's speakers),
  so on FACEGOOD this and ``facesynth`` are in-sample; docs/real-speech.md's within-speaker
  figures came from the release before's model, fitted on 1114_2_01..03
  (``benchmarks/voice_articulation.py --model-out`` writes it).
- ``facesynth_before`` (with ``--before-work``): the same from the database of an earlier run
  (e.g. the actress before calibration), so that the two are paired on the same phones.
- ``coarticulation``: the same chain with ``synthesize --method coarticulation`` (the
  Cohen-Massaro model fitted per phone and emotion on the same database with ``facesynth
  fit-method``, its defaults; the method ``evaluate`` recommends on the virtual actress), with
  the audio; ``coarticulation_phones`` the same from the phones alone. Paired differences are
  facesynth's against every other method and this one's against the baselines.
- ``actress_mean``: the built-in actress's mean pose per phone (``facesynth evaluate``'s
  ``baseline``) at phone centres, interpolated, from the same database and phones; mouth
  opening only. It shows how much of facesynth's score is lost in the search itself.
- ``openfacefx``: the same phones through openfacefx (as ``facesynth evaluate`` calls it); its
  ARKit curves are the channels; its mouth opening is the inner-lip gap of those curves on the
  built-in rig at the sample corpus's lip-marker vertices.
- ``energy``: the audio's log-RMS envelope (frames of two output frames, smoothed over
  ``--energy-smooth-s``), scored as mouth opening and jawOpen (Pearson r ignores the linear map).
- ``phone_mean``: the speaker's own mean of every real channel per recognised phone, fitted on
  one half of the takes (alternate takes) and scored on the other half, interpolated between
  phone centres as facesynth's ``baseline`` is: the best a method driven by these phones alone
  can expect from a per-phone pose.

Scores: Pearson r between each method's curve and the real one in windows of about
``--window-s`` seconds (each take cut into equal windows), the mean over windows with a
bootstrap 95% interval over windows (percentile method, :mod:`facesynth.domain.evaluation.bootstrap`), and
paired differences (facesynth minus each other method) on the same resamples; the same again
with the takes resampled instead (``r_takes``, ``paired_takes``: wider, since windows of one
take are not independent).
Lip closures: real closures are the deep minima of the real mouth opening (normalized per take
by its 5th..95th percentiles: below ``--closure-depth`` with prominence ``--closure-prominence``);
a method's closures are the same minima of its own opening curve; the recall is the fraction
of real closures with a method closure within +-``--closure-tolerance-frames``, the precision
the fraction of method closures with a real one that near.

    python benchmarks/real_speech_lipsync.py --data FACEGOOD_DIR --work WORK [--takes 1114_3_15,1114_3_16] [--out table.md] \
        [--corpus-config benchmarks/data/actress_uncalibrated.toml]

The actress is calibrated on takes 1114_2_01..03 (``benchmarks/articulation_statistics.py``),
and ``synthesize.loudness_weight`` was chosen on the same three; her figures on real speech are
the ones on the other takes, 1114_2_04, 1114_2_05, 1114_3_15 and
1114_3_16. ``--corpus-config`` builds her corpus with other settings (a ``--config`` file for
``facesynth sample-corpus``), e.g. the ones before calibration.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config, settings_json
from facesynth.base.hashing import sha256_of
from facesynth.base.phonemes import PAU, to_festival
from facesynth.domain.evaluation.baselines import openfacefx_arkit, openfacefx_missing, rig_markers
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.speech.loudness import envelope
from facesynth.domain.voice import articulation as A
from facesynth.formats.audio import read_audio, resample
from facesynth.formats.labels import Segment, read_phone_segments, write_textgrid

FPS = 30.0
TABLE = Path(__file__).resolve().parent / "data" / "facegood_arkit.tsv"
#: The real mouth opening: FACEGOOD's two jaw-opening channels (see the module docstring).
REAL_OPENING = ("mouth_stretch_c", "mouth_oh_c")
CHANNELS = ("opening", "jawOpen", "mouthClose", "mouthFunnel", "mouthPucker", "mouthPress")
METHODS = ("facesynth", "facesynth_loudness", "facesynth_phones", "facesynth_before", "coarticulation",
           "coarticulation_phones", "actress_mean", "openfacefx", "voice", "energy", "phone_mean")
#: The packaged articulation model (``synthesize.articulation_model`` empty), whose curves are the
#: ``voice`` method.
ARTICULATION_MODEL = Path(__file__).resolve().parents[1] / "facesynth" / "data" / "articulation.h5"
#: The rig shapes (built-in rig, ICT names) behind each channel of the facial solve.
RIG_SHAPES = {"jawOpen": ("jawOpen",), "mouthClose": ("mouthClose",), "mouthFunnel": ("mouthFunnel",),
              "mouthPucker": ("mouthPucker",), "mouthPress": ("mouthPress_L", "mouthPress_R")}
#: The ARKit shapes behind each channel (openfacefx's curves and FACEGOOD's table).
ARKIT_SHAPES = {"jawOpen": ("jawOpen",), "mouthClose": ("mouthClose",), "mouthFunnel": ("mouthFunnel",),
                "mouthPucker": ("mouthPucker",), "mouthPress": ("mouthPressLeft", "mouthPressRight")}


# ---------------------------------------------------------------- scoring (pure; tests call these)

def pearson(a: np.ndarray, b: np.ndarray) -> float:
    """Pearson r of two (n,) curves; NaN when either is constant or n < 3."""
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    if len(a) < 3 or a.std() == 0 or b.std() == 0:
        return float("nan")
    return float(np.corrcoef(a, b)[0, 1])


def windows(n: int, fps: float, seconds: float) -> list[tuple[int, int]]:
    """Frames [a, b) of the equal windows, of about ``seconds`` each, that tile ``n`` frames."""
    count = max(1, int(round(n / (seconds * fps))))
    edges = np.linspace(0, n, count + 1).round().astype(int)
    return [(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:])]


def window_r(method: np.ndarray, real: np.ndarray, spans: list[tuple[int, int]]) -> np.ndarray:
    """(W,) Pearson r of ``method`` against ``real`` (both (T,)) in each window of ``spans``."""
    return np.array([pearson(method[a:b], real[a:b]) for a, b in spans])


def closure_events(opening: np.ndarray, depth: float, prominence: float) -> np.ndarray:
    """Frames (K,) of the closures of a mouth-opening curve (T,): its minima that, with the curve
    scaled so that its 5th percentile is 0 and its 95th is 1, lie below ``depth`` and stand out
    by at least ``prominence``. None for a constant curve."""
    from scipy.signal import find_peaks

    x = np.asarray(opening, np.float64)
    low, high = np.percentile(x, [5, 95])
    if high <= low:
        return np.zeros(0, int)
    z = (x - low) / (high - low)
    frames, _ = find_peaks(-z, height=-depth, prominence=prominence)
    return frames


def match_closures(real: np.ndarray, method: np.ndarray, tolerance: int) -> tuple[int, int]:
    """(real closures with a method closure within +-``tolerance`` frames, method closures with a
    real one that near); ``real``, ``method`` (K,) frames
    (:func:`facesynth.domain.voice.articulation.match_closures`, as ``fit-articulation`` counts them)."""
    return A.match_closures(real, method, tolerance)


def mean_r_statistic(values: np.ndarray):
    """The statistic "mean r over the chosen windows" of (W,) window r's (NaN windows skipped)."""
    def stat(idx: np.ndarray) -> float:
        v = values[idx]
        return float(np.nanmean(v)) if np.isfinite(v).any() else float("nan")
    return stat


def ratio_statistic(hits: np.ndarray, totals: np.ndarray):
    """The statistic "sum of hits / sum of totals over the chosen windows"."""
    def stat(idx: np.ndarray) -> float:
        total = totals[idx].sum()
        return float(hits[idx].sum() / total) if total else float("nan")
    return stat


def by_take(stat, groups: np.ndarray):
    """``stat`` (window indices -> float) as a statistic of take indices: the windows of the
    chosen takes (a take drawn twice counts twice). groups : (W,) the take of each window."""
    members = [np.flatnonzero(groups == g) for g in range(int(groups.max()) + 1)]

    def take_stat(idx: np.ndarray) -> float:
        return stat(np.concatenate([members[i] for i in idx]))
    return take_stat


def summarize(r: dict, closures: dict, groups: np.ndarray, resample_count: int, seed: int) -> dict:
    """Intervals over windows (``r``, ``paired``, ``closures``) and over takes (``r_takes``,
    ``paired_takes``: the takes resampled, each with all its windows). r: {channel: {method: (W,)
    window r}}; closures: {method: (W, 4) int per window: real closures, matched real, method
    closures, matched method}; groups: (W,) int, the take of each window (0..K-1)."""
    n, k = len(groups), int(groups.max()) + 1
    index, take_index = resamples(n, resample_count, seed), resamples(k, resample_count, seed)
    out = {"windows": n, "takes": k}
    for suffix, wrap, count, idx in (("", lambda f: f, n, index), ("_takes", lambda f: by_take(f, groups), k, take_index)):
        overall, differences = {}, {}
        for channel, per in r.items():
            overall[channel] = {m: interval(wrap(mean_r_statistic(v)), count, idx) for m, v in per.items()}
            differences[channel] = {
                f"{lead} - {m}": paired_difference(wrap(mean_r_statistic(per[lead])), wrap(mean_r_statistic(v)), count, idx)
                for lead in ("facesynth", "coarticulation") if lead in per
                for m, v in per.items() if m != lead and not (lead == "coarticulation" and m == "facesynth")}
        out["r" + suffix], out["paired" + suffix] = overall, differences
    out["closures"] = {m: {"recall": interval(ratio_statistic(c[:, 1], c[:, 0]), n, index),
                           "precision": interval(ratio_statistic(c[:, 3], c[:, 2]), n, index),
                           "closures": int(c[:, 2].sum())} for m, c in closures.items()}
    return out


# ---------------------------------------------------------------- the real curves and the audio

def read_table(path: Path = TABLE) -> dict[str, list[str]]:
    """FACEGOOD's ARKit table: {ARKit name: [FACEGOOD channels, whose max it is]} (valid rows)."""
    out = {}
    for line in path.read_text(encoding="utf-8").splitlines()[1:]:
        arkit, expr, status = line.split("\t")
        if status == "valid" and expr:
            inner = re.fullmatch(r"max\((.*)\)", expr)
            out[arkit] = [c.strip() for c in (inner.group(1) if inner else expr).split(",")]
    return out


def real_curves(values: np.ndarray, names: list[str], table: dict[str, list[str]]) -> dict[str, np.ndarray]:
    """The real channels (T,) of a take's FACEGOOD curves ``values`` (T, 116) with channel ``names``."""
    col = {n: i for i, n in enumerate(names)}

    def arkit(name: str) -> np.ndarray:
        return values[:, [col[c] for c in table[name]]].max(1)

    out = {"opening": values[:, [col[c] for c in REAL_OPENING]].sum(1)}
    for channel, shapes in ARKIT_SHAPES.items():
        out[channel] = np.mean([arkit(s) for s in shapes], axis=0)
    return out


# ---------------------------------------------------------------- phones from audio

def phone_loop(samples: np.ndarray, rate: int, settings) -> list[Segment]:
    """pocketsphinx's phone-loop decoding (its en-us phone language model, no words) of mono
    ``samples``: Festival phones tiling the audio (silence and noise as pause)."""
    import pocketsphinx

    if rate != settings.sample_rate:
        samples, rate = resample(samples, rate, settings.sample_rate), settings.sample_rate
    model = os.path.join(pocketsphinx.get_model_path(), "en-us", "en-us-phone.lm.bin")
    decoder = pocketsphinx.Decoder(allphone=model, lm=None, samprate=rate, frate=settings.frame_rate,
                                   loglevel="FATAL", backtrace=False)
    pcm = (np.clip(np.asarray(samples, np.float64), -1, 1) * 32767).astype(np.int16)
    decoder.start_utt()
    decoder.process_raw(pcm.tobytes(), full_utt=True)
    decoder.end_utt()
    duration = len(samples) / rate
    segs, t = [], 0.0
    for s in decoder.seg():
        end = min((s.end_frame + 1) / settings.frame_rate, duration)
        if end <= t:
            continue
        segs.append(Segment(t, end, to_festival(s.word) or PAU))
        t = end
    if t < duration:
        segs.append(Segment(t, duration, PAU))
    return segs


def phones_from_audio(wav: Path, out: Path, settings) -> tuple[list[Segment], str]:
    """The phones of ``wav`` with their timing, written to ``out`` (TextGrid), and what made them:
    facesynth's own audio-only alignment (``facesynth align AUDIO -o OUT`` without text) where
    this facesynth has it, else pocketsphinx's phone loop (:func:`phone_loop`)."""
    from click.testing import CliRunner

    from facesynth.cli import main

    result = CliRunner().invoke(main, ["align", str(wav), "-o", str(out), "--overwrite", "-q"])
    if result.exit_code == 0 and out.exists():
        return read_phone_segments(out), "facesynth align (audio only)"
    samples, rate = read_audio(wav)
    segs = phone_loop(samples, rate, settings)
    write_textgrid(out, {"phones": segs}, xmax=len(samples) / rate)
    return segs, "pocketsphinx phone loop (en-us phone language model)"


# ---------------------------------------------------------------- methods

def facesynth_cli(*args: str) -> None:
    """Run one facesynth command (quiet); a failure stops the benchmark with its message."""
    done = subprocess.run([sys.executable, "-m", "facesynth.cli", *args, "-q"], capture_output=True, text=True, check=False)
    if done.returncode:
        raise SystemExit(f"facesynth {' '.join(args)} failed: {done.stderr.strip() or done.stdout.strip()}")


def build_database(work: Path, corpus_config: Path | None = None) -> Path:
    """The built-in actress's database (``small`` preset, seed 0) in ``work``, built once; the
    actress's settings from ``corpus_config`` (a ``--config`` file) where given."""
    db = work / "db.h5"
    if not db.exists():
        corpus = work / "corpus"
        if not (corpus / "manifest.csv").exists():
            config = ["--config", str(corpus_config)] if corpus_config else []
            facesynth_cli("sample-corpus", str(corpus), "--preset", "small", "--seed", "0", *config)
        steps = [("ingest", corpus / "manifest.csv", "corpus.h5"), ("normalize", "corpus.h5", "normalized.h5"),
                 ("pca", "normalized.h5", "pca.h5"), ("build-db", "pca.h5", "db.h5")]
        for command, src, dst in steps:
            if not (work / dst).exists():
                facesynth_cli(command, str(work / src), "-o", str(work / dst))
    return db


def facesynth_method(db: Path, phones: Path | None, folder: Path, n: int, lip_markers, method: str = "dp",
                     audio: Path | None = None, loudness_weight: float | None = None,
                     solve: bool = True, voice_given: str | None = None) -> dict[str, np.ndarray]:
    """facesynth's channels (n,) for a take: synthesize with ``method`` from ``db`` (the database,
    or the method's fitted model) on the recognised ``phones`` given as a file, with the take's
    ``audio`` (the voice moves the mouth too, by ``synthesize.voice_given``, or ``voice_given``
    where given: ``"loudness"`` its loudness, ``synthesize.loudness_weight`` or ``loudness_weight``
    where given) or without it (phones alone); or, ``phones`` None, from the audio alone (``synthesize --audio``: the phones
    recognised inside, the voice's articulation by ``synthesize.voice_recognized``); solve onto
    the built-in rig (unless ``solve`` is False: the mouth opening alone), read back."""
    from facesynth.domain.evaluation.held_out import lip_gaps
    from facesynth.model.curves import RigCurves
    from facesynth.model.motion import Motion

    tag = (("" if method == "dp" else f".{method}") + ("" if audio is not None else ".phones")
           + ("" if phones is not None else ".audio") + ("" if loudness_weight is None else f".w{loudness_weight:g}")
           + ("" if voice_given is None else f".{voice_given}"))
    motion, curves = folder / f"motion{tag}.h5", folder / f"curves{tag}.h5"
    given = (["--phonemes", str(phones)] if phones is not None else []) + (["--audio", str(audio)] if audio is not None else [])
    if loudness_weight is not None:
        given += ["--set", f"synthesize.loudness_weight={loudness_weight:g}"]
    if voice_given is not None:
        given += ["--set", f"synthesize.voice_given={voice_given}"]
    # The cached motion holds only for the source, phones, audio, options and settings it was made from.
    made_from = [phones.read_bytes() if phones is not None else b"", audio.read_bytes() if audio is not None else b"",
                 " ".join(given).encode(), settings_json(Config.load().settings("synthesize")).encode(),
                 settings_json(Config.load().settings("align")).encode(), ARTICULATION_MODEL.read_bytes(),
                 sha256_of(db).encode()]  # the database (or model) too: another one, another motion
    digest = hashlib.sha256(b"\0".join(made_from)).hexdigest()
    stamp = folder / f"inputs{tag}.sha256"
    if not stamp.exists() or stamp.read_text() != digest:
        motion.unlink(missing_ok=True)
        curves.unlink(missing_ok=True)
        stamp.write_text(digest)
    if not motion.exists():
        facesynth_cli("synthesize", "--method", method, str(db), *given, "-o", str(motion))
    m = Motion.read(motion)
    if m.fps != FPS:
        raise SystemExit(f"{motion}: output at {m.fps} frames/s; the benchmark needs synthesize.output_fps = {FPS:g}")
    out = {"opening": lip_gaps(m.markers, list(m.marker_names), lip_markers)}
    if solve:
        if not curves.exists():
            facesynth_cli("solve", str(motion), "-o", str(curves))
        c = RigCurves.read(curves)
        names = list(c.shape_names)
        for channel, shapes in RIG_SHAPES.items():
            out[channel] = c.weights[:, [names.index(s) for s in shapes]].mean(1)
    return {k: fit_length(v, n) for k, v in out.items()}


def voice_method(samples: np.ndarray, rate: int, n: int) -> dict[str, np.ndarray]:
    """The packaged articulation model's own curves (n,) for a take's audio (opening, jawOpen,
    mouthFunnel, mouthPucker): what the voice alone says, before any motion takes it in (in-sample
    on FACEGOOD: the packaged model is fitted on all its takes)."""
    from facesynth.domain.voice import articulation
    from facesynth.model.articulation import ArticulationModel

    model = ArticulationModel.read(ARTICULATION_MODEL)
    pred = articulation.predict(model, samples, rate, n, FPS)
    return {c: pred[:, model.column(c)] for c in ("opening", "jawOpen", "mouthFunnel", "mouthPucker")}


def actress_mean_method(database, segs: list[Segment], n: int, lip_markers) -> dict[str, np.ndarray]:
    """The actress's per-phone mean pose (``facesynth evaluate``'s ``baseline``) as a mouth opening (n,)."""
    from facesynth.domain.evaluation.held_out import lip_gaps
    from facesynth.domain.methods.mean import mean_pose_markers
    from facesynth.domain.speech.utterance import utterance

    utt = utterance([s.label for s in segs], np.array([s.start for s in segs]), np.array([s.end for s in segs]))
    gap = lip_gaps(mean_pose_markers(database, utt, by_emotion=False), list(database.marker_names), lip_markers)
    return {"opening": np.interp(np.arange(n) / FPS, np.arange(len(gap)) / database.fps, gap)}


def openfacefx_method(segs: list[Segment], n: int, rig, lip_vertices: np.ndarray) -> dict[str, np.ndarray]:
    """openfacefx's channels (n,) from the phones ``segs``."""
    arkit = openfacefx_arkit([s.label for s in segs], np.array([s.start for s in segs]),
                             np.array([s.end for s in segs]), n, FPS, rig.arkit_names)
    lips = rig_markers(rig, arkit, lip_vertices)
    out = {"opening": np.linalg.norm(lips[:, 0] - lips[:, 1], axis=1)}
    column = {a: i for i, a in enumerate(rig.arkit_names)}
    for channel, shapes in ARKIT_SHAPES.items():
        out[channel] = arkit[:, [column[s] for s in shapes]].mean(1)
    return out


def frame_phones(segs: list[Segment], n: int) -> list[str]:
    """The phone at each of ``n`` frame times f / FPS (the last one past the end)."""
    ends = np.array([s.end for s in segs])
    k = np.minimum(np.searchsorted(ends, np.arange(n) / FPS, side="right"), len(segs) - 1)
    return [segs[i].label for i in k]


def phone_means(takes: list[dict]) -> dict[str, dict[str, float]]:
    """{channel: {phone: mean real value over the frames of that phone}} over ``takes``
    (each with ``segs``, ``real``, ``n``); '' holds the overall mean (for unseen phones)."""
    out = {}
    for channel in CHANNELS:
        values = np.concatenate([t["real"][channel] for t in takes])
        labels = np.concatenate([frame_phones(t["segs"], t["n"]) for t in takes])
        out[channel] = {"": float(values.mean())}
        for p in np.unique(labels):
            out[channel][str(p)] = float(values[labels == p].mean())
    return out


def phone_mean_method(means: dict, segs: list[Segment], n: int) -> dict[str, np.ndarray]:
    """The per-phone means at phone centres, interpolated over the ``n`` frames."""
    centres = np.array([(s.start + s.end) / 2 for s in segs]) * FPS
    return {channel: np.interp(np.arange(n), centres, [m.get(s.label, m[""]) for s in segs])
            for channel, m in means.items()}


def load_npy(path: Path) -> np.ndarray:
    """A .npy file without pickles (FACEGOOD's were written by Python 2, which NumPy warns about)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return np.load(path, allow_pickle=False)


def fit_length(x: np.ndarray, n: int) -> np.ndarray:
    """``x`` cut or held to ``n`` frames (the synthesized take may end a frame early or late)."""
    x = np.asarray(x, np.float64)
    return x[:n] if len(x) >= n else np.concatenate([x, np.full(n - len(x), x[-1])])


# ---------------------------------------------------------------- the run

def add_scoring_options(ap: argparse.ArgumentParser) -> None:
    """The options of every real-speech benchmark's scoring: windows, the energy envelope, closures,
    the bootstrap, and ``--out`` (a markdown table)."""
    ap.add_argument("--window-s", type=float, default=10.0)
    ap.add_argument("--energy-smooth-s", type=float, default=0.1)
    ap.add_argument("--closure-depth", type=float, default=0.25)
    ap.add_argument("--closure-prominence", type=float, default=0.25)
    ap.add_argument("--closure-tolerance-frames", type=int, default=3)
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--out", type=Path, default=None, help="also write a markdown table here")


def channel_names(data: Path) -> list[str]:
    """FACEGOOD's 116 channel names, in the column order of its curves (``--data``'s names file)."""
    names_file = data / "shirley_1015_bs_name.npy"
    if not names_file.exists():
        raise SystemExit(f"{data}: no shirley_1015_bs_name.npy; see the layout in real_speech_lipsync.py's docstring")
    return [str(s) for s in load_npy(names_file)]


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", type=Path, required=True, help="the FACEGOOD folder (see the module docstring)")
    ap.add_argument("--work", type=Path, required=True,
                    help="cache: the database, phones, motion and curves (empty it after changing facesynth)")
    ap.add_argument("--takes", default=None, help="comma-separated take names (default: every wav/*.wav)")
    ap.add_argument("--before-work", type=Path, default=None,
                    help="the --work folder of an earlier run (e.g. with --corpus-config): its database scored "
                         "again on these phones as method facesynth_before, paired with facesynth")
    ap.add_argument("--corpus-config", type=Path, default=None,
                    help="a settings file for the actress's corpus (e.g. benchmarks/data/actress_uncalibrated.toml)")
    ap.add_argument("--loudness-weights", default=None,
                    help="comma-separated values of synthesize.loudness_weight: the DP's mouth-opening r with each "
                         "(loudness_sweep in the JSON), e.g. on the takes the weight is chosen on")
    add_scoring_options(ap)
    args = ap.parse_args(argv)

    missing = openfacefx_missing()
    if missing:
        raise SystemExit(missing)
    names = channel_names(args.data)
    take_names = args.takes.split(",") if args.takes else sorted(p.stem for p in (args.data / "wav").glob("*.wav"))
    if not take_names:
        raise SystemExit(f"{args.data / 'wav'}: no takes")
    config = Config.load()
    align_settings, lip_markers = config.settings("align"), config.settings("evaluate").lip_markers
    table = read_table()
    started = time.perf_counter()
    args.work.mkdir(parents=True, exist_ok=True)
    db = build_database(args.work, args.corpus_config)

    from facesynth.domain.rig.face import load_face_rig
    from facesynth.formats.mesh import read_binding
    from facesynth.model.motiondb import MotionDatabase

    rig, database = load_face_rig(), MotionDatabase.read(db)
    coarticulation = args.work / "coarticulation.h5"  # the fitted Cohen-Massaro model, a member users can choose
    if not coarticulation.exists():
        facesynth_cli("fit-method", "coarticulation", str(db), "-o", str(coarticulation))
    binding = read_binding(args.work / "corpus" / "markers.csv")
    lip_vertices = np.array([binding[m] for m in lip_markers])

    takes, sources = [], set()
    sweep: dict[float, list[np.ndarray]] = {float(w): [] for w in args.loudness_weights.split(",")} \
        if args.loudness_weights else {}
    for take in take_names:
        folder = args.work / "takes" / take
        folder.mkdir(parents=True, exist_ok=True)
        wav, curves_file = args.data / "wav" / f"{take}.wav", args.data / "bs_value_npy" / f"bs_value_{take}.npy"
        if not wav.exists() or not curves_file.exists():
            raise SystemExit(f"{args.data}: take {take!r} needs wav/{take}.wav and bs_value_npy/bs_value_{take}.npy")
        values = load_npy(curves_file)
        real = real_curves(np.asarray(values, np.float64), names, table)
        samples, rate = read_audio(wav)
        n = min(len(values), int(np.floor(len(samples) / rate * FPS)))
        real = {k: v[:n] for k, v in real.items()}
        segs, source = phones_from_audio(wav, folder / "phones.TextGrid", align_settings)
        sources.add(source)
        phones = folder / "phones.TextGrid"
        methods = {"facesynth": facesynth_method(db, None, folder, n, lip_markers, audio=wav),
                   "facesynth_loudness": facesynth_method(db, phones, folder, n, lip_markers, audio=wav,
                                                          voice_given="loudness"),
                   "facesynth_phones": facesynth_method(db, phones, folder, n, lip_markers),
                   "voice": voice_method(samples, rate, n),
                   "coarticulation": facesynth_method(coarticulation, phones, folder, n, lip_markers, "coarticulation",
                                                      audio=wav),
                   "coarticulation_phones": facesynth_method(coarticulation, phones, folder, n, lip_markers,
                                                             "coarticulation"),
                   "actress_mean": actress_mean_method(database, segs, n, lip_markers),
                   "openfacefx": openfacefx_method(segs, n, rig, lip_vertices)}
        if args.before_work:
            before = args.before_work / "takes" / take
            before.mkdir(parents=True, exist_ok=True)
            methods["facesynth_before"] = facesynth_method(build_database(args.before_work), phones, before, n,
                                                           lip_markers, audio=wav)
        for weight in sweep:
            sweep[weight].append(window_r(facesynth_method(db, phones, folder, n, lip_markers, audio=wav,
                                                           loudness_weight=weight, solve=False,
                                                           voice_given="loudness")["opening"],
                                          real["opening"], windows(n, FPS, args.window_s)))
        env = envelope(samples, rate, n, FPS, args.energy_smooth_s)
        methods["energy"] = {"opening": env, "jawOpen": env}
        takes.append({"take": take, "n": n, "segs": segs, "real": real, "methods": methods,
                      "spans": windows(n, FPS, args.window_s)})

    # The speaker's per-phone means: fitted on alternate takes, scored on the others.
    halves = [takes[0::2], takes[1::2]]
    for fit, score in ((halves[1], halves[0]), (halves[0], halves[1])):
        if fit:
            means = phone_means(fit)
            for t in score:
                t["methods"]["phone_mean"] = phone_mean_method(means, t["segs"], t["n"])

    r = {c: {} for c in CHANNELS}
    closures, per_take = {}, {}
    for t in takes:
        real_closures = closure_events(t["real"]["opening"], args.closure_depth, args.closure_prominence)
        per_take[t["take"]] = {"seconds": round(t["n"] / FPS, 2), "windows": len(t["spans"]),
                               "phones": sum(s.label != PAU for s in t["segs"]),
                               "real_closures": len(real_closures), "opening_r": {}}
        for method, curves in t["methods"].items():
            for channel, curve in curves.items():
                values = window_r(curve, t["real"][channel], t["spans"])
                r[channel].setdefault(method, []).append(values)
                if channel == "opening":
                    per_take[t["take"]]["opening_r"][method] = (float(np.nanmean(values)) if np.isfinite(values).any()
                                                                 else None)
            if "opening" in curves:
                events = closure_events(curves["opening"], args.closure_depth, args.closure_prominence)
                rows = []
                for a, b in t["spans"]:
                    rc, mc = real_closures[(real_closures >= a) & (real_closures < b)], events[(events >= a) & (events < b)]
                    hit_real = match_closures(rc, events, args.closure_tolerance_frames)[0]
                    hit_method = match_closures(real_closures, mc, args.closure_tolerance_frames)[1]
                    rows.append((len(rc), hit_real, len(mc), hit_method))
                closures.setdefault(method, []).append(np.array(rows, int).reshape(-1, 4))
    complete = {c: {m: np.concatenate(v) for m, v in per.items() if len(v) == len(takes)} for c, per in r.items()}
    complete = {c: per for c, per in complete.items() if per}
    closures = {m: np.concatenate(v) for m, v in closures.items() if len(v) == len(takes)}
    groups = np.concatenate([np.full(len(t["spans"]), i) for i, t in enumerate(takes)])
    summary = summarize(complete, closures, groups, args.resamples, args.seed)
    seconds = sum(t["n"] for t in takes) / FPS
    if sweep:
        index = resamples(len(groups), args.resamples, args.seed)
        summary["loudness_sweep"] = {f"{w:g}": interval(mean_r_statistic(np.concatenate(v)), len(groups), index)
                                     for w, v in sweep.items()}
    result = {
        "data": {"source": "FACEGOOD Audio2Face training takes (MIT)", "takes": take_names,
                 "seconds": round(seconds, 1), "real_opening": " + ".join(REAL_OPENING)},
        "phones_from": sorted(sources),
        "settings": {"fps": FPS, "window_s": args.window_s, "lag_frames": 0, "energy_smooth_s": args.energy_smooth_s,
                     "closure_depth": args.closure_depth, "closure_prominence": args.closure_prominence,
                     "closure_tolerance_frames": args.closure_tolerance_frames, "resamples": args.resamples,
                     "seed": args.seed, "phone_mean_fit": "alternate takes, two folds",
                     "corpus_config": args.corpus_config.name if args.corpus_config else "defaults"},
        **summary,
        "real_closures_per_minute": round(sum(p["real_closures"] for p in per_take.values()) / seconds * 60, 1),
        "per_take": per_take,
        "seconds": round(time.perf_counter() - started, 1),
    }
    if args.out:
        args.out.write_text(markdown(result), encoding="utf-8")
    return result


def _fmt(s: dict | None) -> str:
    if not s or s["value"] is None:
        return "—"
    if s["low"] is None:
        return f"{s['value']:.2f}"
    return f"{s['value']:.2f} [{s['low']:.2f}, {s['high']:.2f}]"


def markdown(result: dict) -> str:
    """The result as markdown tables: r per channel and method, paired differences, closures, takes."""
    methods = [m for m in METHODS if any(m in per for per in result["r"].values())]
    lines = [f"Real speech: {len(result['data']['takes'])} takes, {result['data']['seconds']:.0f} s, "
             f"{result['windows']} windows of ~{result['settings']['window_s']:g} s; phones from "
             f"{', '.join(result['phones_from'])}; lag 0. Mean Pearson r over windows [95% bootstrap interval].", "",
             "| channel | " + " | ".join(methods) + " |", "|---|" + "---|" * len(methods)]
    for channel, per in result["r"].items():
        lines.append(f"| {channel} | " + " | ".join(_fmt(per.get(m)) for m in methods) + " |")
    lines += ["", "| paired difference (mouth opening r) | over windows [95%] | over takes [95%] |", "|---|---|---|"]
    for name, s in result["paired"].get("opening", {}).items():
        lines.append(f"| {name} | {_fmt(s)} | {_fmt(result['paired_takes']['opening'][name])} |")
    lines += ["", f"Lip closures ({result['real_closures_per_minute']:g} real closures per minute, "
              f"+-{result['settings']['closure_tolerance_frames']} frames):", "",
              "| method | recall | precision | closures |", "|---|---|---|---|"]
    for m, c in result["closures"].items():
        lines.append(f"| {m} | {_fmt(c['recall'])} | {_fmt(c['precision'])} | {c['closures']} |")
    if result.get("loudness_sweep"):
        lines += ["", "| synthesize.loudness_weight | the loudness step's mouth-opening r (phones given) [95%] |", "|---|---|"]
        lines += [f"| {w} | {_fmt(cell)} |" for w, cell in result["loudness_sweep"].items()]
    lines += ["", "| take | seconds | " + " | ".join(f"{m} opening r" for m in methods) + " |",
              "|---|---|" + "---|" * len(methods)]
    for take, p in result["per_take"].items():
        lines.append(f"| {take} | {p['seconds']:.0f} | " + " | ".join(
            "—" if p["opening_r"].get(m) is None else f"{p['opening_r'][m]:.2f}" for m in methods) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
