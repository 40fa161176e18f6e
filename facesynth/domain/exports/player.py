"""The web player: one self-contained HTML page that plays an animation in 3D with its audio.

The page holds everything it needs (no network at view time): three.js (vendored from the npm
package ``three``, MIT, minified by ``make vendor``, in ``facesynth/data/three.*.js`` with ``three.LICENSE``) as base64 text
loaded through blob URLs, the mesh, the animation and the audio (16-bit mono WAV, base64).

The animation is stored as morph targets, compact and exact where it can be:

* rig curves: the rig's own shapes (55 targets) and the curves' weights per frame;
* a mesh animation: its principal components (the frames' offsets from the rest mesh, at most
  :data:`MAX_COMPONENTS`, enough to keep :data:`KEEP_VARIANCE` of the motion's variance) and
  each frame's coefficients;
* marker motion: the same for the markers, drawn as points.

Targets are quantized to int16 with one scale per target (error at most half a step: the
largest offset / 65534).

A mesh is drawn whole, as ``facesynth render`` draws it (:mod:`facesynth.domain.rendering`): the
eyeballs (turning with the gaze where the animation carries one), mouth cavity, teeth and tongue
of :func:`~facesynth.domain.rendering.parts.build_scene` are one more set of vertices, placed for every
frame by :meth:`~facesynth.domain.rendering.parts.FaceScene.positions` and sent like a mesh animation
(principal components, int16); every vertex carries the renderer's albedo, specular strength and
eye attribute, and the page shades with the renderer's lights and parameters
(:func:`~facesynth.domain.rendering.raster.shading_params`) and frames the whole head with its camera
(``render.fov_deg``, ``yaw_deg``, ``pitch_deg``; the points of
:func:`~facesynth.domain.rendering.parts.frame_points`, fitted as
:meth:`~facesynth.domain.rendering.camera.Camera.fit` fits them, to the page's own aspect ratio).
The head motion a motion or curves carry (``x -> R @ x + t``) moves the whole head group.

The page shows the frame count and duration, play/pause, a scrub bar, and for an artifact made
from a synthesis a timeline of its phones with their emotion, database node and take (the
artifact's provenance, or ``--motion``'s), the current phone highlighted.

A live page (:func:`live_payload`) holds the built-in rig with its 52 ARKit blendshapes as
morph targets, draws the same whole face with the same code (the parts as morph targets of the
same weights, :func:`live_parts_targets`) and connects to a ``facesynth stream --serve`` WebSocket: it sends its speech as
PCM in real time, shows each frame at its time after a small jitter buffer, and plays the speech
in sync (see docs/live.md).
"""

from __future__ import annotations

import base64
import io
import json
from importlib import resources
from pathlib import Path

import numpy as np

from facesynth.base.config import Config, RenderSettings
from facesynth.base.errors import InputError
from facesynth.domain.live.phones import SAMPLE_RATE
from facesynth.domain.rendering.camera import FRAME_MARGIN
from facesynth.domain.rendering.parts import FaceScene, build_scene, frame_points
from facesynth.domain.rendering.raster import BACKGROUND, shading_params
from facesynth.domain.rig.face import Rig, gaze_from_rig_weights, load_face_rig
from facesynth.formats.audio import pcm16, read_audio, resample

from .animation import Exportable

#: Frames placed at once when the procedural parts are built (bounds the posed skins in memory).
PART_BLOCK = 64

#: Largest number of principal components kept for a mesh animation or marker motion.
MAX_COMPONENTS = 96
#: Fraction of the variance of the offsets from the rest pose the kept components explain.
KEEP_VARIANCE = 0.999999

#: Seconds a live page holds a frame after it arrives before showing it (the jitter buffer).
LIVE_JITTER_S = 0.15

#: The vendored three.js files (package data) and the ids of the page's script blocks.
THREE_FILES = {"three-core": "three.core.js", "three-module": "three.module.js", "three-orbit": "three.OrbitControls.js"}


def _b64(array: np.ndarray) -> str:
    return base64.b64encode(np.ascontiguousarray(array).tobytes()).decode("ascii")


def quantize(targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(K, N) float targets -> (K, N) int16 and (K,) float64 scales with ``targets ~ q * scale``."""
    t = np.asarray(targets, np.float64)
    peak = np.abs(t).max(axis=1) if t.size else np.zeros(len(t))
    scale = np.where(peak > 0, peak / 32767.0, 1.0)
    return np.round(t / scale[:, None]).astype(np.int16), scale


def principal_targets(frames: np.ndarray, rest: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Morph targets for an animation without a rig: frames (T, P, 3) and rest (P, 3) mm ->
    targets (K, P * 3) and weights (T, K), the principal components of the offsets from rest
    (K at most :data:`MAX_COMPONENTS`, enough for :data:`KEEP_VARIANCE` of their variance)."""
    d = (np.asarray(frames, np.float64) - np.asarray(rest, np.float64)[None]).reshape(len(frames), -1)
    d = np.nan_to_num(d)
    gram = d @ d.T  # (T, T): the frames' offsets span at most T directions
    values, vectors = np.linalg.eigh(gram)
    order = np.argsort(values)[::-1]
    values, vectors = np.clip(values[order], 0, None), vectors[:, order]
    total = values.sum()
    if total <= 0:
        return np.zeros((0, d.shape[1])), np.zeros((len(frames), 0))
    k = int(np.searchsorted(np.cumsum(values) / total, KEEP_VARIANCE) + 1)
    k = max(1, min(k, MAX_COMPONENTS, int((values > total * 1e-12).sum())))
    basis = (vectors[:, :k].T @ d) / np.sqrt(values[:k])[:, None]  # (k, P*3) orthonormal rows
    return basis, d @ basis.T


def payload(anim: Exportable, audio: Path | None = None, view: RenderSettings | None = None) -> dict:
    """The page's data: rest pose, faces, quantized targets, per-frame weights; for a mesh the
    procedural parts and per-vertex materials (``face``); the camera of ``view`` (``render``'s
    settings: fov_deg, yaw_deg, pitch_deg; None: the default configuration's) and the renderer's
    shading parameters; the head motion; the timeline (phones, or runs of one emotion or take
    without phones) with the per-frame provenance; and the audio as a data URI."""
    if anim.weights is not None:
        rest, _ = anim.mesh()
        rig, weights = anim.rig_weights()
        targets = rig.deltas.reshape(len(rig.deltas), -1)
        names = list(rig.shape_names)
    else:
        frames = anim.vertices if anim.vertices is not None else anim.marker_motion()[0]
        rest = anim.rest if anim.rest is not None else np.nanmean(frames, axis=0)
        targets, weights = principal_targets(frames, rest)
        names = [f"pc{k + 1}" for k in range(len(targets))]
    if view is None:
        view = Config.load().settings("render")
    q, scale = quantize(targets)
    face, framed = _face(anim) if anim.faces is not None else (None, np.asarray(rest, np.float64))
    prov = anim.provenance
    data = {
        "kind": anim.kind, "source": Path(anim.path).name, "fps": anim.fps, "frames": anim.n_frames,
        "duration": anim.duration_s, "rest": _b64(np.asarray(rest, np.float32)), "vertices": int(len(rest)),
        "faces": "",  # a mesh's triangles are in face["faces"], the skin's first
        "targets": [_b64(row) for row in q], "scales": [float(s) for s in scale], "target_names": names,
        "weights": _b64(np.asarray(weights, np.float32)), "face": face,
        "camera": _camera(framed, view), "shading": [float(x) for x in shading_params()],
        "background": list(BACKGROUND), "head": None,
        "phones": [{"phone": p.phone, "emotion": p.emotion, "start": p.start, "end": p.end, "node": p.node, "take": p.take}
                   for p in anim.phones],
        "frame_provenance": prov.to_json()["frames"] if prov is not None else None,
        "emotion_runs": _runs(anim.emotion, anim.fps) if not anim.phones and anim.emotion else [],
        "take_runs": _runs(prov.take, anim.fps) if prov is not None and not anim.phones else [],
        "audio": "",
    }
    if anim.head_rotation is not None:
        data["head"] = {"rotation": _b64(np.asarray(anim.head_rotation, np.float32).reshape(-1, 9)),
                        "translation": _b64(np.asarray(anim.head_translation, np.float32).reshape(-1, 3))}
    if audio is not None:
        data["audio"] = _wav_uri(*_read_audio(audio))
    return data


def _camera(points: np.ndarray, view: RenderSettings) -> dict:
    """The page's camera: ``render``'s field of view, yaw and pitch, and the points (n, 3) it
    frames as :meth:`~facesynth.domain.rendering.camera.Camera.fit` does (the page fits them
    to its own aspect ratio, and again when resized)."""
    finite = np.asarray(points, np.float64)
    finite = finite[np.isfinite(finite).all(1)]
    return {"points": _b64(np.asarray(finite, np.float32)), "margin": FRAME_MARGIN, "fov": view.fov_deg,
            "yaw": view.yaw_deg, "pitch": view.pitch_deg}


def _face(anim: Exportable) -> tuple[dict, np.ndarray]:
    """The whole face of a mesh animation or curves, as the renderer builds it (:func:`_scene_data`),
    with the parts' motion as quantized principal targets and their weights per frame; and the
    points the camera frames (:func:`~facesynth.domain.rendering.parts.frame_points`)."""
    rest_mm, faces = anim.mesh()
    rest = np.asarray(rest_mm, np.float64)
    scene = build_scene(rest, faces)
    n_skin, n_parts = scene.n_skin, scene.n_vertices - scene.n_skin
    parts_rest = scene.positions(rest)[n_skin:]
    frames = np.empty((anim.n_frames, n_parts, 3), np.float32)
    for start in range(0, anim.n_frames if n_parts else 0, PART_BLOCK):
        skins = anim.mesh_frames(start, min(start + PART_BLOCK, anim.n_frames))
        for k, skin in enumerate(skins):
            gaze = anim.gaze[start + k] if anim.gaze is not None else None
            skin = np.where(np.isfinite(skin), skin, rest)  # a capture's gaps: the rest pose there
            frames[start + k] = scene.positions(skin, gaze)[n_skin:]
    targets, weights = principal_targets(frames, parts_rest) if n_parts else (np.zeros((0, 0)), np.zeros((anim.n_frames, 0)))
    data = _scene_data(scene, parts_rest, targets, len(faces))
    data["weights"] = _b64(np.asarray(weights, np.float32))
    return data, frame_points(scene)


def _scene_data(scene: FaceScene, parts_rest: np.ndarray, targets: np.ndarray, skin_triangles: int) -> dict:
    """What the page draws of a scene (both pages draw it with the same code): all faces (skin
    first), per-vertex albedo (linear RGB and specular strength) and eye attribute, the parts'
    rest positions (P, 3) and their morph ``targets`` (K, P * 3) quantized, the skin's triangle
    count (the first ``skin_triangles`` of the faces), where the eyeballs
    and the mouth loop are (for the page's state) and the parts left out and why."""
    q, scale = quantize(targets)
    eyes = [list(e) for e in scene.eyeball_vertices]
    loop = scene.layout.mouth.loop if scene.layout.mouth is not None else np.zeros(0, np.int64)
    index = np.uint16 if scene.n_vertices <= 65536 else np.uint32  # half the bytes for a mesh of up to 65,536 vertices
    return {"vertices": int(scene.n_vertices), "faces": _b64(np.asarray(scene.faces, index)),
            "index_bits": 8 * np.dtype(index).itemsize,
            "skin_triangles": int(skin_triangles),
            "albedo": _b64(np.asarray(scene.albedo, np.float32)), "eye": _b64(np.asarray(scene.eye, np.float32)),
            "parts_rest": _b64(np.asarray(parts_rest, np.float32)), "targets": [_b64(row) for row in q],
            "scales": [float(s) for s in scale], "weights": "",
            "eyes": eyes, "mouth_loop": _b64(np.asarray(loop, np.uint32)), "notes": list(scene.notes)}


def live_parts_targets(rig: Rig, scene: FaceScene) -> tuple[np.ndarray, np.ndarray]:
    """The parts (eyeballs, mouth cavity, teeth, tongue) of the live page as morph targets of the
    52 ARKit weights, so a stream frame poses them in the page as it poses the skin: the parts'
    rest positions (P, 3) mm and, for each ARKit name, where its shape at weight 1 moves them
    (52, P * 3) mm (:meth:`FaceScene.positions` of the rig posed by that name alone, its
    ``eyeLook*`` turning the eyes as :func:`gaze_from_rig_weights` says).

    The parts follow the skin through rigid fits (the jaw's rotation) and the gaze's rotation,
    which are not linear in the weights; their sum is a linearisation, exact at the rest pose and
    at each shape alone. On the built-in rig its error is at most 0.42 mm over the FACEGOOD
    performer's frames (every 100th; tests/exports/test_player_live.py holds it under 0.5 mm)
    and 4 mm at worst on random mixes of ten shapes at full weight."""
    rest = np.asarray(rig.neutral, np.float64)
    n_skin = scene.n_skin
    parts_rest = scene.positions(rest)[n_skin:]
    arkit = rig.arkit_matrix()
    deltas = np.asarray(rig.deltas, np.float64)
    targets = np.empty((len(arkit), parts_rest.size))
    for k, weights in enumerate(arkit):
        gaze = gaze_from_rig_weights(weights[None], rig.shape_names)
        skin = rest + np.tensordot(weights, deltas, axes=1)
        targets[k] = (scene.positions(skin, gaze[0] if gaze is not None else None)[n_skin:] - parts_rest).reshape(-1)
    return parts_rest, targets


def _read_audio(path: Path) -> tuple[np.ndarray, int]:

    return read_audio(path)


def _wav_uri(samples: np.ndarray, rate: int) -> str:
    """A 16-bit mono WAV data URI of ``samples`` (S,) in [-1, 1] at ``rate`` Hz."""
    import soundfile as sf

    buffer = io.BytesIO()
    sf.write(buffer, np.clip(samples, -1.0, 1.0), rate, format="WAV", subtype="PCM_16")
    return "data:audio/wav;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")


def live_payload(url: str, audio: Path | None = None, jitter_s: float = LIVE_JITTER_S,
                 view: RenderSettings | None = None) -> dict:
    """The data of a live page: the built-in rig's neutral mesh with its 52 ARKit blendshapes as
    morph targets (each the sum of the rig shapes the ARKit name drives, as
    :meth:`Rig.from_arkit`), so a stream frame's ``arkit`` weights pose the face directly; the
    whole face as the player draws it (eyeballs, mouth cavity, teeth and tongue, their motion as
    morph targets of the same 52 weights: :func:`live_parts_targets`), shaded with the renderer's
    lights and framed by ``view``'s camera (``render``'s settings; None: the default's);
    the stream's WebSocket ``url``; and optionally the speech to send (16 kHz mono int16 PCM,
    ``pcm``) and play (``audio``, a WAV data URI)."""
    if not url.startswith(("ws://", "wss://")) or len(url) <= len("ws://"):
        raise InputError(f"--live {url!r}: give the stream server's WebSocket URL, e.g. ws://127.0.0.1:8765 "
                         "(the address 'facesynth stream DB --serve' listens on).")
    rig = load_face_rig()
    targets = rig.arkit_matrix() @ rig.deltas.reshape(len(rig.deltas), -1).astype(np.float64)  # (52, V*3) mm
    q, scale = quantize(targets)
    scene = build_scene(rig.neutral, rig.faces)
    face = _scene_data(scene, *live_parts_targets(rig, scene), len(rig.faces))
    data = {
        "kind": "live", "source": url, "live": url, "jitter": float(jitter_s), "fps": 0, "frames": 0, "duration": 0.0,
        "rest": _b64(np.asarray(rig.neutral, np.float32)), "vertices": int(len(rig.neutral)), "faces": "",
        "targets": [_b64(row) for row in q], "scales": [float(s) for s in scale], "target_names": list(rig.arkit_names),
        "weights": "", "face": face, "camera": _camera(frame_points(scene), view or Config.load().settings("render")),
        "shading": [float(x) for x in shading_params()], "background": list(BACKGROUND),
        "phones": [], "emotion_runs": [], "audio": "", "pcm": "",
    }
    if audio is not None:
        samples, rate = _read_audio(audio)
        if rate != SAMPLE_RATE:
            samples, rate = resample(samples, rate, SAMPLE_RATE), SAMPLE_RATE
        data["audio"] = _wav_uri(samples, rate)
        data["pcm"] = base64.b64encode(pcm16(samples)).decode("ascii")
    return data


def _runs(emotion: list[str], fps: float) -> list[dict]:
    """Runs of one emotion: [{emotion, start, end}] in seconds."""
    runs, start = [], 0
    for i in range(1, len(emotion) + 1):
        if i == len(emotion) or emotion[i] != emotion[start]:
            runs.append({"emotion": emotion[start], "start": start / fps, "end": i / fps})
            start = i
    return runs


def page(data: dict) -> str:
    """The player page for ``data`` (:func:`payload`): the template with the data and three.js in."""
    root = resources.files("facesynth").joinpath("data")
    html = root.joinpath("player.html").read_text(encoding="utf-8")
    scripts = "\n".join(
        f'<script type="text/plain" id="{sid}">{base64.b64encode(root.joinpath(name).read_bytes()).decode("ascii")}</script>'
        for sid, name in THREE_FILES.items())
    license_text = root.joinpath("three.LICENSE").read_text(encoding="utf-8").replace("--", "- -")
    blob = json.dumps(data, separators=(",", ":")).replace("</", "<\\/")
    return (html.replace("<!--THREE_LICENSE-->", f"<!--\nthree.js (npm package 'three'):\n{license_text}\n-->")
            .replace("<!--THREE-->", scripts)
            .replace("<!--DATA-->", f'<script type="application/json" id="anim">{blob}</script>'))
