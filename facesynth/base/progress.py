"""Progress bars that show on a terminal and stay silent in pipes, in CI and with ``-q``.

Whether to draw is read from the ``facesynth`` logger, which the command line configures
(``-q`` raises it to errors only), so no flag of our own is kept between calls.
"""

from __future__ import annotations

import logging
import os
import sys
from collections.abc import Callable, Iterable, Iterator
from typing import TypeVar

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


class Overall:
    """One progress bar for a long search of ``total`` steps: :meth:`step` advances it and sets
    the text after the bar (e.g. the best score so far). On a terminal it is drawn on stderr;
    otherwise ``say`` (if given) gets a line every ``every`` steps and at the last one, so a
    log still shows the search moving."""

    def __init__(self, total: int, label: str, say: Callable[[str], None] | None = None, every: int = 5):
        self.total, self.label, self.say, self.every = max(total, 1), label, say, max(every, 1)
        self.done, self.text = 0, ""
        self._bar = None
        if _interactive():
            self._bar = click.progressbar(length=self.total, label=label, file=sys.stderr,
                                          item_show_func=lambda _: self.text, show_eta=True)
            self._bar.__enter__()

    def step(self, text: str) -> None:
        """One step done; ``text`` describes where the search stands."""
        self.done += 1
        self.text = text
        if self._bar is not None:
            self._bar.update(1, current_item=text)
        elif self.say is not None and (self.done % self.every == 0 or self.done == self.total):
            self.say(f"{self.label} {min(self.done, self.total)}/{self.total}: {text}")

    def close(self) -> None:
        """Finish the bar (a no-op when none is drawn)."""
        if self._bar is not None:
            self._bar.__exit__(None, None, None)
            self._bar = None
