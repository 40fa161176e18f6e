"""Run the lines of a batch on Dask: the client is created here and only here.

By default a ``LocalCluster`` of worker processes (one thread each: the search, the
alignment and the rasterizer hold the GIL for long stretches, so threads would not run in
parallel), one per core unless ``workers`` says otherwise; with ``scheduler`` the lines go
to an existing cluster (``tcp://host:8786``), whose workers need facesynth installed and the
same view of the files' paths. One task per line, inputs by path; each worker keeps the
database it read (:mod:`.line`). A line's problem is a result, not an exception; a task that
raises (a bug) or whose worker dies is recorded as failed with its traceback, and the other
lines go on.
"""

from __future__ import annotations

import contextlib
import logging
import os
import time
import traceback
from collections.abc import Iterator
from pathlib import Path

from facesynth.base.errors import InputError

from .line import Job, LineResult, run_line
from .script import Line


def _quiet_worker() -> None:
    """Workers say nothing on the terminal (no progress bars, no warnings): the client reports."""
    logging.getLogger("facesynth").setLevel(logging.ERROR)
    logging.getLogger("facesynth").propagate = False


@contextlib.contextmanager
def dask_client(scheduler: str | None, workers: int) -> Iterator:
    """A ``distributed.Client`` on ``scheduler`` or on a new local cluster of ``workers``
    processes (0: one per core); closed (and the local cluster shut down) on exit."""
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise InputError("facesynth batch needs Dask's distributed scheduler; install it with "
                         "pip install 'dask[distributed]'.") from None
    if scheduler:
        try:
            client = Client(scheduler, timeout="20s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(f"--scheduler {scheduler}: cannot reach the Dask scheduler ({exc}); "
                             "check the address (e.g. tcp://host:8786) and that it is running.") from None
        with client:
            yield client
        return
    n = workers or os.cpu_count() or 1
    with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0",
                      silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
        yield client


def run_lines(lines: list[Line], job: Job, client) -> Iterator[LineResult]:
    """Submit every line to ``client``'s cluster; yields the results as they finish."""
    from distributed import as_completed

    client.run(_quiet_worker)
    futures = {}
    for k, line in enumerate(lines):
        future = client.submit(run_line, line, job, key=f"facesynth-line-{k}-{line.id}-{time.time_ns()}", pure=False)
        futures[future] = line
    for future in as_completed(futures):
        line = futures.pop(future)
        try:
            result = future.result()
        except Exception as exc:  # a bug or a dead worker: recorded for this line, the others go on
            result = _crashed(line, job, exc)
        future.release()
        yield result


def _crashed(line: Line, job: Job, exc: BaseException) -> LineResult:
    """A failed result for a line whose task raised, with the traceback kept in ``ID.error.txt``."""
    log = Path(job.out_dir) / f"{line.id}.error.txt"
    text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))
    with contextlib.suppress(OSError):
        log.write_text(text, encoding="utf-8")
    return LineResult(line.id, line.row, "failed",
                      reason=f"internal error ({type(exc).__name__}: {exc}); the traceback is in {log.name}")
