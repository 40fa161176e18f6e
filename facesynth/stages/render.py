"""``facesynth render``: mesh animations -> AVI with the audio muxed in.

Views: ``shaded`` (lit, smooth-normal, depth-correct mesh from a z-buffer rasterizer on
OpenCL, with a NumPy reference), ``markers`` (the paper's marker mode: the markers as
dots) and ``side-by-side`` (the animation beside a second one, e.g. ground truth: the
left half is labelled "synthesis", the right half, ``--compare``, "capture").
The camera looks along -z at the rest mesh (+y up), fitted once so the view is steady.
Several animations render one after another into one video, each with its own audio;
every clip's audio is cut or padded to its frame count, so the first frame is at audio
time 0 and picture and sound end together.
"""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import sparse

from ..artifacts import atomic_path
from ..config import RenderSettings
from ..errors import InputError, UsageError
from ..formats.audio import read_audio, resample, write_wav
from ..model.meshanim import MeshAnimation
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
        """A camera whose view holds ``vertices`` (V, 3), steady for the whole clip."""
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
    """(V, F) sparse vertex-face incidence, to sum face normals onto vertices."""
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
        """One RGB frame (H, W, 3) uint8 from projected vertices ``screen`` (V, 4) and ``normals`` (V, 4)."""
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
        """(height, width) int32 triangle per pixel of the last frame, INT32_MAX where none."""
        import pyopencl as cl

        out = np.empty(self.width * self.height, np.int32)
        cl.enqueue_copy(self.q, out, self.ids)
        return out.reshape(self.height, self.width)


def _edge(ax, ay, bx, by, px, py):
    """``edge_fn`` of raster.cl, operation for operation in float32."""
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax)


def _cover(screen: np.ndarray, faces: np.ndarray, f: np.ndarray, x: np.ndarray, y: np.ndarray):
    """``cover`` of raster.cl for fragments (triangle f, pixel x, y): (covered, w0, w1, w2, z), float32."""
    a, b, c = (screen[faces[f, k]] for k in range(3))
    area = _edge(a[..., 0], a[..., 1], b[..., 0], b[..., 1], c[..., 0], c[..., 1])
    px = x.astype(np.float32) + np.float32(0.5)
    py = y.astype(np.float32) + np.float32(0.5)
    with np.errstate(divide="ignore", invalid="ignore"):
        w0 = _edge(b[..., 0], b[..., 1], c[..., 0], c[..., 1], px, py) / area
        w1 = _edge(c[..., 0], c[..., 1], a[..., 0], a[..., 1], px, py) / area
        w2 = _edge(a[..., 0], a[..., 1], b[..., 0], b[..., 1], px, py) / area
    z = w0 * a[..., 2] + w1 * b[..., 2] + w2 * c[..., 2]
    covered = (area != 0) & (w0 >= 0) & (w1 >= 0) & (w2 >= 0) & (z > 0)
    return covered, w0, w1, w2, z


def triangle_ids_numpy(screen: np.ndarray, faces: np.ndarray, width: int, height: int) -> np.ndarray:
    """The z-buffer of ``kernels/raster.cl`` in NumPy: per pixel the nearest triangle (lowest id
    on equal depth), -1 where none.

    screen : (V, 4) float32, pixel x, pixel y, depth (> 0 in front), 0.
    faces : (F, 3) int vertex indices.
    Returns (height, width) int64. Coverage and depth are computed with the kernel's float32
    operations in the kernel's order, so the ids equal the kernel's wherever the device rounds
    divisions correctly (PoCL on the CPU does); elsewhere a pixel on a shared edge may differ.
    Triangles are rasterized in groups of similar bounding-box size, all fragments of a group
    at once, and the nearest fragment of each pixel is found with one sort.
    """
    screen = np.ascontiguousarray(screen, np.float32)
    faces = np.asarray(faces, np.int64)
    corners = screen[faces][:, :, :2]                                   # (F, 3, 2)
    with np.errstate(invalid="ignore"):
        x0 = np.clip(np.floor(corners[:, :, 0].min(1)), 0, None)
        y0 = np.clip(np.floor(corners[:, :, 1].min(1)), 0, None)
        x1 = np.clip(np.ceil(corners[:, :, 0].max(1)), None, width - 1)
        y1 = np.clip(np.ceil(corners[:, :, 1].max(1)), None, height - 1)
    ok = np.isfinite(x0 + y0 + x1 + y1) & (x1 >= x0) & (y1 >= y0)
    idx = np.nonzero(ok)[0]
    x0, y0, x1, y1 = (v[idx].astype(np.int64) for v in (x0, y0, x1, y1))
    # Buckets by bounding box size rounded up to a power of two, so padding stays below 4x.
    bw = 1 << np.ceil(np.log2(x1 - x0 + 1)).astype(np.int64)
    bh = 1 << np.ceil(np.log2(y1 - y0 + 1)).astype(np.int64)
    pixels, depths, ids = [], [], []
    for w, h in sorted(set(zip(bw.tolist(), bh.tolist()))):
        sel = np.nonzero((bw == w) & (bh == h))[0]
        for part in np.array_split(sel, max(1, len(sel) * w * h // (1 << 22))):  # bounded memory
            ox, oy = np.meshgrid(np.arange(w), np.arange(h))
            x = x0[part, None] + ox.reshape(1, -1)
            y = y0[part, None] + oy.reshape(1, -1)
            f = np.broadcast_to(idx[part, None], x.shape)
            inside = (x <= x1[part, None]) & (y <= y1[part, None])
            x, y, f = x[inside], y[inside], f[inside]
            covered, _, _, _, z = _cover(screen, faces, f, x, y)
            pixels.append((y * width + x)[covered])
            depths.append(z[covered])
            ids.append(f[covered])
    out = np.full(height * width, -1, np.int64)
    if pixels:
        pixel, depth, face = np.concatenate(pixels), np.concatenate(depths), np.concatenate(ids)
        order = np.lexsort((face, depth, pixel))                        # nearest, then lowest id
        first = order[np.r_[True, pixel[order][1:] != pixel[order][:-1]]] if len(order) else order
        out[pixel[first]] = face[first]
    return out.reshape(height, width)


def shade_numpy(screen: np.ndarray, faces: np.ndarray, normals: np.ndarray, ids: np.ndarray) -> np.ndarray:
    """``shade`` of ``kernels/raster.cl`` in NumPy: (H, W, 3) uint8 from the triangle ids of
    :func:`triangle_ids_numpy`. Same float32 operations; a channel may differ from the kernel's
    by one level where the device's sqrt or division rounds differently."""
    height, width = ids.shape
    f32 = np.float32
    colour = np.broadcast_to(BACKGROUND, (height * width, 4)).copy()
    hit = np.nonzero(ids.reshape(-1) >= 0)[0]
    f = ids.reshape(-1)[hit]
    _, w0, w1, w2, _ = _cover(np.asarray(screen, f32), np.asarray(faces, np.int64), f, hit % width, hit // width)
    nrm = np.asarray(normals, f32)
    n = w0[:, None] * nrm[faces[f, 0]] + w1[:, None] * nrm[faces[f, 1]] + w2[:, None] * nrm[faces[f, 2]]
    length = np.sqrt(n[:, 0] * n[:, 0] + n[:, 1] * n[:, 1] + n[:, 2] * n[:, 2]) + f32(1e-12)
    n = n / length[:, None]
    key, fill = np.array([-0.35, 0.45, 0.82], f32), np.array([0.6, -0.1, 0.79], f32)
    kl = np.sqrt(key[0] * key[0] + key[1] * key[1] + key[2] * key[2])
    fl = np.sqrt(fill[0] * fill[0] + fill[1] * fill[1] + fill[2] * fill[2])
    d1 = np.maximum((n[:, 0] * key[0] + n[:, 1] * key[1] + n[:, 2] * key[2]) / kl, f32(0))
    d2 = np.maximum((n[:, 0] * fill[0] + n[:, 1] * fill[1] + n[:, 2] * fill[2]) / fl, f32(0))
    h = np.array([key[0] / kl, key[1] / kl, key[2] / kl + f32(1)], f32)
    hl = np.sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2])
    spec = np.maximum((n[:, 0] * h[0] + n[:, 1] * h[1] + n[:, 2] * h[2]) / hl, f32(0))
    for _ in range(5):  # ^32
        spec = spec * spec
    lit = SKIN[None] * (f32(0.18) + f32(0.72) * d1 + f32(0.25) * d2)[:, None] + (f32(0.25) * spec)[:, None]
    colour[hit] = np.where((n[:, 2] < 0)[:, None], SKIN[None] * f32(0.12), lit)  # back face: dark interior
    colour = np.clip(colour, f32(0), f32(1))
    return (colour[:, :3] * f32(255) + f32(0.5)).astype(np.uint8).reshape(height, width, 3)


class NumpyRasterizer:
    """The NumPy implementation of :class:`OpenCLRasterizer`, used when no OpenCL device builds."""

    def __init__(self, faces: np.ndarray, n_vertices: int, width: int, height: int):
        self.faces = np.asarray(faces, np.int64)
        self.width, self.height = width, height
        self.ids = np.full((height, width), -1, np.int64)

    def render(self, screen: np.ndarray, normals: np.ndarray) -> np.ndarray:
        """One RGB frame (H, W, 3) uint8, as :meth:`OpenCLRasterizer.render`."""
        self.ids = triangle_ids_numpy(screen, self.faces, self.width, self.height)
        return shade_numpy(screen, self.faces, normals, self.ids)

    def triangle_ids(self) -> np.ndarray:
        """(height, width) int32, INT32_MAX where no triangle (as the kernel's buffer)."""
        return np.where(self.ids < 0, np.iinfo(np.int32).max, self.ids).astype(np.int32)


def rasterizer(faces: np.ndarray, n_vertices: int, width: int, height: int, wanted: bool = True):
    """The OpenCL rasterizer when a device builds (and ``wanted``), else the NumPy one."""
    from ..opencl import use_opencl

    cls = OpenCLRasterizer if use_opencl(wanted) else NumpyRasterizer
    return cls(faces, n_vertices, width, height)


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


#: Audio may be longer or shorter than its animation by at most this many video frames;
#: the difference (rounding of the frame count) is cut or padded with silence.
MAX_AUDIO_MISMATCH_FRAMES = 2


def clip_audio(audio_path: Path, n_frames: int, fps: float, rate: int, anim_path: Path | None = None) -> np.ndarray:
    """The clip's audio at ``rate`` (samples,) float, cut or padded to exactly n_frames / fps
    seconds. An audio file longer or shorter than that by more than
    :data:`MAX_AUDIO_MISMATCH_FRAMES` frames is an InputError: it is another utterance's."""
    samples, src_rate = read_audio(audio_path)
    samples = resample(samples, src_rate, rate)
    need = int(round(n_frames / fps * rate))
    if abs(len(samples) - need) > MAX_AUDIO_MISMATCH_FRAMES / fps * rate:
        anim = f" ({anim_path})" if anim_path is not None else ""
        raise InputError(f"{audio_path}: the audio lasts {len(samples) / rate:.2f} s but the animation{anim} "
                         f"{n_frames / fps:.2f} s (more than {MAX_AUDIO_MISMATCH_FRAMES} frames apart); "
                         "give the audio of the utterance it was synthesized from, or trim or pad the audio to match.")
    return np.pad(samples, (0, max(0, need - len(samples))))[:need]


SIDE_BY_SIDE_LABELS = ("synthesis", "capture")  # left: the animation rendered; right: --compare


def label_mask(text: str, scale: int = 2) -> np.ndarray:
    """A (h, w) float mask in [0, 1] of ``text`` in Pillow's default bitmap font, enlarged
    ``scale`` times (nearest neighbour, so the same on every machine)."""
    from PIL import Image, ImageDraw, ImageFont

    font = ImageFont.load_default_imagefont() if hasattr(ImageFont, "load_default_imagefont") else ImageFont.load_default()
    left, top, right, bottom = ImageDraw.Draw(Image.new("L", (1, 1))).textbbox((0, 0), text, font=font)
    image = Image.new("L", (right - left + 4, bottom - top + 4), 0)
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


def render_frames(clip: MeshAnimation, settings: RenderSettings, compare: MeshAnimation | None = None):
    """Yield RGB frames (H, W, 3) uint8 for one clip in the configured view."""
    view = settings.view
    width = settings.width // 2 if view == "side-by-side" else settings.width
    camera = Camera.fit(clip.vertices[0], width, settings.height, settings.fov_deg)
    incidence = face_incidence(clip.vertices.shape[1], clip.faces)
    raster = rasterizer(clip.faces, clip.vertices.shape[1], width, settings.height, settings.use_opencl) if view != "markers" else None

    def shaded(vertices):
        # The camera looks along -z without rotation, so world normals are camera normals.
        return raster.render(camera.project(vertices), vertex_normals(vertices, clip.faces, incidence))

    if view == "side-by-side":
        masks = [label_mask(text) for text in SIDE_BY_SIDE_LABELS]
    if view == "markers":
        marker_camera = Camera.fit(clip.markers[0], width, settings.height, settings.fov_deg)
    for t in range(len(clip.vertices)):
        if view == "shaded":
            yield shaded(clip.vertices[t])
        elif view == "markers":
            yield draw_markers(marker_camera.project(clip.markers[t].astype(np.float64)), width, settings.height)
        else:
            other = compare.vertices[min(t, len(compare.vertices) - 1)]
            left, right = (np.array(shaded(v), np.uint8) for v in (clip.vertices[t], other))
            yield np.concatenate([burn_label(left, masks[0]), burn_label(right, masks[1])], axis=1)


def run(anims: list[Path], audios: list[Path], out: Path, settings: RenderSettings, compare: Path | None = None,
        overwrite: bool = False) -> dict:
    """Render the animations one after another, each with its audio, into the AVI ``out``;
    returns frames, seconds of video and frames rendered per second.
    """
    import imageio_ffmpeg

    if len(anims) != len(audios):
        raise UsageError(f"give one --audio per animation ({len(anims)} animations, {len(audios)} audio files).")
    if settings.view == "side-by-side" and compare is None:
        raise UsageError("the side-by-side view needs --compare ANIM (e.g. the ground truth deformed onto the same mesh).")
    if out.suffix.lower() != ".avi":
        raise InputError(f"{out}: the output must be an .avi file.")
    if settings.width % 16 or settings.height % 16:
        raise InputError(f"render size {settings.width}x{settings.height}: width and height must be multiples of 16.")
    started = time.perf_counter()
    clips = [MeshAnimation.read(p) for p in anims]
    other = MeshAnimation.read(compare) if compare else None
    for path, c in zip(anims, clips):
        if abs(c.fps - settings.fps) > 1e-6:
            raise InputError(f"{path}: animation is at {c.fps:g} fps but render.fps is {settings.fps:g}; set one to the other.")
    rate = 48000
    audio = np.concatenate([clip_audio(a, len(c.vertices), settings.fps, rate, p) for c, a, p in zip(clips, audios, anims)])
    n_frames = sum(len(c.vertices) for c in clips)
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
        frames = (f for c in clips for f in render_frames(c, settings, other))
        for frame in progress(frames, "render", length=n_frames):
            writer.send(np.ascontiguousarray(frame))
        writer.close()
    return {"frames": n_frames, "seconds": n_frames / settings.fps, "frames_per_s": n_frames / (time.perf_counter() - started)}
