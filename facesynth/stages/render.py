"""``facesynth render``: mesh animations -> AVI with the audio muxed in.

Views: ``shaded`` (lit, smooth-normal, depth-correct mesh from a z-buffer rasterizer on
OpenCL, with a NumPy reference), ``markers`` (the paper's marker mode: the markers as
dots) and ``side-by-side`` (the animation beside a second one, e.g. ground truth).
The camera looks along -z at the rest mesh (+y up), fitted once so the view is steady.
Several animations render one after another into one video, each with its own audio;
every clip's audio is cut or padded to its frame count, so the first frame is at audio
time 0 and picture and sound end together.
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import sparse

from ..artifacts import atomic_path, open_artifact, read
from ..config import RenderSettings
from ..errors import InputError
from ..formats.audio import read_audio, resample, write_wav
from ..progress import progress

SKIN = np.array([0.86, 0.68, 0.58, 1.0], np.float32)
BACKGROUND = np.array([0.10, 0.11, 0.13, 1.0], np.float32)


@dataclass
class Camera:
    """Perspective camera on the +z side of the mesh, looking along -z."""

    eye: np.ndarray
    focal_px: float
    width: int
    height: int

    @classmethod
    def fit(cls, vertices: np.ndarray, width: int, height: int, fov_deg: float) -> "Camera":
        lo, hi = vertices.min(0), vertices.max(0)
        centre = (lo + hi) / 2
        half = 0.55 * max((hi[1] - lo[1]), (hi[0] - lo[0]) * height / width)
        focal = 0.5 * height / np.tan(np.deg2rad(fov_deg) / 2)
        # Far enough in front of the nearest point that the half-extent fills the frame.
        return cls(np.array([centre[0], centre[1], hi[2] + half * focal / (0.5 * height)]), focal, width, height)

    def project(self, points: np.ndarray) -> np.ndarray:
        """(n, 3) -> (n, 4) float32: pixel x, pixel y, depth (> 0 in front), 0."""
        c = points - self.eye
        depth = -c[:, 2]
        safe = np.where(depth > 1e-6, depth, 1e-6)
        x = self.width / 2 + self.focal_px * c[:, 0] / safe
        y = self.height / 2 - self.focal_px * c[:, 1] / safe
        return np.stack([x, y, depth, np.zeros_like(x)], 1).astype(np.float32)


def vertex_normals(vertices: np.ndarray, faces: np.ndarray, incidence: sparse.csr_matrix) -> np.ndarray:
    """Area-weighted smooth vertex normals, (V, 4) float32 (w = 0)."""
    a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
    n = incidence @ np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-12
    return np.concatenate([n, np.zeros((len(n), 1))], 1).astype(np.float32)


def face_incidence(n_vertices: int, faces: np.ndarray) -> sparse.csr_matrix:
    rows = faces.reshape(-1)
    cols = np.repeat(np.arange(len(faces)), 3)
    return sparse.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(n_vertices, len(faces)))


class OpenCLRasterizer:
    """Three-pass z-buffer rasterizer (``kernels/raster.cl``); one instance per mesh and size."""

    def __init__(self, faces: np.ndarray, n_vertices: int, width: int, height: int):
        import pyopencl as cl

        from ..opencl import context, kernel, queue

        self.ctx, self.q = context(), queue()
        self.k_depth, self.k_ids, self.k_shade = (kernel("raster", k) for k in ("raster_depth", "raster_ids", "shade"))
        mf = cl.mem_flags
        self.n_faces, self.width, self.height = len(faces), width, height
        self.faces = cl.Buffer(self.ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=faces.astype(np.int32).ravel())
        self.screen = cl.Buffer(self.ctx, mf.READ_ONLY, 16 * n_vertices)
        self.normals = cl.Buffer(self.ctx, mf.READ_ONLY, 16 * n_vertices)
        self.zbuf = cl.Buffer(self.ctx, mf.READ_WRITE, 4 * width * height)
        self.ids = cl.Buffer(self.ctx, mf.READ_WRITE, 4 * width * height)
        self.rgb = cl.Buffer(self.ctx, mf.WRITE_ONLY, 3 * width * height)
        self.big = np.full(width * height, np.iinfo(np.int32).max, np.int32)

    def render(self, screen: np.ndarray, normals: np.ndarray) -> np.ndarray:
        import pyopencl as cl

        q = self.q
        cl.enqueue_copy(q, self.screen, screen)
        cl.enqueue_copy(q, self.normals, normals)
        cl.enqueue_copy(q, self.zbuf, self.big)
        cl.enqueue_copy(q, self.ids, self.big)
        w, h, n = np.int32(self.width), np.int32(self.height), np.int32(self.n_faces)
        self.k_depth(q, (self.n_faces,), None, self.screen, self.faces, n, w, h, self.zbuf)
        self.k_ids(q, (self.n_faces,), None, self.screen, self.faces, n, w, h, self.zbuf, self.ids)
        self.k_shade(q, (self.width, self.height), None, self.screen, self.faces, self.normals, self.ids, w, h,
                     SKIN, BACKGROUND, self.rgb)
        out = np.empty((self.height, self.width, 3), np.uint8)
        cl.enqueue_copy(q, out, self.rgb)
        return out

    def triangle_ids(self) -> np.ndarray:
        import pyopencl as cl

        out = np.empty(self.width * self.height, np.int32)
        cl.enqueue_copy(self.q, out, self.ids)
        return out.reshape(self.height, self.width)


def triangle_ids_numpy(screen: np.ndarray, faces: np.ndarray, width: int, height: int) -> np.ndarray:
    """Reference z-buffer: the nearest triangle per pixel (lowest id on equal depth), -1 if none."""
    depth = np.full((height, width), np.inf, np.float32)
    ids = np.full((height, width), -1, np.int64)
    for f, (a, b, c) in enumerate(screen[faces][:, :, :3].astype(np.float32)):
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if area == 0:
            continue
        x0, x1 = max(int(np.floor(min(a[0], b[0], c[0]))), 0), min(int(np.ceil(max(a[0], b[0], c[0]))), width - 1)
        y0, y1 = max(int(np.floor(min(a[1], b[1], c[1]))), 0), min(int(np.ceil(max(a[1], b[1], c[1]))), height - 1)
        if x1 < x0 or y1 < y0:
            continue
        px, py = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        e = lambda p, q: (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0])  # noqa: E731
        w0, w1, w2 = e(b, c) / area, e(c, a) / area, e(a, b) / area
        z = (w0 * a[2] + w1 * b[2] + w2 * c[2]).astype(np.float32)
        inside = (w0 >= 0) & (w1 >= 0) & (w2 >= 0) & (z > 0)
        region = depth[y0 : y1 + 1, x0 : x1 + 1]
        better = inside & (z < region)
        region[better] = z[better]
        ids[y0 : y1 + 1, x0 : x1 + 1][better] = f
    return ids


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


@dataclass
class Clip:
    vertices: np.ndarray   # (T, V, 3)
    faces: np.ndarray
    markers: np.ndarray    # (T, M, 3) mm, head frame
    fps: float
    path: Path


def read_clip(path: Path) -> Clip:
    with open_artifact(path, "meshanim") as f:
        return Clip(read(f, "vertices"), read(f, "faces").astype(np.int64), read(f, "markers"),
                    float(f["vertices"].attrs["fps"]), Path(path))


def clip_audio(audio_path: Path, n_frames: int, fps: float, rate: int) -> np.ndarray:
    """The clip's audio at ``rate``, cut or padded to exactly n_frames / fps seconds."""
    samples, src_rate = read_audio(audio_path)
    samples = resample(samples, src_rate, rate)
    need = int(round(n_frames / fps * rate))
    if len(samples) < need - int(0.5 * rate):
        raise InputError(f"{audio_path}: the audio lasts {len(samples) / rate:.2f} s but the motion {n_frames / fps:.2f} s; use the utterance's own audio.")
    return np.pad(samples, (0, max(0, need - len(samples))))[:need]


def render_frames(clip: Clip, settings: RenderSettings, compare: Clip | None = None):
    """Yield RGB frames (H, W, 3) uint8 for one clip in the configured view."""
    view = settings.view
    width = settings.width // 2 if view == "side-by-side" else settings.width
    camera = Camera.fit(clip.vertices[0], width, settings.height, settings.fov_deg)
    incidence = face_incidence(clip.vertices.shape[1], clip.faces)
    raster = OpenCLRasterizer(clip.faces, clip.vertices.shape[1], width, settings.height) if view != "markers" else None

    def shaded(vertices):
        # The camera looks along -z without rotation, so world normals are camera normals.
        return raster.render(camera.project(vertices), vertex_normals(vertices, clip.faces, incidence))

    if view == "markers":
        marker_camera = Camera.fit(clip.markers[0], width, settings.height, settings.fov_deg)
    for t in range(len(clip.vertices)):
        if view == "shaded":
            yield shaded(clip.vertices[t])
        elif view == "markers":
            yield draw_markers(marker_camera.project(clip.markers[t].astype(np.float64)), width, settings.height)
        else:
            other = compare.vertices[min(t, len(compare.vertices) - 1)]
            yield np.concatenate([shaded(clip.vertices[t]), shaded(other)], axis=1)


def run(anims: list[Path], audios: list[Path], out: Path, settings: RenderSettings, compare: Path | None = None,
        overwrite: bool = False) -> dict:
    import imageio_ffmpeg

    if len(anims) != len(audios):
        raise InputError(f"give one --audio per animation ({len(anims)} animations, {len(audios)} audio files).")
    if settings.view == "side-by-side" and compare is None:
        raise InputError("the side-by-side view needs --compare ANIM (e.g. the ground truth deformed onto the same mesh).")
    if out.suffix.lower() != ".avi":
        raise InputError(f"{out}: the output must be an .avi file.")
    if settings.width % 16 or settings.height % 16:
        raise InputError(f"render size {settings.width}x{settings.height}: width and height must be multiples of 16.")
    clips = [read_clip(p) for p in anims]
    other = read_clip(compare) if compare else None
    rate = 48000
    audio = np.concatenate([clip_audio(a, len(c.vertices), settings.fps, rate) for c, a in zip(clips, audios)])
    for c in clips:
        if abs(c.fps - settings.fps) > 1e-6:
            raise InputError(f"{c.path}: animation is at {c.fps:g} fps but render.fps is {settings.fps:g}; set one to the other.")
    n_frames = sum(len(c.vertices) for c in clips)
    with tempfile.TemporaryDirectory() as tmp, atomic_path(out, overwrite) as tmp_out:
        wav = Path(tmp) / "audio.wav"
        write_wav(wav, audio, rate)
        writer = imageio_ffmpeg.write_frames(
            str(tmp_out), (settings.width, settings.height), fps=settings.fps, codec="mjpeg", quality=9,
            ffmpeg_log_level="error",
            pix_fmt_out="yuvj420p", audio_path=str(wav), audio_codec="pcm_s16le", macro_block_size=16,
            output_params=["-f", "avi", "-fflags", "+bitexact", "-flags:v", "+bitexact", "-flags:a", "+bitexact"],
        )
        writer.send(None)
        frames = (f for c in clips for f in render_frames(c, settings, other))
        for frame in progress(frames, "render", length=n_frames):
            writer.send(np.ascontiguousarray(frame))
        writer.close()
    return {"frames": n_frames, "seconds": n_frames / settings.fps}
