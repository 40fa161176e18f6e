"""Hard motion-node constraints of a synthesis request (the paper's Eq. 10): a phone of the
utterance pinned to a captured motion node, from a constraints file or given (format in
``docs/inputs.md``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError, SearchError
from facesynth.base.phonemes import PAU
from facesynth.domain.speech.utterance import Utterance
from facesynth.formats.labels import read_text


def read_constraints(path: Path, utt: Utterance, node_phone: list[str]) -> dict[int, int]:
    """Hard motion-node constraints: ``INDEX NODE`` (0-based phone index) or ``TIMEs NODE``
    (a time in seconds with an ``s`` suffix) per line. Returns {phone index: node id}."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: constraints file not found; check the --constraints path.")
    out: dict[int, int] = {}
    for n, line in enumerate(read_text(path, "constraints file").splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        where = f"{path}, line {n}"
        parts = line.split()
        if len(parts) != 2:
            raise InputError(f"{where}: expected 'INDEX NODE' or 'TIMEs NODE', got {line!r}.")
        at, node_text = parts
        try:
            node = int(node_text)
            if at.endswith("s"):
                time_s = float(at[:-1])
                index = utt.index_at(time_s)
                if index is None:
                    raise SearchError(f"{where}: time {time_s:.3f} s is outside the utterance (0 to {utt.ends[-1]:.3f} s).")
                place = f"the phone at {time_s:.3f} s (index {index})"
            else:
                index = int(at)
                if not 0 <= index < len(utt):
                    raise SearchError(f"{where}: phone index {index} is out of range (0 to {len(utt) - 1}).")
                place = f"phone {index}"
        except ValueError:
            raise InputError(f"{where}: expected 'INDEX NODE' or 'TIMEs NODE' with numbers, got {line!r}.") from None
        _add_constraint(out, index, node, place, where, utt, node_phone)
    return out


def given_constraints(constraints, utt: Utterance, node_phone: list[str],
                      where: str = "the constraints given") -> dict[int, int]:
    """Hard motion-node constraints given as {phone index: node id} (0-based phone index of
    ``utt``), checked as a constraints file's lines are. Returns a new {phone index: node id}."""
    out: dict[int, int] = {}
    for at, node in dict(constraints).items():
        here = f"{where}, phone {at!r}"
        if isinstance(at, bool) or not isinstance(at, (int, np.integer)) or isinstance(node, bool) \
                or not isinstance(node, (int, np.integer)):
            raise InputError(f"{here}: expected a phone index and a node id, both whole numbers, got {at!r}: {node!r}.")
        index, node = int(at), int(node)
        if not 0 <= index < len(utt):
            raise SearchError(f"{here}: phone index {index} is out of range (0 to {len(utt) - 1}).")
        _add_constraint(out, index, node, f"phone {index}", here, utt, node_phone)
    return out


def _add_constraint(out: dict[int, int], index: int, node: int, place: str, where: str, utt: Utterance,
                    node_phone: list[str]) -> None:
    """Add ``index -> node`` to ``out`` after the checks every constraint passes (the node
    exists, is of the phone's phone, the phone is spoken and not constrained already)."""
    if not 0 <= node < len(node_phone):
        raise SearchError(f"{where}: node {node} does not exist (the database has nodes 0 to {len(node_phone) - 1}).")
    if utt.phones[index] == PAU:
        raise SearchError(f"{where}: {place} is a pause, whose frames are interpolated; constrain a spoken phone.")
    if node_phone[node] != utt.phones[index]:
        raise SearchError(f"{where}: node {node} is /{node_phone[node]}/ but {place} is /{utt.phones[index]}/; pick a node of that phone (see facesynth suggest).")
    if index in out:
        raise SearchError(f"{where}: {place} is already constrained to node {out[index]}; keep one constraint per phone.")
    out[index] = node
