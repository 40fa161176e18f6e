"""The HDF5 artifact contract (see ``docs/file-format.md``).

Every artifact is one ``.h5`` file stamped with its kind, schema, producing version,
the resolved configuration that made it and the provenance (path, kind, sha256) of the
artifacts it was made from. Readers check kind and schema; writes are atomic, and the outputs
of a command that writes several are published together (:func:`published_together`).
"""

from __future__ import annotations

import contextlib
import contextvars
import dataclasses
import errno
import json
import mmap
import os
import re
import shutil
import signal
import threading
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

import h5py
import numpy as np

from facesynth import __version__
from facesynth.base.errors import ArtifactError, InputError, OutputExistsError
from facesynth.base.hashing import sha256_of
from facesynth.base.opencl import aligned_empty

from .check import Snapshot, bounds_in_force, validate, value_problem, written_problem
from .kinds import ENCODING_VERSION, PRODUCERS, SCHEMAS

STR = h5py.string_dtype("utf-8")


def _writable_folder(path: Path) -> None:
    """Refuse an output whose folder is missing or not writable."""
    folder = path.parent
    if not folder.is_dir():
        raise OutputExistsError(f"{path}: the output folder {folder} does not exist; create it first.")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise OutputExistsError(f"{path}: the output folder {folder} is not writable; choose another place.")


def check_output(path: Path, overwrite: bool) -> None:
    """Refuse, before any work, an output that cannot be written: an existing file without
    ``overwrite``, a folder (an output here is one file; ``--overwrite`` does not delete
    folders), or a missing or read-only folder. Stale temporary files of this output left by
    killed runs are removed."""
    path = Path(path)
    if path.is_dir():
        raise OutputExistsError(f"{path}: is a folder, but this output is one file; give a file name (e.g. inside that folder).")
    if path.exists() and not overwrite:
        raise OutputExistsError(f"{path}: output exists; pass --overwrite to replace it or choose another path.")
    _writable_folder(path)
    clean_stale_temporaries(path)


def check_output_folder(path: Path, what: str, overwrite: bool | None = None) -> None:
    """Refuse an output folder (``what``: 'the report', 'the images') whose path is a file, one
    that exists and is not empty when ``overwrite`` is False (None: not checked), or whose parent
    is missing or read-only."""
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise OutputExistsError(f"{path}: is a file, but this output is a folder (for {what}); give a folder path.")
    if overwrite is False and path.is_dir() and any(path.iterdir()):
        raise OutputExistsError(f"{path}: is not empty; pass --overwrite to replace the folder or choose another path.")
    _writable_folder(path)
    clean_stale_temporaries(path)


#: Temporary outputs are named ``NAME.tmp-PID`` in the output's folder (with a suffix, e.g.
#: ``.wav``, for a helper file of that output).
_TEMP = re.compile(r"^(?P<name>.+)\.tmp-(?P<pid>\d+)(?:\.[A-Za-z0-9]+)?$")


def temporary_path(path: Path) -> Path:
    """The temporary name of ``path`` for this process: ``NAME.tmp-PID`` beside it."""
    path = Path(path)
    return path.with_name(f"{path.name}.tmp-{os.getpid()}")


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    return True


def clean_stale_temporaries(path: Path) -> list[Path]:
    """Remove ``NAME.tmp-PID`` files and folders of the output ``path`` left by runs that were
    killed (their process is gone); returns what was removed. Those of live processes stay."""
    path = Path(path)
    removed = []
    try:
        entries = list(path.parent.iterdir())
    except OSError:
        return removed
    for entry in entries:
        m = _TEMP.match(entry.name)
        if not m or m.group("name") != path.name or int(m.group("pid")) == os.getpid() or _alive(int(m.group("pid"))):
            continue
        with contextlib.suppress(OSError):
            if entry.is_dir() and not entry.is_symlink():
                shutil.rmtree(entry)
            else:
                entry.unlink()
            removed.append(entry)
    return removed


def _fsync_folder(folder: Path) -> None:
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def publish(tmp: Path, path: Path, overwrite: bool) -> None:
    """Move the finished file ``tmp`` to ``path``. Without ``overwrite`` the final name is created
    exclusively (a hard link, or where the file system has none an exclusive placeholder then
    replaced), so of two writers racing for one output exactly one wins and the other gets
    OutputExistsError; with ``overwrite``, ``os.replace``."""
    if overwrite:
        os.replace(tmp, path)
    else:
        lost = OutputExistsError(f"{path}: another process wrote this output while this one ran; its file is kept. "
                                 "Pass --overwrite to replace it or choose another path.")
        try:
            os.link(tmp, path)
        except FileExistsError:
            raise lost from None
        except OSError:  # no hard links here (some network and FUSE file systems)
            try:
                os.close(os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644))
            except FileExistsError:
                raise lost from None
            os.replace(tmp, path)
        else:
            os.unlink(tmp)
    _fsync_folder(path.parent)
    _note_published(path)


#: The outputs published while :func:`recording_published` runs (the command line's record of
#: what an interrupt leaves behind), and the open group of :func:`published_together`.
_PUBLISHED: contextvars.ContextVar[list[Path] | None] = contextvars.ContextVar("facesynth_published", default=None)
_GROUP: contextvars.ContextVar[list[_Pending] | None] = contextvars.ContextVar("facesynth_group", default=None)


def _note_published(path: Path) -> None:
    published = _PUBLISHED.get()
    if published is not None:
        published.append(Path(path))


@contextlib.contextmanager
def recording_published(published: list[Path]) -> Iterator[list[Path]]:
    """Append to ``published`` every output published in the body (files and folders, in order),
    so that a command interrupted after writing something can say what it wrote."""
    token = _PUBLISHED.set(published)
    try:
        yield published
    finally:
        _PUBLISHED.reset(token)


def _aside(path: Path) -> Path:
    """Where the previous version of output ``path`` waits until its replacement is in place."""
    return path.with_name(f"{path.name}.old.tmp-{os.getpid()}")


def _remove(path: Path) -> None:
    """Remove a file or folder (nothing if missing)."""
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()


def _publish_folder(tmp: Path, path: Path, overwrite: bool) -> Path | None:
    """Rename the finished folder ``tmp`` to ``path``; returns where a replaced previous folder
    was moved aside (the caller removes it), or None. A failed rename puts it back."""
    lost = OutputExistsError(f"{path}: another process wrote this output folder while this one ran; it is kept. "
                             "Pass --overwrite to replace it or choose another path.")
    old = None
    if path.is_dir() and not any(path.iterdir()):
        pass  # an empty folder is replaced by the rename
    elif path.exists() and overwrite:
        old = _aside(path)
        _remove(old)
        os.rename(path, old)
    elif path.exists():
        raise lost
    try:
        os.rename(tmp, path)
    except OSError as exc:
        if old is not None:
            with contextlib.suppress(OSError):
                os.rename(old, path)
        if exc.errno in (errno.EEXIST, errno.ENOTEMPTY):
            raise lost from None
        raise
    _fsync_folder(path.parent)
    _note_published(path)
    return old


@dataclasses.dataclass
class _Pending:
    """A finished output (a temporary file or folder) waiting for its group to be published."""

    tmp: Path
    path: Path
    overwrite: bool
    folder: bool
    previous: Path | None = None  # the output it replaced, kept until the whole group is in place

    def publish(self) -> None:
        if self.folder:
            self.previous = _publish_folder(self.tmp, self.path, self.overwrite)
            return
        if self.overwrite and self.path.is_file():
            aside = _aside(self.path)
            _remove(aside)
            try:
                os.link(self.path, aside)
            except OSError:  # no hard links here: a copy
                shutil.copy2(self.path, aside)
            self.previous = aside
        publish(self.tmp, self.path, self.overwrite)

    def undo(self) -> None:
        """Take a published output back: the previous version returns, or nothing stays."""
        with contextlib.suppress(OSError):
            if self.previous is None:
                _remove(self.path)
            elif self.folder:
                _remove(self.path)
                os.rename(self.previous, self.path)
            else:
                os.replace(self.previous, self.path)
        published = _PUBLISHED.get()
        if published is not None and self.path in published:
            published.remove(self.path)

    def discard(self) -> None:
        _remove(self.tmp)

    def finish(self) -> None:
        if self.previous is not None:
            _remove(self.previous)


@contextlib.contextmanager
def _signals_held(caught: list[int]) -> Iterator[None]:
    """Hold SIGINT and SIGTERM for the body (a few renames): one that arrives is appended to
    ``caught`` and delivered, to the handlers the body found, when it ends. Only the main thread
    sets handlers; elsewhere the body runs as is (signals interrupt the main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        handler = signal.getsignal(signum)
        if handler is not None and handler != signal.SIG_IGN:  # None: set outside Python, not restorable
            previous[signum] = signal.signal(signum, lambda number, frame: caught.append(number))
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
        for signum in dict.fromkeys(caught):
            signal.raise_signal(signum)


@contextlib.contextmanager
def published_together() -> Iterator[None]:
    """Publish the outputs finished in the body (by :func:`atomic_path`, :func:`atomic_folder`
    and so :func:`write_artifact`) together when it ends: all of them, or none.

    Until then each waits under its temporary name. An exception, Ctrl-C or SIGTERM in the body
    removes them all. Publishing is a rename per output with SIGINT and SIGTERM held: one that
    arrives meanwhile, or an output that cannot be published (another process took its name),
    takes back those already published (a replaced output returns) before the interrupt or
    error goes on. Only a ``kill -9`` between two renames can leave part of the group, each
    output complete. Nested groups join the outermost one.
    """
    if _GROUP.get() is not None:
        yield
        return
    pending: list[_Pending] = []
    token = _GROUP.set(pending)
    try:
        yield
    except BaseException:
        for item in pending:
            item.discard()
        raise
    finally:
        _GROUP.reset(token)
    done: list[_Pending] = []
    caught: list[int] = []
    with _signals_held(caught):
        try:
            for item in pending:
                item.publish()
                done.append(item)
            if caught:  # interrupted while publishing: none of the outputs stays
                done.reverse()
                for item in done:
                    item.undo()
            else:
                for item in done:
                    item.finish()
        except BaseException:
            for item in reversed(done):
                item.undo()
            for item in pending[len(done):]:
                item.discard()
            raise


def _staged(tmp: Path, path: Path, overwrite: bool, folder: bool) -> bool:
    """Hand a finished temporary output to the open group (True), or False when there is none."""
    group = _GROUP.get()
    if group is None:
        return False
    group.append(_Pending(tmp, path, overwrite, folder))
    return True


@contextlib.contextmanager
def atomic_path(path: Path, overwrite: bool = False) -> Iterator[Path]:
    """Yield a temporary path beside ``path`` (``NAME.tmp-PID``); on success fsync it and
    :func:`publish` it at ``path`` (inside :func:`published_together`, when the group is).

    On any exception, Ctrl-C or SIGTERM (which the command line turns into an exception) the
    temporary file is removed; a ``kill -9`` leaves it under its temporary name, never at
    ``path``, and the next run writing ``path`` removes it.
    """
    path = Path(path)
    check_output(path, overwrite)
    tmp = temporary_path(path)
    staged = False
    try:
        yield tmp
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        staged = _staged(tmp, path, overwrite, folder=False)
        if not staged:
            publish(tmp, path, overwrite)
    finally:
        if not staged:
            with contextlib.suppress(FileNotFoundError):
                tmp.unlink()


@contextlib.contextmanager
def atomic_folder(path: Path, what: str, overwrite: bool = False) -> Iterator[Path]:
    """Yield a temporary folder beside the output folder ``path`` (``NAME.tmp-PID``); on success
    rename it into place (inside :func:`published_together`, when the group is). An existing
    ``path`` that is not empty is refused without ``overwrite`` (and the rename itself refuses a
    folder another process made meanwhile); with it, the old folder is moved aside and removed
    after the new one is in place. On failure the temporary folder is removed."""
    path = Path(path)
    check_output_folder(path, what, overwrite)
    tmp = temporary_path(path)
    if tmp.exists():
        shutil.rmtree(tmp)
    tmp.mkdir()
    staged = False
    try:
        yield tmp
        staged = _staged(tmp, path, overwrite, folder=True)
        if not staged:
            old = _publish_folder(tmp, path, overwrite)
            if old is not None:
                _remove(old)
    finally:
        if not staged and tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def input_record(path: Path) -> dict:
    """Provenance entry of one input file: path, kind (if an artifact) and sha256.

    For an artifact this command opened with :func:`open_artifact` the kind comes from that
    validated snapshot (the file is not opened again), and a path that now names another file
    (replaced while the command ran) is refused rather than recorded with the wrong hash."""
    path = Path(path)
    where = os.path.abspath(path)  # a file of the same name opened from another folder is another file
    live = next(((h, s) for h, s in _live_snapshots() if _OPENED_AT.get(h) == where), None)
    if live is not None:
        handle, snapshot = live
        with contextlib.suppress(OSError):
            held, now = os.fstat(handle), os.stat(path)
            if (held.st_dev, held.st_ino) != (now.st_dev, now.st_ino):
                raise InputError(f"{path}: was replaced while this command ran; run the command again.")
        return {"path": str(path), "kind": snapshot.kind.name, "sha256": sha256_of(path)}
    kind = None
    try:
        if h5py.is_hdf5(path):
            with h5py.File(path, "r") as f:
                kind = f.attrs.get("facesynth_kind")
    except OSError:
        kind = None
    return {"path": str(path), "kind": kind, "sha256": sha256_of(path)}


def recorded_inputs(path: Path, kind: str) -> list[dict]:
    """The ``inputs`` provenance records ({path, kind, sha256}) of the ``kind`` artifact at
    ``path``; [] when the attribute cannot be parsed."""
    with open_artifact(path, kind) as f:
        try:
            records = json.loads(str(attr(f, "inputs")))
        except ValueError:
            return []
    return [r for r in records if isinstance(r, dict)] if isinstance(records, list) else []


def input_records_in_background(paths: Sequence[Path]) -> Callable[[], list[dict]]:
    """Start computing :func:`input_record` of each path on a daemon thread; returns a function
    that waits for the records (re-raising an error of the thread). Hashing a database of a
    few hundred MB takes a few tenths of a second of one core, so it runs while other work does;
    a command that fails meanwhile does not wait for it."""
    outcome: dict = {}

    def work() -> None:
        try:
            outcome["records"] = [input_record(p) for p in paths]
        except BaseException as exc:  # handed to the waiting thread
            outcome["error"] = exc

    thread = threading.Thread(target=work, name="facesynth-input-hashes", daemon=True)
    thread.start()

    def wait() -> list[dict]:
        thread.join()
        if "error" in outcome:
            raise outcome["error"]
        return outcome["records"]
    return wait


@contextlib.contextmanager
def write_artifact(
    path: Path,
    kind: str,
    *,
    config: str | dict = "{}",
    inputs: Sequence[Path] = (),
    records: Sequence[dict] | None = None,
    overwrite: bool = False,
) -> Iterator[h5py.File]:
    """Open a new artifact of ``kind`` for writing; it appears at ``path`` only when complete.

    ``config`` is the JSON (or dict) of the resolved settings used; ``inputs`` the files it
    was made from, recorded with their sha256 (or pass their ``records``, already computed
    with :func:`input_record`, e.g. while other work ran).
    """
    if kind not in SCHEMAS:
        raise ValueError(f"unknown artifact kind {kind!r}")
    records = list(records) if records is not None else [input_record(p) for p in inputs]
    with atomic_path(path, overwrite) as tmp:
        with h5py.File(tmp, "w", track_order=True) as f:
            f.attrs["facesynth_kind"] = kind
            f.attrs["facesynth_schema"] = SCHEMAS[kind]
            f.attrs["facesynth_version"] = __version__
            f.attrs["config"] = config if isinstance(config, str) else json.dumps(config, sort_keys=True)
            f.attrs["inputs"] = json.dumps(records)
            yield f
            problem = written_problem(f, kind)
            if problem:
                sources = ", ".join(r["path"] for r in records) or "the inputs"
                raise ArtifactError(f"{path}: {problem[0]}: the result {problem[1]}, so it was not written; an input "
                                    f"({sources}) holds numbers out of range: check it with `facesynth check`.")


#: What :func:`open_artifact` validated, by the operating-system file handle of the open file
#: (``h5py`` hands out a new File object for ``dataset.file``; the handle is the same).
_SNAPSHOTS: dict[int, tuple[Snapshot, tuple[int, int]]] = {}  # handle -> (snapshot, (device, inode))
#: The absolute path each of those files was opened at (its snapshot keeps the path as given).
_OPENED_AT: dict[int, str] = {}


def _live_snapshots() -> Iterator[tuple[int, Snapshot]]:
    """(handle, snapshot) of the files still open on the inode they were validated on; others are forgotten."""
    for handle, (snap, ids) in list(_SNAPSHOTS.items()):
        try:
            st = os.fstat(handle)
        except OSError:
            st = None
        if st is None or (st.st_dev, st.st_ino) != ids:
            _SNAPSHOTS.pop(handle, None)
            _OPENED_AT.pop(handle, None)
            continue
        yield handle, snap


def _handle(f: h5py.File) -> int | None:
    try:
        return int(f.id.get_vfd_handle())
    except (ValueError, TypeError, RuntimeError, OSError):
        return None


def snapshot_of(f: h5py.File):
    """The :class:`facesynth.model.check.Snapshot` of a file opened by :func:`open_artifact` (or None)."""
    handle = _handle(f)
    if handle is None or handle not in _SNAPSHOTS:
        return None
    snap = dict(_live_snapshots()).get(handle)
    return snap if snap is not None and str(snap.path) == f.filename else None


def _reason(exc: BaseException) -> str:
    """The useful part of an HDF5 error message ('truncated file: eof = 61, ...')."""
    text = str(exc)
    m = re.search(r"\(([^()]*)\)\s*$", text)
    return (m.group(1) if m else text).strip() or type(exc).__name__


def damaged(path: Path, kind: str, where: str, exc: BaseException) -> ArtifactError:
    """The error for an HDF5 part that cannot be read: the file is damaged (e.g. truncated)."""
    return ArtifactError(f"{path}: {where}cannot be read ({_reason(exc)}); the file is damaged or truncated: "
                         f"make it again with {PRODUCERS.get(kind, '`facesynth`')}.")


def artifact_kind(path: Path) -> str | None:
    """The ``facesynth_kind`` of the artifact at ``path`` (e.g. 'motion', 'meshanim', 'curves'),
    or None when the file is missing, no HDF5 file or no facesynth artifact. Only peeks at the
    root attribute: read the artifact itself with :func:`open_artifact`."""
    path = Path(path)
    try:
        if not path.is_file() or not h5py.is_hdf5(path):
            return None
        with h5py.File(path, "r") as f:
            found = f.attrs.get("facesynth_kind")
    except (OSError, RuntimeError, KeyError, ValueError):
        return None
    found = found.decode("utf-8", "replace") if isinstance(found, bytes) else found
    return found if isinstance(found, str) and found in SCHEMAS else None


def open_artifact(path: Path, kind: str) -> h5py.File:
    """Open an artifact for reading after checking it: the one place every reader goes through.

    It checks that the file is an HDF5 file of ``kind`` at a known schema, then validates its
    structure against the specification (:func:`facesynth.model.check.validate`): every group and
    dataset, dtype and shape, the ``[limits]`` size bounds and the memory available, attributes,
    and nothing that reaches outside the file (external or soft links, external storage,
    virtual datasets). All this reads metadata only, before a byte of data is read; values are
    checked as :func:`read` (or :class:`RowReader`) reads them. A damaged or truncated file is an
    ArtifactError naming the file, never an HDF5 traceback.
    """
    path = Path(path)
    producer = PRODUCERS.get(kind, "`facesynth`")
    if not path.exists():
        raise InputError(f"{path}: file not found; make it with {producer} first.")
    if path.is_dir():
        raise InputError(f"{path}: is a folder; expected a facesynth '{kind}' artifact file.")
    try:
        is_hdf5 = h5py.is_hdf5(path)
    except OSError as exc:
        raise InputError(f"{path}: cannot be read ({exc.strerror or exc}); check its permissions.") from None
    if not is_hdf5:
        raise ArtifactError(f"{path}: not an HDF5 file; expected a facesynth '{kind}' artifact.")
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise damaged(path, kind, "", exc) from None
    try:
        found = f.attrs.get("facesynth_kind")
        found = found.decode("utf-8", "replace") if isinstance(found, bytes) else found
        if found != kind:
            found_text = f"a '{found}' artifact" if isinstance(found, str) else "no facesynth artifact"
            raise ArtifactError(
                f"{path}: found {found_text} but expected '{kind}'; pass the output of {PRODUCERS[kind]}.")
        schema = f.attrs.get("facesynth_schema", -1)
        if not isinstance(schema, (int, np.integer)) or int(schema) != SCHEMAS[kind]:
            raise ArtifactError(
                f"{path}: '{kind}' schema {schema} is not the supported schema {SCHEMAS[kind]}; "
                f"rebuild it with this version's {PRODUCERS[kind]}.")
        problems, snapshot = validate(f, path, bounds_in_force())
        if problems:
            # a size past a bound first: it says what to raise, and the rest may follow from it
            p = next((q for q in problems if "--set limits." in q.message or "memory" in q.message), problems[0])
            more = f" (and {len(problems) - 1} more problem{'s' * (len(problems) > 2)})" if len(problems) > 1 else ""
            message = p.message.rstrip(".")
            todo = "" if "--set limits." in message or "memory" in message else (
                f"; make it again with {producer} (`facesynth check {path}` lists every problem)")
            raise ArtifactError(f"{path}: {p.key}: {message}{more}{todo}.")
    except ArtifactError:
        f.close()
        raise
    except (OSError, RuntimeError, KeyError, ValueError) as exc:  # metadata HDF5 cannot read
        f.close()
        raise damaged(path, kind, "", exc) from None
    handle = _handle(f)
    if handle is not None and snapshot is not None:
        st = os.fstat(handle)
        _SNAPSHOTS[handle] = (snapshot, (st.st_dev, st.st_ino))
        _OPENED_AT[handle] = os.path.abspath(path)
    return f


def read(f: h5py.File, key: str, aligned: int = 0) -> np.ndarray:
    """Read dataset ``key`` fully, naming the file and key if it is missing or cannot be read,
    and check its values against the specification (finite, in range) when ``f`` was opened
    by :func:`open_artifact`. With ``aligned`` (bytes) the array's data starts on that
    boundary (an OpenCL CPU device can then use it in place)."""
    try:
        ds = f[key]
    except KeyError:
        raise ArtifactError(f"{f.filename}: missing dataset '{key}'; the file is damaged or from another tool.") from None
    try:
        if aligned and ds.shape and ds.size and ds.dtype.kind in "fiu":

            data = aligned_empty(ds.shape, ds.dtype, aligned)
            ds.read_direct(data)
        else:
            data = ds[()]
    except (OSError, RuntimeError) as exc:
        kind = f.attrs.get("facesynth_kind", "")
        raise damaged(Path(f.filename), kind if isinstance(kind, str) else "", f"/{key.lstrip('/')}: ", exc) from None
    check_values(f, key, data)
    return data


def check_values(f: h5py.File, key: str, data: np.ndarray) -> None:
    """Refuse values of ``key`` that break its specification (non-finite, out of range)."""
    snapshot = snapshot_of(f)
    if snapshot is None:
        return
    problem = value_problem(snapshot, key, data)
    if problem:
        raise ArtifactError(f"{f.filename}: /{key.lstrip('/')}: {problem}; the file is damaged or was changed "
                            f"by another tool: make it again with {PRODUCERS.get(snapshot.kind.name, '`facesynth`')}.")


def read_rows(dataset: h5py.Dataset, rows: slice, out: np.ndarray) -> np.ndarray:
    """Read rows ``rows`` (a slice with start and stop, step 1) of a 2-D dataset into ``out``,
    a C-contiguous array of shape (rows, columns); HDF5 converts to ``out``'s dtype.

    Unlike ``dataset[rows]`` nothing is allocated, so a loop over row blocks reuses one
    buffer instead of faulting in fresh pages for every block. Returns ``out``.
    """
    count = rows.stop - rows.start
    if out.shape != (count, dataset.shape[1]) or not out.flags.c_contiguous:
        raise ValueError(f"read_rows: out must be C-contiguous ({count}, {dataset.shape[1]}), not {out.shape}")
    file_space = dataset.id.get_space()
    file_space.select_hyperslab((rows.start, 0), out.shape)
    dataset.id.read(h5py.h5s.create_simple(out.shape), file_space, out)
    return out


class RowReader:
    """Row blocks of a 2-D dataset as float32, read in place from the page cache when the
    storage allows.

    When the dataset is stored uncompressed as little-endian float32 in chunks that span
    whole rows (as ``build-db`` writes the pair terms) in a plain HDF5 file, a block of rows
    that lies inside one chunk is a read-only view of a memory map of the file at the chunk's
    address: no copy, no buffer. Anything else (other layouts, filters, external storage, a
    block across chunks) is read through HDF5 into a reused buffer with :func:`read_rows`.
    Use as a context manager.
    """

    def __init__(self, dataset: h5py.Dataset, block: int):
        self.dataset, self.block = dataset, block
        self.buffer: np.ndarray | None = None
        self.map: mmap.mmap | None = None
        self.mapped: tuple[int, int] | None = None  # byte range of the last mapped block
        self.chunk_rows = 0
        plist, file = dataset.id.get_create_plist(), dataset.file
        if (dataset.ndim == 2 and dataset.dtype == np.dtype("<f4") and plist.get_layout() == h5py.h5d.CHUNKED
                and dataset.chunks[1] == dataset.shape[1] and plist.get_nfilters() == 0
                and plist.get_external_count() == 0 and file.driver == "sec2"
                and file.id.get_create_plist().get_userblock() == 0):
            with contextlib.suppress(OSError, ValueError):
                with open(file.filename, "rb") as fh:
                    self.map = mmap.mmap(fh.fileno(), 0, access=mmap.ACCESS_READ)
                self.chunk_rows = dataset.chunks[0]

    def rows(self, rows: slice) -> np.ndarray:
        """Rows ``rows`` (at most ``block`` of them), (r, columns); valid until the next call."""
        self._release()
        count, columns = rows.stop - rows.start, self.dataset.shape[1]
        first = rows.start - rows.start % self.chunk_rows if self.map is not None else 0
        if self.map is not None and rows.stop <= first + self.chunk_rows:
            info = self.dataset.id.get_chunk_info_by_coord((first, 0))
            nbytes = self.chunk_rows * columns * 4
            if (info.byte_offset is not None and info.filter_mask == 0 and info.size == nbytes
                    and info.byte_offset + nbytes <= len(self.map)):
                offset = info.byte_offset + (rows.start - first) * columns * 4
                self.mapped = (offset, offset + count * columns * 4)
                block = np.frombuffer(self.map, np.float32, count * columns, offset).reshape(count, columns)
                check_values(self.dataset.file, self.dataset.name, block)
                return block
        if self.buffer is None:
            self.buffer = np.empty((self.block, columns), np.float32)
        try:
            block = read_rows(self.dataset, rows, self.buffer[:count])
        except (OSError, RuntimeError) as exc:
            raise damaged(Path(self.dataset.file.filename), "", f"{self.dataset.name}: ", exc) from None
        check_values(self.dataset.file, self.dataset.name, block)
        return block

    def _release(self) -> None:
        """Unmap the pages of the last block (they stay in the page cache), so the process
        does not grow by the size of everything it read; a view still held reads them again."""
        if self.map is not None and self.mapped is not None:
            start = self.mapped[0] - self.mapped[0] % mmap.PAGESIZE
            with contextlib.suppress(OSError, ValueError):
                self.map.madvise(mmap.MADV_DONTNEED, start, self.mapped[1] - start)
        self.mapped = None

    def close(self) -> None:
        self._release()
        if self.map is not None:
            with contextlib.suppress(BufferError):  # a view still in use keeps the map open
                self.map.close()
            self.map = None

    def __enter__(self) -> "RowReader":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def read_strings(f: h5py.File, key: str) -> list[str]:
    """Read a UTF-8 string dataset as a list of ``str``."""
    return [s.decode("utf-8") if isinstance(s, bytes) else str(s) for s in read(f, key)]


def attr(f: h5py.File | h5py.Dataset | h5py.Group, key: str):
    """Read attribute ``key``, naming the object if it is missing."""
    try:
        value = f.attrs[key]
    except KeyError:
        raise ArtifactError(f"{f.file.filename}: '{f.name}' lacks attribute '{key}'; the file is damaged.") from None
    return value.decode("utf-8") if isinstance(value, bytes) else value


def attr_choice(f: h5py.File, key: str, choices: Sequence[str], remedy: str) -> str:
    """The root attribute ``key``, refused in one sentence (ending with ``remedy``) unless it
    is one of ``choices``."""
    value = str(attr(f, key))
    if value not in choices:
        raise InputError(f"{f.filename}: / attribute '{key}' is {value!r}, not one of {', '.join(choices)}; {remedy}.")
    return value


def stamp(group: h5py.Group, encoding: str) -> h5py.Group:
    """Mark ``group`` with its ``encoding-type`` and ``encoding-version`` (as anndata does), so a
    reader can tell a group it knows from one it does not. Returns the group."""
    group.attrs["encoding-type"] = encoding
    group.attrs["encoding-version"] = ENCODING_VERSION
    return group


def write_strings(group: h5py.Group, key: str, values: Sequence[str]) -> h5py.Dataset:
    """Write a list of strings as a UTF-8 string dataset."""
    return group.create_dataset(key, data=np.array(list(values), dtype=object), dtype=STR)
