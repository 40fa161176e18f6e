"""Frames per second of ``facesynth render`` on the production rig (11,248 vertices, with its
eyeballs, mouth cavity, teeth and tongue), OpenCL and NumPy, against the animation's 30 fps.
Prints JSON.

The animation is the rig speaking-like: jaw, lip and smile weights on sines, a blink and a
gaze sweep, 30 fps. Two figures per rasterizer:

* ``draw_fps``: frames drawn per second (scene placement, normals, projection,
  rasterization, shading), the renderer alone;
* ``stage_fps`` (OpenCL only, and NumPy with ``--stage-numpy``): the whole ``render`` stage
  per frame of video, reading the artifact, drawing, MJPEG encoding and muxing the audio;
  ``curves_stage_fps`` the same from the rig curves of the same animation (the rig posed in
  memory, as ``solve`` -> ``render`` does).

``realtime`` is stage (else draw) fps / 30: above 1 is faster than real time. Wall-clock figures depend on what
else the machine runs (``load_average_1min`` is recorded), so the CPU time per frame is given
too, and ``draw_fps_if_cpus_idle``: the frames per second that CPU time allows with every core
free (the OpenCL path uses all cores, the NumPy path one).

    python benchmarks/render_fps.py [--frames 90] [--numpy-frames 10] [--width 640 --height 480]
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
from scipy import sparse

from facesynth.base.config import Config
from facesynth.base.opencl import device_description, use_opencl
from facesynth.domain.rendering import video
from facesynth.domain.rig.face import gaze_from_rig_weights, load_face_rig
from facesynth.formats.audio import write_wav
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.stages import render

FPS = 30.0


def speaking_weights(frames: int) -> np.ndarray:
    """(frames, E) rig weights at :data:`FPS`: jaw, lips and smile on sines, a blink every 2 s and
    a gaze sweep."""
    rig = load_face_rig()
    t = np.arange(frames) / FPS
    w = np.zeros((frames, len(rig.shape_names)))
    w[:, rig.shape_index("jawOpen")] = 0.45 * (1 - np.cos(2 * np.pi * 2.1 * t))
    w[:, rig.shape_index("mouthFunnel")] = 0.3 * (1 + np.sin(2 * np.pi * 0.7 * t))
    for side in "LR":
        w[:, rig.shape_index(f"mouthSmile_{side}")] = 0.25 * (1 + np.sin(2 * np.pi * 0.3 * t))
        w[:, rig.shape_index(f"eyeBlink_{side}")] = np.exp(-(((t % 2.0) - 1.0) / 0.05) ** 2)
        w[:, rig.shape_index(f"eyeLookUp_{side}")] = 0.3 * np.maximum(np.sin(2 * np.pi * 0.4 * t), 0)
    w[:, rig.shape_index("eyeLookOut_L")] = w[:, rig.shape_index("eyeLookIn_R")] = 0.4 * np.maximum(np.sin(2 * np.pi * 0.25 * t), 0)
    return w


def animation(frames: int) -> tuple[MeshAnimation, RigCurves]:
    """The rig moved by :func:`speaking_weights`, with a gaze track from its eyeLook weights, as a
    mesh animation and as the rig curves that pose it."""
    rig = load_face_rig()
    w = speaking_weights(frames)
    vertices = rig.evaluate(w).astype(np.float32)
    weights = sparse.csr_matrix((len(rig.neutral), 1), dtype=np.float32)
    clip = MeshAnimation(vertices, FPS, rig.neutral.astype(np.float32), rig.faces,
                         np.zeros((frames, 1, 3), np.float32), ["none"], weights, ["none"], np.array([0]),
                         gaze=gaze_from_rig_weights(w, rig.shape_names).astype(np.float32))
    return clip, RigCurves(w, FPS, list(rig.shape_names), rig.name, rig.sha256, "import")


def draw_fps(clip: MeshAnimation, settings, frames: int) -> tuple[float, float]:
    """Frames drawn per second of wall-clock time over ``frames`` frames (after one warm-up
    frame), and the process's CPU time per frame, ms (all its threads, PoCL's included)."""
    view = video.ShadedView(clip, settings, settings.width)
    view.frame(clip.vertices[0], 0)
    started, cpu = time.perf_counter(), time.process_time()
    for t in range(frames):
        view.frame(clip.vertices[t % len(clip.vertices)], t % len(clip.vertices))
    return frames / (time.perf_counter() - started), (time.process_time() - cpu) / frames * 1e3


def stage_fps(clip: MeshAnimation | RigCurves, settings, work: Path) -> tuple[float, float]:
    """The render stage's own frames per second (its ``frames_per_s``) for the clip (a mesh
    animation or rig curves) on disk, and its CPU time per frame, ms: this process's threads and
    the ffmpeg encoder it waits for."""
    anim, wav, avi = work / f"bench.{clip.KIND}.h5", work / "bench.wav", work / "bench.avi"
    n_frames = clip.n_frames if isinstance(clip, RigCurves) else len(clip.vertices)
    if not anim.exists():
        clip.write(anim, config="{}", inputs=[], overwrite=True)
        write_wav(wav, np.zeros(int(n_frames / FPS * 48000)), 48000)
    cpu, children = time.process_time(), resource.getrusage(resource.RUSAGE_CHILDREN)
    fps = render.run([anim], [wav], avi, settings, overwrite=True).frames_per_s
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    used = time.process_time() - cpu + (after.ru_utime - children.ru_utime) + (after.ru_stime - children.ru_stime)
    return fps, used / n_frames * 1e3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--numpy-frames", type=int, default=10)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--stage-numpy", action="store_true", help="also run the whole stage on NumPy (slow)")
    args = parser.parse_args()
    clip, curves = animation(args.frames)
    base = (f"render.width={args.width}", f"render.height={args.height}")
    result = {"vertices": int(clip.vertices.shape[1]), "width": args.width, "height": args.height,
              "animation_fps": FPS, "machine": platform.processor() or platform.machine(), "cpus": os.cpu_count()}
    with tempfile.TemporaryDirectory() as tmp:
        for name, flag, frames in (("opencl", "true", args.frames), ("numpy", "false", args.numpy_frames)):
            settings = Config.load(None, base + (f"render.use_opencl={flag}",)).settings("render")
            if name == "opencl" and not use_opencl(True):
                result["opencl"] = {"error": "no OpenCL device builds"}
                continue
            fps, cpu_ms = draw_fps(clip, settings, frames)
            entry = {"device": device_description(flag == "true"), "supersample": settings.supersample,
                     "draw_fps": round(fps, 2), "draw_cpu_ms_per_frame": round(cpu_ms, 2),
                     "draw_fps_if_cpus_idle": round(1e3 * (os.cpu_count() or 1) / cpu_ms, 1) if name == "opencl"
                     else round(1e3 / cpu_ms, 2)}
            if name == "opencl" or args.stage_numpy:
                fps, cpu_ms = stage_fps(clip, settings, Path(tmp))
                entry.update(stage_fps=round(fps, 2), stage_cpu_ms_per_frame=round(cpu_ms, 2),
                             stage_fps_if_cpus_idle=round(1e3 * (os.cpu_count() or 1) / cpu_ms, 1))
                fps, cpu_ms = stage_fps(curves, settings, Path(tmp))
                entry.update(curves_stage_fps=round(fps, 2), curves_stage_cpu_ms_per_frame=round(cpu_ms, 2))
            entry["realtime"] = round(entry.get("stage_fps", entry["draw_fps"]) / FPS, 2)
            result[name] = entry
    result["load_average_1min"] = round(os.getloadavg()[0], 2)  # other work on the machine meanwhile
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
