"""The HDF5 artifact contract (see ``docs/file-format.md``).

Every artifact is one ``.h5`` file stamped with its kind, schema, producing version,
the resolved configuration that made it and the provenance (path, kind, sha256) of the
artifacts it was made from. Readers check kind and schema; writes are atomic.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import mmap
import os
import stat
import threading
import time
from pathlib import Path
from typing import Callable, Iterator, Sequence

import h5py
import numpy as np

from . import __version__
from .errors import ArtifactError, InputError, OutputExistsError

#: Current schema of each artifact kind; bumped on an incompatible change.
SCHEMAS: dict[str, int] = {
    "corpus": 1,
    "normalized": 1,
    "pca": 1,
    "motiondb": 2,  # 2: per-node transition features instead of (N, N) pair tables
    "isomap": 1,
    "motion": 1,
    "meshanim": 1,
}

#: Which stage makes each kind (used in messages that say what to do).
PRODUCERS: dict[str, str] = {
    "corpus": "facesynth ingest",
    "normalized": "facesynth normalize",
    "pca": "facesynth pca",
    "motiondb": "facesynth build-db",
    "isomap": "facesynth isomap",
    "motion": "facesynth synthesize",
    "meshanim": "facesynth deform",
}

STR = h5py.string_dtype("utf-8")


#: Files at least this large (a motion database) have their sha256 remembered between
#: commands; hashing 500 MB takes about 0.3 s of a core, every time a sentence is synthesized.
HASH_CACHE_MIN_BYTES = 64 << 20


def sha256_of(path: Path) -> str:
    """Hex sha256 of a file's bytes.

    The file is read in 16 MB blocks into one reused buffer; reading and hashing a block
    release the GIL, so other threads run meanwhile.

    The digest of a file of at least :data:`HASH_CACHE_MIN_BYTES` is remembered in
    ``$XDG_CACHE_HOME/facesynth/sha256/`` (default ``~/.cache``) under the file's device,
    inode, size, modification and status-change times (ns), the way git trusts its index:
    the kernel sets the status-change time on every write, rename or ``touch`` of the file
    and ``utime`` cannot set it. A digest is remembered only when the file's times are
    more than a second older than the hashing and the file did not change while it was
    hashed, so a write within the same clock tick is never missed. A cache that cannot be
    read or written is ignored.
    """
    path = Path(path)
    before = os.stat(path)
    key = _hash_cache_key(before) if stat.S_ISREG(before.st_mode) and before.st_size >= HASH_CACHE_MIN_BYTES else None
    if key is not None:
        cached = _hash_cache_get(key)
        if cached is not None:
            return cached
    started_ns = time.time_ns()
    digest = hashlib.sha256()
    buffer = bytearray(min(16 << 20, max(before.st_size, 1 << 16)))
    view = memoryview(buffer)
    with open(path, "rb", buffering=0) as fh:
        while count := fh.readinto(buffer):
            digest.update(view[:count])
    hex_digest = digest.hexdigest()
    settled = max(before.st_mtime_ns, before.st_ctime_ns) < started_ns - 1_000_000_000
    if key is not None and settled and _hash_cache_key(os.stat(path)) == key:
        _hash_cache_put(key, hex_digest)
    return hex_digest


def _hash_cache_key(st: os.stat_result) -> str:
    return f"{st.st_dev}-{st.st_ino}-{st.st_size}-{st.st_mtime_ns}-{st.st_ctime_ns}"


def _hash_cache_folder() -> Path:
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "facesynth" / "sha256"


def _hash_cache_get(key: str) -> str | None:
    try:
        value = (_hash_cache_folder() / key).read_text("ascii").strip()
    except (OSError, UnicodeDecodeError):
        return None
    return value if len(value) == 64 and all(c in "0123456789abcdef" for c in value) else None


def _hash_cache_put(key: str, hex_digest: str) -> None:
    folder = _hash_cache_folder()
    tmp = folder / f"{key}.tmp-{os.getpid()}-{threading.get_ident()}"
    try:
        folder.mkdir(parents=True, exist_ok=True)
        tmp.write_text(hex_digest + "\n", "ascii")
        os.replace(tmp, folder / key)
    except OSError:
        with contextlib.suppress(OSError):
            tmp.unlink()


def check_output(path: Path, overwrite: bool) -> None:
    """Refuse to replace an existing output unless ``overwrite`` is set, and a folder always
    (an output here is one file; ``--overwrite`` does not delete folders)."""
    if Path(path).is_dir():
        raise OutputExistsError(f"{path}: is a folder, but this output is one file; give a file name (e.g. inside that folder).")
    if Path(path).exists() and not overwrite:
        raise OutputExistsError(f"{path}: output exists; pass --overwrite to replace it or choose another path.")


def check_output_folder(path: Path, what: str) -> None:
    """Refuse an output folder (``what``: 'the report', 'the images') whose path is a file."""
    if Path(path).exists() and not Path(path).is_dir():
        raise OutputExistsError(f"{path}: is a file, but this output is a folder (for {what}); give a folder path.")


@contextlib.contextmanager
def atomic_path(path: Path, overwrite: bool = False) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; on success fsync it and rename it into place.

    On any exception (or a kill) the temporary file is removed (or left under its
    ``.tmp-<pid>`` name), never at ``path``.
    """
    path = Path(path)
    check_output(path, overwrite)
    if not path.parent.exists():
        raise InputError(f"{path}: the output folder {path.parent} does not exist; create it first.")
    tmp = path.with_name(f"{path.name}.tmp-{os.getpid()}")
    try:
        yield tmp
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def input_record(path: Path) -> dict:
    """Provenance entry of one input file: path, kind (if an artifact) and sha256."""
    path = Path(path)
    kind = None
    if h5py.is_hdf5(path):
        with h5py.File(path, "r") as f:
            kind = f.attrs.get("facesynth_kind")
    return {"path": str(path), "kind": kind, "sha256": sha256_of(path)}


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


def open_artifact(path: Path, kind: str) -> h5py.File:
    """Open an artifact for reading after checking that it is of ``kind`` and a known schema."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: file not found; make it with `{PRODUCERS.get(kind, 'facesynth')}` first.")
    if not h5py.is_hdf5(path):
        raise ArtifactError(f"{path}: not an HDF5 file; expected a facesynth '{kind}' artifact.")
    f = h5py.File(path, "r")
    found = f.attrs.get("facesynth_kind")
    if found != kind:
        f.close()
        found_text = f"a '{found}' artifact" if found else "no facesynth artifact"
        raise ArtifactError(
            f"{path}: found {found_text} but expected '{kind}'; pass the output of `{PRODUCERS[kind]}`."
        )
    schema = int(f.attrs.get("facesynth_schema", -1))
    if schema != SCHEMAS[kind]:
        f.close()
        raise ArtifactError(
            f"{path}: '{kind}' schema {schema} is not the supported schema {SCHEMAS[kind]}; "
            f"rebuild it with this version's `{PRODUCERS[kind]}`."
        )
    return f


def read(f: h5py.File, key: str) -> np.ndarray:
    """Read dataset ``key`` fully, naming the file and key if it is missing."""
    try:
        return f[key][()]
    except KeyError:
        raise ArtifactError(f"{f.filename}: missing dataset '{key}'; the file is damaged or from another tool.") from None


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
                return np.frombuffer(self.map, np.float32, count * columns, offset).reshape(count, columns)
        if self.buffer is None:
            self.buffer = np.empty((self.block, columns), np.float32)
        return read_rows(self.dataset, rows, self.buffer[:count])

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


#: Version of each group encoding (the ``encoding-type`` attribute names the group's layout,
#: ``encoding-version`` this number); bumped when a group's layout changes incompatibly.
ENCODING_VERSION = "1"


def stamp(group: h5py.Group, encoding: str) -> h5py.Group:
    """Mark ``group`` with its ``encoding-type`` and ``encoding-version`` (as anndata does), so a
    reader can tell a group it knows from one it does not. Returns the group."""
    group.attrs["encoding-type"] = encoding
    group.attrs["encoding-version"] = ENCODING_VERSION
    return group


def write_strings(group: h5py.Group, key: str, values: Sequence[str]) -> h5py.Dataset:
    """Write a list of strings as a UTF-8 string dataset."""
    return group.create_dataset(key, data=np.array(list(values), dtype=object), dtype=STR)
