import os
import signal

import h5py
import numpy as np
import pytest

from facesynth.base.errors import ArtifactError, OutputExistsError
from facesynth.model.artifacts import SCHEMAS, open_artifact, read, write_artifact


def test_stamps_and_provenance(tmp_path):
    src = tmp_path / "in.txt"
    src.write_text("hello")
    out = tmp_path / "a.h5"
    with write_artifact(out, "pca", config={"n": 1}, inputs=[src]) as f:
        f.create_dataset("x", data=np.arange(3))
    with h5py.File(out, "r") as f:
        assert f.attrs["facesynth_kind"] == "pca"
        assert f.attrs["facesynth_schema"] == SCHEMAS["pca"]
        assert '"n": 1' in f.attrs["config"]
        assert "2cf24dba5fb0a30e26e83b2ac5b9e29e1b161e5c1fa7425e73043362938b9824" in f.attrs["inputs"]
        assert read(f, "x").tolist() == [0, 1, 2]
    # open_artifact validates against the specification: a stamped file without the pca layout is refused
    with pytest.raises(ArtifactError, match=r"a\.h5: /takes: missing required group .* make it again with `facesynth pca`"):
        open_artifact(out, "pca")


def test_wrong_kind_names_file_found_and_expected(tmp_path):
    out = tmp_path / "a.h5"
    with write_artifact(out, "corpus"):
        pass
    with pytest.raises(ArtifactError, match=r"a\.h5: found a 'corpus' artifact but expected 'pca'"):
        open_artifact(out, "pca")


def test_unknown_schema_says_rebuild(tmp_path):
    out = tmp_path / "a.h5"
    with write_artifact(out, "pca"):
        pass
    with h5py.File(out, "r+") as f:
        f.attrs["facesynth_schema"] = 99
    with pytest.raises(ArtifactError, match="schema 99 is not the supported schema"):
        open_artifact(out, "pca")


def test_missing_dataset_names_the_key(tmp_path):
    out = tmp_path / "a.h5"
    with write_artifact(out, "pca"):
        pass
    with h5py.File(out, "r") as f, pytest.raises(ArtifactError, match="missing dataset 'pca/mean'"):
        read(f, "pca/mean")


def test_failed_write_leaves_no_file(tmp_path):
    out = tmp_path / "a.h5"
    with pytest.raises(RuntimeError):
        with write_artifact(out, "pca") as f:
            f.create_dataset("x", data=np.arange(3))
            raise RuntimeError("killed")
    assert list(tmp_path.iterdir()) == []


def test_existing_output_is_not_replaced_without_overwrite(tmp_path):
    out = tmp_path / "a.h5"
    out.write_text("precious")
    with pytest.raises(OutputExistsError, match="--overwrite"):
        with write_artifact(out, "pca"):
            pass
    assert out.read_text() == "precious"


def test_read_rows_fills_the_given_buffer(tmp_path):
    from facesynth.model.artifacts import read_rows

    data = np.arange(7 * 5, dtype=np.float32).reshape(7, 5)
    with h5py.File(tmp_path / "x.h5", "w") as f:
        f.create_dataset("d", data=data, chunks=(3, 5))
    buf = np.full((4, 5), -1, np.float32)
    with h5py.File(tmp_path / "x.h5", "r") as f:
        assert read_rows(f["d"], slice(2, 6), buf) is buf
        assert np.array_equal(buf, data[2:6])
        read_rows(f["d"], slice(6, 7), buf[:1])
        assert np.array_equal(buf[0], data[6])
        with pytest.raises(ValueError, match="C-contiguous"):
            read_rows(f["d"], slice(0, 4), buf[:, :3])


@pytest.mark.parametrize("content", [b"", b"hello", bytes(range(256)) * 5000])
def test_sha256_of_any_file(tmp_path, content):
    import hashlib

    from facesynth.model.artifacts import sha256_of

    (tmp_path / "f").write_bytes(content)
    assert sha256_of(tmp_path / "f") == hashlib.sha256(content).hexdigest()


def test_input_records_in_background_give_the_records_or_the_error(tmp_path):
    from facesynth.model.artifacts import input_record, input_records_in_background

    (tmp_path / "a.txt").write_text("hello")
    wait = input_records_in_background([tmp_path / "a.txt"])
    assert wait() == [input_record(tmp_path / "a.txt")]
    with pytest.raises(FileNotFoundError):
        input_records_in_background([tmp_path / "missing.txt"])()


def test_large_file_digests_are_remembered_until_the_file_changes(tmp_path, monkeypatch):
    import hashlib
    import time

    from facesynth.base import hashing

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setattr(hashing, "HASH_CACHE_MIN_BYTES", 4)
    f = tmp_path / "db.bin"
    f.write_bytes(b"first version")
    assert hashing.sha256_of(f) == hashlib.sha256(b"first version").hexdigest()
    assert not (tmp_path / "cache").exists()  # written less than a second ago: not remembered
    real_ns = time.time_ns
    monkeypatch.setattr(hashing.time, "time_ns", lambda: real_ns() + 5_000_000_000)
    hashing.sha256_of(f)
    (entry,) = (tmp_path / "cache" / "facesynth" / "sha256").iterdir()
    entry.write_text("ab" * 32)  # a remembered digest is used without reading the file
    assert hashing.sha256_of(f) == "ab" * 32
    time.sleep(0.05)
    f.write_bytes(b"other version")  # same size, new modification and status-change times
    assert hashing.sha256_of(f) == hashlib.sha256(b"other version").hexdigest()
    time.sleep(0.05)
    f.chmod(0o600)  # only the status-change time moves
    assert hashing.sha256_of(f) == hashlib.sha256(b"other version").hexdigest()
    for e in entry.parent.iterdir():
        e.write_text("not a digest")  # a damaged entry is ignored
    assert hashing.sha256_of(f) == hashlib.sha256(b"other version").hexdigest()
    monkeypatch.setattr(hashing.time, "time_ns", real_ns)
    small = tmp_path / "small.txt"
    small.write_bytes(b"abc")  # below the size limit: always hashed
    assert hashing.sha256_of(small) == hashlib.sha256(b"abc").hexdigest()


@pytest.mark.parametrize("layout, mapped", [
    ({"chunks": (3, 5)}, True),                          # build-db's layout: whole-row chunks, no filter
    ({"chunks": (3, 5), "compression": "gzip"}, False),  # filtered: through HDF5
    ({"chunks": (3, 2)}, False),                         # chunks that split rows
    ({}, False),                                         # contiguous
    ({"chunks": (3, 5), "dtype": ">f4"}, False),         # big-endian
])
def test_row_reader_maps_plain_chunks_and_reads_anything_else(tmp_path, layout, mapped):
    from facesynth.model.artifacts import RowReader

    data = np.arange(8 * 5, dtype=np.float32).reshape(8, 5) / 7
    with h5py.File(tmp_path / "x.h5", "w") as f:
        f.create_dataset("d", data=data, **layout)
    with h5py.File(tmp_path / "x.h5", "r") as f, RowReader(f["d"], 3) as reader:
        assert (reader.map is not None) == mapped
        for a in range(0, 8, 3):
            rows = reader.rows(slice(a, min(8, a + 3)))
            assert np.array_equal(rows, data[a : a + 3]) and rows.dtype == np.float32
            assert rows.flags.writeable != mapped  # a map of the file is read-only
        inside = reader.rows(slice(4, 6))  # inside the second chunk
        assert np.array_equal(inside, data[4:6]) and inside.flags.writeable != mapped
        assert np.array_equal(reader.rows(slice(2, 4)), data[2:4])  # across a chunk boundary: read
        del rows, inside


# --- several outputs published together ----------------------------------------------------

def _write(path, text, overwrite=False):
    from facesynth.model.artifacts import atomic_path

    with atomic_path(path, overwrite) as tmp:
        tmp.write_text(text)


def test_outputs_of_a_group_appear_together_when_it_ends(tmp_path):
    from facesynth.model.artifacts import atomic_folder, published_together, recording_published

    published = []
    with recording_published(published), published_together():
        _write(tmp_path / "a.h5", "a")
        with atomic_folder(tmp_path / "images", "the images") as folder:
            (folder / "1.png").write_text("png")
        assert sorted(p.name for p in tmp_path.iterdir()) == [f"a.h5.tmp-{os.getpid()}", f"images.tmp-{os.getpid()}"]
    assert (tmp_path / "a.h5").read_text() == "a" and (tmp_path / "images" / "1.png").read_text() == "png"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.h5", "images"]
    assert published == [tmp_path / "a.h5", tmp_path / "images"]


def test_an_error_in_a_group_leaves_none_of_its_outputs(tmp_path):
    from facesynth.model.artifacts import published_together

    with pytest.raises(RuntimeError, match="failed after the first"):
        with published_together():
            _write(tmp_path / "a.h5", "a")
            raise RuntimeError("failed after the first")
    assert list(tmp_path.iterdir()) == []


def test_a_group_that_cannot_publish_one_output_takes_back_the_others(tmp_path):
    """The second output's name is taken by another process while the group is written: the
    first, already in place, is taken back and the file it replaced returns."""
    from facesynth.model.artifacts import published_together

    (tmp_path / "a.h5").write_text("old a")
    with pytest.raises(OutputExistsError, match=r"b\.png: another process wrote this output"):
        with published_together():
            _write(tmp_path / "a.h5", "new a", overwrite=True)
            _write(tmp_path / "b.png", "mine")
            (tmp_path / "b.png").write_text("theirs")
    assert (tmp_path / "a.h5").read_text() == "old a" and (tmp_path / "b.png").read_text() == "theirs"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.h5", "b.png"]


def test_an_interrupt_while_a_group_is_published_leaves_none(tmp_path, monkeypatch):
    """Ctrl-C between the renames of two outputs is held until the group is back to nothing
    (the replaced output restored), then raised."""
    from facesynth.model import artifacts

    (tmp_path / "a.h5").write_text("old a")
    publish = artifacts.publish

    def interrupted_after(tmp, path, overwrite):
        publish(tmp, path, overwrite)
        os.kill(os.getpid(), signal.SIGINT)

    monkeypatch.setattr(artifacts, "publish", interrupted_after)
    published = []
    with pytest.raises(KeyboardInterrupt):
        with artifacts.recording_published(published), artifacts.published_together():
            _write(tmp_path / "a.h5", "new a", overwrite=True)
            _write(tmp_path / "b.png", "b")
    assert published == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.h5"] and (tmp_path / "a.h5").read_text() == "old a"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
