"""Real-time search of Cao et al. (2004) over the motion-node database.

* The **Anime Graph** is the database's captured links (``pre``/``suc``); the **Anime
  Array** lists the nodes of each phone.
* **GreedyMatching** (their Algorithm 2) tiles the input phone string with the longest
  captured runs; by their Theorem 1 a greedy tiling uses the fewest tiles, so the path has
  the minimum number of jumps (non-captured joins). Where Cao broke ties between equally
  long runs by audio features, ties here go to the lowest cost in the main paper's terms:
  the transition cost into the run (Table I) plus its emotion mismatch penalties (Eq. 5),
  so emotion is a soft preference; then the lowest node id.
* **PQ-Matching(h)** (their Algorithm 1) is the slow baseline: an exact best-first
  (priority queue) branch-and-bound search over windows of h phones, minimizing jumps and
  then the same cost; windows are concatenated.
* The **clustered graph** (their 5.3) merges nodes whose time-normalized motion falls in
  one k-means cluster into one anime with a set of phones, the union of the members'
  links and the member nearest the cluster mean as its motion.

Input phones with no node of their own are matched, like the DP's Table II, by nodes of
the same viseme, else by any node (a tile of one). Pauses split the input into separately
tiled runs; a pause step takes the node that continues the captured run before it, if any,
else the first node of the run after it (its frames are interpolated anyway).
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass

import numpy as np

from facesynth.base.phonemes import PAU, PHONE_ID, viseme


@dataclass
class AnimeGraph:
    """animes: representative node per anime; phones: (A, P) bool phone sets;
    successors: per anime, the animes that follow it in a capture (sorted)."""

    node: np.ndarray
    phones: np.ndarray
    successors: list[np.ndarray]
    suc: np.ndarray | None  # (A,) single successor when unclustered, else None
    array: dict[int, np.ndarray]  # phone id -> animes holding it (the Anime Array)
    emotion: np.ndarray  # (A,) emotion index of the representative

    @property
    def clustered(self) -> bool:
        """Whether animes are clusters of nodes (Cao et al. 5.3) rather than single nodes."""
        return self.suc is None


def _emotion_index(emotions: list[str]) -> tuple[np.ndarray, dict[str, int]]:
    names = {e: i for i, e in enumerate(sorted(set(emotions)))}
    return np.array([names[e] for e in emotions]), names


def anime_graph(node_phone: list[str], node_emotion: list[str], suc: np.ndarray) -> AnimeGraph:
    """The unclustered Anime Graph: one anime per node."""
    n = len(node_phone)
    ids = np.array([PHONE_ID[p] for p in node_phone])
    phones = np.zeros((n, len(PHONE_ID)), bool)
    phones[np.arange(n), ids] = True
    successors = [np.array([s]) if s >= 0 else np.zeros(0, np.int64) for s in suc]
    array = {int(p): np.nonzero(ids == p)[0] for p in np.unique(ids)}
    emotion, _ = _emotion_index(node_emotion)
    return AnimeGraph(np.arange(n), phones, successors, np.asarray(suc, np.int64), array, emotion)


def cluster_graph(node_phone: list[str], node_emotion: list[str], suc: np.ndarray, features: np.ndarray,
                  k: int, seed: int = 0) -> AnimeGraph:
    """Cao 5.3: k-means on time-normalized node motion (features (N, D)), merged animes."""
    from sklearn.cluster import KMeans

    n = len(node_phone)
    k = min(k, n)
    km = KMeans(n_clusters=k, n_init=1, random_state=seed).fit(features)
    labels = km.labels_
    ids = np.array([PHONE_ID[p] for p in node_phone])
    phones = np.zeros((k, len(PHONE_ID)), bool)
    phones[labels, ids] = True
    node = np.empty(k, np.int64)
    for c in range(k):
        members = np.nonzero(labels == c)[0]
        d = np.linalg.norm(features[members] - km.cluster_centers_[c], axis=1)
        node[c] = members[int(np.argmin(d))]
    links = {(int(labels[i]), int(labels[s])) for i, s in enumerate(suc) if s >= 0}
    successors = [np.array(sorted(b for a, b in links if a == c), np.int64) for c in range(k)]
    array = {int(p): np.nonzero(phones[:, p])[0] for p in np.unique(ids)}
    emotion, _ = _emotion_index(node_emotion)
    return AnimeGraph(node, phones, successors, None, array, emotion[node])


def motion_features(coeffs: np.ndarray, frame_start: np.ndarray, frame_count: np.ndarray, samples: int = 8) -> np.ndarray:
    """Each node's motion time-normalized to ``samples`` frames, flattened (N, samples * K)."""
    out = []
    for a, c in zip(frame_start, frame_count):
        x = np.linspace(a, a + c - 1, samples)
        lo = np.floor(x).astype(int)
        hi = np.minimum(lo + 1, a + c - 1)
        w = (x - lo)[:, None]
        out.append((coeffs[lo] * (1 - w) + coeffs[hi] * w).ravel())
    return np.array(out)


@dataclass
class GreedyResult:
    """A greedy search's path: per step the node ((T,) int64, the anime's representative) and
    anime ((T,) int64), and the number of jumps between spoken steps that are not captured links.
    """

    path: np.ndarray   # (T,) node per step (the anime's representative)
    animes: np.ndarray  # (T,) anime per step
    jumps: int         # joins between spoken steps that are not captured links


def tc_values(tc, i: int, js: np.ndarray) -> np.ndarray:
    """TC[i, js] from an (N, N) matrix, a PanelMatrix or a TransitionCosts (computed on demand)."""
    if isinstance(tc, np.ndarray):
        return tc[i, js]
    if hasattr(tc, "values"):
        return tc.values(i, np.asarray(js))
    return tc.panels[js // tc.panel, i, js % tc.panel]


class Greedy:
    """GreedyMatching over an Anime Graph, ties broken by Table I + Eq. 5 costs.

    tc : the transition costs (ndarray, PanelMatrix or TransitionCosts); emotion_penalty : alpha6 * PNT.
    """

    def __init__(self, graph: AnimeGraph, node_viseme: np.ndarray, node_emotion: list[str], tc, emotion_penalty: float):
        self.g = graph
        self.tc = tc
        self.penalty = emotion_penalty
        self.emotion_names = {e: i for i, e in enumerate(sorted(set(node_emotion)))}
        self.viseme_of_anime = node_viseme[graph.node]

    def candidates(self, phone: str) -> tuple[np.ndarray, bool]:
        """The Anime Array's animes for a phone (exact), else same-viseme ones, else all."""
        pid = PHONE_ID[phone]
        if pid in self.g.array:
            return self.g.array[pid], True
        same = np.nonzero(self.viseme_of_anime == viseme(phone))[0]
        return (same if len(same) else np.arange(len(self.g.node))), False

    def longest_runs(self, start: np.ndarray, phones: list[str], emotions: np.ndarray,
                     suc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Unclustered LongestMatching from every start anime at once, along ``suc`` (the
        unclustered graph's single successors). Returns (run lengths, emotion mismatches along
        each run)."""
        g = self.g
        cur = start.copy()
        alive = np.ones(len(cur), bool)
        length = np.ones(len(cur), np.int64)
        mismatches = (g.emotion[cur] != emotions[0]).astype(np.int64)
        for s in range(1, len(phones)):
            nxt = suc[cur]
            alive &= nxt >= 0
            alive[alive] = g.phones[nxt[alive], PHONE_ID[phones[s]]]
            if not alive.any():
                break
            cur = np.where(alive, nxt, cur)
            length += alive
            mismatches += alive & (g.emotion[cur] != emotions[s])
        return length, mismatches

    def longest_clustered(self, a: int, phones: list[str], memo: dict) -> tuple[int, list[int]]:
        """Clustered LongestMatching: a depth-first search over (position, anime) states,
        memoized; states only lead from position s to s + 1, so they are evaluated by
        decreasing position."""
        key = (0, a)
        if key in memo:
            return memo[key]
        seen, stack = {key}, [key]
        while stack:
            s, c = stack.pop()
            if s + 1 < len(phones):
                pid = PHONE_ID[phones[s + 1]]
                for c2 in self.g.successors[c]:
                    child = (s + 1, int(c2))
                    if self.g.phones[c2, pid] and child not in memo and child not in seen:
                        seen.add(child)
                        stack.append(child)
        for s, c in sorted(seen, reverse=True):
            best = (1, [c])
            if s + 1 < len(phones):
                pid = PHONE_ID[phones[s + 1]]
                for c2 in self.g.successors[c]:
                    if self.g.phones[c2, pid]:
                        length, run = memo[(s + 1, int(c2))]
                        if length + 1 > best[0]:
                            best = (length + 1, [c] + run)
            memo[(s, c)] = best
        return memo[key]

    def tile(self, phones: list[str], emotions: list[str], before: int) -> list[int]:
        """Greedy tiling of one spoken run; ``before`` is the node preceding it (-1 if none)."""
        g = self.g
        emo = np.array([self.emotion_names.get(e, -1) for e in emotions])
        out: list[int] = []
        i = 0
        while i < len(phones):
            cand, exact = self.candidates(phones[i])
            prev = int(g.node[out[-1]]) if out else before
            if exact and g.suc is not None:  # unclustered
                length, mismatches = self.longest_runs(cand, phones[i:], emo[i:], g.suc)
                tied = np.nonzero(length == length.max())[0]
                cost = self.penalty * mismatches[tied]
                if prev >= 0:
                    cost = cost + tc_values(self.tc, prev, g.node[cand[tied]])
                run = [int(cand[tied[int(np.argmin(cost))]])]  # lowest cost, then lowest id
                for _ in range(int(length.max()) - 1):
                    run.append(int(g.suc[run[-1]]))
            else:
                memo: dict = {}
                runs = [self.longest_clustered(int(c), phones[i:], memo) if exact else (1, [int(c)]) for c in cand]
                best = max(r[0] for r in runs)
                tied = [r[1] for r in runs if r[0] == best]
                cost = np.array([self.penalty * sum(g.emotion[a] != emo[i + k] for k, a in enumerate(run)) for run in tied], float)
                if prev >= 0:
                    cost = cost + tc_values(self.tc, prev, g.node[np.array([run[0] for run in tied])])
                run = tied[int(np.argmin(cost))]
            out += run
            i += len(run)
        return out

    def search(self, phones: list[str], emotions: list[str]) -> GreedyResult:
        """GreedyMatching (Cao et al. 5.2) for the input ``phones`` and ``emotions``."""
        animes = np.full(len(phones), -1, np.int64)
        t, before = 0, -1
        while t < len(phones):
            if phones[t] == PAU:
                t += 1
                continue
            end = t
            while end < len(phones) and phones[end] != PAU:
                end += 1
            animes[t:end] = self.tile(phones[t:end], emotions[t:end], before)
            before = int(self.g.node[animes[end - 1]])
            t = end
        return self.finish(phones, animes)

    def finish(self, phones: list[str], animes: np.ndarray) -> GreedyResult:
        """Fill pause steps and count jumps between spoken steps."""
        g = self.g
        for t in range(len(phones)):
            if animes[t] >= 0:
                continue
            follow = g.successors[animes[t - 1]] if t > 0 else np.zeros(0, np.int64)
            if len(follow):
                animes[t] = follow[0]
            else:
                animes[t] = next((animes[k] for k in range(t + 1, len(phones)) if animes[k] >= 0), 0)
        jumps = sum(1 for t in range(len(phones) - 1)
                    if phones[t] != PAU and phones[t + 1] != PAU and animes[t + 1] not in g.successors[animes[t]])
        return GreedyResult(g.node[animes], animes, int(jumps))


def pq_matching(greedy: Greedy, phones: list[str], emotions: list[str], h: int) -> GreedyResult:
    """Cao's PQ-Matching(h) (their Algorithm 1): in windows of h spoken phones, a
    best-first (priority-queue) branch-and-bound search for the fewest jumps, then the
    lowest cost; windows are concatenated. Works on either graph."""
    g = greedy.g
    follows_of = [set(x.tolist()) for x in g.successors]
    animes = np.full(len(phones), -1, np.int64)
    spoken = [t for t, p in enumerate(phones) if p != PAU]
    prev = -1  # the anime before the window
    i = 0
    while i < len(spoken):
        window = spoken[i : i + h]
        cands = [greedy.candidates(phones[t])[0] for t in window]
        emo = [greedy.emotion_names.get(emotions[t], -1) for t in window]
        joined = prev >= 0 and window[0] - 1 == spoken[i - 1]
        heap: list = []
        first_tc = tc_values(greedy.tc, int(g.node[prev]), g.node[cands[0]]) if prev >= 0 else np.zeros(len(cands[0]))
        for a, tc in zip(cands[0], first_tc):
            captured = joined and int(a) in follows_of[prev]
            heap.append((int(joined and not captured), (0.0 if captured else float(tc)) + greedy.penalty * (g.emotion[a] != emo[0]), 0, int(a), None))
        heapq.heapify(heap)
        closed: dict[tuple[int, int], tuple | None] = {}
        goal = None
        while heap:
            jumps, cost, depth, a, parent = heapq.heappop(heap)
            if (depth, a) in closed:
                continue
            closed[(depth, a)] = parent
            if depth == len(window) - 1:
                goal = (depth, a)
                break
            follows = window[depth + 1] == window[depth] + 1
            nxt = cands[depth + 1]
            steps = tc_values(greedy.tc, int(g.node[a]), g.node[nxt])
            for b, tc in zip(nxt, steps):
                if (depth + 1, int(b)) in closed:
                    continue
                captured = follows and int(b) in follows_of[a]
                heapq.heappush(heap, (jumps + int(follows and not captured),
                                      cost + (0.0 if captured else float(tc)) + greedy.penalty * (g.emotion[b] != emo[depth + 1]),
                                      depth + 1, int(b), (depth, a)))
        state, chain = goal, []
        while state is not None:
            chain.append(state[1])
            state = closed[state]
        animes[window] = chain[::-1]
        prev = int(animes[window[-1]])
        i += h
    return greedy.finish(phones, animes)
