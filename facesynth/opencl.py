"""OpenCL plumbing: the device comes from ``PYOPENCL_CTX`` (never hard-coded), kernels are
``facesynth/kernels/*.cl`` files built once per context, build failures carry the log."""

from __future__ import annotations

import os
from functools import lru_cache
from importlib import resources

from .errors import FacesynthError


class OpenCLUnavailable(FacesynthError):
    """No OpenCL platform or device could be opened."""


@lru_cache(maxsize=1)
def context():
    """The OpenCL context chosen by ``PYOPENCL_CTX`` (first device if unset)."""
    import pyopencl as cl

    os.environ.setdefault("PYOPENCL_CTX", "0")
    try:
        return cl.create_some_context(interactive=False)
    except (cl.Error, RuntimeError, ValueError) as exc:
        raise OpenCLUnavailable(
            f"no OpenCL device could be opened ({exc}); install pocl-binary-distribution, set PYOPENCL_CTX, "
            "or run on the NumPy reference with --set synthesize.use_opencl=false."
        ) from None


@lru_cache(maxsize=1)
def queue():
    import pyopencl as cl

    return cl.CommandQueue(context())


@lru_cache(maxsize=None)
def program(name: str):
    """Build ``kernels/<name>.cl`` once for the current context."""
    import pyopencl as cl

    source = resources.files("facesynth").joinpath(f"kernels/{name}.cl").read_text("utf-8")
    try:
        return cl.Program(context(), source).build(options=["-cl-std=CL1.2"])
    except cl.RuntimeError as exc:  # build failure: keep the compiler's log
        raise RuntimeError(f"OpenCL kernel {name}.cl failed to build:\n{exc}") from None


@lru_cache(maxsize=None)
def kernel(program_name: str, kernel_name: str):
    """One kernel object per (file, name), retrieved once."""
    import pyopencl as cl

    return cl.Kernel(program(program_name), kernel_name)


def device_name() -> str:
    return ", ".join(d.name for d in context().devices)


def max_alloc_bytes() -> int:
    return min(d.max_mem_alloc_size for d in context().devices)
