"""The Blender add-on's parts that need no Blender (blender/facesynth_blender/core.py, the zip,
docs/blender.md), so they run everywhere: shape-key names and the mapping table, emotion spans
from markers, the facesynth runs and their one-sentence errors, and the Live Link Face CSV route
the add-on keys from, whose values must equal the solve's curves to 1e-6."""

from __future__ import annotations

import ast
import re
import sys
import zipfile

import numpy as np
import pytest
from addon_check import (
    ADDON,
    ROOT,
    TO_BLENDER,
    core,
    expected_arkit,
    expected_head,
    facesynth_command,
    make_zip,
    read_curves,
    run,
)
from scipy.spatial.transform import Rotation

DOCS = ROOT / "docs" / "blender.md"


@pytest.mark.parametrize("spelling", ["mouthSmileLeft", "MouthSmileLeft", "mouthSmile_L", "Mouth_Smile_L",
                                      "mouthSmile.L", "mouthsmile_left", "MOUTHSMILE-L"])
def test_spellings_of_an_arkit_name(spelling):
    assert core().arkit_name(spelling) == "mouthSmileLeft"


def test_directions_are_not_sides():
    c = core()
    assert c.arkit_name("jawLeft") == "jawLeft" and c.arkit_name("mouth_Right") == "mouthRight"
    assert c.arkit_name("mouthRollLower") == "mouthRollLower"  # ends in 'r' with no separator: no side
    assert c.arkit_name("cheekRaiser_L") is None and c.arkit_name("Basis") is None


def test_matching_shape_keys_to_columns():
    c = core()
    keys = ["JawOpen", "mouthSmile_L", "browInnerUp_L", "browInnerUp_R", "Smirk", "cheekRaiser_L"]
    columns = ["JawOpen", "MouthSmileLeft", "MouthSmileRight", "BrowInnerUp", "MouthPucker"]
    assert c.match_shape_keys(columns, keys) == {"JawOpen": ["JawOpen"], "MouthSmileLeft": ["mouthSmile_L"],
                                                 "BrowInnerUp": ["browInnerUp_L", "browInnerUp_R"]}
    mapping = c.parse_mapping("mouthPucker=Smirk; jawOpen = ;\n# a comment\nmouthSmileRight=Smirk+cheekRaiser_L")
    assert c.match_shape_keys(columns, keys, mapping) == {
        "MouthSmileLeft": ["mouthSmile_L"], "MouthSmileRight": ["Smirk", "cheekRaiser_L"],
        "BrowInnerUp": ["browInnerUp_L", "browInnerUp_R"], "MouthPucker": ["Smirk"]}
    # a rig's own shape names (not ARKit) match by spelling
    assert c.match_shape_keys(["cheekRaiser_L"], keys) == {"cheekRaiser_L": ["cheekRaiser_L"]}


@pytest.mark.parametrize("text, words", [("jawOpen", "is not 'arkitName=ShapeKey'"),
                                         ("mouthGrin=Smirk", "'mouthGrin' is not one of the 52 ARKit")])
def test_bad_mapping_entries(text, words):
    with pytest.raises(core().AddonError, match=re.escape(words)):
        core().parse_mapping(text)


def test_mapping_to_a_missing_shape_key():
    c = core()
    with pytest.raises(c.AddonError, match="shape key 'JawDrop', which the mesh does not have"):
        c.match_shape_keys(["JawOpen"], ["jawOpen"], c.parse_mapping("jawOpen=JawDrop"))


def test_spans_from_markers():
    c = core()
    markers = [("shot 2", 5), ("Happy", 22), ("neutral", 4), ("sadness", 46), ("angry", 200)]
    # from frame 10 at 24 frames/s, a 3 s sound: 'neutral' before the start runs into it, the
    # angry marker after the sound's end is dropped, and the sad span ends there
    assert c.spans_from_markers(markers, 10, 24.0, duration_s=3.0) == [
        (0.0, 0.5, "neutral"), (0.5, 1.5, "happy"), (1.5, 190 / 24, "sad")]
    assert c.spans_from_markers([("happy", 1), ("sad", 5)], 10, 24.0) == [(0.0, 1000.0, "sad")]
    assert c.spans_from_markers([("cut", 12)], 10, 24.0) == []


def test_failure_is_one_sentence():
    c = core()
    said = c.failure("synthesize", 1, "warning: something\nerror: x.mp4: has no audio stream (it holds video only); "
                                      "give a file with sound, or the speech as a sound file of its own.\n")
    assert str(said) == ("facesynth synthesize failed: x.mp4: has no audio stream (it holds video only); give a file "
                         "with sound, or the speech as a sound file of its own.")
    usage = "Usage: facesynth solve [OPTIONS] MOTION\nTry 'facesynth solve -h' for help.\n\nError: No such option: --x\n"
    assert str(c.failure("solve", 2, usage)) == "facesynth solve failed: No such option: --x."
    crash = "Traceback (most recent call last):\n  File \"x.py\", line 1\nValueError: bad shape\n"
    assert str(c.failure("solve", 1, crash)) == "facesynth solve failed: it stopped with exit status 1: ValueError: bad shape."


def test_finding_the_executable(tmp_path, monkeypatch):
    c = core()
    with pytest.raises(c.AddonError, match="does not exist; set the add-on preference"):
        c.find_executable(str(tmp_path / "nope" / "facesynth"))
    plain = tmp_path / "facesynth"
    plain.write_text("#!/bin/sh\n")
    with pytest.raises(c.AddonError, match="cannot be run"):
        c.find_executable(str(plain))
    plain.chmod(0o755)
    assert c.find_executable(str(tmp_path)) == str(plain)  # a folder: its facesynth
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    with pytest.raises(c.AddonError, match="facesynth was not found"):
        c.find_executable("")
    monkeypatch.setenv("PATH", str(tmp_path))
    assert c.find_executable("") == str(plain)


def test_job_reports_the_failing_step(tmp_path):
    c = core()
    script = tmp_path / "fake"
    script.write_text("#!/bin/sh\nif [ \"$1\" = solve ]; then echo 'error: motion.h5: not a motion.' >&2; exit 1; fi\n"
                      "echo 'warning: the database has no node of /zh/'\n")
    script.chmod(0o755)
    job = c.Job([("synthesize", [str(script), "synthesize"]), ("solve", [str(script), "solve"]),
                 ("export", [str(script), "export"])])
    seen = []
    with pytest.raises(c.AddonError, match=r"^facesynth solve failed: motion.h5: not a motion\.$"):
        job.run(lambda i, label: seen.append(label))
    assert seen == ["synthesize", "solve"] and job.warnings == ["the database has no node of /zh/"]
    with pytest.raises(c.AddonError, match="facesynth could not be started"):
        c.Job([("synthesize", [str(tmp_path / "missing")])]).run()


def test_commands_for_a_request(tmp_path):
    c = core()
    r = c.Request(audio="a.wav", database="db.h5", method="greedy", text=" hello ", emotions="e.txt",
                  rig="rig/", binding="b.csv", fps=29.97, head=True, work_dir=str(tmp_path))
    steps = dict(c.commands("fs", r))
    assert steps["synthesize"] == ["fs", "synthesize", "db.h5", "--audio", "a.wav", "--method", "greedy", "--text",
                                   "hello", "--emotions", "e.txt", "-o", r.files["motion"], "--overwrite"]
    assert steps["solve"] == ["fs", "solve", r.files["motion"], "--rig", "rig/", "--binding", "b.csv",
                              "-o", r.files["curves"], "--overwrite"]
    assert steps["export"] == ["fs", "export", r.files["curves"], "--format", "arkit-csv", "--fps", "29.97",
                               "--head-motion", "-o", r.files["csv"], "--overwrite"]


def test_a_request_in_another_language_passes_it_on(tmp_path):
    c = core()
    r = c.Request(audio="a.wav", database="db.h5", text="Bonjour", language="fr", work_dir=str(tmp_path))
    assert c.commands("fs", r)[0][1][-7:-3] == ["--text", "Bonjour", "--language", "fr"]
    audio, db = tmp_path / "a.wav", tmp_path / "db.h5"
    audio.write_bytes(b"")
    db.write_bytes(b"")
    with pytest.raises(c.AddonError, match="the language 'French!' is not a BCP-47 tag"):
        c.check_request(c.Request(audio=str(audio), database=str(db), language="French!"))


@pytest.mark.parametrize("fps", [24.0, 30000 / 1001])
def test_the_csv_route_keeps_the_solved_curves(held_out_synthesized, tmp_path, fps):
    """What the add-on keys is what ``facesynth export --format arkit-csv --fps <scene>`` writes:
    its weights equal the solve's curves resampled to the scene's rate to 1e-6, and its head angles,
    turned into Blender's axes as the add-on does, the curves' head rotation to 1e-6."""
    exe = facesynth_command(tmp_path / "bin")
    out = tmp_path / "face.csv"
    run([exe, "export", held_out_synthesized["curves"], "--format", "arkit-csv", "--head-motion", "--fps", repr(fps),
         "-o", out])
    got = core().read_livelink_csv(str(out))
    curves = read_curves(held_out_synthesized["curves"])
    want = expected_arkit(curves, fps)
    assert got.frames == len(want["jawOpen"])
    for name in core().ARKIT_NAMES:
        column = name[0].upper() + name[1:]
        np.testing.assert_allclose(got.shapes[column], want[name], atol=1e-6, rtol=0, err_msg=name)
    blender = []
    for yaw, pitch, roll in got.head:
        angles, order = core().head_euler_blender(yaw, pitch, roll)
        assert order == "YXZ"  # Blender's: y first, then x, then z (extrinsic), i.e. Rz @ Rx @ Ry
        blender.append(Rotation.from_euler("yxz", [angles[1], angles[0], angles[2]]).as_matrix())
    np.testing.assert_allclose(np.array(blender), TO_BLENDER @ expected_head(curves, fps) @ TO_BLENDER.T,
                               atol=1e-6, rtol=0)


def test_zip_holds_the_package(tmp_path):
    first = make_zip().build(tmp_path / "a")
    second = make_zip().build(tmp_path / "b")
    assert first.read_bytes() == second.read_bytes()  # the same sources, the same zip
    with zipfile.ZipFile(first) as zf:
        assert sorted(zf.namelist()) == sorted(f"facesynth_blender/{p.name}" for p in ADDON.glob("*.py"))
        tree = ast.parse(zf.read("facesynth_blender/__init__.py"))
    [info] = [node.value for node in tree.body if isinstance(node, ast.Assign) and node.targets[0].id == "bl_info"]
    bl_info = ast.literal_eval(info)
    assert bl_info["blender"] >= (3, 4, 0) and bl_info["name"] == "facesynth"


def test_addon_needs_nothing_outside_blender():
    """Blender's own Python has none of facesynth's dependencies: the add-on imports the standard
    library, bpy, mathutils and itself only."""
    allowed = set(sys.stdlib_module_names) | {"bpy", "mathutils", "__future__"}
    for path in ADDON.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                names = [node.module]
            else:
                continue
            for name in names:
                assert name.split(".")[0] in allowed, f"{path.name} imports {name}"


def test_docs_page():
    text = DOCS.read_text(encoding="utf-8")
    for image in re.findall(r"\]\((images/[^)]+\.png)\)", text):
        path = ROOT / "docs" / image
        assert path.exists() and path.stat().st_size < 200_000, image
    assert "images/blender_face.png" in text
    rows = re.findall(r"^\| `(\w+)` \|", text.split("## The mapping table", 1)[1], flags=re.M)
    assert rows == list(core().ARKIT_NAMES)
    assert "bpy.ops.facesynth.animate(" in text and "facesynth_executable" in text


def test_the_addon_animates_an_iphone_voice_memo_as_its_wav(tiny_db, tiny_corpus, held_out_take, coded_speech,
                                                           tmp_path):
    """The add-on's runs (facesynth synthesize, solve, export: the Job it starts in Blender) on the
    sentence as an M4A (AAC, an iPhone voice memo) key the WAV's frames and mouth (jawOpen r > 0.9;
    measured 0.94, the aligner's tolerance of tests/stages/test_synthesize.py); a video without
    sound is facesynth's one sentence in the operator's report."""
    import csv

    from coded_audio import coded

    c = core()
    exe = facesynth_command(tmp_path / "bin")
    text = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == held_out_take)["transcript"]
    jaw = {}
    for kind, audio in (("wav", coded_speech["wav"]), ("m4a", coded(coded_speech, "m4a"))):
        r = c.Request(audio=str(audio), database=str(tiny_db), text=text, work_dir=str(tmp_path / kind))
        (tmp_path / kind).mkdir()
        c.check_request(r)
        c.Job(c.commands(exe, r)).run()
        jaw[kind] = np.asarray(c.read_livelink_csv(r.files["csv"]).shapes["JawOpen"])
    assert len(jaw["m4a"]) == len(jaw["wav"]) and np.corrcoef(jaw["m4a"], jaw["wav"])[0, 1] > 0.9
    silent = c.Request(audio=str(coded_speech["silent"]), database=str(tiny_db), work_dir=str(tmp_path / "silent"))
    (tmp_path / "silent").mkdir()
    c.check_request(silent)
    with pytest.raises(c.AddonError, match=r"^facesynth synthesize failed: .*silent\.mp4: has no audio stream"):
        c.Job(c.commands(exe, silent)).run()
