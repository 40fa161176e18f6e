import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from facesynth.domain.geometry.rotations import apply, follow_sources
from facesynth.model.frames import relative_to_take


def test_relative_to_take_removes_each_takes_placement():
    rng = np.random.default_rng(0)
    wobble = Rotation.from_rotvec(rng.normal(0, 0.03, (40, 3))).as_matrix()
    placements = [Rotation.from_euler("y", 30, degrees=True).as_matrix(), Rotation.from_euler("x", -20, degrees=True).as_matrix()]
    rotations = np.concatenate([p @ wobble[:20] for p in placements[:1]] + [placements[1] @ wobble[20:]])
    translations = np.concatenate([np.full((20, 3), 500.0), np.full((20, 3), -300.0)]) + rng.normal(0, 2, (40, 3))
    rel_r, rel_t = relative_to_take(rotations, translations, [slice(0, 20), slice(20, 40)])
    angles = np.linalg.norm(Rotation.from_matrix(rel_r).as_rotvec(), axis=1)
    assert angles.max() < 0.15  # only the wobble is left, not the 20-30 degree placements
    assert np.abs(rel_t.mean(axis=0)).max() < 1e-9 and np.abs(rel_t).max() < 10


def test_sources_are_followed_and_pauses_slerped():
    rot = Rotation.from_euler("z", [[0], [10], [20], [30]], degrees=True).as_matrix()
    trans = np.arange(12, dtype=float).reshape(4, 3)
    r, t = follow_sources(np.array([0, -1, -1, 3]), rot, trans, smooth_frames=0)
    np.testing.assert_allclose(Rotation.from_matrix(r).as_euler("xyz", degrees=True)[:, 2], [0, 10, 20, 30], atol=1e-6)
    np.testing.assert_allclose(t[:, 0], [0, 3, 6, 9])


def _scipy_follow_sources(source_frame, rotations, translations, smooth_frames):
    """The scipy formulation follow_sources replaces (Slerp, gaussian_filter1d on rotation vectors)."""
    from scipy.ndimage import gaussian_filter1d
    from scipy.spatial.transform import Slerp

    have = np.nonzero(source_frame >= 0)[0]
    frames = np.arange(len(source_frame))
    known = Rotation.from_matrix(rotations[source_frame[have]])
    if len(have) == 1:
        rot = Rotation.from_matrix(np.repeat(known.as_matrix(), len(frames), axis=0))
    else:
        rot = Slerp(have, known)(np.clip(frames, have[0], have[-1]))
    trans = np.stack([np.interp(frames, have, translations[source_frame[have], a]) for a in range(3)], 1)
    if smooth_frames > 0 and len(frames) > 1:
        rot = Rotation.from_rotvec(gaussian_filter1d(rot.as_rotvec(), smooth_frames, axis=0, mode="nearest"))
        trans = gaussian_filter1d(trans, smooth_frames, axis=0, mode="nearest")
    return rot.as_matrix(), trans


@pytest.mark.parametrize("spread", [0.001, 0.05, 1.5])
def test_follow_sources_equals_scipy(spread):
    rng = np.random.default_rng(int(spread * 1000))
    rotations = Rotation.from_rotvec(rng.normal(0, spread, (40, 3))).as_matrix()
    translations = rng.normal(0, 5, (40, 3))
    for trial in range(10):
        source = rng.integers(-1, 40, int(rng.integers(2, 60)))
        source[0] = int(rng.integers(0, 40))
        if trial == 0:
            source[1:] = -1  # one known frame
        for smooth in (0.0, 3.0):
            r, t = follow_sources(source, rotations, translations, smooth)
            r_ref, t_ref = _scipy_follow_sources(source, rotations, translations, smooth)
            np.testing.assert_allclose(r, r_ref, atol=1e-12)
            np.testing.assert_allclose(t, t_ref, atol=1e-12)


def test_apply_moves_vertices_rigidly_through_the_marker_frame():
    rng = np.random.default_rng(1)
    verts = rng.normal(0, 5, (30, 3))
    to_mesh = Rotation.from_euler("xyz", [5, 40, -10], degrees=True).as_matrix()
    rot = Rotation.from_euler("x", 15, degrees=True).as_matrix()
    moved = apply(verts, rot, np.array([10.0, 0, 0]), 0.1, to_mesh, np.array([1.0, 2.0, 3.0]))
    d0 = np.linalg.norm(verts[:, None] - verts[None], axis=2)
    d1 = np.linalg.norm(moved[:, None] - moved[None], axis=2)
    np.testing.assert_allclose(d0, d1, atol=1e-9)  # rigid
    assert apply(verts, np.eye(3), np.zeros(3), 0.1, to_mesh, np.zeros(3)) == pytest.approx(verts)


def test_capture_exports_a_take_and_synthesis_carries_head_motion(tiny_db, tiny_artifacts, tiny_corpus, held_out_take, config, tmp_path):
    import h5py

    from facesynth.stages import capture, deform, synthesize

    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, tmp_path / "truth.h5", config.settings("normalize"), 30.0)
    with h5py.File(tmp_path / "truth.h5") as f:
        assert f.attrs["source"] == "capture" and f["markers"].attrs["fps"] == 30
        assert f["head_rotation"].shape == (len(f["markers"]), 3, 3)
    synthesize.run(tiny_db, tmp_path / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    with h5py.File(tmp_path / "m.h5") as f:
        r = f["head_rotation"][()]
        assert len(r) == len(f["markers"]) and np.allclose(r @ np.swapaxes(r, 1, 2), np.eye(3), atol=1e-5)
        assert np.linalg.norm(Rotation.from_matrix(r).as_rotvec(), axis=1).max() > 0.005  # the head moves
    from facesynth.base.config import Config

    on = Config.load(None, ("deform.apply_head_motion=true",)).settings("deform")
    deform.run(tmp_path / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", tmp_path / "a.h5", on)
    deform.run(tmp_path / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", tmp_path / "b.h5", config.settings("deform"))
    with h5py.File(tmp_path / "a.h5") as a, h5py.File(tmp_path / "b.h5") as b:
        forehead = np.argmax(a["rest"][:, 1])  # a vertex no marker motion moves much
        assert np.abs(a["vertices"][:, forehead] - b["vertices"][:, forehead]).max() > 0.2
