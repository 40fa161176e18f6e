"""``facesynth isomap``: expressive phoneme-Isomaps (paper IV, Eq. 3, Figs. 5-7).

``build`` embeds every phoneme cluster (:mod:`facesynth.domain.database.embedding`) and writes
the ``isomap`` artifact and, with ``--images``, the pictures
(:mod:`facesynth.domain.database.isomap_images`) and their index page
(:mod:`facesynth.domain.exports.isomap_index`); ``pick`` prints the frame at a point of a map
(Fig. 7); ``page`` writes the constraint page (:mod:`facesynth.domain.exports.isomap_page`).
"""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import IngestSettings, IsomapSettings, settings_json
from facesynth.base.limits import require_memory
from facesynth.base.phonemes import PAU
from facesynth.domain import methods
from facesynth.domain.database.embedding import build_clusters, memory_estimate, picked_frame
from facesynth.domain.database.isomap_images import page_pictures
from facesynth.domain.exports import isomap_page
from facesynth.domain.exports.isomap_index import write_images
from facesynth.domain.methods import steps
from facesynth.model.artifacts import atomic_folder, atomic_path, check_output, check_output_folder, published_together
from facesynth.model.isomap import PhonemeMaps
from facesynth.model.motiondb import MotionDatabase


@dataclass(frozen=True)
class IsomapResult:
    """What ``facesynth isomap build`` embedded.

    clusters: phoneme clusters embedded.
    frames: frames over all clusters.
    embed_s: seconds spent embedding them.
    largest: frames of the largest cluster.
    notes: per phone, why a small cluster got fewer neighbours (expected; shown with -v).
    """

    clusters: int
    frames: int
    embed_s: float
    largest: int
    notes: dict[str, str]


@dataclass(frozen=True)
class Pick:
    """The frame at a point picked on a phoneme's map (``facesynth isomap pick``).

    markers: (M, 3) the frame's markers, mm.
    marker_names: their names.
    corners: the three frames (rows of the cluster) of the triangle around the point.
    weights: their barycentric weights, summing to 1.
    nodes: the motion nodes those frames belong to.
    """

    markers: np.ndarray
    marker_names: list[str]
    corners: list[int]
    weights: list[float]
    nodes: list[int]


@dataclass(frozen=True)
class PageResult:
    """What ``facesynth isomap page`` wrote.

    phones: spoken phones of the utterance.
    maps: phoneme maps on the page.
    missing: spoken phones the database has no node (and so no map) of.
    constraints: constraints given with ``--constraints``, shown on the page.
    bytes: the page's size.
    notes: warnings for the user.
    """

    phones: int
    maps: int
    missing: list[str]
    constraints: int
    bytes: int
    notes: list[str]


def run(db_path: Path, out: Path, settings: IsomapSettings, images: Path | None = None,
        overwrite: bool = False) -> IsomapResult:
    """Embed every phoneme cluster of ``db_path``, write ``out`` (an ``isomap`` artifact) and,
    with ``images``, the PNGs and ``index.html`` there."""
    check_output(out, overwrite)
    if images is not None:
        check_output_folder(images, "the images", overwrite)
    db = MotionDatabase.read(db_path)
    require_memory(memory_estimate(db.nodes, settings), "embedding the largest phoneme cluster", str(db_path))
    t0 = time.perf_counter()
    clusters = build_clusters(db.coeffs, db.nodes, settings)
    embed_s = time.perf_counter() - t0
    with published_together(), contextlib.ExitStack() as stack:  # the artifact and the images, or neither
        if images is not None:  # written beside the folder, renamed into place after the artifact
            folder = stack.enter_context(atomic_folder(images, "the images", overwrite))
            take_of_node = {k: db.takes.name[int(db.nodes.take[k])] for k in range(len(db.nodes))}
            write_images(folder, clusters, settings, take_of_node)
        PhonemeMaps(db.model, db.marker_names, {c.phone: c for c in clusters}).write(
            out, config=settings_json(settings), inputs=[db_path], overwrite=overwrite)
    small = {c.phone: c.note for c in clusters if c.note}
    return IsomapResult(len(clusters), int(sum(len(c.frames) for c in clusters)), embed_s,
                        max(len(c.frames) for c in clusters), small)


def pick(isomap_path: Path, phone: str, x: float, y: float, use_pca_map: bool = False) -> Pick:
    """Fig. 7: the frame at a picked 2D point as markers (M, 3) mm, by barycentric
    interpolation of the three captured frames of the covering triangle."""
    maps = PhonemeMaps.read(isomap_path)
    markers, corners, weights = picked_frame(maps, phone, (x, y), use_pca_map, isomap_path)
    return Pick(markers, maps.marker_names, corners.tolist(), weights.round(6).tolist(),
                maps.clusters[phone].node[corners].tolist())


def markers_csv(markers: np.ndarray, names: list[str]) -> list[str]:
    """Lines of a marker frame (M, 3) mm as CSV: ``marker,x_mm,y_mm,z_mm``."""
    return ["marker,x_mm,y_mm,z_mm"] + [f"{name},{x:.4f},{y:.4f},{z:.4f}" for name, (x, y, z) in zip(names, markers)]


def page(isomap_path: Path, db_path: Path, phones_path: Path, out: Path, settings: IsomapSettings,
         ingest_settings: IngestSettings, emotions_path: Path | None = None, constraints_path: Path | None = None,
         motion_path: Path | None = None, overwrite: bool = False) -> PageResult:
    """Write the constraint page (paper VI-A, Fig. 9) of an utterance over the maps of
    ``isomap_path`` built from ``db_path``, marking the path of the synthesized ``motion_path``."""
    check_output(out, overwrite)
    maps = PhonemeMaps.read(isomap_path)
    db = MotionDatabase.read(db_path)
    isomap_page.require_maps_of(maps, db, isomap_path, db_path)
    utt = steps.read_utterance(ingest_settings, phones_path=phones_path, emotions_path=emotions_path).utterance
    constraints = steps.constraints_for(methods.get("dp"), db, constraints_path, utt)
    missing = isomap_page.require_some_map(utt, maps, phones_path, db_path)
    path, notes = (None, []) if motion_path is None else isomap_page.checked_motion_path(
        motion_path, utt, db, phones_path, db_path)
    pictures = page_pictures(maps, utt.phones, settings)
    data = isomap_page.page_data(maps, db, utt, constraints, path, pictures,
                                 isomap_page.synthesize_command(db_path, phones_path, emotions_path))
    text = isomap_page.render_page(data, f"Constraints for {phones_path.name}", settings.image_size)
    with atomic_path(out, overwrite) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return PageResult(sum(p != PAU for p in utt.phones), len(pictures), missing, len(constraints),
                      len(text.encode("utf-8")), notes)
