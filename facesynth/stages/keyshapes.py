"""``facesynth keyshapes``: key-shapes per emotion from a motion database (Chuang & Bregler 2005
§4.1 or Huang et al. §5.2; :mod:`facesynth.domain.retarget.keyshapes`), the frames' NNLS
reconstruction error (Eq. 8) and each key-shape's keymorph fitted on the built-in rig, with an
optional contact sheet of the keymorphs rendered on the rig.

Only the database's training takes are used, so held-out takes stay unseen. Frames are the PCA
reconstructions of the database (no gaps), as displacements from its neutral reference.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import KeyshapesSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.domain.rendering.camera import Camera
from facesynth.domain.rendering.parts import build_scene, frame_points, vertex_normals
from facesynth.domain.rendering.raster import rasterizer
from facesynth.domain.retarget.keyshapes import Selection, select_affinity, select_pca
from facesynth.domain.retarget.solve import fit_rig_weights
from facesynth.domain.rig.loading import builtin_rig, marker_map
from facesynth.model.artifacts import atomic_path, check_output, published_together
from facesynth.model.keyshapes import EmotionKeyShapes, KeyShapes
from facesynth.model.motiondb import MotionDatabase

#: Key-shapes per emotion when ``count`` is 0 and the method is PCA (Chuang & Bregler §6: "about 20").
PCA_DEFAULT_COUNT = 20


def emotion_frames(db: MotionDatabase, split: str = "train") -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Per emotion: (frame rows of the database, (N, M, 3) marker displacements from the reference, mm)
    of the takes of ``split``."""
    out: dict[str, list[np.ndarray]] = {}
    for i in range(len(db.takes)):
        if db.takes.split[i] != split:
            continue
        s = db.takes.frames(i)
        out.setdefault(db.takes.emotion[i], []).append(np.arange(s.start, s.stop))
    result = {}
    for emotion, rows in sorted(out.items()):
        rows = np.concatenate(rows)
        markers = db.model.reconstruct(db.coeffs[rows])
        result[emotion] = (rows, markers - db.reference)
    return result


def select(displacements: np.ndarray, settings: KeyshapesSettings, method: str, count: int) -> Selection:
    """The key-shapes of one emotion's (N, M, 3) displacements by ``method``."""
    x = displacements.reshape(len(displacements), -1)
    if method == "pca":
        return select_pca(x, count or PCA_DEFAULT_COUNT, settings.duplicate_mm, settings.curve_frames, settings.seed)
    return select_affinity(x, count, settings.affinity_frames, settings.curve_frames, settings.seed)


def build(db: MotionDatabase, settings: KeyshapesSettings, method: str, count: int, where: str) -> KeyShapes:
    """Key-shapes of every emotion of ``db`` with keymorphs fitted on the built-in rig."""
    rig = builtin_rig()
    mmap = marker_map(rig, db.marker_names, db.reference, where)
    basis = (rig.deltas[:, mmap.vertices]).reshape(len(rig.deltas), -1)
    emotions = {}
    frames = emotion_frames(db)
    if not frames:
        raise InputError(f"{where}: no training takes; key-shapes are chosen from takes with split 'train'.")
    for emotion, (rows, disp) in frames.items():
        sel = select(disp, settings, method, count)
        key = disp[sel.frames]
        targets = mmap.displacements(key + db.reference, db.reference).reshape(len(key), -1)
        keymorphs, _ = fit_rig_weights(targets, basis, settings.keymorph_ridge)
        names = [f"{emotion}-{k + 1:02d}" for k in range(len(sel.frames))]
        emotions[emotion] = EmotionKeyShapes(
            key.astype(np.float32) + db.reference, db.coeffs[rows[sel.frames]].astype(np.float32), rows[sel.frames],
            names, keymorphs.astype(np.float32), sel.counts, sel.errors, float(sel.errors[-1]))
    solver = {"solver": "block principal pivoting on the key-shapes' Gram matrix "
                        "(scipy.optimize.nnls where markers are missing)",
              "frames": "displacements from reference, mm", "keymorph_fit": "scipy.optimize.lsq_linear bvls, bounds [0, 1]",
              "keymorph_ridge": settings.keymorph_ridge}
    return KeyShapes(emotions, list(db.marker_names), db.reference, method, count, solver, rig.name, rig.sha256,
                     list(rig.shape_names))


def contact_sheet(keyshapes: KeyShapes, out: Path, tile: int = 192, columns: int = 10) -> None:
    """A PNG grid of every keymorph rendered on the built-in rig, one row per emotion, labelled."""
    from PIL import Image, ImageDraw

    rig = builtin_rig()
    scene = build_scene(rig.neutral, rig.faces)
    camera = Camera.fit(frame_points(scene), tile, tile, 24.0).scaled(2)
    raster = rasterizer(scene.faces, scene.albedo, scene.eye, tile, tile, 2, False)
    rows = []
    for e in keyshapes.emotions.values():
        if e.keymorphs is None:  # key-shapes as build() makes them have keymorphs
            raise ValueError("the contact sheet shows the keymorphs, and these key-shapes have none")
        for start in range(0, e.count, columns):
            rows.append([(name, w) for name, w in zip(e.names[start:start + columns], e.keymorphs[start:start + columns])])
    sheet = Image.new("RGB", (tile * columns, tile * max(len(rows), 1)), (0, 0, 0))
    draw = ImageDraw.Draw(sheet)
    for r, row in enumerate(rows):
        for c, (name, w) in enumerate(row):
            points = scene.positions(rig.evaluate(w).astype(np.float32), None)
            normals = vertex_normals(points, scene.faces, scene.incidence)
            image = raster.render(camera.project(points), camera.directions(normals))
            sheet.paste(Image.fromarray(image), (c * tile, r * tile))
            draw.text((c * tile + 4, r * tile + 4), name, fill=(255, 255, 255))
    sheet.save(out, format="PNG")


@dataclass(frozen=True)
class EmotionKeyshapes:
    """One emotion's key-shapes: ``count`` chosen, fitting its frames with an RMS of ``rms_mm`` (mm)."""

    count: int
    rms_mm: float


@dataclass(frozen=True)
class KeyshapesResult:
    """What ``facesynth keyshapes`` chose.

    emotions: per emotion, its key-shapes' count and fit (:class:`EmotionKeyshapes`).
    method: how they were chosen ('pca' or 'affinity').
    """

    emotions: dict[str, EmotionKeyshapes]
    method: str


def run(db_path: Path, out: Path, settings: KeyshapesSettings, sheet: Path | None = None,
        overwrite: bool = False) -> KeyshapesResult:
    """Choose key-shapes from ``db_path`` and write ``out`` (and the contact sheet ``sheet``)."""
    check_output(out, overwrite)
    if sheet is not None:
        check_output(sheet, overwrite)
        if sheet.suffix.lower() != ".png":
            raise InputError(f"{sheet}: the contact sheet is a PNG image; give a .png path.")
    db = MotionDatabase.read(db_path)
    result = build(db, settings, settings.method, settings.count, str(db_path))
    with published_together():  # the artifact and its sheet, or neither
        result.write(out, config=settings_json(settings), inputs=[db_path], overwrite=overwrite)
        if sheet is not None:
            with atomic_path(sheet, overwrite) as tmp:
                contact_sheet(result, tmp)
    return KeyshapesResult({e: EmotionKeyshapes(k.count, k.rms) for e, k in result.emotions.items()}, settings.method)

