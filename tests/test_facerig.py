"""The shipped ICT-FaceKit rig loads from the package alone and poses like the asset's own recipe."""

import csv
from pathlib import Path

import numpy as np
import pytest

from facesynth.domain.rig.face import load_face_rig

ASSET = Path(__file__).resolve().parents[2] / "shared" / "assets" / "ict-face"


def test_rig_shapes_and_units():
    rig = load_face_rig()
    assert rig.neutral.shape == (11248, 3) and rig.faces.shape == (22288, 3)
    assert rig.deltas.shape == (55, 11248, 3) and len(rig.shape_names) == 55
    assert len(rig.arkit_names) == 52 and rig.arkit_to_rig.shape == (52, 55)
    # millimetres: the head is about 25 cm wide
    assert 240 < np.ptp(rig.neutral[:, 0]) < 250
    # jawOpen moves the chin about 4 cm (README: chin 4.0 cm)
    chin = rig.evaluate(np.eye(55)[rig.shape_index("jawOpen")]) - rig.neutral
    assert 38 < np.linalg.norm(chin, axis=1).max() < 44
    assert set(rig.loops) == {"mouth", "eye_L", "eye_R", "neck"}


def test_arkit_round_trip():
    rig = load_face_rig()
    w = np.random.default_rng(0).uniform(0, 1, (5, 52))
    w[:, rig.arkit_names.index("tongueOut")] = 0.0
    np.testing.assert_allclose(rig.to_arkit(rig.from_arkit(w)), w)
    assert rig.from_arkit(np.eye(52)[rig.arkit_names.index("browInnerUp")])[
        [rig.shape_index("browInnerUp_L"), rig.shape_index("browInnerUp_R")]].tolist() == [1.0, 1.0]


@pytest.mark.skipif(not ASSET.exists(), reason="needs ../shared/assets/ict-face")
def test_live_link_capture_poses_the_mesh_like_the_asset_recipe():
    rig = load_face_rig()
    with open(ASSET / "llf_capture.csv") as fh:
        rows = list(csv.DictReader(fh))
    columns = [n[0].upper() + n[1:] for n in rig.arkit_names]
    arkit = np.array([[float(r[c]) for c in columns] for r in rows])
    posed = rig.evaluate(rig.from_arkit(arkit[210]))
    data = np.load(ASSET / "ict_face.npz")
    names = list(data["expr_names"])
    w = np.zeros(55)
    for line in open(ASSET / "llf_columns.txt"):
        if line[0] == "#":
            continue
        col, target, *_ = line.rstrip("\n").split("\t")
        if target != "-":
            for t in target.split("+"):
                w[names.index(t)] = float(rows[210][col])
    expected = (data["vertices"] + np.tensordot(w, data["expr_deltas"].astype(np.float32), axes=1)) * 10
    np.testing.assert_allclose(posed, expected, atol=1e-3)
    mouth = rig.loops["mouth"]
    assert np.ptp(posed[mouth, 1]) > 35  # frame 210: mouth wide open (> 3.5 cm)
