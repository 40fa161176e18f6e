"""Where each frame came from survives the pipeline: synthesize -> solve -> rig-mesh, deform,
retarget -> export keep the same per-frame phones, emotions, nodes and takes as the synthesized
motion's own provenance (exactly), in the artifacts, in glTF ``extras`` and in USD ``customData``;
a captured take carries its name and no phones; frames resampled between rates take the
provenance of the nearest source frame."""

import dataclasses
import json

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.formats import usd
from facesynth.model import check
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.model.provenance import nearest_frames
from facesynth.stages import capture, deform, export, keyshapes, retarget, rig_mesh, solve, synthesize


@pytest.fixture(scope="module")
def carried(tiny_db, tiny_corpus, tiny_artifacts, held_out_take, tmp_path_factory):
    """The held-out sentence synthesized from the tiny database and carried through every stage
    that keeps a motion's provenance (solve, rig-mesh, deform, retarget, capture)."""
    config = Config.load()
    d = tmp_path_factory.mktemp("provenance")
    synthesize.run(tiny_db, d / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    solve.run(d / "m.h5", d / "c.h5", config.settings("solve"))
    rig_mesh.run(d / "c.h5", d / "r.h5")
    deform.run(d / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", d / "a.h5", config.settings("deform"))
    ks = dataclasses.replace(config.settings("keyshapes"), count=3, curve_frames=200)
    keyshapes.run(tiny_db, d / "k.h5", ks)
    retarget.run(d / "m.h5", d / "k.h5", d / "rt.h5", dataclasses.replace(config.settings("retarget"), blend="linear"),
                 ks, mesh_out=d / "rt_mesh.h5")
    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, d / "cap.h5", config.settings("normalize"), 30.0)
    solve.run(d / "cap.h5", d / "cap_c.h5", config.settings("solve"))
    return d


def _expected(path):
    """Per output frame of the motion at ``path``, worked out from its capture-rate provenance:
    (phone, emotion, node, take) of the nearest capture-rate frame."""
    m = Motion.read(path)
    search, prov = Motion.read_search(path)
    j = np.clip(np.round(np.arange(len(m.markers)) * prov.fps / m.fps), 0, len(prov.node) - 1).astype(int)
    phone = [search.phone[s] for s in prov.step[j]]
    emotion = [search.emotion[s] for s in prov.step[j]]
    take = [prov.take_names[t] if t >= 0 else "" for t in prov.take[j]]
    return m, search, phone, emotion, prov.node[j], take


def test_every_artifact_of_the_chain_keeps_the_motions_provenance(carried):
    m, search, phone, emotion, node, take = _expected(carried / "m.h5")
    assert len(set(phone)) > 3 and (node >= 0).sum() > len(node) // 2  # a real utterance, mostly from the database
    # each frame's phone is the one whose span holds the frame's time (to a capture-rate frame)
    t = np.arange(len(phone)) / m.fps
    for i, p in enumerate(phone):
        inside = np.flatnonzero((search.start - 1 / 60 <= t[i]) & (t[i] <= search.end + 1 / 60))
        assert p in [search.phone[k] for k in inside]
    for name, reader in (("c.h5", RigCurves.read), ("r.h5", MeshAnimation.read), ("a.h5", MeshAnimation.read),
                         ("rt.h5", RigCurves.read), ("rt_mesh.h5", MeshAnimation.read)):
        prov = reader(carried / name).provenance
        assert prov is not None, name
        assert prov.origin == "synthesis" and prov.method == "dp"
        assert prov.phone == phone and prov.emotion == emotion and prov.take == take, name
        np.testing.assert_array_equal(prov.node, node, err_msg=name)
        assert [s.phone for s in prov.segments] == search.phone
        assert [s.node for s in prov.segments] == [int(n) for n in search.node]
        np.testing.assert_array_equal([s.start for s in prov.segments], search.start)
        report = check.check_file(carried / name)
        assert report.problems == [], name


def test_a_motion_of_the_first_schema_is_refused_and_curves_made_from_one_still_read(carried, tmp_path):
    """Motion schema 1 named the trajectory method in ``source`` and the method in ``path/search``;
    such a motion is refused with the command that makes it again, while curves written from one
    (provenance ``origin = "trajectory"``) read as a synthesis by the trajectory method."""
    import shutil

    import h5py
    from click.testing import CliRunner

    from facesynth.cli import main

    old = tmp_path / "old_motion.h5"
    shutil.copy(carried / "m.h5", old)
    with h5py.File(old, "r+") as f:
        f.attrs["facesynth_schema"] = 1
    r = CliRunner().invoke(main, ["solve", str(old), "-o", str(tmp_path / "c.h5")])
    assert r.exit_code == 1 and "'motion' schema 1 is not the supported schema 2" in r.output
    assert "facesynth synthesize" in r.output and not (tmp_path / "c.h5").exists()
    curves = tmp_path / "old_curves.h5"
    shutil.copy(carried / "c.h5", curves)
    with h5py.File(curves, "r+") as f:
        f["provenance"].attrs["origin"] = "trajectory"
        del f["provenance"].attrs["method"]
    prov = RigCurves.read(curves).provenance
    assert (prov.origin, prov.method) == ("synthesis", "trajectory")


def test_a_captured_take_carries_its_name_and_no_phones(carried, held_out_take):
    prov = RigCurves.read(carried / "cap_c.h5").provenance
    assert prov.origin == "capture" and prov.method == "" and prov.segments == []
    assert set(prov.take) == {held_out_take} and set(prov.phone) == {""} and (prov.node == -1).all()
    cap = Motion.read(carried / "cap.h5")
    np.testing.assert_array_equal(prov.source_frame, nearest_frames(len(cap.markers), cap.fps, len(cap.markers_capture),
                                                                    cap.capture_fps))
    assert check.check_file(carried / "cap_c.h5").problems == []


def test_gltf_extras_carry_the_provenance(carried):
    _, search, phone, emotion, node, take = _expected(carried / "m.h5")
    export.run(carried / "c.h5", "gltf", carried / "c.gltf", Config.load().settings("export"), overwrite=True)
    doc = json.loads((carried / "c.gltf").read_text())
    p = doc["animations"][0]["extras"]["facesynth_provenance"]
    assert p["frames"]["phone"] == phone and p["frames"]["emotion"] == emotion and p["frames"]["take"] == take
    assert p["frames"]["node"] == node.tolist() and p["method"] == "dp"
    assert [s["phone"] for s in p["phones"]] == search.phone and [s["node"] for s in p["phones"]] == search.node.tolist()


def test_resampled_export_takes_the_nearest_source_frame(carried):
    c = RigCurves.read(carried / "c.h5")
    export.run(carried / "c.h5", "gltf", carried / "c60.gltf", Config.load().settings("export"), fps=60.0, overwrite=True)
    p = json.loads((carried / "c60.gltf").read_text())["animations"][0]["extras"]["facesynth_provenance"]
    n = len(p["frames"]["phone"])
    assert n == pytest.approx(2 * c.n_frames, abs=1)
    # frame i at i/60 s: the nearest 30 frames/s frame is round(i / 2) (halves round up)
    src = np.minimum(np.floor(np.arange(n) / 2 + 0.5).astype(int), c.n_frames - 1)
    assert p["frames"]["phone"] == [c.provenance.phone[i] for i in src]
    assert p["frames"]["node"] == c.provenance.node[src].tolist()


@pytest.mark.skipif(not usd.available(), reason="usd-core (pxr) is not installed: pip install 'facesynth[usd]'")
@pytest.mark.parametrize("name", ["c.h5", "a.h5"])
def test_usd_custom_data_carries_the_provenance(carried, name):
    from pxr import Usd

    _, search, phone, emotion, node, take = _expected(carried / "m.h5")
    out = carried / f"{name}.usda"
    export.run(carried / name, "usda", out, Config.load().settings("export"), overwrite=True)
    stage = Usd.Stage.Open(str(out))
    data = stage.GetPrimAtPath("/Face").GetCustomData()["facesynth"]["provenance"]
    assert list(data["phone"]) == phone and list(data["emotion"]) == emotion and list(data["take"]) == take
    assert list(data["node"]) == node.tolist()
    assert list(data["segment_phone"]) == search.phone and list(data["segment_node"]) == search.node.tolist()
    assert data["origin"] == "synthesis" and data["method"] == "dp"


def test_the_player_labels_a_capture_with_its_take_and_a_synthesis_with_its_phones(carried, held_out_take):
    from facesynth.domain.exports.animation import load
    from facesynth.domain.exports.player import payload

    captured = payload(load(carried / "cap_c.h5"))
    assert captured["phones"] == [] and [r["emotion"] for r in captured["take_runs"]] == [held_out_take]
    assert captured["take_runs"][0]["end"] == pytest.approx(captured["duration"])
    synthesized = payload(load(carried / "a.h5"))  # a deformed mesh: its phones from its own provenance
    search, _ = Motion.read_search(carried / "m.h5")
    assert [p["phone"] for p in synthesized["phones"]] == search.phone and synthesized["take_runs"] == []
    assert synthesized["frame_provenance"]["phone"] == _expected(carried / "m.h5")[2]
