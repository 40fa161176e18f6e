"""``facesynth prune`` and ``facesynth db show``: browse and clean the motion-node database
(paper V).

Pruning writes a new ``motiondb`` artifact without the removed nodes; the input is never
changed. Links into removed nodes become "none" (so Table I rule 4 applies to their
former successors), the pairwise terms are cut to the kept rows and columns, and the
removed ids (in the numbering of the original, unpruned database), the reason and each
kept node's original id are recorded under ``pruned/``.

``--auto`` finds contaminated nodes in the normalized markers the database carries:

* an *excursion* is a marker jumping away (a frame-to-frame step beyond ``jump_z`` robust
  z-scores of that marker's steps) and jumping back (an opposite step of similar size)
  within ``max_excursion_s``; natural facial motion is smooth at the capture rate, marker
  spikes and label swaps are not. Its frames are contaminated; two markers making the same
  excursion together are a swap, one alone a spike; a jump never answered flags its frame;
* a node is an outlier when its mean PCA frame lies more than ``outlier_z`` robust z-scores
  from its phoneme cluster's median.

A node is contaminated when any of its frames is.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..artifacts import open_artifact, read, read_strings, write_artifact, write_strings
from ..config import PruneSettings, settings_json
from ..errors import InputError
from ..tables import Takes, copy_tables
from .build_db import Nodes, node_frames, write_pair_terms
from .pca import read_pca, write_pca


def parse_ids(text: str, n: int) -> list[int]:
    """'3,5,10-12' -> [3, 5, 10, 11, 12]; every id must exist."""
    ids: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        m = re.fullmatch(r"(\d+)(?:-(\d+))?", part)
        if not m:
            raise InputError(f"--remove {text!r}: {part!r} is not a node id or a range like 10-12.")
        a, b = int(m.group(1)), int(m.group(2) or m.group(1))
        ids.update(range(a, b + 1))
    bad = sorted(i for i in ids if i >= n)
    if bad:
        raise InputError(f"--remove: node(s) {bad[:5]} do not exist; the database has nodes 0 to {n - 1}.")
    if not ids:
        raise InputError("--remove names no node.")
    return sorted(ids)


def robust_z(x: np.ndarray, axis=0) -> np.ndarray:
    med = np.median(x, axis=axis, keepdims=True)
    mad = np.median(np.abs(x - med), axis=axis, keepdims=True) * 1.4826
    return (x - med) / np.maximum(mad, 1e-9)


def excursions(track: np.ndarray, threshold: float, max_len: int) -> list[tuple[int, int]]:
    """Excursions of one marker: frame ranges [a, b) between a jump and its return.

    track : (T, 3) positions; threshold : step size (mm) counted as a jump.
    A jump with no return within ``max_len`` frames gives the range [a, a + 1).
    """
    step = np.diff(track, axis=0, prepend=track[:1])
    size = np.linalg.norm(step, axis=1)
    jumps = np.nonzero(size > threshold)[0]
    out, used = [], set()
    for i, a in enumerate(jumps):
        if a in used:
            continue
        partner = None
        for b in jumps[i + 1 :]:
            if b - a > max_len:
                break
            cos = float(step[a] @ step[b]) / (size[a] * size[b])
            if cos < -0.5 and 0.5 < size[b] / size[a] < 2.0:
                partner = b
                break
        if partner is None:
            out.append((int(a), int(a) + 1))
        else:
            used.add(partner)
            out.append((int(a), int(partner)))
    return out


def hold_gaps(x: np.ndarray) -> np.ndarray:
    """(T, M, 3) with NaN samples replaced by the marker's last seen position (the first seen
    one before it appears); markers never seen become 0."""
    out = x.copy()
    seen = ~np.isnan(out).any(axis=2)  # (T, M)
    index = np.where(seen, np.arange(len(out))[:, None], -1)
    np.maximum.accumulate(index, axis=0, out=index)
    first = np.argmax(seen, axis=0)
    index = np.where(index < 0, first[None, :], index)
    out = out[index, np.arange(out.shape[1])[None, :]]
    return np.nan_to_num(out)


def detect(nodes: Nodes, takes: Takes, markers: np.ndarray, coeffs: np.ndarray, fps: float,
           settings: PruneSettings) -> dict[int, str]:
    """Contaminated nodes -> kind ('spike', 'swap' or 'outlier')."""
    n_frames, n_markers, _ = markers.shape
    filled = markers.astype(np.float64)
    steps = np.zeros((n_frames, n_markers))
    for t in range(len(takes)):
        sl = takes.frames(t)
        filled[sl] = hold_gaps(filled[sl])  # missing data is not contamination: no jump into a gap
        steps[sl][1:] = np.linalg.norm(np.diff(filled[sl], axis=0), axis=2)
    rows = np.concatenate([np.arange(nodes.frame_start[k], nodes.frame_start[k] + nodes.frame_count[k]) for k in range(len(nodes))])
    med = np.median(steps[rows], axis=0)
    mad = np.median(np.abs(steps[rows] - med), axis=0) * 1.4826
    thresholds = med + settings.jump_z * np.maximum(mad, 1e-6)
    max_len = int(round(settings.max_excursion_s * fps))
    flagged = np.zeros((n_frames, n_markers), bool)
    spans: dict[tuple[int, int], int] = {}
    for t in sorted(set(nodes.take.tolist())):
        sl = takes.frames(t)
        for m in range(n_markers):
            for a, b in excursions(filled[sl, m], thresholds[m], max_len):
                flagged[sl.start + a : sl.start + b, m] = True
                key = (sl.start + a, sl.start + b)
                spans[key] = spans.get(key, 0) + 1
    paired = np.zeros(n_frames, bool)
    for (a, b), count in spans.items():
        if count >= 2:
            paired[a:b] = True
    found: dict[int, str] = {}
    for k in range(len(nodes)):
        sl = nodes.frames(k)
        if flagged[sl].any():
            found[k] = "swap" if paired[sl].any() else "spike"
    phones = np.array(nodes.phone)
    means = np.stack([coeffs[nodes.frames(k)].mean(0) for k in range(len(nodes))])
    for phone in np.unique(phones):
        members = np.nonzero(phones == phone)[0]
        if len(members) < 8:
            continue
        d = np.linalg.norm(means[members] - np.median(means[members], axis=0), axis=1)
        for k in members[robust_z(d) > settings.outlier_z]:
            found.setdefault(int(k), "outlier")
    return dict(sorted(found.items()))


def prune(db_path: Path, out: Path, remove: list[int], reasons: list[str], settings: PruneSettings, overwrite: bool) -> dict:
    with open_artifact(db_path, "motiondb") as f:
        nodes = Nodes.read(f)
        n = len(nodes)
        keep = np.setdiff1d(np.arange(n), remove)
        if len(keep) == 0:
            raise InputError(f"{db_path}: removing every node would leave an empty database.")
        kept = nodes.subset(keep)
        original = read(f, "pruned/original_id") if "pruned" in f else np.arange(n)
        earlier_ids = list(read(f, "pruned/removed_id")) if "pruned" in f else []
        earlier_reasons = read_strings(f, "pruned/reason") if "pruned" in f else []
        with write_artifact(out, "motiondb", config=settings_json(settings), inputs=[db_path], overwrite=overwrite) as g:
            copy_tables(f, g)
            write_pca(g, read_pca(f))
            for key in ("coefficients", "markers", "reference", "head_rotation", "head_translation"):
                if key in f:
                    f.copy(f[key], g, name=key)
            kept.write(g)
            frame_node, relative = node_frames(kept, len(f["coefficients"]))
            g.create_dataset("frames/node", data=frame_node)
            g.create_dataset("frames/relative_time", data=relative)
            pairs = {}
            for key in ("dsc", "pgap", "vgap"):
                src = f[f"pairs/{key}"]
                m = np.empty((len(keep), len(keep)), np.float32)
                for a in range(0, len(keep), 512):
                    m[a : a + 512] = src[keep[a : a + 512]][:, keep]
                pairs[key] = m
            lost_pre = (nodes.pre[keep] >= 0) & (kept.pre < 0)
            pairs["dsc"][:, lost_pre] = 0.0  # their predecessor is gone: rule 4 applies, DSC unused
            states = tuple(read(f, f"boundary/{k}")[keep] for k in ("first_pos", "last_pos", "first_vel", "last_vel"))
            write_pair_terms(g, pairs["dsc"], pairs["pgap"], pairs["vgap"], states)
            p = g.create_group("pruned")
            p.create_dataset("original_id", data=original[keep])
            p.create_dataset("removed_id", data=np.array(earlier_ids + [int(original[i]) for i in remove], np.int64))
            write_strings(p, "reason", earlier_reasons + reasons)
    return {"removed": len(remove), "kept": len(keep), "links_cut": int(lost_pre.sum())}


def run(db_path: Path, out: Path, settings: PruneSettings, remove: str | None, auto: bool, reason: str, overwrite: bool) -> dict:
    from ..artifacts import check_output

    check_output(out, overwrite)
    if (remove is None) == (not auto):
        raise InputError("give exactly one of --remove IDS or --auto.")
    with open_artifact(db_path, "motiondb") as f:
        nodes = Nodes.read(f)
        if auto:
            found = detect(nodes, Takes.read(f), read(f, "markers"), read(f, "coefficients"),
                           float(f["coefficients"].attrs["fps"]), settings)
        else:
            found = {i: reason for i in parse_ids(remove, len(nodes))}
    ids = list(found)
    reasons = [f"auto: {kind}" if auto else kind for kind in found.values()]
    if not ids:
        return {"removed": 0, "kept": len(nodes), "links_cut": 0, "found": {}}
    summary = prune(db_path, out, ids, reasons, settings, overwrite)
    summary["found"] = found
    return summary


def show(db_path: Path, phone: str | None = None, node: int | None = None) -> list[str]:
    """Lines describing the database's nodes (all, one phoneme's, or one node in detail)."""
    with open_artifact(db_path, "motiondb") as f:
        nodes = Nodes.read(f)
        takes = Takes.read(f)
        fps = float(f["coefficients"].attrs["fps"])
        original = read(f, "pruned/original_id") if "pruned" in f else None
    if node is not None:
        if not 0 <= node < len(nodes):
            raise InputError(f"{db_path}: node {node} does not exist (0 to {len(nodes) - 1}).")
        k = node
        lines = [f"node {k}: /{nodes.phone[k]}/ in [{nodes.prev_phone[k]} {nodes.phone[k]} {nodes.next_phone[k]}], {nodes.emotion[k]}",
                 f"  take {takes.name[nodes.take[k]]} ({takes.sentence[nodes.take[k]]}), {nodes.start_s[k]:.3f}-{nodes.end_s[k]:.3f} s, "
                 f"{nodes.frame_count[k]} frames at {fps:g} Hz",
                 f"  captured predecessor: {nodes.pre[k] if nodes.pre[k] >= 0 else 'none'}, successor: {nodes.suc[k] if nodes.suc[k] >= 0 else 'none'}"]
        if original is not None:
            lines.append(f"  id in the unpruned database: {original[k]}")
        same = [j for j in range(len(nodes)) if nodes.phone[j] == nodes.phone[k] and j != k
                and nodes.prev_phone[j] == nodes.prev_phone[k] and nodes.next_phone[j] == nodes.next_phone[k]]
        lines.append(f"  same triphone context: {same[:20] if same else 'none'}")
        return lines
    if phone is not None and phone not in nodes.phone:
        raise InputError(f"{db_path}: no node of /{phone}/; phones present: {' '.join(sorted(set(nodes.phone)))}.")
    lines = ["id\tphone\tcontext\temotion\ttake\tframes\tpre\tsuc"]
    for k in range(len(nodes)):
        if phone is not None and nodes.phone[k] != phone:
            continue
        lines.append(f"{k}\t{nodes.phone[k]}\t{nodes.prev_phone[k]}-{nodes.phone[k]}+{nodes.next_phone[k]}\t{nodes.emotion[k]}\t"
                     f"{takes.name[nodes.take[k]]}\t{nodes.frame_start[k]}+{nodes.frame_count[k]}\t{nodes.pre[k]}\t{nodes.suc[k]}")
    return lines


def contaminated_nodes(nodes: Nodes, takes: Takes, truth_csv: Path) -> set[int]:
    """Nodes whose frames overlap an injected contamination event (the sample corpus's ground truth)."""
    import csv

    events = list(csv.DictReader(open(truth_csv, encoding="utf-8")))
    out = set()
    for e in events:
        if e["take"] not in takes.name:
            continue
        t = takes.index(e["take"])
        a = takes.frame_start[t] + int(e["start_frame"])
        b = takes.frame_start[t] + int(e["end_frame"])
        hit = np.nonzero((nodes.take == t) & (nodes.frame_start <= b) & (nodes.frame_start + nodes.frame_count - 1 >= a))[0]
        out.update(int(k) for k in hit)
    return out


