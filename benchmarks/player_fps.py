"""Frames per second the web player (``facesynth player``) draws in headless Chromium (the Debian
package, WebGL on SwiftShader, i.e. on the CPU), for the clip ``benchmarks/render_fps.py`` draws:
the built-in rig (11,248 vertices plus about 1,800 of eyes, mouth, teeth and tongue) speaking on
sines with a blink and a gaze sweep, 30 fps, once as rig curves (the rig's 55 targets) and once as
a mesh animation (its principal components). Prints JSON.

Two figures per page, at a 640 x 480 view:

* ``draw_fps``: frames posed and drawn back to back (the page's ``player.bench``: skin and parts
  posed on the CPU, normals, upload, draw, and a one-pixel read so the GPU has finished), with
  ``pose_ms_per_frame`` the JavaScript posing alone;
* ``play_fps``: frames the page drew per second while playing in real time (requestAnimationFrame,
  so at most the display rate), with ``played_distinct_frames_per_s`` the animation frames among them.

Compare with ``render_fps.py`` (the video renderer) run on the same machine; both depend on what
else the machine runs (``load_average_1min``), so the CPU time of the browser's processes per
drawn frame is given too, and ``draw_fps_if_cpus_idle``: the rate that CPU time allows with every
core free (as render_fps.py reports it; the bench counts the whole process tree, which may not
spread its work over every core).

    python benchmarks/player_fps.py [--frames 90] [--bench-frames 60] [--play-s 4]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
from chromium_page import CHROMIUM, ChromiumPage  # noqa: E402
from render_fps import FPS, animation, speaking_weights  # noqa: E402

from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig  # noqa: E402
from facesynth.model.curves import RigCurves  # noqa: E402
from facesynth.stages import player  # noqa: E402

VIEW_W, VIEW_H = 640, 480


def tree_cpu_s(root: int) -> float:
    """CPU seconds (user + system) used so far by process ``root`` and every process below it
    (Chromium's renderer and GPU processes), from /proc."""
    parent, cpu = {}, {}
    tick = os.sysconf("SC_CLK_TCK")
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            parent[int(entry.name)] = int(fields[1])
            cpu[int(entry.name)] = (int(fields[11]) + int(fields[12])) / tick
    total = 0.0
    for pid in cpu:
        p = pid
        while p in parent and p != root:
            p = parent[p]
        total += cpu[pid] if p == root else 0.0
    return total


def measure(page_path: Path, profile: Path, bench_frames: int, play_s: float) -> dict:
    """Draw and playback rates of the page at ``page_path``."""
    # the view is 70 % of the window's height
    with ChromiumPage(page_path.as_uri(), profile, VIEW_W, int(round(VIEW_H / 0.7))) as page:
        size = page.evaluate("[document.getElementById('view').clientWidth, document.getElementById('view').clientHeight]")
        page.evaluate("player.bench(5)")  # warm-up: shaders compiled, buffers sized
        cpu = tree_cpu_s(page.browser.pid)
        timing = page.evaluate(f"player.bench({bench_frames})")
        cpu = tree_cpu_s(page.browser.pid) - cpu
        ms = timing["ms"]
        page.evaluate("player.seek(0)")
        before = page.dataset()
        started = time.perf_counter()
        page.evaluate("player.setPlaying(true)")
        frames_seen = set()
        while time.perf_counter() - started < play_s:
            frames_seen.add(page.dataset()["frame"])
            time.sleep(0.05)
        after = page.dataset()
        wall = time.perf_counter() - started
        page.evaluate("player.setPlaying(false)")
        return {"browser": page.call("Browser.getVersion")["product"], "view_px": size, "draw_ms_per_frame": round(ms, 2), "pose_ms_per_frame": round(timing["poseMs"], 2),
                "draw_fps": round(1e3 / ms, 2), "draw_cpu_ms_per_frame": round(1e3 * cpu / bench_frames, 2),
                "draw_fps_if_cpus_idle": round(bench_frames * (os.cpu_count() or 1) / max(cpu, 1e-9), 1),
                "play_fps": round((int(after["drawn"]) - int(before["drawn"])) / wall, 2),
                "played_distinct_frames_per_s": round(len(frames_seen) / wall, 2),
                "page_mb": round(page_path.stat().st_size / 1e6, 2)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--bench-frames", type=int, default=60)
    parser.add_argument("--play-s", type=float, default=4.0)
    args = parser.parse_args()
    if CHROMIUM is None:
        print(json.dumps({"error": "headless Chromium (Debian package 'chromium') is not installed"}))
        return
    rig = load_face_rig()
    result: dict = {"frames": args.frames, "animation_fps": FPS, "webgl": "SwiftShader (CPU)",
                    "machine": platform.processor() or platform.machine(), "cpus": os.cpu_count()}
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        clip = animation(args.frames)
        clip.write(d / "anim.h5", config="{}", inputs=[])
        RigCurves(speaking_weights(args.frames), FPS, list(rig.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(),
                  "solve").write(d / "curves.h5", config="{}", inputs=[])
        for name in ("curves", "anim"):
            started = time.perf_counter()
            player.run(d / f"{name}.h5", d / f"{name}.html")
            entry = {"write_page_s": round(time.perf_counter() - started, 2)}
            entry.update(measure(d / f"{name}.html", d / f"profile-{name}", args.bench_frames, args.play_s))
            entry["realtime"] = round(entry["draw_fps"] / FPS, 2)
            result["curves" if name == "curves" else "meshanim"] = entry
    result["load_average_1min"] = round(os.getloadavg()[0], 2)
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
