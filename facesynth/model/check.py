"""``facesynth check``: validate artifacts against their specification (:mod:`facesynth.model.spec`).

Like the NWB inspector, it reports every problem of a file, each as one sentence
``PATH: /key: problem``, instead of stopping at the first:

* the file is missing, not HDF5, of no or an unknown kind, or of another schema;
* a required group or dataset is missing, or a key is not in the specification;
* a dataset's dtype is wrong, or its shape disagrees with the specification: a fixed size
  differs, or a symbol (M markers, N nodes, ...) has two different sizes in one file;
* a required attribute (``units``, ``fps``, ...) is missing, of the wrong type or out of range;
* a group's ``encoding-type`` / ``encoding-version`` is missing or not the expected one;
* an external or soft link, a dataset stored in external files or a virtual dataset:
  an artifact must stay inside its file, so none of these is followed or read;
* a NaN or infinity in a dataset whose numbers must be finite;
* a size past the ``[limits]`` bounds (markers, nodes, frames, vertices, bytes of one dataset),
  which is reported without reading the dataset (a compression bomb is never expanded);
* an input named in the ``inputs`` provenance that no longer exists or whose sha256 no longer
  matches (relative paths are read from the current directory, as the writers stored them).

Reads are bounded: dtypes and shapes come from the file's metadata, and the finiteness scan
reads a dataset in blocks of rows of at most :data:`SCAN_ELEMENTS` numbers.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import h5py
import numpy as np

from facesynth.base import limits
from facesynth.base.hashing import sha256_of
from facesynth.base.limits import size_text

from .kinds import ENCODING_VERSION, PRODUCERS, SCHEMAS
from .spec import (
    COMMON_ATTRS,
    KINDS,
    MAX_FLOAT,
    MAX_INT,
    SYMBOLS,
    Attr,
    Dataset,
    Entry,
    Group,
    Kind,
    applies,
    parse_size,
)

#: Most numbers read at once by the finiteness scan (16 Mi: 64 MB of float32).
SCAN_ELEMENTS = 1 << 24

#: Deepest group nesting followed when looking for links in parts the specification does not declare.
MAX_DEPTH = 32


@dataclass(frozen=True)
class Problem:
    """One problem: the file, the HDF5 key ('' for the file as a whole) and one sentence."""

    path: str
    key: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.key}: {self.message}" if self.key else f"{self.path}: {self.message}"


@dataclass
class FileReport:
    """What :func:`check_file` found: the kind and schema read (None if unknown) and every problem."""

    path: Path
    kind: str | None = None
    schema: int | None = None
    problems: list[Problem] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.problems

    def lines(self) -> list[str]:
        """One line per problem, or ``PATH: ok (kind, schema N)``."""
        if self.ok:
            return [f"{self.path}: ok ({self.kind}, schema {self.schema})"]
        return [str(p) for p in self.problems]


def check_files(paths: Iterable[Path]) -> list[FileReport]:
    """Check every file; inputs named by several files are hashed once."""
    hashes: dict[Path, str] = {}
    return [check_file(Path(p), hashes) for p in paths]


def check_file(path: Path, hashes: dict[Path, str] | None = None) -> FileReport:
    """Check one file against the specification of its kind; ``hashes`` caches input sha256s."""
    path = Path(path)
    report = FileReport(path)
    say = lambda key, message: report.problems.append(Problem(str(path), key, message))  # noqa: E731
    if not path.exists():
        say("", "file not found.")
        return report
    if not path.is_file():
        say("", "is a folder, not an artifact file.")
        return report
    if not h5py.is_hdf5(path):
        say("", "not an HDF5 file, so not a facesynth artifact.")
        return report
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        say("", f"cannot be opened as HDF5 ({exc}).")
        return report
    with f:
        # size bounds apply; the memory available does not (the scan reads in bounded blocks)
        bounds = dataclasses.replace(bounds_in_force(), available=None)
        checker = _Checker(f, report, {} if hashes is None else hashes, bounds=bounds)
        try:
            checker.run()
        except OSError as exc:  # HDF5 could not read a part of the file: say so after what was found
            checker.say("", f"a part of the file cannot be read ({exc}); it is damaged.")
            checker.finish()
    return report


@dataclass(frozen=True)
class Bounds:
    """Size bounds a reader applies while validating: the largest size of each shape symbol
    (symbol -> (size, the setting that raises it)), the most bytes one dataset may declare, and
    the memory available (bytes, None if unknown)."""

    symbols: dict[str, tuple[int, str]]
    max_dataset_bytes: tuple[int, str]
    available: int | None = None

    def symbol(self, checker: "_Checker", key: str, symbol: str, size: int) -> None:
        if symbol in self.symbols and size > self.symbols[symbol][0]:
            limit, setting = self.symbols[symbol]
            checker.say(key, f"gives {symbol} ({SYMBOLS[symbol]}) = {size}, above {setting} = {limit}; "
                             f"if that is right, raise it with --set {setting}=...")

    def dataset(self, checker: "_Checker", key: str, ds: h5py.Dataset) -> bool:
        """Whether the dataset's declared size is within bounds (else one problem is said)."""
        nbytes = int(np.prod(ds.shape, dtype=np.float64) * ds.dtype.itemsize)
        limit, setting = self.max_dataset_bytes
        if nbytes > limit:
            checker.say(key, f"declares {nbytes / 1e6:.0f} MB ({_shape_text(ds.shape)} of {_dtype_name(ds.dtype)}), above "
                             f"{setting} = {limit / 1e6:.0f} MB; if that is right, raise it with --set {setting}=...")
            return False
        if self.available is not None and nbytes > self.available:

            checker.say(key, f"declares {size_text(nbytes)} but {size_text(self.available)} of memory is available; "
                             "read it on a machine with more memory.")
            return False
        return True


@dataclass
class Snapshot:
    """What :func:`validate` learnt of an open artifact: its kind, variant and symbol sizes."""

    path: Path
    kind: Kind
    variant: str | None
    sizes: dict[str, int]


def bounds_in_force() -> Bounds:
    """The :class:`Bounds` of the ``[limits]`` settings in force (:func:`facesynth.base.limits.current`)."""
    lim = limits.current()
    symbols = {}
    for names, setting in ((("M", "B"), "max_markers"), (("N", "R"), "max_nodes"), (("F", "Fo", "n"), "max_frames"),
                           (("V",), "max_vertices")):
        for name in names:
            symbols[name] = (int(getattr(lim, setting)), f"limits.{setting}")
    return Bounds(symbols, (int(lim.max_dataset_mb * 1e6), "limits.max_dataset_mb"), limits.mem_available())


def validate(f: h5py.File, path: Path, bounds: Bounds) -> tuple[list[Problem], Snapshot | None]:
    """The structural check of an open artifact that every reader runs before reading a value:
    kind, schema, groups, datasets, dtypes, shapes against the specification and ``bounds``,
    attributes, and no links, external storage or virtual datasets. It reads metadata only (no
    dataset values, no provenance hashes); values are checked as they are read (:func:`value_problem`)."""
    report = FileReport(Path(path))
    checker = _Checker(f, report, {}, scan=False, provenance=False, bounds=bounds)
    checker.run()
    snapshot = Snapshot(Path(path), checker.kind, checker.variant, checker.sizes) if checker.kind else None
    return report.problems, snapshot


def entry_at(kind: Kind, key: str) -> Dataset | None:
    """The specification of dataset ``key`` ('nodes/phone', '/clusters/aa/frames') in ``kind``."""
    entries: tuple[Entry, ...] = kind.root
    parts = [p for p in key.split("/") if p]
    for n, part in enumerate(parts):
        match = next((e for e in entries if e.name == part), None)
        if match is None:
            match = next((e for e in entries if isinstance(e, Group) and e.pattern), None)
        if match is None:
            return None
        if n == len(parts) - 1:
            return match if isinstance(match, Dataset) else None
        if not isinstance(match, Group):
            return None
        entries = match.children
    return None


def value_problem(snapshot: Snapshot, key: str, data: np.ndarray) -> str | None:
    """What is wrong with the values just read from ``key`` by its specification (finite, ``ge``,
    ``below``), or None."""
    e = entry_at(snapshot.kind, key)
    if e is None:
        return None
    data = np.asarray(data)
    if data.dtype.kind not in "fiu" or not data.size:  # only numbers have values to check
        return None
    # One pass each for the minimum and the maximum, no temporaries: a NaN makes both NaN and
    # an infinity is one of them, so finite extremes mean every value is finite.
    low, high = data.min(), data.max()
    if data.dtype.kind == "f":
        if applies(e.finite, snapshot.variant):
            if not (np.isfinite(low) and np.isfinite(high)):
                bad = int(data.size - np.count_nonzero(np.isfinite(data)))
                return f"{bad} non-finite value{'s' if bad > 1 else ''} (NaN or infinity) where every number must be finite"
            largest = max(abs(float(low)), abs(float(high)))
            if largest > MAX_FLOAT:
                return f"holds a magnitude of {largest:g}, beyond the largest an artifact holds ({MAX_FLOAT:g})"
        else:  # NaN marks a missing sample here; an infinity is never a measurement
            bad = int(np.count_nonzero(np.isinf(data)))
            if bad:
                return f"{bad} infinite value{'s' if bad > 1 else ''} where only finite numbers or NaN (missing) belong"
    if data.dtype.kind in "iu":
        extreme = max(abs(int(low)), abs(int(high)))
        if extreme > MAX_INT:
            return f"holds {extreme}, beyond the largest integer an artifact holds (2^53)"
    if e.ge is not None:
        if low < e.ge:  # NaN compares False: only where NaN is allowed
            return f"holds {low.item():g}, below the smallest allowed value {e.ge:g}"
    factor, symbol, offset = parse_size(e.below) if e.below is not None else (1, None, 0)
    if symbol is not None and symbol in snapshot.sizes:
        limit = factor * snapshot.sizes[symbol] + offset
        if high >= limit:
            return f"holds {high.item()}, but its values must stay below {e.below} = {limit}"
    return None


def written_problem(f: h5py.File, kind_name: str) -> tuple[str, str] | None:
    """The first (key, problem) of the values an artifact being written holds against its
    specification (non-finite where finite is required, magnitudes past :data:`MAX_FLOAT` /
    :data:`MAX_INT`, ``ge`` bounds), or None. Writers run it before an output is published, so a
    command never exits 0 having written a non-finite or out-of-range value. Reads in blocks."""
    kind = KINDS[kind_name]
    snapshot = Snapshot(Path(f.filename), kind, kind.variant(f.attrs), {})
    found: list[tuple[str, str]] = []

    def visit(name, obj):
        if found or not isinstance(obj, h5py.Dataset) or obj.dtype.kind not in "fiu" or not obj.shape or not obj.size:
            return
        if entry_at(kind, name) is None:
            return
        row = int(np.prod(obj.shape[1:], dtype=np.int64)) or 1
        step = max(1, SCAN_ELEMENTS // row)
        for a in range(0, obj.shape[0], step):
            problem = value_problem(snapshot, name, obj[a : a + step])
            if problem:
                found.append(("/" + name, problem))
                return

    f.visititems(visit)
    return found[0] if found else None


def _text(value) -> str:
    return value.decode("utf-8", "replace") if isinstance(value, bytes) else str(value)


def _dtype_name(dt: np.dtype) -> str:
    """'str' for any HDF5 string, else the numpy name ('float32', 'int64', 'bool', ...)."""
    if h5py.check_string_dtype(dt) is not None:
        return "str"
    if dt.kind == "b":
        return "bool"
    if dt.kind in "iuf":
        return dt.newbyteorder("=").name
    if h5py.check_vlen_dtype(dt) is not None:
        return "variable-length"
    return "compound" if dt.names else str(dt)


def _shape_text(shape) -> str:
    return "(" + ", ".join(str(s) for s in shape) + ("," if len(shape) == 1 else "") + ")"


def _show(value) -> str:
    """An attribute value as a person writes it: 0, 'cm', [6950, 92]."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    return repr(_text(value)) if isinstance(value, (str, bytes)) else str(value)


def _is_int(v) -> bool:
    return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))


def _count_nonfinite(ds: h5py.Dataset) -> int:
    """NaN and infinities in ``ds``, read in blocks of rows (chunk-aligned when chunked)."""
    if ds.size == 0 or ds.ndim == 0:
        return 0
    row = int(np.prod(ds.shape[1:], dtype=np.int64)) or 1
    step = max(1, SCAN_ELEMENTS // row)
    if ds.chunks:
        step = max(ds.chunks[0], step - step % ds.chunks[0])
    bad = 0
    for a in range(0, ds.shape[0], step):
        block = ds[a : a + step]
        bad += int(block.size - np.count_nonzero(np.isfinite(block)))
    return bad


@dataclass(frozen=True)
class _Seen:
    """One size a symbol was given: by ``key`` (``where`` says how), and the problems said before it."""

    value: int
    key: str
    where: str
    via: str
    order: int


class _Checker:
    """Checks one open file, collecting problems into its report in the order of the specification.

    Symbol sizes are collected while walking and compared when their scope ends (a pattern
    group's local symbols at the end of each group, the others at the end of the file): the
    size most keys agree on is taken as right, and each key that disagrees is one problem."""

    def __init__(self, f: h5py.File, report: FileReport, hashes: dict[Path, str], *, scan: bool = True,
                 provenance: bool = True, bounds: "Bounds | None" = None):
        self.f, self.report, self.hashes = f, report, hashes
        self.scan, self.provenance, self.bounds = scan, provenance, bounds
        self.sizes: dict[str, int] = {}  # each file-wide symbol's agreed size
        self.said: list[tuple[tuple, Problem]] = []
        self.seen: dict[str, list[_Seen]] = {}
        self.kind: Kind | None = None
        self.variant: str | None = None

    def say(self, key: str, message: str, order: tuple | None = None) -> None:
        order = order if order is not None else (len(self.said), 0)
        self.said.append((order, Problem(str(self.report.path), key, message)))

    def _settle(self, symbols) -> None:
        """Compare the sizes each of ``symbols`` was given; one problem per disagreeing key."""
        for symbol in symbols:
            seen = self.seen.pop(symbol, [])
            values = [s.value for s in seen]
            if not values:
                continue
            if len(set(values)) < 2:
                self.sizes.setdefault(symbol, values[0])
                continue
            right = max(dict.fromkeys(values), key=values.count)  # most keys agree; ties: the first seen
            self.sizes.setdefault(symbol, right)
            agree = [s for s in seen if s.value == right]
            others = f" (as do {len(agree) - 1} other key{'s' if len(agree) > 2 else ''})" if len(agree) > 1 else ""
            for n, s in enumerate(seen):
                if s.value != right:
                    self.say(s.key, f"{s.where} gives {symbol} = {s.value}{s.via}, but {agree[0].key} has "
                                    f"{symbol} = {right}{others}.", (s.order, -1, n))

    # ------------------------------------------------------------ the whole file

    def run(self) -> None:
        attrs = self.f.attrs
        found = _text(attrs["facesynth_kind"]) if "facesynth_kind" in attrs else None
        if found is None:
            self.say("/", "no 'facesynth_kind' attribute, so not a facesynth artifact.")
        elif found not in KINDS:
            self.say("/", f"unknown kind '{found}'; facesynth writes {', '.join(SCHEMAS)}.")
        else:
            self.report.kind = found
        schema = attrs.get("facesynth_schema")
        if schema is None:
            if found is not None:
                self.say("/", "no 'facesynth_schema' attribute; the file is damaged or from another tool.")
        elif not _is_int(schema):
            self.say("/", f"attribute 'facesynth_schema' is {_show(schema)}; expected an integer.")
        else:
            self.report.schema = int(schema)
            known_name = self.report.kind  # found, where it names a kind
            if known_name is not None and int(schema) != SCHEMAS[known_name]:
                self.say("/", f"'{known_name}' schema {int(schema)} is not the supported schema {SCHEMAS[known_name]}; "
                              f"rebuild it with this version's {PRODUCERS[known_name]}.")
        kind_name = self.report.kind
        if kind_name is not None and self.report.schema != SCHEMAS[kind_name]:
            kind_name = None  # a schema this version does not read: no specification to check against
        if found is not None:
            for a in COMMON_ATTRS:
                if a.name not in ("facesynth_kind", "facesynth_schema"):
                    self._attr(self.f, "/", a)
        if kind_name is not None:
            self.kind = KINDS[kind_name]
            self.variant = self.kind.variant(attrs)
            for a in self.kind.attrs:
                self._attr(self.f, "/", a)
            self._group(self.f, "/", self.kind.root)
        else:  # no specification to check against: only what would reach outside the file
            self._outside_tree(self.f, "/", 0)
        if found is not None and self.provenance:
            self._provenance()
        self.finish()

    def finish(self) -> None:
        """Settle the file-wide symbols and hand the problems to the report, in order."""
        self._settle(list(self.seen))
        self.report.problems = [p for _, p in sorted(self.said, key=lambda item: item[0])]

    # ------------------------------------------------------------ structure

    def _group(self, g: h5py.Group, key: str, entries: tuple[Entry, ...]) -> None:
        """The members of ``g`` against ``entries``: links, missing, unknown and each declared one."""
        prefix = "/" if key == "/" else key + "/"
        hard: dict[str, object] = {}
        names = sorted(g.keys())
        for name in names:
            link = g.get(name, getlink=True)
            if isinstance(link, h5py.HardLink):
                hard[name] = g[name]
            else:
                self._link(prefix + name, link)
        declared = {e.name: e for e in entries if not (isinstance(e, Group) and e.pattern)}
        pattern = next((e for e in entries if isinstance(e, Group) and e.pattern), None)
        for e in entries:
            if e is pattern:
                for name, obj in hard.items():
                    if name not in declared:
                        self._entry(obj, prefix + name, e)
            elif e.name in hard:
                self._entry(hard[e.name], prefix + e.name, e)
            elif e.name not in names and applies(e.required, self.variant):
                if isinstance(e, Group):
                    self.say(prefix + e.name, f"missing required group (encoding-type '{e.encoding}').")
                else:
                    dtype = " or ".join(e.dtype) if isinstance(e.dtype, tuple) else e.dtype
                    self.say(prefix + e.name, f"missing required dataset ({dtype}, shape {_shape_text(e.shape)}).")
        if pattern is None:
            for name, obj in hard.items():
                if name not in declared:
                    what = "group" if isinstance(obj, h5py.Group) else "dataset" if isinstance(obj, h5py.Dataset) else "object"
                    self.say(prefix + name, f"unexpected {what}; the '{self.report.kind}' schema {self.report.schema} "
                                            "specification has no such key.")
                    self._outside_tree(obj, prefix + name, 1)

    def _entry(self, obj, key: str, e: Entry) -> None:
        if isinstance(e, Group):
            if not isinstance(obj, h5py.Group):
                self.say(key, f"is a dataset; expected a group (encoding-type '{e.encoding}').")
                self._outside_tree(obj, key, 1)
                return
            self._encoding(obj, key, e.encoding)
            for a in e.attrs:
                self._attr(obj, key, a)
            self._group(obj, key, e.children)
            self._settle(e.local)
        elif not isinstance(obj, h5py.Dataset):
            self.say(key, "is a group; expected a dataset.")
            self._outside_tree(obj, key, 1)
        else:
            self._dataset(obj, key, e)

    def _encoding(self, g: h5py.Group, key: str, expected: str) -> None:
        found = g.attrs.get("encoding-type")
        if found is None:
            self.say(key, f"no 'encoding-type' attribute; expected '{expected}'.")
        elif _text(found) != expected:
            self.say(key, f"encoding-type is '{_text(found)}'; expected '{expected}'.")
        version = g.attrs.get("encoding-version")
        if version is None:
            self.say(key, f"no 'encoding-version' attribute; expected '{ENCODING_VERSION}'.")
        elif _text(version) != ENCODING_VERSION:
            self.say(key, f"encoding-version is '{_text(version)}'; this version reads '{ENCODING_VERSION}'.")

    def _dataset(self, ds: h5py.Dataset, key: str, e: Dataset) -> None:
        outside = self._outside_dataset(ds, key)
        allowed = e.dtype if isinstance(e.dtype, tuple) else (e.dtype,)
        found = _dtype_name(ds.dtype)
        if found not in allowed:
            self.say(key, f"dtype {found}; expected {' or '.join(allowed)}.")
        shape = ds.shape
        if shape is None:
            self.say(key, f"has no data (an empty dataspace); expected shape {_shape_text(e.shape)}.")
        else:
            self._shape(key, shape, e.shape)
        for a in e.attrs:
            self._attr(ds, key, a)
        if shape is not None and not outside and self.bounds is not None and not self.bounds.dataset(self, key, ds):
            return
        if (self.scan and not outside and found in ("float32", "float64") and shape and applies(e.finite, self.variant)):
            try:
                bad = _count_nonfinite(ds)
            except OSError as exc:
                self.say(key, f"cannot be read ({exc}).")
                return
            if bad:
                self.say(key, f"{bad} non-finite value{'s' if bad > 1 else ''} (NaN or infinity) where every "
                              "number must be finite.")

    def _shape(self, key: str, shape: tuple[int, ...], expected: tuple) -> None:
        if len(shape) != len(expected):
            self.say(key, f"shape {_shape_text(shape)} has {len(shape)} dimension{'s' if len(shape) != 1 else ''}; "
                          f"expected {len(expected)}: {_shape_text(expected)}.")
            return
        for axis, (size, want) in enumerate(zip(shape, expected)):
            self._size(key, f"shape {_shape_text(shape)}", axis, size, want)

    def _size(self, key: str, where: str, axis: int, size: int, want) -> None:
        """Check one size against a shape entry: a fixed size now, a symbol's size when its scope is settled."""
        factor, symbol, offset = parse_size(want)
        if symbol is None:
            if size != offset:
                self.say(key, f"{where} has {size} in axis {axis}; expected {offset}.")
            return
        if size < offset or (size - offset) % factor:
            self.say(key, f"{where} has {size} in axis {axis}, which is not {want} for any whole {symbol}.")
            return
        if self.bounds is not None:
            self.bounds.symbol(self, key, symbol, (size - offset) // factor)
        via = "" if want == symbol else f" ({want} = {size})"
        self.seen.setdefault(symbol, []).append(_Seen((size - offset) // factor, key, where, via, len(self.said)))

    # ------------------------------------------------------------ attributes

    def _attr(self, obj, key: str, a: Attr) -> None:
        try:
            present = a.name in obj.attrs
        except OSError as exc:
            self.say(key, f"attribute '{a.name}' cannot be read ({exc}).")
            return
        if not present:
            if applies(a.required, self.variant):
                self.say(key, f"missing attribute '{a.name}' ({a.type}{': ' + a.doc if a.doc else ''}).")
            return
        try:
            value = obj.attrs[a.name]
        except OSError as exc:
            self.say(key, f"attribute '{a.name}' cannot be read ({exc}).")
            return
        name = f"attribute '{a.name}'"
        if a.type in ("str", "json"):
            if not isinstance(value, (str, bytes)):
                self.say(key, f"{name} is {_show(value)}; expected a string.")
                return
            value = _text(value)
            if a.type == "json":
                try:
                    json.loads(value)
                except ValueError as exc:
                    self.say(key, f"{name} is not valid JSON ({exc}).")
                    return
            if a.choices and value not in a.choices:
                self.say(key, f"{name} is '{value}'; expected {' or '.join(repr(c) for c in a.choices)}.")
            return
        if a.type == "ints":
            arr = np.asarray(value)
            if arr.ndim != 1 or arr.dtype.kind not in "iu":
                self.say(key, f"{name} is {_show(value)}; expected a list of integers.")
                return
            if a.shape:
                if len(arr) != len(a.shape):
                    self.say(key, f"{name} has {len(arr)} values; expected {len(a.shape)} {_shape_text(a.shape)}.")
                    return
                for axis, (size, want) in enumerate(zip(arr.tolist(), a.shape)):
                    self._size(key, f"{name} {_shape_text(arr.tolist())}", axis, int(size), want)
            return
        ok = _is_int(value) if a.type == "int" else (_is_int(value) or isinstance(value, (float, np.floating)))
        if not ok:
            self.say(key, f"{name} is {_show(value)}; expected {'an integer' if a.type == 'int' else 'a number'}.")
            return
        v = float(value)
        for bound, holds, text in ((a.ge, lambda b: v >= b, ">="), (a.gt, lambda b: v > b, ">"), (a.le, lambda b: v <= b, "<=")):
            if bound is not None and not holds(bound):
                self.say(key, f"{name} is {_show(value)}; it must be {text} {bound:g}.")

    # ------------------------------------------------------------ what reaches outside the file

    def _link(self, key: str, link) -> None:
        if isinstance(link, h5py.ExternalLink):
            self.say(key, f"an external link to '{link.path}' in '{link.filename}'; an artifact must stay inside its file.")
        elif isinstance(link, h5py.SoftLink):
            self.say(key, f"a soft link to '{link.path}'; artifacts hold no links.")
        else:
            self.say(key, "a user-defined link; artifacts hold no links.")

    def _outside_dataset(self, ds: h5py.Dataset, key: str) -> bool:
        """Report (and return True for) data stored outside the file: external storage or a virtual dataset."""
        if ds.is_virtual:
            self.say(key, "a virtual dataset (its data lives in other files); an artifact must stay inside its file.")
            return True
        if ds.external:
            names = ", ".join(sorted({_text(name) for name, *_ in ds.external}))
            self.say(key, f"stored in external files ({names}); an artifact must stay inside its file.")
            return True
        return False

    def _outside_tree(self, obj, key: str, depth: int) -> None:
        """Links, external storage and virtual datasets anywhere below ``obj`` (no specification)."""
        if isinstance(obj, h5py.Dataset):
            self._outside_dataset(obj, key)
            return
        if not isinstance(obj, h5py.Group) or depth > MAX_DEPTH:
            return
        prefix = "/" if key == "/" else key + "/"
        for name in sorted(obj.keys()):
            link = obj.get(name, getlink=True)
            if isinstance(link, h5py.HardLink):
                self._outside_tree(obj[name], prefix + name, depth + 1)
            else:
                self._link(prefix + name, link)

    # ------------------------------------------------------------ provenance

    def _provenance(self) -> None:
        raw = self.f.attrs.get("inputs")
        if raw is None or not isinstance(raw, (str, bytes)):
            return  # reported with the root attributes
        try:
            records = json.loads(_text(raw))
        except ValueError:
            return  # reported with the root attributes
        if not isinstance(records, list):
            self.say("/", "attribute 'inputs' is not a JSON list of {path, kind, sha256} records.")
            return
        for i, r in enumerate(records):
            if not (isinstance(r, dict) and isinstance(r.get("path"), str) and isinstance(r.get("sha256"), str)):
                self.say("/", f"inputs[{i}] is not a {{path, kind, sha256}} record.")
                continue
            p = Path(r["path"])
            where = " (relative paths are read from the current directory)" if not p.is_absolute() else ""
            if not p.exists():
                self.say("/", f"input '{p}' (inputs[{i}]) is not found{where}.")
                continue
            if not p.is_file():
                self.say("/", f"input '{p}' (inputs[{i}]) is not a file.")
                continue
            resolved = p.resolve()
            if resolved not in self.hashes:
                try:
                    self.hashes[resolved] = sha256_of(p)
                except OSError as exc:
                    self.say("/", f"input '{p}' (inputs[{i}]) cannot be read ({exc.strerror or exc}).")
                    continue
            now = self.hashes[resolved]
            if now != r["sha256"]:
                self.say("/", f"input '{p}' (inputs[{i}]) has changed since this file was made (its sha256 "
                              f"starts {now[:12]} now, {r['sha256'][:12]} when recorded).")
