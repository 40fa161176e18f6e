"""Cost terms of paper VI-B: transition cost (Table I, Eq. 6-9), observation cost (Table II),
emotion mismatch penalty (Eq. 5) and blocking penalty (Eq. 10).

Eq. 10 read literally would block every node at every unconstrained step; the intent
(stated in the text) is that at a constrained step ``t_m`` every node except ``o_{i_m}``
gets ``HugePenalty``, and unconstrained steps get 0. That is what is implemented.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.ipa import festival_phone_ipa, match_level, phone_distance
from facesynth.base.phonemes import PAU, viseme


@dataclass
class StepCosts:
    """Per input step t and node j, float32 (T, N): observation, emotion and blocking terms."""

    oc: np.ndarray
    emp: np.ndarray
    block: np.ndarray

    @property
    def total(self) -> np.ndarray:
        """(T, N) float32: the sum of the three terms."""
        return (self.oc + self.emp + self.block).astype(np.float32)


def transition_rows(rows: slice, dsc: np.ndarray, pgap: np.ndarray, vgap: np.ndarray, node_viseme: np.ndarray,
                    pre: np.ndarray, s: SynthesizeSettings) -> np.ndarray:
    """Rows ``rows`` of TC (Table I), float32; ``dsc``/``pgap``/``vgap`` hold just those rows.

    Rule 1: pre(o_j) = o_i -> 0. Rule 2: viseme(o_i) = viseme(pre(o_j)) ->
    alpha2 DSC + PVC. Rule 3: otherwise alpha2 DSC + PVC + PNT. Rule 4: pre(o_j) = NIL ->
    alpha1 PNT + PVC (the paper: alpha1 PNT alone, so a join into the first phone of a
    captured phrase had no continuity check at all). PVC = alpha3 PGap + VGap (Eq. 7).
    """
    has_pre = pre >= 0
    pre_viseme = np.where(has_pre, node_viseme[np.maximum(pre, 0)], -1)
    rule4 = np.float32(s.alpha3) * pgap[:, ~has_pre]  # rule 4: (alpha3 PGap + VGap) + alpha1 PNT
    rule4 += vgap[:, ~has_pre]
    rule4 += np.float32(s.alpha1 * s.pnt)
    t = np.float32(s.alpha2) * dsc
    t += np.float32(s.alpha3) * pgap
    t += vgap
    t += np.float32(s.pnt) * (node_viseme[rows, None] != pre_viseme[None, :])
    t[:, ~has_pre] = rule4
    captured = np.nonzero(has_pre & (pre >= rows.start) & (pre < rows.stop))[0]
    t[pre[captured] - rows.start, captured] = 0.0
    return t.astype(np.float32, copy=False)


def transition_panel_rows(panels: np.ndarray, rows: slice, dsc: np.ndarray, pgap: np.ndarray, vgap: np.ndarray,
                          node_viseme: np.ndarray, pre: np.ndarray, s: SynthesizeSettings,
                          scratch: np.ndarray | None = None) -> None:
    """Write rows ``rows`` of TC (Table I) straight into a panel-major matrix.

    panels : (n_panels, N, W) float32, ``panels[p, i, c] = TC[i, p * W + c]``
        (:class:`~facesynth.domain.search.dp.PanelMatrix`); only ``panels[:, rows, :]`` is written,
        the padding columns past N are left as they are.
    dsc, pgap, vgap : (r, N) float32, rows ``rows`` of the pair terms (mm^2/frame^3, mm, mm/frame).
    scratch : (2, r', N) float32 work space with r' >= r, or None to allocate it.

    The same float32 operations in the same order as :func:`transition_rows`, so the values
    are bit-identical. The sums run over contiguous rows in ``scratch`` and the result is
    copied into the panel layout once; no (r, N) array is allocated when ``scratch`` is given.
    """
    n, width = len(pre), panels.shape[2]
    r = rows.stop - rows.start
    total, term = np.empty((2, r, n), np.float32) if scratch is None else scratch[:, :r]
    has_pre = pre >= 0
    pre_viseme = np.where(has_pre, node_viseme[np.maximum(pre, 0)], -1)
    # PNT * [viseme(o_i) != viseme(pre(o_j))] for each viseme a row can have: (V, N) float32
    penalty = np.float32(s.pnt) * (np.arange(node_viseme.max() + 1)[:, None] != pre_viseme[None, :])
    np.multiply(dsc, np.float32(s.alpha2), out=total)
    np.multiply(pgap, np.float32(s.alpha3), out=term)
    total += term
    total += vgap
    rule4 = np.float32(s.alpha3) * pgap[:, ~has_pre]
    rule4 += vgap[:, ~has_pre]
    rule4 += np.float32(s.alpha1 * s.pnt)
    np.take(penalty, node_viseme[rows], axis=0, out=term)
    total += term
    total[:, ~has_pre] = rule4
    captured = np.nonzero(has_pre & (pre >= rows.start) & (pre < rows.stop))[0]
    total[pre[captured] - rows.start, captured] = 0.0
    full = n // width
    panels[:full, rows] = total[:, : full * width].reshape(r, full, width).transpose(1, 0, 2)
    if full < len(panels):
        panels[full, rows, : n - full * width] = total[:, full * width :]


def transition_matrix(dsc: np.ndarray, pgap: np.ndarray, vgap: np.ndarray, node_viseme: np.ndarray,
                      pre: np.ndarray, s: SynthesizeSettings) -> np.ndarray:
    """TC[i, j] of Table I, (N, N) float32, row i = the node before, column j = the node after."""
    n = len(pre)
    tc = np.empty((n, n), np.float32)
    for a in range(0, n, 1024):
        rows = slice(a, min(n, a + 1024))
        tc[rows] = transition_rows(rows, dsc[rows], pgap[rows], vgap[rows], node_viseme, pre, s)
    return tc


def step_costs(phones: list[str], emotions: list[str], node_phone: list[str], node_emotion: list[str],
               constraints: dict[int, int], s: SynthesizeSettings, ipa: list[str] | None = None,
               node_ipa: list[str] | None = None) -> StepCosts:
    """OC (Table II), EMP (Eq. 5) and B (Eq. 10) for every input step and node.

    ``phones``/``node_phone`` are Festival phones. ``ipa``: the IPA phone each step pronounces
    (a line in another language: :attr:`~facesynth.domain.speech.utterance.Utterance.ipa`;
    ``""`` or None: the step's Festival phone); ``node_ipa`` likewise for the nodes. Under
    ``s.phone_match`` (see :func:`phone_match_costs`) such a phone, or every phone, is matched by
    its distance in articulatory features; a step without IPA under ``viseme`` or ``unseen`` is
    Table II exactly: the same phone 0, the same viseme alpha4 alpha5 PNT, else alpha5 PNT."""
    t_count, n = len(phones), len(node_phone)
    phone_codes, node_phone_code = _codes(node_phone)
    emotion_codes, node_emo = _codes(node_emotion)
    node_vis = np.array([viseme(p) for p in phone_codes], np.int64)[node_phone_code]
    oc = np.empty((t_count, n), np.float32)
    emp = np.empty((t_count, n), np.float32)
    block = np.zeros((t_count, n), np.float32)
    by_features = phone_match_costs(phones, ipa, (phone_codes, node_phone_code), node_ipa, node_vis, s)
    for t, (p, e) in enumerate(zip(phones, emotions)):
        if p == PAU:
            oc[t] = 0.0
        elif t in by_features:
            oc[t] = by_features[t]
        else:
            same_phone = node_phone_code == phone_codes.get(p, -1)
            same_viseme = node_vis == viseme(p)
            oc[t] = np.where(same_phone, 0.0, np.where(same_viseme, s.alpha4 * s.alpha5 * s.pnt, s.alpha5 * s.pnt))
        emp[t] = np.where(node_emo == emotion_codes.get(e, -1), 0.0, s.alpha6 * s.pnt)
    for t, node in constraints.items():
        block[t] = s.huge_penalty
        block[t, node] = 0.0
    return StepCosts(oc, emp, block)


def phone_match_costs(phones: list[str], ipa: list[str] | None, node_phone: tuple[dict[str, int], np.ndarray],
                      node_ipa: list[str] | None, node_vis: np.ndarray, s: SynthesizeSettings) -> dict[int, np.ndarray]:
    """The observation cost (N,) float64 of the steps matched by articulatory features
    (``synthesize.phone_match``), by step; the other steps keep Table II on their Festival phones.
    ``node_phone``: the nodes' Festival phones as :func:`_codes` gives them (each distinct
    phone's code, the (N,) int64 codes); ``node_vis``: (N,) int64 their visemes.

    A step's phone is its IPA (``ipa[t]``) or its Festival phone's; a node's likewise. Under
    ``viseme`` no step is matched by features. Under ``unseen`` a step given in IPA is: when some
    node's phone has its features (the database has the phone), those nodes cost 0, the others
    Table II's levels by the viseme of the step's nearest English phone; when none has, each node
    costs :func:`~facesynth.base.ipa.match_level` of how much further its phone is from the step's
    than the nearest phone the database has (so the nearest phone's nodes cost 0, as the same
    phone would, and the others rise with their extra distance), times alpha5 PNT. Under
    ``features`` every spoken step costs the latter (0 extra distance for a phone the database
    has: the distance itself)."""
    if s.phone_match == "viseme" or (s.phone_match == "unseen" and not any(ipa or ())):
        return {}
    if node_ipa is None:  # English nodes: each distinct phone's IPA
        distinct, node_code = [festival_phone_ipa(p) for p in node_phone[0]], node_phone[1]
    else:
        names = list(node_phone[0])
        node_codes, node_code = _codes([q or festival_phone_ipa(names[c]) for q, c in zip(node_ipa, node_phone[1])])
        distinct = list(node_codes)
    unit = s.alpha5 * s.pnt
    out: dict[int, np.ndarray] = {}
    levels: dict[str, np.ndarray] = {}
    for t, p in enumerate(phones):
        q = (ipa[t] if ipa is not None else "") or ""
        if p == PAU or (s.phone_match == "unseen" and not q):
            continue
        q = q or festival_phone_ipa(p)
        if q not in levels:
            d = np.array([phone_distance(q, name) for name in distinct], np.float64)
            if s.phone_match == "unseen" and (d == 0.0).any():
                level = np.where((d == 0.0)[node_code], 0.0, np.where(node_vis == viseme(p), s.alpha4, 1.0))
            else:  # the phones nearest it stand in for the phone itself, the others dearer by how much further
                level = np.array([match_level(x, s.alpha4, s.phone_match_scale) for x in d - d.min()],
                                 np.float64)[node_code]
            levels[q] = unit * level
        out[t] = levels[q]
    return out


def _codes(names: list[str]) -> tuple[dict[str, int], np.ndarray]:
    """Each distinct name's code (in order of first appearance) and the (N,) int64 codes of
    ``names``: comparisons per input step on integers instead of strings."""
    codes: dict[str, int] = {}
    return codes, np.fromiter((codes.setdefault(x, len(codes)) for x in names), np.int64, len(names))


def path_terms(path: np.ndarray, tc, steps: StepCosts) -> dict[str, np.ndarray]:
    """Every cost term along a path: tc[t] is the transition into step t (0 at t = 0).
    ``tc`` is the (N, N) matrix, a :class:`~facesynth.domain.search.dp.PanelMatrix` or a
    :class:`~facesynth.domain.search.pairs.TransitionCosts`."""
    t_idx = np.arange(len(path))
    tcs = np.zeros(len(path), np.float32)
    tcs[1:] = [tc[int(i), int(j)] for i, j in zip(path[:-1], path[1:])]
    return {"tc": tcs, "oc": steps.oc[t_idx, path], "emp": steps.emp[t_idx, path], "block": steps.block[t_idx, path]}
