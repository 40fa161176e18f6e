"""Neutral calibration (facesynth.domain.rig.neutral), a face's priors in the solve
(facesynth.domain.retarget.solve.FacePriors, .face_priors) and the shipped Face Mesh binding
(facesynth.domain.rig.face_mesh): small takes made in the test, answers worked out by hand."""

from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.capture.readers import CaptureOptions, read_capture
from facesynth.domain.retarget.face_priors import antagonist_pairs, symmetric_pairs
from facesynth.domain.retarget.solve import FacePriors, solve_curves
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.face_mesh import bound_for, face_mesh_binding, face_mesh_names
from facesynth.domain.rig.loading import builtin_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.domain.rig.neutral import (
    NeutralChoice,
    calibrated_weights,
    chosen_frames,
    lip_gap,
    neutral_pose,
    neutral_weights,
    quiet_window,
    quietest_of,
    quietness,
)
from facesynth.formats.blendshape_curves import write_mapping

ARKIT = load_face_rig().arkit_names


@pytest.mark.parametrize(("text", "kind", "value"), [("auto", "auto", None), ("off", "off", None),
                                                     ("frame:120", "frame", 120), ("time:2.5s", "time", 2.5),
                                                     ("time:3", "time", 3.0), ("take:calm", "take", "calm")])
def test_every_form_of_the_neutral_is_read(text, kind, value):
    choice = NeutralChoice.parse(text, "--neutral")
    assert choice.kind == kind and value in (None, choice.frame, choice.time_s, choice.take)
    assert NeutralChoice.parse(str(choice), "again") == choice


@pytest.mark.parametrize("text", ["", "quiet", "frame:-1", "frame:x", "time:soon", "take:"])
def test_another_neutral_is_refused_in_one_sentence(text):
    with pytest.raises(InputError, match=r"^solve\.neutral: neutral .* is not one of auto, off, frame:N"):
        NeutralChoice.parse(text, "solve.neutral")


def _talking_take(fps: float = 25.0) -> tuple[np.ndarray, list[str]]:
    """4 s of two lip markers and a chin: the mouth opens and shuts at 3 Hz except from 2.0 s to
    2.8 s, where the face is still and closed (the neutral), the lips 1 mm apart."""
    t = np.arange(int(4 * fps)) / fps
    still = (t >= 2.0) & (t < 2.8)
    opening = np.where(still, 0.0, 6 * (1 + np.sin(2 * np.pi * 3 * t)))
    markers = np.zeros((len(t), 3, 3))
    markers[:, 0, 1] = 1.0  # upper lip
    markers[:, 1, 1] = -opening  # lower lip
    markers[:, 2, 1] = -20 - opening  # chin
    return markers, ["ULI_C", "LLI_C", "CHIN"]


def test_auto_finds_the_still_closed_stretch():
    markers, names = _talking_take()
    gap = lip_gap(markers, names)
    assert gap is not None and gap.min() == pytest.approx(1.0)
    score = quietness(markers, 25.0, gap)
    window = quiet_window(score, 25.0)
    assert window.stop - window.start == 12  # half a second at 25 frames/s
    assert 50 <= window.start and window.stop <= 70  # inside 2.0-2.8 s
    pose = neutral_pose(markers, window)
    np.testing.assert_allclose(pose, [[0, 1, 0], [0, 0, 0], [0, -20, 0]], atol=1e-9)
    assert lip_gap(markers, ["a", "b", "c"]) is None


def test_auto_over_several_takes_finds_the_neutral_take_and_no_window_crosses_takes():
    """Take 1 talks throughout; take 2 is still and closed from its 1.0 s: the quietest window of
    the capture is in take 2, and a window is never split between the takes."""
    talking, names = _talking_take()
    talking[50:70] = talking[49]  # no still stretch in the first take: held open
    calm = np.repeat(talking[:1] * 0, 50, axis=0)
    calm[:, 0, 1], calm[:, 2, 1] = 1.0, -20.0
    calm[:25] += np.sin(np.arange(25))[:, None, None]  # moving until 1.0 s
    markers = np.concatenate([talking, calm])
    score = quietness(markers, 25.0, lip_gap(markers, names))
    window = quietest_of(score, [slice(0, 100), slice(100, 150)], 25.0)
    assert 125 <= window.start and window.stop <= 150 and window.stop - window.start == 12
    only_first = quietest_of(score, [slice(0, 100)], 25.0)
    assert only_first.stop <= 100


def test_a_named_frame_or_time_is_the_neutral_and_one_past_the_take_is_refused():
    score = np.zeros(100)
    assert chosen_frames(NeutralChoice.parse("frame:7", ""), score, 25.0, "t") == slice(7, 8)
    assert chosen_frames(NeutralChoice.parse("time:2s", ""), score, 25.0, "t") == slice(50, 51)
    assert chosen_frames(NeutralChoice.parse("off", ""), score, 25.0, "t") is None
    with pytest.raises(InputError, match=r"^take\.h5: neutral time:5s is beyond the take \(100 frames, 4\.00 s\)"):
        chosen_frames(NeutralChoice.parse("time:5s", ""), score, 25.0, "take.h5")


def test_calibrated_weights_are_the_expressions_only():
    w = np.array([[0.3, 0.0], [0.8, 0.1], [0.2, 0.5], [np.nan, np.nan]])
    neutral = neutral_weights(w, slice(0, 1))
    np.testing.assert_allclose(neutral, [0.3, 0.0])
    out = calibrated_weights(w, neutral)
    np.testing.assert_allclose(out[:3], [[0, 0], [0.5, 0.1], [0, 0.5]], atol=1e-12)
    assert np.isnan(out[3]).all()


def test_another_rigs_curves_are_ingested_from_the_performers_neutral(tmp_path):
    """A curve take resting at a frown of 0.4 (held by the performer's face) with one smile: with
    ``auto`` the rest becomes 0 and the smile stays; with ``off`` the frown stays."""
    n = 100
    frown = np.full(n, 0.4)
    smile = np.zeros(n)
    smile[60:80] = np.hanning(20)
    np.save(tmp_path / "take.npy", np.stack([frown, smile], axis=1))
    (tmp_path / "names.txt").write_text("Frown\nSmile\n")
    write_mapping(tmp_path / "map.csv", [("Frown", "mouthFrownLeft", 1.0, ""), ("Smile", "mouthSmileLeft", 1.0, "")])
    base = CaptureOptions(mapping=tmp_path / "map.csv", names=tmp_path / "names.txt", fps=25.0)
    calm = read_capture(tmp_path / "take.npy", CaptureOptions(**{**base.__dict__, "neutral": NeutralChoice("auto")}))
    raw = read_capture(tmp_path / "take.npy", CaptureOptions(**{**base.__dict__, "neutral": NeutralChoice("off")}))
    f, s = ARKIT.index("mouthFrownLeft"), ARKIT.index("mouthSmileLeft")
    assert np.abs(calm.arkit[:, f]).max() == 0 and calm.arkit[:, s].max() == pytest.approx(smile.max(), abs=1e-6)
    np.testing.assert_allclose(raw.arkit[:, f], 0.4, atol=1e-6)
    # the markers follow: the frown held at rest moves the mouth's corners, which auto takes away
    assert np.abs(calm.positions[:10] - calm.rest).max() < 1e-4 < np.abs(raw.positions[:10] - raw.rest).max()


def test_antagonists_and_mirrors_are_found_from_arkit_and_ict_names():
    pairs = {(ARKIT[a], ARKIT[b]) for a, b in antagonist_pairs(ARKIT)}
    assert {("jawLeft", "jawRight"), ("mouthLeft", "mouthRight"), ("mouthSmileLeft", "mouthFrownLeft"),
            ("browDownRight", "browInnerUp")} <= pairs
    mirrors = {(ARKIT[a], ARKIT[b]) for a, b in symmetric_pairs(ARKIT)}
    assert ("mouthSmileLeft", "mouthSmileRight") in mirrors and ("browDownLeft", "browDownRight") in mirrors
    assert not any(a.startswith(("eyeLook", "jaw")) or a == "mouthLeft" for a, _ in mirrors)
    ict = load_face_rig().shape_names
    assert ("mouthSmile_L", "mouthFrown_L") in {(ict[a], ict[b]) for a, b in antagonist_pairs(ict)}


def _basis() -> np.ndarray:
    """(4, 6, 3): two opposing shapes (left, right: the same marker moved either way), and a
    mirrored pair (two markers each raised by one shape)."""
    b = np.zeros((4, 6, 3))
    b[0, 0, 0], b[0, 1, 0] = 5.0, 1.0  # left
    b[1, 0, 0], b[1, 2, 0] = -5.0, 1.0  # right: mostly the opposite of left
    b[2, 3, 1] = 4.0  # raise left
    b[3, 4, 1] = 4.0  # raise right
    return b


def test_the_priors_keep_antagonists_apart_weights_sparse_and_mirrors_alike():
    b = _basis()
    rng = np.random.default_rng(0)
    # frames: left at 0.5 with both opposing markers a little on (noise that a free solve reads as
    # both on), the two raises at 0.5 and 0.3 (a face that moves symmetrically, measured unevenly)
    frames = np.tensordot(np.tile([0.5, 0.3, 0.5, 0.3], (20, 1)), b, axes=(1, 0))
    frames[:, 2, 0] += 0.4
    frames += rng.normal(0, 0.01, frames.shape)
    kw = dict(smooth=0.0, ridge=0.0, iterations=20000, tolerance=1e-9)
    free, _, _ = solve_curves(frames, b, **kw)
    priors = FacePriors(sparsity=0.0, antagonist=5.0, symmetry=0.0, antagonists=((0, 1),))
    apart, _, _ = solve_curves(frames, b, **kw, priors=priors)
    assert np.minimum(free[:, 0], free[:, 1]).mean() > 0.3 > 0.05 > np.minimum(apart[:, 0], apart[:, 1]).mean()
    mirrored, _, _ = solve_curves(frames, b, **kw, priors=FacePriors(symmetry=5.0, symmetric=((2, 3),)))
    assert abs(free[:, 2] - free[:, 3]).mean() > 0.15 > 0.05 > abs(mirrored[:, 2] - mirrored[:, 3]).mean()
    small = np.tensordot(np.tile([0.0, 0.0, 0.04, 0.0], (20, 1)), b, axes=(1, 0))  # a 0.04 twitch
    sparse, _, _ = solve_curves(small, b, **kw, priors=FacePriors(sparsity=0.1))
    plain, _, _ = solve_curves(small, b, **kw)
    assert plain[:, 2].min() > 0.03 and np.abs(sparse).max() == 0.0


def test_the_shipped_face_mesh_binding_places_the_lips_on_the_rigs_lips():
    rig = load_face_rig()
    binding = face_mesh_binding()
    assert sorted(binding) == face_mesh_names() and all(0 <= v < len(rig.neutral) for v in binding.values())
    markers = build_marker_set(rig)
    for landmark, marker in (("MP013", "ULI_C"), ("MP014", "LLI_C")):  # the inner lips' centres
        place = rig.neutral[binding[landmark]]
        assert np.linalg.norm(place - rig.neutral[markers.vertices[markers.names.index(marker)]]) < 3.0
    # used for a filmed take on the built-in rig; the actress's markers and a user's binding are kept
    assert bound_for(builtin_rig(), face_mesh_names()).binding == binding
    assert bound_for(builtin_rig(), markers.names).binding == builtin_rig().binding
    own = builtin_rig({"MP000": 5})
    assert bound_for(own, face_mesh_names()).binding == {"MP000": 5}


def test_solving_unbound_markers_names_the_bind_command(tiny_artifacts, tmp_path):
    (tmp_path / "b.csv").write_text("marker,vertex\nnobody,1\n")
    out = CliRunner().invoke(main, ["solve", str(tiny_artifacts["normalized"]), "--take", "neutral_s000", "--binding",
                                    str(tmp_path / "b.csv"), "-o", str(tmp_path / "c.h5")])
    assert out.exit_code == 1 and "facesynth bind CAPTURE --rig RIG -o binding.csv" in out.output
    bad = CliRunner().invoke(main, ["solve", str(tiny_artifacts["normalized"]), "--take", "neutral_s000",
                                    "--neutral", "frame:99999", "-o", str(tmp_path / "c.h5")])
    assert bad.exit_code == 1 and "neutral frame:99999 is beyond the take" in bad.output
    assert not (tmp_path / "c.h5").exists()


def test_ingest_names_a_neutral_take_only_through_solve(tmp_path):
    (tmp_path / "m.csv").write_text("take,mocap\nt,t.c3d\n")
    out = CliRunner().invoke(main, ["ingest", str(tmp_path / "m.csv"), "-o", str(tmp_path / "c.h5"),
                                    "--set", "ingest.neutral=take:calm"])
    assert out.exit_code == 1 and "a neutral take is named when solving (facesynth solve --neutral take:NAME)" in out.output
    assert not (tmp_path / "c.h5").exists()
