"""Hostile inputs for every reader, made from the tiny sample corpus by seeded mutations, and
the contract each case is judged by.

A *case* is (input kind, mutation, seed). :func:`prepare` copies the kind's valid base file
into a fresh folder, mutates it with a ``random.Random(seed)`` and returns the command that
reads it; :func:`run` runs that command in-process through click's ``CliRunner`` inside a
forked child (so a hang is killed at the time bound and memory is capped) and :func:`judge`
checks the contract:

* exit 1 with exactly one ``error: `` line that names the mutated file (exit 2 with click's
  one ``Error:`` line for bad usage), no traceback, no escaped exception;
* nothing left in the output folder (no output, no temporary file);
* the input unchanged;
* finished within :data:`TIME_BOUND_S`;
* or exit 0, when the mutation left a file that is still valid, with every artifact written
  passing ``facesynth check`` (finite numbers, shapes and bounds of the specification).

Input kinds: captures (``trc``, ``c3d``, ``csv`` through ``ingest``; a Live Link Face CSV
``livelink``, another rig's ``curves`` CSV and its ``mapping`` to ARKit through ``ingest``), audio (``wav``,
``flac`` through ``ingest``), phone timings (``textgrid``, ``lab``, ``hts`` through
``synthesize``), ``emotions`` and ``constraints`` files (``synthesize``), meshes (``obj``,
``ply``) and the ``binding`` CSV (``deform``), ``toml`` settings (``pca --config``) and every
artifact kind (``corpus`` -> normalize, ``normalized`` -> pca, ``pca`` -> build-db,
``motiondb`` -> synthesize, ``isomap`` -> isomap pick, ``motion`` -> deform, ``meshanim`` ->
render).
"""

from __future__ import annotations

import csv
import hashlib
import json
import os
import random
import re
import resource
import select
import shutil
import signal
import struct
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: Longest a case may take (s) under the contract; a child still running at
#: :data:`KILL_AFTER_S` is killed and the case counts as not handled.
TIME_BOUND_S = 30.0
KILL_AFTER_S = 60.0

#: Address-space cap of a case's child (bytes): a reader that tries to expand a compression
#: bomb fails there instead of taking the machine's memory.
MEMORY_CAP = 6 << 30

TEXT_KINDS = ("trc", "csv", "textgrid", "lab", "hts", "emotions", "constraints", "obj", "ply", "binding", "toml")
BINARY_KINDS = ("c3d", "wav", "flac")
ARTIFACT_KINDS = ("corpus", "normalized", "pca", "motiondb", "isomap", "motion", "meshanim")
#: Capture takes that pose the rig (issue 41), text files; after the others so that adding them
#: left the quick selection of the older kinds as it was.
CAPTURE_KINDS = ("livelink", "curves", "mapping")
KINDS = TEXT_KINDS + BINARY_KINDS + ARTIFACT_KINDS + CAPTURE_KINDS

BYTE_MUTATIONS = ("truncate", "random_bytes", "empty")
NUMBER_MUTATIONS = ("nan", "inf", "negative", "zero", "huge")
#: Mutations an artifact reader must refuse: exit 0 is not enough, even with a valid output.
MUST_REFUSE = ("empty", "wrong_dtype", "extra_dataset", "wrong_kind", "external_link", "soft_link", "external_storage",
               "virtual", "bomb")

HDF5_MUTATIONS = ("wrong_dtype", "wrong_shape", "missing_dataset", "extra_dataset", "missing_attr", "mistyped_attr",
                  "wrong_kind", "external_link", "soft_link", "external_storage", "virtual", "bomb")


def mutations(kind: str) -> tuple[str, ...]:
    """The mutations that apply to an input kind."""
    if kind in TEXT_KINDS or kind in CAPTURE_KINDS:
        return BYTE_MUTATIONS + NUMBER_MUTATIONS + ("non_utf8",)
    if kind == "flac":
        return BYTE_MUTATIONS
    if kind in BINARY_KINDS:
        return BYTE_MUTATIONS + NUMBER_MUTATIONS
    return BYTE_MUTATIONS + NUMBER_MUTATIONS + HDF5_MUTATIONS


def all_cases(seeds: int = 1) -> list[tuple[str, str, int]]:
    """Every (kind, mutation, seed) with ``seeds`` seeds per pair."""
    return [(k, m, s) for k in KINDS for m in mutations(k) for s in range(seeds)]


def quick_cases() -> list[tuple[str, str, int]]:
    """The cases of ``make test`` (under a minute): every kind with truncation, NaN, non-UTF-8
    text and a compression bomb where they apply, each structural HDF5 mutation on two artifact
    kinds, plus a fixed fifth of the other mutations, seed 0; the rest and more seeds run in the
    long suite."""
    rng = random.Random(23)
    out = []
    for k in KINDS:
        # each structural mutation on two artifact kinds, in turn
        turn = HDF5_MUTATIONS[ARTIFACT_KINDS.index(k)::len(ARTIFACT_KINDS)] if k in ARTIFACT_KINDS else ()
        turn += HDF5_MUTATIONS[ARTIFACT_KINDS.index(k) + 2::len(ARTIFACT_KINDS)] if k in ARTIFACT_KINDS else ()
        for m in mutations(k):
            if m in ("truncate", "nan", "non_utf8", "bomb") + turn or rng.random() < 0.2:
                out.append((k, m, 0))
    return out


def check_bases(bases: "Bases", folder: Path) -> dict[str, str]:
    """Run every kind's command on its unmutated base; {kind: why} for those that do not exit 0
    (a case of such a kind proves nothing)."""
    failed = {}
    for kind in KINDS:
        case_dir = folder / f"base-{kind}"
        shutil.rmtree(case_dir, ignore_errors=True)
        case_dir.mkdir(parents=True)
        mutated = case_dir / f"hostile_{kind}{_suffix(kind, bases.files[kind])}"
        shutil.copyfile(bases.files[kind], mutated)
        (case_dir / "out").mkdir()
        args, _ = command(bases, kind, mutated, case_dir / "out")
        outcome = run([str(a) for a in args])
        if outcome["exit_code"] != 0:
            failed[kind] = (outcome.get("escaped") or outcome["output"]).strip().splitlines()[-1:][0:1] or ["?"]
            failed[kind] = failed[kind][0]
        shutil.rmtree(case_dir, ignore_errors=True)
    return failed


# ---------------------------------------------------------------- valid bases


@dataclass
class Bases:
    """Valid inputs, one per kind, and what the commands need beside them."""

    root: Path
    corpus_dir: Path
    files: dict[str, Path] = field(default_factory=dict)
    take: dict = field(default_factory=dict)  # the manifest row used for one-take ingests
    utterance: Path | None = None

    def save(self, path: Path) -> None:
        """Write what :meth:`load` reads (JSON), so other processes use the same bases."""
        path.write_text(json.dumps({"root": str(self.root), "corpus_dir": str(self.corpus_dir), "take": self.take,
                                    "files": {k: str(v) for k, v in self.files.items()},
                                    "utterance": str(self.utterance) if self.utterance else None}), encoding="utf-8")

    @classmethod
    def load(cls, path: Path) -> "Bases":
        d = json.loads(path.read_text(encoding="utf-8"))
        return cls(Path(d["root"]), Path(d["corpus_dir"]), {k: Path(v) for k, v in d["files"].items()}, d["take"],
                   Path(d["utterance"]) if d["utterance"] else None)


def _invoke(args: list[str]) -> tuple[int, str]:
    """Run the command line in a forked child (no OpenCL); (exit status, output). Building a
    base is no case: it has minutes, and one that does not finish is an error (status -1)."""
    out = run([str(a) for a in args], kill_after=600.0)
    if out["exit_code"] is None:
        return -1, "timed out" if out.get("timed_out") else (out.get("escaped") or "the child died without a result")
    return out["exit_code"], out["output"]


def build_bases(root: Path, corpus_dir: Path, artifacts: dict[str, Path] | None = None) -> Bases:
    """Valid inputs of every kind from a tiny sample corpus ``corpus_dir``; ``artifacts`` may
    give already built ``corpus``, ``normalized``, ``pca`` and ``motiondb`` files (else they are
    built here). Raises RuntimeError if a command on the corpus fails."""
    import soundfile as sf

    from facesynth.formats.labels import read_phone_segments, write_lab
    from facesynth.formats.mocap import read_c3d, write_csv, write_trc

    root.mkdir(parents=True, exist_ok=True)
    b = Bases(root, corpus_dir)
    rows = list(csv.DictReader(open(corpus_dir / "manifest.csv", encoding="utf-8")))
    row = next(r for r in rows if r["split"] == "test")
    b.take = row
    c3d = corpus_dir / row["mocap"]
    b.files["c3d"] = c3d
    take = read_c3d(c3d)
    write_trc(root / "take.trc", take)
    write_csv(root / "take.csv", take)
    b.files["trc"], b.files["csv"] = root / "take.trc", root / "take.csv"
    wav = corpus_dir / row["audio"]
    b.files["wav"] = wav
    samples, rate = sf.read(str(wav))
    sf.write(str(root / "take.flac"), samples, rate)
    b.files["flac"] = root / "take.flac"
    textgrid = corpus_dir / row["alignment"]
    b.files["textgrid"] = b.utterance = textgrid
    segs = read_phone_segments(textgrid)
    write_lab(root / "take.lab", segs)
    b.files["lab"] = root / "take.lab"
    hts = []
    labels = [s.label or "pau" for s in segs]
    for k, s in enumerate(segs):
        prev = labels[k - 1] if k else "x"
        nxt = labels[k + 1] if k + 1 < len(labels) else "x"
        hts.append(f"{round(s.start * 1e7)} {round(s.end * 1e7)} x^{prev}-{labels[k]}+{nxt}=x@1_1/A:0_0_0/B:1-1-1\n")
    (root / "take_hts.lab").write_text("".join(hts), encoding="utf-8")
    b.files["hts"] = root / "take_hts.lab"
    end = segs[-1].end
    (root / "emotions.txt").write_text(f"0 {end / 2:.3f} happy\n{end / 2:.3f} {end:.3f} sad\n", encoding="utf-8")
    b.files["emotions"] = root / "emotions.txt"
    b.files["obj"] = corpus_dir / "face.obj"
    b.files["binding"] = corpus_dir / "markers.csv"
    import trimesh

    from facesynth.formats.mesh import read_mesh

    v, f = read_mesh(corpus_dir / "face.obj")
    trimesh.Trimesh(v, f, process=False).export(str(root / "face.ply"), encoding="ascii")
    b.files["ply"] = root / "face.ply"
    _capture_bases(b, root, corpus_dir, row)
    (root / "settings.toml").write_text(
        "[pca]\nn_components = 6\nvariance_target = 0.0\n\n[synthesize]\npnt = 1.0\noutput_fps = 30.0\n\n"
        "[normalize]\nmax_gap_frames = 12\nreference_silence_s = 0.2\n", encoding="utf-8")
    b.files["toml"] = root / "settings.toml"

    artifacts = dict(artifacts or {})
    steps = [("corpus", ["ingest", corpus_dir / "manifest.csv"]), ("normalized", ["normalize", None]),
             ("pca", ["pca", None]), ("motiondb", ["build-db", None])]
    previous = None
    for kind, args in steps:
        if kind not in artifacts:
            out = root / f"{kind}.h5"
            if not out.exists():
                status, text = _invoke([args[0], args[1] or previous, "-o", out, "-q"])
                if status:
                    raise RuntimeError(f"building the base {kind}: {text}")
            artifacts[kind] = out
        previous = artifacts[kind]
    b.files.update({k: artifacts[k] for k in ("corpus", "normalized", "pca", "motiondb")})
    more = [("motion", ["synthesize", artifacts["motiondb"], "--phonemes", textgrid]),
            ("isomap", ["isomap", artifacts["motiondb"]])]
    for kind, args in more:
        out = root / f"{kind}.h5"
        if not out.exists():
            status, text = _invoke(args + ["-o", out, "-q"])
            if status:
                raise RuntimeError(f"building the base {kind}: {text}")
        b.files[kind] = out
    out = root / "meshanim.h5"
    if not out.exists():
        status, text = _invoke(["deform", b.files["motion"], "--mesh", b.files["obj"], "--binding", b.files["binding"],
                                "-o", out, "-q"])
        if status:
            raise RuntimeError(f"building the base meshanim: {text}")
    b.files["meshanim"] = out
    # a constraint that holds: the first spoken phone, pinned to the node the search chose
    import h5py

    with h5py.File(b.files["motion"], "r") as f:
        nodes = [int(n) for n in f["provenance/node"][()]] if "provenance/node" in f else []
    constraint = _first_constraint(b.files["motiondb"], segs, nodes)
    (root / "constraints.txt").write_text(constraint, encoding="utf-8")
    b.files["constraints"] = root / "constraints.txt"
    (root / "secret.bin").write_bytes(b"SECRET-" * 4096)
    return b


def _capture_bases(b: Bases, root: Path, corpus_dir: Path, row: dict) -> None:
    """The take's truth as a Live Link Face CSV (60 frames/s) and as another rig's curves (a CSV
    of three channels at 30 frames/s) with their mapping to ARKit."""
    from facesynth.domain.corpus.truth import read_truth
    from facesynth.formats import livelink_face
    from facesynth.formats.blendshape_curves import write_mapping

    truth = read_truth(corpus_dir / "groundtruth" / f"{row['take']}_truth.csv")
    names = list(truth.arkit_names)

    def at(fps: float) -> tuple[np.ndarray, np.ndarray]:
        t = np.arange(0, truth.time_s[-1] + 1e-9, 1 / fps)
        return t, np.stack([np.interp(t, truth.time_s, truth.arkit_weights[:, k]) for k in range(len(names))], 1)

    _, arkit = at(60.0)
    head = np.stack([0.1 * np.sin(np.arange(len(arkit)) / 30), np.zeros(len(arkit)), np.zeros(len(arkit))], 1)
    livelink_face.write(root / "take_livelink.csv", names, arkit, 60.0, head=head)
    t, arkit = at(30.0)
    channels = {"JawDrop": "jawOpen", "Smile_L": "mouthSmileLeft", "Smile_R": "mouthSmileRight"}
    with open(root / "take_curves.csv", "w", encoding="utf-8", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["time", *channels])
        for i, time_s in enumerate(t):
            w.writerow([f"{time_s:.6f}"] + [f"{arkit[i, names.index(a)]:.5f}" for a in channels.values()])
    write_mapping(root / "take_mapping.csv", [(c, a, 1.0, "") for c, a in channels.items()])
    b.files["livelink"], b.files["curves"], b.files["mapping"] = (root / "take_livelink.csv", root / "take_curves.csv",
                                                                 root / "take_mapping.csv")


def _first_constraint(db: Path, segs, nodes) -> str:
    """'INDEX NODE' for the first spoken phone and any node of its phone."""
    import h5py

    from facesynth.base.phonemes import to_festival

    with h5py.File(db, "r") as f:
        phones = [p.decode() if isinstance(p, bytes) else str(p) for p in f["nodes/phone"][()]]
    for k, s in enumerate(segs):
        phone = to_festival(s.label) if s.label else None
        if phone and phone != "pau" and phone in phones:
            return f"{k} {phones.index(phone)}\n"
    return ""


# ---------------------------------------------------------------- mutations

_NUMBER = re.compile(rb"(?<![\w.\-])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")
_REPLACEMENT = {"nan": b"nan", "inf": b"inf", "zero": b"0", "huge": b"1e300"}


def _byte_mutation(data: bytes, mutation: str, rng: random.Random) -> bytes:
    if mutation == "empty":
        return b""
    if mutation == "truncate":
        return data[: rng.randrange(0, max(1, len(data)))]
    if mutation == "random_bytes":
        n = rng.choice((1, 8, 64, 512))
        at = rng.randrange(0, max(1, len(data) - n))
        return data[:at] + bytes(rng.randrange(256) for _ in range(n)) + data[at + n:]
    raise ValueError(mutation)


def _text_mutation(data: bytes, mutation: str, rng: random.Random) -> bytes:
    if mutation == "non_utf8":
        lines = data.split(b"\n")
        k = rng.randrange(len(lines))
        cut = rng.randrange(len(lines[k]) + 1)
        lines[k] = lines[k][:cut] + b"\xff\xfe\xc3(" + lines[k][cut:]
        return b"\n".join(lines)
    numbers = list(_NUMBER.finditer(data))
    if not numbers:
        return data
    # Numbers in the second half of the file (the data, not the header) three times in four.
    late = [m for m in numbers if m.start() > len(data) // 2]
    m = rng.choice(late if late and rng.random() < 0.75 else numbers)
    token = m.group(0)
    new = (b"-" + token.lstrip(b"-") if not token.startswith(b"-") else b"-1e9") if mutation == "negative" \
        else _REPLACEMENT[mutation]
    return data[: m.start()] + new + data[m.end():]


def _binary_number_mutation(data: bytes, kind: str, mutation: str, rng: random.Random) -> bytes:
    value = {"nan": float("nan"), "inf": float("inf"), "negative": -1e9, "zero": 0.0, "huge": 1e30}[mutation]
    b = bytearray(data)
    if kind == "wav":
        # RIFF fmt chunk: channels at 22, sample rate at 24, block align at 32, bits at 34
        field_, fmt = rng.choice(((24, "<I"), (22, "<H"), (34, "<H")))
        number = {"zero": 0, "huge": 0xFFFFFFFF if fmt == "<I" else 0xFFFF, "negative": 0x80000000 if fmt == "<I" else 0x8000,
                  "nan": 0xFFFFFFFF if fmt == "<I" else 0xFFFF, "inf": 0x7F800000 if fmt == "<I" else 0x7F80}[mutation]
        struct.pack_into(fmt, b, field_, number)
        return bytes(b)
    # C3D: a float32 of the point data (after the parameter blocks), or the header's scale or rate
    if rng.random() < 0.3:
        struct.pack_into("<f", b, rng.choice((12, 20)), value)  # header point scale / frame rate
        return bytes(b)
    start = (struct.unpack_from("<H", data, 16)[0] - 1) * 512 if len(data) > 18 else 0
    start = min(max(start, 512), len(data) - 4)
    at = rng.randrange(start // 4, len(data) // 4) * 4
    struct.pack_into("<f", b, at, value)
    return bytes(b)


def _datasets(f) -> list[str]:
    import h5py

    names: list[str] = []
    f.visititems(lambda name, obj: names.append(name) if isinstance(obj, h5py.Dataset) else None)
    return sorted(names)


def _attributed(f) -> list[tuple[str, str]]:
    """(object path, attribute name) of every attribute in the file."""
    found = [("/", a) for a in f.attrs]
    f.visititems(lambda name, obj: found.extend((name, a) for a in obj.attrs))
    return sorted(found)


def _replace(f, name: str, **create) -> None:
    attrs = dict(f[name].attrs)
    del f[name]
    d = f.create_dataset(name, **create)
    for k, v in attrs.items():
        d.attrs[k] = v


def _hdf5_mutation(path: Path, mutation: str, rng: random.Random, bases: Bases, kind: str, folder: Path) -> None:
    import h5py

    if mutation == "wrong_kind":
        other = rng.choice([k for k in ARTIFACT_KINDS if k != kind])
        shutil.copyfile(bases.files[other], path)
        return
    with h5py.File(path, "r+") as f:
        names = _datasets(f)
        numeric = [n for n in names if f[n].dtype.kind in "fiu" and f[n].size > 0]
        floats = [n for n in numeric if f[n].dtype.kind == "f"]
        if mutation in NUMBER_MUTATIONS:
            name = rng.choice(floats if mutation in ("nan", "inf") else numeric)
            ds = f[name]
            value = {"nan": np.nan, "inf": np.inf, "negative": -1e9 if ds.dtype.kind == "f" else -7,
                     "zero": 0, "huge": 1e30 if ds.dtype.kind == "f" else np.iinfo(ds.dtype).max}[mutation]
            index = np.unravel_index(rng.randrange(ds.size), ds.shape) if ds.shape else ()
            ds[index] = value
        elif mutation == "wrong_dtype":
            name = rng.choice(names)
            data = f[name][()]
            if f[name].dtype.kind in "fiu":
                new = np.asarray(data).astype("S8") if rng.random() < 0.3 else np.asarray(data).astype(np.int8)
            else:
                new = np.zeros(np.shape(data), np.float64)
            _replace(f, name, data=new)
        elif mutation == "wrong_shape":
            name = rng.choice([n for n in names if f[n].shape])
            data = f[name][()]
            axis = rng.randrange(data.ndim)
            new = np.delete(data, -1, axis=axis) if data.shape[axis] > 1 else np.concatenate([data, data], axis=axis)
            _replace(f, name, data=new)
        elif mutation == "missing_dataset":
            del f[rng.choice(names)]
        elif mutation == "extra_dataset":
            groups = ["/"] + sorted({n.rsplit("/", 1)[0] for n in names if "/" in n})
            f[rng.choice(groups)].create_dataset(f"extra_{rng.randrange(1000)}", data=np.arange(5.0))
        elif mutation in ("missing_attr", "mistyped_attr"):
            where, name = rng.choice(_attributed(f))
            obj = f[where]
            if mutation == "missing_attr":
                del obj.attrs[name]
            else:
                old = obj.attrs[name]
                obj.attrs[name] = 7 if isinstance(old, (str, bytes)) else "seven"
        elif mutation == "external_link":
            name = rng.choice(names)
            secret = folder / "elsewhere.h5"
            with h5py.File(secret, "w") as g:
                g.create_dataset("data", data=f[name][()])
            del f[name]
            f[name] = h5py.ExternalLink(str(secret), "/data")
        elif mutation == "soft_link":
            name = rng.choice(names)
            f.move(name, "/hidden_" + name.replace("/", "_"))
            f[name] = h5py.SoftLink("/hidden_" + name.replace("/", "_"))
        elif mutation == "external_storage":
            name = rng.choice(numeric)
            ds = f[name]
            nbytes = ds.size * ds.dtype.itemsize
            raw = folder / "elsewhere.bin"
            raw.write_bytes((b"SECRET-" * (nbytes // 7 + 1))[:nbytes])
            _replace(f, name, shape=ds.shape, dtype=ds.dtype, external=[(str(raw), 0, nbytes)])
        elif mutation == "virtual":
            name = rng.choice(numeric)
            ds = f[name]
            secret = folder / "elsewhere.h5"
            with h5py.File(secret, "w") as g:
                g.create_dataset("data", data=ds[()])
            layout = h5py.VirtualLayout(shape=ds.shape, dtype=ds.dtype)
            layout[...] = h5py.VirtualSource(str(secret), "data", shape=ds.shape)
            attrs = dict(ds.attrs)
            del f[name]
            v = f.create_virtual_dataset(name, layout)
            for k, a in attrs.items():
                v.attrs[k] = a
        elif mutation == "bomb":
            # A few kB on disk that declare 64 GiB: a chunked, compressed dataset never written
            name = rng.choice([n for n in numeric if f[n].shape])
            ds = f[name]
            row = int(np.prod(ds.shape[1:], dtype=np.int64)) * ds.dtype.itemsize or 1
            rows = (64 << 30) // row
            _replace(f, name, shape=(rows,) + ds.shape[1:], dtype=ds.dtype,
                     chunks=(min(rows, max(1, (1 << 20) // row)),) + ds.shape[1:], compression="gzip", fillvalue=1)
        else:
            raise ValueError(mutation)


# ---------------------------------------------------------------- a prepared case


@dataclass
class Prepared:
    """One case ready to run: the mutated file, the command, its output folder and outputs."""

    kind: str
    mutation: str
    seed: int
    mutated: Path
    args: list[str]
    out_dir: Path
    outputs: list[Path]
    digest: str


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else ""


def _suffix(kind: str, base: Path) -> str:
    return {"hts": ".lab", "emotions": ".txt", "constraints": ".txt", "binding": ".csv", "toml": ".toml"}.get(kind, base.suffix)


def prepare(bases: Bases, kind: str, mutation: str, seed: int, folder: Path) -> Prepared:
    """Make the mutated file for the case in ``folder`` (fresh) and the command that reads it."""
    rng = random.Random(f"{kind}/{mutation}/{seed}")
    folder.mkdir(parents=True, exist_ok=True)
    base = bases.files[kind]
    mutated = folder / f"hostile_{kind}{_suffix(kind, base)}"
    shutil.copyfile(base, mutated)
    if kind in ARTIFACT_KINDS and mutation not in BYTE_MUTATIONS:
        _hdf5_mutation(mutated, mutation, rng, bases, kind, folder)
    else:
        data = mutated.read_bytes()
        if mutation in BYTE_MUTATIONS:
            data = _byte_mutation(data, mutation, rng)
        elif kind in BINARY_KINDS:
            data = _binary_number_mutation(data, kind, mutation, rng)
        else:
            data = _text_mutation(data, mutation, rng)
        mutated.write_bytes(data)
    out_dir = folder / "out"
    out_dir.mkdir()
    args, outputs = command(bases, kind, mutated, out_dir)
    return Prepared(kind, mutation, seed, mutated, [str(a) for a in args], out_dir, outputs, _digest(mutated))


def command(bases: Bases, kind: str, path: Path, out_dir: Path) -> tuple[list, list[Path]]:
    """The command that reads ``path`` as an input of ``kind``, and the outputs it writes."""
    f = bases.files
    if kind in ("trc", "c3d", "csv", "wav", "flac") + CAPTURE_KINDS:
        row = dict(bases.take)
        c = bases.corpus_dir
        row["mocap"] = str(path if kind in ("trc", "c3d", "csv", "livelink", "curves") else c / row["mocap"])
        if kind in ("curves", "mapping"):
            row["mocap"] = str(path if kind == "curves" else f["curves"])
            row["mapping"] = str(path if kind == "mapping" else f["mapping"])
        row["audio"] = str(path if kind in ("wav", "flac") else c / row["audio"])
        row["alignment"] = str(c / row["alignment"])
        manifest = path.parent / "manifest.csv"
        with open(manifest, "w", encoding="utf-8", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(row))
            w.writeheader()
            w.writerow(row)
        out = out_dir / "corpus.h5"
        return ["ingest", manifest, "-o", out, "-q"], [out]
    if kind in ("textgrid", "lab", "hts", "emotions", "constraints"):
        out = out_dir / "motion.h5"
        args = ["synthesize", f["motiondb"], "--phonemes", path if kind in ("textgrid", "lab", "hts") else f["textgrid"]]
        if kind == "emotions":
            args += ["--emotions", path]
        if kind == "constraints":
            args += ["--constraints", path]
        return args + ["-o", out, "-q"], [out]
    if kind in ("obj", "ply", "binding", "motion"):
        out = out_dir / "anim.h5"
        return (["deform", path if kind == "motion" else f["motion"], "--mesh", path if kind in ("obj", "ply") else f["obj"],
                 "--binding", path if kind == "binding" else f["binding"], "-o", out, "-q"], [out])
    if kind == "toml":
        out = out_dir / "pca.h5"
        return ["pca", f["normalized"], "--config", path, "-o", out, "-q"], [out]
    if kind == "corpus":
        out = out_dir / "normalized.h5"
        return ["normalize", path, "-o", out, "-q"], [out]
    if kind == "normalized":
        out = out_dir / "pca.h5"
        return ["pca", path, "-o", out, "-q"], [out]
    if kind == "pca":
        out = out_dir / "db.h5"
        return ["build-db", path, "-o", out, "-q"], [out]
    if kind == "motiondb":
        out = out_dir / "motion.h5"
        return ["synthesize", path, "--phonemes", f["textgrid"], "-o", out, "-q"], [out]
    if kind == "isomap":
        return ["isomap", "pick", path, "aa", "0", "0"], []
    if kind == "meshanim":
        out = out_dir / "video.avi"
        return (["render", path, "--audio", f["wav"], "-o", out, "-q", "--set", "render.width=32", "--set",
                 "render.height=32"], [out])
    raise ValueError(kind)


# ---------------------------------------------------------------- running and judging


def _child(args: list[str], fd: int) -> None:
    """In the forked child: run the command line and write the outcome as JSON to ``fd``."""
    outcome: dict
    try:
        os.environ["FACESYNTH_OPENCL"] = "off"
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
        # The parent's OpenMP and BLAS worker threads are not in a forked child: a parallel
        # region would wait on them for ever (scikit-learn's neighbours after the parent ran
        # an Isomap), so the child computes on its one thread.
        from threadpoolctl import threadpool_limits

        threadpool_limits(1)
        from click.testing import CliRunner

        from facesynth.base import opencl
        from facesynth.cli import main

        opencl.reset()
        started = time.perf_counter()
        result = CliRunner().invoke(main, args)
        exc = result.exception
        outcome = {"exit_code": result.exit_code, "output": result.output, "seconds": time.perf_counter() - started,
                   "escaped": None if exc is None or isinstance(exc, SystemExit)
                   else f"{type(exc).__name__}: {exc}"[:300] + "\n" + "".join(traceback.format_exception(*result.exc_info))[-1500:]}
    except BaseException as exc:  # reported to the parent as an escaped exception
        outcome = {"exit_code": -1, "output": "", "seconds": 0.0, "escaped": f"{type(exc).__name__}: {exc}"}
    data = json.dumps(outcome).encode()
    with os.fdopen(fd, "wb") as fh:
        fh.write(data)
    os._exit(0)


def run(args: list[str], kill_after: float = KILL_AFTER_S) -> dict:
    """Run ``facesynth ARGS`` in a forked child; the outcome: exit_code, output, seconds, escaped
    (an exception that escaped the command, with its traceback), timed_out."""
    r, w = os.pipe()
    started = time.perf_counter()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        os.close(r)
        try:
            _child(args, w)
        finally:
            os._exit(3)
    os.close(w)
    chunks, deadline = [], started + kill_after
    timed_out = False
    with os.fdopen(r, "rb") as fh:
        while True:
            left = deadline - time.perf_counter()
            if left <= 0:
                timed_out = True
                os.kill(pid, signal.SIGKILL)
                break
            ready, _, _ = select.select([fh], [], [], left)
            if ready:
                chunk = os.read(fh.fileno(), 1 << 16)
                if not chunk:
                    break
                chunks.append(chunk)
    os.waitpid(pid, 0)
    seconds = time.perf_counter() - started
    if timed_out:
        return {"exit_code": None, "output": "", "seconds": seconds, "escaped": None, "timed_out": True}
    try:
        outcome = json.loads(b"".join(chunks) or b"{}")
    except ValueError:
        outcome = {}
    if "exit_code" not in outcome:  # killed (memory) or crashed before reporting
        outcome = {"exit_code": None, "output": "", "escaped": "the child died without a result"}
    outcome["seconds"] = seconds
    outcome["timed_out"] = False
    return outcome


def judge(case: Prepared, outcome: dict) -> str | None:
    """None if the case met the contract, else why not (one line)."""
    if outcome.get("timed_out"):
        return f"still running after {KILL_AFTER_S:g} s"
    if outcome["seconds"] > TIME_BOUND_S:
        return f"took {outcome['seconds']:.1f} s"
    if outcome.get("escaped"):
        return "exception escaped: " + outcome["escaped"].splitlines()[0]
    text = outcome["output"]
    if "Traceback" in text:
        return "traceback in the output"
    if _digest(case.mutated) != case.digest:
        return "the input was modified"
    code = outcome["exit_code"]
    left = sorted(p.name for p in case.out_dir.iterdir())
    if code == 0:
        if case.kind in ARTIFACT_KINDS and case.mutation in MUST_REFUSE:
            return f"exit 0 reading an artifact with {case.mutation.replace('_', ' ')}"
        extra = [n for n in left if case.out_dir / n not in case.outputs]
        if extra:
            return f"exit 0 but left {extra}"
        return _valid_outputs(case, text)
    if code not in (1, 2):
        return f"exit {code}"
    if left:
        return f"exit {code} but left {left} in the output folder"
    errors = [line for line in text.splitlines() if line.startswith(("error: ", "Error: "))]
    if len(errors) != 1:
        return f"{len(errors)} error lines: {text.strip()[:200]!r}"
    if case.mutated.name not in errors[0]:
        return f"the error does not name the file: {errors[0][:200]!r}"
    return None


def _valid_outputs(case: Prepared, text: str) -> str | None:
    """Exit 0: every artifact written must pass ``facesynth check``; printed numbers must be finite."""
    from facesynth.model.check import check_file

    for out in case.outputs:
        if not out.exists():
            return f"exit 0 without writing {out.name}"
        if out.suffix == ".h5":
            report = check_file(out)
            problems = [p for p in report.problems if "inputs[" not in p.message]
            if problems:
                return f"exit 0 with a bad output: {problems[0].message[:160]}"
    if re.search(r"\b(nan|inf)\b", text, re.IGNORECASE):
        return "exit 0 printing a non-finite number"
    return None


def run_case(bases: Bases, kind: str, mutation: str, seed: int, folder: Path) -> tuple[Prepared, dict, str | None]:
    """Prepare, run and judge one case in ``folder``."""
    case = prepare(bases, kind, mutation, seed, folder)
    outcome = run(case.args)
    return case, outcome, judge(case, outcome)
