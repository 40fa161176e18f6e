import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.geometry.rigid import similarity_fit
from facesynth.domain.rendering.parts import classify_holes, lip_halves
from facesynth.domain.retarget.deform import animate, bind, mesh_distances
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import build_marker_set


@pytest.fixture(scope="module")
def face():
    """The sample corpus's face: the production rig with the actress's markers."""
    rig = load_face_rig()
    return rig, build_marker_set(rig)


def test_mesh_distance_goes_around_the_mouth(face):
    rig, markers = face
    up = markers.vertices[markers.names.index("ULI_C")]
    lo = markers.vertices[markers.names.index("LLI_C")]
    assert np.linalg.norm(rig.neutral[up] - rig.neutral[lo]) < 1.0  # the closed lips touch
    d = mesh_distances(rig.neutral, rig.faces, np.array([lo]), limit=np.inf)[0, up]
    assert d > 45.0  # around a mouth corner: the mouth opening's half width (23 mm), twice


def test_lower_lip_motion_does_not_drag_the_upper_lip(face, config):
    rig, markers = face
    settings = config.settings("deform")
    bound = bind(rig.neutral, rig.faces, markers.binding(), markers.names, settings, "face", "binding")
    reference = rig.neutral[markers.vertices]
    pulled = reference.copy()[None]
    pulled[0, markers.names.index("LLI_C"), 1] -= 10.0  # pull the lower lip down 10 mm
    verts, _ = animate(bound, pulled, markers.names, reference)
    moved = np.linalg.norm(verts[0] - rig.neutral, axis=1)
    up = markers.vertices[markers.names.index("ULI_C")]
    lo = markers.vertices[markers.names.index("LLI_C")]
    # Eq. 15 averages the neighbouring markers, so the pull is diluted; the upper lip must not move at all.
    assert moved[lo] > 0.5 and moved[up] < 1e-4


def test_vertex_error_against_the_rig_ground_truth(face, config):
    """Markers driven by the rig deform its full mesh close to the rig's own vertices."""
    rig, markers = face
    settings = config.settings("deform")
    bound = bind(rig.neutral, rig.faces, markers.binding(), markers.names, settings, "face", "binding")
    weights = np.zeros((3, len(rig.shape_names)))
    weights[0, rig.shape_index("jawOpen")] = 0.4
    weights[1, rig.shape_index("mouthPucker")] = 1.0
    weights[2, [rig.shape_index("mouthSmile_L"), rig.shape_index("mouthSmile_R")]] = 1.0
    truth = rig.evaluate(weights)
    verts, fit = animate(bound, truth[:, markers.vertices], markers.names, rig.neutral[markers.vertices])
    displacement = np.linalg.norm(truth - rig.neutral, axis=2)
    error = np.linalg.norm(verts - truth, axis=2)
    # where the markers are (within 20 mm of one): Eq. 14-15 recover about two thirds of the
    # motion (measured: error 0.33 of the displacement); the rig also moves the neck and the
    # back of the head a little, where no marker is, and those vertices stay put.
    nearest = np.min(np.linalg.norm(rig.neutral[:, None] - rig.neutral[markers.vertices][None], axis=2), axis=1)
    moving = (displacement > 1.0) & (nearest < 20.0)[None]
    assert fit.fit_rms < 1e-9 and fit.scale == pytest.approx(1.0)
    assert moving.sum() > 5000
    assert error[moving].mean() < 0.4 * displacement[moving].mean()


def _rig_binding(rig):
    """About 90 markers on the rig as a capture has them: the 68 landmarks and every third
    vertex of the inner lip line; with which of them are on the upper lip."""
    mouth = rig.loops["mouth"]
    layout = classify_holes(rig.neutral, rig.faces)
    upper, _ = lip_halves(rig.neutral[mouth] - layout.mouth.centre)
    vertices = np.unique(np.concatenate([rig.landmarks68, mouth[::3]]))
    upper_set = set(mouth[upper].tolist())
    return vertices, np.array([v in upper_set for v in vertices]), mouth, upper


def test_the_production_rig_mesh(config):
    """The ICT face in mm (11,248 vertices, holes at the eyes and mouth) with ~90 markers on
    its vertices and the default Eq. 14 settings: bound, the rig's own jaw opening
    carried from the markers to the whole mesh, and the mouth hole keeping the upper lip's
    markers off the lower lip except through the mouth corners."""
    rig = load_face_rig()
    vertices, on_upper, mouth, upper = _rig_binding(rig)
    names = [f"m{v}" for v in vertices]
    bound = bind(rig.neutral, rig.faces, dict(zip(names, vertices.tolist())), names, config.settings("deform"), "ict", "b")
    assert 85 <= len(vertices) <= 100 and bound.weights.shape == (len(rig.neutral), len(vertices))
    assert bound.weights.nnz < 0.2 * bound.weights.shape[0] * bound.weights.shape[1]  # sparse: the threshold bites
    # The jaw opening of the rig itself, sampled at the markers.
    w = np.zeros((2, len(rig.shape_names)))
    w[1, rig.shape_index("jawOpen")] = 0.8
    truth = rig.evaluate(w)
    frames, fit = animate(bound, truth[:, vertices], names, rig.neutral[vertices])
    assert fit.scale == pytest.approx(1.0) and fit.fit_rms < 1e-9
    assert np.allclose(frames[0], rig.neutral, atol=1e-4)
    displacement = np.linalg.norm(truth[1] - rig.neutral, axis=1)
    error = np.linalg.norm(frames[1] - truth[1], axis=1)
    moving = displacement > 1.0
    assert error[moving].mean() < 0.5 * displacement[moving].mean()
    # Only the upper lip's markers move (5 mm up): the lower lip's middle barely follows, since
    # mesh distances go around the hole (the straight gap is ~11 mm, the way round ~45 mm).
    reference = rig.neutral[vertices]
    pulled = reference.copy()[None]
    pulled[0, on_upper, 1] += 5.0
    frames, _ = animate(bound, pulled, names, reference)
    moved = np.linalg.norm(frames[0] - rig.neutral, axis=1)
    ys = rig.neutral[mouth, 1]
    upper_mid = mouth[upper][np.argsort(ys[upper])[-6:]]
    lower_mid = mouth[~upper][np.argsort(ys[~upper])[:6]]
    assert moved[upper_mid].mean() > 2.0
    assert moved[lower_mid].mean() < 0.25 * moved[upper_mid].mean()


def test_several_components_keep_their_own_markers(config):
    # two separate triangles strips 1 mm apart: a marker on one never moves the other
    verts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0], [1, 0, 1], [0, 1, 1]], float)
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    rig = bind(verts, faces, {"a": 0, "b": 1, "c": 2}, ["a", "b", "c"], config.settings("deform"), "m", "b")
    assert rig.unreached == 3
    reference = verts[[0, 1, 2]]
    frames, _ = animate(rig, (reference + [0, 0, 0.5])[None], ["a", "b", "c"], reference)
    assert np.allclose(frames[0, 3:], verts[3:])


@pytest.mark.parametrize("binding, message", [
    ({"a": 0, "b": 1, "zz": 2}, r"marker\(s\) \['zz'\] are not in the motion"),
    ({"a": 0, "b": 1, "c": 99}, "bound to vertex 99, but m has vertices 0 to 5"),
])
def test_bad_bindings(config, binding, message):
    verts = np.zeros((6, 3))
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    with pytest.raises(InputError, match=message):
        bind(verts, faces, binding, ["a", "b", "c"], config.settings("deform"), "m", "b")


def test_similarity_fit_recovers_scale_rotation_translation():
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(0)
    a = rng.normal(size=(20, 3))
    r = Rotation.from_euler("xyz", [30, -10, 70], degrees=True).as_matrix()
    s, rr, t, res = similarity_fit(a, 2.5 * a @ r.T + [1, 2, 3])
    assert s == pytest.approx(2.5) and np.allclose(rr, r) and np.allclose(t, [1, 2, 3]) and res < 1e-9


def test_ply_meshes_and_non_manifold_edges(tmp_path, config):
    import trimesh

    from facesynth.formats.mesh import read_mesh

    # three triangles sharing the edge 0-1 (non-manifold), written as PLY
    verts = np.array([[0, 0, 0], [10, 0, 0], [5, 8, 0], [5, -8, 0], [5, 0, 8]], float)
    faces = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    trimesh.Trimesh(verts, faces, process=False).export(tmp_path / "m.ply")
    v, f = read_mesh(tmp_path / "m.ply")
    assert np.allclose(v, verts) and np.array_equal(f, faces)
    rig = bind(v, f, {"a": 2, "b": 3, "c": 4}, ["a", "b", "c"], config.settings("deform"), "m.ply", "b")
    reference = v[[2, 3, 4]]
    frames, _ = animate(rig, (reference + [0, 0, 1.0])[None], ["a", "b", "c"], reference)
    assert np.allclose(frames[0, :, 2] - verts[:, 2], 1.0)  # every vertex is reached across the shared edge
