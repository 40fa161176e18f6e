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
        samples, rate = read_audio(path)
        yield Utterance(speaker_of[path.stem], path.stem, samples, rate,
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


#: More GRID clips, each repository's copy in its own folder: folder -> (repository at commit, the
#: clips' folder in it, speaker, sex). The repositories name GRID's speakers (s1, s4, s26, s31);
#: which of the LipNet samples' speakers each is was told by their faces: s1 is ``grid01`` (its
#: ``bbaf2n`` is LipNet's sample, byte for byte, and is left out here), s26 is ``grid10``, s4 most
#: likely ``grid06`` (the same grey curly hair and eyes under warmer light: counted as one speaker,
#: so that no fold hears a voice it scores), s31 is none of them (``grid11``).
GRID_MORE = {"osalinasv-lipnet": ("github.com/osalinasv/lipnet at 2149e39d8ea9 (a commit of its history)",
                                  "preprocessing/detect-face-parts/pruebas/videos/s1", "grid01", "M"),
             "vid2speech": ("github.com/arielephrat/vid2speech at 493d26b2db76 (a commit of its history)",
                            "dataset", "grid06", "F"),
             "lipnet_pytorch-s26": ("github.com/souvikg544/lipnet_pytorch at b857ab1f0fd7 (branch landmarknet)",
                                    "sample_gridcorpus/video/s26", "grid10", "M"),
             "lipnet_pytorch-s31": ("github.com/souvikg544/lipnet_pytorch at b857ab1f0fd7 (branch landmarknet)",
                                    "sample_gridcorpus/video/s31", "grid11", "F")}


def grid_more(root: Path, files: list[str]) -> Iterator[Utterance]:
    """The clips of :data:`GRID_MORE`, read as :func:`video_clips` reads loose ones (each
    repository's folder its own speaker, so that clips of two speakers may share a name)."""
    for folder, (_, _, speaker, _) in GRID_MORE.items():
        mine = [f for f in files if f.split("/", 1)[0] == folder]
        yield from video_clips({Path(f).stem: speaker for f in mine}, root, mine)


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
    Source("grid_more", "; ".join(sorted({f"{v[0]}, {v[1]}/*.mpg" for v in GRID_MORE.values()})) +
           " (each copied into a folder named as in GRID_MORE)",
           "CC BY 4.0 (the GRID corpus, Cooke, Barker, Cunningham and Shao 2006; attribution required)", True,
           {spk: Speaker(sex, "English (British)", "GRID studio: frontal video 25 frames/s (vid2speech's copy "
                                                   "720x576), with its sound (MP2, 44.1 kHz); lips tracked with "
                                                   "MediaPipe Face Mesh")
            for _, _, spk, sex in GRID_MORE.values()},
           "inner-lip gap / outer eye corners' distance", "minus mouth width / outer eye corners' distance",
           grid_more),
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
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/bgbsza.mpg 7b053bc68f14aecd333fa7be0f931b33ffc4f81ab09b20980806b34ce445f033
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/bwaq8s.mpg d039efd0a19e81e71a45333c319a499c98b51008355011b3132a722735329fd0
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/lbbo3n.mpg 5e9c38981e60995765c1b0fde6808c7e5c9e3fd98ec46d390728808927beaabe
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/lrbi7p.mpg 0f029da10267acfc40d88dfed18523adc8d5ab3f12086ace31abaa147e109c9c
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/lwajza.mpg 97178cf3c74bec5efd172d53c2358e73983ff90e20e4e1a39f8dbdf75f3ae933
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/lwwx5p.mpg ef65e0b7f0e8e8a48b079f501e3ba4b7d690f969e807b77678b42c61595399fb
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/pbbg5p.mpg 3b979ca17a3ff4f73835f001e2c2b5378c4ec82c62af4bf4242fac22aa461bb4
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/pwabza.mpg 9cbb391ca7087c326642c3f65ec6763a90c07327d78a6c231d30224fa9e17206
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/srizza.mpg 997aba7b0861dbc6e4475c3d9fe87df6491a049721a9ef7b1088f1c50a167637
grid_more lipnet_pytorch-s26/sample_gridcorpus/video/s26/swbm3n.mpg 8523abb9ac15475ed24e696a589a521d64f53e9b8e7e12ddbb442e81f7d05b74
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/bgiq6p.mpg 901c2f5cbbd20e27586110bc8537a2b368ad33cefb6e0ed1d7eb4b9357ffe713
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/bgix8n.mpg 50fb3e30d547c0f633eec183fc10c6a0f2739d8d401dc40b27d55ee71cb3327e
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/bgix9s.mpg 7e1b4f2ecece2862268f318c4060ebd2a07a908a89757c39153e6997f2169985
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lbig7s.mpg ca97b89e13d94a453cd0b454a3b772f5c57e2e067ebe6698a2d54b67ae641e45
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lbwo3s.mpg 248ab7fb26685ff73055dcc7c8ff51ac8b552f095fb3e6d4c67b8008749980af
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lgbj5a.mpg 23f53b0115020d3c521b115cb078a52b161222a8deb3923dede332d6d942c70c
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lrau5s.mpg 3017942678c15f33e6c28f746c20f7d3cb85d681076cd92c0b0f9535539d1873
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lrbvzp.mpg e5f95a2b00d7b331981ffff072e752e2f462de765ba8a2a1041c083e39ae7715
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/lwiu7s.mpg f92ed014e9b8f989714b7610d27a2673c0fbe16c2392ccc94e39f780af146d72
grid_more lipnet_pytorch-s31/sample_gridcorpus/video/s31/prwa4n.mpg a99524116f796371da21c249ed16014791f0ff734a5b387c447f84439f34962b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaf3s.mpg 0d9e595fde86d7f48b6b2bdce2efd2e479ce67c3b130405334750f34bbacd5c3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaf4p.mpg a84ac50ce425800f20c0b897055106c4936122dd4779a5b027ccbc70273160a7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaf5a.mpg 58cc1205ebb642cf2f7805800928f479547cb11db804aad2d8f7129e261c0c87
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbal6n.mpg 0c7f36eaceda1bb64adc2877cfe3370104d9451059addc9035f7da55390e9510
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbal7s.mpg 300c792a26642aaa96d80c409076eb392fc2ef0266676f3d57a7984a3174b4b9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbal8p.mpg 986793f145784a24fbd9f07c47dbb6b56162d167252f90f0487170167d44dde6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbal9a.mpg 22ed3f1bda958e71339f068d0faba4c434ff2fe149bc5a5d31a6d288cf6e8769
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbas1s.mpg 72c0da79e8b0b7e54f343225bb12732ad780d21cda15ef87e2a163f7c099fe11
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbas2p.mpg 7fa412aa1eb32e1be04b5eb585a2be8065a665b1948708f54b5247bd2a9b5ed5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbas3a.mpg d5b60c116066e99e08ceb40e65cb7a8d3aebbab6fb8b331ebf64e47bd5fb20c7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaszn.mpg 769b4ee747a02dc2fb66a718bd644b869ce414ef8963fbb78752e9c6f8c58c56
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaz4n.mpg d8c75199f2eb826246654853a281ad22012fa8ee75aa3d3b49f998e8ac1e4c2f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaz5s.mpg acfb9439b8f6152e771e23c41321a84ac2ad2a073dd63c89e5e8406f4e32acc2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaz6p.mpg 56f2d19228d87ba7aec0f95fe50a4ab8f4e35d32789fc7b49cfe778d77867e6e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbaz7a.mpg dc144ef226edc428ee9f8689a74247ac562eac01656129167b5fcb8c9a1ef54e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbf6n.mpg ceece83cc0e07d0f0c8630cf289fc59feca864403e262b074803cb7ba638dd0c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbf7s.mpg 22db5d83252df47aa29603e7ab92ab34eb622638390dbba9923246a6623ac01c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbf8p.mpg 16a0eac7bfceb379eae669a1b6a772e9a17089b2227e55f30458b04f0bcb1ec4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbf9a.mpg fd1ec833c72783961adf96ef8a74dd5c4df2f9dff55dc4f2994b25cd9aa7b88a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbm1s.mpg bf0e1245bb176e703147bb4665c117e6be796f3c91c95eb68846241fa1400b21
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbm2p.mpg cc862acbe9bb804477ffb5a88fce81afc3f721f1df435216c362d02f512652df
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbm3a.mpg d95ada6d2596bb7f134ad10210d6e30e9baac831d8bb7ef631a6d32d2386cf66
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbmzn.mpg c69d8ec04f90d40b04f1b12c37652460c71b2128b052a8b3d26ea7465f502830
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbs4n.mpg 2c658a37c34710c5c4211d74d05abedf5dce6a2f52e43d17b09214415bb928ba
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbs5s.mpg f3381a8848b8956c6783b03d4cc96c14fac37581ea4bd6d5645c9a1cd207f749
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbs6p.mpg 41d70ef301f028cb3321f859ecd8e1b6760d94ed6cc07537fde1842ea74a675c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbs7a.mpg 1145714400a1862e6ab53fa41e575e1ae52d48efeaca0c34bc0794aea5c0becd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbz8n.mpg 124e3b0006872b4f78262f4cb61b5dd0d19fd4b5235b13d1b5f9a84675ec2cb2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbbz9s.mpg 5eda90d89fb8cc8b7dc9ff435d0240f48688cef56220d701b76e953044a34561
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbie8n.mpg 8b9d33c0cb5d2cba2cf8a6c42b61c9fa846ad3e2edf636f659d1d7f62ce744a2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbie9s.mpg f83b93b92fad4118efc28875f9cc2cb43ff3516b247fb2df3a34d59678c0f02e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbif1a.mpg 39418217ed2e89d0640cac841d28a12e81fb41446b0dc59718a636cab671f090
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbifzp.mpg 0a9a69d83bab487c3da354079bf7056a78f04b1d9ac09815e1ed282e22e235bc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbil2n.mpg 4e362d25c68556fe4bf4b6323a1f5b93062d3c631f2c27fb29b38fb59a88bde1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbil3s.mpg 72c6484c3be0719a76c9315eb3aefa31de8218b1b3b62603f6ba48b103fef310
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbil4p.mpg 2cdfde044b1457cf1459fc64beed31a1913aa6b0b87e4611265a67a1d4993eb1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbil5a.mpg 086b54a3354c846c449e3f2a4f2e4c3c7d902b2781a83892b73d7b69c6554dfd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbir6n.mpg 72dd215db9507d1dcd6004ab271c0f7e13c3a7f9965c75a931eeb52241d23d8b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbir7s.mpg 93fca1ea0a7b8977ebe8902b2f040198f84f0b39b9afa3303f3dce460ce35b64
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbir8p.mpg b9955525357aee521751695457c759ce0135ac13b62213bd20eaf3601bf02977
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbir9a.mpg a31761a1b465b447e3b4f57ff5af8653c0bb3f8fb39ba5cbba9843479eb6dba3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbiz1s.mpg 16d1e16e3bb1310239bbd03b2cb4a5376d05309d9e5dfae9e43d619a0a7b6e21
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbiz2p.mpg ba5b267999e4d839c003545336411c89954541371fecda0c72fc1eada668605c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbiz3a.mpg 4adcf0e0923d830c99982c9faf9600b550b02eed5c6e258ad80da5ce4790af10
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbizzn.mpg 8ab2116f778ccf48828293bfd8d79839921a8df592c8468554e6f3016a7a51f1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwg1s.mpg f617f1b812cc8fe5f00fc0738ff7ff9fda8c701445012683436f5b64590802a9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwg2p.mpg 3a88e921b2c15c3a179c8f12c18793a2bbe76d480250981e1ea74ba52a4348dd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwg3a.mpg 3d4b071685acc7689baccc8f484bebf414ec0bf26daa154eca23fc4df82ad9f7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwgzn.mpg 73bc132c76e16da1592fad16eb270532857b2100bf5cd30eff579c95bad38f8a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwm4n.mpg 7d54402234ebb75420ec62c179eb958bdf8eb2b88bda2b3985835ca7d28c6627
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwm5s.mpg 58fcf4713b857e6ac36c1e8ba8d67f11cf1a8a1c6a15f5c58ead37d94d4296fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwm6p.mpg 900fa2049d69980d0103169ea5cb8cb628bd563b79c9c56d940974f4096a7035
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwm7a.mpg 5f32635f5aaec46d376c398a52770eb01f6119976244cb09247e83239e284612
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbws8n.mpg 7703e0975fc812ff693fa775f28731cdb9cfe94005ca25b730e162bf068e6871
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbws9s.mpg b8d7b885bd4ca6618df31108a18fdeb64b1fd9d34dd9ae753e98314ecdfe1586
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwt1a.mpg a8062fd098a3a4f2761c5e58d5b9e4249e089edb5297f6d58e2580e02a9fcbce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bbwtzp.mpg c9d37ca05153429b5b1782f2d24f04411fbc59dd160b82dc180fa8c120e063c7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgaa6n.mpg 3e5cc04142f45bccf0599d8b1c033263339cb2c6c5471642c601237133306fec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgaa7s.mpg a3d748632c85287b4256c7b97b985499d0e5dc8da04e63f6a8dc52df332930a2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgaa8p.mpg 384dbff2554496d2fd56e4fe90f5e193b430d80555e119a8fb830ff909d066a1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgaa9a.mpg befc01ddef936d80e9e578ab9dc3972e4554281b46901d5568028ce43fa9fe80
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgah1s.mpg db306d67fa6b2e083620ef33ce61886bb9f4c01e4f7e22c3e6f358ea5eb2811f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgah2p.mpg db39bd38c1b73417657c101126ca421414b12284a194b90c92a774786ba7c86d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgah3a.mpg 82413bd2637b1204036fcad2e5ae84b0fd67b550b659eb4ac7d21b6bbe115a39
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgahzn.mpg f2a9bbdcafd472ca05082710545442b31ff0fd6c63f6ae288243a0d552336b23
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgan4n.mpg 5161d04df7ee59a0df5615808267205017c26caf43d81e9a7ad7eaddb395fc18
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgan5s.mpg dc6b4958130a628b92981378aa22222c579dbdfc539a8acbe2c297fb3f8050e7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgan6p.mpg 6759c8e6fe8b69a27a2a81ecbc8b4c3420d768e116d8f41b0af566efbe986397
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgan7a.mpg 403233bcb9018dca8b47436da55793d3ced10f336d2dcfbcacef14825f5f38f4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgat8n.mpg 3eb522047bcf0a1ca834b17473a93bcb17a6e7721846e8087a158e2e2be8eba8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgat9s.mpg 1e0a363233496c0c2a25ac60bdac155e13069a69e496b0e339af559f0248e203
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgau1a.mpg 700333cdfe26732a820682dd158c1a0bf7460297d1190e8c3551a5d6c4c3fabd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgauzp.mpg 92bd4e59cc29046be007eb3b54e98a41633e2e52869928a676f53e458b3c5ab8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbb1s.mpg 7caa0094d1fd40edb5a7380a04839adb38ade5a548426fb7f9c96c7d5d9b815b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbb2p.mpg 0f90da0eb0f1f624f133e6cc125d79e07710849058cc645f91a8f7ad38ec290f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbb3a.mpg 14eaa50d1c563cc55b41663064243121ee18bd18a68a59cad4ddd89d57b85073
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbbzn.mpg 997bfba9e38753b668553efcec0ef1ae5e7b56c52f8a9c13766e8e29f966e60d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbh4n.mpg 449018ee2718703976e17be1cbaea7d5df1140b33bedb671b4d3d449d96db27f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbh5s.mpg 4f7aa032b3d7aa3ebb8d98a7cd6ed905d4b1fed538f732bbb1babaea0154196a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbh6p.mpg 19e1deb6ae6fb85a0dfbad25c68ab0217ec381779e968e3201aab8dde8c7fdfa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbh7a.mpg 9380e9427e2e171f5f97b08bf21ae9c931866c5e2c1cbf1557d3ec5e3ee8c9a0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbn8n.mpg 37c64fa3d1d6effd68b499bb27d9c7ce8b2662ea143a3c76f7f9bd32b3957612
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbn9s.mpg 11cd49580a8919a33127c306a82aa7a98cf9c65d6acf89b0796fd9d36e55d422
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbo1a.mpg 25104144e7d9b81f6298522f6ef2d2e69454faae705e470b7a381ca7dae4beff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbozp.mpg 9356e70244af4d0e075bc7d5dbae59048d7e59edb38af34c065b763210b73ec8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbu2n.mpg 12cd1236c521435eed92a1196a2dcfe2feae4dbd9cdfbf5aea2691dd4a457ad5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbu3s.mpg c4967fa515384d6fa54dc675ad8181d5aae13cbeed67410a5f51db22d2ba7def
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbu4p.mpg d1edb9ed9006b3d802b7198f2062e2d2ce78d9bbe481f2e56183d4351c2c7321
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgbu5a.mpg ad4d30611b9b70ef790e7d6feed0cb105e97cd1d5ecce570ba03c36fe0948e43
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgia2n.mpg 8d0486ad0aa6b6879861baf6e125d402c419a0767b174009663638150b3c1258
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgia3s.mpg 61158d85ec0f3fe73c04e56595987694efce146b8b0d8b56c5939d719d73d626
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgia4p.mpg 1efec56ea28431535f03366a929c10692ccc688198faabcfb7dfc5f044605188
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgia5a.mpg 0efa631f4b839ccdc165e3201cebe576317447a00f1faaf7b2f6752c4ff5054e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgig6n.mpg 99eea29cdd54cc407144b89a77eef5236cad8b36721c52cbf8efb07567ab8d1f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgig7s.mpg 5de382d17a728c5d35ccc9dc7ac2e142ae96e4df509152e4fd9ab21b609c73dc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgig8p.mpg 88746020ec98633acf0dd8a4a2f9177c95484765bffa4137ba849f17c2e36988
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgig9a.mpg 023b0d2566fbfd9dc5a9806d61b779cd02fa2ca74e9f7bdfd4725342284bedbf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgin1s.mpg 937df506f3d0dc9b8f39d0a619f1965123e49503bc0e7a5a9b709938eca40b84
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgin2p.mpg 88da3b9f7d6444cc86ee42570aaf99fa073bb015c9144b365cddb7b5b8429704
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgin3a.mpg c71e5c009165c10a9b45693d268ff57c3fc535870a8e4e4aaabc9de0ac0963b6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bginzn.mpg 85b9ab28815070bc1c4062938d57242e7ed6c15629ade96963f06e96489171c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgit4n.mpg 106c1f0001afa0a5de8c8a49f78925c0522e1aec42465745c8f4fdb706fa5dff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgit5s.mpg a414495763aa03b00a269f23bddefb16e7e2b682224e32c6dc521619d8837140
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgit6p.mpg 034bb352f2fb700817673cb9c0fd3fac3972de0335465c33be1eb4ce4b1a819b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgit7a.mpg 3f8a0a71cada861f3803e31d78b3fdea88d834cefde662dde54a873072e37afe
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwb4n.mpg 192be5f2dfc1ac8f5577b7ae197edcd123ad9f3d046bec4789c7cd3c50a1364a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwb5s.mpg d12a884f0177e12cb63e7b4cd2323812e9f50559b2fe67f3f59cc63541bbc7df
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwb6p.mpg d35d69e31a9c11dca3f29c320d8ba44cbf7f23011b8db7ddd7b5b8ab12a62c0f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwb7a.mpg 676363bfa13df2a4c896bb7389e0bdcc44a1726e21c1a4da9c7405bfae89b59a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwh8n.mpg e455731bb5cf18c87f6a4d358565fd345a4cba8b9164ffc8eff0396868eb3b40
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwh9s.mpg a06666ee2838e42fedb34488591401e9dd4d6469c0ebb4d2f068a09c4152f763
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwi1a.mpg 5548e0293ecbecfb5ca38073cfc3f923ec702f1a419d59afac0f63a282ec2216
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwizp.mpg 17bb5394858e88091753e5055d39d01dffefa14d52972abad180db1b90b03f21
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwo2n.mpg abcfee5f6b557333d9dc9129a41ac384ae953929d06b56a03aa05b1b57bddbc5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwo3s.mpg 77fd8203790985d05751e90458f5460e5c3704f455d2758859f695f2f0e67b1b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwo4p.mpg 3ef84ffac717f5d19a86c3df608dd01ef5a2701f1490b6aa01e3298a2099b379
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwo5a.mpg a195466ac41fbd10713487a000aef207d696eddef80b3380f18eeda4b5194a73
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwu6n.mpg a2b4e5d0d8f19b8686ed6ed69b8618e7d0a047f07d91383192de05224484c7ad
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwu7s.mpg af9a9f5201105e0649907a5839384ad62287a16937e46d2d053538651abcee30
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwu8p.mpg ae422a8daf3f310bc3443db5ad8cba53affd55c7fcf19182aabf6a7df63e17bc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bgwu9a.mpg 1a518b496c57f5f5cf1eca705633427bf88231b4a055cae450371b724cdec556
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/braf8n.mpg 97cdd70320bcf0f1f368ae9fab6e8e8b38fb53c0318c43c80e44c647eab2620e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/braf9s.mpg 7a98a51d8fe327a5a2b49554b1edff143536179888435adc8f10f1bf155ca52a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brag1a.mpg 7a6f8f7c09e3d37130f76d2a120dfbf8f6fb2902a431bbdcd2c3dc128b001363
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bragzp.mpg f35d8c966076d97227c22f23310cae86249660c08ed34fbad2dafef1ec10d0f8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bram2n.mpg 3c43bff4cd5269e4bf74c3cd7d7e4bd5f7150960f3268a242fe39b0b541da383
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bram3s.mpg c7b174b9e304c7199b8a618a4b43daa1b3c9fbb889c4629015c986323145d27c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bram4p.mpg 23326d3456722130d29b32630a78c18a1d4cf8e959ff7b144fd2850de2a9d25e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bram5a.mpg eb6200271898c881a438009f32bf0a959db662373261f9b71d7dcb937544cb3b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bras6n.mpg dd14a2a3fc4b34e75b40ade864a4a218c7ba4e3d2bf48d643eec4fec8e61f780
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bras7s.mpg b65f9e9a0c30254f4018ca83c67463bedb88bacfefd2d813a6eef7387fe0bf85
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bras8p.mpg c1b42d6110b41981b2d09214faaa30547b16738c93a9914bd37c54e2e6139dd2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bras9a.mpg 7208ca021772c5d08b690e16daa2298b42cddcf04f3a4914d38608f7360cf957
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brba1a.mpg a7a07755b1d43661ffb118afceeaa9cfa33eb5aa89a476e3076efa11929e8fb2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbazp.mpg afaad7b4e704ef54b13bc8fe6d7e8e5a4ec856f97fd77f9645f4c439254e9aa6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbg2n.mpg 1091c21fd795bf07115bb9d171f133e47a45cc3e6ecec3cb21fa1cccb499950a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbg3s.mpg 518608796dbee718a16a0cd69719202a9dbf4e75bb0c367bbb4f832571d2e33d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbg4p.mpg 10d03c4115b6e50092198a94c3ceb4c37b78ecc8e0eb448a9a73bb52e61b6071
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbg5a.mpg 41058731ddb286a90f092d02eedc3599af35824806eb6f420e8b6065b4d78526
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbm6n.mpg 62ebd1af1ada9f30b91ebd5356946c88a0b7081a68156036fec24e1ef6168209
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbm7s.mpg 10be5d1422836f834d8c974719bc6ca3cf9aadf36ef72aae0b75fd57ff020451
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbm8p.mpg b5ede4507bc32f254a8cf1b1093883ad117e8b6fbd7d2c964f73f2fe91ddaa99
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbm9a.mpg 60ba2fd0dc414b33746951ea8d91d8fda980c02bff9025ef38b0fae02372a6d4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbt1s.mpg 5f6164a9213dc72382044c5df70fbdf0ad08a0445321730c4d1e7be8f4875bd1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbt2p.mpg 5758e96928a75afd2858289558ca6e9eeebf4be612354514e85eb9ec7519313d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbt3a.mpg 9aa0a33c0029c0e62ecd9e8aa27405e69f428e98934b44ddbbac5d0c59063fd0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brbtzn.mpg 6f7b12bfe01e39da9cbd910f51bb16d523a6986d66f4b4cc4be61712f0c73a3f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brif4n.mpg c93a450e1fb5fa40eb1d25394dce503b1030a06186e1de444fac0003385addf9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brif5s.mpg 05419276ea4df269dc93f2fa0d054dbe8b2ec7aa769c89aedb12e3064a1db45d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brif6p.mpg 8a8616ed0f84ab4ed9b23ac528b8fd11be34ce3df8bed44b3f8ea76cf3dc228a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brif7a.mpg eca0c55c6a4ab957ee917d69593c5ac43095d5583ec9b695a28fe8c01b60ba46
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bril8n.mpg 7ea09c4f0a250da247af8574d8897593dc5efa5b5d04b4da7e93cb04f3e9d6fd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bril9s.mpg f622f81639de02044d114c2864ffa4b833b62b12b5b4844d006ebeb1ec0120d7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brim1a.mpg 3913b46545e6f84af66d68bffcfc90c599c2c3f0f43bae5f00b22e243e542387
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brimzp.mpg 6bf8c8d5e411f905e1fc1dc912009407bc42228298ac29baa37435a723531c97
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bris2n.mpg 035d58d83046ab16a47f6533da99c06242b7ce448d8280cb404d2ab3b3803af4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bris3s.mpg f51d9de22a29f6898e7b77064f9daa74776cf624b18ead695c7cf8df67f7dea3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bris4p.mpg 29c537fcc66a9a51a11c7e2d94023c41c2e65eccc01230a272c5143c602117fe
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bris5a.mpg ef76e2efb44a03e10d1e86256c7f9659f48162bb39c52db5af82ad66f5a3bc50
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/briz6n.mpg c157cc415e4a4d7353f64f90a38152c26b082ea46e2a0ca354d9f35645e3869b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/briz7s.mpg d23edc5806576b4cdabadfb1fbde40f71c3a2210b46d31d9d6a3394293c3a2e9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/briz8p.mpg 15a03ec68d6cf8b3778064db224bcca1bd3926d3fd5246a07d38069b7a07be94
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/briz9a.mpg 631e36ddc58ceb208230555141ab03b0396ff3c737cc0e14e495c19e6f681900
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwa2n.mpg 41da235cd21ab67fed12bc8ddaae92a6764e13a691b0ee3bcf1fc2e2014e8da7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwa3s.mpg c0d27921dcbbcaf9627929cacf5c3b33bed59d53cd0ea1ad6f74543863220baf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwa4p.mpg a7bfe35951100725f3ef9c6557854c649b2de063c7f73577724abbc566a5bebb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwa5a.mpg 5d4fb791de9bd980c5155ace773edef8fcdace9d22722cf9c09d32277817838a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwg6n.mpg 6bc095f1b186a28cd81fd50ad1477ec071ee5f431dd429c4e046d02c6f7c6ada
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwg7s.mpg 04507d474dc347bf3280c7c8dd1f7f6bad15e22b2142e2b884265f2e90e4765a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwg8p.mpg c75c42ba32dc6d002cde9c9d7aed5e9c4c83382d3eb90761c404bde487ce48c3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwg9a.mpg 7d7a6e7cef003406eb4ed56716e0903c210b753887b033e0fe1809f9a12da049
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwn1s.mpg c61386291651d60df99325e66712d0fcb732fdab66f3b6909d7ea817307da022
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwn2p.mpg c2e4711a3f8183e5fa8dad55dd1c694815559655fd3998761b550dceb6ce829c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwn3a.mpg c7fee2868e62ae87a54e361057ebd6730b5aeb5aad2cb73bc3f5de2437b4933c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwnzn.mpg 3ca1611f951f4d52bcf53f303ff4f13820b6375c6e875a77691561b5f43f0bdb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwt4n.mpg 0d8504cdad6f6392789fa1489847082d9eb6ce6b95e8840290945fcc7b73ebff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwt5s.mpg fd4b87dcfdc72b7228f75576064d564b0d3514d4fe1463bfa21e8103572f54ea
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwt6p.mpg 84c7c32d3444d5636ec4505bdfdce9c7e99a273102b210a55090794e7976ad13
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/brwt7a.mpg dbaed25eec54fa345f8ae300d1c7b57c03c9b705ea41832f3e8aec9e38cae128
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwaa1s.mpg c6a89c928fb68c30a895469b39a8deb1c8116b0314421f47819f4209118b5dd1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwaa2p.mpg 072f5a7fb72657d57b6b5ab19d08f2a05a94601e32886d6961e2131f4f4ce754
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwaa3a.mpg 017451554ec9bc56c96dccfdcd7dea2ffb7155121260c2bb1a7dd1c3133649bf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwaazn.mpg b9f457a4adc777f199a5794cc04e72cb181113afa54899f903f1774604eab955
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwag4n.mpg b72e74f492b91ce30a4588c3b37d31b3987f5f94df72cf84f1357828d6558d79
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwag5s.mpg 07c5aacabde2cc8c431a713d49003997c79e224f9de91b55bfed9efc2637a7cf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwag6p.mpg b2fc375799d7ca49dc240f5b7634dc1d442d94cb5d719c864dd56b8e825cddf7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwag7a.mpg 964bd9166b93831d8b8e4d701a3cd717201adedaa6100d4fd906c3ed65c5787d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwam8n.mpg 2dd00f06b7c94b09217b5e8c5630d16fabe04b9c9281e66bda60e0f402d3d118
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwam9s.mpg 9bc3fe5bd3a582ba762f8e75032d463a57bdd581edbaefcdd911e62bae77cdd6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwan1a.mpg 0fd8e72fd67d2e953dda35ef53d22bededba64daf9378c459ae8a47f8f9d6273
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwanzp.mpg ef75feeb63828316ee7b75619c0e02c777910a2207c2616f263a1a54643f18d9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwat2n.mpg a333b90e41c43dfa4ca86a31d9d7db0691b15a4317cff618acae978994b6aeb6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwat3s.mpg 72914c15ebcf5da5a75ddc57dd79275c0fb249eda63327373e40848e86ac683c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwat4p.mpg d0b3ff68366b9ad8d222b96181789a088e76e95a692551c78342558ad6b4f17c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwat5a.mpg f074b2bd502fa7b546e8709b27f8716ccf3c77f4e99f27519af520e811a5f2d9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwba4n.mpg 476a619e05bdd7664552c448b3f716d1d91a78cd1ca593893c44e175c34175e2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwba5s.mpg 131b4ee605b7576d85c7bed5be7fa17c22361cc54dc78539742d242091005d1d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwba6p.mpg b4bf1c66df8f04c943f6eae5faefde9f0d187ff3d962cb2f5acd36ca74d24e9d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwba7a.mpg f08a7ce978400d714b32c95807d6e9621a0ad833f04774842ae5a672a9769094
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbg8n.mpg a081cd2627ff4cac32be1d03d33fb5fdb988682890fc8fbb8a724fba0e724e44
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbg9s.mpg b8eff4ebb59c23a8a4a1fd337d7731172f0b46b2008ea4e6c7b893002607fe5a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbh1a.mpg 4f040bcd13dec3496386a0ae04ab73f88605ce9d6a4546cc47cfea013dd3588f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbhzp.mpg d88b4da2d94532d265a0cd24a05e0a4c1bdd4d308172934dcb7bf69a31b2a96d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbn2n.mpg 3ce19b781d128c746c395fd9a5f5d32b93bf65f83998e72d8a14535051c965ff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbn3s.mpg 187229cce200945a956ab685c6330da84ac597af9c764a72a3e657a8327e0436
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbn4p.mpg d4ad1d0f9c3ab7ac729649681a02895ff511a31ffd641791e83612b3b2a86167
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbn5a.mpg 4176aa4eb0a558a4ccab708e1a14ce0ca602240daf599582be1294e7f67e5bfb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbt6n.mpg b8ea3f6a81a805fbc5d319d8b9ae9d89c3e4fc80faaf611eacc1f2dc4ccb3864
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbt7s.mpg e5fea89e68c0cf654210351eef94005c20b3a01246103af8badf6802c1fb9f4f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbt8p.mpg aa8e691bdfff34762e87b9eb99898afe417be0aced6d5b2de3afadece3e15c81
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwbt9a.mpg 51a0a9670720b91b544972d366e970114e31ccace0ccc2bdb304e0015c705f1a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwig1s.mpg a56964b55d4a34b5be31c9048a5ff192293b229d326ba0dbb150d854333ad85e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwig2p.mpg 977f4fd2d0365f408d1dbd42bf024c21fefbae862bd39242c52dccf0bddd117d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwig3a.mpg d2e95c2c0c5745b5c33640ca2ffcb3c1c548e9b3ba5c55ee5811f0e5d28f426d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwigzn.mpg 9d0e70c01c2bebb30537895557de59e5027146294c3b7ba8ad3dfa14f2e7e043
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwim4n.mpg fd3a425d327beddb146985cfec03519fb5385a412f9fc6ad28248ff28f93c450
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwim5s.mpg 854de415ed8c7d96a06d9d075816bc9217b903ffbbbbc34c6d45ef5ef6433f52
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwim6p.mpg 4efd46bf8edc59da805ab82f0b3758ccf1ca19913f201f2a543cde9ea07c862e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwim7a.mpg faae57be8a53db773d0a273c7fbc10bee7c7d30a1211f7e9f7eb8e29901efeed
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwis8n.mpg 908414f5ac44f5503c3db236fd4206126afbc0efc7b54c7b9cc0d0c49e135404
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwis9s.mpg 24e351fc5e0be25c990578cd38a9caec8a292153a0439ee5dfb570286e6b12fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwit1a.mpg 60c528ae0b71d378761ffd9654096bb9757dd000918b7a47324de0e9d9a4a9c6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwitzp.mpg 0004ef126404c94d182355f31708bee209beb951d686a09de8c90e0b4db5e0c8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwa8n.mpg 2ab3436db0afbfd928d5602c098629d1d07cc0000edf0082fd496f9a79b50aba
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwa9s.mpg 9362a1794a27b9cf1b3eebb999b7bcb2deba2c50c022b31456c8eea16f02ee44
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwb1a.mpg e653523630dac14450f2bbd93028c74e480d37a0bae7826d301b9f6fe9e8c849
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwbzp.mpg 8ef95d750338a6b6794abbffcb715abbc67741860099b8f4a8b4e51fdf72e0c0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwh2n.mpg bd4b98e00da1da3f2ba06c1cbe42807d78fde55f3e426dfbe0bf960a628da4ba
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwh3s.mpg 81548f32559a12f1ffe1cf674a42b51f321a1a25610946a6d4c079919082f9ed
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwh4p.mpg eb5b57c083e9027ff26e161dc15b3dddbbf60f4826d1d8f4ceb2d8f3dd8fccb1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwh5a.mpg 6c9ce84c3fc384662a960323b1351bc83f56ad43c30f8d8ff20047b185740cb1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwn6n.mpg 1443f690a88c19f09db985d538e19ca27369db256a3a4a890b10a6a5bad55c50
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwn7s.mpg aafa01f66741661e05e5ee1c6bd4838a9fda467b47428a14f0bf071e00dea2fc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwn8p.mpg 4942a244f3f7c15fd76716d5c3c5f520bda6fd503304a8fab7de0a73df0d64cb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwn9a.mpg 01cbff623bdb1e3e44d505342d37cedb352319c917a69f4dcbcb7d6f4069b89d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwu1s.mpg 15b6eb8633178a7102fb5b38ab9280b5fc1932e8b1b3e1d99020764f78ec0d20
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwu2p.mpg 9a1a88f33737cb2dc29c0d7ee8c4801b8b66f6b78333a870fb07b5e12fb6257f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwu3a.mpg af31c5211653c2efa8321d4e960aa0641bf90da75eba2ce2bb1c90ab874afea3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/bwwuzn.mpg 1df0641a52404ed2832d5c392dbb91eb7e73a72546b270f146e6bd72d8c0b161
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbad6n.mpg fec8f1cb6b25c9f03ee72beaa6fcf7b34842886639208cce22e9b548a3c2db57
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbad7s.mpg 3dc683d83b9dd6cfff0220f2a349c64bdb737c71e3237bfa507d6890d028a2f3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbad8p.mpg 6b3d3b7502bc66ba00fc521149451efa60e2fb654f9a44b83afd947dd4c0af18
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbad9a.mpg d9c714ee81ccb1d9c5d1cc70c4c30a7d72ed1eaab0b81d2be9fb53f06104edda
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbak1s.mpg e185b3d09eab7dd385141a878932f3f22f6c858f2ecf17c6792d0e10aff9186d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbak2p.mpg 2faf659d3e409877c051fbfe8c4e1a77fef2d1e5b99e55933a961e8cbe8dbe96
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbak3a.mpg cc34548dbd3964ce98f48eb7a8e144f375778e40497cb5abc68f9f81dcdd83ab
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbakzn.mpg 37d887af158f8e29eaaa217b5593aab711e07af3fcb8953c4d51ed62087a0c6b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbaq4n.mpg bb6bd232a9c25ce1798d6a762f9d5c345079d10b864a1f0e92c611fda84e1879
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbaq5s.mpg 208419e67a40ecf2464cd8cc2f97891c36efb6c3d764fbf35029d0324312fce9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbaq6p.mpg 9734b649234de2946b9feefba9066c0617ecb5bea4d143ce223de5aef71be373
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbaq7a.mpg 4f663498d6d211febf105eeb5b9baadece59ae7b235ace9e699c367f82317c5e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbax8n.mpg 04c6383a7cce3f4e830082b02cb1dea989b2dafca1d0f4d085b69d3fc596d820
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbax9s.mpg 9528df8565805112f1734f95fd31a9dd961041c3f277c81f981bdcdc50f7475f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbay1a.mpg 82376033b87dfec83418b4256fa00decee0b0b4a1824d8141017c0b8f566a9b5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbayzp.mpg aa0a0bb82f6290b7b6d0ac96515e41bb07ed7db968534fdf1444ac457dd80b72
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbe1s.mpg 4c3ace76b7be7e4f7052ff87bb5d175963f6dbc9b03c0a56ee0af46311bfc81f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbe2p.mpg f354606bfba1da89056c6cdf4f51afd8b7734f2636465cfbbb68e66a6cebe4cc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbe3a.mpg 8dc9b657e23175073dae1034de93d904623aaa945c65d75c969819679af14b9e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbezn.mpg bb217a0c15979a8e285c12bf397fe80cc76fede3444a4819ec3dc78501909ceb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbk4n.mpg d508fe0144961391b1cc71f002f36be6ee8f081cbc597e411935f75624ad53ba
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbk5s.mpg 9f697fb8ac81bdec20fe1d8d88d5a33de0c2a4df9db1e21d07571bc73671e6ac
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbk6p.mpg a24a531a257ca4cdf8096d3aeaaf10794d681ec4f642236d352af8ad5e975d21
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbk7a.mpg 43f835f23c3b6af76711ca8c130e2cf39f74ed81f5532d156611d16bc4199886
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbq8n.mpg 3d8c74891b6f64a6c71d4a7213fb96f12d94c1e63af23100de42d7588a77bc58
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbq9s.mpg 6d49a1f69d838a52cda05d9ec355e45e25ed069a6fa082accf3713df9664351e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbr1a.mpg 446a5f7474ac70a4f457f8a36f6d0f70cca13067bc535719976376ccff729942
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbbrzp.mpg a41539510f42267ec5a36b8f1957ca3ca0b8feae3275c5f73b545108391130af
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbby2n.mpg 2122bcad6654282868095051bf7f36bfbb91e22f2f01bf4464f265aa9afe95ce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbby3s.mpg 47743135aae12213b277fcf5806feeca7e6cbc0006d3578c5c89a906ac800acc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbby4p.mpg 4d287b233c7cf6330ac7f441891057c19bea627bb6dfbc482785ed07b6a6c6e8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbby5a.mpg 7aff1ecf7e752b49a102d677d478d83480b5e0d4a989d0062de18acb880b9eca
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbid2n.mpg bf9aff8ba5693fc9875e8c61e640b6cf3f2b1b9b2843470576c28c14cacd668e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbid3s.mpg 2f5f3c350b95cd5db48c080ea8746006e93f4a3a116ae3728e9ca595a115df94
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbid4p.mpg 5c408874776ed42196e619c340827e2ecf00839d01e6274d09e2ec3bd534b0a2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbid5a.mpg 1527086e426f8fda542704fa7d938b0fcd382c209046dda53e1c6e553c5c0a01
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbij6n.mpg 1295e8d9f8bd8ac256613ffad9da778928951483d475f04d3fb4a4eaa0e28bab
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbij7s.mpg 698e4a821c061f84a2bc5ff9182f548837af95b3d799c7b9f13acae5f4c5d784
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbij8p.mpg 5dd46dec417002897cd27c5ef546adcd9f0c717fe2d0d66c2b8cc73ae6c718de
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbij9a.mpg d27217ea8af914589a049fcb6d28caf8bcd527f1e9cfeac28b5198fd8724b22b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbiq1s.mpg 7d768b865c8475b69202a7f168c93c33278fb22076bd9d3cafec77aaadd6ca26
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbiq2p.mpg b78953bdcc38604f1d9ed5d59eafcbfab546f471fc8be2d617c974074146878f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbiq3a.mpg cb76ce8d8f99205242be49a3af9c88ad177ba5990a7ec5b9b36fd8b3e11d6830
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbiqzn.mpg 928ac99e8f0d9689044d45704e8cb4e9453ffb7aa77fc550e34411cd395621bc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbix4n.mpg bee5561e2a775699ed6fb8052eabef229c14a419a2ec107009e2dc011e475e7e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbix5s.mpg ab5c344290c122b7bfae99d836151c5d7fd28459d36e7b8f13cd3e01c2af940d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbix6p.mpg de10004fa82d2ea00f05150bfa2ccfc93d2f13d5e4fbd50c530a2e0cca678428
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbix7a.mpg bacef26ad345e9d8602ffc368ee47c415ff93a277564d33f87d28c9781c172b8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwe4n.mpg 9a98c38c18525e79772d1822c6127c9abc5bdee27797287ae388626ae6d48a8b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwe5s.mpg 58fbe3e9e7e953c3ab9880701197dcf6a3d7bb59b68806330a076314be495bf5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwe6p.mpg 2157884f8d144629500cc146ab47da83308264239a14fb7e360f754cd0c5696f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwe7a.mpg f5f7c8260322dd0ca1aa3e45552a311b565fc16bb649f937dc2545e656413786
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwk8n.mpg cb114f24385cb61ed89c09cb5bb510259511c06e2c9adfd3510bae9cd0286d35
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwk9s.mpg 89a9f8ba59f357a7e9a811a805df93f790c6b7880e9f69967d517b1c971a5631
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwl1a.mpg 7ed7022bdd2688efabe180367a6302601bcfb9c489b60766cbad342bfdd9db94
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwlzp.mpg 97e10bcadbde024b6646c5c6ba7c915613d8f96eee3e49b82ef2b0bd5cf996c5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwr2n.mpg 7fff7237e604fd454c4cc14e3ccb941602f6da84a37f20d9128857ffcba019e6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwr3s.mpg d95be62e09abf45b5c8c7c6384fc5d8f64ad815328e9fff6565f540d9ecbd00e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwr4p.mpg 74517947ef52d42208d7f8f0a97a3d61d69935bb8acbe225e06d8c28dd31b547
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwr5a.mpg 91943221bf7f90a0f7c1465ea8ae508dc687ffebf563747bd07624b12a106edd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwy6n.mpg 75558f11d5153f04607baf534a379959e94f3bf154b88a9420f6c5c58a57c6c3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwy7s.mpg 13dcac0e8a5ed7cd84ef15bc2272c7146410f3622c368aaa1c66ab313bd1bd5f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwy8p.mpg c48ed733505eed9f00f140e19e25e3f5f37197499ad3a61cb1b735a98469770a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lbwy9a.mpg d03ba365c92895492ec347353db3e9165b32fceea718b3fea463086f24a76ea0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaf4n.mpg 1d34493584f465f2fcd7ae584a93b25e933c7e1311a65a88cc8286227433f037
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaf5s.mpg f211ead1134f08feed6cb6ad8720630b861216cb7726c0ad05ef2fcf454de888
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaf6p.mpg 12e5c8811b475479db7a40896eb29c26f1e9bdae169fe63bec86ef3dd8f3c00a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaf7a.mpg 89fb19d04a658091f0f72e634a4c925f7698ad9f76d01789cd84c45236432f16
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgal8n.mpg 89d672f6d684c3b1849dd5a40f6a1e7131966bc0d0d35507a92dd94b05c7ec61
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgal9s.mpg ee0af25ffb128e09a4be4e14c9389ded26a5c1ea62df30a2faf7f1108d68009f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgam1a.mpg b35a40014765bbfdcd5e243bde2fc0068fdbb3f8c029675a52a36522539bc935
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgamzp.mpg 2bde152437c21a464b4c9162a0f1b24b276e4d639568f4475ea47c060f3e75c0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgas2n.mpg 2bb01f45bc5da46a3c4f4e9066819990f0615a7a0cf68196da8bf12759a6b033
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgas3s.mpg d04e9e1c8a28c77457ddcc836ca20dc61ee85a6e1f87a3f35800b958280b40d6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgas4p.mpg a106d24be8cc690e2e828793f8174f89cf8632ef0e5582fa42f95f51df049dd5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgas5a.mpg 0722f10bef49e153efa4115749fe70b8aa83b42e52f3875ad84452aa981eb4f3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaz6n.mpg 3b8a745158dbd714ed5b5fd824ae93e34305b71a5ae58faf01b05487332a665b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaz7s.mpg 9c579f9b9e3768702166895670ca224bece30fa2105c1c28c3297f3f56d9771e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaz8p.mpg fb1b51fb47c76095fb21a0adda517581d6641b652b427c75e162930f46374283
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgaz9a.mpg 5c03e816b78a0beacfa8ae8fc429bb98d21bc69095a221d36c888c20325ff410
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbf8n.mpg 7609f6c9d8784ea03314d123590bb003c6179e20ff247dc41d75e33c01a43044
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbf9s.mpg 1bbd9bb3aaa56cd30529ee23800bfa07c67b6f04cc6f4da6dedc79ab68a56ea1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbg1a.mpg cc1d9a09eef871658dd42e994bf976cd8df287e9254b5f1e8de7dbb0ad6fa5fe
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbgzp.mpg d4d56b31539caa7a4a1cc4088c28e8f8a8ccdbb6b143a37334ef35b10c8da3f9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbm2n.mpg a77f62df4c13909de817fa5b0d4e173525916c90c3fb60745dadc664dc94e588
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbm3s.mpg f888ed4b2b83e48beaae293cc7c273b37131560a56f7b12fbca2ddcf207311e5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbm4p.mpg e00b665684fae9b57b1a0051caba70b85036132dcde93b4cef276639e6937fc9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbm5a.mpg 2563d7392370818cbcd80913f88db5b14030e30ee1e828a05fd661cf03589e0e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbs6n.mpg 9cbe2ab54ee2e305a753e67c207759510666caf3b592a223d270873be00d2ab0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbs7s.mpg 3b48b9494e830d2e65bf614495d835f20bf318699786d0554e27c2502f01a379
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbs8p.mpg 840aec9e6d0b080b70384b4ed6b4d3602e9395477d943c965e9bd2fccd3c8929
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgbs9a.mpg 2bd1425520b40ed0b0a524657ce6e410e25252b2abb7a64c23603808a18067c6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgif1s.mpg 6dbb4d286118831e43d80d9ff34e8824e3d6d5acfcb73a7700122e3d2b5a9b5a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgif2p.mpg 1063d18f11208952f3178cd46d870891064026be494999a5d591d3d777e4e3e8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgif3a.mpg 83134341b105b7cd7c7b7bd0638bcfc56d33987e8aa980bc8af0e9fdb72c42a7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgifzn.mpg f47b99eddfb449c48f8c31832014219dfcba58bd1e4d2814e8707a010fdc2104
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgil4n.mpg 808c3424c47969c2fd39027139eb16c05c6f136658e3e62aa49ca9c3ab591a0f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgil5s.mpg ef947835727ab4e5a9fb31bc4f4c17c8ab4b886185f187b8f6f3e34af4d7f3fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgil6p.mpg 4504a05ed169070259cf0e275f51b9d6cab8bbee13a6d19e1ca272e2491213e3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgil7a.mpg 8d641eabfd84c21b722ee5a1013466f6b02243f124515fb24c41c5c57478cd27
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgir8n.mpg 90f4ccdabc118cad3f243d76a9dd07c0de4285dff08e4a87253c3534d3027ece
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgir9s.mpg 8fa2ba6459a771e5d999154ec35b581ba2f27da3e8415b175f68e4e37372dcde
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgis1a.mpg c3cfc9963b582fba439700b60af03ea53b32c0876a7f958ef33fb13a512fa9d8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgiszp.mpg b1d22f0b191774103d71ab2d7abcddb7f16acd4dd52bc4886b5713d67b9645d1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgiz2n.mpg 2d4153a5d44acfc745ca71e50d833e22ce0cc208b26e787d7a133082bf0e1200
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgiz3s.mpg a59500199a18860798d05cd6bede8a3d00ef785f6832dcaf8d9174fa8e66f34e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgiz4p.mpg 7a7bcd4b6c20de1e6403c99509dd05d591401e937d194ee2e61a5f3c234dda45
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgiz5a.mpg b02d5ac642addacf7d84dd96c1fc5cfd956bdb68186fea8b0d8135b594daede7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwa1a.mpg dbb05a193075ede0221cf61e79b06caab52071d94580e063268d402829c41109
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwazp.mpg 6e5bcbd1ecc6424bfc7b0f08ec83948fda5c64d6053c39ff3cdc742f94eb8443
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwg2n.mpg 1222d3362b5e33e24de0e02c96ef2795187947b14afad1661061083700bcf7ca
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwg3s.mpg 5a0002b774969425c1683f52e893453665b22c8d5b41d3f6829ee1fa5a7d99e9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwg4p.mpg 0347ebdb3074a7dacd3cdcfed81b964215962be26bbfb4ec88fbccbea6b3d623
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwg5a.mpg 8d1b403b35fa1b6dc5c7829ec0e1bfacf5a4f4ae7f8445460611628b3965c769
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwm6n.mpg 4693afd22edc788855f987cd540f44b22813bc1999cb0a46c562a0a0fa1a5e81
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwm7s.mpg 221bf4c277e693d51143fed113df82f40dc4ac9560d44f206de45d725c4da6a6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwm8p.mpg 4d057fcde694d7402bc9aa91304cce14093fa3179334cc72ec60f2e8bd62bfe1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwm9a.mpg 2b279322dba91f92a4f99e32d69f052eb63cb8dacb66a23da565d92a30ea1c8c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwt1s.mpg f487b1d81f131f2495d4d2919025554f51a60b4e301517c55fbf842a45ad4e7f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwt2p.mpg 4c13ef67a6e56da712116ed176105c130eecf17a5f4d602fea657854e8cfaff1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwt3a.mpg a5c619febed8322b4abd28e31055872a7a0b62c3e3196fe4d2e0220b97e3551e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lgwtzn.mpg 58ad8ec435a8f1631b17882f0b447be92532e0c3f970cf605b8a6f3c0b90b582
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrae2n.mpg f1b6df6b51cc46d23a50ea4fadc1cd440c976f8b2a72c5956adc9fbc34cac592
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrae3s.mpg fdd72bea2659507f704a257fb75acfa194b9c31e934691b2131e5a78d100429a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrae4p.mpg 4883528e4510300475f2fd8a76267d5cc0521d70940f936c37d1237512514aaf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrae5a.mpg 890bdf0375a690142fa9b683082a288f0ee42bc1012687f659f82cdab56c48d5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrak6n.mpg 313773fe95d6d20ee63e9664a7d8828ab428f9d169cef3110b87ac74fd216936
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrak7s.mpg 51b56debb86d776033158b4f6df3e50f395ab8fe91feb72be12e5829647d12e9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrak8p.mpg b2daa1345272a7be7d7b5e7c3d8740fe47b651f1a65c137dc68dfc340aa377b7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrak9a.mpg 53aaa035aa37f05c7c5a962ceeac0df08093206c67dfca09837cc7867deaeb2c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrar1s.mpg c58978d4f94a5d89884954e11171166b26fe231a70712f7ffe5a19236c66989e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrar2p.mpg ea9b9b6275df15b13c52b8e42ca694efc1c7fb158e41fe63ad328f63f613d18c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrar3a.mpg a9f3d36c058c485fcf631bc9c8fbb2c9cd43b238e2df26e6b02b16214276892c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrarzn.mpg bea560ba4b8617ea9a94a6894c15652c7e5accb3773a54662d48a290e9102c10
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lray4n.mpg 9821b2b093ce23d3c609ca6795aaf2e23979d0a44024b41e89f225465e7458fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lray5s.mpg 3dedfc8c3764e1896421988af8be44a0b482d4f273ac162d2f63b32772ee05f2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lray6p.mpg 405e9b9e70676cd5debbdbb5e6336f8ada20bcd32eb658586430c04002e9e1ea
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lray7a.mpg b93d1edfd324fadc1c01f359cfe53ed0d8e5a793b459c2b297baf37a0f112517
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbe6n.mpg 6f345e7ce9694451eec7660a0c370dbae8f424521496b30391f39e03c3a7c62a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbe7s.mpg d96e70c1f17c9348d2745592b300c6357c8d41c95f03838773e4cabf8d4daa38
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbe8p.mpg c4bd9bb4086777eead3c0646b7ce861633210c725df36a992ec5a5610c6631f0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbe9a.mpg 4a9c0301f9da79a1a5891257b66f2386a2fc898f7b47f140d377bdad8cbfb1eb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbl1s.mpg 9d301c2fc1e5c843040a5e2109f7e0eded48f179c5100312ec95c19a9db0fa12
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbl2p.mpg 38699f7208148ce3b79bada0107e5fd884322ec15773916a48cf2623d0dfcbfc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbl3a.mpg c530110486e7590884d234152d03fe0f6ec0fbd7f0d9f4fbac0fe92b52a27125
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrblzn.mpg 796f731a013ca335827553bcdd0a9ef4dbd0b0fc2085b01220359bbbeb138fdb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbr4n.mpg 1fab3d169f8550edac55d0b4a4055290a62ed5fcd72d1dfbb5d525ffc393a2f2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbr5s.mpg 8c2644cd7970552c48d822505616c25ed889b74e488adfaad40f3af6e2cbf69e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbr6p.mpg 82ebb7334641c9737658157032fc36291f28c5f423ff08275976b940d7728483
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbr7a.mpg 3b8df2cd63970aabd5ddd03b3728643913ccd8248691a17dc0e723471c489423
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrby8n.mpg 0504c0be579ed1df3fa542e36c4f4846dcd798e3fd1c03d2ff09c63b1c921e31
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrby9s.mpg 6432dbc76e5479aee253a766954164cc67a63be9d62dca84ff2c711254b1c643
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbz1a.mpg 236bde0d1047aa7d0d7a2eb9636f7043ca78b167fb88ab58ebc84067ce166855
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrbzzp.mpg 4bd1326b6fd1d5fe16e1f62a23b637e8158538d1caf75dd5b5da4986b1b63979
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrid8n.mpg 011bf8cd9dd1c6ab9f14cb26b0fd419acda4855453c222833b95afbcc1081a4a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrid9s.mpg fd02a57591c99aaccf193ddfc310a9f767457b65b2649ada34329272e911cca0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrie1a.mpg 557ab0374be15a0d97d552c00f9da5c1d1bb06a77f178ea5e603a4a544b052ec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriezp.mpg b5d13d20b83c5e1c3ecd007725510d82e33c02c6db69ad34a00d279235f4daec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrik2n.mpg 9159785605ee9cd2a17d478778ba13ea2a3a48294ab5e59a30faaa02b7531b6e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrik3s.mpg 6248d15c899473332f947c9911c6dff8907016cac8b5535b05fe1ab256907cf3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrik4p.mpg 161bdd49251e33b9d8dd6f8c15d5e10468c19b397bd9e780590d80e5bfa71836
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrik5a.mpg 741868e45f4511af91a267a2172545705bb1c2da7abaed5568d69d13e89d7ac3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriq6n.mpg 00e21ab844a220b33924680ec74d29da0d6b56bfd22f9234cc900be227b14092
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriq7s.mpg c07bf44d88625736423479caf8f39e574cce253ed704f0a33a041c6897e6e1c5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriq8p.mpg 69652a59599932b22d1212acf4f436fe03157c71e695e4fc44e61469dcdaf685
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriq9a.mpg 806e70f5daf6f482ce86db005a1c064a2cb39c9c2dc6d38f42c16a119e76ad65
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriy1s.mpg 5e91ee020ff07f8b2d2bb2019bcefbf0f5a337e4bcd0b1d1a85ea089dee8c212
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriy2p.mpg 678e6e72d329b7314e724267992b76010c16f09d67e5e53af6910bba34cafdc4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriy3a.mpg ffcd9d5d4c3b474555b0af66c87ef75986b007ccd8c824e22298dc46f410e05f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lriyzn.mpg ba3b0518007dfaecdaffa83bf8b47524a0a8ac3dfbb047783d12cf27c7e2edc1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwf1s.mpg 04fce83d6894264ec1f875d26446d765b4e479ce81eedeaf99382975eb1c6e2b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwf2p.mpg 9d771df876d3ac7032b0e310b529f6d7c4abb1e812ce7803c95fb7a96c2b9821
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwf3a.mpg 7a4431976ea5ca78b42fe02035e0425b38c5b17f17238cb25c8c3e7390c20ef3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwfzn.mpg 0590ec546dcdc4907221072f01c7372befe971436021493986ec3b780390857e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwl4n.mpg 0ded33036ba67696e8a48f865b81e8b5231ec9ffa5e96a6b88edeea4e154e278
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwl5s.mpg ebca6f181f0d6565bccaafbacf68690a3a3d454b4778c3e86947c59c72592b64
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwl6p.mpg d1f53cd1303151a78c3ecb08ee2376feb32b57b563621649e76c514d1931e4d0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwl7a.mpg 48938209cc0b0af798c32feb28feda2f2c052657885b96b666a83d443ce585dd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwr8n.mpg 51e442fd90d3d916ab42b59bb5d4b7a2c68c1a133775da28c6052a77b8b6a010
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwr9s.mpg 4316f2228355b75bba0e3a9b9b1aee026bbb1f13a73fcd466dd26c0b3582fd87
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrws1a.mpg 13caf5c3609737551045655da75348b8dcfd1a4314aac76f6f4154d536f4b48c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwszp.mpg 63ed4c3f6494127389c3e0c57dd4e8b6b42e83a56980f63f1fbde2e2f1b2ac03
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwz2n.mpg b3e380f475586d34d37e7b5b85e02005f9beccea8b656bdbb6eb0c0f8fa88c0b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwz3s.mpg 4e4cf82dc5d069cd02b2ec2b528402fc3e861638d42ac7b357f2b0d9b70de9c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwz4p.mpg 1b5174f6e1d7af4d04250f50c3779b9f9b822ac4e8a7d0aa1d4b5bc6cf0d09e4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lrwz5a.mpg 1a7e8ca5c3d09e1d2f841e5d03270eeb9626db8372d0ca496c1fc79b438200e3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwae8n.mpg d0712e3a34e7051e5cebe8fe54441f667cccda5634f810442caad0b287ff346a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwae9s.mpg be4e673c8c4d14f97ad0d06b228509987f313de7a986af406767f252b5ccc3bb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwaf1a.mpg 6ed77df9e1fe6ccaf512dfd17216f9851af568c886aa615d740eaf1de3197b64
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwafzp.mpg 62abf4c11d40feb2f7a836632c33ac3a4ff6ccd6e4636ae095d3125d25c37fca
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwal2n.mpg 4a8a522b0fe721710070a708bdff73edf2f76a1610a1d138cf08b7ab226d7cf7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwal3s.mpg 693a76bd5cb6f5e9275c2173c9e9f9b7ab4f7563875d615c47d9c933fed16767
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwal4p.mpg 39aa857e97455a0e583140a047c82d963a2f855f73f7ba11fc64bfcd94ca6ac7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwal5a.mpg f0407b9ae75a2dc2c2b6719d3deeb757f19139dd6cbffd13dc5eae8079bd02a4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwar6n.mpg 3658570d7a01a4a003a8b26204d96f1b4f78592e32bcfe9a261e86d9082616a9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwar7s.mpg 02b4b9585d3935dfd57d7db91a91edb88e044415270c3db1091d34b8cd246cc3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwar8p.mpg 0d309d6901ef65da5bd9bc685761de11fb8bdc3574767cf4bff8b16047375cff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwar9a.mpg a141b756a542045274ba3d5d71474cf3ad98a45c9196a92d6cb7cf2ef1eb1aa4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwaz1s.mpg 0688497ac60ecf98ada8f4045f023730f30e7c7deaf01a50afcaea2d6a09c458
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwaz2p.mpg bee2a0ea61f46e7635bc4f92f584d0ea366754506f1a08871ae43dd6b4895143
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwaz3a.mpg 7b25329c0e47b74d96c4d81221a1a248a4bdcf97a435ac4c7acb2b5713434540
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwazzn.mpg d5837052d70b99f774b9d7c1512e3fe7b89fbd00387d043cdabf2de015711d80
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbf2n.mpg 9a8f5e5cdf1b4c3e654ee769a62829284b2ee081b7441e92ab6227a222dfe4f4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbf3s.mpg 86f0b920ef0c7202d1c64f671314153219e860d2629755ab0b23c41222db16db
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbf4p.mpg 21370deac29aaea89646c39a422361d93b76faba48b2eff9f69190183db48ea9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbf5a.mpg 26f7345bd92acb8f54f444913e9d12d8adb908f21d1a3b1f24523854228e1c60
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbl6n.mpg 62418d0f5f931a0f0969ef4f0e7a51aa9b6c390466da31a900a09d9e2851ccc1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbl7s.mpg 5ae7744bd2f62a4227d39a1b7bd5843471241f22de8b2565ca3dde49fddd1858
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbl8p.mpg ac31ef52a59bcd580e231486302d353023b89d808fac0cb1b0a6660fff270b2a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbl9a.mpg 41ce856821fdac4d22878db1bff3faf221f15917e3c970519cc416747b2ceee1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbs1s.mpg 9b36c8983a0f62b6d730049e57e0c587b6ab9b115a1c04807cfe67f718f395e9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbs2p.mpg ab49387d9812ae43ac4011d9f63c8ef8796345066c0394782040523799b4d135
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbs3a.mpg c498941354d41bb93f4c4d3ad22693592deb273b0b280e89ca790febc1702e52
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbszn.mpg 50763236e58c394796419a65e2a22825258ad8aded4463a8c2c21ec89b16a14a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbz4n.mpg 93ab63cf5767cbf41e6eefcce9e3f6fcffa04fc3ace4d4a9def03a3f57713d9e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbz5s.mpg 5afaa9c9fa26a0f6bb8f3a2a2120a664d1adb2d279201197b4ffc33166f719b0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbz6p.mpg 94b0d4aaf47428b8cf643a1916bd5e56e73ebf89164c089cbdf256cbd21c8704
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwbz7a.mpg f5f4fcc71f49e0b4f9fb402dea1e3124791daf2e94670663eaec1329a1359795
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwie4n.mpg 3a62f023f04c676d9a753fdd0b97b8fb75a3c4b0157d5b6827c02f486e8ef051
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwie5s.mpg 20e0d06e3b2f2524e3bf322c2a35d56933145be3d1c5396f5d4e5b340dc1a68f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwie6p.mpg a94b5b8c4acbd93adbbb351beb103ec31d97de9ffd34a8c0fadc8047ad8e2dda
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwie7a.mpg 7f589dd1cd9ba23f92d48ee3c44e8a7b73d3bb08c3a6dbe454790b7cb3b75cf7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwik8n.mpg ad77d07c65cfd7b44c5b5d906a10e072913f683306082188ac1fac0467b3c8dd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwik9s.mpg 3e5da02054ba5b24005a0e039713ac815f32b6f7d517ba21c9fd1332fd8fc3ef
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwil1a.mpg 5b2ddb0cb160e4cad231ea6c13bf7fb3962018d44428b3ea83950f6a65b81660
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwilzp.mpg 0e51a7962c45fac76fe18174bf959ccc74b8bcc37d3707db2ad62f28630286ce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwir2n.mpg 3fde03911fb3a4129441a0e1a8dd2e88349bfbe679050706b43d72510176822a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwir3s.mpg 8b378a7a0709346068110fb522cda9fe8458c71162847c50b20b8b0ad2dd0050
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwir4p.mpg fb448bfb01f6a3b1cafa5b1b1e22b8bec8657741e8b605a9b386bf8193c44a09
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwir5a.mpg 98c746d8f04af9c4a1ba3be45b52fcc011153999a28da4ea7c91a6a9c7cd583e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwiy6n.mpg 876a4fd93528f24a1b106138511343ba88ee4efcdf9e539c4bc6aa6c0f24e863
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwiy7s.mpg 962c8c19f65af1a267bb30b51ca71d35d1ced4dd197853a1ae711bfd1d6d4c30
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwiy8p.mpg 05b281780bd37d6f108d14a4af1c4ea1741a84e38d448418880ffe5bd7d48915
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwiy9a.mpg a827aeaaf6c952f4ef7780d8c6f35d1da0115ee8cb4d7ed89203db05faa119ab
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwf6n.mpg a106d20f9269f96e6fcf6bb2ff6ca1203492c69964f8d3b42219eecf67ac3563
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwf7s.mpg 7f96e232555a19595bd7d21c48f969e82c8acd9149d5ebc3496a0fde660cf450
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwf8p.mpg d9f36aec2920aafc5cc9d797b2680a42956ae9bd47850c0fb418f6a1f6f58721
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwf9a.mpg 0a8d91043d79deb6f17d88b684caaaa016ef829132bc7d8e760c64ec01345a0b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwm1s.mpg da543763e7e29317387b9bd91536fbb80f882c8e7710bf176f5b44965ff8659e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwm2p.mpg 8d645a35d3f29d89544454ceed4a6790653eb92c7f60500689862e4705f6829f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwm3a.mpg 3175e724ba432f4001efa74823b1bb43b52cd1bd3ab7a26b6906e73ca45cab14
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwmzn.mpg 0e95c1f72126c4b106f696878ee33dfcd48effa3ad442a00727772887970d998
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwws4n.mpg 6aa310c8189e1a724ca97d5d98f807acea950e226ce051f7f5528f15eb605b2d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwws5s.mpg 7f35abf48fdc24dc817f97c46eca3fde8528ce1fdd999f6e91f7a94c4690ae95
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwws6p.mpg 9beb151bf9e75f7b1c2d7df4253782002ebda1d379f766f9575b9a7629cc01aa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwws7a.mpg ea761b6407250fbeaf31f7fd86eacbee3f8127790799ef9bf82ff5c48475d00f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwz8n.mpg f4ac181e93f40f19dd215f285205643edea77a62671c27d95a2f45f3bfe3720c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/lwwz9s.mpg 146dd61580af2aa94a4470a10c74fc12967e45626040f3033d2403f14aaeb969
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbac1s.mpg c5c4e488d7c4d768ce176f7b546f8ebe1a552e708945b4380702306418a5c07d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbac2p.mpg fabb04b1fe1cd737a31b04a36e8ebb92dd70fe087f11b2ec116b85d9fac6669c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbac3a.mpg 5c9f3be2b67f8156fa66c61752b206c2c8bd6ae4ec3dc81c4d9b8a236888d787
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbaczn.mpg e71ecf4934caca2863e8ed5a68b32567760664a669e7974b0e9124413a9e1b69
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbai4n.mpg 739e5793d930387201147a2df959de0185f7e2eb29e6bb825370dd8cb6ebbb1c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbai5s.mpg 42788eedfbf2a707c325d598a7fb0fc13272006b5ebf7fb4147920b3cf29290f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbai6p.mpg a4adbcf41262ab5a6d5bb8e921cb92079e5702d8558259527f49fa71901e9c5f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbai7a.mpg 2cf6c443140e5173962ad982671afcbe460f75b8fc66dcd9113834219a320a8e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbao8n.mpg 9d4fa476993257353a87ceaeb1183764297f2a5735f553e19345daccf684e483
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbao9s.mpg d8fa74cf1119489ed7d1a4839a76d085e53749cce7f438d0734df0b3d75abb77
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbap1a.mpg a8a19efb93665bb0d141c7977fe0e4d1d49055e06cf099e111588e044a555355
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbapzp.mpg 77999f818f33a7bedf9168de0bca598ac79837213ae465ad4f30050a4ea22ffc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbav2n.mpg 6c89a3cdf1fe455c16d581c88b7d0038fe33930bb8a0f1c5d727a888df2e116d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbav3s.mpg 28d479519f02a2d7f708cb632a32a1a274f8b49426929ecaac613b5c72f39860
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbav4p.mpg 83e15579e138259ede85e485aa8668ca03435d75dcad6cd6802b2c32398264b5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbav5a.mpg ced63686f6d9410834cec27bfd96780bbced103fbec0b26bea50a422aec13bab
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbc4n.mpg 8e99494fd81a2dc1513e74dc7a4248dec3ea6096645d7a5167cb01ab6125bce4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbc5s.mpg ed7713eacb70b191c4d941654a050b48dab8cb3ac6439bd30b8f35c44ec7ce68
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbc6p.mpg 5ea1587a55fc6faa76e3aee359d694d0eb3ee528bdb681aa9d942cf2dd9c39d2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbc7a.mpg 751dddaea6d4f01a5982cb420eb2ff8868bf8284ce415a5d8fc2df915b9ad002
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbi8n.mpg 9fe3e49a26795f5217b40f554ad7090f796e59b1d53a9ad9f0a666749e67c693
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbi9s.mpg 4e415a77a75546788606d5b4e1e79a677d02a4b4fc2f09f01b44bcf8ee446a89
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbj1a.mpg d00e7b8180ebf537e58184a0e2093e0a558e30cb65a7cd390d1de95032815604
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbjzp.mpg 97b7c4b4e0049a640763aac111a7f1ab2df8a51e49ebbc5aa67a4c777b9f71dd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbp2n.mpg 0691bd77ab5ee17f466d8f6d7b9aa45ff3780593d1900ec5806cc60a6fff7526
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbp3s.mpg b9c139bf4c13a02e364d97add4f94d4e81447bcff2d6f62722c84a29940c6247
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbp4p.mpg 60d3bad2f000f388a7e40f8442ba8453c745c6fc8fd0320cb0a234c818ba3ae6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbp5a.mpg 7107973aca0182afe90de2d2c9b48a0fa73cd49853e86e1241dcd09bac8ff4bd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbv6n.mpg 5f44c569f729a7bf54d08b4438780021f384ff742ade19be2a69db06d11bed6f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbv7s.mpg b7b502582968b4c98d4300f2911bedd85f0e9f9a696798a0d778c6915be3be8c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbv8p.mpg 5affe3d2fe0a0d3172cf36ce63b2a7e5a2adfc8ccd9298ee2e9a6b1cf4eb27a6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbbv9a.mpg 1ce4a13df61a6228e88e5135c4d041cb7c3e7071423bb74cac1dcdddea279f61
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbib6n.mpg 67d2513b4814a30527946b394183f9b7126938fb3f86f402de6db4e51d199bab
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbib7s.mpg d53cc0a41099b47b933db98e4b07d7ed2607277670cc1326abd3ef284795f2ad
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbib8p.mpg cc7d8984335e2c40903c8746f9f24f31b4141c15d8fa9175dc9e0ab206dccf60
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbib9a.mpg 250ab9949c7a368e0b8ebe566ef6b8d0ec215998b18c344c49f63e550fcd6a74
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbii1s.mpg 53427b3435b72b17522e8a097865654f64198d6cd4517e0cee446466384c1809
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbii2p.mpg 1438cb57bbe2876906c0964fe1c1be1271dabd366bb11cb2e9cfe17e9c485cc0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbii3a.mpg 6569cbcfe438ab64350a6331a334c592d58e7502565ab97cd8d7db526e19f878
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbiizn.mpg 0546cc3edf85d9f6090a6927c4aec3c32af7fed70ad92e9a9a708f25e54e13ac
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbio4n.mpg 0066c31faa9a1b895493a872ebd769a4ceda881f09fa799e80741745e2e5cac3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbio5s.mpg 49fa5e78322a3d5c09d118fd4d2646a3eca4246f22773711b92c8979de4a7fdc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbio6p.mpg be710674a743e45719d935cf3d65a914dc57c88970aa39654636af7b028b54e0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbio7a.mpg e64800e8c89f0daa08cde2639e8e3b906ac100bbdf2a0fc697fc31cd115aa83c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbiu8n.mpg 3fbfcc913319546228c4ddb4b13bff8616b62a5344a9d000bac06a540cffe3b5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbiu9s.mpg 004f1170bf70f9f0f61e8e7d5c6a4066a00947bbaed89be498b78c962e16585d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbiv1a.mpg ea66e933f32ca081e85c8051380faac152aea5bc05024cf6ae9873f4d55e5a1c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbivzp.mpg 47bf52d6bbfa88d0c24a034f9a32d4471c4422a71c9706ce89ff9df006fb3e72
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwc8n.mpg 35844a28435e21ac6b17095f8d8dc8e24255debf2be4faea6e3d9b0189ec8f4b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwc9s.mpg 645d0a457c1b3d8a96f3f83fff54877a935a93f67a1b287cb12a53e9c92a12d0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwd1a.mpg bd7d171d234beb5e0727a497f6f6720ed830f80a9dad44c5b936af362d89e703
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwdzp.mpg 7db3fe48fa01fa2edd10bf8952de07458ce1b70c4a381189d69f3f896935c3db
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwj2n.mpg 7f8c62983740aadcf704d9fdf10fda46407c01bedac2aa25f21a9e2c351bd74d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwj3s.mpg 650d9acce456f6b0ca500cf0d9d77e84206c9e28bbae4112e2e5da80749d7e22
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwj4p.mpg 049d358aed850d32c04cec86c65fd25a47c70a7fadba98be46bbebfeae328f28
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwj5a.mpg f10cdda33816d146eb36db8c46dbdf710de4594f4d600741993928a450f68abe
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwp6n.mpg 6df1ba0ddb83de6b375745a4e517c4ccfe32fcad88c1d86b21b6a482828254e5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwp7s.mpg 10c80a11b6d9a4f4c7d4f4f8f3ca1f22ab6b36bc16d57d30df148494783d10b4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwp8p.mpg f8d549b3e4ee6fad1f19fcb28bd89e00a19bc835bcd5865e2fc259c7c5fab170
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwp9a.mpg ff33e67a4547d86bf94e9bc5d41a125aa024bfedbbf5ed94686451450d0a9522
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwx1s.mpg ff4940b8b32117c7fa0e86b97f7b2fa57093eddeff0832e2a66975a62851066b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwx2p.mpg e56fd77e984c38d04aa3ad89e8a75927e19c2609a64947128b02344e262196ed
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwx3a.mpg cda41b945be39651b52e1516df03edd8b2044e2f19c8e018fb4c0a9cdced8f01
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pbwxzn.mpg 6b292b134f4d4e2e5ce9086438935be9e5795351e09cfb08c40fd9e97733b8b3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgad8n.mpg d0ac44e7ec3fe17212b0ab33c65091489dae0c98d759382cadd835aea9a23297
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgad9s.mpg d20fbf469814d7cda9f14515dc631bbfb05041648f4d1cdcc038729f4db0cfe8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgae1a.mpg 87cfa247ad22fbdfe9a8ba6f5eefebca05f4afb728044d05846d90aa45887efd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgaezp.mpg b4f1ecf8b572683eb8ca34044382147ef151c3d72f0a9192c920a22eb19d1a2a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgak2n.mpg d4346eb9c4ae6501f16fe2cd0219504397ab552b8512dbcc65bfb98e3af91f59
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgak3s.mpg 2abb0d09968cb7b7a5473ecfe8619bd10e07eab6e6c81b1d1b178edb6028bd23
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgak4p.mpg 5d6003f0668408b1ac3eadd7c878430dd7311f52b0bb4ecba67df9cea35f7d9f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgak5a.mpg 8d6211e4c7940d004cfe3ef384a97266bec58956505b0e53b36e2aafdf7bebfd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgaq6n.mpg 4cf511100e4491e13e56208828d70b8ed3ef04d6345a0bf7fa6d97f57501a8b3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgaq7s.mpg 90561c00b7d65ce8769f960b9abac25c732e42d8bc654f635b4c79b48a3ff170
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgaq8p.mpg 354a904b733683f6942088012a39b8108f120065b27639985840f4326e46659b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgaq9a.mpg ce8fb4a02db4c3e3736e1035e21f26aef4a02bbcbcac346b3c0c271bcdbd8979
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgay1s.mpg 3e5e97fbbedf20432775e3bffe8e169a83bde9d8a3026243b52a1b0f2edcf362
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgay2p.mpg f5ee40054649ce073f60882622cdced23151658446e462b444bbc0b0a069367f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgay3a.mpg 5d6945799f4b9799adff02f0d7f9e0ef248b755bde128e30bf32e5d8dca02f61
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgayzn.mpg b79d105d1eb3292ceb9d26b93125e05d0b418c2b616d27a17e0399757ad0592b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbe2n.mpg 32e88c083a93e41cd86fbda19074d2fa1de12f483ad63af130134e03a59ca151
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbe3s.mpg 89aae851d3b76353c182aee9f1bdf34951ee344f1b117805a9d699bf7e1ea489
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbe4p.mpg 56ed1a518771498e1ff8cc31db42fd926579e78edc38bf26adaa202b761c6d9c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbe5a.mpg 60ae46a22b879d53fd997a4908d8ca5a04f577f4a3c1ea1f4283e200138fec3f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbk6n.mpg 8e829d8169ebce8e23f7346e9d9ffea3b9c5b98fb33080a480bfe4eb43d4ed9b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbk7s.mpg e14705fa38f7268e0229f282ccb62231fad7b3a296b2a96b40af345ca7d20543
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbk8p.mpg 35f7cc435fa203dabcd18c46903109d6cf11cafc44c9784a963b4b610882a53d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbk9a.mpg 9327909ad162f6a0db5792064e30679dfc42352895d31f840f7f3a361534f588
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbr1s.mpg 2da84dd4208d929386ffd41181cd2df5f0de76426305bfea467faa3f293e20c0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbr2p.mpg 9cf00b41001357de546dcf20c7014e7f7a0fb7a7f507aafdff7bb0c2444232fc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbr3a.mpg 1a3b605955d18c1aae10b37c9d8fe0d1ecae7bea8931fe37cb57a25f16ecb028
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgbrzn.mpg 7d835970c125e37cd85189625ee3c89249c786ffe7c2ee1f90c4962a42a30f55
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgby4n.mpg bc87a0d2db55f2904471c0e7eff6a13d13470edd49f7ec8fe585fc00597047a7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgby5s.mpg 3af6960ce247c0461594d4f59e44e1db5798c06bab59acf8c463b44824c79329
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgby6p.mpg ef3d4ab3d16e4a09c6c644af8b740f5c07b13cc2869eb355481b748a9b8355a8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgby7a.mpg 808a2438bec1d33e3207657b0b2b8aaca73b25eb7e13fe0e6ca411ac043539b0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgid4n.mpg f89af4ab6ed8e6b10ca0d0565e5e0c697576f730929697a98ca4ee7826288e03
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgid5s.mpg 6b99ae0dbc1272e7b5fd1130f5d6effedbb2efdfe9c80f546efc95382e702044
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgid6p.mpg 8a33de683f2639cafbed2e1b2692371c03e2d428896300ba392c570600eea3c6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgid7a.mpg bf84e0635fae7b17b2e39b2be3da34c6bc933e65c4427535afcea1cfa0f1e367
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgij8n.mpg 338b80e00dfe902b72b2d8c1e38d8076d5b06e422b029508e0fc0beee1ac9142
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgij9s.mpg 11eb08412405b4a3220a797086db0bb90e35a13c0a13dc2d3e217d495441c096
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgik1a.mpg 9077bbd678ce3ec1a97237e816e478ce48387490c886223b6daa898e771370da
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgikzp.mpg 130ba00f3382597cd64064a51e5244f062f3c87cdea6d38c7d346ef585ae3534
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgiq2n.mpg 2c81a4d41f542e5ed7e39d61d4a1e3ef61668dab38eb61d56c13bc7833c52e25
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgiq3s.mpg ee4f9dd3e901ba906496a6a86a5a1d1e55867496cd0677a9cf45d47889256083
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgiq4p.mpg b8af5c2ae6e80d1e97887b39d6401b6e097b05d822458dfe7e1ff64b8669640b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgiq5a.mpg 1b00d81db3d5b2dbd5d716c5e84bc6f99716c760f16d1f9ced137cc58b7d99bc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgix6n.mpg 04733b7fd0ce9d36e1d9ed68427a501c4ca6e3c2baf30dfbf12c2ff935cae709
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgix7s.mpg 6586d8755f53d91210b78181f566e8551571ee8aed20f4fb00e447d8f5b099fe
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgix8p.mpg 27d0903569c75007b3fbb0b8dcfea0a8169fd8cb1b7c04fe813f9bdc8b1a8cc2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgix9a.mpg 36c0650db2ed73f6d7b181698341a8c35d2c481a928fe20a56e12dc386291c1b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwe6n.mpg f05405e6a8424999ba8b45252dc744e4ec6054cd2161ff24d3df8c3494f6ff47
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwe7s.mpg 0456119d865ac7a7dda0423bec9a82de281959f479c87af8e00fc240fba0bf9e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwe8p.mpg 86f1f074d19f1847617fddd716a06f2b865bea0436a94b4cdf1270d17ac00410
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwe9a.mpg df63198de83d37055532a8ebe9f6eadb79184d58aaed060c408f53446ed72e23
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwl1s.mpg c202bc7190310803d097f656583583bdddb40d94143ec89b2d1341fe0772d5fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwl2p.mpg e9896af13de0bc4e5842cea38210e9a6b2ff7588bf1aacebc394858fc179a5c5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwl3a.mpg 984df5dc4ca2f575da539f6c90a62fd43853619972ff01aff2b40828b736ed24
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwlzn.mpg e3502d3bcebea44b80a80748365d849747f3a14abf5810f6bfaf008d26a46f17
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwr4n.mpg 784d05427e3612310414041a43f028a2e4f857a6a567334834d611f8e46863d1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwr5s.mpg 7ba103e1ef10ef9425af1b27411bbd8da52d861800adbd6d1e1416c27332e256
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwr6p.mpg 13441ba4d45f72f403ea69777593b04f41474446a2d5e5f775fea3b7b53b9f1d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwr7a.mpg ec02ee509eac2ecb01936adc55bbc8c0ec66ef742dd7cdcf4b4f59e3720cb306
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwy8n.mpg 33e9621dd7b63d5df1fe3dbf6dfff40c19aeacf39a0bf6f5d0d5c59ceeaf55b4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwy9s.mpg 4492a2f0ef5c917352ecf604d4305e5461f6a432714876a50da0386c143402c1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwz1a.mpg 934bc5148dc797a2d0393abc29c795892eb8d13885e738fdeaad3800594fa0a9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pgwzzp.mpg 519e9b23ee59725bb0c02c9297a05a8a0ef9ee4c8aa7535b46af69b2b939baee
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prac6n.mpg 137f0ce3dfe249da11c424f259d8a89b81a7de7f71e1cbaed04e2ff2d7939eb5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prac7s.mpg b915367a968b1bd4d3e9f6d1cf1dad3abfb4763091bdd58b18e184025ccf7ca4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prac8p.mpg 287fd4f433dc462120c4a0dd20a4ad06d00681c845c59126806097bf251e4e53
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prac9a.mpg f36246efda3caab239f6e91546c2b1716a4d2481f73357385e92b988e6bb1569
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/praj1s.mpg f29570eb3ef0eb2bc7ccd167cafe0ba2766b102ca19e55eea8b07fde6b409b51
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/praj2p.mpg 774ed8d9110daed407cdf3bf3e9d20f5ba540b8683c955a9e4decaf3c4bf4b54
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/praj3a.mpg e88c7fd0d626e65f7303fc3d65cc87b708128345745060a1fce71bfb217ac052
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prajzn.mpg 39a3f1ad9493f4ebf43ccbdd19df29964f57d8da3b7721a6f7ad7ac9d49934c7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prap4n.mpg 4c52de64a84159acc7c76ee568e1e21637c5a30ae262ef4d6b201aa2fd824494
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prap5s.mpg 84fa1fbf844dbfd726512c648d40b4fa12519ffbc71bedda9bae90369d149792
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prap6p.mpg d270467329254cfc0145dd8a97729859b8f4cfb31970eb2bc24cda2d52b66129
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prap7a.mpg faf18f1880aea253a9937f33a4a485d94aba6dcddebfc3c76c1d1c75bda4b618
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prav8n.mpg fca3d288bff3647debcec747272f85ceb22aee5479c6d675d19b930cb11d820d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prav9s.mpg 7d9e9db49a35776320e359db2ce3c07aef8bfd39c8d996423499590b50490e2c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prax1a.mpg 086045ef6da6b80d3b71962e2b5434739d431a1183d863e687fb3f01f26502e0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/praxzp.mpg 5eb43c002532a8156a33b518111859822cc64b2283966076846ca67980731900
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbd1s.mpg d98e9d38b2505ddb55c7f809c9c79040656fed164b16b10a99ba170e92478df7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbd2p.mpg 755401bf99ddcae55f89133a4c66814cd4f9d9050eac1cd76494329f8ba8efc8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbd3a.mpg 689587cda335244118429563fb796cef2aabae5c505f74e76125938b3b7113e4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbdzn.mpg a0c9fcf8fe091820b726de50e13a4180b84ba1d14cb796cdc528e2c84dc82873
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbj4n.mpg 89f82f918d9c4e2d212eae09646222423897a930160d8ad78cf751c72efd307f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbj5s.mpg 257de27966709c838e7a19fcd6eeb890c0c6ee875951bfc89ff60b1b386b6aa1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbj6p.mpg 2c8a2f6647316ef3ea2ac3a06ef3b65c5550e00b1d6a9dcfc524bf28392c7336
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbj7a.mpg a5b184144d503fe02a994086b0ba12b119e7d7f2a3f465b0a62690d11e66bcb6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbp8n.mpg b6655a235d65480559948baee3da3d120984ed4900f5fd80bd5af90accdfd49a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbp9s.mpg 23db2efe40c0997af85a196358dad14f268b8fddfaf6c9d7cfa238554cbcd616
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbq1a.mpg 712d84b3cdcd246e03951f9c8862a179b1597bd8d8e806427bfcc474b53b68f4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbqzp.mpg a63297505a837cc5f7add49afd3e8fa70bc79d364508793f67dec985f9b705c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbx2n.mpg 152c0688aca1e278ad6b32382241d9853f4d1e70e8c90e6c570796947ba5f02f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbx3s.mpg d716fd0ea97e0196c4af49acd68f7c68a1496cfaae68506696d9b117e0170897
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbx4p.mpg d1176aecd6add33174a71fa88ec3becbdfdb7f9e6ebb8ca20021a1a9729b5039
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prbx5a.mpg ffac7519a4d31cae61a3386c230764b1c54f0c68a8f290943d6e5cdfe870f135
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pric2n.mpg d429f452b761831d56d9a9b4667870da2826dc72ddaf56ed9ebbd7017d060df7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pric3s.mpg e70174b97949c429e276238170f8f9b70cbe35805ecc733798d85f3352fbdeed
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pric4p.mpg 8a9c6b9ed0d9acf3e8733fa0101707af060ee46b3f0a55463c8a0a99f5527243
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pric5a.mpg a18347ea4e89dd171380a35da0a1c4215d7f4d957790787ee6b1aca2d8ca9ce4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prii6n.mpg d46a07136cd0adac68a3732860b626580338d42cdaabeff43a159471755835e2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prii7s.mpg de7a945d48cb9c6760f5e357a33af54d96ae1a9b358600efebd6b8426a77da4d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prii8p.mpg 14560c7b3a7f2986f114a5bbef6cf9f1188156a20cefbe1db7a5b62035c93b1e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prii9a.mpg 36e5c632553ae8335884c204b97f1ee80b7914fcce72f4394e1e51c4254fa67d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prip1s.mpg 84466e3d537de70b63ea7544969600d1225ab609794b7dbaaf045faa5fe3a9ce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prip2p.mpg 4be1784bbebd5b8d32d60771d62460edddd2c766dea43e10bc46d064fcce3228
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prip3a.mpg 38fc2ee41c10eacf3b7aab193f14aadc1ad9bfc347b649424a22e9747fcd92ec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pripzn.mpg a990be5cbe2a349bdddab35342094ba722d8d966a8dffb8703e3070759340db5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/priv4n.mpg 6b36bb0df243ed88e61227e2020c536abdb5fb21ee178b4b08fb3d846f699103
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/priv5s.mpg b04e8bf790a949943dcb532cf4653fd93e3f5d082ca2eca94f4eb61c8cb9f6ff
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/priv6p.mpg 09842a6c354438634ed8a30d344c5061b502d4d4691b43898d1cce2f6d7c233d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/priv7a.mpg 03857ace475a69947508b847284c4bf677eee792709cff52b5fd679c11a9bbae
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwd4n.mpg f1321ee0178b2cb08a8aaa2c341dc9b619d73de7e7a935a42f52b83ba7274e20
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwd5s.mpg cf51167a3c0517b16f09ff0951fad0901f441980a8ef175502f66a5038ac4747
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwd6p.mpg 579140bbb31563622e1a491e41857428e76d65e88409adb508b5a0592c30d850
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwd7a.mpg 60dd639afc50ea0c00bfcb795083171576c4a1001df7380896777008ba560667
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwj8n.mpg 473776e3b7be75be39950284d579243afe032a37df96db90cda8bd8862c29922
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwj9s.mpg c186a23ee5ee1a13cff4a84ca63817c59c85aab718f7269667b64f9f79ce3154
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwk1a.mpg a9e361f4e323b8c02232a49e60f9304c163d4301df6fbd36317af1fe54f48e38
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwkzp.mpg 7f05a4af37587e1193d20dc83936fe23f2b8f9db805c4c9b826eb54cabffac45
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwq2n.mpg 76e1665fdcaf42e8ab12e29d0cd92153eeb1d86603deb6d47f69ca30cbd9c55f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwq3s.mpg 11c3ea28f236b706ebb4ea24e68bc9bd3991b8cf8f9948815f89c02c54900ef6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwq4p.mpg eb30a1eaf0f5d79e1a0148ddf11ea197680c52c47ac9e5df24b26e88d6b0c376
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwq5a.mpg 6e30ddc911d09bacf6c2089a4cea6335ec988705e29fe2071badc4ff0bbad805
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwx6n.mpg cd717ca8740c724b4c53cbd5de01f52ed589cf9e07d50caea3d3bee36ae42dc2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwx7s.mpg 7286112166a768614033dd186d4c9f7ccfbb93b4279573e0141e43770f10e084
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwx8p.mpg 1e2d2107ae56b4e95e281c377ff0498fa613c6c294c0613128ca50c5d5291fa2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/prwx9a.mpg 916a2304d1b00f2a72dd7a46b76e71ae0db3d06039f8fde4ac8d91588f8ed643
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwad2n.mpg fdec3e6d0892547bc405c461b219a50d41aa6b3bc542e36036a4a7715b054c7f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwad3s.mpg aa4efab35d4b20a5ba28483b9f5b1d99f6b26ff2022895c1c3cbf192bd438e38
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwad4p.mpg c7467e1bcc843a6e8bd4c6eee340b700d57aede914b8cdc5ce6cbac7d9f8d73a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwad5a.mpg 679d59b7d8878479e48d1e3ccacc10161975cee4a2ec322d496eb65f524d6693
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaj6n.mpg a49871aaa516dcd3a265e859558cb3af863fc88fdd6849580cf4097c91b493af
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaj7s.mpg 15205cbfabd3eee87509d63f6a915c0fba3620ec3a4db52c6dedecf4b1bb89b8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaj8p.mpg 718038a4bd1b521a6d5ff6912c5bb88d2a0a28d5eb9475f0b302d0f4302c608a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaj9a.mpg 48b6b8d4aed6fa136f7d395c5ef82a4738e3348b01b182e938378163f2675ee2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaq1s.mpg ec2c0936f3e6e3c5b495c5288c9745a7d2072e88f0d9da7e3152f5e46afb5b13
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaq2p.mpg 1dab7bbb6abe888a276c2e7b0d3cb77f4562f231e48744fe4a37d598d346bd43
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaq3a.mpg 6fe5d14f7c1d2102ded1a23b7d5750d5b0973a08b3c6aeb7f4e34d983123a396
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwaqzn.mpg 6c6584aa5468d36f45cbb414c81653a4df868b48eeedfd31b1c5ad4def956853
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwax4n.mpg 3c280006f234ef31107c60fd61d63b834f8f399b60b392fa4a27ad1afedc29ef
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwax5s.mpg 631c7713e5a9d2f46a80f9bc14b282235e05becfb122cddabb29638fa274b954
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwax6p.mpg 4a97e1dd4c4bf5f0c8630d9faa55e0379e5c3ad86ea972a69d5fd4a0f68e060f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwax7a.mpg ef92016a4f7523b3a61ebee30fefeec372d5f029e6e99c98c514ace63a7b6fbd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbd6n.mpg 076a9751ec5ccebedb47b5fddcccf1227e5a5d614b367cef977fa1b6aae5485e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbd7s.mpg dacc09a7de70ba0d77970f8c60bc87494d628e282e81f02880463f9f4ecb98e2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbd8p.mpg 56c0b71d880d8db547641fded72771180db37ed595fc142e6a772ca9071aaaa9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbd9a.mpg a71ec64938dd6d83bf7b4c3e456267cdbb25e0b8b4f2068fe634cf6f1781a03b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbk1s.mpg 70d9a7df9774951703da28f773d0add071cff9b1c6d9e7ef6f5658d1575a4477
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbk2p.mpg 2873031b35a9e3e57864495cc3fdf5d8c565c12a9bc2d300f4a3c4534a73ff7d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbk3a.mpg 9cd921f0909c012d1141480081a5f81a633b0001fc7085279d3264b02143fc7f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbkzn.mpg 4eed5f5ab6b72aafac4330a83f8e288c0e54f604c98e83ef99a6bbef04553655
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbq4n.mpg be88f964383ec2c6d61baf97956a7b34bffea8814eabe620be43c898fa5ba385
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbq5s.mpg f7df1c5e36187a58b9085e565542d1fd8468aae0f3f81d1589e85c34be3bafbf
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbq6p.mpg c4ee391abf5c8e2ba4b1b9102e430daa6370678d7116f9be4f2c9f05b1329155
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbq7a.mpg 12334dc48d4a3956390f226e864870f545bceefa4c8e40d34f6fa27d94b79a80
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbx8n.mpg 1fe227458f0fa327f00090b1a69cfd677cd4981c554857b17ee439c119cc54d6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbx9s.mpg e55587e76a6cad03aa47ad339a57c63345b9fd6e99a283bb9c7b50fb8c886ebb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwby1a.mpg 6034783948fd39da42af0fe9be6645629b805c804efc465cd6145c96aa12d5f1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwbyzp.mpg cd7c1bf49db8f689c53c65799afc5e0735d35a4ee5e466eda06a58d851f05840
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwic8n.mpg 1a96012d7bd6a979efe4137003384a17c948dab887f7042c79c4485f46d2a160
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwic9s.mpg 2f3c0e9609e2345554c2fc3dba3fdd9773bd963a1a42c4fb47581e691a041d28
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwid1a.mpg 125e2c64b3090cd06766c5ff5a48cdd92f9509b30f93bcd83199bb94f4419e8b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwidzp.mpg 577e5940776e60b53e5e1f31dec58484e392b7beb46fe7b1ac50920b0207753c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwij2n.mpg 0d14ea404cfeee0890abab4a1659d5e3182c78d607480062c57a465736ed4ae7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwij3s.mpg fe751193668dfbc69065d77e292a66efe8105f53a1b205be6e2d62c5e9e55587
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwij4p.mpg 1910f7a8ba5068db2bba9d7d9860b6ba749d9c43f66e78cef76a215fc4f2759c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwij5a.mpg edcf48c1addd14419c0e77cb8618da58529ab66df5d0f099e1d5cff9c00c275f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwip6n.mpg 561cd92ab72376bd4f3472b58289065d6d428d09c2ac15973bf79d997dfa48ca
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwip7s.mpg fc3b21dea60559c2c7356d7c1ef22aa4e2fe7e91cb34d5992154ecd64114b900
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwip8p.mpg d5102102ca839ce630674bf751a88afac5bea5cdb7ad63a9bcaf9d8cb700a232
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwip9a.mpg 411042ba3b71dbb21af33e913de1de0efe9eb79c56dec8bd1812dab739f7ee41
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwix1s.mpg 12d070f437c81451504918237c7c5c3697aa1fff2be7f2e76186193f4d135e9b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwix2p.mpg 230a11926efd27b812009e6da8944444371e31f6b9264c5aaa250ac4b8427549
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwix3a.mpg 04c38ba4383dee7b172084cdd4c9e01d6861f7b9449583a0047b3cbb47314a3c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwixzn.mpg 4070b66f8e715965044fee9bb02eda95e81576301b8d22f108dfb6486b008e42
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwe1s.mpg abee1fc2b997d4e30cca7d105b614bcab5295cc32909e8cbc1be65c2c26036c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwe2p.mpg 31fe9c3df470d6f74d91bdcecbb57cee0fdb87ad1356691850212cf8f040112c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwe3a.mpg 91b63dc2c6f1fd842b1666d293fc1b96aaf4563a16ea50f1d21db67c4b11e207
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwezn.mpg 72186784b5f9b974daa8e8a859a948ad88fca7e233ac9e659cdfea07fd81249f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwk4n.mpg b5b6b37190089aef632e5e95015c9d34813edd1a3769a3a9e0699a2c4aa3bbf2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwk5s.mpg 99bac4f8befab4fdc7fd446534bc9993893b2c440608a8c60b1fde1460a72464
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwk6p.mpg a093f43fe29625e7d28a8edb412ec82d0082dfb8ad7b1c2d2e687bd23063a6c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwk7a.mpg bb0a7fb4745fdd881f1f2708e49cbbb1a2fad9a9e5b5769df443de4c840b4762
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwq8n.mpg 9c57be7b544a3e4971d227549a4c75bb776e5a8b088807883625dea150451f45
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwq9s.mpg 7473a84457bec0643a159e2d367a10ab2e40ce43cf676b644a8937524a51aaad
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwr1a.mpg 8c8a1728c79cc238529668ad0e84ffc7c11676cf38a073697e6f1bcdceb0b99d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwrzp.mpg 1004ab86ea3306f5a2c925ae514ecee4f131a0acefd75236c812b0edccf787b0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwy2n.mpg b7481e400975c287b9003f2f6ecc911d2c48151afefab966e49e103c3c68b07f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwy3s.mpg 43d715f50462307d8c2d47bc16d3966677dedec1026f0ab7c52bc440ef3583d9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwy4p.mpg e6f17a3bac39dd5cf63a4c2ac44e673e72b7776fa6a02a9a75c8d761f798b061
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/pwwy5a.mpg 3389db70c6bb1d767d676759e6b4ca199747de2bb26ef30d6e8acc50b648baeb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbaa4n.mpg 973245f605d4b7e575bb5071d09a128c4822f5392d81de27a8cd67d911bd7234
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbaa5s.mpg 9dbc9410636e975d56ade1fe4be5db4900be3eb7681b44dc79dd514f0c533f8c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbaa6p.mpg f061b009574d1b62348cf1e449fb3a247b4d5d1d2c05cc3ea0a149f0ee66fa33
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbaa7a.mpg 9e89ed230115e24b9109ba8b9174ab461ea3c1f1d322a7875134520f2ea5b898
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbag8n.mpg fe6e0fdcb713cf3a4b08cf8998c7277455f8448bba6bad7231d69b545b5e6557
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbag9s.mpg 64b91f544cc088bd4018662682946fc8b5d4a7ddc3ba49a0bed40d7d822edc65
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbah1a.mpg 6c027c69e14375506b978e8dba0b0d92113ebaa6fb099517fdfba72b5812aeae
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbahzp.mpg 1347d30577d059573ee6800c09b473901cab52f1b7a27e6e5078c15de018e775
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sban2n.mpg e3433b47fff03efaff3058c1d0b0ef3a80d5efcfcf2314749fdddd19b5d06a29
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sban3s.mpg 7a0944a8f3d9683691fcf82febfc91a82f02e4abf09d10cb73e48ec5cb38aec6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sban4p.mpg 6ecb207ecb69fd0a178d7dbbf753297ebee0c66111e22a5b69856a6633a9aff4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sban5a.mpg 690bc5541af8b6ab5d0d82d99e82878e6f5591f4bbe58e249f9222a528708c1a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbat6n.mpg 3d84ae09d1e6a7dbe28bab6df8bff06027a30c052972ba066ec76546a5630090
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbat7s.mpg f1e30d24589e9383ebfb0cc27bf05e241bd133727320e7874f572c3b3137b968
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbat8p.mpg ffbba6d57f7674884a3613dc6f9705e21659856a52d2148b86937312c3f76934
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbat9a.mpg e75cb18c2c0773966c2469d149032e0edd771afa56835a990bd3d4d6e8003554
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbba8n.mpg f1151185d59c91c71b159ae241ed0cfb3b034eca5f80408017b2037ee7db6509
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbba9s.mpg 9bc29287111347b727a302da7855cb0bc72a51007a99043492199addf83d79b4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbb1a.mpg 628ef3bc76c8460ad9928275dceaa8ec7e62d2331a33b014ecf42426864f55dc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbbzp.mpg 624c8f6024cda6c6ea2a8fa508aa32ad82373c0cbe5aceae70f9857cac2b9fd3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbh2n.mpg 55e45e2452d066dc930dd3542e07290f38273aa212bbded7f5e56913c1ddab23
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbh3s.mpg 6d0f9cf22a36652aee665c75f3ef12f6c6b32cecdc385756c1356e49312af6f5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbh4p.mpg 6e6541aec729c63633d28b50b88055d2e65cad56a107286b569dd08c9ba33d1f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbh5a.mpg 3908a660208ef1eab0a29a2bbe6538c079d0e049d3777ba7a450e1d83e0ce8aa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbn6n.mpg df02758d62f0bbff945ebe33320d097029fbe964ba28d9bc4e0c9cd7fc2cec51
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbn7s.mpg d9a419583a76684eac427c7b09145242f539af9d6f62d9341285c49ec847e595
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbn8p.mpg 3bb943293d0fbbf8980c32b33ba2fe7506321a13e9fb026a02d2ca22b60daef8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbn9a.mpg 9ada899a66a21a0b452ce6157f7490ccd2553b323c18b9b775f22d645bd625af
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbu1s.mpg a9bc899e87b54f750a30b1ca31860fde5cb850f643972d5333db8c72a727ce18
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbu2p.mpg c742b0d610caab4284fe37cf133eca633e50bd1302a3597f4ec625634af1b3c7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbu3a.mpg f9648b13ce13b0ca96018f33d92ca12ab3a17b9e8d14862787cf2e411cc1c8a4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbbuzn.mpg df8e423a9540ca331a5b91adbdc9ea9e66f7af4c074e2ab8bb971e3c4af40a2a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbia1s.mpg ffb13af2fe801721159d991f8afc36d0a7cfd97eb3954a9866597074c243e8ac
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbia2p.mpg 20a6062e8a4da9765a75613ebea29b96fce7f0755d65e92955efadba4d23f783
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbia3a.mpg 2f7d4122b5a26e6840293f258f534e08d8eb17a57d229c3532a063467c5ee08c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbiazn.mpg 9531cf9b2d96112c8392b441e6f59fe42673a43355cb63993b282a2a3bd1f356
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbig4n.mpg 42edd87b0bc0bed88cb81761ca117f7951fac89f37a7cb49f1f731b5933743d3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbig5s.mpg 95500622b1f703fbbde0108efaa7f6b76c056993fe43726d168c8337949ce136
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbig6p.mpg 78eeedac06ce7e765b456e010ab74fd61ef03599a0f22d26a6d5df2405cfb574
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbig7a.mpg 223f219ec10c2fb38c79c98e1f7c70ed8ded20562d7735359e63275d95e7f6a0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbim8n.mpg 1f7ccaf87d2012ff2b98b2c5d7506a4b7863d8942bd8903ef189a6c2cb383413
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbim9s.mpg 2e4eacd052735ff6d6126ab2f12dfbe2b7a95b0700bc2cd67f1d3cccc287072d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbin1a.mpg c0b89b5cc0e4b945d5612ba9c89143e8bf8634c90fcfb07a53c3ccfe95fb31e9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbinzp.mpg 1694b45435b4a61080814aa78fdbd3105c9af9c6919cca4b9da27268a50915f5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbit2n.mpg 2dbf079989252196e3d1b99c73c2b8c8f197e04809410f2a37b3fbd2fbd33aeb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbit3s.mpg d16b029e6ff9263123180c5aff85aa5ae4651dbe06000049867fdf1ff83ce712
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbit4p.mpg b8da3051447223ad0e6c6284a6727eb024447432c5c1aefdbf07439d3b65cdc9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbit5a.mpg 5ded6c6b1f9b3fa1510d31e251c20c3b92c94e11803bcd29e0abc8d0307e1561
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwb2n.mpg a88b6d662b9b6b8929bb795af79a027d0961a75e9bfa79d629e7faf1b9520dcd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwb3s.mpg ac936af99e02e621083b3510e2b314e2dfa833913135302a47bb9a8899e4d5c0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwb4p.mpg 3cbecf55239d54a1ccb402b6d448e966fbf4f881c28203f36b4cd58458f70d86
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwb5a.mpg 7751c8430899d7693ef9e486bb8798a1b2c61ddf48d21e0c8535dc78f11aef0e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwh6n.mpg 2673cc5ea20d9a261edbfe560ce88513b8d29df23c75261f825d4e247362a332
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwh7s.mpg d59797177f4e36e98103d463c3456ad1f2c008547d1fbf3b319f3f56bfcc5b1c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwh8p.mpg 4f88e9f2b7e94d8ba8874aea82471678869c3182e0cbebeae66ea8acb050dec1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwh9a.mpg 775ba02fa1fbc986a8e04c1adaba10ed15d01d6e525cab0981f2dec3eb799202
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwo1s.mpg 8ae05e79874f634740319b9fb028d97ce176e536f932b718f4ebdb0f378be13f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwo2p.mpg 14b769c6a9bf29fd18d16960784bca4124775986a422a1871dd32243c8e44e86
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwo3a.mpg 03e9f29a9098dd4bd0ac0b9925d2e44d067e6a89611981cabfeea36db7c08ab9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwozn.mpg f2c05bdfd6b43aa7fb51925db2f4a1060a01d2adc5ece20bc3e9846a3af7fa35
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwu4n.mpg 221e9cf33d44a2c7fcca7a9a685de29cbeb6ee6a20b192ff714efc79c07e139a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwu5s.mpg 8c8730fff9b6e0c5d740f1e055143ff4a49c31b6d49d648c96cabfd7d20d3078
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwu6p.mpg e199370c246c6903fe9bc0ea337a95f7b02547faded6b0904bddeb6f2cd698ce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sbwu7a.mpg bbfd62ec902abf9eb8849213e8ef684a3d4ddaf971fd57635679170b821341c7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgac2n.mpg d2b65050fbf5d929cbeed1bd721248c3bd3835192306fce6b716f3578a82d183
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgac3s.mpg ce275a570a170d8daa507e714e266f4ce2a1aa71cd29eb688854d7cb611b07c6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgac4p.mpg 76601fb92c06b595d0248f583533d1c1f9adcf66f9526b2a0386fbd319b6e2f0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgac5a.mpg 13da1bd0dc9eb51d6f9cb00cda15d397a86aaa018795fbc136d9821aa2b4adb7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgai6n.mpg bf570ed6a7a42940bcea96ce9615cfd53adec3347b13c1daa84562f78ace14f5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgai7s.mpg 4e5746a3ccde58368af305fee1ac4323b70e285ebbd9248803d20c48266e1976
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgai8p.mpg 0e62f095361a3ccdfa1a3db248340c5176b12322fd965712f86d73ba918f54f9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgai9a.mpg 048ad7cc08240235be11450adaa4584b4161194176bd20b276fa19f0ff7909ec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgap1s.mpg 766fe51966bb9e57066834379dcb5b6c38d13eb2543041ce64da6ea955a25499
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgap2p.mpg 20aa6239b1ed6fca1709c7381e05f553d9c526fd07b3254452380cb6d860c2f0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgap3a.mpg 29194f4e95e0a3d6333704d27f3537dcf10d0bc2a34899f10295407c927a0182
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgapzn.mpg 8857925aaaa5eec552c3de29bd66bc0cbad4b78c4ad1d56bc6ad0995c434bd4c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgav4n.mpg c518e713a188263e8ba6d048889ac20d877368b8098ce34eb8fda7915b071809
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgav5s.mpg e4334824235b453edf3e3a65686699fabc2b13ec96678f424991f9ec0d7548fa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgav6p.mpg 6fab431fbc598e524c9a4efb353ae825abbed1dea509f78146f32b81c3bbeaef
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgav7a.mpg 7358c717773e312da68a95809ad1f00e1ab487f13a24fffbcd526312c70530a1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbc6n.mpg b2560546fc5ece309e7afa2770b49b58fa35acba15add8ad72fb3c315f75dd01
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbc7s.mpg 1499e95c74b20b8f2b5743b460af9efad1b8d69784b477b7a6f8ba622c3d1641
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbc8p.mpg 73e1418b50229513df68775ff2f0b4a1f63d887e8f8fc6ff346ad695ec4de0b3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbc9a.mpg 0e35fb3e90480d238890765ce2c247bc8d9b2b8564eed00ce398cd2865e8bc70
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbj1s.mpg a1a3c7eb5c2839c715cd38ed57e3a6b4fe0ed9294d0c2b48bc127260ee6b4ec8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbj2p.mpg 27fb7519a5fca19a9fe61a237818fc27fe9bc205fce23fe9506cf3d618ef228d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbj3a.mpg 7fa6c5b773346758988ec756d48d0295143183f6eb6f3bc1374a136713017b4d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbjzn.mpg 4a0195062b9bcfdddc3e4e4a267d0b2a0d022f9b9f84f69f65ca90c4eba9e948
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbp4n.mpg 59a1b1f436d552f95695a4decbdb8c19b602be8c286528f3c44cf89db8a9fdb9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbp5s.mpg ff827ff21db280b0a980ace3beeb380f1cc58f48c0fef45ac463e3fa12abaa95
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbp6p.mpg 16cc6714f2f76c726aa1d3236698e60eaaf3f75fa47acaf135fac47f108a1810
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbp7a.mpg e31201490e91a039afaec70dc2e16dd5c7edc04f9c478a78416d8850cdec15a4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbv8n.mpg b4b12503192420556e1e445866a2444a7e01ab600123b132d6f87d0a3bf3db35
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbv9s.mpg e52dada79e2f821fcb3ccde0e9777640009fa99ac63e74753de3f37ec1857d39
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbx1a.mpg 9bb6559aeda782fc9e3aa89b68eb6892f540e5cf068f23a16cdf5cea2de2082b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgbxzp.mpg 42720c3d689d5ef27b738c8ec78607b86393cb51939ccf2f5e1c9edacce69aa8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgib8n.mpg e1135999b1b41b7d25addf7231d08ed1e624cfb279c276d62742288307a1d80a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgib9s.mpg fdc61271c6e77989544b90c473b5130494ab9f4d5c3ea5b310bc662485863806
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgic1a.mpg e1fb2a3861ef39d7ae2075a04dced7236fae2d2fd545cf8074829274f3913d3a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgiczp.mpg 9368092b5bcd70b492e03827468555c0ec7bece94a4325685450da37ec011885
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgii2n.mpg 15e27c724dde1843456c8a0beac3092e207bd8e574c2436c3977fbc88753e134
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgii3s.mpg 383c916eb85e89de3332d9e5f025e9644986f33ae30312fa5635d15528d4716f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgii4p.mpg c5793e8e706d8e1d79085691cb7b6a9cefd5fc2e81a99dbbc445fc12125bca48
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgii5a.mpg d3111dce67ba274f54ca20bca3f3fbfaa2962bc5e140130e94f464c7afbdd4c8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgio6n.mpg 25cb42eb8c667e9c259fdb2ffd5e50f536aee9a891d1244264dd22da960105ec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgio7s.mpg 025c89c4a95e0994c0eef2c9f22c4e3154d417a4dc2c7b3d71a26b8f461f2187
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgio8p.mpg 45a16d6dd27fa30b23f9a50f61f013c53f7a5c7e4bfeacf5844c8e678b0a3a18
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgio9a.mpg d370a096e7bb86661b0b16170a5c4286767c11f17addff074e6d889510ccb749
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgiv1s.mpg 273087bb91e17305e3cf4ce91ddd4e0ce1a63a0a95a37e208c880206ace299e6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgiv2p.mpg 7947b24706dbfa1916fd7b588ac3afc3504b19294c1a3055126941b0123d8603
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgiv3a.mpg ad7ba0024cb1f4b0308fb2b181de6e5b22b03da6a90af9ba2c828b57f81b14c6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgivzn.mpg 41d7be926fae95b8de6fd177f61757e14c2e1a872730620fd768461c018b6a6e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwd1s.mpg 484e4cc41d8f448bcae15e335dbb88082941e21bee53423d664004b0d19aeead
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwd2p.mpg c9451f9d12edf6c0b2620b43375d24394409c6a7bf4e9186dcc8e6b255b2bff5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwd3a.mpg 15ddfa18b41c2f34a3d13e114a4b5bf169460078cf23840b929a0f3db076e1c1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwdzn.mpg 45abdef28b23d9eb2e7cd42f26d40615755898d229f3f83ac2bd665476009f96
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwj4n.mpg c79aab34429439a7364d03f27af8c8f3ca16eb84bb4da2981a849b1d740c0236
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwj5s.mpg 46963ea7ec5ac14bf1c7e060f707ce344705f7bff205be13f05363ed80affebd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwj6p.mpg 1f1d5549d32f3392fda019edc5e277e27a725624439ec52d2e59072cb6e7169e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwj7a.mpg efc210b567af529605b9145075f1ad8abafccd732734845c4eb29576f916aad7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwp8n.mpg d128332b4ef8b210acc9c7293a1054ad3ce292ab5ac709241fb9ae97d17d576c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwp9s.mpg 7d5ca1168f614dbcc87b6a83427b70dfdef58aee8e48009baa5f90370fec3363
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwq1a.mpg 5843191fd309facefa9f8b378ac48d9f31d9d50810eece48160f79b143d1e038
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwqzp.mpg 2c835f4c381716b441ca91ab5fa3616a02407d6c3f0dd011e3604faca153b326
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwx2n.mpg 0703c162ce7eb11d1d2c27d4ba574cf73d126fbba1d31c535ca654c22b32f6d6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwx3s.mpg 85bba5b8b6ea53106190837b58c0e18203162fb7678da1676c8fd6448d7c1ef1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwx4p.mpg 8eaa17a217e9b941d1b0d97dc0dd715f98217a0320d0531283861c7331a704c4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sgwx5a.mpg 50dca0c1320fa6c2609f680113aed81e5e4159782c5689c51bc13bab861e2770
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srab1s.mpg f92d2e2f455413cd2bd72d0a4f6a190244ba27ed56e9787fc4311a8a41e9539d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srab2p.mpg 2b4489bb27d72af087e9c89480af29a6046e4c95861cdc3b177fb0ad6aaf7d69
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srab3a.mpg 547262cd7059332348e73b52cb8f41e53bc2120e401b98ae7b6c95229327edf2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srabzn.mpg 66321d522055c7b7a71e617c6260b34b620ce1b4dffcf4c676d849a7d4bee411
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srah4n.mpg 08052434e06b8471525462e519421d2891431b45e0aa189927d8a21d12f07d6c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srah5s.mpg 5931b4f1e8c80b1bbff07a5277447fc9dad93ec65be1ab0fdee48591259320b0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srah6p.mpg efbe44187029f0080f6c716c02cd15fa70782f8c19498defe60b0af10c0a68ce
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srah7a.mpg febdf6e0a797a2c88628689e63ed0b285877bff3f34489abbae12e1164e49a94
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sran8n.mpg 0da6a5e7e70bf25be146ce39170ed4072828ad6056c2f8216fba83202905413b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sran9s.mpg c94d6127c83e267787a67c5e6b489a143d8106ed296abbf0dab7b1c8eea3d60d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srao1a.mpg 2dbfa1e40290fdc2ba4987a13e9843d2fa6ffe68519e6cb36f0c534bc0b742fa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sraozp.mpg 60c2622795ab94f3eb19917c1c07ac53e12844b6c8530095f899fc9dac72b53f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srau2n.mpg a46d321ce7a95881f8671cf2f22514e3acd58edf0cea655114591fb4ec3e6faa
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srau3s.mpg 3e2cec9c1b756719062296c29f18981f521944aa4e4a83c3da509260236900f4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srau4p.mpg 3a6c986bce5de4b88bf1d2a6102a3d121b1bccda5b357973d59b3aeeb4fa057c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srau5a.mpg 8d4fecfe124ee0ffb0d0d6ac29ca8b50be93d3b5cc8a567a27a77db32660ffd0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbb4n.mpg cd8028808a4731146f3d4958962f799b27ca2d42b5072b76f995833e19edce23
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbb5s.mpg 7bcc60fa7c795126a84556da1aa4dd734cc0d5c8cb9aba4241446dd66b8a9751
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbb6p.mpg 8335578aece19a7ead5d3f07ef36a513c9b48432bb9321b957ee330d95b7ef03
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbb7a.mpg 0e6ade48c8eb94c356596a453f688832bb68042c7cfbd2aef7b0aa3a91a1d836
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbh8n.mpg da977d1b1c1bb55eba1200f1ddbe243b8b302f203043594a338ba204ed9ebbf3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbh9s.mpg 94ef7fe4ea39588ab8b1379e79f5c6b85834ee0e9e840b8a075755b287e28965
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbi1a.mpg fb479585d59e1dac554ee2aa5d6669aaaeb8b9c79c7feb581c5cf035f870ad69
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbizp.mpg 6469a8ab74b9a7cdc898ba9c44d00846a0902528ea54e6ec26ebf73b52028ae8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbo2n.mpg 628e0ed91865f5b8d3c436b42acd4e9852fe608fd0fbfd9f3a0d91b8e51859bb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbo3s.mpg c8b37abc6d65f819a7f6ca46d5af711d24d56a1d3e8811536accd330c9985e47
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbo4p.mpg 455877996a256b2ed35210d42f7906a2e17d0ee4ab9d12ba00b9e34db587b00c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbo5a.mpg e3d63e5df52fb751d7ac106f2297a407869f640d4cac08606e9146d69b93d4f4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbu6n.mpg 20d7da081e2e8f72198ff7e17ea476183d29b83e51eebb8a3954be94ced4925b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbu7s.mpg 9ccc387f0c83632e199fc9b447047b347d71125a21f2721c65a51eccd7379c9f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbu8p.mpg 0524d88364a3e2b12bca0c95bb0e697dc2bec2b3a2dda9aa01c46dc6d4aa3040
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srbu9a.mpg 9717096e3acf42d1378389d36b849bda646bdda466b2d5d8a982450ed6d993b0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sria6n.mpg 02bbf35bebae9c02c9319d706a354dcc0f728057b4718b40a1d3c5e516fc2ae1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sria7s.mpg 82208c3bc3aa51a8386d693ad5ca8e8fd244f52df310a6b19bb0855aaa4d5999
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sria8p.mpg ef21cc3c3dea292db47aed57f45d4b482229051e855f2b915739ef5de98368bd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sria9a.mpg 33f12416d1549e12da91f0c59f8d469813e7073d1a20408e1c24b86b0b058087
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srih1s.mpg d39a197837153b894098a9d6707d35627b665a4180a417d2c2ede3fb195985c5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srih2p.mpg 0b41c76aa7ae481cc62f21a3acb30ad35e72c272b497cde1533652eab519c52a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srih3a.mpg 86c66a2ebaf9e745242628f7786366f5f34ed8cf785e8ac058718c40bbc53649
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srihzn.mpg ac5b4065f668eb1facbd7354d6f6d54eeba51a4150f50609a5037795b710d3e7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srin4n.mpg a25516c92ac78f6a02f3392f8385f725517b7e4c6d0808fb6f5bb286fa8df29e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srin5s.mpg 3f7c70bc149874cf1d949e81444fcf2cec18df0f971c377f4a489bc0e679c14e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srin6p.mpg 695cb2f98e3f744c89382797815a7d05c2d3f9ba7074040d73dbc9f34383a1bb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srin7a.mpg b7af19b107a3b63668941f19990be8f2d32e2ee88a5db47f29f2efd07925c6a6
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srit8n.mpg fac395911b00ae702d4eef940dbe6c3b60a3821bf8686982ebedf95dbece47cb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srit9s.mpg 689b4e5741dcb91db8ed274fe8dcd455aaa103154673e6fe117ed104a512b36b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sriu1a.mpg 65ebd5b1fa810c1eacff50ba74c121fb240c5b6e8de1e5d1d7cef3465e46b1c3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/sriuzp.mpg fbb07a4e42546689015867053131407aefe5166281f41f703cc8b41178d1f336
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwb8n.mpg 1330eb8b6bfda72de9df062c611a5e1cb95d154e9ba2be5eb77b020c5994d029
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwb9s.mpg b711c8a914664a37be742db26a3f209586024595440e24aa781014d0293b58d1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwc1a.mpg 7a89684a92da318897a277b81504ce589b40e6914ba492338c0162c545f8eb3c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwczp.mpg 231521e77a241657c98a7a48fbf58c9f1c7a0425be9b95565758026d4ac7481c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwi2n.mpg 46839b1d665250f37e67bb719aa4a5f0e9d709c645033357a57f48ff622bd113
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwi3s.mpg 5536c7c686f5a64cc70f8b00094d44abaf85d55009f555fa0bcbbe98726a4249
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwi4p.mpg 4d2caaa5b24ef689d9e3e16cdf9281cc5778d8c57414e79583cae8b8045e45c9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwi5a.mpg 90d3385ddfe43dcdd150cf6bfa375deb76a0e2fe8d2fe8f0b9b0a5dcfb292dd8
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwo6n.mpg bed6cd68e1c39cd8cbf63ac2ab2ce30e97c935dae4df81b4fcaf6dc9bbc7a6a1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwo7s.mpg 2667711f30f43a90f68b72e5778f9048a51741cd6a0da42fa7503eebda6b3504
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwo8p.mpg 74d143c901caffdc537b5fb75cec087267cd5e2685fe859346921cb526957406
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwo9a.mpg bc50c027a60c631cbe7a768e668a439141565db3fe11b0bd40845d60f956c68b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwv1s.mpg c5cb95b673e38b3e84a6bbf4ab9d28ef2510198079396cd705bdc7c345933220
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwv2p.mpg 4e00c93177dd51152454667775fd5d944939e5f15eabc6b904589bce38b5838a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwv3a.mpg e79dddf91e8b070ef4b8458f8a4aa8cf3180987eb5cddbe0d75e42da6a1c8464
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/srwvzn.mpg 29bd1f51eec0bd95115b914a1d1428c06c8024ba4d3d78390bad5eb974034d3d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swab6n.mpg b70ec52d70ca6117b285116e55b0c7ef5868edbc089b7c8b09515063c72d7f7e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swab7s.mpg 007e6a5cf63b1c9c672e025cfe8d2309ba37ab2e4e42db12e1f507e628b0adba
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swab8p.mpg 50767b0a4c43bec1ffbcc9ae422937e2f8d6bd2515e412f2649228e07c9180be
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swab9a.mpg 153b3d455964c8e6d98ff17bd837aa30f867e42e0d0417d86a61d48fadcc79f2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swai1s.mpg a02046854ca6ba34de8b27841628c8b8fdc17fbf903d2c0f5c7e0a0fcb0cfb41
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swai2p.mpg 916da1d72cace7351bf829ebdc9dd32ea2cd82986439dbab7c498e7af63b7d12
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swai3a.mpg 2bf734b524c75f5de8714cb47925e59a59ffc757ed1523c0b7426fad84c3a7d3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swaizn.mpg 48b0e0cfefb1902bcd45f6f521e2f50b600840b0f160ad35e18d393139188cfd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swao4n.mpg 1eeea91bf683ae099b94236ad76d31e6a4e4e40665adbcf2a137b6a8dee0af51
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swao5s.mpg 16c6d587dc94f2ca6b47987ce69ccb9f3bc8f192694e0052db8a592c89dfa911
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swao6p.mpg 81345f01e23f66744903ddbf11f5521d50de2caef2c9cfd1b9c630706e10ef2e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swao7a.mpg d66db35b7838ff3bc60b85130a532a81bb711fa53f319de301f03a8b59a16364
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swau8n.mpg 3b60a35c84efee873f6672f63742e9eeeb0bf16f8859809e37d0288a852b4211
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swau9s.mpg 9a429a63a5dbcfb9862e0be6f74b95d0b6363c3f003d74472304f034d16cd5ec
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swav1a.mpg 9e7f6bf324173c464fac030c50b052102a6945509be1ea031f1fb8d9f8b913f3
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swavzp.mpg 0728955161f7497f2a5f1e2c59f1355aa47d8e97d7d39218c857e9d5bca7f710
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbc1s.mpg 4bbb6d715d3be3701cb3c7c82eca8249d455c8f161c996b3ab3d683a1efb731c
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbc2p.mpg 3f6e30ee33bb29ab0aa7a4ca8ebb6e2011946a35aae33ad35ef8c57934db6621
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbc3a.mpg d6c814baecc592f29243a7bcc903d2b3e389d7b7896c99708fe98d87c26d1dc2
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbczn.mpg 8d70f92db16c33831e84a3e6eed8f19f0745fd5a1d9f108abfe73286363c3020
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbi4n.mpg e12a305ec343d822e27c7a0eb1e3fee69594ab81001d072c39ca8bad26ecc01f
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbi5s.mpg e73010e8ac87e465f74cbfdfde4689f2eae5a20afe862381bf178f2cfd76777d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbi6p.mpg a6fd9bdf9a123f4f0f37757f4ea0a75e6ecd7b6b44ce9192c1691c371190366d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbi7a.mpg f6543bf91579781ddcbaa2f834cb795ef6cc5e7dc77636beecdac2c9f56d218e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbo8n.mpg ca091293503fee5c096861450c7313efd38a29681ffb21635e445442adfd580b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbo9s.mpg f4e3c0942af52f3697687f5219a7442b8567f705797cf21c93a3520e9da53c97
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbp1a.mpg 4655fa8b153bf7addbe4430009e99de2bbee3bf17c2806e91f790af9012b4cb7
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbpzp.mpg d837554294bc9e2c418d00f4ab2c1bd5a45554ed410d7236e8e0cab95314b9dd
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbv2n.mpg 81a11394011561e7a6b3ffcf2ca5d58612865348bcb3201ca6ec9bca45763616
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbv3s.mpg d38837fca6a345cb865d303b0dbf0bf290ba1a575a24a0bc46b2ad390e16bad0
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbv4p.mpg ecf18bb2cf64b6f8d2642dd62f343778a9396e5722324ffd32ffc1be61f6d182
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swbv5a.mpg 52308cb47c710eca74359125ad0b2b080742055998db3c421c8e93428962430a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swib2n.mpg 73573ce941169b3ee8ab965caf5d2ec118846f0d34408216be48f5bf585f8eb5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swib3s.mpg 837de27b22d7ba9d65e6b73340c9da44cfef961f9647bbaa06ac43ed9171a748
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swib4p.mpg 721b5edd67a1012a5ae5f66fc11d5ffce9baab6da788a2965daa98b07f2504e4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swib5a.mpg 39e4a3a80322b49901f6f028f0342063bc6c702a72a69012f712d482594dcd90
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swih6n.mpg 677312baf65667f098670da6e217b511a8027a50d2ca8c03e290f3998f2e9693
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swih7s.mpg 2b42de3a3d28a8f3f99adb4c9307441d8619d872f54a008fbef003432c864a51
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swih8p.mpg 3aebf9ac5eae2c77c199f11e74119ff81c64a25c9c46052470eabf42cc83dcd1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swih9a.mpg b2f95ce171fce3bf24e00bab6f00394a0a5ccd6fba6645a74ae2c7777b4a0c35
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swio1s.mpg 46c6a98a1a92de0f26bbc6202a2f10c1f58084be4ed98eabec52945d11632d6a
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swio2p.mpg e40cbdcf35d08ff2db6e63de313d5099fe0329ea19f89729cbd2f128141e2d99
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swio3a.mpg 0695b13f71d8ca0bc2532ecc4b30539ee86e244c9c8f3619efba61eb6700ebbc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swiozn.mpg 792690e65e4d9fb7cad12e5d57ceee8da40c7d5b431c67e449a2f98edbc6fc35
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swiu4n.mpg c36d70754f25105ffb0f772e181d1a7c8a3ebe23986cb716f0a79e639b1f2e1e
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swiu5s.mpg 6b824ec53a8f4def9409a1eb0def1cb4df690f2f02cb81cdf7784d9a1f4c3556
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swiu6p.mpg 396a4395c1aa7005fe02e84cbe23cf49f190ce797c7876719047a4f53ddc17b4
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swiu7a.mpg 419ac6a718d66f9841128da1eccc65d628afa4fa9950c66f0cc1c41143d61a21
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwc4n.mpg bc135263da4d95d454abae36a402f6d297ec8eb22e26db48463df3c621a02df9
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwc5s.mpg 43bb5559fc4fcd6c3229bc57194ae145bf68a6f91a3a6163a2d838f22254cc24
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwc6p.mpg 1786a08b61750ef025a7e6eebc02ba453cf49131bf6bebd67401ee6832de2acc
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwc7a.mpg 2b7d91be815265b26faf59a86cf41826d0fd9fa557961f3a4de96e2dd8d633fb
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwi8n.mpg 29cb828a9cd1a419b46df0c53eaaeb245105542a636d6d07e882ef898688f540
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwi9s.mpg 99295d11b73bd29b3e323410e3572d8a7082b7d65e61bf9ec7292dcf714e93ac
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwj1a.mpg acb857b46b2b2453f51460d4921e4e1165dc6000f6fd13f83d7e96a748d4b470
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwjzp.mpg a0dbb3cc45760a8f21338a7a3ce20713c3b2b673bcbb9300ec1dd8f857327507
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwp2n.mpg ee165365348bd1850155ecf21fb2e7db4926fc4912056c97734015b2e620c68d
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwp3s.mpg 550fd6ec3d2f66da3a77ad4d6361c4099880798a914268d8d31ef47612645386
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwp4p.mpg 9072c1d54835189ff91ae2cf9678859f8c3769967e96dc69443cafae84f2cde5
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwp5a.mpg f79234547cb75339eb54c5b39cd2e9e8e15a17823f97adad709fb64d58c53758
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwv6n.mpg 65cc1c3e4199bb70bc25c986ba1b205503900076377f05961329b8dd3a7d88c1
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwv7s.mpg eb39e39610af7aa32467faf4d6638a1cd7019d6baf3600f234d3a84a2ac22b6b
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwv8p.mpg 06102ed813a4b6897dafda2ee49a39377edf9b2a70e8ba2d10600b6bed1a4f22
grid_more osalinasv-lipnet/preprocessing/detect-face-parts/pruebas/videos/s1/swwv9a.mpg 4701491708ce4131ea41ead9ab459b68bb4b968075130c2116bd1bcf7aa29179
grid_more vid2speech/dataset/bbaf2a.mpg 19808c5d7cf4e94e0d8716fb9d4c9b46f8a95b430cef8f57d9911fc476af919b
grid_more vid2speech/dataset/bbilzs.mpg d02bf35d017a609361f18765085c7ae34f13459d33e033f83d4814dbe3ba8607
grid_more vid2speech/dataset/bbwgza.mpg 1dbace8dd058fe2065b052bc46821d0806fc39e6751bc8183a3c74e1096325f9
grid_more vid2speech/dataset/bgbu2a.mpg 555216cad33eef948f550d6cde46eedf41eef627b91eb53b42661f3d17d4ccd0
grid_more vid2speech/dataset/bgim8s.mpg fe4d6ed7d64bc02b11742e6f914c4164a109a7e1d60ae5fe947b8c8818b523b0
grid_more vid2speech/dataset/bginza.mpg 01c589581d3e570f3ea9723fe5b5299cd38b611ed6fafc53dc620a653f2ecbc2
grid_more vid2speech/dataset/bgwo2a.mpg df79640e06454a58b727c3e2ffa232c2c1bf26739cc1c8c45ccd5ed70873b323
grid_more vid2speech/dataset/brwm8s.mpg e8d7691012b49bceb54102eae435f4bba303cc932bac2116067fe60f97c5fb72
grid_more vid2speech/dataset/brwt1n.mpg 4a2aeeebc224daf285ee753ccd68aba500ad26b52ccf7145b2d952015cb2f411
grid_more vid2speech/dataset/bwat1p.mpg e360bc0f1f0dfd1d13676c6b9d31537d300e5c35b4b5d9a4a9aec2b316059a8b
grid_more vid2speech/dataset/bwbm9n.mpg 5720f126befc832103a40a4bbcdf7201d208425f40391efc00ff2712ad162848
grid_more vid2speech/dataset/bwbt5p.mpg 5cb44c9ba5d0c157a5c8875e035b8d7ffaadc46fed501fe3f84149054be18c36
grid_more vid2speech/dataset/bwif7n.mpg 10a4c245d0f8852312ee2eb12d9535a60f9e39b51103132f2997bd23e47f6f73
grid_more vid2speech/dataset/lbaq2s.mpg bd3aaeb01c1f0ad0c090f13a6e19419617bf3a1b71f21b450776228022977963
grid_more vid2speech/dataset/lbaq3p.mpg 9bda5061b21e0c4dd174161188e87a63a553263dd23b9ac89e246c91425959ee
grid_more vid2speech/dataset/lbic9n.mpg d59cc46eb6bee0f916ebea3e80e2aef2319eba95136c480aecc37131ee3904c5
grid_more vid2speech/dataset/lgar9n.mpg e5c0b15cce6b742f73e743e63bc3adbf7e492fa0570115dfc8e98dc765bb6d25
grid_more vid2speech/dataset/lgbf6s.mpg 72b9bcca78bfdb91196fcfce63d0c5669e50037a642aa4f84889f0d638c16734
grid_more vid2speech/dataset/lrbr2s.mpg 2f08f42fe2f33ecb981736dcfa9573c69d42d66a83b645a0003856a4265b0172
grid_more vid2speech/dataset/lriq4s.mpg a4fc5213451d230048285963fad4b3a16589bd6fc483698ce58367859e3440c5
grid_more vid2speech/dataset/pbbc4a.mpg 23911fd606f95bfe9ff8731c000a9a184746f722b734f795f33159ec4a9feac4
grid_more vid2speech/dataset/pgbq8s.mpg cdade5c0c45e65f03c7c9310f67b1a8fcd1fa88d81e6334f8c79e77fc289c55b
grid_more vid2speech/dataset/prai9p.mpg f83c9df69cd4b512c0e69d4d678a058497505ae745dc284ac382204fc928c01a
grid_more vid2speech/dataset/prap2s.mpg 75c89b516eaf92d9c50c8d27a2c9d91a7bfd53585a89f9efdb76b8877c849825
grid_more vid2speech/dataset/prbc8s.mpg cc8c9af4287521e2a5f026ee9c235c455426dfb4d9c8cc96c8490e78b3bcc09f
grid_more vid2speech/dataset/prbp7p.mpg 5f84e1977c6d26599a6093d234a54ee533a76822df501f1685120062c5393855
grid_more vid2speech/dataset/pric2a.mpg 78b37ee1ec32350097e3bff791ffe0a8c2e3487303061968d4747e5f1905d59a
grid_more vid2speech/dataset/prii6a.mpg 4147893f418d1847ddfe2a6bb5882c965146646b2725316a36bee4b9540d4bcb
grid_more vid2speech/dataset/prio8s.mpg 0d7640761418d5f31385676615a958243313dc3fff23a7eeebdba9765a344529
grid_more vid2speech/dataset/priv3p.mpg 81819f511d9fe39808aed5e170d974b931bc96a16455f9e91d4dc0e5a8fea360
grid_more vid2speech/dataset/prwj7p.mpg d2ec969fcafb2d12cd00e93648a94b4acb4e45359bbe0af4d5673a63efeb5062
grid_more vid2speech/dataset/prwj8a.mpg 9578a378af28e3ffc5b8bc88c8ab4fb8e123ae995467c91a6f12efbd28d263e8
grid_more vid2speech/dataset/prwp9n.mpg fc47db2400ce07b49ca7d29074c33e461424a7e567350c608e12844321cce621
grid_more vid2speech/dataset/pwap8s.mpg 291afb3b3a22baf862d4a20139b11655706c96d30cbaea106f63ec349b37f122
grid_more vid2speech/dataset/pwbj8s.mpg e354bf1ce03168372aa184eca27b2b0f6fd9b1bccfeb3aee2cf6d96c97abe079
grid_more vid2speech/dataset/pwip6a.mpg 98e57ba4140ce36acd50683289e3f2e8ac771d48b40cedd15ef38da830443e8a
grid_more vid2speech/dataset/sbwn8s.mpg cc4028b585fbb4dcc753e48687f8a310a95328ef2c4b46d399ea770edcfb3570
grid_more vid2speech/dataset/sbwu4a.mpg dbea3ada80118c38c4032bee2ad6c19f388e4526d3740f6d0d36bf371f45d46d
grid_more vid2speech/dataset/sgac2a.mpg 37d9c86f5f3cd57621fdefd0a8912c8437126542968c57ad625c77a230ff6f9d
grid_more vid2speech/dataset/sgav2s.mpg f54aa74c48c049a6b06202874b20753522b63af05e229c51def6ac39c2352280
grid_more vid2speech/dataset/sgbc3n.mpg 473b1d8e5cbc7289b7f6db19b14a6a40b1903168527200b71a64d76635a9f958
grid_more vid2speech/dataset/sgbc6a.mpg 6c7b43684ddd95e1434b758fb3d359bd45962e32a43e67197e7ca2bec70571b0
grid_more vid2speech/dataset/sgbv6s.mpg 143e44713cca81e01d9aaf2a4756cabfc5d57de3859aab503adef7ee27ee7531
grid_more vid2speech/dataset/sgib6s.mpg b50e5b9c88193c6c7a3dae966f3eafb8ceee825ccb9a27098f482f411adf7e19
grid_more vid2speech/dataset/sgii1p.mpg a47ee5e4dc641ab440883bd57ffd32110f454d39cf00fbc1d3f49f1043641b83
grid_more vid2speech/dataset/sgiizs.mpg 0f4fe56d6dd06076529fb1ea23aae7c2ef277bba90d8eb9dbe58976aa371432b
grid_more vid2speech/dataset/srah4a.mpg 0407fd449d535e56962472e4fc06800fa2c95fa6bae3bce72743c3a66f81acb4
grid_more vid2speech/dataset/swao4a.mpg 04a315f7a87cce4bc42c51211344a3e1e133284ef8fee467615555f4e8a21e46
grid_more vid2speech/dataset/swau8a.mpg 4d2a4c69037dea56c4b6973709d6ba0c43a12fe34186df00c0b699a684699d3a
grid_more vid2speech/dataset/swwc4a.mpg ece059396c2ba1de0dc9c1dc0ad6f9b7d4063ff2b10825efd1a50e43da9beac3
"""

if __name__ == "__main__":
    try:
        main()
    except InputError as exc:
        print(exc, file=sys.stderr)
        sys.exit(1)
