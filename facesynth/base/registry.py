"""Registries: the extension points of facesynth as tables of named members.

Five families can grow without touching the code that uses them: synthesis methods
(:data:`METHODS`), export formats (:data:`EXPORT_FORMATS`, also the outputs of ``batch``),
capture readers (:data:`CAPTURE_READERS`), artifact kinds (:data:`ARTIFACT_KINDS`) and the
grapheme-to-phoneme backends of languages other than English (:data:`G2P_BACKENDS`). A member
is registered by one line where its family is defined (the family's package ``__init__``), naming
the module and attribute that implement it (``"module:attribute"``), a one-line summary and the
facts the command line needs about it. The member's module is imported only when the member is
used, so listing the names (``--help``, ``--set`` validation, the docs' tables) imports nothing
heavy. The command-line choices, ``--set`` validation, ``evaluate``'s methods and the generated
docs tables all read the registries, so a new member appears in each of them.

A registry fills itself on first use by importing its home package (the one place where the base
layer names a module above it, by name, as :mod:`facesynth.base.pipeline` does for the stages).
Standard library only.
"""

from __future__ import annotations

import importlib
import re
import sys
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from .errors import UsageError


@dataclass(frozen=True)
class Entry:
    """One member: its ``name`` (what users type), ``target`` (``"module:attribute"``, or the
    object itself for a member registered at run time), ``summary`` (one line for the docs and
    ``--help``) and ``facts`` (what the users of the family need to know without importing it,
    e.g. an export format's file suffix)."""

    name: str
    target: Any
    summary: str
    facts: Mapping[str, Any] = field(default_factory=dict)

    def load(self) -> Any:
        """The registered object (its module imported on first use)."""
        if not isinstance(self.target, str):
            return self.target
        module, _, attribute = self.target.partition(":")
        return getattr(importlib.import_module(module), attribute)


class Registry:
    """Named members of one family, in registration order (the order reports and docs list them).

    ``what`` names a member in messages ("synthesis method"); ``home`` is the package whose
    import registers the built-in members."""

    def __init__(self, what: str, home: str) -> None:
        self.what = what
        self.home = home
        self._entries: dict[str, Entry] = {}
        self._filled = False

    def register(self, name: str, target: Any, summary: str, **facts: Any) -> Entry:
        """Add a member; a second member of the same name is a programming error."""
        if name in self._entries:
            raise ValueError(f"a {self.what} named {name!r} is already registered")
        entry = Entry(name, target, summary, MappingProxyType(dict(facts)))
        self._entries[name] = entry
        return entry

    def unregister(self, name: str) -> None:
        """Remove a member (a test's toy member, after the test)."""
        self._fill()
        del self._entries[name]

    def _fill(self) -> None:
        if not self._filled:
            self._filled = True
            importlib.import_module(self.home)

    def names(self) -> tuple[str, ...]:
        """Every member's name, in registration order."""
        self._fill()
        return tuple(self._entries)

    def entries(self) -> tuple[Entry, ...]:
        """Every member's entry, in registration order."""
        self._fill()
        return tuple(self._entries.values())

    def entry(self, name: str) -> Entry:
        """The entry of ``name``; a usage error naming the members for an unknown name."""
        self._fill()
        if name not in self._entries:
            raise UsageError(f"unknown {self.what} {name!r}; use one of {', '.join(self._entries)}.")
        return self._entries[name]

    def get(self, name: str) -> Any:
        """The object registered as ``name`` (its module imported now)."""
        return self.entry(name).load()

    def __contains__(self, name: object) -> bool:
        self._fill()
        return name in self._entries

    def __iter__(self) -> Iterator[str]:
        return iter(self.names())

    def view(self, value: Callable[[Entry], Any]) -> Mapping[str, Any]:
        """A read-only mapping name -> ``value(entry)``, always current (a member registered
        later is in it)."""
        return _View(self, value)


class _View(Mapping):
    """See :meth:`Registry.view`."""

    def __init__(self, registry: Registry, value: Callable[[Entry], Any]) -> None:
        self._registry, self._value = registry, value

    def __getitem__(self, name: str) -> Any:
        if name not in self._registry:
            raise KeyError(name)
        return self._value(self._registry.entry(name))

    def __iter__(self) -> Iterator[str]:
        return iter(self._registry.names())

    def __len__(self) -> int:
        return len(self._registry.names())


#: Synthesis methods: ``target`` a :class:`facesynth.domain.methods.Method` subclass; facts:
#: ``settings`` (the settings section it reads; a section facesynth does not declare comes with
#: ``settings_type``, its dataclass, and ``settings_defaults``), ``fitted`` (its source is a model
#: made by ``facesynth fit-method``), ``source_kind`` (the artifact kind it reads), ``streams`` (it
#: has a live form, ``facesynth stream`` runs it), ``searches`` and ``simplicity`` (for ``evaluate``).
METHODS = Registry("method", "facesynth.domain.methods")
#: Export formats (``facesynth export --format``, ``batch``'s outputs): ``target`` a writer
#: ``(Exportable, Path, ExportOptions) -> None``; facts: ``suffix``, ``needs`` (an optional extra).
EXPORT_FORMATS = Registry("export format", "facesynth.domain.exports")
#: Capture readers (a capture manifest's ``mocap`` column): ``target`` a
#: :class:`facesynth.domain.capture.readers.CaptureReader`, or a marker file's reader
#: ``path -> MarkerTake``; facts: ``suffixes``, ``needs`` (an optional extra).
CAPTURE_READERS = Registry("capture format", "facesynth.domain.capture")
#: Artifact kinds: ``target`` its :class:`facesynth.model.spec.Kind` (which holds its schema).
ARTIFACT_KINDS = Registry("artifact kind", "facesynth.model")
#: Grapheme-to-phoneme backends (text in a language other than English, ``align.language``):
#: ``target`` a function ``(text, language) -> [(word, IPA phones), ...]``; facts: ``languages``
#: (the primary language subtags it may read), ``installed`` (a function ``language -> bool``:
#: whether the packages it needs for that language are installed), ``needs`` (the optional extra).
G2P_BACKENDS = Registry("G2P backend", "facesynth.domain.speech.languages")


#: The registries by the name their docs tables use, with the facts each table shows (column
#: header, fact, value when the member does not say).
TABLES: dict[str, tuple[Registry, tuple[tuple[str, str, Any], ...]]] = {
    "methods": (METHODS, (("reads", "source_kind", "motiondb"), ("settings", "settings", "synthesize"),
                          ("streams", "streams", False))),
    "export-formats": (EXPORT_FORMATS, (("file", "suffix", ""), ("batch output", "batch", False))),
    "capture-formats": (CAPTURE_READERS, (("file names", "suffixes", ()),)),
    "artifact-kinds": (ARTIFACT_KINDS, ()),
}


def _cell(value: Any) -> str:
    if isinstance(value, bool):
        return "yes" if value else ""
    if isinstance(value, (tuple, list)):
        return ", ".join(f"`*{v}`" for v in value)
    return f"`{value}`" if value else ""


def markdown(table: str) -> str:
    """The docs table of one registry (``TABLES``): a row per member in registration order."""
    registry, facts = TABLES[table]
    head = ["name"] + [h for h, _, _ in facts] + ["what it is"]
    rows = [f"| {' | '.join(head)} |", "|" + "---|" * len(head)]
    for e in registry.entries():
        cells = [f"`{e.name}`"] + [_cell(e.facts.get(key, default)) for _, key, default in facts] + [e.summary]
        rows.append(f"| {' | '.join(cells)} |")
    return "\n".join(rows)


_TABLE = re.compile(r"(<!-- registry: ([\w-]+) -->\n)(?:.*?\n)?(<!-- /registry -->)", re.S)


def document(text: str) -> str:
    """``text`` with every registry table between its markers (``<!-- registry: NAME -->`` and
    ``<!-- /registry -->``) written anew from the registries."""
    return _TABLE.sub(lambda m: m.group(1) + markdown(m.group(2)) + "\n" + m.group(3), text)


def main(argv: list[str]) -> int:
    """``python -m facesynth.base.registry FILE...``: rewrite the registry tables of the docs."""
    for name in argv:
        path = Path(name)
        path.write_text(document(path.read_text(encoding="utf-8")), encoding="utf-8")
    return 0


if __name__ == "__main__":  # pragma: no cover
    # this module as imported: its registries are the ones the members' packages fill
    sys.exit(importlib.import_module("facesynth.base.registry").main(sys.argv[1:]))
