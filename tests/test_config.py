import dataclasses
from pathlib import Path

import pytest
from click.testing import CliRunner

from facesynth.base.config import (
    DECLARATIONS,
    SAMPLE_CORPUS_PRESETS,
    SECTIONS,
    Config,
    choices,
    default_config,
    reference_markdown,
)
from facesynth.base.errors import ConfigError
from facesynth.cli import main

DOCS = Path(__file__).resolve().parents[1] / "docs" / "configuration.md"


def test_defaults_hold_the_paper_values():
    c = Config.load()
    assert c.settings("pca").n_components == 25
    assert c.settings("isomap").n_neighbors == 12
    s = c.settings("synthesize")
    assert s.weight_high == 2.0 and s.weight_low == 0.5
    # the paper's Eq. 16 window is s = 3; the default join blend reaches 6 frames (50 ms) each side
    assert s.join_smoothing == "blend" and s.smoothing_half_window == 6
    assert "p" in s.high_phones and "k" in s.low_phones


def test_file_then_set_overrides(tmp_path):
    f = tmp_path / "my.toml"
    f.write_text("[pca]\nn_components = 10\nvariance_target = 0.9\n")
    c = Config.load(f, ("pca.n_components=12", "synthesize.search=greedy"))
    assert c.settings("pca").n_components == 12
    assert c.settings("pca").variance_target == 0.9
    assert c.settings("synthesize").search == "greedy"


def test_an_integer_is_taken_for_a_number_and_lists_become_tuples():
    c = Config.load(None, ("synthesize.output_fps=24", "synthesize.high_phones=['p', 'b']"))
    s = c.settings("synthesize")
    assert s.output_fps == 24.0 and isinstance(s.output_fps, float)
    assert s.high_phones == ("p", "b")


def test_every_default_has_a_declaration_and_every_declaration_a_default():
    defaults = default_config()
    assert list(defaults) == list(SECTIONS)
    for section, cls in SECTIONS.items():
        fields = dataclasses.fields(cls)
        assert list(defaults[section]) == [f.name for f in fields], section
        for f in fields:
            assert f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING, f.name
            assert f.metadata["setting"].source, f"{section}.{f.name} names no source"
    Config.load()  # the defaults pass their own declarations


@pytest.mark.parametrize("override, message", [
    ("pca.components=3", r"unknown key 'pca.components'; the keys of \[pca\] are n_components, variance_target\."),
    ("nosuch.key=1", r"unknown section \[nosuch\]; the sections are ingest, align, "),
    ("pca.n_components=abc", r"'pca.n_components' must be an integer >= 1; got \"abc\"\."),
    ("pca.n_components=0", r"'pca.n_components' must be an integer >= 1; got 0\."),
    ("pca.n_components=2.5", r"must be an integer >= 1; got 2\.5\."),
    ("pca.n_components=true", r"must be an integer >= 1; got true\."),
    ("synthesize.pnt=nan", r"'synthesize.pnt' must be a number > 0 \(cost\); got nan\."),
    ("synthesize.pnt=inf", r"got inf\."),
    ("synthesize.output_fps=-30", r"'synthesize.output_fps' must be a number > 0 and <= 1000 \(frames/s\); got -30\.$"),
    ("synthesize.alpha4=1", r"'synthesize.alpha4' must be a number > 0 and < 1; got 1\."),
    ("synthesize.search=beam", r"'synthesize.search' must be one of dp, greedy; got \"beam\"\."),
    ("synthesize.use_opencl=yes", r"'synthesize.use_opencl' must be true or false; got \"yes\"\."),
    ("synthesize.high_phones=['p', 'q']", r"must be a list of strings, each one of aa, .*; got \[\"p\", \"q\"\]\."),
    ("synthesize.high_phones='p'", r"must be a list of strings, each one of"),
    ("evaluate.lip_markers=['ULI_C']", r"'evaluate.lip_markers' must be a list of strings, exactly 2; got"),
    ("ingest.emotions=[1, 2]", r"'ingest.emotions' must be a list of strings, at least 1; got \[1, 2\]\."),
    ("ingest.emotion_aliases={ a = 1 }", r"'ingest.emotion_aliases' must be a table of strings; got \{ a = 1 \}\."),
    ("deform.sigma=-1.5", r"'deform.sigma' must be a number > 0 \(mesh units\); got -1\.5\."),
    ("pca", "expected section.key=value"),
])
def test_bad_overrides_are_named(override, message):
    with pytest.raises(ConfigError, match=message) as info:
        Config.load(None, (override,))
    assert str(info.value).startswith(f"--set {override}: ") or override == "pca"


@pytest.mark.parametrize("text, message", [
    ("[synthesize]\npnt = nan\n", r"'synthesize.pnt' must be a number > 0 \(cost\); got nan\."),
    ("[synthesize]\noutput_fps = -30\n", r"'synthesize.output_fps' must be a number > 0 and <= 1000 \(frames/s\); got -30\.$"),
    ("[pca]\nn_components = 0\n", r"'pca.n_components' must be an integer >= 1; got 0\."),
    ("[deform]\nsigma = -1.0\n", r"'deform.sigma' must be a number > 0 \(mesh units\); got -1\.0\."),
    ("[render]\nview = \"wire\"\n", r"'render.view' must be one of shaded, markers, side-by-side; got \"wire\"\."),
    ("[render]\nwidth = \"640\"\n", r"'render.width' must be an integer >= 16 \(px\); got \"640\"\."),
    ("[render]\nsize = 3\n", r"unknown key 'render.size'; the keys of \[render\] are width, height,"),
    ("[rendering]\nwidth = 3\n", r"unknown section \[rendering\]"),
    ("render = 3\n", r"\[render\] must be a table of settings; got 3\."),
])
def test_bad_config_file_values_are_named(tmp_path, text, message):
    f = tmp_path / "bad.toml"
    f.write_text(text)
    with pytest.raises(ConfigError, match=message) as info:
        Config.load(f)
    assert str(info.value).startswith(f"{f}: ")
    assert "\n" not in str(info.value)


def test_a_bad_file_is_refused_before_any_work(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[synthesize]\npnt = nan\n")
    r = CliRunner().invoke(main, ["sample-corpus", str(tmp_path / "c"), "--preset", "tiny", "--config", str(f)])
    assert r.exit_code == 1
    assert r.output == f"error: {f}: 'synthesize.pnt' must be a number > 0 (cost); got nan.\n"
    assert not (tmp_path / "c").exists()


def test_bad_toml_file_is_named(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[pca\n")
    with pytest.raises(ConfigError, match="bad.toml: not valid TOML"):
        Config.load(f)


def test_click_choices_come_from_the_declarations():
    from facesynth.domain.corpus.generate import PRESETS

    def option(command, name):
        return next(p for p in command.params if p.name == name)

    assert option(main.commands["synthesize"], "search").type.choices == choices("synthesize", "search")
    assert option(main.commands["render"], "view").type.choices == choices("render", "view")
    assert option(main.commands["sample-corpus"], "preset").type.choices == SAMPLE_CORPUS_PRESETS
    assert (*PRESETS, "facegood") == SAMPLE_CORPUS_PRESETS  # the actress's sizes, then a real performer's takes
    with pytest.raises(KeyError):
        choices("pca", "n_components")


def test_the_settings_reference_is_up_to_date():
    assert DOCS.read_text("utf-8") == reference_markdown(), (
        "docs/configuration.md is stale; rewrite it with `python -m facesynth.base.config > docs/configuration.md`.")
    for declared in DECLARATIONS.values():
        for name in declared:
            assert f"| `{name}` |" in reference_markdown()
