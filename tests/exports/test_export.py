"""``facesynth export`` as a user runs it: every format written from the artifacts that can carry
it and read back by the library another tool would use (the Live Link Face columns of the real
iPhone capture, pygltflib and the Khronos validator, usd-core, facesynth's own C3D reader, OBJ),
and the refusals of what a format cannot carry."""

import csv
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from coded_audio import COMPRESSED, coded

from facesynth.cli import main
from facesynth.domain.corpus.generate import CAPTURE_FPS
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, gaze_from_rig_weights, load_face_rig
from facesynth.formats import livelink_face as livelink
from facesynth.formats.mesh import read_mesh
from facesynth.formats.mocap import read_c3d
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion

ROOT = Path(__file__).resolve().parents[2]
VALIDATOR = Path(os.environ.get("FACESYNTH_GLTF_VALIDATOR", ROOT / ".cache" / "npm" / "node_modules" / "gltf-validator"))
NODE = shutil.which("node")
TIMECODE = re.compile(r"^\d\d:\d\d:[0-5]\d:\d\d\.\d{3}$")


def write_truth_curves(truth_csv: Path, out: Path) -> RigCurves:
    """The true rig weights, emotion and head motion of a sample-corpus take as a curves artifact."""
    t = read_truth(truth_csv)
    head = np.loadtxt(str(truth_csv).replace("_truth.csv", "_head.csv"), delimiter=",", skiprows=1, ndmin=2)
    c = RigCurves(t.rig_weights, CAPTURE_FPS, list(t.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(), "truth",
                  head[:, :9].reshape(-1, 3, 3), head[:, 9:], t.emotion, t.intensity)
    c.write(out, config="{}", inputs=[])
    return c


@pytest.fixture(scope="module")
def made(held_out_synthesized, tiny_corpus, held_out_take, tmp_path_factory):
    """A synthesized motion, its mesh animation and the held-out take's true curves."""
    d = tmp_path_factory.mktemp("export")
    write_truth_curves(tiny_corpus / "groundtruth" / f"{held_out_take}_truth.csv", d / "c.h5")
    return {"motion": held_out_synthesized["motion"], "anim": held_out_synthesized["anim"], "curves": d / "c.h5",
            "audio": held_out_synthesized["audio"], "mesh": tiny_corpus / "face.obj"}


def fs(*args):
    r = CliRunner().invoke(main, [str(a) for a in args], prog_name="facesynth")
    return r


def ok(*args):
    r = fs(*args)
    assert r.exit_code == 0, r.output
    return r


def refused(*args, says: str):
    r = fs(*args)
    assert r.exit_code == 1, r.output
    lines = [line for line in r.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: ") and says in lines[0], r.output
    assert "Traceback" not in r.output
    return lines[0]


# --- Live Link Face CSV ------------------------------------------------------------------------

def test_arkit_csv_has_the_iphone_apps_columns_and_timecode(made, tmp_path, shared_assets):
    out = tmp_path / "take.csv"
    ok("export", made["curves"], "--format", "arkit-csv", "-o", out)
    rows = list(csv.reader(open(out, newline="")))
    rig = load_face_rig()
    capture = shared_assets / "ict-face" / "llf_capture.csv"
    if capture.exists():  # the real app's file, column for column
        assert rows[0] == next(csv.reader(open(capture, newline="")))
    assert rows[0] == livelink.columns(rig.arkit_names) and len(rows[0]) == 63
    c = RigCurves.read(made["curves"])
    n = int(np.floor(c.n_frames / c.fps * 60 + 1e-6))
    assert len(rows) - 1 == n  # 60 frames/s by default
    frames = []
    for r in rows[1:]:
        assert TIMECODE.match(r[0]) and r[1] == "61" and len(r) == 63
        hh, mm, ss, ff = r[0].split(".")[0].split(":")
        frames.append(((int(hh) * 60 + int(mm)) * 60 + int(ss)) * 60 + int(ff))
    assert frames == list(range(n))  # FF counts 0..59 within each second
    values = np.array([[float(v) for v in r[2:]] for r in rows[1:]])
    # frame i of the CSV is frame 2i of the 120 frames/s curves
    assert np.abs(values[:, :52] - rig.to_arkit(c.weights[::2][:n])).max() < 1e-6
    gaze = gaze_from_rig_weights(c.weights[::2][:n], rig.shape_names)
    assert np.abs(values[:, 55:] - livelink.eye_angles(gaze)).max() < 1e-6
    assert (values[:, 52:55] == 0).all()  # head only with --head-motion

    ok("export", made["curves"], "--format", "arkit-csv", "--fps", "30", "-o", tmp_path / "30.csv")
    rows30 = list(csv.reader(open(tmp_path / "30.csv", newline="")))
    assert len(rows30) - 1 == int(np.floor(c.n_frames / c.fps * 30 + 1e-6))
    assert [r[0] for r in rows30[1:4]] == ["00:00:00:00.000", "00:00:00:01.000", "00:00:00:02.000"]


def test_arkit_eye_columns_follow_the_real_captures_convention(shared_assets):
    """The app's eye rotations are mirrored: exported from the capture's own eyeLook weights,
    they come back within 0.02 rad (eye roll, which no blendshape carries, within that too)."""
    capture = shared_assets / "ict-face" / "llf_capture.csv"
    if not capture.exists():
        pytest.skip("the shared ict-face assets (llf_capture.csv) are not here")
    rows = list(csv.reader(open(capture, newline="")))
    v = np.array([[float(x) for x in r[2:]] for r in rows[1:]])
    rig = load_face_rig()
    eyes = livelink.eye_angles(gaze_from_rig_weights(rig.from_arkit(v[:, :52]), rig.shape_names))
    err = np.abs(eyes - v[:, 55:]).max(axis=0)
    assert err[[0, 1, 3, 4]].max() < 0.005 and err.max() < 0.02
    swapped = eyes[:, [3, 4, 5, 0, 1, 2]]  # the other convention is plainly worse
    assert np.abs(swapped - v[:, 55:]).max(axis=0)[[0, 3]].min() > 0.05


def test_arkit_head_columns_are_the_mirrored_head_rotation():
    from scipy.spatial.transform import Rotation

    r = Rotation.from_euler("YXZ", [[0.2, 0.1, -0.05]]).as_matrix()  # about +y, then +x, then +z
    assert livelink.head_angles(r)[0] == pytest.approx([-0.2, 0.1, 0.05])
    assert livelink.timecode(61, 60.0) == "00:00:01:01.000" and livelink.timecode(3600 * 60, 60.0) == "01:00:00:00.000"
    # at 23.976 frames/s the 25th frame falls just after the second: a sub-frame into it
    assert livelink.timecode(24, 24000 / 1001) == "00:00:01:00.024"


def test_arkit_csv_head_motion(made, tmp_path):
    out = tmp_path / "head.csv"
    ok("export", made["curves"], "--format", "arkit-csv", "--head-motion", "--fps", "120", "-o", out)
    rows = list(csv.reader(open(out, newline="")))
    values = np.array([[float(v) for v in r[2:]] for r in rows[1:]])
    c = RigCurves.read(made["curves"])
    assert np.abs(values[:, 52:55] - livelink.head_angles(c.head_rotation)).max() < 1e-6
    assert np.abs(values[:, 52:55]).max() > 1e-3  # the take's head moves


# --- glTF --------------------------------------------------------------------------------------

def _accessor(gltf, index: int, data: bytes) -> np.ndarray:
    a = gltf.accessors[index]
    v = gltf.bufferViews[a.bufferView]
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a.type]
    dtype = {5126: np.float32, 5125: np.uint32}[a.componentType]
    return np.frombuffer(data, dtype, a.count * width, v.byteOffset + (a.byteOffset or 0)).reshape(a.count, width)


def _validate(path: Path) -> dict:
    if NODE is None:
        pytest.skip("node is not installed (Debian package 'nodejs'); the glTF validator needs it")
    if not VALIDATOR.is_dir():
        pytest.skip("the Khronos glTF validator is not installed: `npm install --prefix .cache/npm gltf-validator` "
                    "(or set FACESYNTH_GLTF_VALIDATOR)")
    done = subprocess.run([NODE, str(Path(__file__).with_name("validate_gltf.js")), str(VALIDATOR), str(path)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout)


@pytest.mark.parametrize("fmt", ["glb", "gltf"])
def test_gltf_round_trip_and_validator(made, tmp_path, fmt):
    import pygltflib

    out = tmp_path / f"face.{fmt}"
    ok("export", made["curves"], "--format", fmt, "--head-motion", "--audio", made["audio"], "-o", out)
    wav = tmp_path / "face.wav"
    assert wav.read_bytes() == made["audio"].read_bytes()

    g = pygltflib.GLTF2().load(str(out))
    data = g.binary_blob() if fmt == "glb" else g.get_data_from_buffer_uri(g.buffers[0].uri)
    rig, c = load_face_rig(), RigCurves.read(made["curves"])
    prim = g.meshes[0].primitives[0]
    assert np.abs(_accessor(g, prim.attributes.POSITION, data) - rig.neutral * 1e-3).max() < 1e-6  # mm -> m
    assert np.array_equal(_accessor(g, prim.indices, data).reshape(-1, 3), rig.faces)
    assert g.meshes[0].extras["targetNames"] == list(rig.shape_names) and len(prim.targets) == 55
    k = rig.shape_index("jawOpen")
    assert np.abs(_accessor(g, prim.targets[k]["POSITION"], data) - rig.deltas[k] * 1e-3).max() < 1e-6
    anim = g.animations[0]
    times = _accessor(g, anim.samplers[0].input, data)[:, 0]
    assert len(times) == c.n_frames and times == pytest.approx(np.arange(c.n_frames) / c.fps, abs=1e-6)
    weights = _accessor(g, anim.samplers[0].output, data).reshape(c.n_frames, 55)
    assert np.abs(weights - c.weights).max() < 1e-7
    assert {ch.target.path for ch in anim.channels} == {"weights", "translation", "rotation"}
    assert anim.extras["audio"]["uri"] == "face.wav"

    report = _validate(out)
    assert report["issues"]["numErrors"] == 0, report["issues"]["messages"][:5]
    assert report["issues"]["numWarnings"] == 0, report["issues"]["messages"][:5]


# --- USD ---------------------------------------------------------------------------------------

def test_usd_blendshapes_from_curves(made, tmp_path):
    pytest.importorskip("pxr", reason="usd-core is not installed (pip install 'facesynth[usd]')")
    from pxr import Usd, UsdGeom, UsdSkel

    out = tmp_path / "face.usd"
    ok("export", made["curves"], "--format", "usd", "-o", out)
    c = RigCurves.read(made["curves"])
    stage = Usd.Stage.Open(str(out))
    assert stage.GetTimeCodesPerSecond() == c.fps
    assert stage.GetEndTimeCode() - stage.GetStartTimeCode() + 1 == c.n_frames
    assert UsdGeom.GetStageMetersPerUnit(stage) == pytest.approx(0.001) and UsdGeom.GetStageUpAxis(stage) == "Y"
    root = UsdSkel.Root(stage.GetPrimAtPath("/Face"))
    cache = UsdSkel.Cache()
    cache.Populate(root, Usd.PrimDefaultPredicate)
    [binding] = cache.ComputeSkelBindings(root, Usd.PrimDefaultPredicate)
    query = cache.GetSkelQuery(binding.GetSkeleton()).GetAnimQuery()
    rig = load_face_rig()
    assert list(query.GetBlendShapeOrder()) == list(rig.shape_names)
    for frame in (0, c.n_frames // 2, c.n_frames - 1):
        assert np.abs(np.array(query.ComputeBlendShapeWeights(frame)) - c.weights[frame]).max() < 1e-7


def test_usda_time_sampled_points_from_mesh_animation(made, tmp_path):
    pytest.importorskip("pxr", reason="usd-core is not installed (pip install 'facesynth[usd]')")
    from pxr import Usd, UsdGeom

    out = tmp_path / "anim.usda"
    ok("export", made["anim"], "--format", "usda", "-o", out)
    a = MeshAnimation.read(made["anim"])
    stage = Usd.Stage.Open(str(out))
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Face/Mesh"))
    samples = mesh.GetPointsAttr().GetTimeSamples()
    assert len(samples) == len(a.vertices) and stage.GetTimeCodesPerSecond() == a.fps
    assert stage.GetEndTimeCode() - stage.GetStartTimeCode() + 1 == len(a.vertices)
    k = len(a.vertices) // 2
    assert np.abs(np.array(mesh.GetPointsAttr().Get(k)) - a.vertices[k]).max() < 1e-4
    assert np.array_equal(np.array(mesh.GetFaceVertexIndicesAttr().Get()).reshape(-1, 3), a.faces)


# --- C3D and OBJ sequences -----------------------------------------------------------------------

def test_c3d_round_trips_through_facesynths_reader(made, tmp_path):
    out = tmp_path / "m.c3d"
    ok("export", made["motion"], "--format", "c3d", "-o", out)
    m = Motion.read(made["motion"])
    take = read_c3d(out)
    assert take.names == list(m.marker_names) and take.fps == pytest.approx(m.fps)
    assert np.nanmax(np.abs(take.positions - m.markers)) < 0.1  # mm

    ok("export", made["motion"], "--format", "c3d", "--head-motion", "-o", tmp_path / "head.c3d")
    moved = read_c3d(tmp_path / "head.c3d").positions
    want = np.einsum("tij,tmj->tmi", m.head_rotation, m.markers) + m.head_translation[:, None]
    assert np.nanmax(np.abs(moved - want)) < 0.1


def test_obj_sequence_one_file_per_frame(made, tmp_path):
    out = tmp_path / "seq"
    r = ok("export", made["anim"], "--format", "obj-seq", "-o", out)
    a = MeshAnimation.read(made["anim"])
    files = sorted(out.iterdir())
    assert [f.name for f in files] == [f"frame_{i + 1:06d}.obj" for i in range(len(a.vertices))]
    assert not [p for p in tmp_path.iterdir() if ".tmp-" in p.name]  # renamed into place
    for k in (0, len(files) - 1):
        v, f = read_mesh(files[k])
        assert np.abs(v - a.vertices[k]).max() < 1e-4 and np.array_equal(f, a.faces)
    assert "obj-seq" in r.output or "files" in r.output
    refused("export", made["anim"], "--format", "obj-seq", "-o", out, says="--overwrite")
    ok("export", made["anim"], "--format", "obj-seq", "--overwrite", "-o", out)


# --- what a format cannot carry, and other bad input -----------------------------------------------

def test_formats_that_cannot_carry_the_artifact_say_what_to_run(made, tmp_path):
    out = tmp_path / "x.out"
    refused("export", made["motion"], "--format", "arkit-csv", "-o", out, says="facesynth solve")
    refused("export", made["anim"], "--format", "gltf", "-o", out, says="facesynth solve")
    refused("export", made["motion"], "--format", "usd", "-o", out, says="facesynth deform")
    refused("export", made["curves"], "--format", "c3d", "-o", out, says="export the motion")
    refused("export", made["anim"], "--format", "usda", "--head-motion", "-o", out, says="without --head-motion")
    refused("export", made["audio"], "--format", "c3d", "-o", out, says="facesynth synthesize")
    assert list(tmp_path.iterdir()) == []


def test_existing_output_needs_overwrite(made, tmp_path):
    out = tmp_path / "take.csv"
    out.write_text("mine\n")
    refused("export", made["curves"], "--format", "arkit-csv", "-o", out, says="--overwrite")
    assert out.read_text() == "mine\n"
    wav = tmp_path / "face.wav"
    wav.write_text("mine")
    refused("export", made["curves"], "--format", "glb", "--audio", made["audio"], "-o", tmp_path / "face.glb",
            says="--overwrite")
    assert not (tmp_path / "face.glb").exists() and wav.read_text() == "mine"


def test_mesh_with_another_vertex_count_is_refused(made, tmp_path):
    small = tmp_path / "small.obj"
    v, f = read_mesh(made["mesh"])
    keep = f[(f < len(v) - 10).all(axis=1)]
    from facesynth.formats.mesh import write_obj

    write_obj(small, v[:-10], keep)
    out = tmp_path / "seq"
    line = refused("export", made["anim"], "--format", "obj-seq", "--mesh", small, "-o", out, says="vertices")
    assert str(small) in line and not out.exists()
    # the mesh the animation was made on is accepted
    ok("export", made["anim"], "--format", "obj-seq", "--mesh", made["mesh"], "-o", out)


def test_ctrl_c_between_the_scene_and_its_audio_leaves_neither(made, tmp_path, monkeypatch):
    import signal

    from facesynth.model import artifacts

    publish = artifacts.publish

    def then_interrupt(tmp, path, overwrite):
        publish(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGINT)

    monkeypatch.setattr(artifacts, "publish", then_interrupt)
    r = fs("export", made["curves"], "--format", "glb", "--audio", made["audio"], "-o", tmp_path / "face.glb")
    assert r.exit_code == 130, r.output
    assert r.output.strip().splitlines() == ["interrupted; no output was written."], r.output
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", COMPRESSED)
def test_gltf_audio_from_coded_speech_is_a_wav_of_its_sound(made, coded_speech, tmp_path, name, monkeypatch):
    """``export --audio`` with the sentence as M4A, MP3, Opus, Ogg or an MP4: the file beside the
    glTF is a 16-bit WAV of the decoded sound (not the file's bytes under a .wav name), at the
    file's own rate, the WAV's sound within the codec's error (r > 0.99 at 16 kHz), decoded once."""
    import soundfile as sf

    from facesynth.formats import audio
    from facesynth.formats.audio import read_audio, resample

    decodes = []
    real_decode = audio._read_ffmpeg
    monkeypatch.setattr(audio, "_read_ffmpeg", lambda path: decodes.append(path) or real_decode(path))
    out = tmp_path / "face.glb"
    ok("export", made["curves"], "--format", "glb", "--audio", coded(coded_speech, name), "-o", out)
    assert len(decodes) == 1
    info = sf.info(tmp_path / "face.wav")
    assert (info.format, info.subtype, info.channels) == ("WAV", "PCM_16", 1)
    got, rate = read_audio(tmp_path / "face.wav")
    wav, wav_rate = read_audio(coded_speech["wav"])
    got = resample(got, rate, wav_rate)
    assert abs(len(got) - len(wav)) <= 16 and np.corrcoef(got[:len(wav)], wav[:len(got)])[0, 1] > 0.99


@pytest.mark.parametrize("bad, says", [("silent", "has no audio stream"), ("notes", "unreadable audio")])
def test_gltf_audio_without_sound_is_refused_before_anything_is_written(made, coded_speech, tmp_path, bad, says):
    refused("export", made["curves"], "--format", "gltf", "--audio", coded_speech[bad], "-o", tmp_path / "face.gltf",
            says=f"{coded_speech[bad]}: {says}")
    assert list(tmp_path.iterdir()) == []
