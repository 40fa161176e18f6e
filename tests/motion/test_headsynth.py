"""Pitch cleaning, segmentation and the head-motion search and blending (Chuang & Bregler §5)."""

import numpy as np

from facesynth.domain.head_motion import synthesis as headsynth
from facesynth.domain.speech import pitch as P


def test_cleaning_drops_out_of_range_pitch_and_short_runs_and_fills_short_gaps():
    f0 = np.array([np.nan, 200, 210, np.nan, 230, 240, 250, np.nan, np.nan, np.nan, 900, 120, np.nan, 180, 190])
    p = P.clean(f0, fmin=60, fmax=500, hop_s=0.01, max_gap_s=0.01, min_voiced_s=0.015)
    assert np.isnan(p[0]) and np.isclose(p[3], 220.0)          # one-frame gap filled between 210 and 230
    assert np.isnan(p[10])                                      # out of range
    assert np.isnan(p[11])                                      # a one-frame run is noise
    assert np.isnan(p[7:10]).all() and np.isfinite(p[13:]).all()


def test_segments_run_from_one_voiced_onset_to_the_next():
    p = np.full(100, np.nan)
    p[10:30] = 200
    p[50:70] = 150
    segs = P.segments(p, 0.01, 1.0)
    assert np.allclose([(s.start, s.end, s.voiced_end) for s in segs], [(0.1, 0.5, 0.3), (0.5, 1.0, 0.7)])
    assert np.allclose(segs[1].contour, P.semitones(np.full(20, 150.0)))
    assert P.segments(np.full(10, np.nan), 0.01, 0.1) == []


def _take(name, sentence, onsets, rng, fps=100.0, n=300):
    p = np.full(n, np.nan)
    for a in onsets:
        p[a:a + 20] = 150 + 40 * np.sin(np.linspace(0, np.pi, 20)) + rng.normal(0, 1, 20)
    head = np.cumsum(rng.normal(0, 0.1, (n, 6)), axis=0)
    return headsynth.LibraryTake(name, sentence, p, P.segments(p, 0.01, n / 100), head, fps, 0.01)


def test_viterbi_finds_the_cheapest_path_of_a_small_trellis():
    node = [np.array([1.0, 0.0]), np.array([0.0, 5.0]), np.array([0.0, 0.0])]
    trans = [np.array([[0.0, 0.0], [9.0, 0.0]]), np.array([[1.0, 0.0], [0.0, 0.0]])]
    assert headsynth._viterbi(node, trans) == [0, 0, 1]          # cost 1 + 0 + 0 + 0 + 0 = 1


def test_the_search_prefers_consecutive_segments_and_the_blend_is_continuous():
    rng = np.random.default_rng(0)
    lib = [_take(f"t{i}", f"s{i}", [20, 90, 160, 230], rng) for i in range(4)]
    query = lib[0]
    choices = headsynth.search(lib, query.segments, query.features, m=4, k=8, b=0.05, c=0.3, omega_h=1.0, omega_r=1.0,
                               breath_s=10.0)
    assert len(choices) == len(query.segments)
    # the query is a library take: matching its own segments in order is free of R cost
    assert [(c.take, c.index) for c in choices] == [(0, i) for i in range(4)]
    head = headsynth.blend(lib, query.segments, choices, 3.0, 30.0, breath_s=10.0, join_smooth_s=0.0)
    assert head.shape == (90, 6)
    assert np.abs(np.diff(head, axis=0)).max() < 1.0             # starts moved onto previous ends: no jumps
    excluded = headsynth.search(lib, query.segments, query.features, m=4, k=8, b=0.05, c=0.3, omega_h=1.0,
                                omega_r=1.0, breath_s=10.0, exclude={"s0"})
    assert all(c.take != 0 for c in excluded)


def test_subsentences_split_at_breaths():
    segs = [P.Segment(0.0, 1.0, 0.5, np.zeros(3)), P.Segment(1.0, 2.0, 1.9, np.zeros(3)), P.Segment(2.0, 3.0, 2.2, np.zeros(3))]
    assert headsynth.subsentences(segs, 0.3) == [[0], [1, 2]]
