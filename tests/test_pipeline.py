"""The stage declarations (facesynth.base.pipeline) agree with the commands, the artifact kinds,
the settings and the docs generated from them."""

import dataclasses
import inspect
from pathlib import Path

import click
import pytest

from facesynth.base import pipeline
from facesynth.base.config import SECTIONS
from facesynth.base.pipeline import STAGE, STAGES
from facesynth.cli import main
from facesynth.model.artifacts import PRODUCERS, SCHEMAS

DOC = Path(__file__).resolve().parents[1] / "docs" / "pipeline.md"


def _commands(group: click.Group = main, prefix: str = ""):
    """Every leaf command below ``group``, as (path, click command)."""
    for name, command in group.commands.items():
        if isinstance(command, click.Group):
            yield from _commands(command, f"{prefix}{name} ")
        else:
            yield prefix + name, command


COMMANDS = dict(_commands())


def test_every_command_is_declared_and_every_declared_command_exists():
    assert sorted(COMMANDS) == sorted(STAGE)
    assert len(STAGE) == len(STAGES)  # no command declared twice


def test_help_lists_the_commands_in_the_declared_order():
    listed = main.list_commands(click.Context(main))
    assert tuple(listed) == pipeline.COMMAND_ORDER
    assert [s.name.split()[0] for s in STAGES] == sorted((s.name.split()[0] for s in STAGES),
                                                          key=pipeline.COMMAND_ORDER.index)  # a group's commands together


@pytest.mark.parametrize("stage", STAGES, ids=lambda s: s.name)
def test_declared_output_options_exist_and_writing_commands_take_overwrite(stage):
    params = {p.name: p for p in COMMANDS[stage.name].params}
    assert set(stage.output_options) <= set(params), f"{stage.name}: no option {set(stage.output_options) - set(params)}"
    assert set(stage.folder_outputs) <= set(stage.output_options)
    for folder in stage.folder_outputs.values():
        if folder.when is not None:
            option, value = folder.when
            assert option in params and value in params[option].type.choices  # type: ignore[attr-defined]
    assert ("overwrite" in params) == stage.writes


def test_every_path_option_named_like_an_output_is_declared():
    """An option whose help says 'Output' (or a folder written) must be checked before any work."""
    for name, command in COMMANDS.items():
        outputs = {p.name for p in command.params if isinstance(p, click.Option) and p.help
                   and (p.help.startswith(("Output", "Report folder", "Also write")))}
        outputs |= {p.name for p in command.params if isinstance(p, click.Argument) and p.name == "out_dir"}
        assert outputs <= set(STAGE[name].output_options), f"{name}: {outputs - set(STAGE[name].output_options)}"


@pytest.mark.parametrize("stage", STAGES, ids=lambda s: s.name)
def test_core_and_result_resolve(stage):
    core = stage.load_core()
    assert callable(core)
    result = stage.load_result()
    if result is None:
        return
    assert dataclasses.is_dataclass(result) and result.__dataclass_params__.frozen  # type: ignore[attr-defined]
    assert result.__module__ == core.__module__, "a stage's result is defined beside its core"
    returned = inspect.signature(core).return_annotation
    assert returned in (result.__name__, result), f"{stage.core} is annotated to return {returned}"
    assert result.__doc__ and all(f.name in result.__doc__ for f in dataclasses.fields(result)), \
        f"{stage.result}: document every field"


def test_kinds_and_sections_are_real():
    for stage in STAGES:
        assert set(stage.input_kinds()) | set(stage.output_kinds()) <= set(SCHEMAS), stage.name
        assert set(stage.sections()) <= set(SECTIONS) - {pipeline.ALWAYS_READ}, stage.name
    assert {s for stage in STAGES for s in pipeline.READS[stage.name]} == set(SECTIONS)


def test_every_kind_has_its_writers_named():
    for kind in SCHEMAS:
        # a kind no command writes yet names what does write it (pipeline.OTHER_WRITERS)
        assert pipeline.writers(kind) or kind in pipeline.OTHER_WRITERS, f"no stage declares that it writes '{kind}'"
    assert PRODUCERS["articulation"] == "`facesynth fit-articulation`"
    assert PRODUCERS["motion"] == ("`facesynth synthesize`, `facesynth expression restyle`, `facesynth batch` "
                                   "or `facesynth capture`")
    assert PRODUCERS["pca"] == "`facesynth pca`"
    assert pipeline.writers("motiondb") == ("facesynth build-db", "facesynth prune")


def test_a_wrong_kind_names_every_command_that_makes_the_right_one(tmp_path):
    from facesynth.base.errors import ArtifactError
    from facesynth.model.artifacts import open_artifact, write_artifact

    with write_artifact(tmp_path / "c.h5", "curves"):
        pass
    with pytest.raises(ArtifactError, match=r"found a 'curves' artifact but expected 'motion'; pass the output of "
                                            r"`facesynth synthesize`, .* or `facesynth capture`\.$"):
        open_artifact(tmp_path / "c.h5", "motion")


def test_the_folder_of_an_obj_sequence_is_a_folder_only_for_that_format():
    export = STAGE["export"]
    assert export.folders({"fmt": "obj-seq"})["output"].what == "the OBJ sequence"
    assert export.folders({"fmt": "glb"}) == {}


def test_pipeline_md_stage_table_is_generated_from_the_declarations():
    text = DOC.read_text(encoding="utf-8")
    assert text == pipeline.document(text), ("docs/pipeline.md is out of date: run make docs "
                                             "(python -m facesynth.base.pipeline docs/pipeline.md)")
    for stage in STAGES:
        assert f"`{stage.usage.replace('|', chr(92) + '|')}`" in text


def test_the_declarations_import_nothing_of_facesynth():
    import ast

    tree = ast.parse(Path(pipeline.__file__).read_text())
    imported = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    imported |= {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    assert not any(m is None or m.startswith("facesynth") for m in imported)


def test_a_folder_filled_in_place_may_exist_before_the_run(tmp_path):
    """batch writes into its folder line by line and a rerun skips the lines done: the check made
    before any work accepts the existing folder (it refused it as 'a folder, but this output is one file')."""
    from facesynth.base.errors import OutputExistsError
    from facesynth.cli import _check_outputs

    (tmp_path / "lines").mkdir()
    (tmp_path / "lines" / "l1.motion.h5").write_text("done before")
    _check_outputs("batch", {"output": tmp_path / "lines"}, overwrite=False)
    with pytest.raises(OutputExistsError, match="is not empty"):
        _check_outputs("evaluate", {"output": tmp_path / "lines"}, overwrite=False)


def test_an_interrupted_batch_says_its_folder_keeps_the_lines_done(tmp_path, monkeypatch):
    """batch's lines are written into its folder one by one (by worker processes): an interrupt
    leaves the lines finished, and says so instead of 'no output was written'."""
    from click.testing import CliRunner

    from facesynth.stages import batch

    def some_lines_then_interrupt(script, db, out_dir, *args, **kwargs):
        out_dir.mkdir()
        (out_dir / "l1.motion.h5").write_text("a line done")
        raise KeyboardInterrupt

    monkeypatch.setattr(batch, "run", some_lines_then_interrupt)
    script, db = tmp_path / "script.csv", tmp_path / "db.h5"
    script.write_text("id,audio,text\n")
    db.write_text("")
    r = CliRunner().invoke(main, ["batch", str(script), "--db", str(db), "-o", str(tmp_path / "lines")])
    assert r.exit_code == 130, r.output
    assert r.output.strip().splitlines() == [f"interrupted; {tmp_path / 'lines'} keeps what was finished before it; "
                                             "a rerun goes on from there."]
