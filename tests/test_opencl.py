"""Device choice and the NumPy fallback: a machine whose OpenCL cannot build kernels still runs
the whole pipeline, says why once, and gets the same results."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base import opencl
from facesynth.cli import main

BROKEN = "error: unknown target CPU 'generic'"


def _device(p, d, kind="CPU", bundled=False, name=None):
    return opencl.Device(p, d, name or f"dev{p}{d}", kind, "Some Platform, OpenCL 3.0",
                         "/lib/libdriver.so", bundled)


@pytest.fixture
def fresh_choice(monkeypatch):
    """A clean device choice for the test, with no device named in the environment."""
    monkeypatch.delenv("PYOPENCL_CTX", raising=False)
    monkeypatch.delenv(opencl.FORCE_ENV, raising=False)
    opencl.reset()
    yield
    opencl.reset()


@pytest.fixture
def no_device_builds(monkeypatch, fresh_choice):
    """One CPU device whose every kernel build fails, as the bundled PoCL on a CPU newer than its LLVM."""
    broken = _device(0, 0, bundled=True, name="pthread-fake")
    monkeypatch.setattr(opencl, "list_devices", lambda: [broken])
    monkeypatch.setattr(opencl, "probe", lambda device: opencl.Probe(device, False, BROKEN))
    return broken


def test_candidates_are_gpus_first_and_system_drivers_before_the_bundled_pocl():
    bundled_cpu = _device(0, 0, bundled=True)
    system_cpu = _device(1, 0)
    gpu = _device(2, 0, kind="GPU")
    order = opencl.candidate_order([bundled_cpu, system_cpu, gpu])
    assert order == [gpu, system_cpu, bundled_cpu]


def test_the_first_device_that_builds_is_chosen_and_the_skipped_one_named(monkeypatch, fresh_choice):
    gpu, cpu = _device(0, 0, kind="GPU", name="gpu0"), _device(1, 0, name="cpu0")
    monkeypatch.setattr(opencl, "list_devices", lambda: [cpu, gpu])
    monkeypatch.setattr(opencl, "probe", lambda d: opencl.Probe(d, d is cpu, "" if d is cpu else "no compiler"))
    chosen = opencl.choice()
    assert chosen.device == cpu
    assert "skipped gpu0: no compiler" in chosen.reason
    assert chosen.description.startswith("OpenCL: cpu0")


def test_a_failed_build_falls_back_to_numpy_with_one_warning(no_device_builds, caplog):
    with caplog.at_level("WARNING", logger="facesynth"):
        assert opencl.use_opencl(True) is False
        assert opencl.use_opencl(True) is False  # said once per process
    warnings = [r.getMessage() for r in caplog.records if r.levelname == "WARNING"]
    assert len(warnings) == 1
    assert BROKEN in warnings[0] and "pocl-opencl-icd" in warnings[0] and "PYOPENCL_CTX" in warnings[0]
    assert opencl.device_description(True) == "NumPy"


def test_forcing_numpy_is_silent(monkeypatch, fresh_choice, caplog):
    monkeypatch.setenv(opencl.FORCE_ENV, "off")
    with caplog.at_level("WARNING", logger="facesynth"):
        assert opencl.use_opencl(True) is False
    assert not caplog.records


def test_an_explicit_device_that_cannot_build_is_a_clear_error(no_device_builds, monkeypatch, tiny_db, tiny_corpus,
                                                               held_out_take, tmp_path):
    monkeypatch.setenv("PYOPENCL_CTX", "0:0")
    out = tmp_path / "m.h5"
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes",
                                  str(tiny_corpus / "labels" / f"{held_out_take}.TextGrid"), "-o", str(out)])
    assert r.exit_code == 1, r.output
    assert "Traceback" not in r.output and len(r.output.strip().splitlines()) == 1
    assert "PYOPENCL_CTX='0:0'" in r.output and "pthread-fake" in r.output and BROKEN in r.output
    assert not out.exists()


def test_an_unknown_explicit_device_is_a_clear_error(monkeypatch, fresh_choice):
    monkeypatch.setattr(opencl, "list_devices", lambda: [_device(0, 0)])
    monkeypatch.setenv("PYOPENCL_CTX", "3")
    with pytest.raises(opencl.OpenCLUnavailable, match="no such OpenCL device"):
        opencl.choice()


def test_the_pipeline_runs_and_matches_without_a_working_device(no_device_builds, tiny_artifacts, tiny_db, tiny_corpus,
                                                                held_out_take, tmp_path):
    """build-db, synthesize and render on a machine where no kernel builds: exit 0, one warning
    line, the same database and motion as the OpenCL run, and the device recorded as NumPy."""
    runner = CliRunner()
    r = runner.invoke(main, ["build-db", str(tiny_artifacts["pca"]), "-o", str(tmp_path / "db.h5")])
    assert r.exit_code == 0 and BROKEN not in r.output, r.output  # build-db needs no device
    with h5py.File(tiny_db) as a, h5py.File(tmp_path / "db.h5") as b:
        for key in ("transition/dsc_out", "transition/dsc_in", "boundary/first_pos", "transition/pivot_last_pos"):
            assert np.array_equal(a[key][()], b[key][()])
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    opencl.reset()  # a new process
    r = runner.invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tg), "-o", str(tmp_path / "m.h5")])
    assert r.exit_code == 0 and r.output.count(BROKEN) == 1, r.output
    with h5py.File(tmp_path / "m.h5") as f:
        assert f["path"].attrs["device"] == "NumPy" and BROKEN in f["path"].attrs["device_reason"]
    opencl.reset()
    r = runner.invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tg), "-o", str(tmp_path / "n.h5"),
                             "--set", "synthesize.use_opencl=false"])
    assert r.exit_code == 0 and BROKEN not in r.output, r.output  # asked for NumPy: nothing to warn about
    with h5py.File(tmp_path / "m.h5") as a, h5py.File(tmp_path / "n.h5") as b:
        assert np.array_equal(a["path/node"][()], b["path/node"][()])
        assert np.array_equal(a["markers"][()], b["markers"][()])


def test_devices_lists_each_device_with_why_it_does_not_build(no_device_builds):
    r = CliRunner().invoke(main, ["devices"])
    assert r.exit_code == 0, r.output
    assert f"0:0  CPU   pthread-fake (Some Platform, OpenCL 3.0) [bundled with pyopencl]: does not build: {BROKEN}" in r.output
    assert "facesynth uses NumPy" in r.output


def test_verbose_says_which_device_and_why(monkeypatch, fresh_choice, tiny_db, tiny_corpus, held_out_take, tmp_path):
    from facesynth.domain.methods import search as search_method
    from facesynth.domain.search import pairs, synthesis

    cpu = _device(0, 0, name="cpu0")
    monkeypatch.setattr(opencl, "list_devices", lambda: [cpu])
    monkeypatch.setattr(opencl, "probe", lambda d: opencl.Probe(d, True))
    costs = pairs.transition_costs
    for module in (search_method, synthesis):  # no real device behind cpu0
        monkeypatch.setattr(module, "transition_costs", lambda db, s, on=None: costs(db, s, False))
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tg), "-o", str(tmp_path / "m.h5"), "-v"])
    assert r.exit_code == 0, r.output
    assert "OpenCL device cpu0 (Some Platform, OpenCL 3.0): the first device that builds the probe kernel" in r.output


def _pocl_devices():
    return [d for d in opencl.list_devices() if "pocl" in d.platform.lower() or "portable" in d.platform.lower()]


@pytest.mark.skipif(sys.platform != "linux", reason="PoCL's POCL_EXTRA_BUILD_FLAGS is tried on Linux")
def test_a_real_pocl_build_failure_falls_back(tiny_db, tiny_corpus, held_out_take, tmp_path):
    """The real failure: PoCL told to build for an unknown CPU (as the bundled PoCL does on AMD Zen 5)."""
    if not _pocl_devices():
        pytest.skip("no PoCL device on this machine to break")
    env = {k: v for k, v in os.environ.items() if k not in ("PYOPENCL_CTX", opencl.FORCE_ENV)}
    env["POCL_EXTRA_BUILD_FLAGS"] = "-mcpu=generic"
    # only PoCL's drivers: a GPU's (which builds) would be taken instead of falling back
    vendors = tmp_path / "vendors"
    vendors.mkdir()
    for icd in Path("/etc/OpenCL/vendors").glob("*.icd"):
        if "pocl" in icd.name.lower():
            shutil.copy(icd, vendors / icd.name)
    env["OCL_ICD_VENDORS"] = str(vendors)
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    out = tmp_path / "m.h5"
    r = subprocess.run([sys.executable, "-m", "facesynth.cli", "synthesize", str(tiny_db), "--phonemes", str(tg),
                        "-o", str(out)], env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    warnings = [line for line in r.stderr.splitlines() if line.startswith("warning:") and "OpenCL" in line]
    assert len(warnings) == 1 and "NumPy implementation" in warnings[0] and "-mcpu=generic" in warnings[0], r.stderr
    assert "Traceback" not in r.stderr
    with h5py.File(out) as f:
        assert f["path"].attrs["device"] == "NumPy"


def test_a_device_whose_sqrt_is_not_correctly_rounded_is_refused(opencl_device, monkeypatch):
    """OpenCL 1.2 lets a device's float32 sqrt be 3 ulp off (NVIDIA's is, unless built with
    -cl-fp32-correctly-rounded-divide-sqrt); the pair costs would then differ from the NumPy
    reference. The probe checks sqrt bit for bit: a sqrt one ulp off is refused with the reason."""
    source = opencl.kernel_source("probe")
    monkeypatch.setattr(opencl, "kernel_source", lambda name: source.replace(
        "y[i] = sqrt(x[i]);", "y[i] = as_float(as_uint(sqrt(x[i])) + (get_global_id(0) % 3 == 0));"))
    result = opencl.probe(opencl_device)
    assert not result.ok
    assert "sqrt is not correctly rounded" in result.reason and "1366 of 4096" in result.reason


def test_the_kernels_ask_for_correctly_rounded_sqrt_where_the_device_offers_it(opencl_device):
    import pyopencl as cl

    dev = opencl.context().devices[0]
    offered = bool(dev.single_fp_config & cl.device_fp_config.CORRECTLY_ROUNDED_DIVIDE_SQRT)
    assert (opencl.CORRECTLY_ROUNDED in opencl.build_options(dev)) == offered
    assert opencl.probe(opencl_device).ok
