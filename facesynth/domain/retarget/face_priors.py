"""What the solve knows of a face beyond the markers: which channels of a rig oppose each other
(antagonists: jawLeft and jawRight, a side's smile and frown) and which move together when the
face moves symmetrically (a left and right brow raise), found from the rig's shape names.

Names are read as ARKit's and ICT-FaceKit's are: a side is a suffix ``Left``/``Right`` or
``_L``/``_R`` (case aside). ``jawLeft``/``jawRight`` and ``mouthLeft``/``mouthRight`` are
directions, not sides: they are antagonists and never symmetric; the gaze channels
(``eyeLook*``) are never tied either (looking left turns the eyes the same way, not mirrored).

Antagonists (:data:`SAME_SIDE_ANTAGONISTS`, each on each side; a channel without a side, e.g.
ARKit's ``browInnerUp``, opposes both sides' partner): smile and frown, brow down and brow raise
(inner, outer), eyes wide and blink, eyes wide and squint, gaze up and down, gaze in and out.
"""

from __future__ import annotations

import re

#: Channel bases (the name without its side) that oppose each other on one side of the face.
SAME_SIDE_ANTAGONISTS = (("mouthsmile", "mouthfrown"), ("browdown", "browinnerup"), ("browdown", "browouterup"),
                         ("eyewide", "eyeblink"), ("eyewide", "eyesquint"), ("eyelookup", "eyelookdown"),
                         ("eyelookin", "eyelookout"))
#: Channels named by a direction: the left one opposes the right one; neither is a side.
DIRECTIONS = ("jaw", "mouth")
#: Bases never tied symmetric (the gaze).
NOT_SYMMETRIC = ("eyelook",)

_SIDE = re.compile(r"^(.+?)_?(left|right|l|r)$")


def _split(name: str) -> tuple[str, str | None]:
    """(base, side 'l' / 'r' / None) of a channel name, lower case."""
    low = name.lower()
    m = _SIDE.match(low)
    if not m:
        return low, None
    return m.group(1), m.group(2)[0]


def antagonist_pairs(names: list[str] | tuple[str, ...]) -> list[tuple[int, int]]:
    """(i, j) index pairs of channels of ``names`` that should not both be on."""
    parts = [_split(n) for n in names]
    index = {p: i for i, p in enumerate(parts)}
    pairs = []
    for base in DIRECTIONS:
        if (base, "l") in index and (base, "r") in index:
            pairs.append((index[(base, "l")], index[(base, "r")]))
    for a, b in SAME_SIDE_ANTAGONISTS:
        for side in ("l", "r"):
            ia = index.get((a, side), index.get((a, None)))
            ib = index.get((b, side), index.get((b, None)))
            if ia is not None and ib is not None and (ia, ib) not in pairs:
                pairs.append((ia, ib))
    return pairs


def symmetric_pairs(names: list[str] | tuple[str, ...]) -> list[tuple[int, int]]:
    """(left, right) index pairs of channels of ``names`` that mirror each other."""
    parts = [_split(n) for n in names]
    index = {p: i for i, p in enumerate(parts)}
    pairs = []
    for (base, side), i in index.items():
        if side != "l" or base in DIRECTIONS or base.startswith(NOT_SYMMETRIC) or (base, "r") not in index:
            continue
        pairs.append((i, index[(base, "r")]))
    return pairs
