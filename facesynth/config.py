"""Typed, per-stage settings.

``configs/default.toml`` is the single source of default values. A stage asks for its
own section as a frozen dataclass; the resolved section is stored in the artifact the
stage writes (root attribute ``config``). Precedence: defaults < ``--config`` file <
``--set section.key=value`` overrides.
"""

from __future__ import annotations

import dataclasses
import json
import sys
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Mapping, TypeVar

from .errors import ConfigError

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


@dataclass(frozen=True)
class IngestSettings:
    emotions: tuple[str, ...]
    emotion_aliases: Mapping[str, str]
    max_audio_mismatch_s: float
    phone_tiers: tuple[str, ...]


@dataclass(frozen=True)
class AlignSettings:
    frame_rate: int
    sample_rate: int


@dataclass(frozen=True)
class NormalizeSettings:
    origin_marker: str
    rigid_markers: tuple[str, ...]
    max_gap_frames: int
    reference_take: str
    reference_frame: int
    reference_silence_s: float


@dataclass(frozen=True)
class PcaSettings:
    n_components: int
    variance_target: float


@dataclass(frozen=True)
class BuildDbSettings:
    dsc_samples: int
    use_opencl: bool


@dataclass(frozen=True)
class IsomapSettings:
    n_neighbors: int
    max_exact_frames: int
    image_size: int
    kernel_sigma_px: float
    rho: float


@dataclass(frozen=True)
class PruneSettings:
    jump_z: float
    max_excursion_s: float
    outlier_z: float


@dataclass(frozen=True)
class SynthesizeSettings:
    search: str
    greedy_clusters: int
    postprocess: str
    use_opencl: bool
    pnt: float
    alpha1: float
    alpha2: float
    alpha3: float
    alpha4: float
    alpha5: float
    alpha6: float
    huge_penalty: float
    smoothing_half_window: int
    smoothing_lambda: float
    weight_high: float
    weight_low: float
    weight_intermediate: float
    high_phones: tuple[str, ...]
    low_phones: tuple[str, ...]
    output_fps: float
    silence_interpolation: str


@dataclass(frozen=True)
class EvaluateSettings:
    split: str
    lip_markers: tuple[str, ...]
    closure_mm: float
    plot_marker: str


@dataclass(frozen=True)
class TuneSettings:
    starts: int
    max_evaluations: int
    seed: int
    spread: float


@dataclass(frozen=True)
class DeformSettings:
    sigma: float
    distance_threshold: float
    apply_head_motion: bool


@dataclass(frozen=True)
class RenderSettings:
    width: int
    height: int
    fps: float
    view: str
    fov_deg: float
    use_opencl: bool


SECTIONS: dict[str, type] = {
    "ingest": IngestSettings,
    "align": AlignSettings,
    "normalize": NormalizeSettings,
    "pca": PcaSettings,
    "build_db": BuildDbSettings,
    "isomap": IsomapSettings,
    "prune": PruneSettings,
    "synthesize": SynthesizeSettings,
    "evaluate": EvaluateSettings,
    "tune": TuneSettings,
    "deform": DeformSettings,
    "render": RenderSettings,
}

_CHOICES = {
    ("synthesize", "search"): ("dp", "greedy"),
    ("synthesize", "silence_interpolation"): ("linear", "cubic", "cosine"),
    ("synthesize", "postprocess"): ("deng", "cao"),
    ("render", "view"): ("shaded", "markers", "side-by-side"),
    ("evaluate", "split"): ("test", "val"),
}

S = TypeVar("S")


def _read_toml(path: Path) -> dict[str, Any]:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise ConfigError(f"{path}: configuration file not found; check the --config path.") from None
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML ({exc}); fix the file.") from None


def default_config() -> dict[str, dict[str, Any]]:
    """The packaged defaults, ``configs/default.toml``, as nested dicts."""
    text = resources.files("facesynth").joinpath("configs/default.toml").read_text("utf-8")
    return tomllib.loads(text)


def _parse_override(item: str) -> tuple[str, str, Any]:
    if "=" not in item or "." not in item.split("=", 1)[0]:
        raise ConfigError(f"--set {item!r}: expected section.key=value, e.g. --set pca.n_components=20.")
    key, raw = item.split("=", 1)
    section, name = key.strip().split(".", 1)
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        value = raw  # a bare word is a string: --set synthesize.search=greedy
    return section, name, value


class Config:
    """The resolved configuration: defaults, then a file, then ``--set`` overrides."""

    def __init__(self, data: dict[str, dict[str, Any]]):
        self._data = data

    @classmethod
    def load(cls, path: Path | None = None, overrides: tuple[str, ...] = ()) -> "Config":
        data = default_config()
        layers: list[tuple[str, dict[str, Any]]] = []
        if path is not None:
            layers.append((str(path), _read_toml(Path(path))))
        for item in overrides:
            section, name, value = _parse_override(item)
            layers.append((f"--set {item}", {section: {name: value}}))
        for origin, layer in layers:
            for section, values in layer.items():
                if section not in data or not isinstance(values, dict):
                    known = ", ".join(sorted(data))
                    raise ConfigError(f"{origin}: unknown section [{section}]; known sections: {known}.")
                for name, value in values.items():
                    if name not in data[section]:
                        raise ConfigError(
                            f"{origin}: unknown key '{section}.{name}'; see configs/default.toml for the keys."
                        )
                    default = data[section][name]
                    if isinstance(default, (int, float)) and not isinstance(default, bool) and isinstance(value, int) and not isinstance(value, bool):
                        value = type(default)(value)
                    if type(value) is not type(default) and not (isinstance(default, float) and isinstance(value, int)):
                        raise ConfigError(
                            f"{origin}: '{section}.{name}' must be {type(default).__name__}, got {value!r}."
                        )
                    choices = _CHOICES.get((section, name))
                    if choices and value not in choices:
                        raise ConfigError(f"{origin}: '{section}.{name}' must be one of {', '.join(choices)}; got {value!r}.")
                    data[section][name] = value
        return cls(data)

    def section(self, name: str) -> dict[str, Any]:
        """The raw values of one section (a copy)."""
        return json.loads(json.dumps(self._data[name]))

    def settings(self, section: str, cls: type[S] | None = None) -> S:
        """The section as its frozen dataclass (lists become tuples)."""
        cls = cls or SECTIONS[section]
        values = {}
        for field in dataclasses.fields(cls):
            value = self._data[section][field.name]
            values[field.name] = tuple(value) if isinstance(value, list) else value
        return cls(**values)


def settings_json(settings: Any) -> str:
    """JSON of a settings dataclass, stored as the ``config`` attribute of artifacts."""
    def plain(v):
        if isinstance(v, tuple):
            return [plain(x) for x in v]
        if isinstance(v, Mapping):
            return {k: plain(x) for k, x in v.items()}
        return v
    return json.dumps({k: plain(v) for k, v in dataclasses.asdict(settings).items()}, sort_keys=True)
