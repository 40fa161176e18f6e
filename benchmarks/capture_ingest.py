"""Speed of ``facesynth ingest`` on capture routes that are not marker files: a minute of Live Link
Face capture at 60 frames/s (the rig posed with its 52 curves and head rotations, the virtual
actress's 91 markers recorded) and a minute of 25 frames/s video (MediaPipe Face Mesh, 478
landmarks; needs ``facesynth[video]``), each with its ratio to real time (ingest seconds per
second of capture: below 1 is faster than real time). Prints JSON.

The Live Link take is the rig speaking-like (jaw, lips, smile on sines, blinks, a gaze sweep, a
nodding head: :func:`speaking_arkit`), written by facesynth's own Live Link Face writer. The video
is the same rig rendered by ``facesynth render`` (640x480, frontal, with a tone as its sound),
made once in ``--work`` and reused, or ``--video FILE``. Phones are not recognised (``ingest.recognize_phones`` false:
recognition is the speech's cost, not the capture's; ``benchmarks/recognition_accuracy.py``
times it). Wall-clock figures depend on what else the machine runs (``load_average_1min`` is
recorded), so the CPU time (the process's threads and ffmpeg's) is given too.

    python benchmarks/capture_ingest.py [--seconds 60] [--repeats 2] [--work DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig
from facesynth.formats import livelink_face
from facesynth.formats.audio import write_wav
from facesynth.model.curves import RigCurves
from facesynth.stages import ingest, render


def speaking_arkit(frames: int, fps: float) -> tuple[np.ndarray, np.ndarray]:
    """((frames, 52) ARKit weights, (frames, 3) head angles in radians) of a face speaking-like."""
    names = load_face_rig().arkit_names
    t = np.arange(frames) / fps
    w = np.zeros((frames, len(names)))
    w[:, names.index("jawOpen")] = 0.4 * (1 - np.cos(2 * np.pi * 2.1 * t))
    w[:, names.index("mouthFunnel")] = 0.3 * (1 + np.sin(2 * np.pi * 0.7 * t))
    w[:, names.index("mouthClose")] = 0.2 * np.maximum(np.sin(2 * np.pi * 1.3 * t), 0)
    for side in ("Left", "Right"):
        w[:, names.index(f"mouthSmile{side}")] = 0.25 * (1 + np.sin(2 * np.pi * 0.3 * t))
        w[:, names.index(f"eyeBlink{side}")] = np.exp(-(((t % 2.0) - 1.0) / 0.05) ** 2)
        w[:, names.index(f"eyeLookUp{side}")] = 0.3 * np.maximum(np.sin(2 * np.pi * 0.4 * t), 0)
    head = np.stack([0.15 * np.sin(2 * np.pi * 0.2 * t), 0.08 * np.sin(2 * np.pi * 0.5 * t),
                     0.03 * np.sin(2 * np.pi * 0.1 * t)], axis=1)
    return np.clip(w, 0, 1), head


def timed_ingest(manifest: Path, out: Path, config: Config, repeats: int) -> dict:
    """Wall and CPU seconds of ``ingest`` (best of ``repeats``) and what it read."""
    runs, cpus = [], []
    result = None

    def cpu() -> float:  # this process's threads and its children (ffmpeg)
        return sum(u.ru_utime + u.ru_stime for u in (resource.getrusage(resource.RUSAGE_SELF),
                                                      resource.getrusage(resource.RUSAGE_CHILDREN)))

    for _ in range(repeats):
        cpu0, t0 = cpu(), time.perf_counter()
        result = ingest.run(manifest, out, config.settings("ingest"), config.settings("align"), overwrite=True)
        runs.append(time.perf_counter() - t0)
        cpus.append(cpu() - cpu0)
    assert result is not None
    seconds = result.frames / result.fps
    return {"frames": result.frames, "fps": result.fps, "markers": result.markers, "capture_s": round(seconds, 3),
            "ingest_s": [round(r, 3) for r in runs], "cpu_s": [round(c, 3) for c in cpus],
            "x_realtime": round(min(runs) / seconds, 4), "cpu_x_realtime": round(min(cpus) / seconds, 4),
            "missing_fraction": result.missing_fraction}


def live_link(work: Path, seconds: float, config: Config, repeats: int) -> dict:
    fps = 60.0
    arkit, head = speaking_arkit(int(round(seconds * fps)), fps)
    livelink_face.write(work / "minute.csv", load_face_rig().arkit_names, arkit, fps, head=head)
    (work / "llf.csv").write_text("take,mocap\nminute,minute.csv\n")
    return {"file_mb": round((work / "minute.csv").stat().st_size / 1e6, 2),
            **timed_ingest(work / "llf.csv", work / "llf.h5", config, repeats)}


def video(work: Path, seconds: float, config: Config, repeats: int, given: Path | None = None) -> dict:
    try:
        import mediapipe  # noqa: F401
    except ImportError:
        return {"skipped": "facesynth[video] is not installed (pip install 'facesynth[video]')"}
    fps = 25.0
    clip = given.resolve() if given is not None else work / f"minute_{seconds:g}s.avi"
    made_s = None
    if not clip.exists():
        rig = load_face_rig()
        arkit, head = speaking_arkit(int(round(seconds * fps)), fps)
        rotations = livelink_face.head_rotations(head).astype(np.float32)
        RigCurves((arkit @ rig.arkit_matrix()).astype(np.float32), fps, list(rig.shape_names), BUILTIN_RIG_NAME,
                  builtin_rig_sha256(), "truth", rotations, np.zeros((len(arkit), 3), np.float32)).write(
            work / "minute.h5", config="{}", inputs=[], overwrite=True)
        t = np.arange(int(seconds * 16000)) / 16000
        write_wav(work / "minute.wav", (0.2 * np.sin(2 * np.pi * 180 * t)).astype(np.float32), 16000)
        settings = Config.load(overrides=["render.fps=25", "render.yaw_deg=0", "render.pitch_deg=0"]).settings("render")
        t0 = time.perf_counter()
        render.run([work / "minute.h5"], [work / "minute.wav"], clip, settings, overwrite=True)
        made_s = round(time.perf_counter() - t0, 1)
    (work / "video.csv").write_text(f"take,mocap\nminute,{clip}\n")
    return {"file": clip.name, "file_mb": round(clip.stat().st_size / 1e6, 2), "render_s": made_s,
            **timed_ingest(work / "video.csv", work / "video.h5", config, repeats)}


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=60.0, help="length of each capture (s)")
    ap.add_argument("--repeats", type=int, default=2, help="ingests of each (the best is the ratio)")
    ap.add_argument("--work", type=Path, default=None, help="folder for the captures (the video is kept and reused)")
    ap.add_argument("--video", type=Path, default=None, help="a video (with a face and sound) to ingest instead of "
                    "rendering one")
    args = ap.parse_args(argv)
    config = Config.load(overrides=["ingest.recognize_phones=false"])
    work = args.work or Path(tempfile.mkdtemp(prefix="capture_ingest_"))
    work.mkdir(parents=True, exist_ok=True)
    out = {"machine": {"cpus": os.cpu_count(), "platform": platform.platform(),
                       "load_average_1min": round(os.getloadavg()[0], 2)},
           "live_link_face_60fps": live_link(work, args.seconds, config, args.repeats),
           "video_25fps": video(work, args.seconds, config, args.repeats, args.video)}
    out["machine"]["load_average_1min_after"] = round(os.getloadavg()[0], 2)
    print(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main()
