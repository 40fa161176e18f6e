"""Real speakers with the mouth measured together with the sound, prepared into one layout for
the leave-speakers-out benchmarks. Prints JSON (the speakers, their utterances and seconds).

Nothing is downloaded: ``--raw`` names folders where the raw files already are (copies of the
public repositories below, each in a folder of its own or in ``--raw`` itself; a source's folder
is found by its files' relative paths). Every raw file used is listed with its sha256 in
:data:`FILES` and checked before use; a source none of whose files is found is skipped and
listed under ``missing`` (or refused when named in ``--sources``). FACEGOOD's folder is the one
``benchmarks/real_speech_lipsync.py`` reads (``--raw`` may name it directly).

Layout written under ``--out`` (a source is written to a temporary folder and moved into place
only when complete; a ``READY-<source>`` file marks it done)::

    <source>/<speaker>/<utterance>.wav   mono 16-bit PCM at the recording's own rate
    <source>/<speaker>/<utterance>.npz   times (N,) s; opening (N,); optional jaw (N,), rounding (N,)
    speakers.json                        one entry per speaker (see below)

All arrays are float64 of one length N, one value per measurement frame at ``times`` (seconds
from the wav's first sample). The measures, per kind of source:

- **EMA** (electromagnetic articulography; ``stem_e2va``, ``haskins``): ``opening`` is the 3-D
  distance between the upper- and lower-lip sensors (mm). The axes are found from the data: the
  vertical axis is the one along which the upper lip lies farthest from the lower lip (up =
  upper lip's side), the front-back axis the one along which the tongue sensors spread most
  (front = the tongue tip's side). ``jaw`` is the lowering of the jaw (lower-incisor) sensor
  along the vertical axis (mm, larger = lower, relative to the utterance's highest position)
  where there is one; ``rounding`` is minus the distance between the two lip-corner sensors
  (mm; larger = narrower mouth) where both corners are measured, else the lips' protrusion (the
  mean of the upper- and lower-lip sensors along the front-back axis, mm, larger = further
  forward, relative to the utterance's median). Short sensor dropouts (NaN, at most 0.1 s) are
  filled linearly; an utterance with longer ones is left out.
- **video** (``video_retalking``): the clip's face tracked with MediaPipe Face Mesh
  (:func:`facesynth.domain.capture.video_take.track`, the ``ingest`` video route) at the
  container's frame rate; ``opening`` is the inner-lip gap (landmarks 13-14) divided by the
  outer eye corners' distance (33-263) in the same frame, ``rounding`` minus the mouth's width
  (corners 61-291) divided by the same. Frames without a face are NaN, filled when at most
  0.1 s; a clip with longer gaps is left out. The sound is the clip's own track.
- **facegood**: FACEGOOD's solved curves at 30 frames/s (``real_speech_lipsync.py``): ``opening``
  = ``mouth_stretch_c + mouth_oh_c``, ``jaw`` = ``mouth_stretch_c`` (jawOpen in FACEGOOD's ARKit
  table), ``rounding`` = mouthFunnel + mouthPucker from that table.

``speakers.json`` lists, per speaker: source, speaker, sex, language, setting (microphone and
recording), repository, licence, may_ship (whether the licence lets the data ship in the package;
data without a licence that grants use serves local benchmarks only), utterances, seconds, rate
(measurement frames/s), opening_unit, jaw (bool), rounding (what it measures), and the sync check:
``lag_s``, the lag at which the opening best follows the audio's log-RMS envelope (positive =
the mouth leads the sound), searched within +-0.3 s on the cross-correlation of the two per-
utterance z-scored curves pooled over the speaker's utterances, with ``lag_r`` (r at that lag)
and ``r0`` (r at lag 0), and ``sync``: "ok", "offset" (best lag beyond 0.15 s and its r at
least 0.1 above lag 0's: articulation normally leads the sound by a few tens of ms, so more means
a misaligned file; in a clip of a few seconds the peak wanders, hence the margin) or "weak" (best r
below 0.2: the curves are too weakly related to tell, e.g. a short clip, continuous speech over
noise, or a face that listens while someone else talks). ``READY-<source>`` holds the source's
summary: speakers, seconds, and the same check pooled over all its utterances (``pooled_sync``;
None when they differ in frame rate), which is steadier than one short clip's.

    python benchmarks/speaker_data.py --raw RAW_DIR [RAW_DIR ...] --out SPEECH_DATA [--sources stem_e2va,haskins]
"""

from __future__ import annotations

import argparse
import hashlib
import importlib.util
import json
import pickle
import shutil
import sys
import tempfile
import zipfile
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from facesynth.base.errors import InputError
from facesynth.formats.audio import read_audio, write_wav

HERE = Path(__file__).resolve().parent
#: Longest sensor or tracking gap filled by interpolation (s).
MAX_GAP_S = 0.1
#: Lags searched by the sync check (s).
MAX_LAG_S = 0.3
#: The sync check's verdicts: a best lag beyond this (s) whose r beats lag 0's by OFFSET_GAIN is
#: an ``offset``...
OFFSET_S = 0.15
OFFSET_GAIN = 0.1
#: ...unless the best r is below this: then the curves are too weakly related to tell (``weak``).
WEAK_R = 0.2


@dataclass(frozen=True)
class Speaker:
    """One recorded person: sex ("F"/"M"), language, and the microphone and recording setting."""

    sex: str
    language: str
    setting: str


@dataclass(frozen=True)
class Utterance:
    """One prepared recording: mono ``samples`` (S,) float32 at ``rate`` Hz, and the mouth
    measures at ``times`` (N,) s: ``opening`` (N,) and optional ``jaw``, ``rounding`` (N,)."""

    speaker: str
    name: str
    samples: np.ndarray
    rate: int
    times: np.ndarray
    opening: np.ndarray
    jaw: np.ndarray | None = None
    rounding: np.ndarray | None = None


@dataclass(frozen=True)
class Source:
    """A public source: its repository, licence, whether it may ship, its speakers, what its
    measures are, and the reader that turns its raw files (under a root folder) into utterances."""

    name: str
    repository: str
    licence: str
    may_ship: bool
    speakers: dict[str, Speaker]
    opening_unit: str
    rounding: str
    reader: Callable[[Path, list[str]], Iterator[Utterance]]
    files: list[str] = field(default_factory=list)


# ---------------------------------------------------------------- pure measures (tests call these)

def fill_gaps(x: np.ndarray, rate: float, max_gap_s: float = MAX_GAP_S) -> np.ndarray | None:
    """(N,) or (N, D) values with NaN gaps -> the same with gaps of at most ``max_gap_s`` filled
    linearly (ends held), or None when a longer gap (or no value at all) is found."""
    x = np.array(x, np.float64)
    flat = x.reshape(len(x), -1)
    bad = np.isnan(flat).any(axis=1)
    if not bad.any():
        return x
    if bad.all():
        return None
    edges = np.diff(np.concatenate([[0], bad.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    if ((ends - starts) / rate > max_gap_s).any():
        return None
    idx, good = np.arange(len(x)), ~bad
    for d in range(flat.shape[1]):
        flat[:, d] = np.interp(idx, idx[good], flat[good, d])
    return flat.reshape(x.shape)


def ema_axes(upper: np.ndarray, lower: np.ndarray, tongue_back: np.ndarray, tongue_tip: np.ndarray
             ) -> tuple[int, float, int, float]:
    """(vertical axis, its sign, front-back axis, its sign) of an EMA coordinate frame from (N, 3)
    sensor positions: up is the upper lip's side of the lower lip, front the tongue tip's side of
    the tongue's back (the axes of largest mean separation; the two are different axes)."""
    lips = np.nanmean(upper - lower, axis=0)
    vertical = int(np.argmax(np.abs(lips)))
    tongue = np.nanmean(tongue_tip - tongue_back, axis=0)
    tongue[vertical] = 0.0
    front = int(np.argmax(np.abs(tongue)))
    return vertical, float(np.sign(lips[vertical])), front, float(np.sign(tongue[front]))


def ema_measures(upper: np.ndarray, lower: np.ndarray, tongue_back: np.ndarray, tongue_tip: np.ndarray,
                 jaw: np.ndarray | None = None, corners: tuple[np.ndarray, np.ndarray] | None = None
                 ) -> dict[str, np.ndarray]:
    """Mouth measures (N,) mm from (N, 3) EMA sensor positions in mm (module docstring): opening,
    jaw (when a jaw sensor is given), rounding (lip-corner width when both corners are given,
    else protrusion)."""
    vertical, up, front, forward = ema_axes(upper, lower, tongue_back, tongue_tip)
    out = {"opening": np.linalg.norm(upper - lower, axis=1)}
    if jaw is not None:
        height = up * jaw[:, vertical]
        out["jaw"] = height.max() - height
    if corners is not None:
        out["rounding"] = -np.linalg.norm(corners[0] - corners[1], axis=1)
    else:
        protrusion = forward * 0.5 * (upper[:, front] + lower[:, front])
        out["rounding"] = protrusion - np.median(protrusion)
    return out


def video_measures(points: np.ndarray) -> dict[str, np.ndarray]:
    """Mouth measures (T,) from Face Mesh landmarks (T, 478, 3) (any length unit; NaN rows = no
    face): opening = inner-lip gap / outer eye corners' distance, rounding = -mouth width / the same."""
    eyes = np.linalg.norm(points[:, 33] - points[:, 263], axis=1)
    return {"opening": np.linalg.norm(points[:, 13] - points[:, 14], axis=1) / eyes,
            "rounding": -np.linalg.norm(points[:, 61] - points[:, 291], axis=1) / eyes}


def log_rms(samples: np.ndarray, rate: int, times: np.ndarray, window_s: float) -> np.ndarray:
    """(N,) log-RMS of mono ``samples`` in windows of ``window_s`` centred on ``times`` (s), floored
    at 1e-4 of the loudest window's RMS."""
    x = np.asarray(samples, np.float64)
    c2 = np.concatenate([[0.0], np.cumsum(x * x)])
    half = max(1, int(round(window_s * rate / 2)))
    centres = np.round(np.asarray(times) * rate).astype(np.int64)
    a, b = np.clip(centres - half, 0, len(x)), np.clip(centres + half, 0, len(x))
    rms = np.sqrt((c2[b] - c2[a]) / np.maximum(b - a, 1))
    return np.log(np.maximum(rms, 1e-4 * max(float(rms.max(initial=0.0)), 1e-12)))


def sync_lag(pairs: list[tuple[np.ndarray, np.ndarray]], rate: float, max_lag_s: float = MAX_LAG_S
             ) -> dict[str, float]:
    """The lag (s) at which ``opening`` best follows ``loudness``, pooled over (opening (N,),
    loudness (N,)) pairs sampled at ``rate`` Hz: the pooled Pearson r of the per-pair z-scored
    curves at each lag in +-``max_lag_s``. Positive lag = the opening leads the loudness.
    Returns {lag_s, lag_r, r0}."""
    k = int(round(max_lag_s * rate))
    lags = np.arange(-k, k + 1)
    sums, counts = np.zeros(len(lags)), np.zeros(len(lags))
    for opening, loud in pairs:
        o = (opening - opening.mean()) / (opening.std() or 1.0)
        e = (loud - loud.mean()) / (loud.std() or 1.0)
        n = len(o)
        for i, lag in enumerate(lags):
            if abs(lag) >= n:
                continue
            # opening at t against loudness at t + lag
            a, b = (o[: n - lag], e[lag:]) if lag >= 0 else (o[-lag:], e[: n + lag])
            sums[i] += float(a @ b)
            counts[i] += len(a)
    r = sums / np.maximum(counts, 1)
    best = int(np.argmax(r))
    return {"lag_s": round(float(lags[best] / rate), 4), "lag_r": round(float(r[best]), 3),
            "r0": round(float(r[k]), 3)}


def sync_verdict(lag: dict[str, float]) -> str:
    """"ok", "offset" (best lag beyond :data:`OFFSET_S` with an r :data:`OFFSET_GAIN` above lag
    0's) or "weak" (best r below :data:`WEAK_R`) for a :func:`sync_lag` result."""
    if lag["lag_r"] < WEAK_R:
        return "weak"
    shifted = abs(lag["lag_s"]) > OFFSET_S and lag["lag_r"] - lag["r0"] >= OFFSET_GAIN
    return "offset" if shifted else "ok"


# ---------------------------------------------------------------- readers

def stem_e2va(root: Path, files: list[str]) -> Iterator[Utterance]:
    """STEM-E2VA: ``matfiles/<name>.mat`` (N, 42) at 250 Hz (7 sensors x X, Y, Z, phi, theta,
    RMS: upper lip, lower lip, left and right lip corners, tongue root, middle, tip) with
    ``wavfiles/<name>.wav`` (48 kHz, the articulograph's microphone, same start); name =
    speaker (3 letters), sex, emotion, text number."""
    from scipy.io import loadmat

    rate = 250.0
    for rel in files:
        if not rel.startswith("matfiles/"):
            continue
        name = Path(rel).stem
        data = loadmat(str(root / rel))[name]
        if data.ndim != 2 or data.shape[1] != 42:
            raise InputError(f"{root / rel}: expected a (frames, 42) array named {name}; got {data.shape}.")
        xyz = fill_gaps(data.reshape(len(data), 7, 6)[:, :, :3], rate)
        if xyz is None:
            continue
        samples, audio_rate = read_audio(root / "wavfiles" / f"{name}.wav")
        m = ema_measures(xyz[:, 0], xyz[:, 1], xyz[:, 4], xyz[:, 6], corners=(xyz[:, 2], xyz[:, 3]))
        yield Utterance(name[:3], name, samples, audio_rate, np.arange(len(xyz)) / rate, m["opening"],
                        rounding=m["rounding"])


class _NumpyOnlyUnpickler(pickle.Unpickler):
    """Unpickles dicts, lists and NumPy arrays only (the viewer's .pkl files); anything else is refused."""

    ALLOWED = {("numpy._core.multiarray", "_reconstruct"), ("numpy.core.multiarray", "_reconstruct"),
               ("numpy", "ndarray"), ("numpy", "dtype"), ("numpy._core.multiarray", "scalar"),
               ("numpy.core.multiarray", "scalar")}

    def find_class(self, module: str, name: str):
        if (module, name) not in self.ALLOWED:
            raise pickle.UnpicklingError(f"refused to load {module}.{name}")
        return super().find_class(module, name)


def _haskins_tracks(path: Path) -> tuple[dict[str, np.ndarray], np.ndarray, int]:
    """{sensor: (N, 3) positions mm}, audio (S,), audio rate of a Haskins MVIEW .mat or its .pkl copy."""
    if path.suffix == ".pkl":
        with path.open("rb") as f:
            record = _NumpyOnlyUnpickler(f).load()
        tracks = {k: np.asarray(v["SIGNAL"], np.float64) for k, v in record.items()}
        rates = {k: float(np.asarray(v["SRATE"]).ravel()[0]) for k, v in record.items()}
    else:
        from scipy.io import loadmat

        mat = loadmat(str(path))
        struct = mat[path.stem][0]
        tracks = {str(r["NAME"][0]): np.asarray(r["SIGNAL"], np.float64) for r in struct}
        rates = {str(r["NAME"][0]): float(np.asarray(r["SRATE"]).ravel()[0]) for r in struct}
    if rates.get("UL") != 100.0:
        raise InputError(f"{path}: expected the sensors at 100 Hz; its UL track says {rates.get('UL')}.")
    audio = tracks.pop("AUDIO").ravel()
    return {k: v[:, :3] for k, v in tracks.items()}, audio, int(rates["AUDIO"])


def haskins(root: Path, files: list[str]) -> Iterator[Utterance]:
    """Haskins IEEE rate-comparison samples (MVIEW structs: AUDIO at 44.1 kHz, sensors TR, TB, TT,
    UL, LL, (ML,) JAW, (JAWL) at 100 Hz, columns X, Y, Z, ...; same start); speaker = name's
    first field."""
    rate = 100.0
    for rel in files:
        path = root / rel
        tracks, audio, audio_rate = _haskins_tracks(path)
        n = min(len(v) for v in tracks.values())
        stacked = fill_gaps(np.stack([tracks[k][:n] for k in ("UL", "LL", "TR", "TT", "JAW")], axis=1), rate)
        if stacked is None:
            continue
        peak = float(np.abs(audio).max())
        samples = (audio / peak * 0.9 if peak > 1.0 else audio).astype(np.float32)
        m = ema_measures(stacked[:, 0], stacked[:, 1], stacked[:, 2], stacked[:, 3], jaw=stacked[:, 4])
        yield Utterance(path.stem.split("_")[0], path.stem, samples, audio_rate, np.arange(n) / rate,
                        m["opening"], jaw=m["jaw"], rounding=m["rounding"])


def video_clips(speaker_of: dict[str, str], root: Path, files: list[str]) -> Iterator[Utterance]:
    """Talking-face clips with their sound; ``speaker_of`` maps a clip's file stem to its speaker."""
    from facesynth.domain.capture.video_take import track
    from facesynth.formats import video

    for rel in files:
        path = root / rel
        info = video.probe(path)
        if info.audio_rate is None:
            raise InputError(f"{path}: the clip has no sound track.")
        points = track(video.frames(path, info), str(path))
        m = {k: fill_gaps(v, info.fps) for k, v in video_measures(points).items()}
        if m["opening"] is None or m["rounding"] is None:
            continue
        samples = video.sound(path, info.audio_rate)
        yield Utterance(speaker_of[path.stem], path.stem, samples, info.audio_rate,
                        np.arange(len(points)) / info.fps, m["opening"], rounding=m["rounding"])


#: video-retalking's example faces: clip stem -> (speaker, sex, frame rate).
RETALKING = {"1": ("face1", "M", "22 frames/s, variable"), "2": ("face2", "M", "25 frames/s"),
             "3": ("face3", "F", "25 frames/s"), "4": ("face4", "F", "30 frames/s"),
             "5": ("face5", "F", "25 frames/s")}
#: GRID clips in LipNet's evaluation samples: clip stem -> (speaker, sex). Speakers are told apart
#: by their faces (GRID's speaker numbers are not in the file names); ``id2_vcd_swwp2s`` is the
#: same man as ``pwij3p``.
GRID = {"bbaf2n": ("grid01", "M"), "brbk7n": ("grid02", "F"), "lbax4n": ("grid03", "M"), "lbbc2a": ("grid04", "F"),
        "lrwp9a": ("grid05", "F"), "lwbsza": ("grid06", "F"), "pwij3p": ("grid07", "M"),
        "id2_vcd_swwp2s": ("grid07", "M"), "sbia1a": ("grid08", "M"), "sbwe5n": ("grid09", "M"),
        "swiz3n": ("grid10", "M")}


#: PC-AVS's demo clips (VoxCeleb2 crops): clip stem -> (speaker, sex). Speakers told apart by
#: their faces: 741400104 and 741400163 are one man, 00002 and 517600055 one woman.
PCAVS = {"00015": ("vox01", "M"), "00086": ("vox02", "M"), "00373": ("vox03", "F"), "681100216": ("vox04", "M"),
         "741400104": ("vox05", "M"), "741400163": ("vox05", "M"), "00002": ("vox06", "F"),
         "517600055": ("vox06", "F"), "00010": ("vox07", "M"), "00098": ("vox08", "M"), "00473": ("vox09", "M"),
         "620900105": ("vox10", "M"), "731200067": ("vox11", "M"), "796100172": ("vox12", "M")}


def zipped_clips(speaker_of: dict[str, str], root: Path, files: list[str]) -> Iterator[Utterance]:
    """Talking-face clips inside zip archives (members whose stem ``speaker_of`` names), read as
    :func:`video_clips` reads loose ones."""
    with tempfile.TemporaryDirectory() as tmp:
        members = []
        for rel in files:
            with zipfile.ZipFile(root / rel) as archive:
                for member in sorted(archive.namelist()):
                    if member.endswith(".mp4") and Path(member).stem in speaker_of:
                        archive.extract(member, tmp)
                        members.append(member)
        yield from video_clips(speaker_of, Path(tmp), members)


def load_lipsync() -> Any:
    """``benchmarks/real_speech_lipsync.py`` as a module (FACEGOOD's channels and table)."""
    spec = importlib.util.spec_from_file_location("real_speech_lipsync", HERE / "real_speech_lipsync.py")
    if spec is None or spec.loader is None:
        raise InputError(f"{HERE / 'real_speech_lipsync.py'}: cannot be loaded; run this script from the repository.")
    lipsync = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(lipsync)
    return lipsync


def facegood(root: Path, files: list[str]) -> Iterator[Utterance]:
    """FACEGOOD's takes: ``wav/<take>.wav`` (16 kHz) with ``bs_value_npy/bs_value_<take>.npy``
    (frames, 116) at 30 frames/s and the channel names ``shirley_1015_bs_name.npy``."""
    lipsync = load_lipsync()
    names = lipsync.channel_names(root)
    table = lipsync.read_table()
    for rel in files:
        if not rel.startswith("wav/"):
            continue
        take = Path(rel).stem
        samples, rate = read_audio(root / rel)
        values = np.asarray(lipsync.load_npy(root / "bs_value_npy" / f"bs_value_{take}.npy"), np.float64)
        n = min(len(values), int(np.floor(len(samples) / rate * 30.0)))
        real = {k: v[:n] for k, v in lipsync.real_curves(values, names, table).items()}
        col = {c: i for i, c in enumerate(names)}
        yield Utterance("performer", take, samples, rate, np.arange(n) / 30.0, real["opening"],
                        jaw=values[:n, col["mouth_stretch_c"]], rounding=real["mouthFunnel"] + real["mouthPucker"])


# ---------------------------------------------------------------- the sources

SOURCES = {s.name: s for s in (
    Source("stem_e2va", "github.com/zziqian/STEM-E2VA at a71b72090501", "none stated (the README: samples released for review)",
           False,
           {"CXY": Speaker("F", "Mandarin", "EMA (250 Hz) with the articulograph's microphone, 48 kHz; read "
                                            "sentences in seven emotions"),
            "DPM": Speaker("M", "Mandarin", "EMA (250 Hz) with the articulograph's microphone, 48 kHz; read "
                                            "sentences in seven emotions"),
            "JJW": Speaker("M", "Mandarin", "EMA (250 Hz) with the articulograph's microphone, 48 kHz; read "
                                            "sentences in seven emotions")},
           "mm (lip sensor distance)", "minus lip-corner distance (mm)", stem_e2va),
    Source("haskins", "github.com/jaekookang/Python-EMA-Viewer (Haskins IEEE rate comparison samples) at 4c09b275e336",
           "none stated in the repository", False,
           {"F01": Speaker("F", "English (US)", "EMA (NDI Wave, 100 Hz) with a head-mounted microphone, 44.1 kHz; "
                                                "IEEE sentence, normal rate"),
            "M01": Speaker("M", "English (US)", "EMA (NDI Wave, 100 Hz) with a head-mounted microphone, 44.1 kHz; "
                                                "IEEE sentence, normal rate"),
            "M04": Speaker("M", "English (US)", "EMA (NDI Wave, 100 Hz) with a head-mounted microphone, 44.1 kHz; "
                                                "IEEE sentence, normal rate")},
           "mm (lip sensor distance)", "lip protrusion (mm, from the utterance's median)", haskins),
    Source("video_retalking", "github.com/OpenTalker/video-retalking (examples/face/*.mp4) at d32e8e582482",
           "Apache-2.0 (the repository); the footage's own origin and rights are not stated", False,
           {spk: Speaker(sex, "English (presumably; not checked by listening)",
                         f"broadcast-style video ({fps}), frontal, its AAC sound track at 44.1 kHz; lips tracked with "
                         "MediaPipe Face Mesh") for spk, sex, fps in RETALKING.values()},
           "inner-lip gap / outer eye corners' distance", "minus mouth width / outer eye corners' distance",
           partial(video_clips, {k: v[0] for k, v in RETALKING.items()})),
    Source("grid", "github.com/rizkiarm/LipNet (evaluation/samples/: clips of the GRID corpus) at bec592aa1e66",
           "CC BY 4.0 (the GRID corpus, Cooke, Barker, Cunningham and Shao 2006; attribution required)", True,
           {spk: Speaker(sex, "English (British)", "GRID studio: frontal video 25 frames/s, 360x288 MPEG-1, with its "
                                                   "sound (MP2, 44.1 kHz); lips tracked with MediaPipe Face Mesh")
            for spk, sex in GRID.values()},
           "inner-lip gap / outer eye corners' distance", "minus mouth width / outer eye corners' distance",
           partial(video_clips, {k: v[0] for k, v in GRID.items()})),
    Source("pcavs", "github.com/Hangz-nju-cuhk/Talking-Face_PC-AVS (misc/*.zip: VoxCeleb2 clips) at 201d2b946caa",
           "CC BY 4.0 (the repository); the clips are VoxCeleb2 excerpts of online videos whose rights are not "
           "granted", False,
           {spk: Speaker(sex, "English (presumably; not checked by listening)",
                         "interview and broadcast video (VoxCeleb2), 224x224 face crops at 25 frames/s with 16 kHz "
                         "sound, each clip its own microphone and room; lips tracked with MediaPipe Face Mesh")
            for spk, sex in PCAVS.values()},
           "inner-lip gap / outer eye corners' distance", "minus mouth width / outer eye corners' distance",
           partial(zipped_clips, {k: v[0] for k, v in PCAVS.items()})),
    Source("facegood", "github.com/FACEGOOD/FACEGOOD-Audio2Face (code/train/wav, code/train/bs_value; as real_speech_lipsync.py reads it)", "MIT", True,
           {"performer": Speaker("F", "Mandarin (presumably)", "studio microphone, 16 kHz; face solved from video "
                                                               "into 116 blendshape curves, 30 frames/s")},
           "blendshape weight (mouth_stretch_c + mouth_oh_c)", "mouthFunnel + mouthPucker (weights)", facegood),
)}


# ---------------------------------------------------------------- preparation

def file_table() -> dict[str, dict[str, str]]:
    """{source: {relative path: sha256}} from :data:`FILES`."""
    out: dict[str, dict[str, str]] = {}
    for line in FILES.strip().splitlines():
        source, rel, digest = line.split()
        out.setdefault(source, {})[rel] = digest
    return out


def find_root(rels: list[str], raws: list[Path]) -> Path | None:
    """The first of the ``raws`` folders, or their immediate subfolders, holding the first of ``rels``."""
    for raw in raws:
        for candidate in [raw, *sorted(p for p in raw.iterdir() if p.is_dir())]:
            if (candidate / rels[0]).is_file():
                return candidate
    return None


def sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def check_files(root: Path, table: dict[str, str]) -> None:
    """Every file of ``table`` exists under ``root`` with its sha256, or one sentence naming the first that does not."""
    for rel, digest in table.items():
        path = root / rel
        if not path.is_file():
            raise InputError(f"{path}: missing; the source's copy under {root} is incomplete (every file listed in "
                             "benchmarks/speaker_data.py's FILES is needed).")
        if sha256(path) != digest:
            raise InputError(f"{path}: sha256 differs from the one in benchmarks/speaker_data.py's FILES; this is not "
                             "the file it was prepared from, use the repository's copy at the commit named in SOURCES.")


def write_utterances(utterances: Iterator[Utterance], folder: Path) -> tuple[dict[str, dict], dict[str, list]]:
    """Write each utterance's wav and npz under ``folder/<speaker>/``; return per speaker its
    totals ({utterances, seconds, jaw, rate}) and its (opening, loudness) pairs for the sync check."""
    stats: dict[str, dict] = {}
    pairs: dict[str, list] = {}
    for u in utterances:
        speaker_folder = folder / u.speaker
        speaker_folder.mkdir(parents=True, exist_ok=True)
        write_wav(speaker_folder / f"{u.name}.wav", u.samples, u.rate)
        arrays = {"times": u.times, "opening": u.opening}
        arrays.update({k: v for k, v in (("jaw", u.jaw), ("rounding", u.rounding)) if v is not None})
        columns: dict[str, Any] = {k: np.asarray(v, np.float64) for k, v in arrays.items()}
        np.savez(speaker_folder / f"{u.name}.npz", **columns)
        s = stats.setdefault(u.speaker, {"utterances": 0, "seconds": 0.0, "jaw": u.jaw is not None})
        s["utterances"] += 1
        s["seconds"] += len(u.samples) / u.rate
        frame_rate = 1.0 / float(np.median(np.diff(u.times)))
        s["rate"] = round(frame_rate, 3)
        pairs.setdefault(u.speaker, []).append(
            (u.opening, log_rms(u.samples, u.rate, u.times, max(2.0 / frame_rate, 0.025))))
    return stats, pairs


def prepare(source: Source, root: Path, rels: list[str], out: Path) -> tuple[list[dict], dict]:
    """Write ``source``'s utterances under ``out/<source>`` (via a temporary folder) and return its
    speakers' entries for speakers.json and the source's summary (speakers, seconds, and the sync
    check pooled over all its utterances where they share one frame rate, else None)."""
    tmp = out / f".{source.name}.partial"
    shutil.rmtree(tmp, ignore_errors=True)
    try:
        stats, pairs = write_utterances(source.reader(root, rels), tmp)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)  # no half-written source is left behind
        raise
    entries = []
    for speaker, s in sorted(stats.items()):
        info = source.speakers[speaker]
        lag = sync_lag(pairs[speaker], s["rate"])
        entries.append({"source": source.name, "speaker": speaker, "sex": info.sex, "language": info.language,
                        "setting": info.setting, "repository": source.repository, "licence": source.licence,
                        "may_ship": source.may_ship, "utterances": s["utterances"],
                        "seconds": round(s["seconds"], 2), "rate": s["rate"], "opening_unit": source.opening_unit,
                        "jaw": s["jaw"], "rounding": source.rounding, **lag, "sync": sync_verdict(lag)})
    rates = {e["rate"] for e in entries}
    pooled = sync_lag([p for spk in sorted(pairs) for p in pairs[spk]], rates.pop()) if len(rates) == 1 else None
    summary = {"source": source.name, "speakers": len(entries), "seconds": round(sum(e["seconds"] for e in entries), 1),
               "pooled_sync": pooled}
    final = out / source.name
    shutil.rmtree(final, ignore_errors=True)
    tmp.rename(final)
    return entries, summary


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--raw", type=Path, nargs="+", required=True,
                    help="folders holding the raw copies (each source in the folder itself or a subfolder)")
    ap.add_argument("--out", type=Path, required=True, help="the prepared layout's folder")
    ap.add_argument("--sources", default=None, help=f"comma-separated, of {', '.join(SOURCES)} (default: all found)")
    args = ap.parse_args(argv)
    tables = file_table()
    wanted = args.sources.split(",") if args.sources else list(SOURCES)
    unknown = [w for w in wanted if w not in SOURCES]
    if unknown:
        raise InputError(f"--sources: unknown {', '.join(unknown)}; choose from {', '.join(SOURCES)}.")
    for raw in args.raw:
        if not raw.is_dir():
            raise InputError(f"{raw}: not a folder; --raw names folders holding the raw copies.")
    args.out.mkdir(parents=True, exist_ok=True)
    listing = args.out / "speakers.json"
    entries = [e for e in (json.loads(listing.read_text()) if listing.exists() else []) if e["source"] not in wanted]
    missing: list[str] = []
    summaries: list[dict] = []
    for name in wanted:
        source, table = SOURCES[name], tables[name]
        rels = sorted(table)
        root = find_root(rels, args.raw)
        if root is None:
            if args.sources:
                raise InputError(f"{rels[0]}: not found under {', '.join(map(str, args.raw))}; give the folder "
                                 f"holding {source.repository}'s files with --raw.")
            missing.append(name)
            continue
        check_files(root, table)
        speakers, summary = prepare(source, root, rels, args.out)
        entries.extend(speakers)
        summaries.append(summary)
        order = list(SOURCES)
        entries.sort(key=lambda e: (order.index(e["source"]), e["speaker"]))
        listing.write_text(json.dumps(entries, indent=1) + "\n")
        (args.out / f"READY-{name}").write_text(json.dumps(summary) + "\n")
    result = {"speakers": entries, "sources": summaries, "missing": missing,
              "seconds": round(sum(e["seconds"] for e in entries), 1),
              "by_sex": {sex: sum(e["sex"] == sex for e in entries) for sex in ("F", "M")}}
    print(json.dumps(result, indent=1))
    return result


#: Every raw file used: source, path relative to the source's folder, sha256.
FILES = """
stem_e2va matfiles/CXYFIA01.mat a3cd02780c27e24541beea395a331f107ad7736b43226e4020bf7856f9223d6c
stem_e2va matfiles/CXYFIA02.mat 1b962a37104582b4c0fe539f6ce69e799c541f3d43d3cd1ad8a495fce4acd0ec
stem_e2va matfiles/CXYFIA03.mat b839d3d872818d406e78f3fc065d3342bf91295a061c6fb2c97dc2612719fbd7
stem_e2va matfiles/CXYFIA04.mat 5ac9c6a7e4c24633979d7f3bb4d887c60b81da251a8a1544b35c8997eb869025
stem_e2va matfiles/CXYFIA06.mat 1b90cc6d2cea3e814ee5286c32406bd657f16f1c3028e985a6fe94ad2a1c351a
stem_e2va matfiles/CXYFIA07.mat 1e7e77b64f1d3b6222f29c6774d9ac98591dfa2f24c6a6c1ec71f1019a06b2c0
stem_e2va matfiles/CXYFIA08.mat e162277b4f33c42e2f3161bd4e936daea3e359efe26a1547189344ca51266614
stem_e2va matfiles/CXYFIA09.mat bb2a26616207510c7d2c0244373e4f59264823faad9d0c63c876fb1d44a4bb75
stem_e2va matfiles/CXYFIA10.mat 5ac2750bdd41fae1ec73bd1ee45f54fc705a13a353e1677c0878a876f78c705d
stem_e2va matfiles/CXYFIA11.mat 2d2277a9eb49bd5d17bcb0d2fc8105534c2feb19e18389cc08f53e371c06c302
stem_e2va matfiles/CXYFIA12.mat 61619c5ff49c3fecd7d4f25db500a9916c8ca20fb4500ca8059139a30441cc4a
stem_e2va matfiles/CXYFIA13.mat bb9db72086e91e4bf1146530a9a64cd01104dbd0fbd1861d9382892c1e56dc2b
stem_e2va matfiles/CXYFIA14.mat 295b217dc64441f0d165f654136dccbe58032edc873b01dec0398445dd041692
stem_e2va matfiles/CXYFIA15.mat d54890b895f12afa9ebd80aefb24ac65277fa8d69eb599dcba17d213e76e0e80
stem_e2va matfiles/CXYFIA16.mat da63f9374ce27460659dcf25e80be21a725e404d1d38799d0f576dbc1d51ff5a
stem_e2va matfiles/CXYFIJ01.mat 6c75dcd779f7c027a44daaf31fa7477603aba5d37a17c0e54795ae9b0f3bce0c
stem_e2va matfiles/CXYFIJ02.mat ed1571a37b063baea15cfd9d4e42082290d1f701f0a0f2d1670f432ce668db45
stem_e2va matfiles/CXYFIJ03.mat b5bb640c24c97ef02b5a39dbf62caea295edd544b3bba205b412c978ce950efe
stem_e2va matfiles/CXYFIJ04.mat e4bafaa48e6222afea80ea8200c189031b6645328b4e9d2b3ad013bb95b471d7
stem_e2va matfiles/CXYFIJ05.mat 2f12c70758df4b46d05724c68f08dfdb5a1300d08c4a77b7af416a3d32b4e0f5
stem_e2va matfiles/CXYFIJ06.mat 463919e66437cd1b9877489e95db228979394b8d57a09386e256e740e05050d4
stem_e2va matfiles/CXYFIJ07.mat b6950974453ea63659d5d279d2c60f412f374511b03580f4ae35f2a4d386bab1
stem_e2va matfiles/CXYFIJ08.mat c0b79c3fd4797a97932022b7dbce15404661ec868c1428d44be26c49c8f87f0c
stem_e2va matfiles/CXYFIJ09.mat e878002919d82045c9cd8c679c771bb068d544fbf6fc9b9d92b25231bb804786
stem_e2va matfiles/CXYFIJ10.mat e0620a3f8fa4d0be1b2220752828815f5562991d3e5021506badff774f7e03b3
stem_e2va matfiles/CXYFIJ11.mat 35be3fe7793af37f009d9115bca8ce9954f1bb1d9ba2dd10ab3110ed6eb9d112
stem_e2va matfiles/CXYFIJ12.mat 9dd29c880720b5db133e11cc11d23c3139492e3e8f083889d1b0abd16dfde0c3
stem_e2va matfiles/CXYFIJ13.mat fc29395c38cf89048addf3eb52d46f0b091c40b84bd50de241b660730cdc5be9
stem_e2va matfiles/CXYFIJ14.mat 1594739313dada762a5f1dea1d2653ac7274942d2ed39a8dcadc8c1e0a24d043
stem_e2va matfiles/CXYFIJ15.mat 2516e4152669d1428d6604b4feed3d0604faedb893731523977466f469b8fd9e
stem_e2va matfiles/CXYFIJ16.mat dd33e58a347e784231e004d337a41866d193941863831f689cd0c3f354823e1e
stem_e2va matfiles/CXYFIS01.mat 3b9cd901e00ba221b15b1ecdad7f062d818acfd9967f8efcb22af8f6fc073646
stem_e2va matfiles/CXYFIS02.mat 38a17ffc36b589656beecabea3ae4db0e36dd8e022804efb302f8b5f99a505db
stem_e2va matfiles/CXYFIS03.mat 14bedb487fd3c1172606de20d98715154275604b950acbc195b89ad8fe5d7b9c
stem_e2va matfiles/CXYFIS04.mat edaa1f025234d3558e3cc8f9a3f629768497695acdd98d01dee24fa8f973930f
stem_e2va matfiles/CXYFIS05.mat bae51440857a50652375141c3f096033696b1974350c9629ebc24113e908be84
stem_e2va matfiles/CXYFIS06.mat 17d0f5d592a5f7df89fa40f758453c73194b06542e9e03854a550effe5cace34
stem_e2va matfiles/CXYFIS07.mat 1a8087233dd400b0254ad1b2c8522f47e94ec2ab95b6606499d84e309965045c
stem_e2va matfiles/CXYFIS08.mat a76778e10edcd556a058dd5af2cb1c6f3494fe14ffcf19e571f4a14621deda2b
stem_e2va matfiles/CXYFIS09.mat e896dd9be1cf018919474260167abfc674705daadda1a2c690e74733cbfdd1a6
stem_e2va matfiles/CXYFIS10.mat 3f6cfbffaa43456292ed72e5b7edfd743f399aaf6e76452de78ddff5f32ff6e6
stem_e2va matfiles/CXYFIS11.mat ce64794fecb3530706af5147f78befd82ade6cd79ac25c60d0fc158ba991846d
stem_e2va matfiles/CXYFIS12.mat 328d634116a67d0c003c9978106f4425e53cbe9438f0ee184fd5cedee9c6cbb3
stem_e2va matfiles/CXYFIS13.mat cac858ef183c846f391e5f64519c0229c5b8d7796a272ed0cb4a69ae8bc45ae5
stem_e2va matfiles/CXYFIS14.mat 58457e5a49dc1694b54d8796a52734824dbd9f9e06a94af70b2947afbb196625
stem_e2va matfiles/CXYFIS15.mat 30f05ea4749d2b9e2f3cd14751641f8180cfe54814483a84a7b0ff146b69a313
stem_e2va matfiles/CXYFIS16.mat 8915ebb3159dabd0da6b5d5f870f0d0ffebb3afdfa11fcf6cfae158ed2524189
stem_e2va matfiles/CXYFMA01.mat 718848624ca94e8eda6f7968525e942f54da1246f651bac86f96665d00720667
stem_e2va matfiles/CXYFMA02.mat f4f1207e5eade7f9acf8235f9ce5dc69787bf2c8fb6de41c49fe37d0983c4abd
stem_e2va matfiles/CXYFMA03.mat d58804b90a3950f08e4b10bbd669dcce4f1a372cae02f681cd6ee3f55b144972
stem_e2va matfiles/CXYFMA04.mat aac87156e1f75295413b759852b3b028166b1cdd8d5c8d8a98dd0ad9acc457cd
stem_e2va matfiles/CXYFMA05.mat 088e36b4645628f37e7bc07e931481accdb05f6cc9a7d64924d866470f9d2b54
stem_e2va matfiles/CXYFMA06.mat 617a2c058542de43b165b668483bc62ed153fd2233395cdc36943371432edd98
stem_e2va matfiles/CXYFMA07.mat 0c25e8e1694c2785942080d8a461807aeb19e993839b0dac332d7b8940389565
stem_e2va matfiles/CXYFMA08.mat 3c194f14773d8205926618c3afb2068f3dafe0bd483480944e8da2f99805b564
stem_e2va matfiles/CXYFMA09.mat ad8921121091eebb2f2644a1dfeb2ba433b990292f1fdb23b2f6b604b4153423
stem_e2va matfiles/CXYFMA10.mat be874c511f145b718eca2a7513bca61b72845237405c29ddc981e60b0ac354b5
stem_e2va matfiles/CXYFMA11.mat e6e885757ead53b11a02c7bc6278b1c1eba731cf31fb1b2844067624d0d76953
stem_e2va matfiles/CXYFMA12.mat 1fa3c1107df1d61f6b66b4da5a5a46ea1810b95143eb1505cd796f270245e27a
stem_e2va matfiles/CXYFMA13.mat 6650a45449baa68064c413a12c3a6e6eec8a0cbced3e798fe14f327fc1c3f66d
stem_e2va matfiles/CXYFMA14.mat fca2c3a24648abdd89ebbe5f8d8b1895110e13ee399068a2d541b1cfa9f1f1dc
stem_e2va matfiles/CXYFMA15.mat acd9ff60e061dba5c0335bdc32dc895a42d2f6621e24992b418fb9f148e4d404
stem_e2va matfiles/CXYFMA16.mat e07cc217028eabc0ed6e9ce7168955afde6a126eb4add5f77307f9f714494404
stem_e2va matfiles/CXYFMJ01.mat 7b0aff08608821a8cb6da5fac436a69ec8419ac73394ce69e82f3f201a9a0700
stem_e2va matfiles/CXYFMJ02.mat 4cc59ce24116949ab7920b663b8f9912452c88c0cc466a2b5c2e93b4720f5d5c
stem_e2va matfiles/CXYFMJ03.mat 3f1dfb0a6562932853a7471c535e619d4874aaa81490b9d8176604047f2ed2ed
stem_e2va matfiles/CXYFMJ04.mat 0cfbd9ca8aaab11d952552074bfc674d0c84b947455700ef66860c4616c1e0df
stem_e2va matfiles/CXYFMJ05.mat 126ca81c1d1f6c01829325c4c31cdb728e5ea8c880ef4b7571b7d053c4575e7b
stem_e2va matfiles/CXYFMJ06.mat d2d7d6bea77604d090b4ae6b437dd7e7821966410f4acd9c1a36e897fa632cf9
stem_e2va matfiles/CXYFMJ07.mat b29df7ede7de3778442a6028e6d3f73d8ed007854f88ae287769ada24717f963
stem_e2va matfiles/CXYFMJ08.mat 5f41d1376beb9644f98121d4070edb26e97fea0ab0167cc722c5f5bc5e09fb8d
stem_e2va matfiles/CXYFMJ09.mat 51c1ca1bc8a2a46f82db0d5da051bb755927f02286ed10b42580be2edaae6d79
stem_e2va matfiles/CXYFMJ10.mat 1796df6669cce7501f00d22f80e093badb1c22cef66d274804ce3de6e82807fe
stem_e2va matfiles/CXYFMJ11.mat e999822a232486e3e658c5868cedb95eb8ac1e56625f80d2c82f3a867a209cd1
stem_e2va matfiles/CXYFMJ12.mat b1948702c3481265b83238cbf6e54077355ec1955066ad0b10e7205818e5e101
stem_e2va matfiles/CXYFMJ13.mat b359f2cc8855fa484b4a411f035da2e5976e28932ef64a5c270609eee71ee1c0
stem_e2va matfiles/CXYFMJ14.mat 56cad0306e321240bd117e2bf3eee1040b0da38c7407526ef1b87f0ec1c6ced9
stem_e2va matfiles/CXYFMJ15.mat cc68c2b271e263e0cdd05e50c2dab229b396395d1381099e306ac54021552d65
stem_e2va matfiles/CXYFMJ16.mat 693ba54fc24c7367042ce622a395647a073b2248c2de3b3c6ec8e598cc2d55ad
stem_e2va matfiles/CXYFMS01.mat 9661be278ef1ab69518b98488a82c206284eda903d14ff192f9d29649961bcdf
stem_e2va matfiles/CXYFMS02.mat 5e38c0109fcc0d6c4f93019fc6ce94cf1a1e916277e360a4cb29c5bf62a4a24f
stem_e2va matfiles/CXYFMS03.mat 6287abcaeb6f1a703e40d5e4e97dd5127638f1c19103dada9583fa64b55507ac
stem_e2va matfiles/CXYFMS04.mat d189c20c7f79f95986cbfb8dd03a462192a281b53c71cb406815cdb67f36a541
stem_e2va matfiles/CXYFMS05.mat 2e28f64095bdfb112a60d1eb9dd513490be15c7dc0693132cdb7e59bbda231c8
stem_e2va matfiles/CXYFMS06.mat 704be0cdba66f7826b520b4aa704eedb8abfb072dcd88b5cbca74807eabf11e0
stem_e2va matfiles/CXYFMS07.mat 8b8e462d027d9a766229ef9de46cda9b6b880c812d5b73b08711df67fbfddde1
stem_e2va matfiles/CXYFMS08.mat 59d8934a477d42be9a7bbf357c290667723199780281e6f5de073fadfc836f80
stem_e2va matfiles/CXYFMS09.mat d9ad69427e22e1c9aedf1e0130cefbcd13c34c1846eacd2c7db63a53d73b89c6
stem_e2va matfiles/CXYFMS10.mat 60be1af0f5f9fa406203fdbd88c20b7b09d6a6f556539be7c35efcec82fca24b
stem_e2va matfiles/CXYFMS11.mat 33df538f3e83091aa2c54af3afd54cdb9ee253cf5ebc5bc472f4006674cb12d9
stem_e2va matfiles/CXYFMS12.mat b50e9009e512187c62ff3ecf32c0ec448ad1ac4f9756cc0d3f63b04e1aaf620c
stem_e2va matfiles/CXYFMS13.mat b88917ffe61f7f5edbbe0b7cc425b8b6b97413cc2ea56374128b4cf17613ca51
stem_e2va matfiles/CXYFMS14.mat 04d5c112ba80ed569693dd2d961adfbea524bc483b0be611b6b1e826df9263b4
stem_e2va matfiles/CXYFMS15.mat 49ca85906afab9aa8ade73ce43d0acd1264ab0ae15f02d6387aabe5ac17e1c26
stem_e2va matfiles/CXYFMS16.mat f76a4a68e04653b7af677090f9ff61f8ccea2c33fa36ed8d3e198c04f1b9cd56
stem_e2va matfiles/CXYFNE01.mat 30a0743df1199f7d660913e04ab6f2a2347c7f5d6f6e32f2c310c1c2d982d1aa
stem_e2va matfiles/CXYFNE02.mat 40d4aa4adb12eb546c30b1d76c653de5d93a067f3179ff5ab6867c303e6162e0
stem_e2va matfiles/CXYFNE03.mat 13bbc0507fe4c606a114bd990c87e04878a13f26b954229246cbeb7537f1031a
stem_e2va matfiles/CXYFNE04.mat 531d551b6b873c6c57508b4d784f4c3deefb039b9f30a394d09981c0bf14a6f2
stem_e2va matfiles/CXYFNE05.mat 90f8d0c229ff25790f0e59908981c4a26494025ebfac022a83e3900cd030ecd4
stem_e2va matfiles/CXYFNE06.mat 205286eb9534f138230b26de4ce226abf893473aa193e8b9b3b2ad138278c27e
stem_e2va matfiles/CXYFNE07.mat 967c880ec227eb8888b84e0bab642868dac15dec2fbc533283114c5d1606eaee
stem_e2va matfiles/CXYFNE08.mat 55a634a6d52f1e08410294cbded43f8df9870cefdfe7e8f0a9618d072d0f7d94
stem_e2va matfiles/CXYFNE09.mat 7da3fc326ccd188c3cf8d7c2dbcb91bf806e34c148d8ab85a0abb9e2719a4229
stem_e2va matfiles/CXYFNE10.mat bc1f212df841f0c6c315edf37d0561a2d09d5b6e9204103ac6457ddeaedbeb59
stem_e2va matfiles/CXYFNE11.mat 1e46275c67251f7a25281c307a4c63489669b7f83904f9872c78c989b3b50b77
stem_e2va matfiles/CXYFNE12.mat ef8794205851a6ebd1fb8000edd3b559f0dfa0b1cf889f2db01fc1934f6d6f67
stem_e2va matfiles/CXYFNE13.mat ce9cd21ed49e9d3fa8b72c19365b7129557f6f969fc3a30d0e0e77ed0b38682d
stem_e2va matfiles/CXYFNE14.mat c060bb599e98cf19dd6dcb6aa28de6e66961eeed03d8bf21e514a81e55bfb97f
stem_e2va matfiles/CXYFNE15.mat d48c4d8cdacef9155ae28ab1ec5ebcb475b7a5094757319d24ce92c2d45da55d
stem_e2va matfiles/CXYFNE16.mat 47dbf3dba298763ff1cc85c9594e731b3c893da69a532ca484b11c27bda34fa5
stem_e2va matfiles/DPMIA01.mat ad57db149fd97b4974fc0460bfb6e9d84f0dfa1a4376964566b36c8fbb644814
stem_e2va matfiles/DPMIA02.mat 515f2dfdf4fa5442b5e172c3221d1af844ce40db1ebba03df43daafed2d7b27c
stem_e2va matfiles/DPMIA03.mat 3230a5fb8086646d7587ac9140bfb7766a7bed5a371c1acf64cb9634c737a6bd
stem_e2va matfiles/DPMIA04.mat b95947ed3e1a8a0f0e26fed23861f275e593d5e8d4694cd0e6d523a6bdcde654
stem_e2va matfiles/DPMIA05.mat 38d304bd9e5889fd29d2d3daee3ca4534b2f4823bbea7472876fffed219ede2a
stem_e2va matfiles/DPMIA06.mat e7e8d0c6b2bea5a29001b71758955d63c5e9edad113407f7fe7204f5a3c0fd1d
stem_e2va matfiles/DPMIA07.mat d21be6074e346abd19ffedf7f11a383756679346853c96cefbda3605bdd1a69e
stem_e2va matfiles/DPMIA08.mat 9c8c58ddef177fbdb6f1f710210d0728bf5f557a0dcd182a256fd9714d46cafc
stem_e2va matfiles/DPMIA09.mat 9d21b98162dc74c70d688e474a35d0fc61f6f052f566a17a852050a0aa2b9bc6
stem_e2va matfiles/DPMIA10.mat 7e58e87ab2f929981afe39caff2d2b1984244670d195e2d7b2bba9b6b8926510
stem_e2va matfiles/DPMIA11.mat b6e557f3199a0c91a4c7a8c880beff510fd9bd2420b11afbde1ee14204b676f2
stem_e2va matfiles/DPMIA12.mat a29446f6f24ea4292dd1d31a358eaf458fdc4bb81818f23968044dbd8f149683
stem_e2va matfiles/DPMIA13.mat f354a3f9837549b22c7addae5c556adda8958c9bab0356f6d2ca593f4ff48a2e
stem_e2va matfiles/DPMIA14.mat 14b847d25b1820d5357d9ea967dd4878221192beb37a712b33a767625c00637c
stem_e2va matfiles/DPMIA15.mat 29261a1ede6927bfed1ca540afb3fa38577af31a92af9836eab6ec340d920f8e
stem_e2va matfiles/DPMIA16.mat bcae05eaa4ccfea30054ac3f07ab152728c002eeed1f33eeaa7d5322b7b77205
stem_e2va matfiles/DPMIJ01.mat b7007221e7dd60d418451e57da5d206061de1dd034bf001eb5663ab27dc7a587
stem_e2va matfiles/DPMIJ02.mat bbb3aaceec5b8c70bf08110902675d20a2708253651e8052d520802dc259368b
stem_e2va matfiles/DPMIJ03.mat e8952397689ecc5be5f8955100be732231832393df48fc5e5a28c511be749c49
stem_e2va matfiles/DPMIJ04.mat b52c10abcf0f8a55d03ace86c482ee0ca4f1e8647852ab8b06fcda85e112faac
stem_e2va matfiles/DPMIJ05.mat 7d3795fdfb836884e81a0684b6e63eea3a0423a2bd003fabfc0981523f04601b
stem_e2va matfiles/DPMIJ06.mat 70fe70cc67ff068bb84d5e056f164c73b28dd2c3c4e295e9b683de896635383f
stem_e2va matfiles/DPMIJ07.mat c5925a456ef9c4661338686d90dfea1ef48af68932bc6677504ab959a784f083
stem_e2va matfiles/DPMIJ08.mat 1f9a3c311967412b1b1d20f81ba4e7848b744ad44de7e39f85c9ba101ce00bc6
stem_e2va matfiles/DPMIJ09.mat a608df883671de9c92f496c72a0eae31753900971fa5ddfa63569cb8be4bb3ba
stem_e2va matfiles/DPMIJ10.mat bbc68d84320934578feae1886bf2cd38507839e27ff6820f71735b11603d1be3
stem_e2va matfiles/DPMIJ11.mat e8adb3b513c91772f372e6ff8977ea133085003daba6d69c4ce45394cfe5b4d5
stem_e2va matfiles/DPMIJ12.mat 1fcfceb093627b8f05732785348dd5c552be5e5865b63cf51d8ceb83f7885ed3
stem_e2va matfiles/DPMIJ13.mat 0ab51f4d6b64736fab2dbc423b8bbffafa4b541ecc8ed797e61101eca793d87a
stem_e2va matfiles/DPMIJ14.mat 41505fa036fd4446f4e0824594dd4b44f8eb75e7772c982f220026c87d611824
stem_e2va matfiles/DPMIJ15.mat 92af7631397cccf27fb6e6d80e47e310382e2cf9201fdb9b8b0cbd40fabeda57
stem_e2va matfiles/DPMIJ16.mat c2e8075218d7b6fc29d0fba5fc28f7b54b90d072253adb4f0a1da406d1187fe9
stem_e2va matfiles/DPMIS01.mat 7c2e87074f03e7014cfdec2deda5f4cfd803ce406a776a40a303c94a70f473b0
stem_e2va matfiles/DPMIS02.mat 001529608f225d539c86a5d82dbed4275d22fb53bd4364b087708dd03ae62140
stem_e2va matfiles/DPMIS03.mat 5a676cfb4accbacdd5998442a6a2403016fa123dc8df423ea99b893ba807c72d
stem_e2va matfiles/DPMIS04.mat bb34db86984bbeaf18ae7f762055ece7daff5f882fd5349442f1b6e9e2fd0a27
stem_e2va matfiles/DPMIS05.mat 41a1d978206a3cf302d71e2959a54436c7f26df8645887acc7ac0025bcc4efe1
stem_e2va matfiles/DPMIS06.mat 2f0ab5d6e0a9c94cd02a4b20013de7a0c8f220b2b5f321650cf58a1b4b4848ee
stem_e2va matfiles/DPMIS07.mat 49c07996996a054c061bd5dbd1be8977cdd08677a5e363a36837b659df0edf41
stem_e2va matfiles/DPMIS08.mat 706b531a4549e57f552b9cfa275c1a21424da64f8e19c9ee4f177a813718220e
stem_e2va matfiles/DPMIS09.mat b281798174138e36925ba895103dd40d70ac902689a58354f998b4ad668fde88
stem_e2va matfiles/DPMIS10.mat c5760369f0295802ffa1a719511d08c8bc7f51d8dbef8fdf1ad3afd67f2025e7
stem_e2va matfiles/DPMIS11.mat f809499483b146ec1109fc9e886592fc923190bd3331ab1fa27e3e5c3f1dd3ce
stem_e2va matfiles/DPMIS12.mat 25d27d8170e70cb07c6fc5602feab1c8f2f3971a29c5c37e004e63577ac892a1
stem_e2va matfiles/DPMIS13.mat 079bd2fb4c267d2dc2df802d93b56e0b2ee5d69fd88713e21784b8b5fad47e9e
stem_e2va matfiles/DPMIS14.mat 88be15df43040ea7d9730a840b9074aa36a808ef4325abf2298d6b9947d2a743
stem_e2va matfiles/DPMIS15.mat 8319137809302b9ea6800c7fd69d75e4f31c9cc24d6da4f9b41094230ec00927
stem_e2va matfiles/DPMIS16.mat ad3fce9ef34331668bd53c31aab5716e574f51d6ae566bf2f8e5cd371baf1704
stem_e2va matfiles/DPMMA01.mat cbf6388282b981ddd11682059c00dea7bfb276e79547cf515c9bb1d5acdbb909
stem_e2va matfiles/DPMMA02.mat ac1d2f811bdb36a3600e5257053141f8736bef25b54d6790be820c5cac2d5126
stem_e2va matfiles/DPMMA03.mat e53561f33ebf6bc2873ff11a85df87720bba2a124a1c6d96b90028d39fea54df
stem_e2va matfiles/DPMMA04.mat 295ab89b3e1f979efff20993c5f57222614264990e0b4c59590acfa23b8cc221
stem_e2va matfiles/DPMMA05.mat 3ac2f2458c8f2fe3403b5422d654488cdcfdab0270596268852eec94483a678e
stem_e2va matfiles/DPMMA06.mat bbd908b9de6b2b115763bb369de12c97c7acc353f60036f2841686a3a36d0ba6
stem_e2va matfiles/DPMMA07.mat b4f942a72e660594acf987f387d9b79804b4a9a870d61263aae00fafcbc83f95
stem_e2va matfiles/DPMMA08.mat 9743f01b9c1eb3ccb2566200e35af287e75472538837bf39c3201ff11b044532
stem_e2va matfiles/DPMMA09.mat 4c82d86cca7cbbbe45a74a4c51f4250da0d8c2db1a91296ae90bed2ecfe2388d
stem_e2va matfiles/DPMMA10.mat 702bcc5d425a1d454c5e3dac26b356331fecc66083ae1ca27ab066eb4842c9a0
stem_e2va matfiles/DPMMA11.mat 0e07e9191021bc626e0c7a3e22be18041aef34322e8b3690decb962f2bc4b639
stem_e2va matfiles/DPMMA12.mat 174cb46a6ecf4f42261ac03a093339a431806b9b72919fd19222479349f33ee1
stem_e2va matfiles/DPMMA13.mat 8a251160a7ee2c2bf6fc9df7cd948d34e4c743f61bdd11b7b294d4a71d5dae43
stem_e2va matfiles/DPMMA14.mat d4f518002b0b28593270f15df514a96ea985906436e1ea2bb2f073c7a4c3d8c6
stem_e2va matfiles/DPMMA15.mat e9a6112080c39a5f2591bad2c8c2ae61b2aeb75148480889e81c16448c9ef6fe
stem_e2va matfiles/DPMMA16.mat 116adb66f4ff5d3673e97678e5a9b21bbba4b42df51418a44a7d0cb81e748ade
stem_e2va matfiles/DPMMJ01.mat 29d8f9e813f40f23045bc8894490b5993e2eb53e1d488206fed5adbc68e3b9f1
stem_e2va matfiles/DPMMJ02.mat 9126fec59395fe87af8bb564793a9ec79e6356358990e511e099d48a2231ba98
stem_e2va matfiles/DPMMJ03.mat 77d26e46fbbca093ef67c5c82c48ea15b270f160a0e2ec600e21a590295faf7b
stem_e2va matfiles/DPMMJ04.mat 785ad8aaa40f851cf8af1849b7c39c9caefe66d17e9a3bef57cc641b71bdfe18
stem_e2va matfiles/DPMMJ05.mat 077dbf5dbed0d3bfa1d99965c7c3a9ec8b8c9d1b9938e3a2af4407449fc2e3d2
stem_e2va matfiles/DPMMJ06.mat 9fe4df1f66b7028fe1797ee3206b0583f68ad10bd2346bdb14afef07e47ca389
stem_e2va matfiles/DPMMJ07.mat ad2dea3d9e18ec2f885c6560ee6ad9a028f129468bb8839cae35239d307e7094
stem_e2va matfiles/DPMMJ08.mat 986b938e52cd967e0fbd8e74858e0b91b10abb20de037babd5349806b83e6665
stem_e2va matfiles/DPMMJ09.mat c008253ba590e65e22f40bad3e4e4cca89c9f5d2d6d4ad5d3fc109e25b99f796
stem_e2va matfiles/DPMMJ10.mat cd80ee257782a0eba12a1ad86daa41e2d7d4d26dab05f0e9a277eec8efe25f53
stem_e2va matfiles/DPMMJ11.mat f9151c10e106c0f18a1a90a1a5125c1208ac86fca67f7c0f31de052c351c4494
stem_e2va matfiles/DPMMJ12.mat 8c906255aee971a25c3893687c8dabe133c7da40be30aa1487dcae1ed6d7a04a
stem_e2va matfiles/DPMMJ13.mat 0c8e8b7f546ba7dc9f6c446faf573e38b8a13f4f89bccbd08d35e223a6bfbc15
stem_e2va matfiles/DPMMJ14.mat 0868a73626c5040be136bf3ee5339e102050ad93f23fc62bfa8fad0447795f6c
stem_e2va matfiles/DPMMJ15.mat 86289a3ce3babebecb237fa656df3fea70842fe19e4f0e710e6ff58b3f507466
stem_e2va matfiles/DPMMJ16.mat 6ae559f901afe7472b339bc3d81359d0f8561db0d85cc494aa6fb9896760a5d8
stem_e2va matfiles/DPMMS01.mat e65572e7ca89de0b91e11cfc72008aedeb97899140a1c6b129946b733aae14cf
stem_e2va matfiles/DPMMS02.mat d34a350ee10e06189cb9f3a646bbac45a2dde13257c5a7294bb5e2a7ef90e8d3
stem_e2va matfiles/DPMMS03.mat a6e694e6b994767adb5258d40e623f8b1d99dfcfd354aee72d208e3799e886c7
stem_e2va matfiles/DPMMS04.mat 428d14cc2271525dfc8a5ebd4234d3b6fb584ad9c12fb03a82e6a069e07f929a
stem_e2va matfiles/DPMMS05.mat daa1f36f876742569f5988e3106b22c79388a522fc94c86a53941e169a85c0e1
stem_e2va matfiles/DPMMS06.mat 59cf20915bedf90f0b19946f8c9fac40a1aa81d5fcd4368332eba375236c477c
stem_e2va matfiles/DPMMS07.mat 0351cc2d925fdfbd06d1ce8ffe6edcc190e810ef6e9d2aed4857b2106dbe9a9f
stem_e2va matfiles/DPMMS08.mat 013df5d3c1aaf0459cccdf305f72fe5edc6a35afd861097523e4b04069736702
stem_e2va matfiles/DPMMS09.mat 3dcde2d2bb941b334e375c45cd51031a859278cdcb32186bf3eef9cf620aff4c
stem_e2va matfiles/DPMMS10.mat 29e24f5e371b26b4b9cebbb22fe1365e272ad281ed15330ade9a5c74f9288dc0
stem_e2va matfiles/DPMMS11.mat afe16718dd99b5bc8fe1497278ba42b928a36deead94d5df3ca700453de277dc
stem_e2va matfiles/DPMMS12.mat b6dac07bbea53b0466b761d4bc5b89ecee82fa3dddc3658eaf0048d971146f0e
stem_e2va matfiles/DPMMS13.mat 9a70b181605ac2d6c63ac871881cc6a06477fd42f75460bb63976aa31707bc60
stem_e2va matfiles/DPMMS14.mat b3a11c75c505537c42a8853385d8100d41a6d14d750994e87921962497291daa
stem_e2va matfiles/DPMMS15.mat c929fb73404b3d6a9bf287f6d3695470f8c06b19ba9f31df62ee5f0c45580c6c
stem_e2va matfiles/DPMMS16.mat 7e80715b767d34e628c2d9e0fc9a0409f8842a4fd10641520149e730444662ab
stem_e2va matfiles/DPMNE01.mat 5a637673f23fa3583869ad99103fe61d6982c9c702b21422c1e6191902d14882
stem_e2va matfiles/DPMNE02.mat 836578a6f2bfaa89de716bbd9cb1988bfd8aa07f79693d43d9a7af4cc4eb473f
stem_e2va matfiles/DPMNE03.mat c22a19dd969640548e0c1a9932fecb6f7b6bd747849b4685d22c4f571218e933
stem_e2va matfiles/DPMNE04.mat 54d0de1ffbb08a7065d3364fef1f24369de2bd893ade18669d4ec3e2917bfc9b
stem_e2va matfiles/DPMNE05.mat 97647cf2739d1cd1d4f95febd0fd634d41264c593ec3627726d40c5d2abc2f6f
stem_e2va matfiles/DPMNE06.mat 943c7618496aaf2bdf6a8e53f07673338f649839121d759a296dfc56afa4930c
stem_e2va matfiles/DPMNE07.mat 676d3ae6a645329c9a71a81f545c5f308441e604a5ad6e2cd09408cc4e7b5e67
stem_e2va matfiles/DPMNE08.mat fa59c168286c2b9bf460b2d673a4a8adcffb8cbe1326cfb288f729ade63bba55
stem_e2va matfiles/DPMNE09.mat da079c31f34bb887355c82531503bda44b27824df12a01161b90cfdb4d19b996
stem_e2va matfiles/DPMNE10.mat 1484e592da710037773748c948a35018024d51f64cea3013d85c014c45b70018
stem_e2va matfiles/DPMNE11.mat d703e783a3071c24e077db0c1faeab60dccd1ee9e707508f31ea8e2172db8fba
stem_e2va matfiles/DPMNE12.mat 434ff8fa813b955c353ecf34e196b644f25cf85859934ec993a467b6f737981c
stem_e2va matfiles/DPMNE13.mat 6d4d126395bf3b2d36581829e8d681b4fc3de5b7a0ee04b493a72beff7df0051
stem_e2va matfiles/DPMNE14.mat d983730ee80ac20911e892fdc5592d4d117207df108a4b0b6dbcab9d769a6b99
stem_e2va matfiles/DPMNE15.mat b885fdc5caca7c2c7623a2e0f0c4e4ecec3545b9cfc59a4eb70ba3a7e8c20c7e
stem_e2va matfiles/DPMNE16.mat c82a4324cf62f95200261fec8c0cc528f9a192d8a1d613f9c79000fdb85e0401
stem_e2va matfiles/JJWMIA01.mat a5d3c7c2795fa9c872eaf35bb8f7996468c0622283c0294992d3cad6dc828560
stem_e2va matfiles/JJWMIA02.mat abfc995b6f6e291c43f9bd82e6383cadeb5a410fef5a8a7d8bc46b7c05e619b5
stem_e2va matfiles/JJWMIA04.mat 81439414d2717e091de384f6199ff1b5c917a35d0cf65e90359c8df24cbda531
stem_e2va matfiles/JJWMIA05.mat ced4a6678c78912c0a8c082427cb0b704ecd91ab3347799cbe366fe14307215f
stem_e2va matfiles/JJWMIA06.mat 87c9838019d42ec1041632bee8c86ae5d4e143bc4c5cd281cdfe21473a7b077f
stem_e2va matfiles/JJWMIA07.mat e7ec98c3be95ae35733280a9b89fbe64135acab84453bc6c9d9897616879c90a
stem_e2va matfiles/JJWMIA08.mat 462b3d9e65c2edb50813a8cee597225d1bdf86e74a7545f0741cc5b9dcb84a8b
stem_e2va matfiles/JJWMIA10.mat 9aabc338cb615d838e050a75fc8d6d33d9a4a214ccf789d4b7f680572ff55dd2
stem_e2va matfiles/JJWMIA11.mat b3386529f0e23298a0ea0d285a267d9ad7444210954a0b41cbb4027f6569444b
stem_e2va matfiles/JJWMIA12.mat 3fb23ac42ed26cafab046d833726babd4b1bbe176fa0e300f8f351530e27a6d1
stem_e2va matfiles/JJWMIA13.mat 3ba2bf0f2f3902cb0f8c7cc6a04b20a672492bb038df3aa44921ab58bf9f41f7
stem_e2va matfiles/JJWMIA14.mat 2592d44725fb891285dbc24148395341b3590d61de00fac210d7940d89501e78
stem_e2va matfiles/JJWMIA15.mat 49de71a8dee653a57c3cebecae3864efac074d9ceff7dbac50318954cd3e5130
stem_e2va matfiles/JJWMIA16.mat 91c3a900124b3172ef7d09e6d401ea77daacd89393edb56aa3a101dc6201d434
stem_e2va matfiles/JJWMIJ01.mat 82cbd1b2b8f2fdf2314986af6f2ba100ef84bc5ce58edc16efe753654ec7cf40
stem_e2va matfiles/JJWMIJ02.mat aeef6a737b6503108dc0be724c5440230d4f6757564011b09fe6e43efa0b3783
stem_e2va matfiles/JJWMIJ03.mat 9ffbdf2ae434beecfd37a5809633d960ac9429fb9a23b2471a894fd22d1f596a
stem_e2va matfiles/JJWMIJ04.mat 60348d3b71512ad25a62cd82cf96d6e6698729322291c1f6e0c14960fe625313
stem_e2va matfiles/JJWMIJ05.mat dd711ea4591dcfd63f606821cba3a2d370993193cfdb4973272381610393817f
stem_e2va matfiles/JJWMIJ06.mat 553da79ab501cd76601adc7d130d098047a069cc52be9846ed6b74881deab756
stem_e2va matfiles/JJWMIJ07.mat c606e1480251e99b022aadc951ad55aad15153164d7abfb8a82e9dbdda136478
stem_e2va matfiles/JJWMIJ08.mat d76a3ffa3f30a577937ba98b119838180e3c6494f00a6d4ec5132dfbf7cf6415
stem_e2va matfiles/JJWMIJ09.mat 4bdbf98dcaa2f613895365c714a70a7e1e30241c33d9a173b4e3bff9c4e0b215
stem_e2va matfiles/JJWMIJ10.mat baff188f151597372bcc20dc799865df6e329edca9b54d3e52e02c07d942eca0
stem_e2va matfiles/JJWMIJ11.mat 42372fd87ec94351dca14c4def47ba71959adb8e72bfb59c440a912cee936232
stem_e2va matfiles/JJWMIJ12.mat afead658a170452c23482774b2d1c4df3a2481308ff5b205c973a9114f59b9c6
stem_e2va matfiles/JJWMIJ14.mat f2b460ed324123a9e2b812be9402d488014716f46de92dc0d4d289615c614c31
stem_e2va matfiles/JJWMIJ15.mat 7c30878c3b739008bbbc74e1937a3d58ed11f5858bc5575a41d54c4a3079b5a1
stem_e2va matfiles/JJWMIJ16.mat d4e27722914bf2fbff479873c9044f23ede912dd11e1239ac05fc49ee8f19574
stem_e2va matfiles/JJWMIS01.mat ff456c77b3196351e68d4f0b004895ef5043ad16c71716ab14204880ffdd1581
stem_e2va matfiles/JJWMIS04.mat b2b5033a91da1aee8241938fc1d4754d649b47866b6d1cbf0de509d09ee3f8dc
stem_e2va matfiles/JJWMIS05.mat 82c23242fbf7be21f4edd2ed0e876034f28548a5d9654459b551aaf161c0a669
stem_e2va matfiles/JJWMIS06.mat 65910575d6a5ef45257d04f6b8c0bc71489ad951f35939fc028059ee82d2b9f1
stem_e2va matfiles/JJWMIS07.mat ec6108653ba1676034514d4f3c95300ea32192dcb77b25f4f42bb9411f8155fd
stem_e2va matfiles/JJWMIS08.mat f3ec8544bfb29c7cf99530ee6011e5cfab3d33a2f3350bd9853efc10bf22210f
stem_e2va matfiles/JJWMIS09.mat 902936bb36c514d9e94a0a5443f5a6e501a39e1bc742fa5062f753fda599a161
stem_e2va matfiles/JJWMIS10.mat f8d9b9c716cdc3cbbccc586dfa90ad51806b29f2a417bf16622c4b9504a33025
stem_e2va matfiles/JJWMIS11.mat 68e92bc285251263980319d0cfb1534ac992062eb14527d044488d2b74572d1c
stem_e2va matfiles/JJWMIS12.mat fcc9f6e4bd3307550ca26c6645339766b81fa221d4b13c9650d00a81bb63a61f
stem_e2va matfiles/JJWMIS13.mat cc0894599ae1413acd331748cd7e7e7370562a37ac29ac6e97add70b4743f7c4
stem_e2va matfiles/JJWMIS14.mat 04aec0a6f4830bb894912c9f437728d5e9e9107761cbd7b81f2f35b42602b907
stem_e2va matfiles/JJWMIS15.mat f7d66c68f2cdbc3a91ba33b6d7ed053e97ebad7eecfa8d08fd8b2285c2460c30
stem_e2va matfiles/JJWMIS16.mat c2efb869cdccbe35034ae158c07bf15a30269bb048698994d6c92058ee0b9b47
stem_e2va matfiles/JJWMMA02.mat a53219f2a1cf091d6a60887e01086b0d0c84eb847259dec33e755461fb9f4214
stem_e2va matfiles/JJWMMA04.mat 8497339c3b13db3afbf14b03e9118d03746fb1c3346315495f839752a7f33e4a
stem_e2va matfiles/JJWMMA05.mat ae1715b61182efa51b3e146d8adb2c28cc5e6ebb5e4045d680b2280ff2d2fb17
stem_e2va matfiles/JJWMMA06.mat ee342ca29c82cb4fd1769e9e7a442429a2294112cf0c83e9a3986f61baa268aa
stem_e2va matfiles/JJWMMA07.mat f63b7e554a201cf8d68e4d89fab362d2babd951ba3c855bc76b66eeabd2c162a
stem_e2va matfiles/JJWMMA08.mat a4d70f5dd42f833f6e09436735f6cf5bac685ca4fb2ab883b7e999d4688ccdd7
stem_e2va matfiles/JJWMMA09.mat 65e9456b5d6d82450521ac657dc2aed853719aaece79ce0755c3d9a29c6a56d2
stem_e2va matfiles/JJWMMA10.mat 84a09cfb81d4fe7159b69068b384247f55c87d89946992eef4cec655bbcb06ed
stem_e2va matfiles/JJWMMA11.mat 3539281b152747afbeeec8525fb00c6089105f31d5bcd2b50d1160daa31649d2
stem_e2va matfiles/JJWMMA12.mat 3eac8033b247fae6b7cc9849cb9d0fef07ce23ab1169929fff86afd27685907c
stem_e2va matfiles/JJWMMA13.mat ed54bd4133a136f2d982d1a0b57b6604fd780f853dcd283f33e771daad4f1eb0
stem_e2va matfiles/JJWMMA14.mat 904aac68d9891ee2fe0e3312564ee47198e2f689e77885847fb0166af8a254ec
stem_e2va matfiles/JJWMMA15.mat f185af4d3bf5d4446797c74d037e36bfd1fa6d9ec0f9a22f8ff24da07aeba12a
stem_e2va matfiles/JJWMMA16.mat 88d04d3dcc8b6e2f5e63356db338f228f33b6b9c98b497c5fc9819ca09f69275
stem_e2va matfiles/JJWMMJ02.mat 2a8b49d911012a4ea562c60d828a1e729484d8e62f92b381fdba0d2e265a2018
stem_e2va matfiles/JJWMMJ03.mat 92d7bf21ea6cd53adcbb2c5d415d9ff142ed69b99ce403febe84e9a26469b29b
stem_e2va matfiles/JJWMMJ04.mat 11e68868adeb6550af97d51be417bf8e0f8f9291d771ef90507f9271c709442c
stem_e2va matfiles/JJWMMJ05.mat 983519dd44185ea4b9e53fe2da6aa4b7df3f62ec55e04ff5ad15dae2b74c56d2
stem_e2va matfiles/JJWMMJ06.mat 97079cbdfd011d5d7d3fa6440a4797ee9caf9e0c89622a321217d3792a4c941b
stem_e2va matfiles/JJWMMJ07.mat 927bca61b694a8053126fdb8cd262008fa81733be6b8e7747d710c58cb2b2c2b
stem_e2va matfiles/JJWMMJ08.mat c2bb8a4352c5475485ddef659011aa35122d67b912fa8e3aca854a75c602af1a
stem_e2va matfiles/JJWMMJ09.mat 2a5dc038886e1201a902bc23ad65fc12e0e446892239620832b98efe76969ce6
stem_e2va matfiles/JJWMMJ10.mat 3b26bc52645f0a5db7d5f60b8eab4c0cfa66ee3a62b8a148cdb06f7c7b0ae4b4
stem_e2va matfiles/JJWMMJ11.mat bc106f9b27a442bf69864a0066b2df85cf6f513980fda312e3e0ec0cd27c8357
stem_e2va matfiles/JJWMMJ13.mat 1b229ca1dd8d7afd21854e52e9a7d605e23cc75da11689cdea263619e3b8895d
stem_e2va matfiles/JJWMMJ14.mat 670aee69e866bf1f5fde4b8a3c50e1e97244c5c43125c3daaf92a0c4da18fd97
stem_e2va matfiles/JJWMMJ15.mat 18fa8a363f61c9f6e2bb995fd88603acb7f2be4d21a8e98e5be3219b19943da0
stem_e2va matfiles/JJWMMS01.mat 1dc3e29a39b23a0fa12a4e3b446c9a669ea5bdeb6c4b444c514d71d72746e591
stem_e2va matfiles/JJWMMS02.mat fa60b16c16fef8761594135a94534fca01f7738e52e808be389c7af859ee1d74
stem_e2va matfiles/JJWMMS03.mat ed94266faf47e5d9da41c12d1cab4bbea9302224a68ae8d2400589ef89ea91c7
stem_e2va matfiles/JJWMMS04.mat 75f22f022a5ac7d96fd99bb2e99eaaab5d4d1a516153bbc7c933f48384c34633
stem_e2va matfiles/JJWMMS05.mat 05c4b78cefb78cb16b060fd882440e0ea3eced19ba0968098c98f7c774327662
stem_e2va matfiles/JJWMMS06.mat cdbae57dab651991c1f1334fac0c7ef1940808709a67e8c8a9841b8925182ae6
stem_e2va matfiles/JJWMMS07.mat 33642d42a8ac4b669937e442020a7d44a8890406e5947d20479e487786599c82
stem_e2va matfiles/JJWMMS08.mat 3f39961f66ee82b0a6ee09ef371760d587771595656a529898f79de027da42c2
stem_e2va matfiles/JJWMMS09.mat 024e4f1a60714cf65e347b68ded5911dedd5c51be998844980a141e28402ca65
stem_e2va matfiles/JJWMMS10.mat 408ad4960bc1c1548c0f141a0718012387dd39ec12ec164f61908901fa4838a5
stem_e2va matfiles/JJWMMS11.mat 4f1d30ce23fd422d82b5be5d37c0061cdfa561356275efd332cb9875978ea06e
stem_e2va matfiles/JJWMMS12.mat 1352be0210d015d80f6bf5a9566c111736656d2008b265a23da619070bad736f
stem_e2va matfiles/JJWMMS13.mat 9ba7274380a1549888767cd030c63a18fae48b13f8329d3552eba45fb31ba028
stem_e2va matfiles/JJWMMS14.mat 0bbfef83dfbaead46741e5e3d6c36788f055298054d9a4156d50c242d1e36815
stem_e2va matfiles/JJWMMS15.mat f926ef65ef5ff3c0eb9c6c9387b9d3a71a1e8414f77a081e64eda199909bf18c
stem_e2va matfiles/JJWMMS16.mat cc577ebd9411a485fad374414c691391e3a801e01483ad548005fd6d55cdc218
stem_e2va matfiles/JJWMNE01.mat 49922cd0400e9764a6965cd74ddc1194b5cfd01f93a1594f6c3c3e3be13a95e6
stem_e2va matfiles/JJWMNE02.mat 0f2d30d5cbdfc17cc22dffbf00236806b5782f2b70f31074acd1ef9e1ed3bc97
stem_e2va matfiles/JJWMNE03.mat 51adbaa62fc090d21e25251c2f764334231c793a66e27fe84b6c99b9e2153fa5
stem_e2va matfiles/JJWMNE04.mat f601685b4093dde895bb67e2e3761a228523b178b1cd6e04c252dd7ef81fb21f
stem_e2va matfiles/JJWMNE05.mat bf75e66f16fd960c5a880e1c2d471459ccc5e2e87ddba46458577c9836c08443
stem_e2va matfiles/JJWMNE06.mat 2e8118206f67d24dedae3ae797356db2b4a24db8eb73f5a65a3bd198645e90e9
stem_e2va matfiles/JJWMNE07.mat c36e206fb3de99665b1cec87ce8a7f067b6fc9d79de25a131a4a644a2889bd4b
stem_e2va matfiles/JJWMNE08.mat 3b74fcb02f578392eadf7ee52341d2f9c9696e754781f96d906ad8eb67957701
stem_e2va matfiles/JJWMNE09.mat 1032b5f6ef8b746534b937b72add2458947cdfc409583ab6b0f6f2c5de3364f2
stem_e2va matfiles/JJWMNE10.mat 18d4a794fa4e98cc58b376a14cd1af0c6096b6919376e0326fa25dad22256b57
stem_e2va matfiles/JJWMNE11.mat ccc5c40956f8ed08b8c40c447108c0c91fca7851c52700796d3cd79316673a1b
stem_e2va matfiles/JJWMNE12.mat a6421ffbcfc45f8bd2f0dbf5133fc3c85b0e53f5570977c96f999df80d91afb5
stem_e2va matfiles/JJWMNE13.mat 3437de6bac3fe005642d20a0110b6ebfaa562dd966be350047b6e25b32e1e37b
stem_e2va matfiles/JJWMNE14.mat ac0952985c55d65e312310d9fcd0e43b42dfe75bd23a12b66725b712648188ef
stem_e2va matfiles/JJWMNE15.mat c389f332a7c89de6e78e11e7d7f271ab8ba36acbcde0fe92205622a91617e8d1
stem_e2va matfiles/JJWMNE16.mat 3fbaa3c3951f3ae0fa055896018dabca32b0ef076a2fd7a4fdb2b877a7330427
stem_e2va wavfiles/CXYFIA01.wav b3d383cbc311f8b32c1497d35ba62a0a796135f073c682b60659d466657b01a0
stem_e2va wavfiles/CXYFIA02.wav 13315c8a4cc152efb9702ba69ee88a4fba236ac06aaa34f57e45375fca93706c
stem_e2va wavfiles/CXYFIA03.wav 338801e155bfc8c8b9afb2351a35b3b55d8e3ce4a7043ec8a6d29cef10a4ef67
stem_e2va wavfiles/CXYFIA04.wav f756c92b218b57ecba9aec56b7337fbecb81c5d653e42d15b9963b2977bcecbf
stem_e2va wavfiles/CXYFIA06.wav 83d842afdbfa4c738a8c18ac5c37585f8c69e52eeda271f5def8fc08f54d5a69
stem_e2va wavfiles/CXYFIA07.wav 687d8c367b97450e8e94a45a4b7b64be49f39e8eb76ab2fa97d73148f04c4ad2
stem_e2va wavfiles/CXYFIA08.wav 77268227cf434bdd12adbeefbd0aee0f1eb08345af96ca7e3b55db505b1ffc00
stem_e2va wavfiles/CXYFIA09.wav d339b184a8faf7cfdc09ea5be54552bed5a0e7d71f062e024aaca330148385de
stem_e2va wavfiles/CXYFIA10.wav 03e86c886175c86f3fc00b8bf9b73415c22b9ff242d828e4d2d4a32c58fbecae
stem_e2va wavfiles/CXYFIA11.wav f10583286bbd46ce590d1114cf9ed2d3dead30c2670a7503039170f3f68cd57e
stem_e2va wavfiles/CXYFIA12.wav 872142f8df875ad8ca1426ef254714562876ed5bf9c88d70875f1db13dd04a30
stem_e2va wavfiles/CXYFIA13.wav 600bc94256d9dadc16b2551380ab1f9e78f05ef89edad1d94a82bf8b5067624c
stem_e2va wavfiles/CXYFIA14.wav 7c45a2c16f65b4ba89b4c89a23dbd00a39dfc11104e3ab3c92c10c342e13177d
stem_e2va wavfiles/CXYFIA15.wav 28d55ab6a2135067268be33ae2f5b9cf8698a396b36f61518d46c04ebf3058ac
stem_e2va wavfiles/CXYFIA16.wav 7b9f9023b19826f3b3677c3814f8c8611b2a2fbd848af49e804dc962564ee25d
stem_e2va wavfiles/CXYFIJ01.wav 2246614776da7b328ea1db3c497ff99270f3ee1df0865b2f80185a2e04b09357
stem_e2va wavfiles/CXYFIJ02.wav 6b17ae1b3f9885d14cf6080c4749583e6ff4908a7475ca10492e294a78995306
stem_e2va wavfiles/CXYFIJ03.wav d3dd8c8f7a067f32a19ac5f93efbbcb6f925000b562062eb338e762a6f9defc1
stem_e2va wavfiles/CXYFIJ04.wav 75a599c291161ba64b0352ad2240dbeb48b63636ee79dc83460e1f040801a29a
stem_e2va wavfiles/CXYFIJ05.wav ab9c2eb1c848e752de1d815f72549a19fa010b3474dcbe39bd9fb97d296fbac8
stem_e2va wavfiles/CXYFIJ06.wav f71af0415faf3fee2d5bf9cf2504177861e4770e408d325463905f23a6b971f1
stem_e2va wavfiles/CXYFIJ07.wav 739afa646082b8474bae0be2a1b602e8b7cb9d5c1a3b683c10f1e8a91249ab95
stem_e2va wavfiles/CXYFIJ08.wav d4066644a8f6a2f6857ff5b831a2624253d501135189efd6724243d647c6de39
stem_e2va wavfiles/CXYFIJ09.wav e876c1090fe5db3f13938d5260b71eebb4b3b9217df24c9bf830531d7b0b3e5c
stem_e2va wavfiles/CXYFIJ10.wav dd819df759eeeeae6887ff88625a1fa01468f94216486e5ab0c91e6b4b87cf6c
stem_e2va wavfiles/CXYFIJ11.wav 90a0d422f4481a3db4e67716d15f7b00b860da35f848261fe5c9af0b39ece314
stem_e2va wavfiles/CXYFIJ12.wav 0e7085fcb7ff6e5199e25df7244ca2b900a1a0e719e2e6eb79ec5775ca62eaaa
stem_e2va wavfiles/CXYFIJ13.wav f8dece60a1374eedce211a8a724d99d0f5182274f386324e880bddebfe0bfd59
stem_e2va wavfiles/CXYFIJ14.wav 81d22d2d188ce09a0aad2ab8f046f572146a327d3c9926f67e3542dd40d7075a
stem_e2va wavfiles/CXYFIJ15.wav e4f6c54138f508be78537514054d71c1d87ac7cb642699a8d390678a0d762669
stem_e2va wavfiles/CXYFIJ16.wav 6755ce10632724af48018eee40f6a4028eb8a1938d74e6f5645510cbc4506dc0
stem_e2va wavfiles/CXYFIS01.wav 37d68440b7ff9636fe4223eacd946dc119473469cd4732b80fe1f6bdb03501d3
stem_e2va wavfiles/CXYFIS02.wav 7e279620a8cc9e01c6c2a23d3047a7b6ab08c9568598edbd7f1d07a8443d5a6d
stem_e2va wavfiles/CXYFIS03.wav 29a0b512ce1f17ac01cd5986732636bc700761ceed2c8426d9e3fffa9241c190
stem_e2va wavfiles/CXYFIS04.wav 84714ea29e0690e15196050662df23c04eb5ee7732ec73d64b651e4988ab01df
stem_e2va wavfiles/CXYFIS05.wav 78948a642493c5cf6605529212169db18ca49c66cd9974241b2efcc312f1bb81
stem_e2va wavfiles/CXYFIS06.wav 0b6185fddefa8d65e5a96ddbfb56c2a3e22a7451769909e2999e23fe28cab251
stem_e2va wavfiles/CXYFIS07.wav 68dc123b0b1933abb8705e875eca940dcaade15afb811327a860a5a61d2b8047
stem_e2va wavfiles/CXYFIS08.wav e9983bfa060f8302da4e15ead410ca3e55c73011a891aa4428a09523a76d6b91
stem_e2va wavfiles/CXYFIS09.wav 5ce67500c278f0894cfbfab163495bf6294a57a319af751d420b156c53c3f6ef
stem_e2va wavfiles/CXYFIS10.wav 35f7b87b6011b66b1d6617aaba65c07013f0d7093010dae3537c1edb4db38f51
stem_e2va wavfiles/CXYFIS11.wav 753222ac1781e1b83ba06cd5f7bf9fa5c872e2601925e2479a68521c2b99053c
stem_e2va wavfiles/CXYFIS12.wav 0825f55b75693787c3f838e9bff59e3cb59b6f6d6085db32dd18344b74821c8a
stem_e2va wavfiles/CXYFIS13.wav abe3314eb109417360773a193539483a323969d5437b6fef815e1bf6665d5181
stem_e2va wavfiles/CXYFIS14.wav 6dfc8004c23c6de2e1b66ca62b8fbd5a37585441032e66e4242029a199b9bfc1
stem_e2va wavfiles/CXYFIS15.wav dd438bf4f92c59f8ac4c1ef1824037e590c3bd1355010ede9af81962e31e864d
stem_e2va wavfiles/CXYFIS16.wav ef1c4da32d75a695a6cd79ae4feb41d3054fe9302a3c1e901dd50a4cbfb823aa
stem_e2va wavfiles/CXYFMA01.wav d94a9a833b38ac7f9c21de847e896deb561c7a752a2b8dee8201a8b8a33d3fd5
stem_e2va wavfiles/CXYFMA02.wav 49477621095876ae5288310c1c6b36a400b75c6ede010d84bcab1cab4f52a3d2
stem_e2va wavfiles/CXYFMA03.wav 9467293e7d919a77634c893397a03aa3fb74e8f70439dc82aba4523723cc3f64
stem_e2va wavfiles/CXYFMA04.wav bbfc20a4f0ceca92cdd91699bd780b75f3afb6e0c0875d481b1babd4389234bd
stem_e2va wavfiles/CXYFMA05.wav 6cc174a47e833c8ba17051f390f49ca549736f457393c3b87db2a4ca8b8bf5cd
stem_e2va wavfiles/CXYFMA06.wav 17fd9c3b378ea197a6791bffe62b8a9466df09504f496c9b89399df7bb8be953
stem_e2va wavfiles/CXYFMA07.wav 86c6a169d154e1b4ef297b5b052e37fa3a05b0008f848e58ef2806d0b4127d68
stem_e2va wavfiles/CXYFMA08.wav 8bae38eee73d80856342a6656c3043257d1bd9a2caedf11814693287ce450eca
stem_e2va wavfiles/CXYFMA09.wav b1c9feb859ff01055494eec6da0c43f56b27193a53686cee8d82b8ad25621600
stem_e2va wavfiles/CXYFMA10.wav e5fcb1ae5e05fc11e2f061030e9cde5f27fded99ff2ac5646cfd22a8606b4048
stem_e2va wavfiles/CXYFMA11.wav c253d09caef2140efd2ea578cd26c3c79b992b292b29da141553240e0de74fc3
stem_e2va wavfiles/CXYFMA12.wav a8cc83e1f1db8bb1920296871e4cb7117d2b4e93e74e5076cebe4597741b5f79
stem_e2va wavfiles/CXYFMA13.wav 2b4bb4de4e2f5eaffedd9e2532a9cb1459fefc866062c3d215c24ad5bf6847ef
stem_e2va wavfiles/CXYFMA14.wav c47905ec950ee74543b16db5b71d7ab29c80139ef9d1754e9e33c03078663035
stem_e2va wavfiles/CXYFMA15.wav fc310242af6c9e2675dfa74a8d54564c00de48767d5f0f2bfb76e236d4582a6d
stem_e2va wavfiles/CXYFMA16.wav 01e5f29a1f6fcac5d7d349830bd7f50e6f67b50a6ea9a70125f41dea6c2aa92e
stem_e2va wavfiles/CXYFMJ01.wav 6c70712547a29590a4281df75fc1d5808a8612932611c2a71632813bd5427333
stem_e2va wavfiles/CXYFMJ02.wav 3006d203e70c3c81dec63d9e3a71f1a2f7ad240ad2fcc351c2cc8ca7a26cfb88
stem_e2va wavfiles/CXYFMJ03.wav f6c090c5d0d61bef42c8c985a425c2e9256eafb1c32bd583e3574f231c64149e
stem_e2va wavfiles/CXYFMJ04.wav c1e7df90d67de157fdee31287e00d6cddf5d8f91fde790bdffebdd90ff8a45ee
stem_e2va wavfiles/CXYFMJ05.wav 8749b30d804b19600dd0540e389f27f0a51e6b59248851289f994dc62f0ef514
stem_e2va wavfiles/CXYFMJ06.wav 919a7a179685ed04c136d9ee445bd82a8d1d4e8368a5eb63e5b8d869efb7e008
stem_e2va wavfiles/CXYFMJ07.wav a312d64bf7ab93de84072b7c1d852ce399659994f17475954c66d4410b42641f
stem_e2va wavfiles/CXYFMJ08.wav 1b0ab276d14d4766ae9ed63b7a8d3ffb27e9e4102419b58946340a94874fed9d
stem_e2va wavfiles/CXYFMJ09.wav 7a75910d286d672e7ca9b1dc887f96e1c52d59fd42e195a109005b5827b70cc7
stem_e2va wavfiles/CXYFMJ10.wav a7ce897cbe169f89bc75d794ab9c6343eeb55c0d4838e6ba5c3deefa33a1ea8c
stem_e2va wavfiles/CXYFMJ11.wav 0a653878c71f36b888a6d7aefe9f41ecd2ff13ff3be00999ba8d8ac2ced7232b
stem_e2va wavfiles/CXYFMJ12.wav d3e8d2fdb2ef75e3f0b94e70192aeff414aed8ce88ab275ef363b57dc021c022
stem_e2va wavfiles/CXYFMJ13.wav e48de015857a3a2272e3a7cbf16f8f287068f58588235427465fb96da70ba205
stem_e2va wavfiles/CXYFMJ14.wav 5f3df2355195e331f1790cb1b6d76edd572fd64e621d7d22f4f3d1dc213da18a
stem_e2va wavfiles/CXYFMJ15.wav 94d2c1a08b602d10faf832e0b1837bb7152a527f805ea858999d09d6db300644
stem_e2va wavfiles/CXYFMJ16.wav 542b426735f4a5751e871cfd4b73d11f37b7c08b07a6770c486a6d40c40150a6
stem_e2va wavfiles/CXYFMS01.wav a4de9dd2454b291bf7e2e83d1178125d7fa47c586e5e221fee1b686ca4d2d1e0
stem_e2va wavfiles/CXYFMS02.wav 692ebfa8078fedac698f08045758678be611888d4a0d67e2fbd2e4f8c0b9167e
stem_e2va wavfiles/CXYFMS03.wav 6626db2b21a72923e7aec19d6e6b44e5413fb8f2d4cb4a51b5633a7bfc284dc9
stem_e2va wavfiles/CXYFMS04.wav 3f9b423eb5cab57feb0ce51c982a59e5df97ec1f54c6ba08f43288c990813f36
stem_e2va wavfiles/CXYFMS05.wav e5887a49b8a19fe7a76b405ffa9d91e77cb1bfc187d503e7c876f895f21e97be
stem_e2va wavfiles/CXYFMS06.wav 0def0be48b7a95df91235d48f7aabf7c37d020d2091a83013e0b2f605829fc96
stem_e2va wavfiles/CXYFMS07.wav ce44d33926430e509f85efb35cf651836193324a0eb9c89781638c74ae67820c
stem_e2va wavfiles/CXYFMS08.wav 5e05660f857be5eef82738e4241bd46c0595103ce757a7a9996228bbbf626174
stem_e2va wavfiles/CXYFMS09.wav 10014ffa0d0cc7d3a3f8b83018401dd912dbd213769f39f56efd208030a74455
stem_e2va wavfiles/CXYFMS10.wav 5e720be9021f9fadc27e78d9429f91b58ef891cd3ea2bc7e8970fa39be58bbb7
stem_e2va wavfiles/CXYFMS11.wav 0b0793d2dc3cfbb7494d4c203e030bd1ddddb4cab1a56ada4f6bf7669788d081
stem_e2va wavfiles/CXYFMS12.wav 1a92a576e2c6f8a90d96ac91606a4e5351b3e08ba547a84bf05ace1a358bbe9f
stem_e2va wavfiles/CXYFMS13.wav 2ea3b3bf7f3050ebd2ac2a0788843a61387e4a1a164ce9d80133ae720bbd6469
stem_e2va wavfiles/CXYFMS14.wav 63556dfdde41dc9ac71edaa28a36c3724c044bdf6c9a858a060b72a214f5b0e0
stem_e2va wavfiles/CXYFMS15.wav ce4ffe3f1909ca4dd6b26b702277cb72c35d1f4c2e2c553e530db7df6517a21e
stem_e2va wavfiles/CXYFMS16.wav b31ff31eb7ab1a67cc1aebf909b9700df4b4d218b9d58373b14cf4c553cbec49
stem_e2va wavfiles/CXYFNE01.wav 9f96ae55b8764939574afdc0ef24b2dcfc330ff60aec36b360357efcfdaefa11
stem_e2va wavfiles/CXYFNE02.wav 4c6953f8ee2646219659783bdab1979e824a51a9fe66ae203645c524ee3c26eb
stem_e2va wavfiles/CXYFNE03.wav 223f21d0ff911c1de8d04e7231b922a75f6c6c6c8e271975aa8c38973e6c541a
stem_e2va wavfiles/CXYFNE04.wav a0e9d11d57967298832b09e5d7ba342054bd6a43ebbe7562c32bd5480eb2697c
stem_e2va wavfiles/CXYFNE05.wav 4438fc289ad3303b68dee9f49a91184910de0a25380cde1233fe71b2e6dcbcbc
stem_e2va wavfiles/CXYFNE06.wav acc18693fea94e12ebb2cb9c5a3e46d93144b5d70e14ea009cea6f6aad83b6f0
stem_e2va wavfiles/CXYFNE07.wav 66a49db67d8895f1d9965a0811d7eebd8b966418bf26ebb820ed9c8136229c68
stem_e2va wavfiles/CXYFNE08.wav 50de49e1da19d03d8297b945fe96502bae73ab596be5e63e5e80ae84c01becf9
stem_e2va wavfiles/CXYFNE09.wav 75f7d27877f71b6d40add3aefed58e5f946bd812f34168cdcc23f7d8c4924877
stem_e2va wavfiles/CXYFNE10.wav 32b75e95593b5ef5639181bacc79f981a0695ab1d57db065ce51396caabfa4b4
stem_e2va wavfiles/CXYFNE11.wav b47c939ed585bcfd90c2c7a4caef235bada3bb747f8727f7534b385062b6b8af
stem_e2va wavfiles/CXYFNE12.wav 827db4f4c34a1f2ad1c1c57bb27456835c5b91b607d81d5a91559172ed01d8eb
stem_e2va wavfiles/CXYFNE13.wav c3b6eb2d116594a9155354216d52c369132cd22aee2f1c149e8c73251660c4d9
stem_e2va wavfiles/CXYFNE14.wav a0d3e1dd14c84e56bb7d831b265d1ada701d51c0cdf7eade91cd8639d5890e9a
stem_e2va wavfiles/CXYFNE15.wav 436697775f7430dc9ca9991e58b17e63517f3217669ec0eb613dffbff099b7d9
stem_e2va wavfiles/CXYFNE16.wav 91fd02522e8230af56446dea05626db550de7725509cfff486cec029b0683630
stem_e2va wavfiles/DPMIA01.wav 9c7d1302e6bb94001d0d6eeffcdc66129cf053756a9d832b51bd373769a55743
stem_e2va wavfiles/DPMIA02.wav b78c543e951a64d52e404280dec169278376cf145279be36f5be298ddd35deeb
stem_e2va wavfiles/DPMIA03.wav 4a39b7d05c39c4be86e86d9211f7df8718890955770a8f0e1ed85cd0c55da0da
stem_e2va wavfiles/DPMIA04.wav c8482f4c951ad99bffa15041ce6b0c5de2fadb4925585fcbe885c84a839997b9
stem_e2va wavfiles/DPMIA05.wav e1da579aa9121cb8ddf6b97edb6a23e5ffcbd3b976ca02d3448a6ce3af51a860
stem_e2va wavfiles/DPMIA06.wav adf9905e2c7ce3714ce0a0381f81453d7246737a71289d710bdd61ec37228638
stem_e2va wavfiles/DPMIA07.wav 81ff96b520c8a129159b52b7d34c4b89558c3faac5bf09e7c7deafc18ba8075f
stem_e2va wavfiles/DPMIA08.wav e6cf419d77fa33801de28413453dbb2f96fba93080fb6833458d45917e200962
stem_e2va wavfiles/DPMIA09.wav 3941bb04717b70dbe89316e6e1f1ae9e8a0e8fcd5841fe2f45bc812784c5d06b
stem_e2va wavfiles/DPMIA10.wav 9413f8728726781b862a93f4335f37bdd47b8204ce08f1b2345c46e839ae6a2a
stem_e2va wavfiles/DPMIA11.wav 503261bdbf36368e6ef36abb88f4f806242bff8da508ff695b64df9ea3ca708b
stem_e2va wavfiles/DPMIA12.wav 8c790d5b86252817149757683c5b7c7289bb0e48279dc497f16500228c7ee5de
stem_e2va wavfiles/DPMIA13.wav 210c5a69afdafd3e34edbc2bc95e936a370e60a783ff3dad43b36a19f6410fc4
stem_e2va wavfiles/DPMIA14.wav 0103f52eb40221f51b302ec70783479a6943e3f99c5688309eb547f483460562
stem_e2va wavfiles/DPMIA15.wav 1ca47b7aa7ff6a1d4da581edc90fdc02ed99c809b01077e5014989644de4e63e
stem_e2va wavfiles/DPMIA16.wav a931b07f2d15a796285accc99408d82a3fe7e28bbc8f734293b3461bba789e15
stem_e2va wavfiles/DPMIJ01.wav 1eeedfd659c32e9b7d9017410bc01eecb6332d4a8a4dafd4a78648717f0f99d6
stem_e2va wavfiles/DPMIJ02.wav 7229e0d4af5118e1babe2f8ee523982ec81a8b05f98d70b9c7e7e0eb5815cf97
stem_e2va wavfiles/DPMIJ03.wav f7639fc906b125f8cce43e601be5c7f8937274993fe957e82d6c9dadf5b6d9dc
stem_e2va wavfiles/DPMIJ04.wav 16658da4164d5d56358632ecf20da5ac8c453660c6b1663fbb8ad95c58c93905
stem_e2va wavfiles/DPMIJ05.wav e8e3ead34a10423b84779d79a40dc581b93aa80d39659806d0a2bdb8aaa2622e
stem_e2va wavfiles/DPMIJ06.wav 39d450730db00db1c845133951307f4c9b3d8fcc187440a368257c2b99106af4
stem_e2va wavfiles/DPMIJ07.wav c9c9ceb0b9399ed8d8fcbb052a1e5ac7478753336c64eabf964c909da73b0f45
stem_e2va wavfiles/DPMIJ08.wav 8f9e016919f5489f51dd5a82ed0852a8d604fe0e9c07978a6f30c55240259480
stem_e2va wavfiles/DPMIJ09.wav f8492ae8fbf313cfdb270adfc353fa02d32dab683fc5d9e63895e0a7c68d6d4c
stem_e2va wavfiles/DPMIJ10.wav 9b00ab65ad23cc6d554a461448bd742c2f2500108518f964f6ec716c0cf7883b
stem_e2va wavfiles/DPMIJ11.wav 2f767a4d09caf19a6a3237b76bfe0ad331392413aac29a70da786512ade0f59c
stem_e2va wavfiles/DPMIJ12.wav 79ca2c262e1643c7af6752a309e306091de13be30dfbac97d692b7e5b861e760
stem_e2va wavfiles/DPMIJ13.wav 04a6b3c881b92dbb0fea9732a9ca7fab4d86705a4269c67082dcb97c31975419
stem_e2va wavfiles/DPMIJ14.wav cdf3c8ab7703135c8b872949d95ecae4e16b17a6a2f67aa7e08a0befde521c51
stem_e2va wavfiles/DPMIJ15.wav 2dc8545885817e5022bd9eb6e4def77e697e3266417c0f38780b5f354890f3e2
stem_e2va wavfiles/DPMIJ16.wav 6230b9f7a78d45cd2616c76a6ede5c3a97e548e769526595fbf624478640769f
stem_e2va wavfiles/DPMIS01.wav 6d7bc7ea97cda5f1f644b9fd5ad976b4ef295648b50d31935bee9efdedecbbbb
stem_e2va wavfiles/DPMIS02.wav 55817bddd7282761e79f413ac1a486201a2cd3441ef5f7230373a7ffb61b8386
stem_e2va wavfiles/DPMIS03.wav 33dc882bebac7a70db5e7fdb21f3c02bf98e36d4d44ec43616cf5fb7e643493f
stem_e2va wavfiles/DPMIS04.wav c78db832d402e4e5adeedc87083fd7605d93f0c9e6c987771f444519b5230686
stem_e2va wavfiles/DPMIS05.wav 41b0170e8dbcc44930d4fd8736de0bf14b013643f6b16141f03c40125b1d5264
stem_e2va wavfiles/DPMIS06.wav 28842bddffcbdf683e29f2075491f08c10cfd6514c09d41af67299791f2f1cbd
stem_e2va wavfiles/DPMIS07.wav a34b64db7259ad3231df719f1cf0f86236ad8d1567325ccdc37578404c3e710e
stem_e2va wavfiles/DPMIS08.wav f0d208a3cb19260a73aa2f8be8fa8de8a13ff9953cb203f698e3982528f5dfca
stem_e2va wavfiles/DPMIS09.wav 5e0aabe7b1bc8f0c320df2b775cfa2d72d9554e735f56b8f6f21e4398cf96e0c
stem_e2va wavfiles/DPMIS10.wav a11e1e4826b34123823d1683ba5d0fb9119519742703b7174b28553482f947e7
stem_e2va wavfiles/DPMIS11.wav 04f5f228fb1d2a3e8f88c7795b21e154fb7446e283a557d4d27ae06f0c075a69
stem_e2va wavfiles/DPMIS12.wav 8b151b301d9989b9454a75f1eb3e05d0aa63f864265cb56e71b98fab8b23e479
stem_e2va wavfiles/DPMIS13.wav a1a2d2c31cc04f657aa4e89302067de8c99c5ae1b9b9eaa2740f2f03d43c4dc2
stem_e2va wavfiles/DPMIS14.wav e4d55e165baf52e08960881f32fac1c2b5f30e82af2cf95dfdfd3e3c7ff56552
stem_e2va wavfiles/DPMIS15.wav b6124eaa168ace890ff3443f5e7cd4872cad5faec3a4866b8b790e59e36caa22
stem_e2va wavfiles/DPMIS16.wav 9aa780abe668afa2be44b66b3633a034c741e472f5f7498a7ae41143105443bb
stem_e2va wavfiles/DPMMA01.wav 93cf1028ac26b2475869cc6a2d8e1539c2c708a083284acaa1ff37026a7624e4
stem_e2va wavfiles/DPMMA02.wav af862871e6b6e78c19a1ec8c62bf04a11fd7719a955e2448dc54fc8e832c3377
stem_e2va wavfiles/DPMMA03.wav 03868ccd5415f1f2a6f185f0a13b9e513d15b4d26b0cd9081333c8c53322a7d8
stem_e2va wavfiles/DPMMA04.wav 999be0d226faf21ed30ed27a8f3b48e84169ab3c4dbe9df970716cac837b1fb9
stem_e2va wavfiles/DPMMA05.wav 8260e22cdf54941aea9a879191303e88920f8ebf47281c92eee22ba1d389659b
stem_e2va wavfiles/DPMMA06.wav 39d0bbc2fb68eb1873407c4d5b4a42a28a536ad4302f04ac66c55b5da1d441d3
stem_e2va wavfiles/DPMMA07.wav ac57f6e10c31ea564b46727e30f609d1aedc1f9896f63e3394255090c4884eb0
stem_e2va wavfiles/DPMMA08.wav 9ee8d6d575196d46bab656aa2d668caa213f3193dacf191d26eb7eaeb4f809a3
stem_e2va wavfiles/DPMMA09.wav 95d357a44f40647b1b3125e113a2a0a38e9ae15a4b1307ad8e226a937629073f
stem_e2va wavfiles/DPMMA10.wav 1690f927190c82e0d773f618ce7fe89970ca29c7589184dffb8f9354e4896887
stem_e2va wavfiles/DPMMA11.wav 98240dfb982dc4e618d6e4de5b5abe199d9354f21486ef17162d3f287e35f941
stem_e2va wavfiles/DPMMA12.wav 3dfed99ddcbcae9e5e5741c90d9d24ee5921ab9bdbd5641aa404dd9d0497fb49
stem_e2va wavfiles/DPMMA13.wav 135fefcb70224ebffaa0d463aa75b0286794a65a7fd79e98bfccb552adfd9477
stem_e2va wavfiles/DPMMA14.wav dd20218c636f27011699a3481a5523aa5b456febf3f7c33a62b3559443ce0646
stem_e2va wavfiles/DPMMA15.wav f35bf35b31214fcfe26b2f8148be110ac74731b48f5a119bef322e8efb0ce34a
stem_e2va wavfiles/DPMMA16.wav 165f85fb1471d4ad60a9efc8be8faa5208c7e032e641e63140aca1a0e405691d
stem_e2va wavfiles/DPMMJ01.wav b15d04646f0621da25b6dc95699d840f188a7e5a82d4275cd0a1c2cccfbd4b83
stem_e2va wavfiles/DPMMJ02.wav 98ade3e73c80f69ef574d637a1ea6ef0653af93d9326a9760d6d5573bb115bf1
stem_e2va wavfiles/DPMMJ03.wav 7f57db75e264474a06476bf976f8e451415ba1f095b922f13d2f515ca54f856f
stem_e2va wavfiles/DPMMJ04.wav 9819fa6d67ef63a234e8a236b6b6b9271eb923a7197b467905d7b2563fbc3bc2
stem_e2va wavfiles/DPMMJ05.wav a398ad9c1e9fd13483acd85685ec5afdbf50d2f4ff2f0533bcc6aa1deee39bce
stem_e2va wavfiles/DPMMJ06.wav a6cdcfba8fdda30b1b2ae5b837c52fcb5e6a0a8e56a3675a57152ac4d8a9dc29
stem_e2va wavfiles/DPMMJ07.wav f5fb7c3de8ba8318bee20986fe1ea97f2e8b15f115d579132a31e42298f32761
stem_e2va wavfiles/DPMMJ08.wav 575f792ffb76aedc293615242d19be39f61277ff25af62b097d623d3f611fe97
stem_e2va wavfiles/DPMMJ09.wav aa43b00ccd1490a6cfc8e9ea0e6dfef57863d28ea2f6413e07843d5d84d909a0
stem_e2va wavfiles/DPMMJ10.wav ac8703471fc2f8f00ed3975e91ca7d911a13de9d2d8cb496eb9c67ef1e08a90a
stem_e2va wavfiles/DPMMJ11.wav 4e059592ec4d9082e4ee662747fa5bc4e6788dafba6de83ac7f7ee8bfce1da74
stem_e2va wavfiles/DPMMJ12.wav ff25192b3c7a1d8f3495d33e5b0c06747dd11210aca2d9c45e4c01f8840d92d5
stem_e2va wavfiles/DPMMJ13.wav c1022631eaa9d949691275ba6e463cc1464930844d137cb3afce2358beefddfb
stem_e2va wavfiles/DPMMJ14.wav 0bd214438278a1607b3825b4d28362c428e88d14b37b7243e589f1c9520208b1
stem_e2va wavfiles/DPMMJ15.wav 1229e8fa332f6a1c54a1b60836de1293f18a611477e1b3a91bd6bda3c7bcf4be
stem_e2va wavfiles/DPMMJ16.wav 81fb5621904cbe6ea656f53de272e5257ef5b8c50ca80e654eac42e6c4142f1e
stem_e2va wavfiles/DPMMS01.wav e04929524db9db52da2efac5d8bf2402839e17d0485179e5b629afaac677996f
stem_e2va wavfiles/DPMMS02.wav 69de7a7c7dbd8e31c36fb03977f3e65450e3b3a451ad0e0e478e174e46fcc05d
stem_e2va wavfiles/DPMMS03.wav cd876b51adbda05f9a7ff1fd68ed6c98e721ce1dd763aa2ea908e25582ac543c
stem_e2va wavfiles/DPMMS04.wav 08a954b81a25795110132088b56faa407c6faed7066e674847a0ae5ddeeca999
stem_e2va wavfiles/DPMMS05.wav e9d954190f3c918c0f54b25396fd40961466cb7f909191ee0bcdb280edb9cff9
stem_e2va wavfiles/DPMMS06.wav 5587320871149afc976f22400ce2b3993db9dbab085e94fbd0a08ab5c98a3296
stem_e2va wavfiles/DPMMS07.wav ddb8c9a7233292ba6c5b6c0328c64a2bf227c8fd0980a2a5f7c4faf1b630324d
stem_e2va wavfiles/DPMMS08.wav 3f9d311380ebe6a73800745a20970d9e11582313053f181e01727af073174ddb
stem_e2va wavfiles/DPMMS09.wav b56bb9af092482ed0493651f5148e0ce66338963f6b8e03772bc849f5a8e4879
stem_e2va wavfiles/DPMMS10.wav aaeba5c4fe33c5bb5d97f6139fbc823d7b41bf4bedafde8298d9e771b77e635a
stem_e2va wavfiles/DPMMS11.wav 86086b26aba64d1c91289b677673da7bfe577ee45145461d981c27edda2d14cb
stem_e2va wavfiles/DPMMS12.wav 2a57cbdb398690c58f71faf46a3c5d1c906252dca2a0e600890b470f767e0ddf
stem_e2va wavfiles/DPMMS13.wav ae677d609503bd0a297c274a8e3645ceaf0f97e0f7b0eda440676d0a626df9cc
stem_e2va wavfiles/DPMMS14.wav 16e58d7bd327e9b86e75b974326c2105a39c8671d4d99898f55de3408c987ee2
stem_e2va wavfiles/DPMMS15.wav 89be4805ce4851ea29a4fd878f56b39a509eaaeab5e80dacd61a398e446c1a48
stem_e2va wavfiles/DPMMS16.wav d52a045ea7b15d210bda9b3a95f53a33b4dded8202d1dba45ecf3e433536d90d
stem_e2va wavfiles/DPMNE01.wav daa5cec15ea89abd5a4d8f1e72b1ae6147b97bfa5959b7e1fd87b020801c1833
stem_e2va wavfiles/DPMNE02.wav ebf4e2d05000fdaab32ab5fddec86f9a3f96bf803722f8f58abf105a36365be2
stem_e2va wavfiles/DPMNE03.wav 831575e065eac3d73ade9ef2df2bb79438be4209d1600ac3060cbe8e6e327945
stem_e2va wavfiles/DPMNE04.wav db3a163aef19f1c3a58ee09082c71e4c4074e19ea65b02b5626aea8e1c1988d1
stem_e2va wavfiles/DPMNE05.wav a21db8b600ed78d0068203d5661752831f2e581f65b53a667caec8cc5469395f
stem_e2va wavfiles/DPMNE06.wav d305be3f7cbb8af9a602cb87e5f48e7c915f6e4ded7958d868203664e2518c66
stem_e2va wavfiles/DPMNE07.wav 1078f031e729b4e6ddd820b61ab9a7be5abc815cb52caef8d5c30b5e4793f007
stem_e2va wavfiles/DPMNE08.wav 6de8e57d0d0c537d1d15b3083561de548b98dace821f98787374f8268a10b87c
stem_e2va wavfiles/DPMNE09.wav 1e4028dab90b62809dc15ca4eac79249d20554f1cff70bc29674c652bff3eaf7
stem_e2va wavfiles/DPMNE10.wav d1bb131d8c1b048cbedd1095df3d19475e53ae47b5b7fa9e1d89484aaa9f1c15
stem_e2va wavfiles/DPMNE11.wav 3d27ad4db1128700fcfd8a925cb95dad4c5fb22c34b6ec30be81c35a5223148d
stem_e2va wavfiles/DPMNE12.wav 2182026097297b42a36df07ab6622e2dc3e0942617a3510fdee3fa788ccac7fe
stem_e2va wavfiles/DPMNE13.wav a7550c0a7e1c4a7569449d53e07b273870b0b19b018f5128ebdd3572a13d9d4c
stem_e2va wavfiles/DPMNE14.wav 99bb3e72a791a8ad2fe0a7e23cac2cd0ac40ed99a7f7edde2031f25afccf5385
stem_e2va wavfiles/DPMNE15.wav cfde6cdf1f54acbd476eb7cc7396f3b043022d26ce066db4f6592ac221f06113
stem_e2va wavfiles/DPMNE16.wav a86e984c77595bcf1b240ed1951b220a6276245d8eec4a59864fc0683f3859ab
stem_e2va wavfiles/JJWMIA01.wav 3caf2621fc2ad7e4bd4139d740a6215bceea327e44bbcaba3a2a1e3bb8785127
stem_e2va wavfiles/JJWMIA02.wav 893f25cd4170c1bef4292740a4e2d9fc0fe8d1c6f94ab4f31f97e0a0b993f543
stem_e2va wavfiles/JJWMIA04.wav 9186e24815d81da69302cfa2501394affb257444fec43c9d3780165001fe9b50
stem_e2va wavfiles/JJWMIA05.wav ee9f3626e2534bfb4d094cde658001bfdfdf024c7913d0123cd9ea76fd2540ce
stem_e2va wavfiles/JJWMIA06.wav 7747236f1f61d731f2aa2760dd4cd42a74b932bff00a348e43848fb615e9f7f0
stem_e2va wavfiles/JJWMIA07.wav f373b70faa28d8115594d9b72c4dd34dff698a26da1970fbbe0e6c6de5e6d4f5
stem_e2va wavfiles/JJWMIA08.wav 9706d60b809f023c6daf1cc479397e4ace3d8bdbcd7a668ad362bff0358cd04a
stem_e2va wavfiles/JJWMIA10.wav 4351f47e177eb857ef6e5e0b09330667de001576a77cb9862941f2b64871d669
stem_e2va wavfiles/JJWMIA11.wav 3a1552125e1a71634078c02f4c95e0f9c260888322606bed858fcb7731ed65e1
stem_e2va wavfiles/JJWMIA12.wav dd3a7a8aff982cb0c6c020afd241834d15a623d360158f4520dc7011ccdd0514
stem_e2va wavfiles/JJWMIA13.wav d6266a625ff4f23ddb0896f55ae890cb735a39eab32eb50e3cb66b75c14872d3
stem_e2va wavfiles/JJWMIA14.wav 59691d75d2750b5adee3f5944d52b01877ca579ef66d0089f5eea72595ad04bf
stem_e2va wavfiles/JJWMIA15.wav 4c5103cd63891423e04e1321606030d8b8e31729fdab4abbc38077817d7b9d83
stem_e2va wavfiles/JJWMIA16.wav 0648e1806036ef7a9708a48bd9764c893e89b391fdca311f347c818ac925f3b3
stem_e2va wavfiles/JJWMIJ01.wav cdd8c4248d9d42672bf140f62ae46930aa0fa0da678a8eff8165d299207508fc
stem_e2va wavfiles/JJWMIJ02.wav b8523a36368ba09b3a02d5132b9026795be3760e904812419c49fe8292bbcd41
stem_e2va wavfiles/JJWMIJ03.wav 24e32cbe984f75df5c03b0955e58b72309c3250808e4c7e7126472ca80cf87ee
stem_e2va wavfiles/JJWMIJ04.wav 707a9cff8bc4e76768e4bb05bcf3628d2eed90c85ce1810d69c8051fd4d9874d
stem_e2va wavfiles/JJWMIJ05.wav bcb51a6855030f8d8b17f6443cd450e454f59d7836d232630e839acd13e2b727
stem_e2va wavfiles/JJWMIJ06.wav b64e99a6efa6bd9f67a0cf7479bd0ed7e176afa251d03f4c33ad2ff58fb84814
stem_e2va wavfiles/JJWMIJ07.wav 59589b2ac8fac0660aadccdaffa087eab7660a6f29f01605646e62034da7f9dc
stem_e2va wavfiles/JJWMIJ08.wav 1f965d08a623ce188e7c4517d020d7d37df14524063a45b173f18b7ea13950a7
stem_e2va wavfiles/JJWMIJ09.wav 177d8a723de95344d0069fe827f8bfb8ea9841c79273f2164831fd269fab11dd
stem_e2va wavfiles/JJWMIJ10.wav 83ef2dac5b99f7db9f99b0ac0e1604f5fa3da053bd5e4e2adac98577a286b133
stem_e2va wavfiles/JJWMIJ11.wav 3f461b889d5b041fb7cf5feaf75efd0f67e2a7f30cec603150241de34ab49e1a
stem_e2va wavfiles/JJWMIJ12.wav add256e25bee0a7a9bc24275b999ee832ac4dcbd2328d17d236343429e4a027e
stem_e2va wavfiles/JJWMIJ14.wav 113960941e35e0389448b8bd0fb9a2ef344e063690dbf1aa352be9b1669ab02b
stem_e2va wavfiles/JJWMIJ15.wav e47d94cfe08580519c95505de2dfdf3643c4ca05ef58a61fa49bf3bd7df4a722
stem_e2va wavfiles/JJWMIJ16.wav 3ce76fd92d3e0170c41b141f7db4085a4fb41537a1748c1000044b99a56b9996
stem_e2va wavfiles/JJWMIS01.wav 1c5ddeb6f227b4e76f555163ea1ba12d241078d23c3ee45207a089309ac0dece
stem_e2va wavfiles/JJWMIS04.wav f02f7790de481172a015d246da181536ca6f158460e8b15f055a0c04a3fd47b3
stem_e2va wavfiles/JJWMIS05.wav a37ffdf9a13fc31dffdc8faa6548086a437aea5a179c7dccc9a62aaaa27b6748
stem_e2va wavfiles/JJWMIS06.wav 0ff19a60a38a31f5009c499f098300665eaa330d237838b35bcbdd4c1a2dbcaa
stem_e2va wavfiles/JJWMIS07.wav 5b07825d150b6e152edd54f1b816bdd72d63b73dc7204bca5a7d776e3808f710
stem_e2va wavfiles/JJWMIS08.wav 40da4ac8408ce70bd3080e9bbb42ba5fcbf815ca6c4481ccbc935d23341ebda1
stem_e2va wavfiles/JJWMIS09.wav d600872f91788ff5b1e423d97dfb5d427d098895aa8b2dd69220f47aeff14ea9
stem_e2va wavfiles/JJWMIS10.wav 72dc47a7fe7fa79b1951a66299a522bdbd6f2d2b0cdc7132425ad1ec9f76a476
stem_e2va wavfiles/JJWMIS11.wav 6bd1356f73e088176042f61c5568110ea0e5b6306dd6fa2f3caf56a08efd9b6f
stem_e2va wavfiles/JJWMIS12.wav 912c9d10f9d4b18fc7cc5f8e98f99dfafa7e0bd6356499c601f091dc5ede06e0
stem_e2va wavfiles/JJWMIS13.wav e4124e540299477e0e50d51e354e0f6afecf6ae0b553dc1ff213de3fba1b12c8
stem_e2va wavfiles/JJWMIS14.wav 1e805d9391bb8e787a8e16c5aa71994cf10c5af7faa13a155b23211a7171559a
stem_e2va wavfiles/JJWMIS15.wav 3da3f22494df0e1ea612cb0ee5de5509e10f91dd07f8d26ea7ab3f9826c77f3a
stem_e2va wavfiles/JJWMIS16.wav b2af13cd1849ee61e41779557666445fc6d77ef31ebfcb581766ceb712b68cdc
stem_e2va wavfiles/JJWMMA02.wav 3913bfd240b9cfec95b6b1305d5fb4533eea37010ffd1f1dcf5662143c9bfdce
stem_e2va wavfiles/JJWMMA04.wav a90508379a43372f4ee936c2d7f1486d8e4acd5e92142320e993dd85493a3ee0
stem_e2va wavfiles/JJWMMA05.wav 87025988d27f786b89e862319255788e11fc5fbcbbf190ebae9070b5a7c9e45b
stem_e2va wavfiles/JJWMMA06.wav da791aca57c75e7ebd13afdca3c866f9c4150e1b52546f02b7bda9279804bb93
stem_e2va wavfiles/JJWMMA07.wav 7e39fbd2266f9415ee50bf9d48d749665aef77e238198aae1682345666b243c1
stem_e2va wavfiles/JJWMMA08.wav d6c22f6eb6578db6a73fe510788a4ce79f9b05b2e72d309cea93d51f88de6c34
stem_e2va wavfiles/JJWMMA09.wav a01b365788eee340fa289aa7d1543a2cbcee2fe60ac7d96eea07e819a7e01ece
stem_e2va wavfiles/JJWMMA10.wav e5b8a7ec5c3acc2b75bf46b85c3f5ef4da579eeed1622c57b6c44df5fdaf6d95
stem_e2va wavfiles/JJWMMA11.wav f4147146d0a7521f7882df27fe9b8a09f50c44b963cfd25f3b2ca82d6491f29a
stem_e2va wavfiles/JJWMMA12.wav 92e9ae11087363ce6d658d6ed6cc8c8f9ac438e24458eac58b45c7b5f4e1309c
stem_e2va wavfiles/JJWMMA13.wav bb007dcb456d3a53caed1497eb8de3af73e37c1c54ccfd59367cc17c6e3538c3
stem_e2va wavfiles/JJWMMA14.wav 9ef5905a7064d0fed466059021387009c80d9a1103fbdba33a03f5f9d489b773
stem_e2va wavfiles/JJWMMA15.wav 4f269a13fc18d23ad7e1057e6a7136bd2486bbe9f88d3448073ec5d5e850a16d
stem_e2va wavfiles/JJWMMA16.wav 11a6cb693869b8b845b5533d203a8e42e161ad012f842bbbc002a8f57f792f55
stem_e2va wavfiles/JJWMMJ02.wav 10c9e8342c0730e3253d6ba5abab6712f9803c84f91e3fd1ce98b9dd9c89cbbe
stem_e2va wavfiles/JJWMMJ03.wav 7b125de206e75c95fbb129117d3e1cd8fa3d474fcb79398b1952cd0eafcf73b0
stem_e2va wavfiles/JJWMMJ04.wav 6713d10b61c7fa75aa3ac3ad98bb2331a3f019d076787ae81e6dd293dc6aeb82
stem_e2va wavfiles/JJWMMJ05.wav b4ae3ada5a73003479c832d76b3a309e5b23898a3dd6adb9dc218f4cad4e24c9
stem_e2va wavfiles/JJWMMJ06.wav 425d2e4b853f8662cf9159743faf5ef29a023762504c4530e790011231f8100c
stem_e2va wavfiles/JJWMMJ07.wav 79f68e67a778430a91e77dc2ec41b1010a7340a7efef9ac7f231aeaa7ecb1fe7
stem_e2va wavfiles/JJWMMJ08.wav 3654af8450ed8c95746b3b9b93b3eedfb09cebbc56384b0f334590c431db942e
stem_e2va wavfiles/JJWMMJ09.wav 33c3089cc91598298ecf8313e483f958790aa59365bab2db5e42da8151453a37
stem_e2va wavfiles/JJWMMJ10.wav 3875b61939cc8226fff4890c7681a87946130dd6c078a982fba07301b92f204a
stem_e2va wavfiles/JJWMMJ11.wav 4d0c2530205852f2886a54fc2cb93b45c50c6c08feae2fdddab1cbccc5e0b2cb
stem_e2va wavfiles/JJWMMJ13.wav 4896f86015b942e52ff1a778d8837e5bdf8211f0fc9598a3fe5c01562034ebcb
stem_e2va wavfiles/JJWMMJ14.wav c3232237f1bf48081b92827524fbf5ae2362717d97561d6fd20950523e8a20a4
stem_e2va wavfiles/JJWMMJ15.wav c006bfd6ca073ec5fd6b95cedc84d499a2feb098622c217dcf62b2519376f3d7
stem_e2va wavfiles/JJWMMS01.wav a97d53cb06310664123d30c72e1ba0185bf1a63ac2030b2621b272472fa63ccb
stem_e2va wavfiles/JJWMMS02.wav 401c1f87ab80b9b32217228cd55c10c9ded3f4513670220e6f0c6008614bbe09
stem_e2va wavfiles/JJWMMS03.wav e2e073b96895f83a77e0dc41552c7bab5089c04a2afaae6f59713410e93b1b41
stem_e2va wavfiles/JJWMMS04.wav f29a0ea0349ee7fca3d99c07eacd8693855c6841e6dee2002da3340455e8e1c1
stem_e2va wavfiles/JJWMMS05.wav 1caf3af761228fbd014a16883473d230a5aaeb18c2b7efbadb389f2a2bc77d97
stem_e2va wavfiles/JJWMMS06.wav 3d14e91024a765fcffd32ae618e77e04f86883607a2f3a32dc9a3c797e57294b
stem_e2va wavfiles/JJWMMS07.wav da3836a2be036026b95a61bfcdc99465ca05fc4e59f1cd4788052e0c52c730f7
stem_e2va wavfiles/JJWMMS08.wav 3a243231cb705f7d57381610e13d9f60b278a2991aa35899e4fbd638d763e9cb
stem_e2va wavfiles/JJWMMS09.wav 5bbb9d4704f5db90ae05be0ee063faf30b317a0d17e6f136e03f4f1cb798d571
stem_e2va wavfiles/JJWMMS10.wav 49608b6e553edbb7b0f1b2d91d7f6d95a59df30a81e31c02077cdaa0e076311f
stem_e2va wavfiles/JJWMMS11.wav de7155f71204aa8a5867418c7a42253af14889470a7c97b406d6b08c40acad3d
stem_e2va wavfiles/JJWMMS12.wav 345c9ae851a2e826453fc4753d6ffab452f60b1d9ee6b571bc594b6467b14de5
stem_e2va wavfiles/JJWMMS13.wav 3067647355d7fe69af91a62cf734381508cfb1204834b3caf3de2eb75c682ee3
stem_e2va wavfiles/JJWMMS14.wav f2fb46663fed8129816f51d6e96066ee5fdb8be3a0626d6b321e8a9f7c11b9f4
stem_e2va wavfiles/JJWMMS15.wav 46e394bab018f5f7cffa7e9d2dbef5b7b1dafa8173149f7d95fbd1ba568691b4
stem_e2va wavfiles/JJWMMS16.wav 20128e54568efeb28fc70e00a8817d576af6ee18b55fd939973936c3b97fc2a7
stem_e2va wavfiles/JJWMNE01.wav 22c2f61b0dfc17b1a3c7fc0ca6566d3a1cfb88feee2670cde252bdf1faef554a
stem_e2va wavfiles/JJWMNE02.wav 968582710cd437a3ace35a9a1ab58cce0af32ce2c02210264df62343e5a176db
stem_e2va wavfiles/JJWMNE03.wav 045ab4aa5118f49c9713e4fe90efa0028225fdca702b8944f77d91945131a91f
stem_e2va wavfiles/JJWMNE04.wav 3cf0f5f64e6b90dc4bd95ea1c8945dc094c979ef63a9b0107cac42453b9a32ff
stem_e2va wavfiles/JJWMNE05.wav 8408664c0514efe88b27ec429914519c5e8e99b607a4c023645c35aafd52509f
stem_e2va wavfiles/JJWMNE06.wav 8200aa39bed3d03504d46cbbae745fed69d54ecb52a50d4d1ed3a5d854cb4fef
stem_e2va wavfiles/JJWMNE07.wav 6fef7946eb102850d0493de0d27669719ef6ad3dd8d15088028f3d54726ad5c5
stem_e2va wavfiles/JJWMNE08.wav e3d3bd4d65905654cf75bf42f698dbc831eeb84bc43c95dfbb1329f779779fcf
stem_e2va wavfiles/JJWMNE09.wav 788d1c25ce13c0b2c01757621cc8184a344236b27fdb883591e838ec295d2299
stem_e2va wavfiles/JJWMNE10.wav 89a1796641d11287b155bee8a682628b34548a46c86c01035226d47b7df333cb
stem_e2va wavfiles/JJWMNE11.wav dafe507d8890b16ff28355cd0beff504b6bcf777b8f1410f9c5f9c4d89f90297
stem_e2va wavfiles/JJWMNE12.wav bbd9ec741619c2b371b638bc0e2fd0fc07c23ac8b44e7cf71581144bd24e011e
stem_e2va wavfiles/JJWMNE13.wav cf6922ad7e0ced222b03e9fae586f268f7ffd163b6ae5ba697beb7d4f6c40aa9
stem_e2va wavfiles/JJWMNE14.wav 1a2dfbdb7d5a69f8eb832d45ecffe1726013823f7a77c9f7e2eb3151aededaab
stem_e2va wavfiles/JJWMNE15.wav eb26f6aaa3a0fe2841f6b7606e6e3972173cbc99f3fe0e32fef2ac127434a828
stem_e2va wavfiles/JJWMNE16.wav 60ea5e06696b8f477c5c4d6006cf890aa722772196279f5d32aa2607a9c58def
haskins example/F01_B01_S01_R01_N.mat 719c8b59406257d44933e67c0567915b9a6469211f2dec4cd627ab77955ea496
haskins example/M01_B01_S01_R01_N.mat 0a72df9305655cb94622929a6de8f4076bad90240de4829d0ea35e1c8e7bac9d
haskins test/M04_B02_S44_R01_N.pkl 1b3bece68a4c8e310eea815e93975dcfed82d54b0b4c50a3db78dc84a37f09a5
video_retalking examples/face/1.mp4 60fb69b90af2edbcec762530bfab8be5be2753bca9f3f897005772b544313f94
video_retalking examples/face/2.mp4 f7d30499bc380f4d18c18b1837fc1f6eb280fa21d79a9f7c6dd66db94296c43c
video_retalking examples/face/3.mp4 707d58aa3511138bd69e51944a732e010cc6d9063d3d79c178b50fc33cdc0ecf
video_retalking examples/face/4.mp4 414be3ad61f09432adfbc4933e0163539e94f74fc445c2b9114f8c64e38a480e
video_retalking examples/face/5.mp4 f664ca850492bbe151898174f83e054ca90f7390696232a9935e10f88a31dfd4
grid evaluation/samples/GRID/bbaf2n.mpg e468120039e208b5ff9b9e269f8dc96bbddc45701f8dddcf2c0ae21abc0df546
grid evaluation/samples/GRID/brbk7n.mpg 2122707c6dd3b59a32b5272870afb37397dc6b20cf52241cf8ff7cfda7b3efa3
grid evaluation/samples/GRID/lbax4n.mpg 8f80c8ced6a8cb47d55c5c01704d4669b410369af653f6be7fbda9003337dedf
grid evaluation/samples/GRID/lbbc2a.mpg 9447e5e0732eeaf4444b5ba1e3412c8a9e194975ba7c814fa64c4c41c83d4e4c
grid evaluation/samples/GRID/lrwp9a.mpg 1a6c86fc5e7d4e9ee66a891f188f9a648c9b8be3bdc2431d73ac7e533aa70b3f
grid evaluation/samples/GRID/lwbsza.mpg 09090d1f7a8a946233a015a1b4258fafcb790ed6dbbd884ed88ae51fe36841a0
grid evaluation/samples/GRID/pwij3p.mpg a610d98c101dde3587cc66d70cb569d3b1d0111cfad90bd0037e47e21316beda
grid evaluation/samples/GRID/sbia1a.mpg 768e49272122f1577839db576ea00146d08e83d778c7fe8b9ca1b194dff57c7d
grid evaluation/samples/GRID/sbwe5n.mpg 6707e709f1d713a6ff6673c85605e2fa721cfe59749c56b9f34e6d159c5fdf55
grid evaluation/samples/GRID/swiz3n.mpg 080f3e1511879a3baa41cdc31aa7029981f29c71434a570de3d52ee78f9e5dd0
grid evaluation/samples/id2_vcd_swwp2s.mpg 3bb8cffd51399caaf0c97abcd32bcab3493b2878ffda73bd648490ea47c75cc0
pcavs misc/Audio_Source.zip c2db3448e2269050e066fc43fc705d29e6638f75c01cdab4b8781b89f1664979
pcavs misc/Input.zip cce17109e931d3b29062a7ec949ff4a2e14dba0d6576cca2751a3de426be9dc3
pcavs misc/Pose_Source.zip 80052de6b2e3519be1a9d0a71ecfb51c7c88f48cb0b5dc159def9aef4c668297
facegood shirley_1015_bs_name.npy e564a3ca9f6136efc2201b9d77c1daf346cc1fbbde0b8d9a41b1ae24540aed43
facegood wav/1114_2_01.wav d3e5ce7435e179ea8598f285fcad34b4faf81fe75755479a108752402c0ccdf9
facegood wav/1114_2_02.wav 1e046d9a37a1a5702f7b74c78144236da838d86a1c804c77f3802ea603aa4a7b
facegood wav/1114_2_03.wav 7e1e1f729a14253baf7bc19aaec9c9b9f3b9bd900ce8bbd36304bf7d05a83cbc
facegood wav/1114_2_04.wav 00d721b17eec37473850c20db8dff6c82268041381949acf34f1e5678c9fd062
facegood wav/1114_2_05.wav 2e21473a2d427cee5b6a9928096b354993c5017c840026859e4915305d51fa11
facegood wav/1114_3_15.wav 3f50dcdf34ba5ce588714cecfb018263b04b0de575bdbe57c39d2757c13fda61
facegood wav/1114_3_16.wav bc9f6d035ee179816c02bdfee72f6d85a7908503536baf3858992d2d0f4ea606
facegood bs_value_npy/bs_value_1114_2_01.npy ead56d986e6b6001e923607df31f4322abf1e6155ba269b2ae9894c11920b6e9
facegood bs_value_npy/bs_value_1114_2_02.npy c8ea7d39aa08820cc11a65f9f1b051e8fa971eb8ded02107686917172bd5c396
facegood bs_value_npy/bs_value_1114_2_03.npy 2f5ad20bd64b8f3fbdc708462292dbc61f1c1e7ae0dd5c0acdb091a2b69c9549
facegood bs_value_npy/bs_value_1114_2_04.npy c6541160e2514a9f393be1369df557f9d14df692eea996b754b2ca5f3925526d
facegood bs_value_npy/bs_value_1114_2_05.npy 0856e9938aa29b6eedb0eab016adcd433cbe3920b86213eab53b9e91a13cc63f
facegood bs_value_npy/bs_value_1114_3_15.npy ec9d15ea4ce15ca620814ad7ce437411c4bf1733f8663567a92061732af05921
facegood bs_value_npy/bs_value_1114_3_16.npy 1cb17d04da6c7d98f3953a8953e4f22ea6df3fe139e5318ea02c882b573ef6f3
"""

if __name__ == "__main__":
    try:
        main()
    except InputError as exc:
        print(exc, file=sys.stderr)
        sys.exit(1)
