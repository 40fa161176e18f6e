"""facesynth batch on a real Dask LocalCluster of two worker processes and the tiny corpus."""

import csv
import dataclasses
import hashlib
import importlib.util
import json
import subprocess
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

pytest.importorskip("distributed", reason="facesynth batch needs dask[distributed] (pip install 'dask[distributed]')")

from facesynth.cli import main  # noqa: E402
from facesynth.domain.batch.job import prepare  # noqa: E402
from facesynth.stages import batch  # noqa: E402


@pytest.fixture(scope="module")
def client():
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            Client(cluster) as c:
        yield c


@pytest.fixture(scope="module")
def takes(tiny_corpus):
    return {r["take"]: r for r in csv.DictReader(open(tiny_corpus / "manifest.csv"))}


def _settings(config, **batch_values):
    names = ("batch", "synthesize", "ingest", "align", "deform", "render")
    values = [config.settings(n) for n in names]
    values[0] = dataclasses.replace(values[0], **batch_values)
    return values


def _write(path, rows):
    with open(path, "w", newline="") as fh:
        csv.writer(fh).writerows(rows)
    return path


def test_lines_fail_alone_with_their_reason_and_a_rerun_skips_what_is_done(tiny_corpus, tiny_db, takes, config,
                                                                         client, tmp_path):
    a, b, c = (takes[t] for t in ("neutral_s001", "happy_s002", "sad_s003"))
    audio = lambda row: str(tiny_corpus / row["audio"])  # noqa: E731
    script = _write(tmp_path / "script.csv", [
        ("id", "audio", "text", "alignment", "emotion"),
        ("aligned", audio(a), a["transcript"], "", "happy"),
        ("given", audio(b), "", str(tiny_corpus / b["alignment"]), "sad"),
        ("no_audio", str(tmp_path / "missing.wav"), "hello", "", ""),
        ("empty", audio(c), "", "", ""),
        ("moody", audio(c), c["transcript"], "", "furious"),
        ("aligned", audio(c), c["transcript"], "", ""),
        ("partial", audio(c), c["transcript"].split()[0], "", ""),
        ("too_short", audio(c), " ".join([c["transcript"]] * 8), "", ""),
    ])
    out = tmp_path / "out"
    s = batch.run(script, tiny_db, out, *_settings(config), client=client)
    status = {(r.id, r.row): (r.status, r.reason) for r in s.results}
    assert (s.ok, s.failed, s.skipped) == (4, 4, 0)
    assert status[("aligned", 2)][0] == status[("given", 3)][0] == status[("empty", 5)][0] == "ok"
    # the one transcript-mismatch policy (as synthesize --audio): the motion is made, the mismatch is a warning
    assert status[("partial", 8)][0] == "ok"
    assert "missing.wav not found" in status[("no_audio", 4)][1]
    assert "unknown emotion 'furious'" in status[("moody", 6)][1]
    assert "id 'aligned' is already used by row 2" in status[("aligned", 7)][1]
    assert "too short for its text" in status[("too_short", 9)][1]
    for name in ("aligned.motion.h5", "aligned.TextGrid", "aligned.json", "given.motion.h5", "given.json",
                 "empty.motion.h5", "empty.TextGrid", "empty.json"):
        assert (out / name).exists(), name
    assert not (out / "given.TextGrid").exists() and (out / "partial.motion.h5").exists()
    # a line is synthesize with its audio: the given phones, and the mouth opening with the voice's loudness
    spans = _write(tmp_path / "sad.txt", [("0 1000 sad",)])
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tiny_corpus / b["alignment"]),
                                  "--audio", audio(b), "--emotions", str(spans), "-o", str(tmp_path / "given.h5"), "-q"])
    assert r.exit_code == 0, r.output
    from facesynth.model.motion import Motion

    np.testing.assert_array_equal(Motion.read(out / "given.motion.h5").markers, Motion.read(tmp_path / "given.h5").markers)
    summary = list(csv.DictReader(open(out / "summary.csv")))
    assert [r["id"] for r in summary] == ["aligned", "given", "no_audio", "empty", "moody", "aligned", "partial",
                                          "too_short"]
    assert summary[0]["method"] == "pocketsphinx" and summary[1]["method"] == "given" and int(summary[0]["phones"]) > 5
    # the line without text is recognised: words recognised then aligned, the words in the summary
    assert summary[3]["method"].startswith("words/") and summary[3]["recognized"] and not summary[0]["recognized"]
    assert json.loads((out / "empty.json").read_text())["result"]["recognized"] == summary[3]["recognized"]
    assert "the transcript may lack words" in summary[6]["warnings"]
    assert "furious" in (out / "summary.html").read_text()
    manifest = json.loads((out / "aligned.json").read_text())
    assert manifest["status"] == "ok" and len(manifest["inputs"]["audio"]) == 64

    before = (out / "aligned.motion.h5").stat().st_mtime_ns
    again = batch.run(script, tiny_db, out, *_settings(config), client=client)
    assert (again.ok, again.skipped, again.failed) == (0, 4, 4)
    assert next(r for r in again.results if r.id == "empty").recognized == summary[3]["recognized"]
    assert (out / "aligned.motion.h5").stat().st_mtime_ns == before

    changed = _write(tmp_path / "script.csv", [("id", "audio", "text", "emotion"),
                                               ("aligned", audio(a), a["transcript"], "angry")])
    third = batch.run(changed, tiny_db, out, *_settings(config), client=client)
    assert (third.ok, third.skipped) == (1, 0)
    assert json.loads((out / "aligned.json").read_text())["inputs"]["emotion"] == "angry"

    broken = _write(tmp_path / "script.csv", [("id", "audio", "text"), ("aligned", str(tmp_path / "gone.wav"), "x")])
    fourth = batch.run(broken, tiny_db, out, *_settings(config), client=client)
    assert fourth.failed == 1  # and the outputs of the earlier inputs are gone, not left looking current
    assert not any((out / f"aligned{suffix}").exists() for suffix in (".motion.h5", ".TextGrid", ".json"))


def test_anim_and_video_outputs(tiny_corpus, tiny_db, takes, config, client, tmp_path):
    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    settings = _settings(config, outputs=("anim", "avi"))
    settings[5] = dataclasses.replace(settings[5], width=64, height=48)
    s = batch.run(script, tiny_db, tmp_path / "out", *settings, mesh=tiny_corpus / "face.obj",
                  binding=tiny_corpus / "markers.csv", client=client)
    assert s.ok == 1, s.results[0].reason
    assert (tmp_path / "out" / "one.avi").stat().st_size > 0 and (tmp_path / "out" / "one.anim.h5").exists()
    assert not (tmp_path / "out" / "one.motion.h5").exists()
    assert not list((tmp_path / "out").glob("*.part-*")) and not list((tmp_path / "out").glob("*.tmp-*"))
    from facesynth.model.meshanim import MeshAnimation

    provenance = MeshAnimation.read(tmp_path / "out" / "one.anim.h5").provenance  # where each frame came from
    assert provenance.origin == "synthesis" and len(provenance.segments) > 3 and (provenance.node >= 0).any()


def test_command_exit_status_and_a_malformed_script(tiny_corpus, tiny_db, takes, tmp_path):
    bad = _write(tmp_path / "bad.csv", [("name", "audio"), ("x", "y.wav")])
    r = CliRunner().invoke(main, ["batch", str(bad), "--db", str(tiny_db), "-o", str(tmp_path / "o")])
    assert r.exit_code == 1 and r.output.count("\n") == 1 and "lacks the column(s) id;" in r.output
    assert not (tmp_path / "o").exists()
    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("ok", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"])),
                                         ("bad", str(tmp_path / "none.wav"), str(tiny_corpus / row["alignment"]))])
    r = CliRunner().invoke(main, ["batch", str(script), "--db", str(tiny_db), "-o", str(tmp_path / "o"),
                                  "--workers", "2"])
    assert r.exit_code == 1 and "1 of 2 lines failed (first: bad: audio file" in r.output
    assert "Traceback" not in r.output and (tmp_path / "o" / "ok.motion.h5").exists()
    again = CliRunner().invoke(main, ["batch", str(script), "--db", str(tiny_db), "-o", str(tmp_path / "o"),
                                      "--workers", "1"])  # a rerun into the same folder, as docs/pipeline.md does
    assert again.exit_code == 1 and "1 of 2 lines failed (first: bad: audio file" in again.output, again.output


def test_the_job_carries_the_limits_to_the_workers(tiny_corpus, tiny_db, takes, config, client, tmp_path):
    """--set limits.* reaches the worker processes: a line past a bound fails there, naming the setting."""
    from facesynth.base import limits

    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    tight = dataclasses.replace(config.settings("limits"), max_utterance_s=0.5)
    with limits.using(tight):
        s = batch.run(script, tiny_db, tmp_path / "out", *_settings(config), client=client)
    assert s.failed == 1 and "above limits.max_utterance_s = 0.5" in s.results[0].reason
    assert batch.run(script, tiny_db, tmp_path / "out2", *_settings(config), client=client).ok == 1


def test_a_line_checks_memory_matches_aliases_in_any_case_and_refuses_constraints_off_the_dp(
        tiny_corpus, tiny_db, takes, config, tmp_path, monkeypatch):
    """In the worker's code (run here in-process): the memory check of the shared core, emotion aliases
    matched case-insensitively (an alias written with capitals in the settings, asked in upper case),
    and constraints refused for a method that takes none."""
    from facesynth.base import limits
    from facesynth.domain.batch.line import run_line
    from facesynth.domain.batch.script import read_script

    row = takes["neutral_s001"]
    (tmp_path / "c.txt").write_text("1 0\n")
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment", "emotion", "constraints"),
                                         ("joy", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]),
                                          "JOY", ""),
                                         ("pinned", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]),
                                          "", str(tmp_path / "c.txt"))])
    values = _settings(config)
    values[2] = dataclasses.replace(values[2], emotion_aliases={"Joy": "happy"})
    joy, pinned = read_script(script)
    _, job = prepare(script, tiny_db, tmp_path / "out", *values)
    result = run_line(joy, job)
    assert result.status == "ok", result.reason
    from facesynth.model.motion import Motion

    assert set(Motion.read_search(tmp_path / "out" / "joy.motion.h5")[0].emotion) == {"happy"}

    _, mean_job = prepare(script, tiny_db, tmp_path / "mean", *values, method="mean")
    refused = run_line(pinned, mean_job)
    assert refused.status == "failed" and refused.reason == (
        "motion-node constraints need the DP search (Eq. 10); the mean method takes none: drop --constraints or use "
        "--method dp.")

    monkeypatch.setattr(limits, "mem_available", lambda: 1000)
    starved = run_line(joy, dataclasses.replace(job, redo=True))
    assert starved.status == "failed" and "of memory but 1.0 kB is available" in starved.reason
    assert "the search over" in starved.reason


def _validate_gltf(path):
    """The Khronos validator's report of ``path``, through the export tests' helper (which skips
    where node or the validator is missing)."""
    spec = importlib.util.spec_from_file_location("export_tests", Path(__file__).parents[1] / "exports" / "test_export.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module._validate(path)


def test_rig_outputs_from_one_solve_named_in_the_manifest(tiny_corpus, tiny_db, takes, config, client, tmp_path):
    """curves, arkit, gltf, usd and avi of one line: each written, each in the manifest with its
    sha256, the curves exactly those `facesynth solve` makes of the line's motion; a rerun skips the
    line, a new output asked redoes it."""
    import imageio_ffmpeg
    import numpy as np
    import soundfile as sf

    from facesynth.formats import livelink_face as livelink
    from facesynth.model.curves import RigCurves
    from facesynth.stages import solve

    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    kinds = ("motion", "curves", "arkit-csv", "gltf", "avi")
    settings = _settings(config, outputs=kinds)
    settings[5] = dataclasses.replace(settings[5], width=64, height=48)
    out = tmp_path / "out"
    s = batch.run(script, tiny_db, out, *settings, client=client)
    assert s.ok == 1, s.results[0].reason
    names = ["one.motion.h5", "one.curves.h5", "one.arkit.csv", "one.gltf", "one.wav", "one.avi"]
    _check_manifest(out, "one", names)

    solve.run(out / "one.motion.h5", tmp_path / "solved.h5", config.settings("solve"))
    mine, theirs = RigCurves.read(out / "one.curves.h5"), RigCurves.read(tmp_path / "solved.h5")
    assert mine.shape_names == theirs.shape_names and mine.rig_sha256 == theirs.rig_sha256
    assert np.array_equal(mine.weights, theirs.weights) and mine.weights.std() > 0.01
    assert np.array_equal(mine.head_rotation, theirs.head_rotation)
    n = mine.n_frames

    arkit = list(csv.reader(open(out / "one.arkit.csv")))
    assert arkit[0] == livelink.columns(arkit[0][2:54]) and len(arkit[0]) == 2 + 61
    assert len(arkit) - 1 == int(np.floor(n / mine.fps * config.settings("export").arkit_fps + 1e-6))

    assert (out / "one.wav").read_bytes() == (tiny_corpus / row["audio"]).read_bytes()
    doc = json.loads((out / "one.gltf").read_text())
    assert doc["animations"][0]["extras"]["audio"]["uri"] == "one.wav"
    assert len(doc["meshes"][0]["primitives"][0]["targets"]) == len(mine.shape_names)

    n_frames, _ = imageio_ffmpeg.count_frames_and_secs(str(out / "one.avi"))
    assert n_frames == n
    wav = tmp_path / "back.wav"
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-y", "-i", str(out / "one.avi"), str(wav)],
                   check=True)
    audio, rate = sf.read(wav)
    assert len(audio) / rate == pytest.approx(n / mine.fps, abs=1e-3) and np.abs(audio).max() > 0.01

    again = batch.run(script, tiny_db, out, *settings, client=client)
    assert (again.ok, again.skipped) == (0, 1)
    reordered = [dataclasses.replace(settings[0], outputs=tuple(reversed(kinds)))] + settings[1:]
    assert batch.run(script, tiny_db, out, *reordered, client=client).skipped == 1  # the same outputs asked
    report = _validate_gltf(out / "one.gltf")
    assert report["issues"]["numErrors"] == 0, report["issues"]

    pytest.importorskip("pxr", reason="usd-core is not installed (pip install 'facesynth[usd]')")
    from pxr import Usd, UsdSkel

    with_usd = [dataclasses.replace(settings[0], outputs=kinds + ("usd",))] + settings[1:]
    redone = batch.run(script, tiny_db, out, *with_usd, client=client)  # a new output asked: the line is redone
    assert (redone.ok, redone.skipped) == (1, 0), redone.results[0].reason
    _check_manifest(out, "one", names + ["one.usd"])
    stage = Usd.Stage.Open(str(out / "one.usd"))
    assert stage.GetEndTimeCode() == n - 1
    animation = next(p for p in stage.Traverse() if p.GetTypeName() == "SkelAnimation")
    weights = np.array(UsdSkel.Animation(animation).GetBlendShapeWeightsAttr().Get(10))
    assert np.allclose(weights, mine.weights[10], atol=1e-6)


def _check_manifest(out, line_id, names):
    """The line's manifest names exactly ``names``, each with its file's sha256; no temporary left."""
    manifest = json.loads((out / f"{line_id}.json").read_text())
    assert set(manifest["outputs"]) == set(names)
    for name in names:
        assert manifest["outputs"][name] == hashlib.sha256((out / name).read_bytes()).hexdigest(), name
    assert not list(out.glob("*.part-*")) and not list(out.glob("*.tmp-*"))


def test_a_line_without_usd_core_fails_alone_in_one_sentence(tiny_corpus, tiny_db, takes, config, tmp_path,
                                                              monkeypatch):
    from facesynth.domain.batch.line import run_line
    from facesynth.domain.batch.script import read_script
    from facesynth.formats import usd

    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    monkeypatch.setattr(usd, "available", lambda: False)
    _, job = prepare(script, tiny_db, tmp_path / "out", *_settings(config, outputs=("curves", "usd")))
    result = run_line(read_script(script)[0], job)
    assert result.status == "failed" and result.reason == (
        "usd export needs Pixar's usd-core, which is not installed; run `pip install 'facesynth[usd]'` "
        "(or `pip install usd-core`).")
    assert not list((tmp_path / "out").iterdir())


def test_the_command_renders_the_rig_without_a_mesh(tiny_corpus, tiny_db, takes, tmp_path):
    import imageio_ffmpeg

    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    out = tmp_path / "o"
    r = CliRunner().invoke(main, ["batch", str(script), "--db", str(tiny_db), "-o", str(out), "--outputs", "curves,avi",
                                  "--workers", "1", "--set", "render.width=64", "--set", "render.height=48"])
    assert r.exit_code == 0, r.output
    from facesynth.model.curves import RigCurves

    n = RigCurves.read(out / "one.curves.h5").n_frames
    assert imageio_ffmpeg.count_frames_and_secs(str(out / "one.avi"))[0] == n
    assert not (out / "one.motion.h5").exists()
    r = CliRunner().invoke(main, ["batch", str(script), "--db", str(tiny_db), "-o", str(tmp_path / "p"),
                                  "--outputs", "anim"])
    assert r.exit_code == 2 and "the anim output needs --mesh and --binding" in r.output


def test_a_user_s_rig_takes_the_rig_outputs(tiny_corpus, tiny_db, takes, config, tmp_path):
    """--rig FOLDER --rig-binding CSV: the line solves onto that rig (its ARKit-named shapes drive
    the ARKit CSV by name, the others none), and the video poses it; a user's rig without its
    binding, or without one ARKit-named shape for the arkit output, is refused before any work."""
    import imageio_ffmpeg
    import numpy as np

    from facesynth.base.errors import InputError, UsageError
    from facesynth.domain.batch.line import run_line
    from facesynth.domain.batch.script import read_script
    from facesynth.domain.rig.face import load_face_rig
    from facesynth.domain.rig.loading import builtin_rig
    from facesynth.formats.mesh import write_obj
    from facesynth.model.curves import RigCurves

    builtin = load_face_rig()
    folder = tmp_path / "myrig"
    folder.mkdir()
    write_obj(folder / "neutral.obj", builtin.neutral, builtin.faces)
    for name, shape in (("jawOpen", "jawOpen"), ("mouthFunnel", "mouthFunnel"), ("wrinkle", "cheekRaiser_L")):
        write_obj(folder / f"{name}.obj", builtin.neutral + builtin.deltas[builtin.shape_index(shape)], builtin.faces)
    binding = _write(tmp_path / "binding.csv", [("marker", "vertex")] + sorted(builtin_rig().binding.items()))
    row = takes["neutral_s001"]
    script = _write(tmp_path / "s.csv", [("id", "audio", "alignment"),
                                         ("one", str(tiny_corpus / row["audio"]), str(tiny_corpus / row["alignment"]))])
    values = _settings(config, outputs=("curves", "arkit-csv", "gltf", "avi"))
    values[5] = dataclasses.replace(values[5], width=64, height=48)
    _, job = prepare(script, tiny_db, tmp_path / "out", *values, rig=folder, rig_binding=binding)
    result = run_line(read_script(script)[0], job)
    assert result.status == "ok", result.reason
    curves = RigCurves.read(tmp_path / "out" / "one.curves.h5")
    assert curves.rig_name == "myrig" and curves.shape_names == ["jawOpen", "mouthFunnel", "wrinkle"]
    assert curves.weights[:, 0].max() > 0.05  # the jaw opens in speech
    table = list(csv.DictReader(open(tmp_path / "out" / "one.arkit.csv")))
    assert max(float(r["JawOpen"]) for r in table) > 0.05 and all(float(r["EyeBlinkLeft"]) == 0 for r in table)
    assert imageio_ffmpeg.count_frames_and_secs(str(tmp_path / "out" / "one.avi"))[0] == curves.n_frames
    assert np.isfinite(curves.weights).all()

    assert prepare(script, tiny_db, tmp_path / "o1", *values, rig=Path("builtin"))[1].rig is None
    with pytest.raises(UsageError, match="a user's rig needs --rig-binding"):
        prepare(script, tiny_db, tmp_path / "o2", *values, rig=folder)
    for p in folder.glob("*.obj"):
        if p.stem != "neutral":
            p.rename(p.with_name(f"shape_{p.name}"))
    with pytest.raises(InputError, match="none of the shapes of rig 'myrig' has an ARKit name"):
        prepare(script, tiny_db, tmp_path / "o3", *values, rig=folder, rig_binding=binding)


def test_the_old_name_of_an_output_still_works_with_a_warning():
    from facesynth.domain.batch.line import output_names

    names, warnings = output_names(("motion", "arkit", "arkit-csv"))
    assert names == ("motion", "arkit-csv")
    assert len(warnings) == 1 and "'arkit' is now called 'arkit-csv'" in warnings[0]
    assert output_names(("curves", "gltf")) == (("curves", "gltf"), [])


def test_lines_of_coded_speech_give_the_wavs_motion(tiny_corpus, tiny_db, takes, held_out_take, coded_speech, config,
                                                    client, tmp_path):
    """A script whose lines are the held-out sentence as the WAV, M4A, MP3, Opus, Ogg and an MP4
    (aligned to its text): every line the WAV's phones (boundaries within 50 ms) and motion
    (``coded_audio.same_motion``, as ``synthesize``); the M4A line's glTF
    has a real WAV beside it, decoded (not the M4A's bytes under a .wav name); a line whose
    audio is a silent video fails alone, in one sentence."""
    import h5py
    import numpy as np
    import soundfile as sf
    from coded_audio import COMPRESSED, correlation, same_motion

    text = takes[held_out_take]["transcript"]
    names = ["wav"] + [n for n in COMPRESSED if n in coded_speech]
    script = _write(tmp_path / "s.csv", [("id", "audio", "text")] + [(n, str(coded_speech[n]), text) for n in names]
                    + [("silent", str(coded_speech["silent"]), text)])
    settings = _settings(config, outputs=("motion",))
    s = batch.run(script, tiny_db, tmp_path / "out", *settings, client=client)
    failed = {r.id: r.reason for r in s.results if r.reason}
    assert s.ok == len(names) and list(failed) == ["silent"]
    assert failed["silent"].startswith(f"{coded_speech['silent']}: has no audio stream")
    got = {}
    for n in names:
        with h5py.File(tmp_path / "out" / f"{n}.motion.h5") as f:
            got[n] = ([p.decode() for p in f["path/phone"][()]], f["path/start"][()], f["markers"][()])
    for n in names[1:]:
        assert got[n][0] == got["wav"][0] and np.abs(got[n][1] - got["wav"][1]).max() <= 0.05, n
        assert correlation(got["wav"][2], got[n][2]) > same_motion(n), n
    if "m4a" in coded_speech:
        s = batch.run(_write(tmp_path / "g.csv", [("id", "audio", "text"), ("g", str(coded_speech["m4a"]), text)]),
                      tiny_db, tmp_path / "gl", *_settings(config, outputs=("gltf",)), client=client)
        assert s.ok == 1, s.results[0].reason
        sound, rate = sf.read(tmp_path / "gl" / "g.wav")
        assert sf.info(tmp_path / "gl" / "g.wav").format == "WAV" and rate == 16000
        assert abs(len(sound) - sf.info(coded_speech["wav"]).frames) <= 16


@pytest.mark.skipif(importlib.util.find_spec("gruut_lang_fr") is None,
                    reason="gruut's French pack is not installed (pip install 'facesynth[languages]')")
def test_a_language_column_reads_each_line_in_its_language(tiny_corpus, tiny_db, takes, config, client, tmp_path):
    from facesynth.formats.labels import read_textgrid

    a = takes["neutral_s001"]
    audio = str(tiny_corpus / a["audio"])
    script = _write(tmp_path / "script.csv", [
        ("id", "audio", "text", "language"),
        ("french", audio, "Papa boit une pomme.", "fr"),
        ("english", audio, a["transcript"], ""),
        ("klingon", audio, "Qapla'", "tlh"),
    ])
    out = tmp_path / "out"
    s = batch.run(script, tiny_db, out, *_settings(config), client=client)
    status = {r.id: (r.status, r.reason) for r in s.results}
    assert status["french"][0] == status["english"][0] == "ok"
    assert status["klingon"][0] == "failed" and "language 'tlh': no G2P backend reads it" in status["klingon"][1]
    words = [w.label for w in read_textgrid(out / "french.TextGrid")["words"]]
    assert words == ["Papa", "boit", "une", "pomme"]
    english = [w.label for w in read_textgrid(out / "english.TextGrid")["words"]]
    assert english == a["transcript"].lower().split()
