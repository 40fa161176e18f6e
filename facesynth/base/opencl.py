"""OpenCL plumbing: which device runs the kernels, and what happens when none can.

The device comes from ``PYOPENCL_CTX`` when it is set (never hard-coded). Without it,
every device of every platform is tried in a fixed order, GPUs first, then accelerators,
then CPUs, and within a kind a system driver before the PoCL that the pyopencl wheel
bundles; the first device that builds and runs ``kernels/probe.cl`` is used. The bundled
PoCL (3.0-rc2 on LLVM 14) cannot build for processors newer than its LLVM (e.g. AMD
Zen 5), so on such a machine a system driver (Debian's ``pocl-opencl-icd``) or a GPU is
taken instead.

When no device builds, :func:`use_opencl` says so once with one warning line and every
stage runs its NumPy implementation (the DP is bit-identical to its kernel; the pair gaps
and the rasterizer agree within the tolerances their docstrings give). Setting the
environment variable ``FACESYNTH_OPENCL=off`` (or a stage's ``use_opencl = false``)
forces NumPy. An explicit ``PYOPENCL_CTX`` whose device cannot build is a user error
naming the device and the first line of its build log.

Kernels are ``facesynth/kernels/*.cl`` files, built once per process.
"""

from __future__ import annotations

import ctypes
import logging
import os
from dataclasses import dataclass
from functools import cache, lru_cache
from importlib import resources
from pathlib import Path

from .errors import FacesynthError

log = logging.getLogger("facesynth")

#: Environment variable that forces the NumPy implementations ("off", "0", "no", "false", "numpy").
FORCE_ENV = "FACESYNTH_OPENCL"
_OFF = {"off", "0", "no", "false", "numpy"}

#: Build options of every facesynth kernel.
BUILD_OPTIONS = ("-cl-std=CL1.2",)

#: Asks for IEEE-754 correctly rounded single-precision sqrt and division. OpenCL 1.2 allows a
#: device 3 ulp of error in sqrt without it (NVIDIA's driver uses that freedom, PoCL does not),
#: and the kernels' values must equal the NumPy reference's bit for bit.
CORRECTLY_ROUNDED = "-cl-fp32-correctly-rounded-divide-sqrt"

_KIND_ORDER = {"GPU": 0, "ACCELERATOR": 1, "CPU": 2}

_ADVICE = ("install your system's OpenCL driver (e.g. Debian's pocl-opencl-icd) or choose a device with "
           "PYOPENCL_CTX; 'facesynth devices' lists them")


class OpenCLUnavailable(FacesynthError):
    """No OpenCL device can be used (or the one named by ``PYOPENCL_CTX`` cannot build)."""


@dataclass(frozen=True)
class Device:
    """One OpenCL device as the ICD loader lists it."""

    platform_index: int
    device_index: int
    name: str
    kind: str             # "GPU", "ACCELERATOR", "CPU" or "OTHER"
    platform: str         # platform name and version, e.g. "Portable Computing Language, OpenCL 3.0 PoCL 3.1"
    driver: str           # the driver library's path ("" when it cannot be told)
    bundled: bool         # the PoCL inside the pyopencl wheel

    @property
    def spec(self) -> str:
        """The value of ``PYOPENCL_CTX`` that selects this device."""
        return f"{self.platform_index}:{self.device_index}"

    def describe(self) -> str:
        """Device and platform, e.g. "pthread-AMD EPYC (Portable Computing Language, OpenCL 3.0 PoCL 3.1)"."""
        return f"{self.name} ({self.platform})"


@dataclass(frozen=True)
class Probe:
    """Whether a device builds and runs the probe kernel; ``reason`` is the first line of the
    build log (or of the error) when it does not."""

    device: Device
    ok: bool
    reason: str = ""


@dataclass(frozen=True)
class Choice:
    """The device this process uses (None: the NumPy implementations) and why."""

    device: Device | None
    reason: str
    probes: tuple[Probe, ...] = ()

    @property
    def description(self) -> str:
        """What artifacts record as their ``device`` attribute."""
        return f"OpenCL: {self.device.describe()}" if self.device else "NumPy"


def _cl():
    import pyopencl as cl

    return cl


def _library_ranges() -> list[tuple[int, int, str]]:
    """Address ranges of the shared libraries mapped into this process (Linux; else empty)."""
    ranges = []
    try:
        with open("/proc/self/maps") as fh:
            for line in fh:
                parts = line.split()
                if len(parts) >= 6 and parts[5].startswith("/"):
                    lo, hi = (int(x, 16) for x in parts[0].split("-"))
                    ranges.append((lo, hi, parts[5]))
    except OSError:
        pass
    return ranges


def _driver_library(platform, ranges) -> str:
    """The library that implements ``platform``: an ICD platform handle starts with a pointer
    to its driver's dispatch table, which lives in that driver's mapped image."""
    try:
        dispatch = ctypes.c_void_p.from_address(platform.int_ptr).value or 0
    except (ValueError, OSError, AttributeError):
        return ""
    return next((path for lo, hi, path in ranges if lo <= dispatch < hi), "")


def list_devices() -> list[Device]:
    """Every device of every OpenCL platform (empty when there is no OpenCL at all)."""
    try:
        cl = _cl()
        platforms = cl.get_platforms()
    except (ImportError, OSError, RuntimeError) as exc:  # no ICD loader or no platform: no OpenCL here
        log.debug("no OpenCL platforms: %s", exc)
        return []
    ranges = _library_ranges()
    wheel = str(Path(cl.__file__).parent)
    out = []
    for p, platform in enumerate(platforms):
        try:
            devices = platform.get_devices()
        except cl.Error as exc:  # e.g. POCL_DEVICES=none: a platform without devices
            log.debug("platform %s has no devices: %s", platform.name, exc)
            continue
        driver = _driver_library(platform, ranges)
        for d, device in enumerate(devices):
            kind = next((k for k in _KIND_ORDER if device.type & getattr(cl.device_type, k)), "OTHER")
            version = " ".join(platform.version.split(",")[0].split())  # e.g. "OpenCL 3.0 PoCL 3.1+debian Linux"
            out.append(Device(p, d, device.name.strip(), kind, f"{platform.name.strip()}, {version}",
                              driver, bool(driver) and driver.startswith(wheel)))
    return out


def candidate_order(devices: list[Device]) -> list[Device]:
    """GPUs, then accelerators, then CPUs; a system driver before the bundled PoCL; then as listed."""
    return sorted(devices, key=lambda d: (_KIND_ORDER.get(d.kind, 3), d.bundled, d.platform_index, d.device_index))


def _cl_device(device: Device):
    return _cl().get_platforms()[device.platform_index].get_devices()[device.device_index]


def build_options(cl_device) -> list[str]:
    """:data:`BUILD_OPTIONS`, plus :data:`CORRECTLY_ROUNDED` where ``cl_device`` (a pyopencl
    device) offers correctly rounded sqrt and division; the probe refuses a device whose sqrt
    still differs from IEEE-754's."""
    cl = _cl()
    options = list(BUILD_OPTIONS)
    if cl_device.single_fp_config & cl.device_fp_config.CORRECTLY_ROUNDED_DIVIDE_SQRT:
        options.append(CORRECTLY_ROUNDED)
    return options


def build_log_line(exc: BaseException) -> str:
    """The first meaningful line of a failed build's log (pyopencl puts the log after
    'Build on <device>:'), else the first line of the error."""
    text = str(exc)
    marker = text.find("Build on")
    if marker >= 0:
        for line in text[marker:].splitlines()[1:]:
            if line.strip() and not line.startswith("(options:"):
                return line.strip()
    return text.strip().splitlines()[0] if text.strip() else type(exc).__name__


#: The context each successful probe made, kept so the chosen device's is not made twice.
_probe_contexts: dict[Device, object] = {}


def probe(device: Device) -> Probe:
    """Build ``kernels/probe.cl`` on ``device`` and check what it computes: float8 arithmetic,
    integer atomics on float bits, and sqrt rounded as IEEE-754 (bit-identical to NumPy's)."""
    import numpy as np

    try:
        cl = _cl()
        cl_device = _cl_device(device)
        ctx = cl.Context([cl_device])
        prg = cl.Program(ctx, kernel_source("probe")).build(options=build_options(cl_device))
        q = cl.CommandQueue(ctx)
        x = np.array([3.0, 1.5, 2.0, 4.0], np.float32)
        mf = cl.mem_flags
        xb = cl.Buffer(ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=x)
        yb = cl.Buffer(ctx, mf.WRITE_ONLY, x.nbytes)
        low = np.array([np.iinfo(np.int32).max], np.int32)
        lb = cl.Buffer(ctx, mf.READ_WRITE | mf.COPY_HOST_PTR, hostbuf=low)
        prg.probe(q, x.shape, None, xb, yb, lb)
        y = np.empty_like(x)
        cl.enqueue_copy(q, y, yb)
        cl.enqueue_copy(q, low, lb, is_blocking=True)
        roots_of = _sqrt_probe_values()
        rb = cl.Buffer(ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=roots_of)
        sb = cl.Buffer(ctx, mf.WRITE_ONLY, roots_of.nbytes)
        prg.probe_sqrt(q, roots_of.shape, None, rb, sb)
        roots = np.empty_like(roots_of)
        cl.enqueue_copy(q, roots, sb, is_blocking=True)
    except (_cl().Error, RuntimeError, ValueError, OSError) as exc:  # a driver failure: this device is unusable
        return Probe(device, False, build_log_line(exc))
    if not (np.array_equal(y, 36 * x) and low[0] == np.float32(1.5).view(np.int32)):
        return Probe(device, False, "the probe kernel ran but computed wrong numbers")
    wrong = int(np.count_nonzero(roots.view(np.uint32) != np.sqrt(roots_of).view(np.uint32)))
    if wrong:
        return Probe(device, False, f"its float32 sqrt is not correctly rounded ({wrong} of {roots_of.size} "
                                    "probe values differ from IEEE-754), so results would not be bit-identical")
    _probe_contexts[device] = ctx
    return Probe(device, True)


def _sqrt_probe_values():
    """(4096,) float32: fixed positive values spread over 2^-20 .. 2^20 (the range of squared
    marker distances in mm^2 and more), whose correctly rounded square roots the probe checks."""
    import numpy as np

    return np.exp2(np.random.default_rng(0).uniform(-20.0, 20.0, 4096)).astype(np.float32)


def _forced_off() -> bool:
    return os.environ.get(FORCE_ENV, "").strip().lower() in _OFF


def _explicit(spec: str) -> tuple[Device, Probe]:
    """The device named by ``PYOPENCL_CTX`` and its probe; refused with the reason when it cannot build."""
    devices = list_devices()
    parts = spec.strip().split(":")
    try:
        p = int(parts[0]) if parts[0] else 0
        d = int(parts[1]) if len(parts) > 1 and parts[1] else 0
    except ValueError:
        raise OpenCLUnavailable(f"PYOPENCL_CTX={spec!r}: expected PLATFORM[:DEVICE] numbers, e.g. 0:0; "
                                "'facesynth devices' lists them.") from None
    device = next((x for x in devices if (x.platform_index, x.device_index) == (p, d)), None)
    if device is None:
        listed = ", ".join(f"{x.spec} {x.name}" for x in devices) or "none"
        raise OpenCLUnavailable(f"PYOPENCL_CTX={spec!r}: no such OpenCL device (devices: {listed}); "
                                "choose one that 'facesynth devices' lists, or unset PYOPENCL_CTX.")
    result = probe(device)
    if not result.ok:
        raise OpenCLUnavailable(f"PYOPENCL_CTX={spec!r}: device {device.describe()} cannot build OpenCL kernels "
                                f"({result.reason}); choose another device ('facesynth devices' lists them), "
                                f"unset PYOPENCL_CTX, or set {FORCE_ENV}=off to run on NumPy.")
    return device, result


@lru_cache(maxsize=1)
def choice() -> Choice:
    """The device this process uses, chosen once (see the module docstring)."""
    if _forced_off():
        return Choice(None, f"{FORCE_ENV}={os.environ[FORCE_ENV]}")
    spec = os.environ.get("PYOPENCL_CTX")
    if spec is not None and spec.strip():
        device, result = _explicit(spec)
        chosen = Choice(device, f"PYOPENCL_CTX={spec}", (result,))
        log.info("OpenCL device %s (%s)", device.describe(), chosen.reason)
        return chosen
    probes = []
    for device in candidate_order(list_devices()):
        result = probe(device)
        probes.append(result)
        if result.ok:
            skipped = "; ".join(f"{r.device.name}: {r.reason}" for r in probes[:-1])
            reason = "the first device that builds the probe kernel (GPUs, then CPUs, system drivers before the bundled PoCL)"
            chosen = Choice(device, reason + (f"; skipped {skipped}" if skipped else ""), tuple(probes))
            log.info("OpenCL device %s: %s", device.describe(), chosen.reason)
            return chosen
    if probes:
        why = "; ".join(f"{r.device.name}: {r.reason}" for r in probes)
        return Choice(None, f"no OpenCL device builds kernels ({why})", tuple(probes))
    return Choice(None, "no OpenCL device found")


def describe_devices() -> list[str]:
    """Lines of ``facesynth devices``: each device with its probe result, then the choice."""
    devices = list_devices()
    try:
        chosen, error = choice(), None
    except OpenCLUnavailable as exc:
        chosen, error = None, exc
    probed = {p.device: p for p in (chosen.probes if chosen else ())}
    lines = []
    for device in devices:
        result = probed.get(device) or probe(device)
        state = "builds" if result.ok else f"does not build: {result.reason}"
        origin = " [bundled with pyopencl]" if device.bundled else ""
        lines.append(f"{device.spec}  {device.kind:<5} {device.name} ({device.platform}){origin}: {state}")
        if device.driver:
            lines.append(f"      driver {device.driver}")
    if not devices:
        lines.append("no OpenCL platform or device found")
    if chosen is None:
        lines.append(f"facesynth cannot use OpenCL: {error}")
    elif chosen.device is None:
        lines.append(f"facesynth uses NumPy: {chosen.reason}")
    else:
        lines.append(f"facesynth uses {chosen.device.spec} {chosen.device.name}: {chosen.reason}")
    return lines


def use_opencl(wanted: bool = True) -> bool:
    """Whether a stage that can use OpenCL should: ``wanted`` (its ``use_opencl`` setting), not
    forced off, and a device builds. A fallback caused by the drivers is warned about once."""
    if not wanted:
        return False
    chosen = choice()
    if chosen.device is None and not _forced_off():
        _warn_fallback(chosen.reason)
    return chosen.device is not None


@lru_cache(maxsize=1)
def _warn_fallback(reason: str) -> None:
    log.warning("%s; running the NumPy implementation (same results, slower); to use OpenCL, %s.", reason, _ADVICE)


def device_description(wanted: bool = True) -> str:
    """What an artifact records as ``device``: "OpenCL: <device> (<platform>)" or "NumPy"."""
    return choice().description if use_opencl(wanted) else "NumPy"


def device_record(wanted: bool = True) -> tuple[str, str]:
    """What an artifact records of where it was computed: the device (as :func:`device_description`)
    and why that one ("use_opencl = false", the choice's reason, or why no device could be used)."""
    if not wanted:
        return "NumPy", "use_opencl = false"
    chosen = choice()
    return device_description(wanted), chosen.reason


def reset() -> None:
    """Forget the chosen device and built kernels (tests switch devices through the environment)."""
    for cached in (choice, _warn_fallback, context, queue, program, kernel):
        cached.cache_clear()
    _probe_contexts.clear()


@lru_cache(maxsize=1)
def context():
    """The OpenCL context of the chosen device."""
    chosen = choice()
    if chosen.device is None:
        raise OpenCLUnavailable(f"{chosen.reason}; {_ADVICE}, or set use_opencl = false.")
    return _probe_contexts.get(chosen.device) or _cl().Context([_cl_device(chosen.device)])


@lru_cache(maxsize=1)
def queue():
    """The command queue of the chosen device (one per process)."""
    return _cl().CommandQueue(context())


def kernel_source(name: str) -> str:
    """The text of ``kernels/<name>.cl``."""
    return resources.files("facesynth").joinpath(f"kernels/{name}.cl").read_text("utf-8")


def build(source: str, name: str = "<source>", **defines: int):
    """Build OpenCL C ``source`` for the current context; ``defines`` become ``-DNAME=value``
    options, so a kernel's compile-time sizes come from the Python constant that lays out its data."""
    cl = _cl()
    options = build_options(context().devices[0]) + [f"-D{key}={value}" for key, value in sorted(defines.items())]
    try:
        return cl.Program(context(), source).build(options=options)
    except cl.Error as exc:  # the probe built, so this is a kernel the device cannot take: keep the log
        raise RuntimeError(f"OpenCL kernel {name} failed to build on {choice().description}:\n{exc}") from None


@cache
def program(name: str, **defines: int):
    """Build ``kernels/<name>.cl`` once per set of ``defines`` for the current context."""
    return build(kernel_source(name), f"{name}.cl", **defines)


@cache
def kernel(program_name: str, kernel_name: str, **defines: int):
    """One kernel object per (file, name, defines), retrieved once."""
    return _cl().Kernel(program(program_name, **defines), kernel_name)


def device_name() -> str:
    """Name(s) of the chosen device."""
    return ", ".join(d.name for d in context().devices)


def max_alloc_bytes() -> int:
    """The largest single buffer the chosen device allows, bytes."""
    return min(d.max_mem_alloc_size for d in context().devices)


#: Host alignment (bytes) of arrays handed to a device with USE_HOST_PTR: at least the
#: device's CL_DEVICE_MEM_BASE_ADDR_ALIGN, and a page, so kernels may read float8s in place.
HOST_ALIGNMENT = 4096


def aligned_empty(shape, dtype, alignment: int = HOST_ALIGNMENT):
    """An uninitialized C-order array whose data starts on an ``alignment``-byte boundary.
    NumPy only promises 16 bytes; a kernel reading float8s through USE_HOST_PTR needs more."""
    import numpy as np

    dtype = np.dtype(dtype)
    count = int(np.prod(shape, dtype=np.int64))
    raw = np.empty(count * dtype.itemsize + alignment, np.uint8)
    offset = (-raw.ctypes.data) % alignment
    return raw[offset : offset + count * dtype.itemsize].view(dtype).reshape(shape)


def host_aligned(a, alignment: int | None = None):
    """``a`` itself when it is C-contiguous and starts on the device's base alignment (at least
    128 bytes), else an aligned copy (:func:`aligned_empty`): what USE_HOST_PTR may be given."""
    import numpy as np

    if alignment is None:
        alignment = max([128] + [d.mem_base_addr_align // 8 for d in context().devices])
    if a.flags.c_contiguous and a.ctypes.data % alignment == 0:
        return a
    out = aligned_empty(a.shape, a.dtype, max(alignment, HOST_ALIGNMENT))
    np.copyto(out, a)
    return out
