"""Pitch-driven head motion synthesis (Chuang & Bregler 2005 §5.2-5.4).

A library holds, per captured take, its cleaned pitch, its §5.1 segments and its head motion
(rotation vector in degrees and translation in mm, relative to the take's mean pose, at the
capture rate). For new speech: the top M takes by phrase features (§5.2, first stage); for
each input segment the top K library segments of those takes by Eq. 10-12; a trellis over
them searched by Viterbi with the transition cost of Eq. 13-15 (§5.3), one search per
subsentence (split where the speaker pauses, §5.4); the chosen head motion resampled to the
input segments, each segment's start moved onto the previous end, each subsentence linearly
warped onto the one before, and joins smoothed (§5.4).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from facesynth.domain.speech import pitch as P


@dataclass
class LibraryTake:
    """One captured take: name, sentence, cleaned pitch (Hz, NaN unvoiced, every ``hop_s`` s),
    its segments, head (F, 6): rotation vector (deg) and translation (mm) at ``fps``, and its
    phrase features (:data:`~facesynth.domain.speech.pitch.SENTENCE_FEATURES`)."""

    name: str
    sentence: str
    pitch: np.ndarray
    segments: list[P.Segment]
    head: np.ndarray
    fps: float
    hop_s: float
    features: np.ndarray = field(init=False)

    def __post_init__(self):
        self.features = P.sentence_features(self.pitch, self.hop_s)


@dataclass
class Choice:
    """The library segment chosen for one input segment: take row, segment index, node cost."""

    take: int
    index: int
    cost: float


@dataclass
class Result:
    """Synthesized head motion: head (T, 6) at ``fps`` (rotation vector deg, translation mm),
    the input segments and what was chosen for each."""

    head: np.ndarray
    fps: float
    segments: list[P.Segment]
    choices: list[Choice]


def _head_slice(t: LibraryTake, seg: P.Segment) -> np.ndarray:
    a = int(round(seg.start * t.fps))
    b = max(a + 2, int(round(seg.end * t.fps)))
    h = t.head[a:min(b, len(t.head))]
    return h if len(h) >= 1 else t.head[-1:]


def _boundary(h: np.ndarray, fps: float, at_end: bool) -> np.ndarray:
    """(3, 6) position, velocity, acceleration at a segment's start or end (Eq. 13's P, V, A)."""
    x = h[::-1] if at_end else h
    x = np.concatenate([x, np.repeat(x[-1:], max(0, 3 - len(x)), 0)])
    pos = x[0]
    vel = (x[1] - x[0]) * fps
    acc = (x[2] - 2 * x[1] + x[0]) * fps * fps
    if at_end:
        vel = -vel
    return np.stack([pos, vel, acc])


def top_sentences(library: list[LibraryTake], features: np.ndarray, m: int, exclude: set[str]) -> list[int]:
    """§5.2 first stage: rows of the ``m`` library takes whose normalised phrase features are
    nearest (Euclidean) to ``features``; takes of sentences in ``exclude`` are skipped."""
    rows = [i for i, t in enumerate(library) if t.sentence not in exclude and t.segments]
    F = np.array([library[i].features for i in rows])
    mu, sd = F.mean(0), F.std(0)
    sd[sd < 1e-9] = 1.0
    d = np.linalg.norm((F - mu) / sd - (features - mu) / sd, axis=1)
    return [rows[k] for k in np.argsort(d, kind="stable")[:m]]


def _viterbi(node: list[np.ndarray], trans: list[np.ndarray]) -> list[int]:
    """Best path through a trellis: node[t] (K_t,) costs, trans[t] (K_t, K_t+1) costs."""
    cost = node[0].copy()
    back = []
    for t in range(1, len(node)):
        total = cost[:, None] + trans[t - 1]
        back.append(np.argmin(total, axis=0))
        cost = total.min(axis=0) + node[t]
    path = [int(np.argmin(cost))]
    for b in reversed(back):
        path.append(int(b[path[-1]]))
    return path[::-1]


def subsentences(segs: list[P.Segment], breath_s: float) -> list[list[int]]:
    """§5.4: segment indices grouped into subsentences, split after a segment whose voiceless
    tail lasts at least ``breath_s`` (a breath)."""
    groups, cur = [], []
    for i, s in enumerate(segs):
        cur.append(i)
        if s.end - s.voiced_end >= breath_s and i + 1 < len(segs):
            groups.append(cur)
            cur = []
    if cur:
        groups.append(cur)
    return groups


def search(library: list[LibraryTake], segs: list[P.Segment], features: np.ndarray, *, m: int, k: int, b: float,
           c: float, omega_h: float, omega_r: float, breath_s: float, exclude: frozenset[str] | set[str] = frozenset()) -> list[Choice]:
    """§5.2-5.3: a library segment for every input segment (the trellis path per subsentence)."""
    rows = top_sentences(library, features, m, set(exclude))
    hop = library[rows[0]].hop_s
    cands = [(r, j) for r in rows for j in range(len(library[r].segments))]
    allsegs = [s for t in library for s in t.segments]
    n_avg = max(2, int(round(np.mean([len(s.contour) for s in allsegs]))))
    geo = np.array([P.geometry(s.contour, hop) for s in allsegs])
    g_sd = geo.std(0)
    g_sd[g_sd < 1e-9] = 1.0
    p_sd = max(float(np.concatenate([s.contour for s in allsegs]).std()), 1e-6)
    cg = np.array([P.geometry(library[r].segments[j].contour, hop) for r, j in cands])
    cp = np.array([P.resample(library[r].segments[j].contour, n_avg) for r, j in cands])
    cl = np.array([library[r].segments[j].end - library[r].segments[j].start for r, j in cands])
    # boundaries of each candidate's head motion, for Eq. 13; weights normalise each term's mean
    heads = [_head_slice(library[r], library[r].segments[j]) for r, j in cands]
    fps = library[rows[0]].fps
    starts = np.array([_boundary(h, fps, False) for h in heads])   # (C, 3, 6)
    ends = np.array([_boundary(h, fps, True) for h in heads])
    diff2 = ((ends[:, None] - starts[None]) ** 2).sum(-1)           # (C, C, 3)
    w = 1.0 / np.maximum(diff2.reshape(-1, 3).mean(0), 1e-12)
    H = (diff2 * w).sum(-1)                                         # Eq. 13
    R = np.ones((len(cands), len(cands)))                           # Eq. 14
    for x, (r, j) in enumerate(cands):
        for y, (r2, j2) in enumerate(cands):
            if r == r2 and j2 == j + 1:
                R[x, y] = 0.0
            elif r == r2 and j2 == j:
                R[x, y] = 2.0
    C = omega_h * H + omega_r * R                                   # Eq. 15
    node, keep = [], []
    for s in segs:
        gd = np.sqrt(np.mean(((cg - P.geometry(s.contour, hop)) / g_sd) ** 2, axis=1))
        pd = np.sqrt(np.mean((cp - P.resample(s.contour, n_avg)) ** 2, axis=1)) / p_sd   # Eq. 10
        ld = np.abs(cl - (s.end - s.start)) / max(s.end - s.start, 1e-6)                 # Eq. 11
        d = b * gd + c * pd + (1 - b - c) * ld                                           # Eq. 12
        top = np.argsort(d, kind="stable")[:k]
        keep.append(top)
        node.append(d[top])
    out: list[Choice] = []
    for group in subsentences(segs, breath_s):
        path = _viterbi([node[i] for i in group], [C[np.ix_(keep[i], keep[i2])] for i, i2 in zip(group, group[1:])])
        for i, p in zip(group, path):
            r, j = cands[keep[i][p]]
            out.append(Choice(r, j, float(node[i][p])))
    return out


def random_choices(library: list[LibraryTake], n: int, rng: np.random.Generator,
                   exclude: frozenset[str] | set[str] = frozenset()) -> list[Choice]:
    """A baseline: ``n`` library segments drawn uniformly (no pitch matching, no trellis)."""
    pool = [(r, j) for r, t in enumerate(library) if t.sentence not in exclude for j in range(len(t.segments))]
    picks = rng.integers(0, len(pool), n)
    return [Choice(pool[p][0], pool[p][1], float("nan")) for p in picks]


def blend(library: list[LibraryTake], segs: list[P.Segment], choices: list[Choice], duration_s: float, fps: float,
          *, breath_s: float, join_smooth_s: float) -> np.ndarray:
    """§5.4: the chosen head motion on the input's timeline. Returns (T, 6) at ``fps``
    (T = ceil(duration_s * fps)); frames before the first onset hold the first pose."""
    from scipy.ndimage import gaussian_filter1d

    T = max(1, int(np.ceil(duration_s * fps)))
    out = np.zeros((T, 6))
    if not segs:
        return out
    bounds = [(min(T - 1, int(round(s.start * fps))), min(T, max(int(round(s.start * fps)) + 1, int(round(s.end * fps)))))
              for s in segs]
    joins = []
    prev_end = None
    for group in subsentences(segs, breath_s):
        first_start, sub_a = None, bounds[group[0]][0]
        for i in group:
            a, z = bounds[i]
            t = library[choices[i].take]
            h = _head_slice(t, t.segments[choices[i].index])
            n = max(z - a, 1)
            src = np.linspace(0, len(h) - 1, n + 1)
            piece = np.stack([np.interp(src, np.arange(len(h)), h[:, d]) for d in range(6)], 1)
            if first_start is None:
                first_start = piece[0].copy()
                level = piece[0]
            else:
                piece = piece - piece[0] + level           # start moved onto the previous end
            out[a:a + n] = piece[:n]
            level = piece[n]
        sub_z = bounds[group[-1]][1]
        if prev_end is not None:                            # warp the subsentence onto the previous one
            u = np.linspace(1.0, 0.0, sub_z - sub_a)[:, None]
            out[sub_a:sub_z] += u * (prev_end - first_start)
        prev_end = out[sub_z - 1].copy()
        joins.extend(bounds[i][0] for i in group)
    first = bounds[0][0]
    out[:first] = out[first]
    out[bounds[-1][1]:] = out[bounds[-1][1] - 1]
    sigma = join_smooth_s * fps
    if sigma > 0 and T > 1:
        smooth = gaussian_filter1d(out, sigma, axis=0, mode="nearest")
        reach = int(np.ceil(3 * sigma))
        for j in joins[1:]:
            lo, hi = max(0, j - reach), min(T, j + reach + 1)
            wgt = np.exp(-0.5 * ((np.arange(lo, hi) - j) / max(sigma, 1e-9)) ** 2)[:, None]
            out[lo:hi] = wgt * smooth[lo:hi] + (1 - wgt) * out[lo:hi]
    return out
