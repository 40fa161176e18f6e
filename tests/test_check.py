"""``facesynth check`` and the specification it checks against (facesynth.model.spec).

Every kind is written from the tiny sample corpus by its own stage and must check clean, and
everything the writers write must be declared (and everything declared written), so the
specification cannot drift from the writers. Damaged copies must be reported, one line per
problem, with exit status 1."""

from __future__ import annotations

import dataclasses
import shutil
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.methods import MethodSettings
from facesynth.model import check, spec
from facesynth.model.artifacts import SCHEMAS, input_record

DOC = Path(__file__).resolve().parents[1] / "docs" / "file-format.md"


@pytest.fixture(scope="module")
def written(tiny_corpus, tiny_artifacts, tiny_db, held_out_take, config, tmp_path_factory) -> dict[str, Path]:
    """One file of every kind (and variant), each written by its stage from the tiny corpus."""
    from facesynth.stages import (
        capture,
        deform,
        expression,
        fit_method,
        head_motion,
        ingest,
        isomap,
        keyshapes,
        normalize,
        prune,
        retarget,
        rig_mesh,
        solve,
        synthesize,
    )

    d = tmp_path_factory.mktemp("check")
    out = {**tiny_artifacts, "motiondb": tiny_db, "pruned": d / "pruned.h5", "isomap": d / "isomap.h5",
           "motion": d / "motion.h5", "greedy": d / "greedy.h5", "capture": d / "capture.h5", "meshanim": d / "anim.h5",
           "keyshapes": d / "keyshapes.h5", "curves": d / "solved.h5", "retargeted": d / "retargeted.h5",
           "rig_mesh": d / "rig_anim.h5"}
    prune.run(tiny_db, out["pruned"], config.settings("prune"), "3,5", False, "test", False)
    isomap.run(out["pruned"], out["isomap"], config.settings("isomap"))
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    synth = config.settings("synthesize")
    for name, settings in (("motion", synth), ("greedy", dataclasses.replace(synth, search="greedy"))):
        synthesize.run(out["pruned"], out[name], settings, config.settings("ingest"), config.settings("align"), phones_path=tg)
    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, out["capture"], config.settings("normalize"), 30.0)
    deform.run(out["motion"], tiny_corpus / "face.obj", tiny_corpus / "markers.csv", out["meshanim"], config.settings("deform"))
    out["expression"], out["restyle"], out["headmotion"] = d / "expr.h5", d / "restyle.h5", d / "head.h5"
    expression.fit(tiny_artifacts["normalized"], out["expression"], config.settings("expression"))
    expression.restyle(out["expression"], out["capture"], out["restyle"], config.settings("expression"),
                       config.settings("ingest"), to="happy", intensity=0.5, emotions_path=None)
    head_motion.run(tiny_db, tiny_artifacts["corpus"], tiny_corpus / "audio" / f"{held_out_take}.wav", out["headmotion"],
                    config.settings("head_motion"))
    ks = dataclasses.replace(config.settings("keyshapes"), count=3, curve_frames=200)
    keyshapes.run(tiny_db, out["keyshapes"], ks)
    solve.run(out["capture"], out["curves"], config.settings("solve"))
    retarget.run(out["motion"], out["keyshapes"], out["retargeted"], dataclasses.replace(config.settings("retarget"), blend="linear"),
                 ks, mesh_out=d / "retargeted_anim.h5")
    rig_mesh.run(out["curves"], out["rig_mesh"])
    out["trajectory"], out["trajectory_motion"] = d / "traj.h5", d / "traj_motion.h5"
    fit_method.run("trajectory", tiny_db, out["trajectory"], MethodSettings.of(config), keyshapes_path=out["keyshapes"])
    every = MethodSettings.of(config)
    synthesize.run(out["trajectory"], out["trajectory_motion"], every, config.settings("ingest"), config.settings("align"),
                   method="trajectory", phones_path=tg)
    out["coarticulation"], out["coarticulation_motion"], out["mean_motion"] = d / "coart.h5", d / "coart_motion.h5", d / "mean.h5"
    fit_method.run("coarticulation", tiny_db, out["coarticulation"],
                   every.replace(coarticulation=dataclasses.replace(every.coarticulation, iterations=5)))
    for name, source in (("coarticulation", out["coarticulation"]), ("mean", tiny_db)):
        synthesize.run(source, out[f"{name}_motion"], every, config.settings("ingest"), config.settings("align"),
                       method=name, phones_path=tg)
    # a corpus of takes posed from curves (a Live Link Face take) writes the rest pose and the known
    # head pose, and its normalized capture says it is posed
    from facesynth.domain.rig.face import load_face_rig
    from facesynth.formats import livelink_face

    (d / "live_link").mkdir()
    livelink_face.write(d / "live_link" / "take.csv", load_face_rig().arkit_names, np.full((30, 52), 0.2), 60.0,
                        head=np.full((30, 3), 0.1))
    (d / "live_link" / "manifest.csv").write_text("take,mocap\nt,take.csv\n")
    out["posed_corpus"], out["posed_normalized"] = d / "posed_corpus.h5", d / "posed_normalized.h5"
    ingest.run(d / "live_link" / "manifest.csv", out["posed_corpus"], config.settings("ingest"), config.settings("align"))
    normalize.run(out["posed_corpus"], out["posed_normalized"], config.settings("normalize"))
    # no stage fits the articulation model yet: one fitted on a take's audio, its loudness the target
    from facesynth.domain.voice import articulation
    from facesynth.formats.audio import read_audio

    samples, rate = read_audio(tiny_corpus / "audio" / f"{held_out_take}.wav")
    raw = articulation.frame_features(samples, rate)
    loudness = raw[::3, articulation.I_LOG_RMS:articulation.I_LOG_RMS + 1].astype(np.float64)
    out["articulation"] = d / "articulation.h5"
    articulation.fit([articulation.Take(raw, loudness, 100.0 / 3.0)], ("opening",)).write(
        out["articulation"], config="{}", inputs=[])
    # a capture in another language keeps each phone's IPA (phones/ipa, nodes/ipa): the tiny corpus
    # with its phones written as IPA, as ingest writes a take aligned in its own language
    from facesynth.base.ipa import FESTIVAL_IPA
    from facesynth.model.corpus import Corpus
    from facesynth.stages import build_db, pca

    relabelled = Corpus.read(tiny_artifacts["corpus"])
    relabelled.phones.ipa = ["" if p == "pau" else FESTIVAL_IPA[p] for p in relabelled.phones.phone]
    for name in ("corpus", "normalized", "pca", "motiondb"):
        out[f"ipa_{name}"] = d / f"ipa_{name}.h5"
    relabelled.write(out["ipa_corpus"], config="{}", inputs=[])
    normalize.run(out["ipa_corpus"], out["ipa_normalized"], config.settings("normalize"))
    pca.run(out["ipa_normalized"], out["ipa_pca"], config.settings("pca"))
    build_db.run(out["ipa_pca"], out["ipa_motiondb"], config.settings("build_db"))
    return out


def _damaged(written, tmp_path, name: str, damage) -> Path:
    """A copy of the clean ``name`` artifact with ``damage(h5py.File)`` applied."""
    path = tmp_path / f"{name}.h5"
    shutil.copyfile(written[name], path)
    with h5py.File(path, "r+") as f:
        damage(f)
    return path


def _check(*paths) -> tuple[int, list[str]]:
    """Exit status and output lines of ``facesynth check PATHS`` (the closing 'error:' summary left out)."""
    result = CliRunner().invoke(main, ["check", *map(str, paths)])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result.exit_code, [line for line in result.output.splitlines() if line and not line.startswith("error:")]


def _replace(f: h5py.File, key: str, data, **kw) -> None:
    attrs = dict(f[key].attrs)
    del f[key]
    f.create_dataset(key, data=data, **kw).attrs.update(attrs)


# ---------------------------------------------------------------- the specification and the writers

def test_the_specification_covers_every_kind_at_its_schema():
    assert set(spec.KINDS) == set(SCHEMAS)
    for kind in spec.KINDS.values():
        assert kind.schema == SCHEMAS[kind.name]
        for key, e in spec.walk(kind.root):
            for a in e.attrs:
                assert a.type in spec.ATTR_TYPES, (kind.name, key, a.name)
                if a.name == "units":  # the stored unit is the documented one
                    assert a.choices == (e.unit,), (kind.name, key)
            if isinstance(e, spec.Dataset):
                dtypes = e.dtype if isinstance(e.dtype, tuple) else (e.dtype,)
                assert set(dtypes) <= set(spec.DTYPES), (kind.name, key)
                for size in e.shape:
                    assert spec.parse_size(size)[1] in (None, *spec.SYMBOLS), (kind.name, key, size)


@pytest.mark.parametrize("name", ["corpus", "normalized", "pca", "motiondb", "pruned", "isomap", "motion", "greedy",
                                  "capture", "meshanim", "expression", "restyle", "headmotion", "keyshapes", "curves",
                                  "retargeted", "rig_mesh", "trajectory", "trajectory_motion", "coarticulation",
                                  "coarticulation_motion", "mean_motion", "posed_corpus", "posed_normalized",
                                  "articulation", "ipa_corpus", "ipa_normalized", "ipa_pca",
                                  "ipa_motiondb"])
def test_every_kind_written_by_its_stage_checks_clean(written, name):
    report = check.check_file(written[name])
    assert report.problems == []
    assert report.lines() == [f"{written[name]}: ok ({report.kind}, schema {SCHEMAS[report.kind]})"]


def _written_keys(f: h5py.File, kind: spec.Kind) -> dict[str, set[str]]:
    """Every key of ``f`` (a pattern group's members under its pattern name) and its attributes."""
    patterns = {k.rsplit("/", 1)[0]: e.name for k, e in spec.walk(kind.root) if isinstance(e, spec.Group) and e.pattern}
    out = {"": set(f.attrs)}

    def visit(name, obj):
        parts = name.split("/")
        for i in range(1, len(parts)):
            if "/".join(parts[:i]) in patterns:
                parts[i] = patterns["/".join(parts[:i])]
        out.setdefault("/".join(parts), set()).update(obj.attrs)

    f.visititems(visit)
    return out


def test_the_writers_write_exactly_what_the_specification_declares(written):
    """Each key and attribute written is declared, and each declared key is written by some stage."""
    declared_written: dict[str, set[str]] = {}
    for path in written.values():
        with h5py.File(path, "r") as f:
            kind = spec.KINDS[f.attrs["facesynth_kind"]]
            entries = dict(spec.walk(kind.root))
            keys = _written_keys(f, kind)
        root_attrs = {a.name for a in spec.COMMON_ATTRS + kind.attrs}
        assert keys.pop("") <= root_attrs, path
        for key, attrs in keys.items():
            assert key in entries, f"{path}: /{key} is written but not declared"
            extra = {"encoding-type", "encoding-version"} if isinstance(entries[key], spec.Group) else set()
            assert attrs <= {a.name for a in entries[key].attrs} | extra, f"{path}: /{key} has undeclared attributes"
        declared_written.setdefault(kind.name, set()).update(keys)
    for kind in spec.KINDS.values():
        assert {k for k, _ in spec.walk(kind.root)} == declared_written[kind.name], kind.name


def test_the_file_format_document_is_generated_from_the_specification():
    text = DOC.read_text(encoding="utf-8")
    assert spec.GENERATED_MARK in text
    assert text == spec.document(text), "docs/file-format.md is out of date: run python -m facesynth.model.spec docs/file-format.md"
    for name in ("encoding-type", "encoding-version", "facesynth check"):
        assert name in text.split(spec.GENERATED_MARK)[0]


# ---------------------------------------------------------------- damaged files, one problem each

DAMAGES = {
    "a dataset dropped": ("motiondb", lambda f: f.__delitem__("transition/dsc_in"),
                          "/transition/dsc_in: missing required dataset (float32, shape (N, D))."),
    "a group dropped": ("motion", lambda f: f.__delitem__("provenance"),
                        "/provenance: missing required group (encoding-type 'provenance')."),
    "a dtype changed": ("motiondb", lambda f: _replace(f, "nodes/viseme", f["nodes/viseme"][()].astype(np.float64)),
                        "/nodes/viseme: dtype float64; expected int64."),
    "a fixed size changed": ("normalized", lambda f: _replace(f, "head_rotation", f["head_rotation"][:, :, :2]),
                             "/head_rotation: shape ({F}, 3, 2) has 2 in axis 2; expected 3."),
    "a dimension lost": ("corpus", lambda f: _replace(f, "audio/start", f["audio/start"][()][:, None]),
                         "/audio/start: shape ({T}, 1) has 2 dimensions; expected 1: (T,)."),
    "an encoding-type removed": ("motion", lambda f: f["path"].attrs.__delitem__("encoding-type"),
                                 "/path: no 'encoding-type' attribute; expected 'search-path'."),
    "an encoding-type wrong": ("meshanim", lambda f: f["weights"].attrs.__setitem__("encoding-type", "csc-matrix"),
                               "/weights: encoding-type is 'csc-matrix'; expected 'csr-matrix'."),
    "an encoding-version unknown": ("pca", lambda f: f["pca"].attrs.__setitem__("encoding-version", "2"),
                                    "/pca: encoding-version is '2'; this version reads '1'."),
    "fps removed": ("normalized", lambda f: f["markers"].attrs.__delitem__("fps"),
                    "/markers: missing attribute 'fps' (float: frames/s)."),
    "units changed": ("motion", lambda f: f["markers"].attrs.__setitem__("units", "cm"),
                      "/markers: attribute 'units' is 'cm'; expected 'mm'."),
    "fps zero": ("pca", lambda f: f["coefficients"].attrs.__setitem__("fps", 0.0),
                 "/coefficients: attribute 'fps' is 0.0; it must be > 0."),
    "an external link": ("meshanim", lambda f: f.__setitem__("outside", h5py.ExternalLink("other.h5", "/x")),
                         "/outside: an external link to '/x' in 'other.h5'; an artifact must stay inside its file."),
    "a soft link": ("corpus", lambda f: f.__setitem__("takes/alias", h5py.SoftLink("/takes/name")),
                    "/takes/alias: a soft link to '/takes/name'; artifacts hold no links."),
    "a non-finite number": ("pca", lambda f: f["pca/basis"].__setitem__((3, 2), np.nan),
                            "/pca/basis: 1 non-finite value (NaN or infinity) where every number must be finite."),
    "an unknown dataset": ("isomap", lambda f: f.create_dataset("notes", data=np.zeros(3)),
                           "/notes: unexpected dataset; the 'isomap' schema 1 specification has no such key."),
    "a wrong schema": ("corpus", lambda f: f.attrs.__setitem__("facesynth_schema", 2),
                       "/: 'corpus' schema 2 is not the supported schema 1; rebuild it with this version's "
                       "`facesynth ingest`."),
    "an unknown kind": ("pca", lambda f: f.attrs.__setitem__("facesynth_kind", "wireframe"),
                        "/: unknown kind 'wireframe'; facesynth writes corpus, normalized, pca, motiondb, isomap, "
                        "motion, meshanim, expression, headmotion, curves, keyshapes, trajectory, coarticulation, "
                        "articulation."),
    "a capture without its take": ("capture", lambda f: f.attrs.__delitem__("take"),
                                   "/: missing attribute 'take' (str: the captured take)."),
}


@pytest.mark.parametrize("what", list(DAMAGES))
def test_a_damaged_file_is_reported_with_the_right_line_and_status_1(written, tmp_path, what):
    name, damage, line = DAMAGES[what]
    path = _damaged(written, tmp_path, name, damage)
    with h5py.File(written["normalized"], "r") as f:
        sizes = {"F": len(f["markers"]), "T": len(f["takes/name"])}
    status, lines = _check(path)
    assert status == 1
    assert lines == [f"{path}: {line.format(**sizes)}"]


def test_shapes_that_disagree_name_the_key_that_differs_from_the_rest(written, tmp_path):
    with h5py.File(written["pca"], "r") as f:
        m = len(f["marker_names"])
    path = _damaged(written, tmp_path, "pca", lambda f: _replace(f, "marker_names", f["marker_names"][:-1],
                                                                  dtype=h5py.string_dtype()))
    status, lines = _check(path)
    assert status == 1
    assert lines == [f"{path}: /marker_names: shape ({m - 1},) gives M = {m - 1}, but /pca/mean has M = {m} "
                     "(as do 3 other keys)."]


def test_a_phoneme_cluster_is_checked_against_its_own_sizes_and_the_model(written, tmp_path):
    def damage(f):
        phone = sorted(f["clusters"])[0]
        _replace(f, f"clusters/{phone}/node", f[f"clusters/{phone}/node"][1:])

    path = _damaged(written, tmp_path, "isomap", damage)
    status, lines = _check(path)
    assert status == 1 and len(lines) == 1
    assert "/node: shape" in lines[0] and "gives n = " in lines[0] and "/frames has n = " in lines[0]


def test_data_kept_outside_the_file_is_refused_and_not_read(written, tmp_path):
    (tmp_path / "raw.bin").write_bytes(np.full(10, np.nan, np.float32).tobytes())

    def damage(f):
        source = tmp_path / "source.h5"
        with h5py.File(source, "w") as g:
            g["x"] = np.zeros(4)
        layout = h5py.VirtualLayout(shape=(4,), dtype="f8")
        layout[:] = h5py.VirtualSource(str(source), "x", shape=(4,))
        f.create_virtual_dataset("virtual", layout)
        f.create_dataset("external", shape=(10,), dtype="f4", external=[(str(tmp_path / "raw.bin"), 0, 40)])

    path = _damaged(written, tmp_path, "motion", damage)
    status, lines = _check(path)
    assert status == 1
    assert f"{path}: /external: stored in external files ({tmp_path / 'raw.bin'}); an artifact must stay inside its file." in lines
    assert (f"{path}: /virtual: a virtual dataset (its data lives in other files); an artifact must stay inside "
            "its file.") in lines
    assert not any("non-finite" in line for line in lines)


def test_every_problem_of_a_file_is_reported(written, tmp_path):
    def damage(f):
        del f["transition/dsc_in"]
        _replace(f, "nodes/viseme", f["nodes/viseme"][()].astype(np.float64))
        del f["boundary"].attrs["encoding-type"]
        f["outside"] = h5py.ExternalLink("other.h5", "/x")
        del f["markers"].attrs["units"]
        f["transition/dsc_out"][0, 0] = np.inf

    path = _damaged(written, tmp_path, "motiondb", damage)
    status, lines = _check(path)
    assert status == 1
    assert lines == [f"{path}: {line}" for line in (
        "/outside: an external link to '/x' in 'other.h5'; an artifact must stay inside its file.",
        "/markers: missing attribute 'units' (str: always 'mm').",
        "/nodes/viseme: dtype float64; expected int64.",
        "/boundary: no 'encoding-type' attribute; expected 'boundary-states'.",
        "/transition/dsc_out: 1 non-finite value (NaN or infinity) where every number must be finite.",
        "/transition/dsc_in: missing required dataset (float32, shape (N, D)).",
    )]


def test_the_finiteness_scan_reads_in_bounded_blocks_and_counts_every_block(written, tmp_path, monkeypatch):
    def damage(f):
        f["pca/basis"][0, 1] = np.nan
        f["pca/basis"][-1, -1] = np.inf

    path = _damaged(written, tmp_path, "pca", damage)
    monkeypatch.setattr(check, "SCAN_ELEMENTS", 64)
    reads = []
    original = h5py.Dataset.__getitem__

    def spy(self, args, *rest):
        out = original(self, args, *rest)
        if self.name == "/pca/basis":
            reads.append(np.size(out))
        return out

    monkeypatch.setattr(h5py.Dataset, "__getitem__", spy)
    report = check.check_file(path)
    assert [str(p) for p in report.problems] == [
        f"{path}: /pca/basis: 2 non-finite values (NaN or infinity) where every number must be finite."]
    with h5py.File(path, "r") as f:
        rows, cols = f["pca/basis"].shape
    assert max(reads) <= 64 and sum(reads) == rows * cols


# ---------------------------------------------------------------- files that are no artifact

def test_a_file_that_is_not_hdf5_or_missing_is_one_line_each(tmp_path, written):
    text = tmp_path / "manifest.csv"
    text.write_text("take,mocap\n")
    status, lines = _check(text, tmp_path / "missing.h5", written["pca"])
    assert status == 1
    assert lines == [f"{text}: not an HDF5 file, so not a facesynth artifact.",
                     f"{tmp_path / 'missing.h5'}: file not found.",
                     f"{written['pca']}: ok (pca, schema 1)"]


def test_an_hdf5_file_of_another_tool_is_not_an_artifact(tmp_path):
    path = tmp_path / "other.h5"
    with h5py.File(path, "w") as f:
        f["x"] = np.zeros(3)
        f["y"] = h5py.ExternalLink("elsewhere.h5", "/z")
    status, lines = _check(path)
    assert status == 1
    assert lines == [f"{path}: /: no 'facesynth_kind' attribute, so not a facesynth artifact.",
                     f"{path}: /y: an external link to '/z' in 'elsewhere.h5'; an artifact must stay inside its file."]


# ---------------------------------------------------------------- provenance

def test_inputs_that_changed_or_went_away_are_reported(tiny_artifacts, config, tmp_path, monkeypatch):
    """Inputs are recorded as the stage was given them (here relative) and read from the current directory."""
    from facesynth.stages import normalize

    monkeypatch.chdir(tmp_path)
    shutil.copyfile(tiny_artifacts["corpus"], "corpus.h5")
    normalize.run(Path("corpus.h5"), Path("normalized.h5"), config.settings("normalize"))
    assert _check("normalized.h5") == (0, ["normalized.h5: ok (normalized, schema 1)"])

    recorded = input_record(Path("corpus.h5"))["sha256"]
    with h5py.File("corpus.h5", "r+") as f:
        f.attrs["note"] = "edited"
    now = input_record(Path("corpus.h5"))["sha256"]
    assert _check("normalized.h5") == (1, [
        f"normalized.h5: /: input 'corpus.h5' (inputs[0]) has changed since this file was made (its sha256 starts "
        f"{now[:12]} now, {recorded[:12]} when recorded)."])

    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    assert _check(tmp_path / "normalized.h5") == (1, [
        f"{tmp_path / 'normalized.h5'}: /: input 'corpus.h5' (inputs[0]) is not found (relative paths are read "
        "from the current directory)."])


# ---------------------------------------------------------------- the command

def test_clean_files_exit_0_and_say_ok(written):
    status, lines = _check(written["corpus"], written["meshanim"])
    assert status == 0
    assert lines == [f"{written['corpus']}: ok (corpus, schema 1)", f"{written['meshanim']}: ok (meshanim, schema 1)"]


def test_quiet_prints_only_problems_and_usage_errors_exit_2(written, tmp_path):
    result = CliRunner().invoke(main, ["check", "-q", str(written["pca"])])
    assert result.exit_code == 0 and result.output == ""
    assert CliRunner().invoke(main, ["check"]).exit_code == 2


def test_help_shows_a_runnable_example():
    result = CliRunner().invoke(main, ["check", "--help"])
    assert result.exit_code == 0 and "facesynth check corpus.h5 db.h5 motion.h5" in result.output


def test_a_damaged_frame_provenance_is_reported(written, tmp_path):
    def damage(f):
        _replace(f, "provenance/node", f["provenance/node"][:-1])
        del f["provenance/segments/start"]
        f["provenance"].attrs["origin"] = "guess"

    path = _damaged(written, tmp_path, "retargeted", damage)
    status, lines = _check(path)
    assert status == 1
    text = "\n".join(lines)
    assert "/provenance/node" in text and "/provenance/segments/start: missing required dataset" in text
    assert "origin" in text
