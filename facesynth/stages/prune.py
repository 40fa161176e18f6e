"""``facesynth prune``: clean the motion-node database (paper V).

Pruning writes a new ``motiondb`` artifact without the removed nodes; the input is never
changed. Links into removed nodes become "none" (so Table I rule 4 applies to their
former successors), the pairwise terms are cut to the kept rows and columns, and the
removed ids (in the numbering of the original, unpruned database), the reason and each
kept node's original id are recorded under ``pruned/``.

``--auto`` removes the contaminated nodes (marker spikes, label swaps, outliers of their
phoneme cluster) that :func:`facesynth.domain.database.contamination.detect` finds.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import PruneSettings, settings_json
from facesynth.base.errors import InputError, UsageError
from facesynth.domain.database.contamination import detect
from facesynth.domain.search.pairs import node_features
from facesynth.model.artifacts import check_output
from facesynth.model.motiondb import MotionDatabase, Pruned


def parse_ids(text: str, n: int) -> list[int]:
    """'3,5,10-12' -> [3, 5, 10, 11, 12]; every id must exist. Each part is checked against the
    ``n`` nodes before a range is expanded, so a range past the end costs nothing."""
    ids: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        m = re.fullmatch(r"(\d+)(?:-(\d+))?", part)
        if not m:
            raise InputError(f"--remove {text!r}: {part!r} is not a node id or a range like 10-12.")
        a, b = int(m.group(1)), int(m.group(2) or m.group(1))
        if b < a:
            raise InputError(f"--remove {text!r}: the range {part!r} ends before it starts; write it low-high.")
        if b >= n:
            missing = f"{b}" if a == b else f"{max(a, n)}-{b}"
            raise InputError(f"--remove: node(s) [{missing}] do not exist; the database has nodes 0 to {n - 1}.")
        ids.update(range(a, b + 1))
    if not ids:
        raise InputError("--remove names no node.")
    return sorted(ids)


@dataclass(frozen=True)
class PruneResult:
    """What ``facesynth prune`` removed.

    removed: nodes removed (0: nothing to remove, and no output written).
    kept: nodes kept.
    links_cut: kept nodes whose captured predecessor was removed.
    found: the nodes removed, by id in the input, with the kind of contamination (``--auto``)
        or the reason given (``--remove``).
    """

    removed: int
    kept: int
    links_cut: int
    found: dict[int, str] = field(default_factory=dict)


def prune(db: MotionDatabase, out: Path, remove: list[int], reasons: list[str], settings: PruneSettings,
          overwrite: bool) -> PruneResult:
    """Write ``db`` without the nodes ``remove`` (ids in ``db``) to ``out``, recording ``reasons``;
    ``db`` must have been read with its markers."""
    n = len(db.nodes)
    keep = np.setdiff1d(np.arange(n), remove)
    if len(keep) == 0:
        raise InputError(f"{db.path}: removing every node would leave an empty database.")
    kept = db.nodes.subset(keep)
    before = db.pruned or Pruned(np.arange(n), np.zeros(0, np.int64), [])
    features = node_features(db).subset(keep, kept.pre)  # a lost predecessor: rule 4, DSC unused
    lost_pre = (db.nodes.pre[keep] >= 0) & (kept.pre < 0)
    pruned = Pruned(before.original_id[keep],
                    np.concatenate([before.removed_id, before.original_id[np.asarray(remove, np.int64)]]).astype(np.int64),
                    before.reason + reasons)
    cleaned = MotionDatabase(db.takes, db.phones, db.marker_names, db.model, db.coeffs, db.frames, kept, pruned)
    cleaned.write(out, features, config=settings_json(settings), inputs=[db.path], overwrite=overwrite)
    return PruneResult(len(remove), len(keep), int(lost_pre.sum()))


def run(db_path: Path, out: Path, settings: PruneSettings, remove: str | None, auto: bool, reason: str,
        overwrite: bool) -> PruneResult:
    """Remove the nodes ``remove`` ('3,5,10-12') or, with ``auto``, the contaminated ones found
    by :func:`facesynth.domain.database.contamination.detect`, writing ``out``; nothing is written when there is nothing to remove."""
    if (remove is None) == (not auto):
        raise UsageError("give exactly one of --remove IDS or --auto.")
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path, markers=True)
    if remove is None:  # so auto: exactly one of the two, as checked above
        found = detect(db.nodes, db.takes, db.frames.loaded_markers(), db.coeffs, db.fps, settings)
    else:
        found = {i: reason for i in parse_ids(remove, len(db.nodes))}
    ids = list(found)
    reasons = [f"auto: {kind}" if auto else kind for kind in found.values()]
    if not ids:
        return PruneResult(0, len(db.nodes), 0)
    return replace(prune(db, out, ids, reasons, settings, overwrite), found=found)



def count_by_kind(found: dict[int, str]) -> dict[str, int]:
    """How many nodes of each contamination kind (``found``: node -> kind), kinds sorted."""
    return {kind: sum(1 for k in found.values() if k == kind) for kind in sorted(set(found.values()))}
