"""Target rigs from a user's files (OBJ folder, glTF), artist keymorphs, and the bad inputs of
issue 17: one sentence, exit 1, nothing written."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from meshes import grid

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import builtin_rig, read_keymorphs, read_rig
from facesynth.formats.mesh import write_obj


def _rig_folder(folder: Path) -> tuple[np.ndarray, np.ndarray]:
    folder.mkdir()
    v, f = grid(4)
    write_obj(folder / "neutral.obj", v, f)
    up = v.copy()
    up[:, 2] += v[:, 0]
    write_obj(folder / "lift.obj", up, f)
    side = v.copy()
    side[:, 0] += 0.5 * v[:, 1]
    write_obj(folder / "shear.obj", side, f)
    return v, f


def _binding(path: Path, n: int = 16) -> Path:
    path.write_text("marker,vertex\n" + "".join(f"M{i},{i}\n" for i in range(n)))
    return path


def test_an_obj_folder_is_a_rig_named_by_its_files(tmp_path):
    v, f = _rig_folder(tmp_path / "rig")
    rig = read_rig(tmp_path / "rig", _binding(tmp_path / "b.csv"))
    assert rig.shape_names == ("lift", "shear") and rig.name == "rig" and len(rig.sha256) == 64
    np.testing.assert_allclose(rig.evaluate(np.array([1.0, 0.0]))[:, 2], v[:, 0], atol=1e-4)


def test_rig_objs_that_disagree_in_vertex_count_or_topology_are_refused(tmp_path):
    v, f = _rig_folder(tmp_path / "rig")
    write_obj(tmp_path / "rig" / "lift.obj", v[:-1], f[:-2])
    with pytest.raises(InputError, match=r"lift.obj: 15 vertices, but neutral.obj has 16"):
        read_rig(tmp_path / "rig", _binding(tmp_path / "b.csv"))
    write_obj(tmp_path / "rig" / "lift.obj", v, f[:, [0, 2, 1]])
    with pytest.raises(InputError, match=r"lift.obj: its triangles differ from neutral.obj's"):
        read_rig(tmp_path / "rig", _binding(tmp_path / "b.csv"))


def test_a_gltf_with_morph_targets_is_a_rig(tmp_path):
    v, f = grid(4)
    delta = np.zeros_like(v)
    delta[:, 2] = 1.0
    blobs = [v.astype(np.float32).tobytes(), f.astype(np.uint32).tobytes(), delta.astype(np.float32).tobytes()]
    data = b"".join(blobs)
    offsets = np.cumsum([0] + [len(b) for b in blobs])
    doc = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": int(offsets[i]), "byteLength": len(blobs[i])} for i in range(3)],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5125, "count": f.size, "type": "SCALAR"},
                      {"bufferView": 2, "componentType": 5126, "count": len(v), "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "targets": [{"POSITION": 2}]}],
                    "extras": {"targetNames": ["puff"]}}],
    }
    (tmp_path / "face.gltf").write_text(json.dumps(doc))
    rig = read_rig(tmp_path / "face.gltf", _binding(tmp_path / "b.csv"))
    assert rig.shape_names == ("puff",)
    np.testing.assert_array_equal(rig.faces, f)
    np.testing.assert_allclose(rig.deltas[0], delta)


def _toy_rig(tmp_path) -> Rig:
    _rig_folder(tmp_path / "rig")
    return read_rig(tmp_path / "rig", _binding(tmp_path / "b.csv"))


def test_keymorph_csv_and_folder_are_matched_by_key_shape_name(tmp_path):
    rig = _toy_rig(tmp_path)
    (tmp_path / "k.csv").write_text("keyshape,lift,shear\nk1,0.5,0\nk2,0,1\n")
    w, meshes = read_keymorphs(tmp_path / "k.csv", ["k2", "k1"], rig)
    np.testing.assert_allclose(w, [[0, 1], [0.5, 0]])
    (tmp_path / "k.csv").write_text("keyshape,lift,shear\nk1,1.5,0\n")
    with pytest.raises(InputError, match=r"k.csv, line 2, column 'lift': weight 1.5 is outside \[0, 1\]"):
        read_keymorphs(tmp_path / "k.csv", ["k1"], rig)
    folder = tmp_path / "morphs"
    folder.mkdir()
    write_obj(folder / "k1.obj", rig.neutral, rig.faces)
    with pytest.raises(InputError, match=r"morphs: no k2.obj; the keymorph folder needs one OBJ per key-shape"):
        read_keymorphs(folder, ["k1", "k2"], rig)


@pytest.fixture(scope="module")
def retarget_inputs(tiny_db, tiny_artifacts, held_out_take, config, tmp_path_factory):
    """A captured held-out take and key-shapes (3 per emotion) of the tiny corpus."""
    import dataclasses

    from facesynth.stages import capture, keyshapes

    d = tmp_path_factory.mktemp("retarget")
    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, d / "take.h5", config.settings("normalize"), 30.0)
    keyshapes.run(tiny_db, d / "ks.h5", dataclasses.replace(config.settings("keyshapes"), count=3, curve_frames=100))
    return d / "take.h5", d / "ks.h5"


def _invoke(args, tmp_path):
    result = CliRunner().invoke(main, [str(a) for a in args])
    return result.exit_code, result.output


def test_retarget_and_solve_write_curves_on_the_built_in_rig(retarget_inputs, tmp_path):
    from facesynth.model.curves import RigCurves

    take, ks = retarget_inputs
    code, out = _invoke(["retarget", take, "--keyshapes", ks, "--blend", "linear", "--mesh", tmp_path / "a.h5",
                         "-o", tmp_path / "r.h5"], tmp_path)
    assert code == 0, out
    curves = RigCurves.read(tmp_path / "r.h5")
    rig = builtin_rig()
    assert curves.source == "retarget" and curves.shape_names == list(rig.shape_names)
    assert curves.weights.min() >= 0 and curves.weights.max() <= 1 and curves.emotion is not None
    code, out = _invoke(["solve", take, "-o", tmp_path / "s.h5"], tmp_path)
    assert code == 0, out
    code, out = _invoke(["rig-mesh", tmp_path / "s.h5", "-o", tmp_path / "m.h5"], tmp_path)
    assert code == 0, out


def test_bad_rig_and_keymorph_inputs_are_one_sentence_and_write_nothing(retarget_inputs, tmp_path):
    take, ks = retarget_inputs
    v, f = _rig_folder(tmp_path / "rig")
    write_obj(tmp_path / "rig" / "shear.obj", v[:-2], f[:-4])
    binding = _binding(tmp_path / "b.csv")
    out_path = tmp_path / "c.h5"
    code, out = _invoke(["solve", take, "--rig", tmp_path / "rig", "--binding", binding, "-o", out_path], tmp_path)
    assert code == 1 and "shear.obj: 14 vertices, but neutral.obj has 16" in out and "Traceback" not in out
    assert not out_path.exists()

    rig = builtin_rig()
    (tmp_path / "k.csv").write_text("keyshape,jawOpen\nangry-01,1.2\n")
    code, out = _invoke(["retarget", take, "--keyshapes", ks, "--keymorphs", tmp_path / "k.csv", "-o", out_path], tmp_path)
    assert code == 1 and "weight 1.2 is outside [0, 1]" in out and not out_path.exists()
    folder = tmp_path / "morphs"
    folder.mkdir()
    write_obj(folder / "angry-01.obj", rig.neutral, rig.faces)
    code, out = _invoke(["retarget", take, "--keyshapes", ks, "--keymorphs", folder, "--mesh", tmp_path / "m.h5",
                         "-o", out_path], tmp_path)
    assert code == 1 and "no angry-02.obj" in out and not out_path.exists() and not (tmp_path / "m.h5").exists()
