"""Rigid (head-pose) markers found from the data, and the most typical frame."""

import csv

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from facesynth.domain.geometry.rigid import choose_rigid, find_rigid_markers, typical_frame
from facesynth.formats.mocap import read_mocap


def _head_and_mouth(rng, frames=200):
    """5 head markers on a rigid body and 6 mouth markers moving 10 mm against it, all under a
    moving head pose, with 0.2 mm noise: (T, 11, 3) mm."""
    head = rng.normal(0, 60, (5, 3))
    mouth = rng.normal(0, 30, (6, 3))
    out = np.empty((frames, 11, 3))
    for t in range(frames):
        r = Rotation.from_rotvec(rng.normal(0, 0.15, 3)).as_matrix()
        local = np.concatenate([head, mouth + rng.normal(0, 10.0, (6, 3))])
        out[t] = local @ r.T + rng.normal(0, 20, 3)
    return out + rng.normal(0, 0.2, out.shape)


def test_the_rigid_body_is_found_with_its_spread():
    rng = np.random.default_rng(0)
    frames = _head_and_mouth(rng)
    idx, spreads = find_rigid_markers(frames, max_spread_mm=1.0, min_markers=3)
    assert idx.tolist() == [0, 1, 2, 3, 4]
    assert np.all(spreads < 0.5)  # noise only: sqrt(2) * 0.2 mm per coordinate pair, about 0.3 mm


def test_a_marker_seldom_seen_is_left_out():
    rng = np.random.default_rng(1)
    frames = _head_and_mouth(rng)
    frames[20:, 2] = np.nan  # seen in 10% of the frames
    idx, _ = find_rigid_markers(frames, max_spread_mm=1.0, min_markers=3)
    assert idx.tolist() == [0, 1, 3, 4]


def test_too_few_markers_seen_is_an_error():
    frames = np.full((10, 4, 3), np.nan)
    frames[:, :2] = 1.0
    with pytest.raises(ValueError, match="only 2 markers are seen"):
        find_rigid_markers(frames, max_spread_mm=1.0)


def test_the_sample_corpus_rigid_markers_are_found(tiny_corpus):
    """Every marker the corpus flags rigid is found, and no marker of the lips, jaw, chin or
    cheeks (the nose and eye corners move under a millimetre too, and are found with them)."""
    takes = [read_mocap(p) for p in sorted((tiny_corpus / "mocap").glob("*.c3d"))]
    names = takes[0].names
    frames = np.concatenate([t.positions for t in takes])
    rows = list(csv.DictReader(open(tiny_corpus / "markers.csv")))
    true = {r["marker"] for r in rows if r["rigid"] == "1"}
    idx, spreads = find_rigid_markers(frames, max_spread_mm=1.0, min_markers=4)
    found = {names[i] for i in idx}
    assert true <= found
    assert not [n for n in found if n.startswith(("UL", "LL", "MC", "JAW", "CHIN", "MENT", "CHK", "NLF"))]
    assert np.all(spreads < 1.0)


def test_choose_rigid_prefers_the_settings_then_the_corpus():
    names = ["a", "b", "c", "d"]
    frames = np.random.default_rng(0).normal(size=(20, 4, 3))
    assert choose_rigid(names, ("b", "c", "d"), ["a"], frames, max_spread_mm=1.0, min_markers=3).indices.tolist() == [1, 2, 3]
    choice = choose_rigid(names, (), ["a", "c", "d"], frames, max_spread_mm=1.0, min_markers=3)
    assert choice.indices.tolist() == [0, 2, 3] and choice.source == "corpus" and choice.spreads is None
    rng = np.random.default_rng(2)
    moving = _head_and_mouth(rng, 100)
    choice = choose_rigid([str(i) for i in range(11)], (), [], moving, max_spread_mm=1.0, min_markers=3)
    assert choice.source == "data" and choice.indices.tolist() == [0, 1, 2, 3, 4] and len(choice.spreads) == 5


def test_typical_frame_is_the_rest_pose_under_any_head_pose():
    """Half the frames at rest (noise only), the rest with the jaw open by various amounts, each
    frame under its own head pose: the typical frame is one at rest."""
    rng = np.random.default_rng(3)
    rest = rng.normal(0, 40, (12, 3))
    frames, at_rest = [], []
    for t in range(60):
        pose = rest.copy()
        opened = t % 3 == 0  # a third of the frames open, as in speech
        if opened:
            pose[6:] += [0.0, -rng.uniform(5, 25), 0.0]
        r = Rotation.random(random_state=t).as_matrix()
        frames.append(pose @ r.T + rng.normal(0, 100, 3) + rng.normal(0, 0.1, (12, 3)))
        at_rest.append(not opened)
    assert at_rest[typical_frame(np.array(frames))]
