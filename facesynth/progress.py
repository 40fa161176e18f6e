"""Progress bars that show on a terminal and stay silent in pipes, in CI and with ``-q``.

Whether to draw is read from the ``facesynth`` logger, which the command line configures
(``-q`` raises it to errors only), so no flag of our own is kept between calls.
"""

from __future__ import annotations

import logging
import os
import sys
from typing import Callable, Iterable, Iterator, TypeVar

import click

T = TypeVar("T")


def _interactive() -> bool:
    return (logging.getLogger("facesynth").isEnabledFor(logging.WARNING) and sys.stderr.isatty()
            and not os.environ.get("CI"))


def progress(iterable: Iterable[T], label: str, length: int | None = None,
             show: Callable[[T | None], str | None] | None = None) -> Iterator[T]:
    """Iterate over ``iterable``, drawing a progress bar on stderr when it is a terminal (with
    the estimated time left when ``length`` is known). ``show`` gives the text after the bar
    for the item just taken (e.g. "12 done, 1 failed")."""
    if not _interactive():
        yield from iterable
        return
    with click.progressbar(iterable, length=length, label=label, file=sys.stderr, item_show_func=show) as bar:
        yield from bar
