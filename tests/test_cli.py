"""The command line end to end on the tiny corpus, through click's CliRunner."""

import h5py
from click.testing import CliRunner

from facesynth.cli import main


def _run(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    return result


def test_intake_chain_end_to_end(tiny_corpus, tmp_path):
    for args in (
        ("ingest", tiny_corpus / "manifest.csv", "-o", tmp_path / "corpus.h5"),
        ("normalize", tmp_path / "corpus.h5", "-o", tmp_path / "normalized.h5"),
        ("pca", tmp_path / "normalized.h5", "-o", tmp_path / "pca.h5"),
    ):
        r = _run(*args)
        assert r.exit_code == 0, r.output
    assert "components cover" in r.output
    with h5py.File(tmp_path / "pca.h5") as f:
        assert f.attrs["facesynth_kind"] == "pca"
        assert f["coefficients"].shape[1] == 25
        assert f["pca"].attrs["explained"] > 0.95


def test_user_error_is_one_line_and_exit_1(tmp_path):
    r = _run("normalize", tmp_path / "missing.h5", "-o", tmp_path / "n.h5")
    assert r.exit_code == 1
    assert r.output.strip().startswith("error: ") and "Traceback" not in r.output
    assert len(r.output.strip().splitlines()) == 1


def test_wrong_artifact_kind(tiny_artifacts, tmp_path):
    r = _run("pca", tiny_artifacts["corpus"], "-o", tmp_path / "p.h5")
    assert r.exit_code == 1
    assert "found a 'corpus' artifact but expected 'normalized'" in r.output


def test_set_override_reaches_the_stage(tiny_artifacts, tmp_path):
    r = _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "--set", "pca.n_components=7")
    assert r.exit_code == 0, r.output
    with h5py.File(tmp_path / "p.h5") as f:
        assert f["coefficients"].shape[1] == 7
        assert '"n_components": 7' in f.attrs["config"]


def test_usage_error_is_exit_2():
    assert _run("pca").exit_code == 2


def test_every_command_has_a_runnable_example():
    for name, command in main.commands.items():
        assert "Example:" in (command.help or "") or "Examples:" in (command.help or ""), name


def test_only_commands_that_write_offer_overwrite():
    from facesynth.cli import main as group

    readers = {("db", "show"), ("devices",), ("suggest",), ("isomap", "pick"), ("check",)}
    for path in [("db", "show"), ("devices",), ("suggest",), ("isomap", "pick"), ("check",), ("synthesize",), ("render",)]:
        command = group
        for name in path:
            command = command.commands[name]
        has = any("--overwrite" in p.opts for p in command.params)
        assert has == (path not in readers), path
