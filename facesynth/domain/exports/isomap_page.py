"""The Isomap constraint page (paper VI-A, Fig. 9): one self-contained HTML file in which a
user picks a time or phone of an utterance and sees, on that phone's Isomap, every node's
*time-correct* frame and the *context-correct* nodes highlighted (the definitions of
:mod:`facesynth.domain.search.constraint_choice`, the ones ``facesynth suggest`` lists), the node
the synthesized path chose there, and by clicking a node writes the constraint line
``TIMEs NODE`` that ``facesynth synthesize --constraints`` reads.

The page holds the maps as PNG data URLs and the utterance, nodes and pixel positions as
JSON; nothing is fetched. The script computes a node's time-correct frame for the time in
the time field with :func:`~facesynth.domain.search.constraint_choice.time_correct_offset`'s
formula (tests hold the two to the same frames).
"""

from __future__ import annotations

import base64
import html
import json
from collections.abc import Sequence
from importlib import resources
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.search.constraint_choice import context_correct, context_name
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.artifacts import recorded_inputs, sha256_of
from facesynth.model.isomap import Cluster, PhonemeMaps
from facesynth.model.motion import Motion, SearchPath
from facesynth.model.motiondb import MotionDatabase


def require_same_database(path: Path, kind: str, what: str, db_path: Path, make: str) -> None:
    """Refuse an artifact (``what``: "was built", "was synthesized") whose recorded ``motiondb``
    input is not the file at ``db_path`` (compared by sha256); ``make`` is the command that
    makes a matching one. An artifact that records no database passes (the node checks of the
    callers still apply)."""
    recorded = [r for r in recorded_inputs(path, kind) if r.get("kind") == MotionDatabase.KIND]
    if not recorded:
        return
    digest = sha256_of(db_path)
    if all(r.get("sha256") != digest for r in recorded):
        raise InputError(f"{path}: {what} from another database ({recorded[0].get('path')}, sha256 "
                         f"{str(recorded[0].get('sha256'))[:12]}) than {db_path} (sha256 {digest[:12]}); {make}.")


def check_maps(maps: PhonemeMaps, db: MotionDatabase, isomap_path: Path, db_path: Path) -> None:
    """Every cluster's nodes are nodes of ``db`` of the cluster's phone, with as many frames."""
    for phone, c in maps.clusters.items():
        nodes, counts = np.unique(c.node, return_counts=True)
        if len(nodes) and (nodes.max() >= len(db.nodes) or any(db.nodes.phone[int(n)] != phone for n in nodes)
                           or (db.nodes.frame_count[nodes] != counts).any()):
            raise InputError(f"{isomap_path}: its /{phone}/ map holds nodes that {db_path} does not have; "
                             f"run facesynth isomap build {db_path} -o ISOMAP.h5 and use that.")


def check_path(path: SearchPath | None, utt: Utterance, db: MotionDatabase, motion_path: Path, phones_path: Path,
               db_path: Path) -> SearchPath:
    """The motion's search ``path``, refused unless it is one of ``db``'s nodes per phone of ``utt``."""
    if path is None:
        raise InputError(f"{motion_path}: holds no search path (it was not made by facesynth synthesize); "
                         "give a motion synthesized for this utterance, or leave --motion out.")
    if list(path.phone) != list(utt.phones):
        step = next((k for k, (a, b) in enumerate(zip(path.phone, utt.phones)) if a != b), min(len(path.phone), len(utt.phones)))
        raise InputError(f"{motion_path}: was synthesized for another utterance than {phones_path} "
                         f"({len(path.phone)} phones against {len(utt.phones)}, first different at phone {step}); "
                         "give the motion synthesized from these phonemes.")
    for k, node in enumerate(path.node):
        if utt.phones[k] != PAU and 0 <= node and (node >= len(db.nodes) or db.nodes.phone[int(node)] != path.node_phone[k]):
            raise InputError(f"{motion_path}: its path uses node {int(node)} at phone {k}, which {db_path} does not "
                             f"have as /{path.node_phone[k]}/; give a motion synthesized from {db_path}.")
    return path


def require_maps_of(maps: PhonemeMaps, db: MotionDatabase, isomap_path: Path, db_path: Path) -> None:
    """Refuse maps built from another database than ``db_path``, or holding nodes it lacks."""
    require_same_database(isomap_path, PhonemeMaps.KIND, "was built", db_path,
                          f"run facesynth isomap build {db_path} -o ISOMAP.h5 and use that")
    check_maps(maps, db, isomap_path, db_path)


def checked_motion_path(motion_path: Path, utt: Utterance, db: MotionDatabase, phones_path: Path,
                        db_path: Path) -> tuple[SearchPath, list[str]]:
    """The search path of the motion at ``motion_path``, checked to be ``db``'s nodes for
    ``utt``, with a warning when it was synthesized with other emotions than the page's."""
    require_same_database(motion_path, Motion.KIND, "was synthesized", db_path,
                          f"give a motion synthesized from {db_path}, or that motion's database")
    path = check_path(Motion.read_search(motion_path)[0], utt, db, motion_path, phones_path, db_path)
    differ, notes = emotion_differences(path, utt), []
    if differ:
        k = differ[0]
        notes.append(f"{motion_path} was synthesized with other emotions than the page's at {len(differ)} phones "
                     f"(phone {k} /{utt.phones[k]}/: {path.emotion[k]}, not {utt.emotions[k]}); "
                     "give the --emotions it was made with")
    return path, notes


def emotion_differences(path: SearchPath, utt: Utterance) -> list[int]:
    """The spoken steps whose emotion in the motion's search differs from the utterance's."""
    return [k for k, (made, asked) in enumerate(zip(path.emotion, utt.emotions)) if utt.phones[k] != PAU and made != asked]


def mid_time(utt: Utterance, c: int) -> float:
    """Step ``c``'s mid time rounded to the millisecond (its start when rounding leaves it)."""
    mid = round(0.5 * (float(utt.starts[c]) + float(utt.ends[c])), 3)
    return mid if utt.index_at(mid) == c else float(utt.starts[c])


def page_data(maps: PhonemeMaps, db: MotionDatabase, utt: Utterance, constraints: dict[int, int],
              path: SearchPath | None, pictures: dict[str, tuple[bytes, np.ndarray]], command: str) -> dict:
    """What the page's script needs. ``pictures``: per phone of the utterance that has a map,
    its Isomap PNG and every cluster row's pixel position (n, 2) on it; ``command``: the
    synthesize command line the constraints are for.

    Per step: phone, start/end (s), emotion, triphone context, the context-correct nodes, the
    chosen node (-1 without a path or in a pause), a millisecond mid time. Per map: the image,
    its size, the pixels and per node ``[node, first row, frames, first frame in its take,
    emotion, take, context]``."""
    steps = []
    for c, phone in enumerate(utt.phones):
        spoken = phone != PAU
        steps.append({
            "phone": phone, "start": float(utt.starts[c]), "end": float(utt.ends[c]), "emotion": utt.emotions[c],
            "context": context_name(utt.phones, c) if spoken else "",
            "contextCorrect": np.nonzero(context_correct(db.nodes, utt.phones, c))[0].tolist() if spoken else [],
            "chosen": int(path.node[c]) if path is not None and spoken else -1,
            "mid": mid_time(utt, c)})
    out_maps = {}
    for phone, (png, pixels) in pictures.items():
        cluster: Cluster = maps.clusters[phone]
        rows = []
        for node in np.unique(cluster.node):
            n = int(node)
            first = int(np.nonzero(cluster.node == node)[0][0])
            take = int(db.nodes.take[n])
            rows.append([n, first, int(db.nodes.frame_count[n]), int(db.nodes.frame_start[n]) - int(db.takes.frame_start[take]),
                         db.nodes.emotion[n], db.takes.name[take], f"{db.nodes.prev_phone[n]}-{phone}+{db.nodes.next_phone[n]}"])
        out_maps[phone] = {"image": "data:image/png;base64," + base64.b64encode(png).decode("ascii"),
                           "px": np.round(pixels, 1).tolist(), "nodes": rows}
    initial = [[c, mid_time(utt, c), node] for c, node in sorted(constraints.items())]
    return {"steps": steps, "maps": out_maps, "constraints": initial, "command": command}


def render_page(data: dict, title: str, size: int) -> str:
    """The page's HTML: the template of ``facesynth/data/isomap_page.html`` with ``data``."""
    template = resources.files("facesynth").joinpath("data").joinpath("isomap_page.html").read_text(encoding="utf-8")
    blob = json.dumps(data, separators=(",", ":")).replace("</", "<\\/")
    return (template.replace("<!--TITLE-->", html.escape(title)).replace("__SIZE__", str(int(size)))
            .replace("<!--DATA-->", f'<script type="application/json" id="pagedata">{blob}</script>'))


def synthesize_command(db_path: Path, phones_path: Path, emotions_path: Path | None) -> str:
    """The synthesize command line the page's constraints are for."""
    emotions = f" --emotions {emotions_path}" if emotions_path is not None else ""
    return f"facesynth synthesize {db_path} --phonemes {phones_path}{emotions} --constraints constraints.txt -o constrained.h5"


def missing_phones(utt: Utterance, maps: PhonemeMaps) -> list[str]:
    """The spoken phones of the utterance that have no map (the database has no node of them)."""
    return [p for p in dict.fromkeys(utt.phones) if p != PAU and p not in maps.clusters]


def require_some_map(utt: Utterance, maps: PhonemeMaps, phones_path: Path, db_path: Path) -> list[str]:
    """The spoken phones without a map; an InputError when no spoken phone has one (nothing to constrain)."""
    missing = missing_phones(utt, maps)
    spoken: Sequence[str] = [p for p in dict.fromkeys(utt.phones) if p != PAU]
    if spoken and len(missing) == len(spoken):
        raise InputError(f"{phones_path}: {db_path} has no node of any of its phones ({', '.join('/' + p + '/' for p in missing)}), "
                         "so no phone can be constrained; give phonemes of the language the database was captured in.")
    if not spoken:
        raise InputError(f"{phones_path}: holds only pauses; give an utterance with spoken phones.")
    return missing
