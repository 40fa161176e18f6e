"""The sha256 of a file, remembered between commands for large files.

Process-wide state: none in memory; the remembered digests live on disk in
``$XDG_CACHE_HOME/facesynth/sha256/`` (default ``~/.cache``), shared by every process.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import stat
import threading
import time
from pathlib import Path

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
