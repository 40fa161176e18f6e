"""Mesh animations -> an AVI with the audio muxed in: the views, the audio fitted to the
frames and the video writing that ``facesynth render`` and ``facesynth batch`` share.

Views: ``shaded`` (the face, smooth-shaded and anti-aliased, with eyeballs, mouth cavity,
teeth and tongue where the mesh has eye and mouth holes, on OpenCL with a NumPy reference),
``markers`` (the paper's marker mode: the markers as dots) and ``side-by-side`` (the animation
beside a second one, e.g. ground truth, each half labelled as ``render.labels`` says).
The camera orbits the rest mesh (+y up, looking toward +z) by ``render.yaw_deg`` and
``render.pitch_deg``, fitted once to the rest mesh so the view is steady: on a face (eyes and
mouth found) it frames the whole head down to just below the chin, otherwise the whole mesh,
centred, with a margin (:func:`~facesynth.domain.rendering.parts.frame_points`,
:meth:`~facesynth.domain.rendering.camera.Camera.fit`). The eyes follow the animation's gaze track where
it is known and look ahead elsewhere. Several animations render one after another into one
video, each with its own audio, cut or padded to its frame count, so the first frame is at
audio time 0 and picture and sound end together.

An animation is a mesh animation (``meshanim``) or rig curves (``curves``, from ``solve``,
``retarget`` or ``openfacefx``): curves pose their rig in memory (the built-in rig, or a
user's rig given to :func:`render_video`) as ``rig-mesh`` does, with the rig's gaze from its
``eyeLook*`` shapes and, with ``render.head_motion``, the head motion the curves carry.
"""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import RenderSettings
from facesynth.base.errors import InputError, UsageError
from facesynth.base.progress import progress
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import load_rig, pose_rig
from facesynth.formats.audio import read_audio, resample, write_wav
from facesynth.model.artifacts import artifact_kind, atomic_path
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation

from .camera import Camera
from .parts import build_scene, frame_points, vertex_normals
from .raster import BACKGROUND as BACKGROUND_RGB
from .raster import rasterizer

BACKGROUND = np.array(BACKGROUND_RGB + (1.0,), np.float32)


def draw_markers(points_px: np.ndarray, width: int, height: int, radius: int = 3) -> np.ndarray:
    """The paper's marker mode: each marker as a filled disc."""
    img = np.empty((height, width, 3), np.uint8)
    img[:] = (BACKGROUND[:3] * 255).astype(np.uint8)
    yy, xx = np.mgrid[-radius : radius + 1, -radius : radius + 1]
    disc = xx**2 + yy**2 <= radius**2
    for x, y in np.round(points_px[:, :2]).astype(int):
        ys, xs = y + yy[disc], x + xx[disc]
        ok = (xs >= 0) & (xs < width) & (ys >= 0) & (ys < height)
        img[ys[ok], xs[ok]] = (240, 220, 90)
    return img


#: The sample rate (Hz) of a video's silent soundtrack (a clip with audio keeps its audio's rate).
SILENCE_RATE = 48000

#: Audio may be longer or shorter than its animation by at most this many video frames;
#: the difference (rounding of the frame count) is cut or padded with silence.
MAX_AUDIO_MISMATCH_FRAMES = 2


def clip_audio(audio_path: Path, n_frames: int, fps: float, rate: int, anim_path: Path | None = None,
               loaded: tuple[np.ndarray, int] | None = None) -> np.ndarray:
    """The clip's audio at ``rate`` (samples,) float, cut or padded to exactly n_frames / fps
    seconds (to the nearest sample). An audio file longer or shorter than that by more than
    :data:`MAX_AUDIO_MISMATCH_FRAMES` frames is an InputError: it is another utterance's.
    ``loaded``: the file's (samples, rate) as :func:`read_audio` returned them, not read again."""
    samples, src_rate = loaded if loaded is not None else read_audio(audio_path)
    samples = resample(samples, src_rate, rate)
    need = int(round(n_frames / fps * rate))
    if abs(len(samples) - need) > MAX_AUDIO_MISMATCH_FRAMES / fps * rate:
        anim = f" ({anim_path})" if anim_path is not None else ""
        raise InputError(f"{audio_path}: the audio lasts {len(samples) / rate:.2f} s but the animation{anim} "
                         f"{n_frames / fps:.2f} s (more than {MAX_AUDIO_MISMATCH_FRAMES} frames apart); "
                         "give the audio of the utterance it was synthesized from, or trim or pad the audio to match.")
    return np.pad(samples, (0, max(0, need - len(samples))))[:need]


def label_mask(text: str, scale: int = 2) -> np.ndarray:
    """A (h, w) float mask in [0, 1] of ``text`` in Pillow's default bitmap font, enlarged
    ``scale`` times (nearest neighbour, so the same on every machine)."""
    from PIL import Image, ImageDraw, ImageFont

    font = ImageFont.load_default_imagefont() if hasattr(ImageFont, "load_default_imagefont") else ImageFont.load_default()
    left, top, right, bottom = ImageDraw.Draw(Image.new("L", (1, 1))).textbbox((0, 0), text, font=font)
    image = Image.new("L", (int(right - left) + 4, int(bottom - top) + 4), 0)
    ImageDraw.Draw(image).text((2 - left, 2 - top), text, fill=255, font=font)
    mask = np.asarray(image, np.float32) / 255.0
    return np.kron(mask, np.ones((scale, scale), np.float32))


def burn_label(frame: np.ndarray, mask: np.ndarray, x: int = 8, y: int = 8) -> np.ndarray:
    """Draw a label mask (from :func:`label_mask`) in white on a dark box at (x, y) of an RGB
    frame (H, W, 3) uint8; returns the frame (modified in place)."""
    h = min(mask.shape[0] + 4, frame.shape[0] - y)
    w = min(mask.shape[1] + 4, frame.shape[1] - x)
    if h <= 4 or w <= 4:
        return frame
    box = frame[y:y + h, x:x + w].astype(np.float32) * 0.35
    m = mask[:h - 4, :w - 4, None]
    box[2:h - 2, 2:w - 2] = box[2:h - 2, 2:w - 2] * (1 - m) + 255.0 * m
    frame[y:y + h, x:x + w] = box.round().astype(np.uint8)
    return frame


class ShadedView:
    """The shaded face of one clip: the scene (skin and procedural parts, built once from the
    rest mesh), a camera fitted once and a rasterizer, to draw frame after frame."""

    def __init__(self, clip: MeshAnimation, settings: RenderSettings, width: int):
        self.scene = build_scene(clip.rest, clip.faces)
        self.gaze = clip.gaze
        s = settings.supersample
        self.camera = Camera.fit(frame_points(self.scene), width, settings.height, settings.fov_deg, settings.yaw_deg,
                                 settings.pitch_deg).scaled(s)
        self.raster = rasterizer(self.scene.faces, self.scene.albedo, self.scene.eye, width, settings.height, s,
                                 settings.use_opencl)

    def frame(self, vertices: np.ndarray, t: int) -> np.ndarray:
        """RGB (H, W, 3) uint8 of the skin ``vertices`` (V, 3) at frame ``t``."""
        gaze = self.gaze[min(t, len(self.gaze) - 1)] if self.gaze is not None else None
        points = self.scene.positions(vertices, gaze)
        normals = vertex_normals(points, self.scene.faces, self.scene.incidence)
        return self.raster.render(self.camera.project(points), self.camera.directions(normals))


def render_frames(clip: MeshAnimation, settings: RenderSettings, compare: MeshAnimation | None = None,
                  notes: list[str] | None = None):
    """Yield RGB frames (H, W, 3) uint8 for one clip in the configured view; parts of the face
    that could not be built are appended to ``notes``."""
    view = settings.view
    width = settings.width // 2 if view == "side-by-side" else settings.width
    if view == "markers":
        camera = Camera.fit(clip.markers[0], width, settings.height, settings.fov_deg, settings.yaw_deg, settings.pitch_deg)
        for t in range(len(clip.markers)):
            yield draw_markers(camera.project(clip.markers[t].astype(np.float64)), width, settings.height)
        return
    shaded = ShadedView(clip, settings, width)
    if notes is not None:
        notes.extend(shaded.scene.notes)
    if view == "shaded":
        for t in range(len(clip.vertices)):
            yield shaded.frame(clip.vertices[t], t)
        return
    if compare is None:  # render_video refuses the view without --compare
        raise UsageError("the side-by-side view needs --compare ANIM (e.g. the ground truth deformed onto the same mesh).")
    other = ShadedView(compare, settings, width)
    masks = [label_mask(text) for text in settings.labels]  # left: the animation rendered; right: --compare
    for t in range(len(clip.vertices)):
        u = min(t, len(compare.vertices) - 1)
        left, right = shaded.frame(clip.vertices[t], t), other.frame(compare.vertices[u], u)
        yield np.concatenate([burn_label(left, masks[0]), burn_label(right, masks[1])], axis=1)


class AnimationReader:
    """Reads what ``render`` draws: a mesh animation as stored, or rig curves posed on the rig
    (read once, when the first curves come: the built-in rig when ``rig_path`` is None)."""

    def __init__(self, rig_path: Path | None, binding: Path | None, head_motion: bool):
        self.rig_path, self.binding, self.head_motion = rig_path, binding, head_motion
        self._rig: Rig | None = None

    def read(self, path: Path) -> MeshAnimation:
        """The animation at ``path`` (``meshanim`` or ``curves``) as a mesh animation."""
        if artifact_kind(path) != "curves":
            if self.rig_path is not None:
                raise UsageError(f"--rig is for rig curves; {path} is not curves (a mesh animation carries its mesh).")
            return MeshAnimation.read(path)

        if self._rig is None:
            self._rig = load_rig(self.rig_path, self.binding, need_binding=False)
        return pose_rig(RigCurves.read(path), self._rig, str(path), self.head_motion)


@dataclass(frozen=True)
class RenderedVideo:
    """What :func:`render_video` wrote.

    frames: video frames.
    seconds: the video's length (s).
    frames_per_s: frames rendered per second of wall time.
    notes: what a plain mesh lacks (eye or mouth holes), once each, sorted.
    """

    frames: int
    seconds: float
    frames_per_s: float
    notes: list[str]


def render_video(anims: list[Path], audios: list[Path], out: Path, settings: RenderSettings,
                 compare: list[Path] | None = None, overwrite: bool = False, rig_path: Path | None = None,
                 binding: Path | None = None) -> RenderedVideo:
    """Render the animations (mesh animations or rig curves) one after another, each with its
    audio (none: silence), into the AVI ``out`` (its sound 16-bit PCM at the audio files' sample
    rate, the highest of them where they differ); ``compare``: for the side-by-side view, one
    animation beside every one, or one per animation. Curves pose the rig ``rig_path`` (None:
    the built-in rig; ``binding`` its markers for the marker view).
    """
    import imageio_ffmpeg

    if audios and len(anims) != len(audios):
        raise UsageError(f"give one --audio per animation ({len(anims)} animations, {len(audios)} audio files), "
                         f"or none for a silent video.")
    compare = list(compare or [])
    if settings.view == "side-by-side" and not compare:
        raise UsageError("the side-by-side view needs --compare ANIM (e.g. the ground truth deformed onto the same mesh).")
    if len(compare) not in (0, 1, len(anims)):
        raise UsageError(f"give one --compare for all animations or one per animation ({len(anims)} animations, "
                         f"{len(compare)} --compare).")
    if out.suffix.lower() != ".avi":
        raise InputError(f"{out}: the output must be an .avi file.")
    if settings.width % 16 or settings.height % 16:
        raise InputError(f"render size {settings.width}x{settings.height}: width and height must be multiples of 16.")
    started = time.perf_counter()
    reader = AnimationReader(rig_path, binding, settings.head_motion)
    clips = [reader.read(p) for p in anims]
    others = [reader.read(p) for p in compare] if settings.view == "side-by-side" else []
    if len(others) == 1:
        others = others * len(clips)
    for path, c in zip(anims + compare, clips + others):
        if abs(c.fps - settings.fps) > 1e-6:
            raise InputError(f"{path}: animation is at {c.fps:g} fps but render.fps is {settings.fps:g}; set one to the other.")
    n_frames = sum(len(c.vertices) for c in clips)
    if audios:  # the sound at the clips' own rate (their highest where they differ): no resampling in the common case
        loaded = [read_audio(a) for a in audios]
        rate = max(r for _, r in loaded)
        audio = np.concatenate([clip_audio(a, len(c.vertices), settings.fps, rate, p, sound)
                                for c, a, p, sound in zip(clips, audios, anims, loaded)])
    else:  # a capture without audio: a silent soundtrack of the video's length
        rate = SILENCE_RATE
        audio = np.zeros(int(round(n_frames / settings.fps * rate)), np.float32)
    # The temporary audio lies beside the output (NAME.tmp-PID.wav: removed on every exit, and by
    # the next run after a kill); ffmpeg gets absolute paths, which never read as options.
    with atomic_path(out, overwrite) as tmp_out, contextlib.ExitStack() as cleanup:
        wav = tmp_out.with_name(tmp_out.name + ".wav")
        cleanup.callback(lambda: wav.unlink(missing_ok=True))
        write_wav(wav, audio, rate)
        writer = imageio_ffmpeg.write_frames(
            str(tmp_out.resolve()), (settings.width, settings.height), fps=settings.fps, codec="mjpeg", quality=9,
            ffmpeg_log_level="error",
            pix_fmt_out="yuvj420p", audio_path=str(wav.resolve()), audio_codec="pcm_s16le", macro_block_size=16,
            output_params=["-f", "avi", "-fflags", "+bitexact", "-flags:v", "+bitexact", "-flags:a", "+bitexact"],
        )
        cleanup.callback(writer.close)  # on an error ffmpeg is stopped before its audio is removed
        writer.send(None)
        notes: list[str] = []
        frames = (f for i, c in enumerate(clips) for f in render_frames(c, settings, others[i] if others else None, notes))
        for frame in progress(frames, "render", length=n_frames):
            writer.send(np.ascontiguousarray(frame))
        writer.close()
    return RenderedVideo(n_frames, n_frames / settings.fps, n_frames / (time.perf_counter() - started), sorted(set(notes)))
