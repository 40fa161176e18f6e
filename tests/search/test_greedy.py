"""Cao et al.'s searches: greedy is jump-optimal (their Theorem 1), the DP's Eq. 4 cost is
never above greedy's, PQ-Matching over the whole sentence agrees, ties follow emotion."""

import numpy as np
import pytest

from facesynth.base.phonemes import PAU
from facesynth.domain.postprocess.cao import blend_jumps, learned_cutoffs, lowpass
from facesynth.domain.search.costs import path_terms, step_costs
from facesynth.domain.search.dp import dp_numpy
from facesynth.domain.search.greedy import Greedy, anime_graph, cluster_graph, motion_features, pq_matching
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.speech.utterance import read_utterance
from facesynth.model.motiondb import MotionDatabase


def min_jumps(phones, node_phone, suc):
    """Exact fewest jumps by a DP per spoken run (pauses split runs): cost 1 for a
    non-captured join, the phone must match."""
    n = len(node_phone)
    tc = np.ones((n, n), np.float32)
    for i, s in enumerate(suc):
        if s >= 0:
            tc[i, s] = 0.0
    total, run = 0, []
    for p in list(phones) + [PAU]:
        if p != PAU:
            run.append(p)
            continue
        if run:
            obs = np.array([[0.0 if q == r else 1e6 for q in node_phone] for r in run], np.float32)
            total += int(round(dp_numpy(tc, obs).cost))
        run = []
    return total


def random_db(seed, n_sentences=12, length=8, alphabet=("aa", "b", "m", "iy", "s", "t", "k", "ow")):
    rng = np.random.default_rng(seed)
    phones, suc, emotion = [], [], []
    for s in range(n_sentences):
        base = len(phones)
        for k in range(length):
            phones.append(str(rng.choice(alphabet)))
            emotion.append(["neutral", "happy"][s % 2])
            suc.append(base + k + 1 if k + 1 < length else -1)
    return phones, np.array(suc), emotion


@pytest.mark.parametrize("seed", range(6))
def test_greedy_finds_the_fewest_jumps(seed):
    phones, suc, emotion = random_db(seed)
    graph = anime_graph(phones, emotion, suc)
    tc = np.ones((len(phones),) * 2, np.float32)
    greedy = Greedy(graph, np.zeros(len(phones), int), emotion, tc, 1.0)
    rng = np.random.default_rng(100 + seed)
    query = [str(p) for p in rng.choice(sorted(set(phones)), 15)]
    query[6] = PAU
    result = greedy.search(query, ["neutral"] * len(query))
    assert result.jumps == min_jumps(query, phones, suc)
    for t, p in enumerate(query):
        if p != PAU:
            assert phones[result.path[t]] == p
    # PQ-Matching over windows as long as the sentence is exact too
    assert pq_matching(greedy, query, ["neutral"] * len(query), h=len(query)).jumps == result.jumps


def test_ties_follow_the_asked_emotion():
    # two captured copies of "b aa m", one neutral one happy: equal length, emotion decides
    phones = ["b", "aa", "m", "b", "aa", "m"]
    suc = np.array([1, 2, -1, 4, 5, -1])
    emotion = ["neutral"] * 3 + ["happy"] * 3
    greedy = Greedy(anime_graph(phones, emotion, suc), np.zeros(6, int), emotion, np.zeros((6, 6), np.float32), 10.0)
    assert greedy.search(["b", "aa", "m"], ["happy"] * 3).path.tolist() == [3, 4, 5]
    assert greedy.search(["b", "aa", "m"], ["neutral"] * 3).path.tolist() == [0, 1, 2]


def test_dp_cost_is_never_above_greedy_on_the_real_database(tiny_db, tiny_corpus, config):
    db = MotionDatabase.read(tiny_db)
    s = config.settings("synthesize")
    tc = transition_costs(db, s).dense()
    greedy = Greedy(anime_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc), db.nodes.viseme, db.nodes.emotion, tc, s.alpha6 * s.pnt)
    for tg in sorted((tiny_corpus / "labels").glob("*.TextGrid")):
        utt = read_utterance(tg)
        emotions = [("happy", "sad")[k % 2] for k in range(len(utt))]
        steps = step_costs(utt.phones, emotions, db.nodes.phone, db.nodes.emotion, {}, s)
        g = greedy.search(utt.phones, emotions)
        g_cost = sum(v.astype(np.float64).sum() for v in path_terms(g.path, tc, steps).values())
        assert dp_numpy(tc, steps.total).cost <= g_cost * (1 + 1e-6)


def test_clustered_graph_matches_phones_through_its_merged_animes(tiny_db, tiny_corpus, config):
    db = MotionDatabase.read(tiny_db)
    features = motion_features(db.coeffs, db.nodes.frame_start, db.nodes.frame_count)
    graph = cluster_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc, features, k=60)
    assert len(graph.node) == 60 and graph.phones.sum() >= 60
    s = config.settings("synthesize")
    greedy = Greedy(graph, db.nodes.viseme, db.nodes.emotion, transition_costs(db, s).dense(), s.alpha6 * s.pnt)
    utt = read_utterance(sorted((tiny_corpus / "labels").glob("*.TextGrid"))[0])
    res = greedy.search(utt.phones, utt.emotions)
    from facesynth.base.phonemes import PHONE_ID

    for t, p in enumerate(utt.phones):
        if p != PAU and PHONE_ID[p] in graph.array:
            assert graph.phones[res.animes[t], PHONE_ID[p]]


def test_blending_follows_a_captured_example_across_a_jump():
    # database: node 0 (aa) -> node 1 (b) captured; nodes 2 (aa) and 3 (b) elsewhere
    coeffs = np.concatenate([np.linspace(0, 1, 10), np.linspace(1, 2, 10), np.full(10, 5.0), np.full(10, -5.0)])[:, None]
    out = np.concatenate([np.full(10, 5.0), np.full(10, -5.0)])[:, None]  # path 2 -> 3: a jump of 10
    changed = blend_jumps(out, [(0, 10), (10, 20)], np.array([2, 3]), ["aa", "b"], ["aa", "b", "aa", "b"],
                          np.array([0, 10, 20, 30]), np.array([10, 10, 10, 10]), np.array([-1, 0, -1, -1]),
                          np.array([(0, 20), (0, 20), (20, 30), (30, 40)]), coeffs)
    assert changed.all()
    assert out[9, 0] == pytest.approx(1.0) and out[10, 0] == pytest.approx(1.0)  # the example's own join
    assert out[0, 0] == pytest.approx(5.0) and out[19, 0] == pytest.approx(-5.0)  # the ends stay


def test_learned_cutoff_and_lowpass():
    fps = 120.0
    t = np.arange(1200) / fps
    x = np.stack([np.sin(2 * np.pi * 3 * t), np.sin(2 * np.pi * 3 * t) + 0.3 * np.sin(2 * np.pi * 40 * t)], 1)
    cut = learned_cutoffs(x, [slice(0, 600), slice(600, 1200)], fps)
    assert cut[0] < 10.0 and cut[1] > 35.0  # the 40 Hz part carries 8% of the second column's energy
    y = lowpass(x, np.array([10.0, 10.0]), fps)
    assert np.abs(y[100:-100, 1] - np.sin(2 * np.pi * 3 * t[100:-100])).max() < 0.05
