"""Shared fixtures: the tiny sample corpus and the artifacts built from it, made once per session
(once for all the session's pytest-xdist workers: see :func:`_built_once`)."""

from __future__ import annotations

import dataclasses
import functools
import os
import shutil
import signal
import threading
from collections.abc import Callable
from pathlib import Path

import pytest
import threadpoolctl
from filelock import FileLock

from facesynth.base.config import Config

SHARED_ASSETS = Path(__file__).resolve().parents[2] / "shared" / "assets"

# One BLAS thread per test process. `make test` runs one pytest-xdist worker per core, and every
# worker's OpenBLAS would start a thread per core on top: OpenBLAS's threads spin while they wait
# for work, so the oversubscribed cores ran two concurrent `facesynth evaluate`s 3.5 times slower
# (37 s against 10.5 s on two cores). The environment reaches the commands the tests start; the
# limit reaches this process's BLAS, already loaded by the plugins' imports.
for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")
threadpoolctl.threadpool_limits(1)


@functools.lru_cache(maxsize=1)
def _opencl_probes():
    from facesynth.base import opencl

    return [opencl.probe(d) for d in opencl.candidate_order(opencl.list_devices())]


def pytest_report_header(config):
    """Which OpenCL devices the OpenCL-versus-reference tests run on, and what the rest uses."""
    from facesynth.base import opencl

    probes = _opencl_probes()
    lines = [f"OpenCL {p.device.spec} {p.device.describe()}: " + ("builds" if p.ok else f"does not build ({p.reason})")
             for p in probes] or ["OpenCL: no device found"]
    try:
        lines.append(f"facesynth's default device: {opencl.choice().description}")
    except opencl.OpenCLUnavailable as exc:
        lines.append(f"facesynth's default device: none ({exc})")
    return lines


def pytest_generate_tests(metafunc):
    """``opencl_device``: every OpenCL device that builds facesynth's kernels, one test each."""
    if "opencl_device" in metafunc.fixturenames:
        working = [p.device for p in _opencl_probes() if p.ok]
        metafunc.parametrize("opencl_device", working or [None], indirect=True,
                             ids=[f"{d.spec}-{d.name}" for d in working] or ["no-device"])


#: Short tests the first worker runs before it reads the chain, which the second builds: at least
#: as long as building it takes (the suite's short tests take 0.3 s on average; more only delays
#: the chain's readers a little).
LEAD_BEFORE_CHAIN = 200


@pytest.hookimpl(trylast=True)  # after ``-m`` and ``-k`` deselected theirs
def pytest_collection_modifyitems(session, config, items):
    """Order the suite for pytest-xdist's work stealing (``make test`` runs ``--dist worksteal``):
    the first half of the list goes to one worker and the second half to the other, and a worker
    that runs out takes tests from the end of the other's list. The longest piece of work, the
    manual's examples (docs/pipeline.md, a session of their own), starts the second half: it builds
    the chain on the small corpus (the first test that needs it builds it) and runs on it. The
    first half starts with :data:`LEAD_BEFORE_CHAIN` short tests, so that its worker does not wait
    for the chain, then half of the tests that read the chain; the other half follows the manual.
    The rest of the short tests come after them and are what gets taken. Without xdist the order
    only changes when the chain is built."""
    manual = [item for item in items if item.name == "test_doc_blocks_run[pipeline.md]"]
    chain = [item for item in items if "chain" in getattr(item, "fixturenames", ()) and item not in manual]
    if not chain or not manual:
        return
    moved = {id(item) for item in chain + manual}
    rest = [item for item in items if id(item) not in moved]
    first, second = chain[0::2], chain[1::2]
    fill = max(0, len(items) // 2 - len(first))
    lead = min(LEAD_BEFORE_CHAIN, fill)
    items[:] = rest[:lead] + first + rest[lead:fill] + manual + second + rest[fill:]


@pytest.fixture
def opencl_device(request, monkeypatch):
    """Run the test with facesynth's OpenCL code on one device (``PYOPENCL_CTX``); skip with the
    reason when no device builds."""
    from facesynth.base import opencl

    device = request.param
    if device is None:
        reasons = "; ".join(f"{p.device.name}: {p.reason}" for p in _opencl_probes()) or "no OpenCL device found"
        pytest.skip(f"no OpenCL device builds facesynth's kernels ({reasons})")
    monkeypatch.setenv("PYOPENCL_CTX", device.spec)
    monkeypatch.delenv(opencl.FORCE_ENV, raising=False)
    opencl.reset()
    yield device
    opencl.reset()


def _interrupt_signals_state() -> tuple[str, ...]:
    """How this process handles SIGINT and SIGTERM, as the kernel sees it (ignored or blocked in
    the main thread: /proc/self/status, Linux) and as Python does (the handlers)."""
    kernel: tuple[str, ...] = ()
    try:
        status = Path("/proc/self/status").read_text()
    except OSError:
        pass
    else:
        masks = dict(line.split(":\t", 1) for line in status.splitlines() if line.startswith(("SigBlk", "SigIgn")))
        bits = {name: int(masks.get(name, "0"), 16) for name in ("SigBlk", "SigIgn")}
        kernel = tuple(f"{name} {signum.name}" for name, mask in bits.items()
                       for signum in (signal.SIGINT, signal.SIGTERM) if mask >> (signum - 1) & 1)
    return kernel + tuple(f"{signum.name} -> {signal.getsignal(signum)!r}" for signum in (signal.SIGINT, signal.SIGTERM))


@pytest.fixture(autouse=True)
def _interrupts_are_left_as_found(request):
    """Every test leaves Ctrl-C and SIGTERM as it found them: a test (or a library it drives) that
    ignores, blocks or replaces them would silently break the interrupt tests that follow it in
    the same process, and their subprocesses, which inherit an ignored or blocked signal. Such a
    test fails here, naming what it changed, and the process's state is put back."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before, handlers = _interrupt_signals_state(), {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    yield
    after = _interrupt_signals_state()
    if after != before:
        for signum, handler in handlers.items():
            if handler is not None:
                signal.signal(signum, handler)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, [signal.SIGINT, signal.SIGTERM])
        pytest.fail(f"the test changed how this process handles interrupts: {before} -> {after} (put back)")


@pytest.fixture(scope="session")
def shared_assets() -> Path:
    """Real data for tests (``../shared/assets``); tests that need it skip without it."""
    return SHARED_ASSETS


@pytest.fixture(scope="session")
def config() -> Config:
    return Config.load()


def _built_once(tmp_path_factory: pytest.TempPathFactory, name: str, build: Callable[[Path], None]) -> Path:
    """A folder ``name`` that ``build(folder)`` fills once per test session, shared by every
    pytest-xdist worker of the session (and by the one process without xdist).

    The folder lives in the session's base temporary folder (the parent of each worker's own,
    as pytest-xdist's documentation recommends); the first worker to ask builds it under a file
    lock while the others wait, then all read it. Tests only read what it holds: anything they
    write goes to their own ``tmp_path``. A build that fails is removed, so the next asks again.
    """
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent
    folder = root / "built-once" / name
    folder.parent.mkdir(parents=True, exist_ok=True)
    with FileLock(str(folder) + ".lock"):
        done = folder.with_name(f"{name}.built")
        if not done.exists():
            shutil.rmtree(folder, ignore_errors=True)
            folder.mkdir()
            try:
                build(folder)
            except BaseException:
                shutil.rmtree(folder, ignore_errors=True)
                raise
            done.touch()
    return folder


@pytest.fixture(scope="session")
def built_once(tmp_path_factory) -> Callable[[str, Callable[[Path], None]], Path]:
    """:func:`_built_once` for fixtures of other folders: ``built_once(name, build) -> folder``."""
    return functools.partial(_built_once, tmp_path_factory)


@pytest.fixture(scope="session")
def tiny_corpus(tmp_path_factory) -> Path:
    from facesynth.domain.corpus.generate import generate

    return _built_once(tmp_path_factory, "tiny", lambda d: generate(d / "corpus", "tiny", seed=0)) / "corpus"


@pytest.fixture(scope="session")
def tiny_artifacts(tiny_corpus, config, tmp_path_factory) -> dict[str, Path]:
    """corpus.h5, normalized.h5, pca.h5 built from the tiny corpus."""
    from facesynth.stages import ingest, normalize, pca

    def build(d: Path) -> None:
        ingest.run(tiny_corpus / "manifest.csv", d / "corpus.h5", config.settings("ingest"), config.settings("align"))
        normalize.run(d / "corpus.h5", d / "normalized.h5", config.settings("normalize"))
        pca.run(d / "normalized.h5", d / "pca.h5", config.settings("pca"))

    d = _built_once(tmp_path_factory, "tiny-artifacts", build)
    return {k: d / f"{k}.h5" for k in ("corpus", "normalized", "pca")}


@pytest.fixture(scope="session")
def tiny_db(tiny_artifacts, config, tmp_path_factory) -> Path:
    from facesynth.stages import build_db

    def build(d: Path) -> None:
        build_db.run(tiny_artifacts["pca"], d / "db.h5", config.settings("build_db"))

    return _built_once(tmp_path_factory, "tiny-db", build) / "db.h5"


@pytest.fixture(scope="session")
def tiny_trajectory(tiny_db, config, tmp_path_factory) -> Path:
    """A trajectory model (traj.h5) trained on the tiny database with 4 key-shapes, built once."""
    from facesynth.domain.methods import MethodSettings
    from facesynth.stages import fit_method, keyshapes

    def build(d: Path) -> None:
        ks = dataclasses.replace(config.settings("keyshapes"), count=4, curve_frames=200)
        keyshapes.run(tiny_db, d / "keyshapes.h5", ks)
        fit_method.run("trajectory", tiny_db, d / "traj.h5", MethodSettings.of(config), keyshapes_path=d / "keyshapes.h5")

    return _built_once(tmp_path_factory, "tiny-trajectory", build) / "traj.h5"


@pytest.fixture(scope="session")
def held_out_take(tiny_corpus) -> str:
    import csv

    return next(r["take"] for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["split"] == "test")


@pytest.fixture(scope="session")
def chain(built_once) -> Path:
    """The folder where the README's block ran, as written, with bash: the whole chain on the
    'small' preset's sample corpus (seed 0), from ``sample-corpus`` to the video, then audio
    alone; the top-level help's example is the same commands (tests/help_examples.py)."""
    from help_examples import run_readme

    return built_once("chain", run_readme) / "out" / "example"


@pytest.fixture(scope="session")
def small_db_and_truth(chain) -> tuple[Path, Path]:
    """The 'small' preset's database (about 1,700 nodes) and its contamination ground truth, as
    the chain built them."""
    return chain / "db.h5", chain / "corpus" / "contamination.csv"


@pytest.fixture(scope="session")
def held_out_synthesized(tiny_db, tiny_corpus, held_out_take, config, tmp_path_factory) -> dict[str, Path]:
    """The held-out sentence synthesized from the tiny database with the default settings and
    carried on, built once for the tests that only read them: ``motion`` (motion.h5), ``curves``
    (solved onto the built-in rig), ``anim`` (the tiny corpus's face.obj deformed by the motion),
    and its ``audio``."""
    from facesynth.stages import deform, solve, synthesize

    def build(d: Path) -> None:
        synthesize.run(tiny_db, d / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                       config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
        solve.run(d / "m.h5", d / "c.h5", config.settings("solve"))
        deform.run(d / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", d / "a.h5",
                   config.settings("deform"))

    d = _built_once(tmp_path_factory, "held-out-synthesized", build)
    return {"motion": d / "m.h5", "curves": d / "c.h5", "anim": d / "a.h5",
            "audio": tiny_corpus / "audio" / f"{held_out_take}.wav"}


@pytest.fixture(scope="session")
def coded_speech(tiny_corpus, held_out_take, tmp_path_factory) -> dict[str, Path]:
    """The held-out sentence (``wav``: the corpus's own 16 kHz file) encoded as the files users
    have (tests/coded_audio.py): ``m4a``, ``mp3``, ``opus``, ``ogg``, ``mp4`` (those the bundled
    ffmpeg can encode: get them with ``coded_audio.coded``), ``silent.mp4`` (no sound) and
    ``notes`` (a text file named ``notes.m4a``)."""
    from coded_audio import FORMATS, encode_all

    wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
    d = _built_once(tmp_path_factory, "coded-speech", lambda d: encode_all(wav, d))
    files = {name: d / file for name, (file, _, _) in FORMATS.items() if (d / file).exists()}
    return {"wav": wav, **files, "silent": d / "silent.mp4", "notes": d / "notes.m4a"}
