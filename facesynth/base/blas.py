"""BLAS on one thread for small linear algebra.

The solves, fits and blends of facesynth multiply matrices of tens to hundreds of rows. A threaded
BLAS (OpenBLAS starts a thread per core) spends more on waking its threads than on such products,
and its threads spin while they wait, so on a busy machine they run several times slower than on
one thread (the key-shapes' rig fit: 9 s against 0.5 s on two cores). :func:`one_blas_thread`
limits BLAS to one thread for a block of code, without changing it for the rest of the process.
"""

from __future__ import annotations

import functools
from typing import Any


@functools.lru_cache(maxsize=1)
def _controller() -> Any:
    """threadpoolctl's view of the loaded BLAS libraries, found once (finding them costs about
    4 ms, more than a live stream's solve of a few frames)."""
    from threadpoolctl import ThreadpoolController  # deferred: only once a solve runs

    return ThreadpoolController()


def one_blas_thread() -> Any:
    """A context in which BLAS runs on one thread: ``with one_blas_thread(): ...``."""
    return _controller().limit(limits=1)
