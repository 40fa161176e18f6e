"""numba for the CPU fallback: ``jit``, numba's ``njit`` with its on-disk cache where that can
be written, and ``worth``, whether a kernel pays for numba's start-up in this process.

numba caches a compiled function beside its source (``__pycache__``), else in the user's cache
folder (``~/.cache/numba``), or in ``NUMBA_CACHE_DIR`` when that is set. Where none of them can
be written (a read-only install and a read-only home), ``njit(cache=True)`` raises RuntimeError
("no locator available") when the module is imported; here the function is then compiled in
every process instead (a few seconds at its first call), and the module still imports.
"""

from __future__ import annotations

import functools
import sys

#: CPU seconds a process pays the first time it uses a numba kernel, its cache filled: importing
#: numba (0.18 s) and the first call of a cached function (0.2 s, LLVM's start-up); each further
#: kernel's first call costs about 0.01 s. Measured on the 2-core host (bench.py).
START_COST_S = 0.4


def worth(numpy_seconds: float) -> bool:
    """Whether to use the numba kernel for work the NumPy path would do in ``numpy_seconds``:
    always once numba is loaded (librosa loads it too), else when NumPy would take longer than
    numba's start-up. Either way the result is the same, bit for bit; only the time differs."""
    return "numba" in sys.modules or numpy_seconds > START_COST_S


class _Kernel:
    """A function to compile with numba at its first call (:func:`jit`)."""

    def __init__(self, fn, options: dict) -> None:
        self.fn, self.options, self.compiled = fn, options, None
        functools.update_wrapper(self, fn)

    def __call__(self, *args):
        if self.compiled is None:
            _compile_module(self.fn.__module__)
        return self.compiled(*args)


#: module name -> its kernels not yet handed to numba, in the order they are defined.
_PENDING: dict[str, list[_Kernel]] = {}


def jit(**options):
    """``numba.njit(cache=True, nogil=True, **options)``, falling back to ``cache=False`` where no
    cache can be written; numba itself is imported only when a kernel is first called, so a module
    of kernels costs nothing to import (a process with a working OpenCL device never loads numba).
    Then every kernel of that module becomes numba's dispatcher, in the module too, so kernels
    calling one another are compiled together."""

    def decorate(fn):
        kernel = _Kernel(fn, options)
        _PENDING.setdefault(fn.__module__, []).append(kernel)
        return kernel

    return decorate


def _compile_module(name: str) -> None:
    from numba import njit  # deferred: numba only once a kernel runs (0.2 s of start-up)

    module = sys.modules[name]
    for kernel in _PENDING.pop(name, []):
        try:
            dispatcher = njit(cache=True, nogil=True, **kernel.options)(kernel.fn)
        except RuntimeError:  # no writable cache location
            dispatcher = njit(cache=False, nogil=True, **kernel.options)(kernel.fn)
        kernel.compiled = dispatcher
        setattr(module, kernel.fn.__name__, dispatcher)
