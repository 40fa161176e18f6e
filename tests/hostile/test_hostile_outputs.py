"""Outputs that cannot be lost or torn, and inputs read once: races between writers, SIGINT and
SIGTERM during a write, stale temporaries of killed runs, folder outputs, output checks before
any work, ffmpeg arguments, the memory check and one open per input (some cases run the
command line in a subprocess, for real signals and real concurrency)."""

from __future__ import annotations

import multiprocessing
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base import limits
from facesynth.base.errors import ArtifactError, InputError, OutputExistsError
from facesynth.cli import main
from facesynth.domain.search.pairs import transition_costs
from facesynth.model import artifacts


def _run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def _one_error(result, status: int, *phrases: str) -> str:
    assert result.exit_code == status, result.output
    assert isinstance(result.exception, SystemExit), result.exception
    lines = [line for line in result.output.splitlines() if line.startswith(("error: ", "Error: "))]
    assert len(lines) == 1, result.output
    for phrase in phrases:
        assert phrase in lines[0], result.output
    return lines[0]


# --- no-clobber under races -------------------------------------------------------------

def _writer(path: str, text: str, barrier, results) -> None:
    try:
        with artifacts.atomic_path(Path(path)) as tmp:
            tmp.write_text(text)
            barrier.wait()  # both have checked the output and written their file: now both publish
        results.put((text, "won"))
    except OutputExistsError as exc:
        results.put((text, str(exc)))


def test_exactly_one_of_two_racing_writers_wins(tmp_path):
    ctx = multiprocessing.get_context("fork")
    barrier, results = ctx.Barrier(2), ctx.Queue()
    out = tmp_path / "out.h5"
    procs = [ctx.Process(target=_writer, args=(str(out), name, barrier, results)) for name in ("first", "second")]
    for p in procs:
        p.start()
    for p in procs:
        p.join(30)
    outcome = dict(results.get(timeout=5) for _ in procs)
    winners = [name for name, what in outcome.items() if what == "won"]
    assert len(winners) == 1, outcome
    loser = next(name for name in outcome if name not in winners)
    assert "another process wrote this output while this one ran" in outcome[loser]
    assert out.read_text() == winners[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.h5"]


def test_two_commands_racing_for_one_output(tiny_artifacts, tmp_path):
    out = tmp_path / "p.h5"
    cmd = [sys.executable, "-m", "facesynth.cli", "pca", str(tiny_artifacts["normalized"]), "-o", str(out), "-q"]
    procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    done = [p.communicate(timeout=120) + (p.returncode,) for p in procs]
    statuses = sorted(d[2] for d in done)
    assert statuses == [0, 1], done
    loser = next(d for d in done if d[2] == 1)
    assert "Traceback" not in loser[1] and loser[1].count("\n") == 1
    assert "output exists" in loser[1] or "another process wrote this output" in loser[1]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.h5"]


def test_overwrite_replaces(tmp_path):
    out = tmp_path / "o.txt"
    out.write_text("old")
    with artifacts.atomic_path(out, overwrite=True) as tmp:
        tmp.write_text("new")
    assert out.read_text() == "new" and sorted(p.name for p in tmp_path.iterdir()) == ["o.txt"]


# --- signals: temporary files removed, one line, 130 / 143 --------------------------------

_SLOW_WRITE = textwrap.dedent("""
    import sys, time
    from facesynth.model import artifacts
    publish = artifacts.publish
    def slow(tmp, path, overwrite):
        open(str(path) + ".ready", "w").close()  # the temporary file is complete: signal now
        time.sleep(60)
        publish(tmp, path, overwrite)
    artifacts.publish = slow
    from facesynth.cli import run
    sys.argv = ["facesynth"] + sys.argv[1:]
    run()
""")


@pytest.mark.parametrize("signum, status, phrase", [(signal.SIGTERM, 143, "terminated (SIGTERM); no output was written."),
                                                    (signal.SIGINT, 130, "interrupted; no output was written.")])
def test_signal_during_a_write_removes_the_temporary(tiny_artifacts, tmp_path, signum, status, phrase):
    out = tmp_path / "p.h5"
    proc = subprocess.Popen([sys.executable, "-c", _SLOW_WRITE, "pca", str(tiny_artifacts["normalized"]), "-o", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not Path(str(out) + ".ready").exists():
        assert proc.poll() is None and time.monotonic() < deadline, proc.communicate()
        time.sleep(0.05)
    assert any(".tmp-" in p.name for p in tmp_path.iterdir())
    proc.send_signal(signum)
    stdout, stderr = proc.communicate(timeout=30)
    assert proc.returncode == status, stderr
    assert stderr.strip().splitlines() == [phrase], stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.h5.ready"]


# The second output of a command is not published: a signal arrives just after the first is in place.
_SIGNAL_BETWEEN_OUTPUTS = textwrap.dedent("""
    import os, signal, sys
    from facesynth.model import artifacts
    publish = artifacts.publish
    def then_signal(tmp, path, overwrite):
        publish(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGTERM)
    artifacts.publish = then_signal
    from facesynth.cli import run
    sys.argv = ["facesynth"] + sys.argv[1:]
    run()
""")


def test_sigterm_between_the_artifact_and_its_contact_sheet_leaves_neither(tiny_db, tmp_path):
    (tmp_path / "keyshapes.h5").write_text("an older key-shapes file")
    proc = subprocess.run([sys.executable, "-c", _SIGNAL_BETWEEN_OUTPUTS, "keyshapes", str(tiny_db), "--method", "pca",
                           "--count", "2", "--set", "keyshapes.curve_frames=50", "--sheet", str(tmp_path / "sheet.png"),
                           "-o", str(tmp_path / "keyshapes.h5"), "--overwrite"], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 143, proc.stderr
    assert proc.stderr.strip().splitlines() == ["terminated (SIGTERM); no output was written."], proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keyshapes.h5"]
    assert (tmp_path / "keyshapes.h5").read_text() == "an older key-shapes file"  # the replaced file returned


@pytest.fixture(scope="module")
def retarget_inputs(tiny_db, tiny_artifacts, held_out_take, config, tmp_path_factory):
    """A held-out take of the tiny corpus and its key-shapes (2 per emotion, fitted on the rig)."""
    import dataclasses

    from facesynth.stages import capture, keyshapes

    d = tmp_path_factory.mktemp("retarget")
    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, d / "take.h5", config.settings("normalize"), 30.0)
    keyshapes.run(tiny_db, d / "ks.h5", dataclasses.replace(config.settings("keyshapes"), method="pca", count=2,
                                                            curve_frames=50))
    return d / "take.h5", d / "ks.h5"


def test_ctrl_c_between_the_curves_and_the_mesh_leaves_neither(retarget_inputs, tmp_path, monkeypatch):
    take, ks = retarget_inputs
    publish = artifacts.publish

    def then_interrupt(tmp, path, overwrite):
        publish(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGINT)

    monkeypatch.setattr(artifacts, "publish", then_interrupt)
    r = _run("retarget", take, "--keyshapes", ks, "--blend", "linear", "--mesh", tmp_path / "anim.h5",
             "-o", tmp_path / "curves.h5")
    assert r.exit_code == 130, r.output
    assert r.output.strip().splitlines() == ["interrupted; no output was written."], r.output
    assert list(tmp_path.iterdir()) == []
    monkeypatch.setattr(artifacts, "publish", publish)
    r = _run("retarget", take, "--keyshapes", ks, "--blend", "linear", "--mesh", tmp_path / "anim.h5",
             "-o", tmp_path / "curves.h5", "-q")
    assert r.exit_code == 0, r.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["anim.h5", "curves.h5"]


@pytest.fixture
def interrupt_after_first_publish(monkeypatch):
    """Ctrl-C just after the first output of a command is renamed into place."""
    publish, publish_folder = artifacts.publish, artifacts._publish_folder

    def then_interrupt(tmp, path, overwrite):
        publish(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGINT)

    def folder_then_interrupt(tmp, path, overwrite):
        old = publish_folder(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGINT)
        return old

    monkeypatch.setattr(artifacts, "publish", then_interrupt)
    monkeypatch.setattr(artifacts, "_publish_folder", folder_then_interrupt)


def test_ctrl_c_between_the_isomap_and_its_images_leaves_neither(tiny_db, tmp_path, interrupt_after_first_publish):
    r = _run("isomap", tiny_db, "-o", tmp_path / "isomap.h5", "--images", tmp_path / "maps")
    assert r.exit_code == 130, r.output
    assert r.output.strip().splitlines() == ["interrupted; no output was written."], r.output
    assert list(tmp_path.iterdir()) == []


def test_an_interrupt_after_the_output_is_written_says_so(tiny_artifacts, tmp_path, monkeypatch):
    from facesynth.stages import pca

    run = pca.run

    def then_interrupt(*args, **kwargs):
        run(*args, **kwargs)
        raise KeyboardInterrupt

    monkeypatch.setattr(pca, "run", then_interrupt)
    r = _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5")
    assert r.exit_code == 130, r.output
    assert r.output.strip().splitlines() == [f"interrupted; {tmp_path / 'p.h5'} was written before it (complete); "
                                             "nothing else was."], r.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.h5"]


# A test-like process: one command in-process (through click's CliRunner), then SIGTERM.
_IN_PROCESS_THEN_WAIT = textwrap.dedent("""
    import signal, sys, time
    from click.testing import CliRunner
    from facesynth.cli import main
    result = CliRunner().invoke(main, sys.argv[1:])
    assert result.exit_code == 0, result.output
    assert signal.getsignal(signal.SIGTERM) == signal.SIG_DFL, signal.getsignal(signal.SIGTERM)
    print("ready", flush=True)
    time.sleep(120)
    print("still running after SIGTERM", flush=True)
""")


# A test-like process whose in-process command (through click's CliRunner) is writing its output.
_IN_PROCESS_SLOW_WRITE = textwrap.dedent("""
    import sys, time
    from click.testing import CliRunner
    from facesynth.model import artifacts
    publish = artifacts.publish
    def slow(tmp, path, overwrite):
        open(str(path) + ".ready", "w").close()
        time.sleep(60)
        publish(tmp, path, overwrite)
    artifacts.publish = slow
    from facesynth.cli import main
    result = CliRunner().invoke(main, sys.argv[1:])
    print("the test process went on after SIGTERM:", result.exit_code, flush=True)
""")


def test_sigterm_during_an_in_process_command_stops_the_process_after_cleaning_up(tiny_artifacts, tmp_path):
    out = tmp_path / "p.h5"
    proc = subprocess.Popen([sys.executable, "-c", _IN_PROCESS_SLOW_WRITE, "pca", str(tiny_artifacts["normalized"]),
                             "-o", str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not Path(str(out) + ".ready").exists():
        assert proc.poll() is None and time.monotonic() < deadline, proc.communicate()
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    stdout, stderr = proc.communicate(timeout=30)
    assert proc.returncode == -signal.SIGTERM, (stdout, stderr)
    assert "went on" not in stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.h5.ready"]  # the temporary file was removed first


def test_a_process_that_ran_a_command_in_process_still_stops_on_sigterm(tiny_db, tiny_corpus, held_out_take, tmp_path):
    labels = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    proc = subprocess.Popen([sys.executable, "-c", _IN_PROCESS_THEN_WAIT, "synthesize", str(tiny_db), "--phonemes",
                             str(labels), "-o", str(tmp_path / "m.h5"), "-q"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout.readline().strip() == "ready", proc.communicate(timeout=60)
        proc.send_signal(signal.SIGTERM)
        stdout, stderr = proc.communicate(timeout=30)
    finally:
        proc.kill()
    assert proc.returncode == -signal.SIGTERM, (stdout, stderr)
    assert (tmp_path / "m.h5").exists()


def test_stale_temporaries_of_killed_runs_are_cleaned(tiny_artifacts, tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    stale = tmp_path / f"p.h5.tmp-{int(dead.stdout)}"
    stale.write_bytes(b"half a file")
    live = tmp_path / f"p.h5.tmp-{os.getpid() if os.getppid() == 0 else os.getppid()}"
    live.write_bytes(b"a live writer's file")
    assert _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "-q").exit_code == 0
    assert not stale.exists()
    assert live.exists()  # its process still runs


# --- outputs checked before work, folders renamed into place ------------------------------

def test_outputs_are_checked_before_any_work(tiny_artifacts, tmp_path, monkeypatch):
    from facesynth.stages import pca

    monkeypatch.setattr(pca, "run", lambda *a, **k: pytest.fail("the stage ran although its output is unwritable"))
    _one_error(_run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "missing" / "p.h5"), 1, "does not exist")
    (tmp_path / "p.h5").write_text("keep")
    _one_error(_run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5"), 1, "output exists")
    assert (tmp_path / "p.h5").read_text() == "keep"


def test_isomap_images_folder_is_not_clobbered(tiny_db, tmp_path):
    images = tmp_path / "maps"
    images.mkdir()
    (images / "mine.txt").write_text("keep")
    _one_error(_run("isomap", tiny_db, "-o", tmp_path / "i.h5", "--images", images), 1, "is not empty")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["maps"] and (images / "mine.txt").read_text() == "keep"
    r = _run("isomap", tiny_db, "-o", tmp_path / "i.h5", "--images", images, "--overwrite", "-q")
    assert r.exit_code == 0, r.output
    assert not (images / "mine.txt").exists() and (images / "index.html").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["i.h5", "maps"]


def test_failed_folder_output_leaves_nothing(tmp_path):
    with pytest.raises(RuntimeError):
        with artifacts.atomic_folder(tmp_path / "report", "the report") as folder:
            (folder / "half.html").write_text("...")
            raise RuntimeError("failed midway")
    assert list(tmp_path.iterdir()) == []


def test_render_output_named_like_an_option(tiny_corpus, held_out_take, tiny_db, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    labels = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    assert _run("synthesize", tiny_db, "--phonemes", labels, "-o", "m.h5", "-q").exit_code == 0
    assert _run("deform", "m.h5", "--mesh", tiny_corpus / "face.obj", "--binding", tiny_corpus / "markers.csv",
                "-o", "a.h5", "-q").exit_code == 0
    r = _run("render", "a.h5", "--audio", tiny_corpus / "audio" / f"{held_out_take}.wav", "-o", "-y.avi", "-q",
             "--set", "render.width=32", "--set", "render.height=32")
    assert r.exit_code == 0, r.output
    assert Path("-y.avi").stat().st_size > 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["-y.avi", "a.h5", "m.h5"]  # no audio left behind


# --- HDF5 that stays inside its file; bounds before reading -------------------------------

def _copy(src: Path, dst: Path) -> Path:
    dst.write_bytes(src.read_bytes())
    return dst


@pytest.mark.parametrize("how", ["external_link", "external_storage", "virtual"])
def test_artifacts_that_reach_outside_are_refused(tiny_artifacts, tmp_path, how):
    path = _copy(tiny_artifacts["pca"], tmp_path / "pca.h5")
    secret = tmp_path / "secret.bin"
    with h5py.File(path, "r+") as f:
        data = f["pca/mean"][()]
        secret.write_bytes(data.tobytes())
        attrs = dict(f["pca/mean"].attrs)
        del f["pca/mean"]
        if how == "external_link":
            with h5py.File(tmp_path / "other.h5", "w") as g:
                g["mean"] = data
            f["pca/mean"] = h5py.ExternalLink(str(tmp_path / "other.h5"), "/mean")
        elif how == "external_storage":
            d = f.create_dataset("pca/mean", shape=data.shape, dtype=data.dtype, external=[(str(secret), 0, data.nbytes)])
            d.attrs.update(attrs)
        else:
            with h5py.File(tmp_path / "other.h5", "w") as g:
                g["mean"] = data
            layout = h5py.VirtualLayout(shape=data.shape, dtype=data.dtype)
            layout[...] = h5py.VirtualSource(str(tmp_path / "other.h5"), "mean", shape=data.shape)
            f.create_virtual_dataset("pca/mean", layout).attrs.update(attrs)
    with pytest.raises(ArtifactError, match=r"pca\.h5: /pca/mean: .*an artifact must stay inside its file"):
        artifacts.open_artifact(path, "pca")


def test_compression_bomb_is_refused_before_reading(tiny_artifacts, tmp_path):
    path = _copy(tiny_artifacts["normalized"], tmp_path / "n.h5")
    with h5py.File(path, "r+") as f:
        attrs = dict(f["markers"].attrs)
        m = f["markers"].shape[1]
        del f["markers"]
        d = f.create_dataset("markers", shape=(50_000_000, m, 3), dtype="f4", chunks=(1024, m, 3), compression="gzip")
        d.attrs.update(attrs)
    assert path.stat().st_size < 50 << 20
    started = time.perf_counter()
    with pytest.raises(ArtifactError, match=r"n\.h5: /markers: .*above limits\.max_frames"):
        artifacts.open_artifact(path, "normalized")
    with limits.using(limits.defaults().__class__(**{**limits.defaults().__dict__, "max_frames": 10**9,
                                                     "max_dataset_mb": 1000.0})):
        with pytest.raises(ArtifactError, match=r"declares \d+ MB .* above limits\.max_dataset_mb = 1000 MB"):
            artifacts.open_artifact(path, "normalized")
    assert time.perf_counter() - started < 5


def test_negative_distances_in_the_transition_features_are_refused(tiny_db, tiny_corpus, held_out_take, tmp_path):
    db = _copy(tiny_db, tmp_path / "db.h5")
    with h5py.File(db, "r+") as f:
        f["transition/pivot_last_pos"][3, 0] = -2960.0
    r = _run("synthesize", db, "--phonemes", tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
             "-o", tmp_path / "m.h5", "--set", "synthesize.use_opencl=false")
    _one_error(r, 1, "db.h5: /transition/pivot_last_pos: holds -2960, below the smallest allowed value 0")
    assert not (tmp_path / "m.h5").exists()


def test_value_past_a_bound_names_the_setting(tiny_db, tmp_path):
    _one_error(_run("prune", tiny_db, "--remove", "0-99999999999", "-o", tmp_path / "p.h5"), 1,
               "do not exist; the database has nodes 0 to")
    _one_error(_run("synthesize", tiny_db, "--phonemes", _lab(tmp_path, "0 1000000000 aa\n"), "-o", tmp_path / "m.h5"),
               1, "above limits.max_phone_s", "--set limits.max_phone_s=")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["u.lab"]


def _lab(folder: Path, text: str) -> Path:
    (folder / "u.lab").write_text(text)
    return folder / "u.lab"


def test_memory_is_estimated_before_heavy_work(tiny_artifacts, tmp_path, monkeypatch):
    from facesynth.stages import build_db, synthesize

    assert 240e6 < synthesize.memory_estimate(5556, 63) < 260e6  # the paper's database, a 63-phone sentence
    monkeypatch.setattr(limits, "mem_available", lambda: 1000)
    with pytest.raises(InputError, match=r"db\.h5: the search needs about 251.2 MB of memory but 1.0 kB is available"):
        limits.require_memory(synthesize.memory_estimate(5556, 63), "the search", "db.h5")
    # reading itself is refused first here: the file's datasets alone do not fit
    _one_error(_run("build-db", tiny_artifacts["pca"], "-o", tmp_path / "db.h5"), 1, "pca.h5: /", "of memory is available")
    assert list(tmp_path.iterdir()) == []
    monkeypatch.setattr(limits, "mem_available", lambda: 100 << 20)
    monkeypatch.setattr(build_db, "build_nodes", lambda *a: type("Nodes", (), {"__len__": lambda self: 10_000})())
    _one_error(_run("build-db", tiny_artifacts["pca"], "-o", tmp_path / "db.h5"), 1,
               "pca.h5: the boundary states of 10000 motion nodes needs about 131.0 MB of memory but 104.9 MB is available")


# --- each input read once ---------------------------------------------------------------

def test_synthesize_opens_the_database_once(tiny_db, tiny_corpus, held_out_take, tmp_path, monkeypatch):
    from facesynth.model import motiondb

    opened = []
    real = artifacts.open_artifact

    def counting(path, kind):
        opened.append((Path(path).name, kind))
        return real(path, kind)

    monkeypatch.setattr(motiondb, "open_artifact", counting)
    r = _run("synthesize", tiny_db, "--phonemes", tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
             "-o", tmp_path / "m.h5", "-q", "--set", "synthesize.use_opencl=false")
    assert r.exit_code == 0, r.output
    assert opened == [(tiny_db.name, "motiondb")]


def test_a_database_replaced_while_synthesize_runs_is_not_mixed(tiny_db, tmp_path):
    db = _copy(tiny_db, tmp_path / "db.h5")
    from facesynth.base.config import Config
    from facesynth.model.motiondb import MotionDatabase

    d = MotionDatabase.read(db)
    replaced = tmp_path / "other.h5"
    with h5py.File(_copy(tiny_db, replaced), "r+") as f:
        f["boundary/first_pos"][...] = 1e6
    os.replace(replaced, db)  # another process replaces the file between the reads
    tc = transition_costs(d, Config.load().settings("synthesize")).dense()
    assert np.isfinite(tc).all() and tc.max() < 1e5  # still the validated snapshot's features
    with pytest.raises(InputError, match="was replaced while this command ran"):
        artifacts.input_record(db)


def test_a_file_of_the_same_name_in_another_folder_is_not_a_replacement(tiny_db, tmp_path, monkeypatch):
    """A database opened as ``db.h5`` from one folder and still open does not make another
    folder's ``db.h5`` look replaced (the record is of the file the name now means there)."""
    from facesynth.model.motiondb import MotionDatabase

    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    _copy(tiny_db, tmp_path / "a" / "db.h5")
    other = _copy(tiny_db, tmp_path / "b" / "db.h5")
    with h5py.File(other, "r+") as f:
        f.attrs["note"] = "another file"
    monkeypatch.chdir(tmp_path / "a")
    first = MotionDatabase.read(Path("db.h5"))  # kept open, as a caller's object keeps it
    monkeypatch.chdir(tmp_path / "b")
    second = MotionDatabase.read(Path("db.h5"))
    record = artifacts.input_record(Path("db.h5"))
    assert record["kind"] == "motiondb" and record["sha256"] == artifacts.sha256_of(other)
    del first, second
