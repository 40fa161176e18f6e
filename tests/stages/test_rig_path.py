"""The way from a motion to the rig: ``solve`` -> rig curves -> ``render`` (the rig posed in
memory by its own blendshapes), ``openfacefx`` curves beside it, and why Gaussian ``deform``
is kept for plain meshes only: on the rig it creases the skin under an open jaw."""

import dataclasses

import imageio_ffmpeg
import numpy as np
import pytest
import soundfile as sf

from facesynth.base.config import Config
from facesynth.base.errors import InputError, UsageError
from facesynth.domain.evaluation.baselines import openfacefx_missing
from facesynth.domain.rendering import video
from facesynth.domain.rig.face import gaze_from_rig_weights, load_face_rig
from facesynth.domain.rig.loading import builtin_rig, pose_rig
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.stages import openfacefx, render, rig_mesh

needs_openfacefx = pytest.mark.skipif(openfacefx_missing() is not None, reason=str(openfacefx_missing()))


@pytest.fixture(scope="module")
def made(held_out_synthesized):
    """A held-out sentence synthesized, solved onto the built-in rig and deformed (the old way)."""
    return dict(held_out_synthesized)


def _settings(*overrides):
    return Config.load(None, ("render.width=320", "render.height=240", *overrides)).settings("render")


def test_curves_render_with_every_frame_and_the_audio(made, tmp_path):
    out = tmp_path / "c.avi"
    s = render.run([made["curves"]], [made["audio"]], out, _settings())
    n_curves = RigCurves.read(made["curves"]).n_frames
    assert s.frames == n_curves == imageio_ffmpeg.count_frames_and_secs(str(out))[0]
    wav = tmp_path / "back.wav"
    import subprocess

    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-y", "-i", str(out), str(wav)], check=True)
    audio, rate = sf.read(wav)
    assert len(audio) / rate == pytest.approx(n_curves / 30.0, abs=1e-3)
    assert np.abs(audio).max() > 0.01  # the speech, not silence


def test_posing_is_the_rig_evaluated_and_moved_by_the_head(made):
    curves = RigCurves.read(made["curves"])
    rig = builtin_rig()
    still = pose_rig(curves, rig, "c.h5")
    t = len(curves.weights) // 2
    expected = rig.neutral + np.tensordot(curves.weights[t].astype(np.float64), rig.deltas, axes=(0, 0))
    assert np.abs(still.vertices[t] - expected).max() < 1e-3
    assert np.array_equal(still.rest, rig.neutral.astype(np.float32)) and np.array_equal(still.faces, rig.faces)
    moving = pose_rig(curves, rig, "c.h5", head_motion=True)
    r, x = curves.head_rotation[t].astype(np.float64), curves.head_translation[t].astype(np.float64)
    assert np.abs(moving.vertices[t] - (expected @ r.T + x)).max() < 1e-2
    assert np.abs(moving.vertices - still.vertices).max() > 0.1  # the synthesized head does move
    # the eyes follow the rig's eyeLook shapes
    assert np.array_equal(still.gaze, gaze_from_rig_weights(curves.weights, rig.shape_names).astype(np.float32))


def test_rig_mesh_writes_what_render_poses(made, tmp_path):
    rig_mesh.run(made["curves"], tmp_path / "posed.h5")
    posed = MeshAnimation.read(tmp_path / "posed.h5")
    in_memory = video.AnimationReader(None, None, head_motion=False).read(made["curves"])
    assert np.array_equal(posed.vertices, in_memory.vertices)
    assert np.allclose(posed.gaze, in_memory.gaze, equal_nan=True)


def _dihedral_growth(vertices: np.ndarray, rest: np.ndarray, faces: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Per edge (E, 4: two vertices, two faces) the angle (degrees) between the normals of its two
    triangles in ``vertices`` minus the same angle at ``rest``: a crease or fold shows as a large growth."""

    def angle(v):
        v = v.astype(np.float64)
        n = np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
        n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-12
        return np.degrees(np.arccos(np.clip((n[edges[:, 2]] * n[edges[:, 3]]).sum(1), -1, 1)))

    return angle(vertices) - angle(rest)


def _jaw_line_edges(rig) -> np.ndarray:
    """Interior edges (vertex, vertex, face, face) of the skin the jaw carries below the mouth:
    vertices ``jawOpen`` moves by more than 0.5 mm, at least 5 mm below the mouth's lowest point
    (the chin, the jaw line and the skin under it, not the lips)."""
    pairs: dict[tuple[int, int], list[int]] = {}
    for f, tri in enumerate(rig.faces):
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            pairs.setdefault((min(a, b), max(a, b)), []).append(f)
    edges = np.array([(a, b, *fs) for (a, b), fs in pairs.items() if len(fs) == 2])
    jaw = np.linalg.norm(rig.deltas[rig.shape_index("jawOpen")], axis=1)
    region = (jaw > 0.5) & (rig.neutral[:, 1] < rig.neutral[rig.loops["mouth"], 1].min() - 5.0)
    return edges[region[edges[:, 0]] & region[edges[:, 1]]]


def test_open_mouth_has_no_crease_under_the_jaw_through_the_rig(made):
    """The same motion, its most open frame: solved onto the rig, the jaw line bends by a few
    degrees more than at rest; Gaussian marker deformation of the same mesh folds it."""
    curves = RigCurves.read(made["curves"])
    rig = load_face_rig()
    t = int(np.argmax(curves.weights[:, rig.shape_index("jawOpen")]))
    assert curves.weights[t, rig.shape_index("jawOpen")] > 0.15  # an open mouth
    edges = _jaw_line_edges(rig)
    assert len(edges) > 1000
    through_rig = pose_rig(curves, builtin_rig(), "c.h5").vertices[t]
    deformed = MeshAnimation.read(made["anim"])
    assert np.array_equal(deformed.faces, rig.faces)  # the sample corpus's face.obj is the rig's mesh
    rig_growth = _dihedral_growth(through_rig, rig.neutral, rig.faces, edges).max()
    deform_growth = _dihedral_growth(deformed.vertices[t], rig.neutral, rig.faces, edges).max()
    assert rig_growth < 20.0
    assert deform_growth > 2 * rig_growth


def test_open_mouth_interior_is_dark_through_the_rig(made, tmp_path):
    """With the jaw open (jawOpen 0.5, nothing else) the mouth opening shows the dark cavity (and
    teeth); at rest the same place is lips and skin."""
    curves = RigCurves.read(made["curves"])
    rig = load_face_rig()
    w = np.zeros_like(curves.weights)
    w[:, rig.shape_index("jawOpen")] = 0.5
    dataclasses.replace(curves, weights=w).write(tmp_path / "open.h5", config="{}", inputs=[])
    t = 0
    clip = video.AnimationReader(None, None, head_motion=False).read(tmp_path / "open.h5")
    settings = _settings("render.use_opencl=false")
    view = video.ShadedView(clip, settings, settings.width)

    def dark_in_mouth(vertices):
        frame = view.frame(vertices, t)
        p = view.camera.project(vertices[rig.loops["mouth"]].astype(np.float64))[:, :2] / settings.supersample
        (x0, y0), (x1, y1) = p.min(0), p.max(0)
        box = frame[int(y0):int(np.ceil(y1)) + 1, int(x0 + 0.25 * (x1 - x0)):int(x1 - 0.25 * (x1 - x0))]
        return (box.astype(int).sum(-1) / 3 < 60).mean()

    assert dark_in_mouth(clip.vertices[t]) > 0.15
    assert dark_in_mouth(rig.neutral.astype(np.float32)) < 0.05


@needs_openfacefx
def test_openfacefx_curves_share_the_motion_s_timing_and_rig(made, tmp_path):
    s = openfacefx.run(made["motion"], tmp_path / "o.h5")
    c = RigCurves.read(tmp_path / "o.h5")
    m = Motion.read(made["motion"])
    search, _ = Motion.read_search(made["motion"])
    assert c.source == "openfacefx" and c.n_frames == len(m.markers) == s.frames and c.fps == m.fps
    assert list(c.shape_names) == list(load_face_rig().shape_names) and c.head_rotation is None
    jaw = c.weights[:, load_face_rig().shape_index("jawOpen")]
    assert jaw.max() > 0.1  # it speaks
    # silent at the leading pause, open inside a vowel
    first_pause = search.end[0] if search.phone[0] == "pau" else 0.0
    if first_pause > 0.1:
        assert jaw[: int(first_pause * m.fps) - 2].max() < jaw.max() / 2
    # a captured take has no phones to give openfacefx
    capture = dataclasses.replace(m, source="capture", take="t", path=None, provenance=None)
    capture.write(tmp_path / "cap.h5", config="{}")
    with pytest.raises(InputError, match="a captured take has no phones for openfacefx"):
        openfacefx.run(tmp_path / "cap.h5", tmp_path / "p.h5")
    assert not (tmp_path / "p.h5").exists()


@needs_openfacefx
def test_side_by_side_of_two_clips_each_beside_its_own_openfacefx(made, tmp_path):
    openfacefx.run(made["motion"], tmp_path / "o.h5")
    settings = _settings("render.view=side-by-side", 'render.labels=["facesynth","openfacefx"]')
    out = tmp_path / "sbs.avi"
    s = render.run([made["curves"], made["curves"]], [made["audio"], made["audio"]], out, settings,
                   compare=[tmp_path / "o.h5", made["curves"]])
    n = RigCurves.read(made["curves"]).n_frames
    assert s.frames == 2 * n == imageio_ffmpeg.count_frames_and_secs(str(out))[0]
    clip = video.AnimationReader(None, None, True).read(made["curves"])
    other = video.AnimationReader(None, None, True).read(tmp_path / "o.h5")
    frame = next(video.render_frames(clip, dataclasses.replace(settings, use_opencl=False), other))
    half = settings.width // 2
    background = np.round(video.BACKGROUND[:3] * 255)
    left, right = frame[8:30, 8:80].astype(float), frame[8:30, half + 8:half + 80].astype(float)
    for region in (left, right):
        assert (np.abs(region - background).max(-1) > 100).sum() > 40  # white text on its dark box
    assert np.abs(left - right).max() > 100  # "facesynth" is not "openfacefx"
    with pytest.raises(UsageError, match="one --compare for all animations or one per animation"):
        render.run([made["curves"]] * 3, [], tmp_path / "x.avi", settings, compare=[made["curves"]] * 2)


def test_curves_of_another_rig_or_a_rig_for_a_mesh_animation_are_refused(made, tmp_path):
    curves = RigCurves.read(made["curves"])
    other = dataclasses.replace(curves, rig_name="mine", rig_sha256="0" * 64)
    other.write(tmp_path / "mine.h5", config="{}", inputs=[])
    with pytest.raises(InputError, match="made for rig 'mine', not 'ict-facekit'; give that rig with --rig"):
        render.run([tmp_path / "mine.h5"], [], tmp_path / "x.avi", _settings())
    with pytest.raises(UsageError, match="--rig is for rig curves"):
        render.run([made["anim"]], [], tmp_path / "x.avi", _settings(), rig_path=tmp_path / "rig")
    assert not (tmp_path / "x.avi").exists()


@needs_openfacefx
def test_a_user_s_rig_with_arkit_names_is_driven_and_rendered_with_rig(made, tmp_path):
    """A rig folder (the built-in mesh with three ARKit-named shapes and one other): openfacefx
    drives its ARKit shapes by name, and render poses it with --rig (no binding needed)."""
    from facesynth.formats.mesh import write_obj

    builtin = load_face_rig()
    folder = tmp_path / "myrig"
    folder.mkdir()
    write_obj(folder / "neutral.obj", builtin.neutral, builtin.faces)
    for name in ("jawOpen", "mouthFunnel", "mouthClose", "wrinkle"):
        delta = builtin.deltas[builtin.shape_index(name if name != "wrinkle" else "cheekRaiser_L")]
        write_obj(folder / f"{name}.obj", builtin.neutral + delta, builtin.faces)
    openfacefx.run(made["motion"], tmp_path / "o.h5", rig_path=folder)
    c = RigCurves.read(tmp_path / "o.h5")
    assert c.rig_name == "myrig" and c.shape_names == ["jawOpen", "mouthClose", "mouthFunnel", "wrinkle"]
    openfacefx.run(made["motion"], tmp_path / "b.h5")
    on_builtin = RigCurves.read(tmp_path / "b.h5").weights
    assert np.allclose(c.weights[:, 0], on_builtin[:, builtin.shape_index("jawOpen")], atol=1e-6)
    assert (c.weights[:, 3] == 0).all()  # no ARKit channel drives it
    settings = _settings("render.width=96", "render.height=80")
    s = render.run([tmp_path / "o.h5"], [made["audio"]], tmp_path / "u.avi", settings, rig_path=folder)
    assert s.frames == c.n_frames
    with pytest.raises(InputError, match="made for rig 'myrig', not 'ict-facekit'; give that rig with --rig"):
        render.run([tmp_path / "o.h5"], [], tmp_path / "x.avi", settings)
    for p in folder.glob("*.obj"):
        if p.stem != "neutral":
            p.rename(p.with_name(f"shape_{p.name}"))
    with pytest.raises(InputError, match="myrig: none of the shapes of rig 'myrig' has an ARKit name"):
        openfacefx.run(made["motion"], tmp_path / "n.h5", rig_path=folder)
