"""The public Python API (``facesynth.api``, offered by ``import facesynth``): its names, its
cheap import, one path with the command line (the command and the API call the same domain steps
and write the same bytes for the same inputs), objects made in memory, and its errors."""

from __future__ import annotations

import ast
import filecmp
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

import facesynth
from facesynth import api
from facesynth.base.errors import FacesynthError
from facesynth.cli import main
from facesynth.domain.exports import format as exporting
from facesynth.domain.methods import steps
from facesynth.domain.retarget import facial_solve

ROOT = Path(__file__).resolve().parents[2]


def cli(*args: object) -> None:
    """Run ``facesynth ARGS`` in this process, as the command line does."""
    result = CliRunner().invoke(main, [str(a) for a in args] + ["-q"], prog_name="facesynth", catch_exceptions=False)
    assert result.exit_code == 0, result.output


def same_files(a: Path, b: Path) -> bool:
    return a.read_bytes() == b.read_bytes()


def h5_contents(path: Path, leave_out: tuple[str, ...] = ()) -> dict:
    """Every group's and dataset's attributes and every dataset's values and dtype, by name; the
    root attributes ``leave_out`` left out."""
    out: dict = {}
    with h5py.File(path, "r") as f:
        out["/"] = {k: str(v) for k, v in f.attrs.items() if k not in leave_out}

        def visit(name, obj):
            attrs = {k: str(v) for k, v in obj.attrs.items()}
            if isinstance(obj, h5py.Dataset):
                data = obj[()]
                values = data.tolist() if isinstance(data, np.ndarray) and data.dtype.kind == "O" else data
                out[name] = (attrs, str(obj.dtype), values.tobytes() if isinstance(values, np.ndarray) else repr(values))
            else:
                out[name] = attrs
        f.visititems(visit)
    return out


# --- the names ------------------------------------------------------------------------------

def test_the_public_names_are_one_list():
    """facesynth's lazy names, facesynth.api.__all__ and the type stub name the same things, and
    each is the API's own object."""
    assert api.__all__ == ["__version__", *facesynth._API]
    stub = ast.parse((Path(facesynth.__file__).parent / "__init__.pyi").read_text(encoding="utf-8"))
    stubbed = [a.asname for n in stub.body if isinstance(n, ast.ImportFrom) and n.module == "facesynth.api"
               for a in n.names]
    assert sorted(stubbed) == sorted(facesynth._API)
    for name in facesynth._API:
        assert getattr(facesynth, name) is getattr(api, name), name
    assert set(facesynth._API) <= set(dir(facesynth))
    with pytest.raises(AttributeError, match="no attribute 'synthesise'"):
        facesynth.synthesise  # noqa: B018


def test_import_stays_cheap():
    """``import facesynth`` (and the command line's import) loads none of the heavy libraries; the
    first API name used does."""
    code = ("import sys, facesynth, facesynth.cli; heavy = ('numpy', 'h5py', 'scipy');"
            "print(sorted(m for m in heavy if m in sys.modules)); facesynth.synthesize;"
            "print(sorted(m for m in heavy if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[0] == "[]" and "numpy" in out[1]


def test_the_version_is_the_package_version():
    declared = re.search(r'^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(), flags=re.M)
    assert declared is not None and facesynth.__version__ == declared.group(1)


# --- one path with the command line ---------------------------------------------------------

@pytest.fixture(scope="module")
def inputs(tiny_db, tiny_corpus, held_out_take, tmp_path_factory) -> dict[str, Path]:
    """The held-out sentence's files, an emotion spans file and a constraints file for it."""
    d = tmp_path_factory.mktemp("api-inputs")
    phones = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    (d / "spans.txt").write_text("0 0.6 happy\n0.6 1000 angry\n")
    db = facesynth.read_database(tiny_db)
    utt = facesynth.utterance_from_phones(phones)
    index = next(i for i, p in enumerate(utt.phones) if p in db.nodes.phone and p != "pau")
    (d / "constraints.txt").write_text(f"{index} {db.nodes.phone.index(utt.phones[index])}\n")
    manifest = (tiny_corpus / "manifest.csv").read_text().splitlines()
    text = next(line.split(",")[4] for line in manifest if line.startswith(held_out_take + ","))
    return {"db": tiny_db, "phones": phones, "audio": tiny_corpus / "audio" / f"{held_out_take}.wav",
            "spans": d / "spans.txt", "constraints": d / "constraints.txt", "text": Path(text)}


SYNTHESES = {
    # case: (the command's options, the API call given the inputs and the output)
    "phones, emotions": (
        ["--phonemes", "phones", "--emotions", "spans"],
        lambda i, o: facesynth.synthesize(i["db"], facesynth.utterance_from_phones(i["phones"], emotions=i["spans"]),
                                          output=o)),
    "constraints": (
        ["--phonemes", "phones", "--constraints", "constraints"],
        lambda i, o: facesynth.synthesize(facesynth.read_database(i["db"]), facesynth.utterance_from_phones(i["phones"]),
                                          constraints=i["constraints"], output=o)),
    "greedy, phones with audio": (
        ["--method", "greedy", "--phonemes", "phones", "--audio", "audio"],
        lambda i, o: facesynth.synthesize(i["db"], facesynth.utterance_from_phones(i["phones"], audio=i["audio"]),
                                          method="greedy", output=o)),
    "mean": (
        ["--method", "mean", "--phonemes", "phones"],
        lambda i, o: facesynth.synthesize(i["db"], facesynth.utterance_from_phones(i["phones"]), method="mean",
                                          output=o)),
    "audio and text": (
        ["--audio", "audio", "--text", "text"],
        lambda i, o: facesynth.synthesize(i["db"], facesynth.utterance_from_audio(i["audio"], str(i["text"])),
                                          output=o)),
    "audio recognised, settings": (
        ["--audio", "audio", "--set", "synthesize.output_fps=24"],
        lambda i, o: facesynth.synthesize(i["db"], facesynth.utterance_from_audio(i["audio"]), output=o,
                                          config=facesynth.load_config(overrides=["synthesize.output_fps=24"]))),
}


@pytest.mark.parametrize("case", list(SYNTHESES))
def test_synthesize_writes_the_commands_bytes(case, inputs, tmp_path):
    options, call = SYNTHESES[case]
    args = [str(inputs[o]) if o in inputs else o for o in options]
    cli("synthesize", inputs["db"], *args, "-o", tmp_path / "cli.h5")
    motion = call(inputs, tmp_path / "api.h5")
    assert same_files(tmp_path / "cli.h5", tmp_path / "api.h5")
    assert isinstance(motion, facesynth.Motion) and motion.path is not None


def test_a_fitted_model_writes_the_commands_bytes(tiny_trajectory, inputs, tmp_path):
    cli("synthesize", tiny_trajectory, "--method", "trajectory", "--phonemes", inputs["phones"], "-o", tmp_path / "cli.h5")
    model = facesynth.read_model(tiny_trajectory)
    assert isinstance(model, facesynth.TrajectoryModel)
    spoken = facesynth.utterance_from_phones(inputs["phones"])
    facesynth.synthesize(tiny_trajectory, spoken, output=tmp_path / "api.h5")  # its member by default
    assert same_files(tmp_path / "cli.h5", tmp_path / "api.h5")
    in_memory = facesynth.synthesize(model, spoken)  # the model object: the same motion, nothing to record
    assert np.array_equal(in_memory.markers, facesynth.read_motion(tmp_path / "cli.h5").markers)


def test_solve_writes_the_commands_bytes(held_out_synthesized, tmp_path):
    motion = held_out_synthesized["motion"]
    cli("solve", motion, "-o", tmp_path / "cli.h5")
    curves = facesynth.solve(motion, output=tmp_path / "api.h5")
    assert same_files(tmp_path / "cli.h5", tmp_path / "api.h5")
    assert isinstance(curves, facesynth.RigCurves) and curves.provenance is not None
    # the motion read into memory: the same curves, only the motion's file is not recorded
    facesynth.solve(facesynth.read_motion(motion), output=tmp_path / "memory.h5")
    assert h5_contents(tmp_path / "cli.h5", ("inputs",)) == h5_contents(tmp_path / "memory.h5", ("inputs",))
    assert h5py.File(tmp_path / "memory.h5").attrs["inputs"] == "[]"


def test_solve_onto_a_users_rig_writes_the_commands_bytes(held_out_synthesized, tmp_path):
    """A user's rig (here the built-in rig's GLB, bound with its own binding) given by file, as a
    :class:`Rig` read once, and on the command line."""
    rig_file, binding = tmp_path / "rig.glb", tmp_path / "binding.csv"
    facesynth.export(held_out_synthesized["curves"], "glb", rig_file)
    binding.write_text("marker,vertex\n" + "".join(f"{m},{v}\n" for m, v in facesynth.read_rig().binding.items()))
    motion = held_out_synthesized["motion"]
    cli("solve", motion, "--rig", rig_file, "--binding", binding, "-o", tmp_path / "cli.h5")
    curves = facesynth.solve(motion, rig=rig_file, binding=binding, output=tmp_path / "api.h5")
    assert same_files(tmp_path / "cli.h5", tmp_path / "api.h5")
    assert curves.rig_name == "rig"
    rig = facesynth.read_rig(rig_file, binding)
    again = facesynth.solve(facesynth.read_motion(motion), rig=rig)
    assert np.array_equal(again.weights, curves.weights)


EXPORTS = {"arkit-csv": "face.csv", "glb": "face.glb", "gltf": "face.gltf", "obj-seq": "face_obj", "usda": "face.usda"}


@pytest.mark.parametrize("fmt", list(EXPORTS))
def test_export_writes_the_commands_files(fmt, held_out_synthesized, tmp_path):
    """Curves exported from their file and from the object in memory: the command's files, byte
    for byte (a glTF with its audio beside it)."""
    try:
        api.EXPORT_FORMATS.get(fmt).require()
    except FacesynthError as exc:
        pytest.skip(str(exc))
    curves, name = held_out_synthesized["curves"], EXPORTS[fmt]
    audio = ["--audio", held_out_synthesized["audio"]] if fmt == "gltf" else []
    folders = {w: tmp_path / w for w in ("cli", "file", "memory")}
    for folder in folders.values():
        folder.mkdir()
    cli("export", curves, "--format", fmt, *audio, "-o", folders["cli"] / name)
    wav = held_out_synthesized["audio"] if audio else None
    files = facesynth.export(curves, fmt, folders["file"] / name, audio=wav)
    facesynth.export(facesynth.read_curves(curves), fmt, folders["memory"] / name, audio=wav)
    assert files[0] == folders["file"] / name or files[0].parent == folders["file"] / name
    for other in ("file", "memory"):
        compared = filecmp.dircmp(folders["cli"], folders[other])
        assert not compared.left_only and not compared.right_only and not compared.diff_files, other
        if fmt == "obj-seq":
            sub = filecmp.dircmp(folders["cli"] / name, folders[other] / name)
            assert not sub.left_only and not sub.right_only and not sub.diff_files


def test_a_motion_exports_from_memory_as_from_its_file(held_out_synthesized, tmp_path):
    motion = held_out_synthesized["motion"]
    cli("export", motion, "--format", "c3d", "-o", tmp_path / "cli.c3d")
    (tmp_path / "memory").mkdir()
    facesynth.export(facesynth.read_motion(motion), "c3d", tmp_path / "memory" / "cli.c3d")
    assert same_files(tmp_path / "cli.c3d", tmp_path / "memory" / "cli.c3d")


def test_the_command_and_the_api_go_through_the_same_steps(held_out_synthesized, inputs, monkeypatch, tmp_path):
    """One path: the command line's synthesize, solve and export call the domain steps the API calls."""
    calls: list[str] = []

    def spy(module, name):
        real = getattr(module, name)

        def wrapper(*args, **kwargs):
            calls.append(f"{module.__name__.rpartition('.')[2]}.{name}")
            return real(*args, **kwargs)
        monkeypatch.setattr(module, name, wrapper)

    for module, name in [(steps, "synthesize_utterance"), (steps, "write_motion"), (facial_solve, "solve"),
                         (facial_solve, "write"), (exporting, "chosen_format"), (exporting, "export")]:
        spy(module, name)
    cli("synthesize", inputs["db"], "--phonemes", inputs["phones"], "-o", tmp_path / "m.h5")
    cli("solve", tmp_path / "m.h5", "-o", tmp_path / "c.h5")
    cli("export", tmp_path / "c.h5", "--format", "arkit-csv", "-o", tmp_path / "c.csv")
    by_command = list(calls)
    calls.clear()
    motion = facesynth.synthesize(inputs["db"], facesynth.utterance_from_phones(inputs["phones"]),
                                  output=tmp_path / "m2.h5")
    facesynth.export(facesynth.solve(motion, output=tmp_path / "c2.h5"), "arkit-csv", tmp_path / "c2.csv")
    assert calls == by_command == ["steps.synthesize_utterance", "steps.write_motion", "facial_solve.solve",
                                   "facial_solve.write", "format.chosen_format", "format.export"]


# --- objects in memory ----------------------------------------------------------------------

def test_phones_and_spans_as_lists_are_the_files(inputs, tmp_path):
    """An utterance from (phone, start, end) triples and (start, end, emotion) spans makes the
    motion its .lab and spans files make."""
    spoken = facesynth.utterance_from_phones(inputs["phones"], emotions=inputs["spans"])
    triples = list(zip(spoken.phones, spoken.starts.tolist(), spoken.ends.tolist()))
    (tmp_path / "u.lab").write_text("".join(f"{a} {b} {p}\n" for p, a, b in triples))
    from_lists = facesynth.utterance_from_phones(triples, emotions=[(0, 0.6, "Happy"), (0.6, 1000, "angry")])
    from_files = facesynth.utterance_from_phones(tmp_path / "u.lab", emotions=inputs["spans"])
    assert from_lists.emotions == from_files.emotions == spoken.emotions and "happy" in spoken.emotions
    assert from_lists.phones_file is None and from_files.phones_file == tmp_path / "u.lab"
    a = facesynth.synthesize(inputs["db"], from_lists)
    b = facesynth.synthesize(inputs["db"], from_files)
    assert np.array_equal(a.markers, b.markers) and list(a.path.node) == list(b.path.node)


def test_constraints_as_a_mapping_are_the_file(inputs):
    db = facesynth.read_database(inputs["db"])
    spoken = facesynth.utterance_from_phones(inputs["phones"])
    index, node = map(int, inputs["constraints"].read_text().split())
    given = facesynth.synthesize(db, spoken, constraints={index: node})
    from_file = facesynth.synthesize(db, spoken, constraints=inputs["constraints"])
    assert given.path.node[index] == node and np.array_equal(given.markers, from_file.markers)


def test_a_synthesis_in_memory_solves_as_its_file(inputs, tmp_path):
    """synthesize -> solve with nothing written between: the curves of the command's chain, apart
    from the inputs recorded (the motion has no file)."""
    cli("synthesize", inputs["db"], "--phonemes", inputs["phones"], "-o", tmp_path / "m.h5")
    cli("solve", tmp_path / "m.h5", "-o", tmp_path / "cli.h5")
    motion = facesynth.synthesize(inputs["db"], facesynth.utterance_from_phones(inputs["phones"]))
    facesynth.solve(motion, output=tmp_path / "api.h5")
    assert h5_contents(tmp_path / "cli.h5", ("inputs",)) == h5_contents(tmp_path / "api.h5", ("inputs",))


def test_utterances_say_what_they_hold(inputs):
    heard = facesynth.utterance_from_audio(inputs["audio"], str(inputs["text"]))
    assert heard.alignment is not None and heard.audio_file == inputs["audio"] and heard.phones_file is None
    assert len(heard) == len(heard.phones) == len(heard.starts) and heard.duration_s == pytest.approx(heard.ends[-1])
    assert heard.where == str(inputs["audio"])
    assert facesynth.utterance_from_phones(inputs["phones"]).alignment is None
    assert {"dp", "greedy", "mean", "trajectory", "coarticulation"} <= set(facesynth.methods())
    assert {"arkit-csv", "glb", "c3d"} <= set(facesynth.export_formats())


# --- errors ---------------------------------------------------------------------------------

def test_bad_inputs_are_one_sentence(inputs, tiny_trajectory, held_out_synthesized, tmp_path):
    db = facesynth.read_database(inputs["db"])
    spoken = facesynth.utterance_from_phones(inputs["phones"])
    with pytest.raises(facesynth.UsageError, match="the trajectory method reads a trajectory model .*a database was given"):
        facesynth.synthesize(db, spoken, method="trajectory")
    with pytest.raises(facesynth.UsageError, match="the dp method reads a motion database; a trajectory model was given"):
        facesynth.synthesize(facesynth.read_model(tiny_trajectory), spoken, method="dp")
    with pytest.raises(facesynth.UsageError, match="unknown method 'dpp'"):
        facesynth.synthesize(db, spoken, method="dpp")
    with pytest.raises(facesynth.UsageError, match="the mean method takes none"):
        facesynth.synthesize(db, spoken, method="mean", constraints={1: 0})
    with pytest.raises(facesynth.SearchError, match=r"the constraints given, phone 0: .*pause"):
        facesynth.synthesize(db, spoken, constraints={0: 0})
    with pytest.raises(facesynth.SearchError, match="phone index 999 is out of range"):
        facesynth.synthesize(db, spoken, constraints={999: 0})
    with pytest.raises(facesynth.InputError, match="expected a phone index and a node id"):
        facesynth.synthesize(db, spoken, constraints={"1": 0})
    with pytest.raises(facesynth.InputError, match=r"the phones given, item 1: expected \(phone, start_s, end_s\)"):
        facesynth.utterance_from_phones([("hh", 0, 0.1), ("ah", 0.1)])
    with pytest.raises(facesynth.InputError, match="the phones given, 0.100 s: segment 'ah' overlaps"):
        facesynth.utterance_from_phones([("hh", 0, 0.2), ("ah", 0.1, 0.3)])
    with pytest.raises(facesynth.InputError, match="the phones given, 0.000 s: unknown phone 'qq'"):
        facesynth.utterance_from_phones([("qq", 0, 0.2)])
    with pytest.raises(facesynth.InputError, match="the emotion spans given, item 0: unknown emotion 'glum'"):
        facesynth.utterance_from_phones(inputs["phones"], emotions=[(0, 1, "glum")])
    with pytest.raises(facesynth.InputError, match="the emotion spans given, item 0: the span ends at or before"):
        facesynth.utterance_from_phones(inputs["phones"], emotions=[(1, 1, "happy")])
    with pytest.raises(facesynth.InputError, match="is a 'motiondb' artifact, not a fitted model"):
        facesynth.read_model(inputs["db"])
    with pytest.raises(facesynth.UsageError, match="take picks a take"):
        facesynth.solve(facesynth.read_motion(held_out_synthesized["motion"]), take="x")
    with pytest.raises(facesynth.UsageError, match="unknown format 'fbx'"):
        facesynth.export(held_out_synthesized["curves"], "fbx", tmp_path / "x.fbx")
    with pytest.raises(facesynth.InputError, match="the motion given: c3d carries markers|the curves given: c3d"):
        facesynth.export(facesynth.read_curves(held_out_synthesized["curves"]), "c3d", tmp_path / "x.c3d")
    (tmp_path / "taken.h5").write_bytes(b"")
    with pytest.raises(facesynth.OutputExistsError, match="output exists; pass --overwrite"):
        facesynth.synthesize(db, spoken, output=tmp_path / "taken.h5")
    assert facesynth.synthesize(db, spoken, output=tmp_path / "taken.h5", overwrite=True) is not None
    with pytest.raises(facesynth.ConfigError, match="synthesize.output_fps"):
        facesynth.load_config(overrides=["synthesize.output_fps=-1"])


def test_the_configs_limits_are_in_force(inputs):
    tight = facesynth.load_config(overrides=["limits.max_utterance_s=0.5"])
    with pytest.raises(facesynth.InputError, match=r"limits.max_utterance_s = 0.5"):
        facesynth.utterance_from_phones(inputs["phones"], config=tight)
    facesynth.utterance_from_phones(inputs["phones"])  # outside the call the defaults apply again
