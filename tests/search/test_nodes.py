import numpy as np
import pytest

from facesynth.domain.search.nodes import build_nodes, dsc_features, dsc_matrix, pair_gaps_numpy
from facesynth.model.motiondb import Nodes
from facesynth.model.tables import Phones, Takes


def _tables():
    # take 0 (train): pau a b pau c pau ; take 1 (test): pau a pau
    takes = Takes(["t0", "t1"], ["happy", "sad"], ["s0", "s1"], ["train", "test"], ["", ""],
                  np.array([0, 100]), np.array([100, 50]))
    seg = [(0, 0.0, 0.1, "pau"), (0, 0.1, 0.2, "aa"), (0, 0.2, 0.3, "b"), (0, 0.3, 0.4, "pau"), (0, 0.4, 0.6, "m"),
           (0, 0.6, 0.8, "pau"), (1, 0.0, 0.1, "pau"), (1, 0.1, 0.3, "aa"), (1, 0.3, 0.4, "pau")]
    phones = Phones(np.array([s[0] for s in seg]), np.array([s[1] for s in seg]), np.array([s[2] for s in seg]), [s[3] for s in seg])
    return takes, phones


def test_nodes_links_pause_splits_and_triphones():
    takes, phones = _tables()
    nodes = build_nodes(takes, phones, fps=100.0)
    assert nodes.phone == ["aa", "b", "m"]  # pauses dropped, the test take left out
    assert nodes.pre.tolist() == [-1, 0, -1]  # the pause before /m/ splits the sentence
    assert nodes.suc.tolist() == [1, -1, -1]
    assert list(zip(nodes.prev_phone, nodes.next_phone)) == [("pau", "b"), ("aa", "pau"), ("pau", "pau")]
    assert nodes.frame_start.tolist() == [10, 20, 40] and nodes.frame_count.tolist() == [10, 10, 20]
    assert nodes.emotion == ["happy"] * 3
    assert nodes.viseme[1] == nodes.viseme[2]  # b and m share a viseme (Table VI)


def _two_node_db(pre_frames):
    """Node 0: three frames of zeros; node 1 has node 2 (pre_frames) as predecessor."""
    coeffs = np.concatenate([np.zeros((3, 1)), np.zeros((3, 1)), np.array(pre_frames, float)[:, None]])
    n = len(pre_frames)
    nodes = Nodes(["aa", "b", "aa"], np.array([3, 12, 3]), ["neutral"] * 3, np.zeros(3, int),
                  np.array([0, 3, 6]), np.array([3, 3, n]), np.zeros(3), np.zeros(3), ["pau"] * 3, ["pau"] * 3,
                  np.array([-1, 2, -1]), np.array([-1, -1, 1]))
    return coeffs, nodes


def test_dsc_of_curves_worked_by_hand():
    # Blend from warp(o_0) = [0, 0, 0] to pre(o_1) = [0, 1, 0] with weights s = [0, .5, 1]:
    # b = [0, .5, 0], second difference -1, squared 1, sample step 1 frame -> DSC = 1.
    coeffs, nodes = _two_node_db([0.0, 1.0, 0.0])
    assert dsc_matrix(coeffs, nodes, samples=3)[0, 1] == pytest.approx(1.0)
    # A straight blend has no curvature.
    coeffs, nodes = _two_node_db([1.0, 1.0, 1.0])
    assert dsc_matrix(coeffs, nodes, samples=3)[0, 1] == pytest.approx(0.0)
    # pre(o_1) of five frames resampled to three samples: the step is 2 frames, DSC = 1 / 2^3.
    coeffs, nodes = _two_node_db([0.0, 0.5, 1.0, 0.5, 0.0])
    assert dsc_matrix(coeffs, nodes, samples=3)[0, 1] == pytest.approx(1.0 / 8.0)
    # Columns of nodes without a predecessor are unused (rule 4) and zero.
    assert dsc_matrix(coeffs, nodes, samples=3)[:, 0].tolist() == [0.0, 0.0, 0.0]


def test_pair_gaps_of_the_reference_by_hand():
    rng = np.random.default_rng(0)
    n, m3 = 30, 3 * 17
    states = [rng.normal(0, 20, (n, m3)).astype(np.float32) for _ in range(4)]
    p_ref, v_ref = pair_gaps_numpy(*states)
    # Eq. 8 for one pair by hand: sum over markers of Euclidean distances.
    fp, lp = states[0].reshape(n, -1, 3), states[1].reshape(n, -1, 3)
    assert p_ref[4, 7] == pytest.approx(np.linalg.norm(fp[7] - lp[4], axis=1).sum(), rel=1e-5)


def test_dsc_features_expand_the_blend():
    # DSC(o_0, pre(o_1)) = scale_1 |x_0 + y_1|^2 with the features; the hand-worked value is 1.
    coeffs, nodes = _two_node_db([0.0, 1.0, 0.0])
    x, y, scale = dsc_features(coeffs, nodes, samples=3)
    assert scale.tolist() == [0.0, 1.0, 0.0] and not y[0].any() and not y[2].any()
    assert float(scale[1] * ((x[0] + y[1]) ** 2).sum()) == pytest.approx(1.0)


def test_the_tiny_database_is_consistent(tiny_db):
    import h5py

    with h5py.File(tiny_db) as f:
        nodes = Nodes.read(f)
        takes = Takes.read(f)
        assert "pairs" not in f  # no N x N table: per-node features only
        assert f["transition/dsc_out"].shape[0] == len(nodes) and f["boundary/first_pos"].shape[0] == len(nodes)
    for k in range(len(nodes)):
        t = nodes.take[k]
        assert takes.split[t] == "train"
        assert takes.frame_start[t] <= nodes.frame_start[k]
        assert nodes.frame_start[k] + nodes.frame_count[k] <= takes.frame_start[t] + takes.frame_count[t]
        if nodes.pre[k] >= 0:
            assert nodes.suc[nodes.pre[k]] == k and nodes.take[nodes.pre[k]] == t
    assert set(nodes.emotion) == {"neutral", "happy", "angry", "sad"}


def test_frames_know_their_node_and_relative_time(tiny_db):
    import h5py

    with h5py.File(tiny_db) as f:
        nodes = Nodes.read(f)
        frame_node, rel = f["frames/node"][()], f["frames/relative_time"][()]
    k = 7
    sl = nodes.frames(k)
    assert (frame_node[sl] == k).all() and rel[sl][0] == 0.0 and rel[sl][-1] == 1.0
    assert np.all(np.diff(rel[sl]) > 0)
    assert np.isnan(rel[frame_node < 0]).all()


def test_a_database_with_pair_tables_says_to_rebuild(tiny_db, tmp_path):
    """Schema 1 stored (N, N) pair tables; such a file is refused with one sentence."""
    import shutil

    import h5py

    from facesynth.base.errors import FacesynthError
    from facesynth.model.motiondb import MotionDatabase

    old = tmp_path / "old.h5"
    shutil.copy(tiny_db, old)
    with h5py.File(old, "a") as f:
        f.attrs["facesynth_schema"] = 1
    with pytest.raises(FacesynthError, match=r"schema 1 is not the supported schema 2; rebuild it with .*facesynth build-db"):
        MotionDatabase.read(old)
