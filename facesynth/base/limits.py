"""Physical bounds on inputs (the ``[limits]`` settings) and the memory check before heavy work.

Every command reads ``[limits]``; the command line puts the command's resolved section in force
for the command's duration with :func:`using` (a context variable, so nothing global is changed
and a library caller that never calls it gets the packaged defaults). Readers ask
:func:`current` and refuse a value past a bound with a sentence naming the setting that raises
it, e.g. ``limits.max_markers``.

:func:`require_memory` compares a computation's estimated memory with what the kernel reports
as available (``MemAvailable`` of ``/proc/meminfo``) and refuses with both numbers instead of
letting the process be killed.
"""

from __future__ import annotations

import contextlib
import contextvars
import functools
from collections.abc import Iterator

from .config import Config, LimitsSettings
from .errors import InputError

_CURRENT: contextvars.ContextVar[LimitsSettings | None] = contextvars.ContextVar("facesynth_limits", default=None)


@functools.lru_cache(maxsize=1)
def defaults() -> LimitsSettings:
    """The packaged ``[limits]`` section."""
    return Config.load().settings("limits")


def current() -> LimitsSettings:
    """The ``[limits]`` in force: the running command's, else the packaged defaults."""
    return _CURRENT.get() or defaults()


@contextlib.contextmanager
def using(settings: LimitsSettings) -> Iterator[LimitsSettings]:
    """Put ``settings`` in force for the body (the command line wraps each command in it)."""
    token = _CURRENT.set(settings)
    try:
        yield settings
    finally:
        _CURRENT.reset(token)


def bound(value: float, name: str, what: str, where: str) -> None:
    """Refuse ``value`` (of ``what``, read at ``where``) above ``limits.<name>``."""
    limit = getattr(current(), name)
    if value > limit:
        raise InputError(f"{where}: {what} is {value:g}, above limits.{name} = {limit:g}; "
                         f"if that is right, raise it with --set limits.{name}=...")


def mem_available() -> int | None:
    """Bytes the kernel reports as available for new allocations (None where unknown)."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return None
    return None


def size_text(nbytes: float) -> str:
    """Bytes as people read them: '1.5 GB', '12.0 MB', '1.0 kB'."""
    for unit, scale in (("GB", 1e9), ("MB", 1e6)):
        if nbytes >= scale:
            return f"{nbytes / scale:.1f} {unit}"
    return f"{nbytes / 1e3:.1f} kB"


def require_memory(nbytes: float, what: str, where: str) -> None:
    """Refuse work estimated to need ``nbytes`` of memory when less is available."""
    available = mem_available()
    if available is not None and nbytes > available:
        raise InputError(f"{where}: {what} needs about {size_text(nbytes)} of memory but {size_text(available)} is available; "
                         "free memory, use a machine with more, or make the input smaller.")
