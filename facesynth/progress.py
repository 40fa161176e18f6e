"""Progress bars that show on a terminal and stay silent in pipes and CI."""

from __future__ import annotations

import contextlib
import os
import sys
from typing import Iterable, Iterator, TypeVar

import click

T = TypeVar("T")

_quiet = False


def set_quiet(quiet: bool) -> None:
    """Silence progress bars for this process (the ``-q`` flag)."""
    global _quiet
    _quiet = quiet


def _interactive() -> bool:
    return (not _quiet) and sys.stderr.isatty() and not os.environ.get("CI")


@contextlib.contextmanager
def _bar(iterable, length, label):
    with click.progressbar(iterable, length=length, label=label, file=sys.stderr) as bar:
        yield bar


def progress(iterable: Iterable[T], label: str, length: int | None = None) -> Iterator[T]:
    """Iterate over ``iterable``, drawing a progress bar on stderr when it is a terminal."""
    if not _interactive():
        yield from iterable
        return
    with _bar(iterable, length, label) as bar:
        yield from bar
