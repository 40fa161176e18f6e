"""The Blender add-on in a real Blender, headless (Debian's ``blender`` package; skipped with the
reason where it is not installed): the add-on is installed and enabled from its zip, a face mesh
with ARKit-named shape keys and a head bone are made, and ``bpy.ops.facesynth.animate`` runs on a
held-out sentence of the tiny sample corpus with its text, emotion markers and a mapping. Its
keyframes must equal the curves ``facesynth solve`` wrote for it (kept in the operator's work
folder, read here with h5py), resampled to the scene's rate; the sound strip must be at the
start frame; a missing executable, a bad sound file, a mesh without shape keys and one without
ARKit names must be reported in one sentence, with nothing keyed; run again from the sound strip,
the keys must start at the strip and replace the first ones. The run also renders the keyed face
(docs/images/blender_face.png; ``FACESYNTH_UPDATE_DOCS_IMAGES=1`` writes it there).

One Blender session does all of it (one start-up); the tests below read what it found.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from addon_check import (
    ROOT,
    TO_BLENDER,
    expected_arkit,
    expected_head,
    facesynth_command,
    make_zip,
    read_curves,
    read_glb,
    run,
)

BLENDER = shutil.which("blender")
SCENE_SCRIPT = Path(__file__).with_name("blender_scene.py")
DOCS_IMAGE = ROOT / "docs" / "images" / "blender_face.png"

pytestmark = pytest.mark.skipif(BLENDER is None, reason="Blender is not installed (`blender` is not on the PATH; "
                                                        ".ci/run installs Debian's blender package where apt can)")

FPS = 24  # the scene's rate; the synthesis runs at another (30 frames/s), so the export resamples
FRAME_START = 10
#: Timeline markers: one not named by an emotion (ignored), then a happy and a sad span.
MARKERS = [("cut", FRAME_START + 5), ("happy", FRAME_START + 12), ("Sad", FRAME_START + 36)]
#: Shape keys named otherwise than ARKit's spelling: by the mapping table, by case, by _L/_R, and
#: the halves of the shapes ICT-FaceKit splits (one ARKit weight keys both).
MAPPING = "jawOpen=JawDrop"
SPELLED = {"jawOpen": "JawDrop", "mouthFunnel": "MouthFunnel", "eyeBlink_L": "eyeBlink_L", "eyeBlink_R": "eyeBlink_R",
           "browInnerUp_L": "browInnerUp_L", "browInnerUp_R": "browInnerUp_R", "cheekPuff_L": "cheekPuff_L",
           "cheekPuff_R": "cheekPuff_R", "cheekRaiser_L": "cheekRaiser_L", "cheekRaiser_R": "cheekRaiser_R"}


def key_name(ict: str) -> str:
    """The test mesh's shape key for a shape of the built-in rig: ARKit's spelling
    ('mouthSmile_L' -> 'mouthSmileLeft'), except the few of :data:`SPELLED`."""
    if ict in SPELLED:
        return SPELLED[ict]
    for suffix, side in (("_L", "Left"), ("_R", "Right")):
        if ict.endswith(suffix):
            return ict[: -len(suffix)] + side
    return ict


def key_sources(ict: str) -> list[str]:
    """The rig shapes whose mean the key of ``ict`` must carry (cheekRaiser has no ARKit shape)."""
    if ict.startswith("cheekRaiser"):
        return []
    for split in ("browInnerUp", "cheekPuff"):
        if ict.startswith(split):
            return [f"{split}_L", f"{split}_R"]
    return [ict]


def run_blender(folder: Path, tiny_db: Path, tiny_corpus: Path, take: str, synthesized: dict) -> None:
    """Make the job (the add-on's zip, the face's arrays, the sentence) in ``folder`` and run
    blender_scene.py on it in a headless Blender -> folder/result.json."""
    exe = facesynth_command(folder / "bin")
    zip_path = make_zip().build(folder / "dist")

    # the face: the built-in rig's mesh and shapes from a GLB the CLI writes, in Blender's axes
    run([exe, "export", synthesized["curves"], "--format", "glb", "-o", folder / "rig.glb"])
    rig = read_glb(folder / "rig.glb")
    (rig["positions"] @ TO_BLENDER.T).astype(np.float32).tofile(folder / "vertices.f32")
    rig["indices"].astype(np.int32).tofile(folder / "faces.i32")
    ((rig["positions"][None] + rig["targets"]) @ TO_BLENDER.T).astype(np.float32).tofile(folder / "shapes.f32")

    [row] = [r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == take]
    (folder / "bad.wav").write_text("this is not a sound\n")
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-nostdin", "-v", "error", "-y", "-f", "lavfi", "-i",
                    "color=c=gray:s=64x48:r=25:d=1", "-c:v", "mpeg4", str(folder / "silent.mp4")], check=True)
    job = {"zip": str(zip_path), "facesynth": exe, "missing_executable": str(folder / "no-such" / "facesynth"),
           "vertices": str(folder / "vertices.f32"), "faces": str(folder / "faces.i32"),
           "shapes": str(folder / "shapes.f32"), "rig_names": rig["names"],
           "shape_names": [key_name(n) for n in rig["names"]], "fps": FPS, "frame_start": FRAME_START,
           "markers": MARKERS, "bone_head": [0.0, 0.01, -0.05], "bone_tail": [0.0, 0.04, 0.07], "bone_roll": 0.4,
           "audio": str(tiny_corpus / "audio" / f"{take}.wav"), "text": row["transcript"],
           "database": str(tiny_db), "method": "dp", "mapping": MAPPING, "work_dir": str(folder / "work"),
           "strip_work_dir": str(folder / "work-strip"), "bad_audio": str(folder / "bad.wav"),
           "silent_video": str(folder / "silent.mp4"),
           "render": str(folder / "blender_face.png"), "render_key": "JawDrop", "result": str(folder / "result.json")}
    (folder / "job.json").write_text(json.dumps(job))
    env = dict(os.environ, BLENDER_USER_SCRIPTS=str(folder / "user" / "scripts"),
               BLENDER_USER_CONFIG=str(folder / "user" / "config"))
    proc = subprocess.run([BLENDER, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                           str(SCENE_SCRIPT), "--", str(folder / "job.json")],
                          capture_output=True, text=True, env=env, timeout=600)
    (folder / "blender.log").write_text(proc.stdout + proc.stderr)
    assert proc.returncode == 0 and (folder / "result.json").exists(), proc.stdout[-4000:] + proc.stderr[-4000:]


@pytest.fixture(scope="module")
def blender_run(built_once, tiny_db, tiny_corpus, held_out_take, held_out_synthesized) -> dict:
    """Blender's findings (blender_scene.py's result) and the job it ran: one Blender session per
    test session, shared by pytest-xdist's workers (tests/conftest.py's ``built_once``)."""
    folder = built_once("blender-addon", lambda d: run_blender(d, tiny_db, tiny_corpus, held_out_take,
                                                               held_out_synthesized))
    job = json.loads((folder / "job.json").read_text())
    found = json.loads((folder / "result.json").read_text())
    if os.environ.get("FACESYNTH_UPDATE_DOCS_IMAGES"):
        DOCS_IMAGE.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(found["render"]["path"], DOCS_IMAGE)
    return {"found": found, "job": job, "work": folder / "work", "names": job["rig_names"]}


def test_the_addon_is_enabled_from_the_zip(blender_run):
    found, job = blender_run["found"], blender_run["job"]
    assert tuple(int(p) for p in found["blender"].split()[0].split(".")[:2]) >= (3, 4)
    assert Path(found["addon_file"]).parent.name == "facesynth_blender"
    assert str(Path(job["zip"]).parent) not in found["addon_file"]  # installed into the user's add-ons
    assert found["animate"] == {"result": ["FINISHED"], "seconds": found["animate"]["seconds"]}, found["animate"]


def assert_keys_are_the_curves(keyed: dict, curves_path: Path, rig_names: list[str]) -> None:
    """Every shape key of the mesh is keyed with its ARKit weight from ``curves_path``, linearly
    resampled to the scene's 24 frames/s, at frames FRAME_START, FRAME_START + 1, ..."""
    curves = read_curves(curves_path)
    assert curves["fps"] != FPS
    index = {n: i for i, n in enumerate(curves["names"])}
    n = len(expected_arkit(curves, FPS)["jawOpen"])
    count = len(curves["weights"])
    src = np.clip(np.arange(n) / FPS * curves["fps"], 0, count - 1)
    lo = np.floor(src).astype(int)
    hi = np.minimum(lo + 1, count - 1)
    a = src - lo
    for ict in rig_names:
        name, sources = key_name(ict), key_sources(ict)
        if not sources:
            assert name not in keyed, f"{name} has no ARKit shape but was keyed"
            continue
        points = np.array(keyed[name])
        assert points[:, 0].tolist() == list(range(FRAME_START, FRAME_START + n)), name
        w = curves["weights"][:, [index[s] for s in sources]].mean(axis=1)
        want = np.clip((1 - a) * w[lo] + a * w[hi], 0, 1)
        np.testing.assert_allclose(points[:, 1], want, atol=2e-6, rtol=0, err_msg=name)
    assert np.ptp(np.array(keyed["JawDrop"])[:, 1]) > 0.05  # the mouth moves: the comparison is not of zeros
    assert len(keyed) == 53  # 55 rig shapes, less cheekRaiser_L/R


def test_keyframes_equal_the_solved_curves(blender_run):
    assert_keys_are_the_curves(blender_run["found"]["after"]["shape_keys"], blender_run["work"] / "curves.h5",
                               blender_run["names"])


def test_a_sound_strip_as_the_sound(blender_run):
    """From a sound strip: the keys start at the strip's start whatever the current frame, replace
    the first run's (neutral now: the panel's default emotions), and no strip is added."""
    found = blender_run["found"]
    assert found["from_strip"]["result"] == ["FINISHED"], found["from_strip"]
    work = Path(blender_run["job"]["strip_work_dir"])
    assert_keys_are_the_curves(found["after_strip"]["shape_keys"], work / "curves.h5", blender_run["names"])
    assert set(read_curves(work / "curves.h5")["emotion"]) == {"neutral"}
    assert found["after_strip"]["strips"] == found["after"]["strips"]
    assert found["after_strip"]["bone"] == found["after"]["bone"]  # no head bone named: its keys are kept


def test_head_bone_turns_as_the_solved_head(blender_run):
    """The head bone's posed rotation (armature space, relative to its rest) is the curves' head
    rotation, resampled by spherical interpolation, in Blender's axes (face toward -Y, +Z up)."""
    curves = read_curves(blender_run["work"] / "curves.h5")
    want = expected_head(curves, FPS)
    posed = blender_run["found"]["head"]
    assert sorted(int(f) for f in posed) == list(range(FRAME_START, FRAME_START + len(want)))
    got = np.array([posed[str(FRAME_START + i)] for i in range(len(want))])
    np.testing.assert_allclose(got, TO_BLENDER @ want @ TO_BLENDER.T, atol=2e-5, rtol=0)
    angles = np.arccos(np.clip((np.trace(want, axis1=1, axis2=2) - 1) / 2, -1, 1))
    assert angles.max() > 0.01  # a turned head: the axes are checked, not an identity


def test_sound_strip_at_the_start_frame(blender_run):
    strips = blender_run["found"]["after"]["strips"]
    assert [(s["type"], s["frame_start"], s["filepath"]) for s in strips] == [
        ("SOUND", FRAME_START, blender_run["job"]["audio"])]


def test_emotion_markers_become_spans(blender_run):
    spans = (blender_run["work"] / "emotions.txt").read_text().splitlines()
    assert [line.split() for line in spans if not line.startswith("#")] == [
        ["0.500000", "1.500000", "happy"], ["1.500000", "1001.500000", "sad"]]
    emotions = read_curves(blender_run["work"] / "curves.h5")["emotion"]
    assert emotions[0] == "neutral" and {"happy", "sad"} <= set(emotions)


@pytest.mark.parametrize("case, words", [
    ("missing_executable", ["facesynth executable", "no-such/facesynth", "does not exist", "preference"]),
    ("bad_audio", ["facesynth synthesize failed", "bad.wav"]),
    ("silent_video", ["facesynth synthesize failed", "silent.mp4: has no audio stream"]),
    ("no_shape_keys", ["mesh", "shape keys"]),
    ("no_arkit_names", ["none of the shape keys of 'Other' has an ARKit name", "mapping"]),
])
def test_failures_are_reported_in_one_sentence(blender_run, case, words):
    said = blender_run["found"]["failures"][case]
    assert set(said) == {"report", "seconds"}, said  # Blender's report (raised to a script), nothing else
    report = said["report"].strip()
    assert report.startswith("Error: ") and "\n" not in report and "Traceback" not in report, report
    assert all(w in report for w in words), report
    assert report.endswith(".")


def test_failures_key_nothing(blender_run):
    assert blender_run["found"]["after_failures"] == blender_run["found"]["after"]


def test_render_of_the_keyed_face(blender_run):
    shot = blender_run["found"]["render"]
    assert (shot["width"], shot["height"]) == (560, 340) and shot["std"] > 0.03, shot
    size = Path(shot["path"]).stat().st_size
    assert 5_000 < size < 200_000
    assert FRAME_START <= shot["frame"] < FRAME_START + 200
