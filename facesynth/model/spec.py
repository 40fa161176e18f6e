"""The specification of every artifact kind, as data: what ``facesynth check`` validates and
what ``docs/file-format.md`` lists.

For each kind and schema it declares every group (with the ``encoding-type`` its writer
stamps on it) and every dataset: dtype, shape in symbols, unit, the attributes it must
carry, whether its numbers must be finite and whether it is required. The facts come from
the writers in this package (one per kind); ``tests/test_check.py`` writes every kind from
the tiny sample corpus and checks it against this specification, so the two cannot drift.

Shapes are tuples of sizes: an int is a fixed size, a symbol (see :data:`SYMBOLS`) has one
size throughout the file (``facesynth check`` takes the size most keys agree on as right);
``"3M"`` is three times M and ``"V+1"`` is V plus one. The symbols a group with a pattern
name (``<phone>``) lists in its ``local`` have one size within each such group.

``python -m facesynth.model.spec docs/file-format.md`` rewrites the generated part of that
document from :func:`markdown`; without an argument it prints it.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.pipeline import producers, writers
from facesynth.base.registry import ARTIFACT_KINDS

from .kinds import ENCODING_VERSION

#: What each shape symbol counts.
SYMBOLS: dict[str, str] = {
    "F": "frames at the capture rate (all takes of a corpus-side artifact; a motion's capture-rate frames)",
    "Fo": "frames at the output rate (a motion's and a mesh animation's frames)",
    "M": "markers",
    "T": "takes",
    "P": "phone segments of the takes",
    "S": "audio samples of all takes",
    "K": "PCA components",
    "N": "motion nodes",
    "D": "DSC features per node: (build_db.dsc_samples - 2) x K",
    "Q": "pivots of the PGap/VGap bounds",
    "R": "nodes removed by every prune so far",
    "U": "phones of a synthesized utterance (steps of the search)",
    "V": "mesh vertices",
    "Tri": "mesh triangles",
    "B": "markers bound to the mesh",
    "W": "stored (non-zero) deformation weights",
    "n": "frames of one phoneme cluster",
    "ti": "Delaunay triangles of one cluster's Isomap",
    "tp": "Delaunay triangles of one cluster's PCA map",
    "Es": "emotions (styles) of a bilinear expression model",
    "Kb": "PCA components of a bilinear expression model",
    "J": "content dimension of a bilinear expression model",
    "It": "iterations of the bilinear fit",
    "Sq": "sentences a bilinear expression model was fitted on",
    "Fh": "frames of a synthesized head motion",
    "Pf": "pitch frames of a synthesized head motion",
    "G": "pitch segments of a synthesized head motion",
    "E": "shapes of a blendshape rig",
    "L": "emotions with key-shapes",
    "k": "key-shapes of one emotion",
    "c": "points of one emotion's reconstruction-error curve",
    "Kt": "key-shapes of a trajectory model (every emotion's, joined)",
    "Ph": "phones with a Gaussian in a trajectory model",
    "Pe": "(phone, emotion) pairs with a Gaussian of their own in a trajectory model",
    "Pc": "phone types of a coarticulation model (a phone with its emotion, or the pause)",
    "Ya": "curves an articulation model predicts",
    "Ca": "offsets of an articulation model's context",
    "Da": "voice features per analysis frame of an articulation model",
    "Xa": "columns of an articulation model's context (offsets times features, loudness hinges included)",
    "Kn": "loudness knots of an articulation model",
}

#: The largest magnitude of any float in an artifact where numbers must be finite (mm, s, costs,
#: PCA coefficients: real values stay many orders below; a larger one is damage, and would
#: overflow float32 sums of squares downstream).
MAX_FLOAT = 1e15

#: The largest magnitude of any integer in an artifact (indices and counts; 2**53 is where
#: float64 stops holding every integer).
MAX_INT = 2**53

#: The dtypes a dataset may be declared with.
DTYPES = ("float32", "float64", "int32", "int64", "bool", "str")

#: Attribute types: a UTF-8 string, an integer, a number, a JSON string, a 1-D integer array.
ATTR_TYPES = ("str", "int", "float", "json", "ints")

_SIZE = re.compile(r"^(\d*)([A-Za-z][A-Za-z0-9]*)(?:\+(\d+))?$")

Required = bool | str
"""True (always), False (optional) or a variant's name (required in that variant, optional otherwise)."""


@dataclass(frozen=True)
class Attr:
    """An attribute of a group, a dataset or the file's root.

    type : one of :data:`ATTR_TYPES`. choices : the allowed strings. ge, gt, le : bounds of a
    number. shape : for type ``ints``, the symbols its values are the sizes of (e.g. ("V", "B")).
    """

    name: str
    type: str
    doc: str = ""
    choices: tuple[str, ...] | None = None
    ge: float | None = None
    gt: float | None = None
    le: float | None = None
    shape: tuple[str, ...] | None = None
    required: Required = True


@dataclass(frozen=True)
class Dataset:
    """A dataset: dtype (one of :data:`DTYPES`, or a tuple of those allowed), shape in symbols,
    the unit of its numbers (stored as the ``units`` attribute when ``attrs`` lists it),
    whether every number must be finite (True, False, or only in the named variant), and the
    range of its numbers: ``ge`` a lower bound, ``below`` a symbol whose size every number must
    stay under (an index into the rows that symbol counts)."""

    name: str
    dtype: str | tuple[str, ...]
    shape: tuple[str | int, ...]
    doc: str
    unit: str | None = None
    attrs: tuple[Attr, ...] = ()
    finite: Required = True
    required: Required = True
    ge: float | None = None
    below: str | None = None


@dataclass(frozen=True)
class Group:
    """A group stamped with ``encoding-type`` = ``encoding``. A name in angle brackets
    (``<phone>``) stands for any number of groups of any name, each laid out alike; their
    ``local`` symbols are bound afresh in each."""

    name: str
    encoding: str
    doc: str
    children: tuple[Entry, ...]
    attrs: tuple[Attr, ...] = ()
    required: Required = True
    local: tuple[str, ...] = ()

    @property
    def pattern(self) -> bool:
        return self.name.startswith("<")


@dataclass(frozen=True)
class Block:
    """Entries several kinds share at their root, written by one function of the model layer."""

    name: str
    doc: str
    entries: tuple[Entry, ...]


Entry = Dataset | Group


@dataclass(frozen=True)
class Kind:
    """An artifact kind at one schema: its root entries (shared blocks included) and root
    attributes beyond the common ones. ``variant_attr`` names the root attribute that selects
    a variant (absent: ``variants[0]``). The commands that write it are declared with the
    stages (:func:`facesynth.base.pipeline.writers`)."""

    name: str
    schema: int
    doc: str
    entries: tuple[Entry | Block, ...]
    attrs: tuple[Attr, ...] = ()
    variant_attr: str | None = None
    variants: tuple[str, ...] = ()

    @property
    def producers(self) -> tuple[str, ...]:
        """The commands that write this kind, in pipeline order."""
        return writers(self.name)

    @property
    def root(self) -> tuple[Entry, ...]:
        """Every root entry, the shared blocks' spelled out."""
        out: list[Entry] = []
        for e in self.entries:
            out.extend(e.entries if isinstance(e, Block) else (e,))
        return tuple(out)

    def variant(self, root_attrs) -> str | None:
        """The variant a file with these root attributes is in (None for a kind without variants)."""
        if not self.variant_attr:
            return None
        value = root_attrs.get(self.variant_attr, self.variants[0])
        return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def applies(flag: Required, variant: str | None) -> bool:
    """Whether a ``required``/``finite`` flag holds in ``variant``."""
    return flag is True or (isinstance(flag, str) and flag == variant)


def parse_size(size: str | int) -> tuple[int, str | None, int]:
    """A shape entry as (factor, symbol, offset): size = factor * symbol + offset (symbol None:
    the fixed size ``offset``)."""
    if isinstance(size, int):
        return 1, None, size
    m = _SIZE.match(size)
    if not m:
        raise ValueError(f"bad shape entry {size!r}")
    return int(m.group(1) or 1), m.group(2), int(m.group(3) or 0)


# ---------------------------------------------------------------- shared pieces

def _fps(doc: str = "frames/s") -> Attr:
    return Attr("fps", "float", doc, gt=0)


def _units(unit: str) -> Attr:
    return Attr("units", "str", f"always {unit!r}", choices=(unit,))


MM = _units("mm")
SECONDS = _units("s")

#: Root attributes of every artifact.
COMMON_ATTRS: tuple[Attr, ...] = (
    Attr("facesynth_kind", "str", "the kind: one of the registered kinds below"),
    Attr("facesynth_schema", "int", "layout version of that kind; bumped on an incompatible change", ge=1),
    Attr("facesynth_version", "str", "the facesynth version that wrote it"),
    Attr("config", "json", "the resolved settings of the stage's configuration section"),
    Attr("inputs", "json", "list of `{path, kind, sha256}` of the files it was made from"),
)

TABLES = Block("tables", "The corpus tables, copied forward by every corpus-side stage (`corpus` to `motiondb`).", (
    Group("takes", "takes", "one row per take; its frames are `frame_start : frame_start + frame_count`", (
        Dataset("name", "str", ("T",), "take name"),
        Dataset("emotion", "str", ("T",), "emotion label"),
        Dataset("sentence", "str", ("T",), "sentence id"),
        Dataset("split", "str", ("T",), "`train`, `val` or `test`"),
        Dataset("transcript", "str", ("T",), "what is said"),
        Dataset("frame_start", "int64", ("T",), "first frame of the take in the frame arrays"),
        Dataset("frame_count", "int64", ("T",), "frames of the take"),
    )),
    Group("phones", "phones", "one row per phone segment", (
        Dataset("take", "int64", ("P",), "row of `takes`"),
        Dataset("start", "float64", ("P",), "start, from the take's first frame", "s", (SECONDS,)),
        Dataset("end", "float64", ("P",), "end, from the take's first frame", "s", (SECONDS,)),
        Dataset("phone", "str", ("P",), "Festival phone (Table VI set), `pau` for silence"),
        Dataset("emotion", "str", ("P",), "emotion of the phone (from the alignment's emotion tier, else its take's); "
                "absent in files written before it existed, read then as the take's", required=False),
        Dataset("ipa", "str", ("P",), "the IPA phone pronounced (takes in another language than English; `phone` "
                "is then its nearest English phone), empty for English phones and pauses; absent when every take "
                "is English", required=False),
    )),
    Dataset("marker_names", "str", ("M",), "marker order of every marker array"),
))

HEAD_FRAMES = Block("head-frames", "The normalized frames and the head motion removed from them (paper III, "
                    "Eq. 1-2), copied forward from `normalized`.", (
    Dataset("markers", "float32", ("F", "M", 3), "head motion removed; NaN where a gap was too long to fill",
            "mm", (MM, _fps(), Attr("origin_marker", "str", "the marker placed at the origin")), finite=False),
    Dataset("head_rotation", "float32", ("F", 3, 3), "`captured = head_rotation @ normalized + head_translation`",
            None, (_fps(), Attr("convention", "str", "this formula, as text"))),
    Dataset("head_translation", "float32", ("F", 3), "see `head_rotation`", "mm", (MM, _fps())),
    Dataset("reference", "float32", ("M", 3), "the neutral closed-mouth reference frame `y` of Eq. 1", "mm", (MM,)),
))

PCA_MODEL = Block("pca-model", "The PCA model of marker frames (Eq. 11); a frame's markers are packed "
                  "marker-major into a 3M vector (index = 3 * marker + axis).", (
    Group("pca", "pca-model", "the model", (
        Dataset("mean", "float64", ("3M",), "MeanMotion of Eq. 11", "mm"),
        Dataset("basis", "float64", ("3M", "K"), "EigMx of Eq. 11, orthonormal columns"),
        Dataset("variances", "float64", ("K",), "variance along each component", "mm^2"),
    ), attrs=(Attr("explained", "float", "fraction of the total variance the K components cover", ge=0, le=1),
              Attr("layout", "str", "`vector index = 3 * marker + axis`"))),
))


# ---------------------------------------------------------------- the kinds

CORPUS = Kind("corpus", 1, "The ingested capture (paper III): every take concatenated.", (
    Dataset("markers", "float32", ("F", "M", 3), "raw capture, head motion in; NaN where a marker was not seen",
            "mm", (MM, _fps()), finite=False),
    Dataset("rigid", "bool", ("M",), "true: the marker moves only with the head (the binding's `rigid` column), "
            "the set `normalize` fits the head pose on; all false when the corpus names none", required=False),
    Dataset("rest_pose", "float32", ("M", 3), "the markers at rest (every weight 0, no head motion) when every take "
            "was posed from curves (Live Link Face, another rig's curves): `normalize`'s reference", "mm", (MM,),
            required=False),
    Dataset("known_head_rotation", "float32", ("F", 3, 3), "with `rest_pose`: the head rotation each frame was posed "
            "with, `markers = known_head_rotation @ posed + known_head_translation`", required=False),
    Dataset("known_head_translation", "float32", ("F", 3), "with `rest_pose`: see `known_head_rotation`", "mm", (MM,),
            required=False),
    TABLES,
    Group("audio", "audio", "all takes' audio, mono, concatenated", (
        Dataset("samples", "float32", ("S",), "samples of every take, one after another"),
        Dataset("start", "int64", ("T",), "first sample of each take"),
        Dataset("count", "int64", ("T",), "samples of each take"),
    ), attrs=(Attr("sample_rate", "int", "samples/s", gt=0),)),
))

NORMALIZED = Kind("normalized", 1, "The capture with head motion removed (paper III, Eq. 1-2).", (
    TABLES, HEAD_FRAMES,
), attrs=(Attr("capture", "str", "`posed`: every take was posed from curves and its known rest pose is the reference "
               "and its known head pose removed (noise-free markers; `solve.posed_captures`); `markers`: a capture "
               "(absent in files written before it, read as `markers`)", choices=("markers", "posed"),
               required=False),))

PCA = Kind("pca", 1, "The normalized frames and their PCA coefficients (paper III, Eq. 11).", (
    TABLES, PCA_MODEL,
    Dataset("coefficients", "float32", ("F", "K"), "PcaCoef of Eq. 11 per frame", "mm", (MM, _fps())),
    HEAD_FRAMES,
))


# schema 2: per-node transition features instead of (N, N) pair tables
MOTIONDB = Kind("motiondb", 2, (
    "The motion-node database (paper III, VI-B): a node per training phone, the frames they index "
    "(the phoneme clusters) and per node the features from which the transition terms of Table I "
    "of any pair are computed on demand (the file grows linearly with the nodes; schema 1 stored "
    "(N, N) pair tables and must be rebuilt). `facesynth prune` writes the same kind with the `pruned` group."), (
    TABLES, PCA_MODEL, HEAD_FRAMES,
    Dataset("coefficients", "float32", ("F", "K"), "PcaCoef of Eq. 11 per frame; nodes index these frames", "mm",
            (_fps(),)),
    Group("nodes", "nodes", "one row per motion node", (
        Dataset("phone", "str", ("N",), "the node's phone"),
        Dataset("emotion", "str", ("N",), "emotion of its take"),
        Dataset("prev_phone", "str", ("N",), "triphone context before (`pau` at sentence edges)"),
        Dataset("next_phone", "str", ("N",), "triphone context after (`pau` at sentence edges)"),
        Dataset("viseme", "int64", ("N",), "Table VI class of the phone"),
        Dataset("take", "int64", ("N",), "row of `takes`"),
        Dataset("frame_start", "int64", ("N",), "first frame in `coefficients`"),
        Dataset("frame_count", "int64", ("N",), "frames of the node"),
        Dataset("start_s", "float64", ("N",), "the phone's start in its take", "s"),
        Dataset("end_s", "float64", ("N",), "the phone's end in its take", "s"),
        Dataset("pre", "int64", ("N",), "captured predecessor node, -1 if none"),
        Dataset("suc", "int64", ("N",), "captured successor node, -1 if none"),
        Dataset("ipa", "str", ("N",), "the IPA phone the node pronounces (a take in another language than English; "
                "`phone` is then its nearest English phone, and the search matches it by its articulatory "
                "features), empty for English phones; absent when every take is English", required=False),
    )),
    Group("frames", "phoneme-clusters", "per frame: its node; a phoneme cluster is the frames whose node has that phone", (
        Dataset("node", "int64", ("F",), "node of each frame, -1 outside nodes (pauses, held-out takes)",
                attrs=(Attr("meaning", "str", "what the values are"),)),
        Dataset("relative_time", "float32", ("F",), "0 to 1 inside the frame's node, NaN outside",
                attrs=(Attr("meaning", "str", "what the values are"),), finite=False),
    )),
    Group("boundary", "boundary-states", "the node boundary states behind Eq. 8-9 (3M vectors): "
          "PGap(i, j) and VGap(i, j) are computed from them on demand", (
        Dataset("first_pos", "float32", ("N", "3M"), "markers of the node's first frame", "mm"),
        Dataset("last_pos", "float32", ("N", "3M"), "markers of the node's last frame", "mm"),
        Dataset("first_vel", "float32", ("N", "3M"), "velocity at the node's first frame", "mm/frame"),
        Dataset("last_vel", "float32", ("N", "3M"), "velocity at the node's last frame", "mm/frame"),
    )),
    Group("transition", "transition-features", "per-node features of Table I's pair terms: "
          "DSC(o_i, pre(o_j)) = dsc_scale[j] * |dsc_out[i] + dsc_in[j]|^2 (Eq. 6), and pivot distances "
          "that bound PGap/VGap for the pruned search; no (N, N) table is stored", (
        Dataset("dsc_out", "float32", ("N", "D"), "second differences of (1 - s) warp(o_i), D = (dsc_samples - 2) K",
                "mm", (MM,)),
        Dataset("dsc_in", "float32", ("N", "D"), "second differences of s pre(o_j); 0 where o_j has no predecessor",
                "mm", (MM,)),
        Dataset("dsc_scale", "float32", ("N",), "1 / (frames between samples of pre(o_j))^3; 0 without predecessor",
                "1/frame^3", (_units("1/frame^3"),), ge=0),
        Dataset("pivot_last_pos", "float32", ("N", "Q"), "sum over markers of the distance of last_pos from each position pivot",
                "mm", (MM,), ge=0),
        Dataset("pivot_first_pos", "float32", ("N", "Q"), "the same for first_pos", "mm", (MM,), ge=0),
        Dataset("pivot_last_vel", "float32", ("N", "Q"), "the same for last_vel and the velocity pivots", "mm/frame",
                (_units("mm/frame"),), ge=0),
        Dataset("pivot_first_vel", "float32", ("N", "Q"), "the same for first_vel", "mm/frame", (_units("mm/frame"),), ge=0),
    )),
    Group("pruned", "pruned", "what `facesynth prune` removed (a pruned database only)", (
        Dataset("original_id", "int64", ("N",), "each kept node's id in the unpruned database"),
        Dataset("removed_id", "int64", ("R",), "every removed id, all prunes so far"),
        Dataset("reason", "str", ("R",), "why each was removed"),
    ), required=False),
))

ISOMAP = Kind("isomap", 1, (
    "Phoneme-Isomaps (paper IV, Eq. 3, Fig. 7): per phoneme cluster two 2D maps with their Delaunay "
    "triangles, and the PCA model and marker names that turn a picked point into markers (Eq. 11)."), (
    PCA_MODEL,
    Dataset("marker_names", "str", ("M",), "marker order"),
    Group("clusters", "phoneme-maps", "one group per phoneme cluster", (
        Group("<phone>", "phoneme-map", "the cluster of frames whose node has phone `<phone>`", (
            Dataset("frames", "int64", ("n",), "the cluster's frames (rows of the database's `coefficients`)"),
            Dataset("node", "int64", ("n",), "their nodes"),
            Dataset("relative_time", "float64", ("n",), "position in the node, 0 to 1"),
            Dataset("emotion", "str", ("n",), "emotion of each frame"),
            Dataset("coefficients", "float32", ("n", "K"), "the frames themselves", "mm"),
            Dataset("isomap", "float64", ("n", 2), "the 2D Isomap of Eq. 3"),
            Dataset("isomap_triangles", "int32", ("ti", 3), "Delaunay triangles of `isomap` (rows of the cluster)"),
            Dataset("pca_map", "float64", ("n", 2), "projection on the cluster's two main axes"),
            Dataset("pca_map_triangles", "int32", ("tp", 3), "Delaunay triangles of `pca_map` (rows of the cluster)"),
        ), attrs=(Attr("n_neighbors", "int", "Isomap neighbours used (0: shown as the PCA map)", ge=0),
                  Attr("exact_frames", "int", "frames embedded exactly (the rest by the out-of-sample extension)", ge=0),
                  Attr("note", "str", "why fewer neighbours were used, or empty")),
            local=("n", "ti", "tp")),
    )),
))

_HEAD_CONVENTION = Attr("convention", "str", "how the head motion applies")

MOTION = Kind("motion", 2, (
    "Marker motion in the head frame, with the head motion beside it. `facesynth synthesize` writes the "
    "`synthesis` variant (root attribute `source = \"synthesis\"`) whatever the method: the search path "
    "(`path/method` names the member of the method family that made it) and per-frame provenance; "
    "`coefficients` when the method works in the database's PCA space (`dp`, `greedy`, `mean`, "
    "`coarticulation`), `keyshape_weights` and `keyshape_names` when it works in key-shapes (`trajectory`: "
    "the path of Huang et al. Eq. 7), neither for a method that makes markers directly. A method without "
    "motion nodes writes -1 for `path/node` and the provenance's node, take and source frame, and zero for "
    "the cost terms it has not (`trajectory`: `cost_oc` and `cost_tc` hold Eq. 6's data and smoothness terms "
    "per phone; `mean`, `coarticulation`: `node_phone` / `node_emotion` the phone and emotion whose pose was "
    "used, '' for a phone's pose over every emotion); the head moves only for the search's members. "
    "`facesynth capture` writes a captured take as the `capture` variant (`source = \"capture\"`, no "
    "`coefficients`, `path` or `provenance`), whose markers keep NaN where a gap was too long to fill; "
    "`facesynth expression restyle` writes the `restyle` variant (`source = \"restyle\"`, likewise without "
    "them). Schema 1 named the trajectory method in `source` and the method in `path/search`."), (
    Dataset("markers", "float32", ("Fo", "M", 3), "the motion at the output rate, head frame", "mm",
            (MM, _fps("output rate, frames/s")), finite="synthesis"),
    Dataset("markers_capture", "float32", ("F", "M", 3), "the motion at the capture rate, before down-sampling", "mm",
            (MM, _fps("capture rate, frames/s")), finite="synthesis"),
    Dataset("coefficients", "float32", ("F", "K"), "the concatenated, smoothed PCA frames, for a method in the "
            "database's PCA space (as the method made them: the voice's loudness, `synthesize.loudness_weight`, "
            "moves the markers only; so for `keyshape_weights`)", "mm",
            (_fps("capture rate, frames/s"),), required=False),
    Dataset("keyshape_weights", "float32", ("F", "Kt"), "key-shape weights, for a method in key-shapes (the "
            "trajectory of Huang et al. Eq. 7), interpolated to the capture rate", "weight",
            (_units("weight"), _fps("capture rate, frames/s")), ge=0, required=False),
    Dataset("keyshape_names", "str", ("Kt",), "the key-shapes, column order of `keyshape_weights` (with it)",
            required=False),
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("reference", "float32", ("M", 3), "rest pose", "mm", (MM,)),
    Dataset("head_rotation", "float32", ("Fo", 3, 3),
            "head pose relative to each source take's mean: `x -> head_rotation @ x + head_translation` "
            "(`deform.apply_head_motion` puts it back)",
            None, (_fps("output rate, frames/s"), _HEAD_CONVENTION)),
    Dataset("head_translation", "float32", ("Fo", 3), "see `head_rotation`", "mm", (MM, _fps("output rate, frames/s"))),
    Group("path", "search-path", "the search's choice, one row per input phone (`cost_tc[t]` is the transition into step t)", (
        Dataset("node", "int64", ("U",), "the chosen node"),
        Dataset("phone", "str", ("U",), "the phone asked for"),
        Dataset("emotion", "str", ("U",), "the emotion asked for"),
        Dataset("node_phone", "str", ("U",), "the chosen node's phone"),
        Dataset("node_emotion", "str", ("U",), "the chosen node's emotion"),
        Dataset("start", "float64", ("U",), "the input phone's start", "s", (SECONDS,)),
        Dataset("end", "float64", ("U",), "the input phone's end", "s", (SECONDS,)),
        Dataset("cost_tc", "float32", ("U",), "transition cost of Eq. 4 into the step"),
        Dataset("cost_oc", "float32", ("U",), "observation cost of Eq. 4"),
        Dataset("cost_emp", "float32", ("U",), "emotion mismatch penalty of Eq. 4"),
        Dataset("cost_block", "float32", ("U",), "blocking penalty of Eq. 10"),
    ), attrs=(Attr("total_cost", "float", "Eq. 4 along the path (trajectory: Eq. 6 of Huang et al.)"),
              Attr("non_captured_joins", "int", "joins without a captured predecessor/successor link", ge=0),
              Attr("method", "str", "the member of the method family that made the motion (`facesynth synthesize "
                   "--method`: `dp`, `greedy`, `trajectory`, `coarticulation`, `mean`, or a plug-in's name)"),
              Attr("device", "str", "where the search ran"),
              Attr("device_reason", "str", "why that device (the OpenCL choice, or why NumPy)")), required="synthesis"),
    Group("provenance", "provenance", "where each capture-rate frame came from", (
        Dataset("node", "int64", ("F",), "source node, -1 for regenerated silence"),
        Dataset("take", "int64", ("F",), "source take (row of `take_names`), -1 for regenerated silence"),
        Dataset("take_names", "str", ("T",), "the database's take names"),
        Dataset("source_frame", "int64", ("F",), "frame in the database, -1 for regenerated silence"),
        Dataset("step", "int64", ("F",), "input phone (row of `path`)"),
        Dataset("smoothed", "bool", ("F",), "frame changed by Eq. 16 smoothing (or Cao's blending)"),
    ), attrs=(_fps("capture rate, frames/s"), Attr("meaning", "str", "what the values are")), required="synthesis"),
), attrs=(Attr("source", "str", "`synthesis` for a motion any method made (`path/method` names it), `capture` "
                         "for a captured take, `restyle` for a motion in another expression",
                         choices=("synthesis", "capture", "restyle")),
          Attr("take", "str", "the captured take", required="capture")),
    variant_attr="source", variants=("synthesis", "capture", "restyle"))

FRAME_PROVENANCE = Group("provenance", "frame-provenance", (
    "where each frame came from, carried from `facesynth synthesize` (its `path` and `provenance`); a frame made "
    "at another rate than its source has the provenance of the nearest source frame. A captured take carries its "
    "name and no phones; a restyled motion, and curves or meshes made without a motion, carry no group"), (
    Dataset("phone", "str", ("Fo",), "the input phone the frame belongs to, empty where none is known"),
    Dataset("emotion", "str", ("Fo",), "the emotion asked for that phone, empty where none is known"),
    Dataset("node", "int64", ("Fo",), "source database node, -1 for regenerated silence, a trajectory or a capture",
            ge=-1),
    Dataset("take", "str", ("Fo",), "source take name, empty for regenerated silence"),
    Dataset("source_frame", "int64", ("Fo",), "source frame (a synthesis: row of the database's frames; a capture: "
            "frame of the take at its capture rate), -1 where none", ge=-1),
    Dataset("step", "int64", ("Fo",), "the frame's row of `segments`, -1 without phones", ge=-1),
    Group("segments", "phone-segments", "the synthesized utterance's phones (the motion's `path`)", (
        Dataset("phone", "str", ("U",), "the phone asked for"),
        Dataset("emotion", "str", ("U",), "the emotion asked for"),
        Dataset("start", "float64", ("U",), "the phone's start", "s", (SECONDS,)),
        Dataset("end", "float64", ("U",), "the phone's end", "s", (SECONDS,)),
        Dataset("node", "int64", ("U",), "the chosen database node, -1 for none", ge=-1),
        Dataset("take", "str", ("U",), "the take most of the phone's frames came from, empty for none"),
    ), required=False),
), attrs=(Attr("origin", "str", "what made the frames: the motion's source (`trajectory`, written before motion "
                         "schema 2, is read as a synthesis by the trajectory method)",
                         choices=("synthesis", "trajectory", "capture")),
          Attr("method", "str", "the method that made a synthesis's frames (the motion's `path/method`)",
               required=False),
          Attr("resampling", "str", "the rule for frames made at another rate, in words")), required=False)

MESHANIM = Kind("meshanim", 1, (
    "The face mesh moved by marker motion (paper VII-A), with the deformation weights of Eq. 14-15. "
    "Vertices and markers keep NaN where the driving motion has them (a capture with long gaps)."), (
    Dataset("vertices", "float32", ("Fo", "V", 3), "the animated mesh", "mesh units",
            (_units("mesh units"), _fps()), finite=False),
    Dataset("rest", "float32", ("V", 3), "the mesh as read", "mesh units"),
    Dataset("faces", "int32", ("Tri", 3), "triangles (rows of `rest`)", ge=0, below="V"),
    Group("weights", "csr-matrix", "the (V, B) Gaussian weights of Eq. 14-15 in CSR form; rows sum to 1 (0 where unreached)", (
        Dataset("data", "float32", ("W",), "the non-zero weights"),
        Dataset("indices", ("int32", "int64"), ("W",), "column (bound marker) of each weight", ge=0, below="B"),
        Dataset("indptr", ("int32", "int64"), ("V+1",), "row starts in `data`", ge=0, below="W+1"),
        Dataset("markers", "str", ("B",), "the bound markers"),
        Dataset("vertex_of", "int64", ("B",), "each bound marker's vertex"),
    ), attrs=(Attr("shape", "ints", "the matrix's shape (V, B)", shape=("V", "B")),)),
    Dataset("markers", "float32", ("Fo", "M", 3), "the driving marker motion", "mm", (MM, _fps()), finite=False),
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("gaze", "float32", ("Fo", 2, 2),
            "per frame (yaw, pitch) of the eye at +x (the subject's left), then of the eye at -x; yaw turns the "
            "gaze toward +x, pitch up; NaN where the gaze is not known (markers do not record it), and then the "
            "rendered eyes look ahead",
            "radians", (_units("radians"), _fps()), finite=False, required=False),
    FRAME_PROVENANCE,
), attrs=(Attr("fit_rms", "float", "residual of the marker-to-mesh similarity fit, mesh units"),))

_WEIGHT = _units("weight")

CURVES = Kind("curves", 1, (
    "Blendshape weight curves of one rig: `facesynth solve` writes a direct facial solve of marker motion "
    "(`source = \"solve\"`), `facesynth retarget` key-shape weights applied to keymorphs (Chuang & Bregler "
    "Eq. 9, `source = \"retarget\"`); a take's true weights are `truth`, weights read from a user's file "
    "`import`. Weights are in [0, 1]; shape names are the rig's own (ICT-FaceKit spelling for the built-in rig)."), (
    Dataset("weights", "float32", ("Fo", "E"), "per-frame rig weights, in [0, 1]", "weight",
            (_WEIGHT, _fps()), ge=0),
    Dataset("shape_names", "str", ("E",), "the rig's shape names, column order of `weights`"),
    Dataset("head_rotation", "float32", ("Fo", 3, 3), "head pose carried from the motion: "
            "`x -> head_rotation @ x + head_translation`", None, (_fps(), _HEAD_CONVENTION), required=False),
    Dataset("head_translation", "float32", ("Fo", 3), "see `head_rotation`", "mm", (MM, _fps()), required=False),
    Dataset("emotion", "str", ("Fo",), "per-frame emotion", required=False),
    Dataset("intensity", "float32", ("Fo",), "per-frame emotion intensity in [0, 1]", required=False, ge=0),
    Dataset("residual", "float32", ("Fo",), "per-frame RMS marker residual of the fit, NaN where a frame had "
            "no markers", "mm", (MM,), finite=False, required=False),
    FRAME_PROVENANCE,
), attrs=(Attr("rig_name", "str", "the rig (`ict-facekit` for the built-in rig)"),
          Attr("rig_sha256", "str", "sha256 of the rig's data (package data, a user's rig folder or glTF)"),
          Attr("source", "str", "what made the weights", choices=("solve", "retarget", "truth", "import", "openfacefx")),
          Attr("method", "str", "how, in words (e.g. `linear`, `deformation-gradient`), or empty")))

KEYSHAPES = Kind("keyshapes", 1, (
    "Key-shapes chosen from a motion database, per emotion (Chuang & Bregler 2005 §4.1 PCA extremes, or "
    "Huang et al. §5.2 affinity propagation with merging to the error knee), with their keymorphs fitted on "
    "the built-in rig. A frame is a non-negative combination of its emotion's key-shapes (Eq. 8), solved "
    "with the settings in `solver`."), (
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("reference", "float32", ("M", 3), "the database's rest pose", "mm", (MM,)),
    Dataset("emotion_names", "str", ("L",), "the emotions, names of the groups under `emotions/`"),
    Dataset("rig_shape_names", "str", ("E",), "the keymorphs' rig shape names", required=False),
    Group("emotions", "keyshape-emotions", "one group per emotion", (
        Group("<emotion>", "keyshape-set", "the key-shapes of one emotion", (
            Dataset("markers", "float32", ("k", "M", 3), "key-shape marker poses, head frame", "mm", (MM,)),
            Dataset("coefficients", "float32", ("k", "K"), "their PCA coordinates in the database's model", "mm", (MM,)),
            Dataset("source_frame", "int64", ("k",), "the database frame each was taken from", ge=0),
            Dataset("names", "str", ("k",), "key-shape names; keymorph files and CSV rows are matched by them"),
            Dataset("keymorphs", "float32", ("k", "E"), "each key-shape's rig weights on the built-in rig, in [0, 1]",
                    "weight", (_WEIGHT,), required=False, ge=0),
            Dataset("counts", "int64", ("c",), "key-shape counts of the reconstruction-error curve", ge=1),
            Dataset("errors", "float32", ("c",), "NNLS reconstruction RMS of the emotion's frames with that many "
                    "key-shapes (Eq. 8)", "mm", (MM,)),
        ), attrs=(Attr("rms", "float", "reconstruction RMS with all the key-shapes, mm", ge=0),), local=("k", "c")),
    )),
), attrs=(Attr("method", "str", "how the key-shapes were chosen", choices=("pca", "affinity")),
          Attr("requested_count", "int", "key-shapes asked for per emotion (0: chosen at the knee)", ge=0),
          Attr("solver", "json", "settings of the non-negative weights solve"),
          Attr("rig_name", "str", "the rig the keymorphs were fitted on", required=False),
          Attr("rig_sha256", "str", "sha256 of that rig's data", required=False)))

TRAJECTORY = Kind("trajectory", 1, (
    "The compact key-shape trajectory model (Huang et al. §5.4): per phone, and per (phone, emotion) with at "
    "least `min_tokens` training tokens, the mean and diagonal covariance of the frames' non-negative "
    "weights over one joint key-shape set (every emotion's key-shapes of a `keyshapes` artifact), with the "
    "key-shapes and the rest pose, so that `facesynth synthesize --method trajectory` needs this file alone. "
    "A frame with weights w is `reference + sum_k w[k] (keyshapes[k] - reference)`."), (
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("reference", "float32", ("M", 3), "rest pose (all weights zero), head frame", "mm", (MM,)),
    Dataset("keyshapes", "float32", ("Kt", "M", 3), "the joint key-shapes' marker poses, head frame", "mm", (MM,)),
    Dataset("keyshape_names", "str", ("Kt",), "key-shape names (those of the `keyshapes` artifact)"),
    Dataset("keyshape_emotion", "str", ("Kt",), "the emotion each key-shape was chosen for"),
    Dataset("phones", "str", ("Ph",), "phones with a Gaussian (Festival names, `pau` included)"),
    Dataset("means", "float32", ("Ph", "Kt"), "mean key-shape weights per phone", "weight", (_WEIGHT,)),
    Dataset("variances", "float32", ("Ph", "Kt"), "variance of each weight per phone (floored, see "
            "`variance_floor`)", "weight", (_WEIGHT,), ge=0),
    Dataset("tokens", "int64", ("Ph",), "training tokens of each phone", ge=1),
    Dataset("samples", "int64", ("Ph",), "training frames that fed each phone's Gaussian", ge=1),
    Dataset("pair_phone", "str", ("Pe",), "phone of each (phone, emotion) Gaussian"),
    Dataset("pair_emotion", "str", ("Pe",), "emotion of each (phone, emotion) Gaussian"),
    Dataset("pair_means", "float32", ("Pe", "Kt"), "mean key-shape weights per (phone, emotion)", "weight", (_WEIGHT,)),
    Dataset("pair_variances", "float32", ("Pe", "Kt"), "variance of each weight per (phone, emotion)", "weight",
            (_WEIGHT,), ge=0),
    Dataset("pair_tokens", "int64", ("Pe",), "training tokens of each pair", ge=1),
    Dataset("pair_samples", "int64", ("Pe",), "training frames that fed each pair's Gaussian", ge=1),
), attrs=(_fps("capture rate of the training frames, frames/s"),
          Attr("sampling", "str", "which frames fed the Gaussians: every frame of a phone, or each token's centre",
               choices=("span", "centre")),
          Attr("min_tokens", "int", "tokens a (phone, emotion) pair needed for its own Gaussian", ge=1),
          Attr("variance_floor", "float", "each variance is at least this fraction of that weight's variance over "
               "all training frames", gt=0),
          Attr("fit_rms", "float", "RMS per marker (mm) of the training frames' reconstruction from the weights", ge=0),
          Attr("covariance", "str", "the covariance's form", choices=("diagonal",))))

COARTICULATION = Kind("coarticulation", 1, (
    "The fitted Cohen-Massaro coarticulation model (Cohen & Massaro 1993, exponent 1): per phone type (a "
    "`phone|emotion` label; `pau` one type) a target pose in the PCA coefficients of the database it was "
    "fitted on, a dominance magnitude and a rate; with that PCA model and the rest pose, so that "
    "`facesynth synthesize --method coarticulation` needs this file alone. The pose at time t is "
    "`sum_i D_i(t) targets[i] / sum_i D_i(t)` over the utterance's tokens i, with "
    "`D_i(t) = magnitude * exp(-rate * |t - centre_i|)`, reconstructed through the PCA model (Eq. 11)."), (
    PCA_MODEL,
    Dataset("labels", "str", ("Pc",), "phone types (`aa|happy`, `pau`)"),
    Dataset("targets", "float64", ("Pc", "K"), "target pose of each type, PCA coefficients"),
    Dataset("magnitude", "float64", ("Pc",), "dominance magnitude alpha", ge=0),
    Dataset("rate", "float64", ("Pc",), "dominance rate theta", "1/s", (_units("1/s"),), ge=0),
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("reference", "float32", ("M", 3), "rest pose, head frame", "mm", (MM,)),
), attrs=(_fps("capture rate of the training frames, frames/s"),
          Attr("iterations", "int", "L-BFGS-B iterations allowed to the fit", ge=1),
          Attr("fit_rms", "float", "RMS per marker (mm) of the fit on the training frames", ge=0)))

ARTICULATION = Kind("articulation", 1, (
    "The acoustic articulation model (issue 42): ridge regression from the voice's frame features "
    "(`feature_names`, 10 ms analysis frames, normalized as `normalization` says), each averaged over `pool` "
    "frames around every offset of `offsets_s` from an output frame's time (with the loudness hinges at `knots` "
    "where `expand` is 1), to the mouth's curves `target_names`: `curves = context @ coef + intercept`, the "
    "context offset-major. `facesynth.domain.voice.articulation.predict` needs this file alone."), (
    Dataset("target_names", "str", ("Ya",), "the predicted curves (ARKit names, or `opening`)"),
    Dataset("offsets_s", "float64", ("Ca",), "offsets of the context from the frame time", "s", (SECONDS,)),
    Dataset("feature_names", "str", ("Da",), "the voice features, in column order"),
    Dataset("feature_mean", "float64", ("Da",), "mean of each feature over the training frames with speech"),
    Dataset("feature_std", "float64", ("Da",), "standard deviation of each feature (floored at 1e-6)", ge=0),
    Dataset("coef", "float64", ("Xa", "Ya"), "regression coefficients on the normalized context"),
    Dataset("intercept", "float64", ("Ya",), "intercept of each curve"),
    Dataset("target_mean", "float64", ("Ya",), "mean of each curve over the training frames (as the fit weighs them)"),
    Dataset("target_std", "float64", ("Ya",), "standard deviation of each curve over the training frames (as the fit weighs them)", ge=0),
    Dataset("knots", "float64", ("Kn",), "knots of the loudness hinges, standardized log RMS"),
), attrs=(Attr("pool", "int", "analysis frames averaged around each offset", ge=1),
          Attr("normalization", "str", "how the features are standardized", choices=("global", "utterance", "running")),
          Attr("tau_s", "float", "time constant of the running normalization, s", gt=0),
          Attr("gate", "float", "a frame has speech within this (log amplitude) of the loudest frame so far", gt=0),
          Attr("peak_decay", "float", "how fast the loudest level falls, log amplitude/s", ge=0),
          Attr("alpha", "float", "the ridge penalty per standardized column, times the training frames", ge=0),
          Attr("expand", "int", "1: the loudness hinges are columns of the context", ge=0, le=1),
          Attr("analysis_rate", "int", "sample rate of the analysis frames, Hz", gt=0),
          Attr("hop", "int", "samples between analysis frames", ge=1),
          Attr("window", "int", "samples of an analysis frame's window", ge=1),
          Attr("fitted_on", "str", "JSON list of what the model was fitted on, one record per file of speech or "
               "curves (`name` as `<source>/<speaker>/<file>`, `sha256`, `seconds` of audio or null); absent in "
               "files written before it existed", required=False),
          Attr("closure_threshold", "float", "the closure score's threshold at which the voice's own closures met "
               "the performer's on held-out takes (`fit-articulation`), taken where "
               "`synthesize.voice_closure_threshold` is -1; absent where none was chosen", ge=0, le=1,
               required=False)))

#: Every kind's specification at its current schema.
EXPRESSION = Kind("expression", 1, (
    "A bilinear style/content model of marker frames (Chuang & Bregler 2005, §3, Eq. 4): "
    "`y[k] = styles[s] . W[k] . content` over the PCA coefficients `y` of the normalized markers "
    "(the paper factors 2D video shape and texture; facesynth factors 3D markers)."), (
    Dataset("marker_names", "str", ("M",), "marker order"),
    Dataset("mean", "float32", ("M", 3), "mean marker frame of the fitted data", "mm", (MM,)),
    Dataset("basis", "float32", ("Kb", "M", 3), "orthonormal PCA modes (Eq. 1) the model's coefficients are in"),
    Dataset("emotions", "str", ("Es",), "the fitted emotions, one per style vector"),
    Dataset("styles", "float64", ("Es", "Es"), "style (expression) vector of each emotion (Eq. 4's e_s)"),
    Dataset("W", "float64", ("Kb", "Es", "J"), "bilinear basis (Eq. 4's W_k)"),
    Dataset("content_mean", "float64", ("J",), "mean training content vector (Eq. 5's initial guess)"),
    Dataset("errors", "float64", ("It",), "mean squared error after each alternating least-squares iteration",
            "mm^2", (_units("mm^2"),)),
    Dataset("sentences", "str", ("Sq",), "sentences whose takes were aligned across emotions and fitted"),
), attrs=(Attr("aligned_frames", "int", "content frames (aligned across emotions) the model was fitted on", ge=1),))

HEADMOTION = Kind("headmotion", 1, (
    "Head motion chosen from captured segments by the pitch of new speech (Chuang & Bregler 2005, §5), "
    "with the cleaned pitch and the chosen segments; `facesynth synthesize --head-motion` puts it on a motion."), (
    Dataset("rotation", "float32", ("Fh", 3, 3), "head pose relative to rest: `x -> rotation @ x + translation`",
            None, (_fps(), _HEAD_CONVENTION)),
    Dataset("translation", "float32", ("Fh", 3), "see `rotation`", "mm", (MM, _fps())),
    Dataset("pitch", "float32", ("Pf",), "cleaned pitch, NaN where unvoiced", "Hz", (_units("Hz"), _fps("pitch frames/s")),
            finite=False),
    Group("segments", "pitch-segments", "the input's segments (voiced onset to the next) and the captured segment chosen for each", (
        Dataset("start", "float64", ("G",), "segment start in the input", "s", (SECONDS,)),
        Dataset("end", "float64", ("G",), "segment end in the input", "s", (SECONDS,)),
        Dataset("take", "str", ("G",), "the captured take of the chosen segment"),
        Dataset("index", "int64", ("G",), "the chosen segment's position in its take", ge=0),
        Dataset("cost", "float64", ("G",), "Eq. 12 distance of the chosen segment (the trellis node cost)"),
        Dataset("take_start", "float64", ("G",), "chosen segment's start in its take", "s", (SECONDS,)),
        Dataset("take_end", "float64", ("G",), "chosen segment's end in its take", "s", (SECONDS,)),
    )),
))

#: Every registered kind by name (always current).
KINDS: Mapping[str, Kind] = ARTIFACT_KINDS.view(lambda entry: entry.load())

BLOCKS: tuple[Block, ...] = (TABLES, HEAD_FRAMES, PCA_MODEL)


def walk(entries: tuple[Entry, ...], prefix: str = "") -> Iterator[tuple[str, Entry]]:
    """Every entry below ``entries`` with its key (``clusters/<phone>/frames``), depth first."""
    for e in entries:
        key = f"{prefix}{e.name}"
        yield key, e
        if isinstance(e, Group):
            yield from walk(e.children, key + "/")


# ---------------------------------------------------------------- the document

def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def _attr_text(a: Attr) -> str:
    bits = []
    if a.choices and len(a.choices) == 1:
        bits.append(f"`{a.name}` = `{a.choices[0]}`")
    else:
        kind = {"str": "string", "int": "int", "float": "float", "json": "JSON string", "ints": "int array"}[a.type]
        bounds = [f">= {a.ge:g}" if a.ge is not None else "", f"> {a.gt:g}" if a.gt is not None else "",
                  f"<= {a.le:g}" if a.le is not None else ""]
        if a.shape:
            bounds.append("(" + ", ".join(a.shape) + ")")
        if a.choices:
            bounds.append("one of " + ", ".join(f"`{c}`" for c in a.choices))
        bounds = [b for b in bounds if b]
        bits.append(f"`{a.name}` ({kind}{' ' + ', '.join(bounds) if bounds else ''})" + (f": {a.doc}" if a.doc else ""))
    if a.required is False:
        bits.append("(optional)")
    elif isinstance(a.required, str):
        bits.append(f"(required in `{a.required}`)")
    return " ".join(bits)


def _required_text(flag: Required) -> str:
    return "yes" if flag is True else "no" if flag is False else f"in `{flag}`"


def _dtype_text(d: Dataset) -> str:
    text = " or ".join(d.dtype) if isinstance(d.dtype, tuple) else d.dtype
    if d.dtype in ("float32", "float64"):
        if d.finite is False:
            text += ", NaN allowed"
        elif isinstance(d.finite, str):
            text += f", finite in `{d.finite}`"
    return text


def _shape_text(shape: tuple) -> str:
    return "(" + ", ".join(str(s) for s in shape) + ("," if len(shape) == 1 else "") + ")"


def _rows(entries: tuple[Entry, ...]) -> list[str]:
    rows = ["| key | type | shape | unit | attributes | required | meaning |", "|---|---|---|---|---|---|---|"]
    for key, e in walk(entries):
        attrs = "; ".join(_attr_text(a) for a in e.attrs)
        if isinstance(e, Group):
            local = f" ({', '.join(e.local)} per group)" if e.local else ""
            rows.append(f"| `{key}/` | group `{e.encoding}` | | | {_cell(attrs)} | {_required_text(e.required)} | "
                        f"{_cell(e.doc)}{local} |")
        else:
            bounds = [f"values >= {e.ge:g}"] if e.ge is not None else []
            bounds += [f"values < {e.below}"] if e.below else []
            doc = e.doc + (f" ({', '.join(bounds)})" if bounds else "")
            rows.append(f"| `{key}` | {_dtype_text(e)} | {_shape_text(e.shape)} | {e.unit or ''} | {_cell(attrs)} | "
                        f"{_required_text(e.required)} | {_cell(doc)} |")
    return rows


def markdown() -> str:
    """The generated part of ``docs/file-format.md``: symbols, shared blocks and every kind's table."""
    out = ["## Shape symbols", "",
           "Shapes name their sizes with symbols; a symbol has one size throughout a file "
           "(`3M` is three times M, `V+1` is V plus one).", "",
           "| symbol | counts |", "|---|---|"]
    out += [f"| `{s}` | {doc} |" for s, doc in SYMBOLS.items()]
    out += ["", f"Every float where numbers must be finite has a magnitude of at most {MAX_FLOAT:g}, every integer at most "
            f"2^53; readers refuse larger values.", "", "## Root attributes of every artifact", "", "| attribute | type | meaning |", "|---|---|---|"]
    out += [f"| `{a.name}` | {a.type} | {_cell(a.doc)} |" for a in COMMON_ATTRS]
    out += ["", f"Every group carries `encoding-type` (named in the tables below as `group TYPE`) and "
            f"`encoding-version` = `{ENCODING_VERSION}`; the root is identified by `facesynth_kind` instead.",
            "", "\"Required\" of an entry inside an optional group means required when the group is there; "
            "\"in `synthesis`\" means required (or finite) in that variant of the kind only.",
            "", "## Shared blocks", "",
            "Root entries several kinds carry, written by one function of the model layer.", ""]
    for b in BLOCKS:
        out += [f"### `{b.name}`", "", b.doc, ""] + _rows(b.entries) + [""]
    out += ["## Kinds", ""]
    for k in KINDS.values():
        by = " and ".join(f"`{w}`" for w in k.producers) or producers(k.name)
        out += [f"### `{k.name}` (schema {k.schema}, written by {by})", "", k.doc, ""]
        blocks = [e.name for e in k.entries if isinstance(e, Block)]
        if blocks:
            out += ["Shared blocks: " + ", ".join(f"`{b}`" for b in blocks) + ".", ""]
        if k.variant_attr:
            out += ["Variants: " + ", ".join(f"`{v}`" for v in k.variants)
                    + f" (root attribute `{k.variant_attr}`; absent: `{k.variants[0]}`).", ""]
        if k.attrs:
            out += ["Root attributes: " + "; ".join(_attr_text(a) for a in k.attrs) + ".", ""]
        own = tuple(e for e in k.entries if not isinstance(e, Block))
        out += (_rows(own) if own else ["Nothing but the shared blocks."]) + [""]
    return "\n".join(out).rstrip() + "\n"


#: The line of ``docs/file-format.md`` after which the document is generated by :func:`markdown`.
GENERATED_MARK = ("<!-- Generated from facesynth/model/spec.py by `python -m facesynth.model.spec docs/file-format.md`; "
                  "edit the specification, not the text below. -->")


def document(current: str) -> str:
    """``current`` (the text of ``docs/file-format.md``) with its generated part brought up to date."""
    head = current.split(GENERATED_MARK)[0].rstrip()
    return f"{head}\n\n{GENERATED_MARK}\n\n{markdown()}"


def main(argv: list[str]) -> int:
    if not argv:
        sys.stdout.write(markdown())
        return 0
    path = Path(argv[0])
    path.write_text(document(path.read_text(encoding="utf-8")), encoding="utf-8")
    return 0


if __name__ == "__main__":  # pragma: no cover
    from facesynth.model import spec  # this module as imported: the registry loads the kinds from it by name

    sys.exit(spec.main(sys.argv[1:]))
