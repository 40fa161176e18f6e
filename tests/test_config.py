import pytest

from facesynth.config import Config
from facesynth.errors import ConfigError


def test_defaults_hold_the_paper_values():
    c = Config.load()
    assert c.settings("pca").n_components == 25
    assert c.settings("isomap").n_neighbors == 12
    s = c.settings("synthesize")
    assert s.smoothing_half_window == 3 and s.weight_high == 2.0 and s.weight_low == 0.5
    assert "p" in s.high_phones and "k" in s.low_phones


def test_file_then_set_overrides(tmp_path):
    f = tmp_path / "my.toml"
    f.write_text("[pca]\nn_components = 10\nvariance_target = 0.9\n")
    c = Config.load(f, ("pca.n_components=12", "synthesize.search=greedy"))
    assert c.settings("pca").n_components == 12
    assert c.settings("pca").variance_target == 0.9
    assert c.settings("synthesize").search == "greedy"


@pytest.mark.parametrize("override, message", [
    ("pca.components=3", "unknown key 'pca.components'"),
    ("nosuch.key=1", r"unknown section \[nosuch\]"),
    ("pca.n_components=abc", "must be int"),
    ("synthesize.search=beam", "must be one of dp, greedy"),
    ("pca", "expected section.key=value"),
])
def test_bad_overrides_are_named(override, message):
    with pytest.raises(ConfigError, match=message):
        Config.load(None, (override,))


def test_bad_toml_file_is_named(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[pca\n")
    with pytest.raises(ConfigError, match="bad.toml: not valid TOML"):
        Config.load(f)
