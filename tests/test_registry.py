"""The extension points are registries (docs/architecture.md, "Extending facesynth"): a toy member
of each family, its own code plus one registration line, is offered by the command line (its
choices and ``--help``), read and checked like the built-in members (``facesynth check``,
``--set`` validation, the pipeline's producers) and listed in the docs' tables; and the docs'
tables are the registries as they stand."""

import json
from dataclasses import dataclass, replace
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base import registry
from facesynth.base.config import Config, reference_markdown, setting
from facesynth.base.pipeline import READS, producers
from facesynth.base.registry import ARTIFACT_KINDS, CAPTURE_READERS, EXPORT_FORMATS, METHODS
from facesynth.cli import main
from facesynth.domain.capture.readers import read_capture
from facesynth.domain.exports.animation import Exportable
from facesynth.domain.exports.format import ExportFormat, ExportOptions
from facesynth.domain.live.synthesizer import LiveModel, LiveSynthesizer
from facesynth.domain.methods import FitSummary, Method, MethodSettings, Synthesis, SynthesisSummary
from facesynth.domain.methods.live import LiveSource, LiveStepper
from facesynth.domain.methods.steps import frame_motion
from facesynth.domain.speech.utterance import read_utterance
from facesynth.formats.mocap import MarkerTake
from facesynth.model.artifacts import attr, open_artifact, read, read_strings, write_artifact, write_strings
from facesynth.model.spec import Attr, Dataset, Kind

DOCS = Path(__file__).resolve().parents[1] / "docs"

# --- a fitted method with its own artifact kind: the database's mean pose, held still ---------

TOY_KIND = Kind("toymean", 1, "A toy model: a database's mean pose.", (
    Dataset("mean", "float32", ("M", 3), "the mean position of each marker", "mm"),
    Dataset("marker_names", "str", ("M",), "marker labels"),
    Dataset("reference", "float32", ("M", 3), "the database's reference frame", "mm"),
), attrs=(Attr("fps", "float", "the capture rate", gt=0),))


@dataclass(frozen=True)
class ToyModel:
    mean: np.ndarray
    marker_names: list[str]
    reference: np.ndarray
    fps: float

    @classmethod
    def read(cls, path: Path) -> "ToyModel":
        with open_artifact(path, "toymean") as f:
            return cls(read(f, "mean"), read_strings(f, "marker_names"), read(f, "reference"), float(attr(f, "fps")))

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        with write_artifact(out, "toymean", config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs["fps"] = self.fps
            g.create_dataset("mean", data=self.mean.astype(np.float32))
            write_strings(g, "marker_names", self.marker_names)
            g.create_dataset("reference", data=self.reference.astype(np.float32))


@dataclass(frozen=True)
class ToySettings:
    """``[toymean]``: the toy's own settings section, declared as facesynth's are."""

    scale: float = setting("not in the paper: a toy; the share of the mean pose's displacement from the "
                           "reference held", ge=0, le=2)


class ToyLive(LiveSource):
    """The toy live: the held pose, whatever the phones."""

    what = "the toy model"

    def __init__(self, model: "ToyModel", settings: MethodSettings):
        self.synth, self.fps = settings.synthesize, float(settings.synthesize.output_fps)
        self.marker_names, self.reference = list(model.marker_names), np.asarray(model.reference, np.float32)
        self.grid_fps, self.emotions = float(model.fps), ["neutral"]
        self.rest_markers = self.reference.copy()
        self.pose = held_pose(model, settings.toymean.scale)

    def stepper(self) -> LiveStepper:
        return ToyStepper(self)


class ToyStepper(LiveStepper):
    def __init__(self, live: ToyLive):
        self.live = live

    def decide(self, track, upto: int) -> list[int]:
        return [-1] * (upto - len(track.committed))

    def final_limit(self, track) -> int:
        return int(round(track.ends[len(track.committed) - 1] * self.live.grid_fps))

    def render(self, track, first: int, stop: int) -> np.ndarray:
        return np.repeat(self.live.pose[None], stop - first, axis=0)


def held_pose(model: "ToyModel", scale: float) -> np.ndarray:
    """(M, 3) float32 mm: the reference moved ``scale`` of the way to the mean pose."""
    return (model.reference + scale * (model.mean - model.reference)).astype(np.float32)


class ToyMethod(Method):
    name = "toymean"

    def read(self, path: Path) -> ToyModel:
        return ToyModel.read(path)

    def fit(self, db, settings: MethodSettings, *, keyshapes=None, where: str = "the database"):
        mean = db.model.reconstruct(db.coeffs).mean(axis=0)
        return ToyModel(mean, list(db.marker_names), db.reference, db.fps), FitSummary(fit_rms_mm=0.0)

    def synthesize(self, source, utt, settings: MethodSettings, constraints=None, *, prepared=None,
                   where: str = "the utterance") -> Synthesis:
        self.refuse_constraints(constraints)
        frames = int(round(utt.ends[-1] * source.fps))
        markers = np.repeat(held_pose(source, settings.toymean.scale)[None], frames, axis=0)
        motion = frame_motion(self.name, utt, markers, None, source.fps, settings.synthesize.output_fps,
                              source.marker_names, source.reference, list(utt.phones), list(utt.emotions), "cpu")
        return Synthesis(motion, SynthesisSummary(phones=len(utt), frames=len(motion.markers)))

    def live(self, source, settings: MethodSettings) -> ToyLive:
        return ToyLive(source, settings)

    def ablations(self, db, settings: MethodSettings):
        """A variant scored beside it: the reference pose (the toy with scale 0)."""
        def reference(utt) -> np.ndarray:
            frames = int(round(utt.ends[-1] * db.fps))
            return np.repeat(np.asarray(db.reference, np.float32)[None], frames, axis=0)
        return {"toymean_still": reference}


# --- an export format: the rig weights as text --------------------------------------------------

class ToyText(ExportFormat):
    name = "toy-txt"
    carries = "weights"

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        np.savetxt(path, anim.weights, fmt="%.6f", header=" ".join(anim.rig.shape_names))
        return [path]


# --- a capture reader: markers as text (a rate line, a names line, then x y z per marker a row) -

def read_toy_markers(path: Path) -> MarkerTake:
    lines = Path(path).read_text().splitlines()
    names = lines[1].split()
    xyz = np.array([[float(v) for v in line.split()] for line in lines[2:]], np.float32)
    return MarkerTake(xyz.reshape(len(xyz), len(names), 3), names, float(lines[0]))


@pytest.fixture
def toys():
    """The four toy members, each registered by one line, unregistered after the test."""
    ARTIFACT_KINDS.register("toymean", TOY_KIND, "a toy model: a database's mean pose")
    METHODS.register("toymean", ToyMethod, "a toy: the database's mean pose, held still", fitted=True,
                     source_kind="toymean", streams=True, settings="toymean", settings_type=ToySettings,
                     settings_defaults={"scale": 1.0})
    EXPORT_FORMATS.register("toy-txt", ToyText(), "a toy: the rig weights as text", suffix=".toy.txt", batch=True)
    CAPTURE_READERS.register("toy", read_toy_markers, "a toy: markers as text", suffixes=(".toym",))
    try:
        yield
    finally:
        for family, name in ((ARTIFACT_KINDS, "toymean"), (METHODS, "toymean"), (EXPORT_FORMATS, "toy-txt"),
                             (CAPTURE_READERS, "toy")):
            family.unregister(name)


def test_toy_members_are_offered_in_help_and_settings(toys):
    runner = CliRunner()
    assert "toymean" in runner.invoke(main, ["synthesize", "--help"]).output
    assert "toymean" in runner.invoke(main, ["fit-method", "--help"]).output
    assert "toy-txt" in runner.invoke(main, ["export", "--help"]).output
    config = Config.load(overrides=('evaluate.methods=["dp", "toymean"]', 'batch.outputs=["curves", "toy-txt"]'))
    assert config.settings("evaluate").methods == ("dp", "toymean")
    assert config.settings("batch").outputs == ("curves", "toy-txt")
    assert producers("toymean") == "`facesynth fit-method`"


def test_a_toy_method_brings_its_settings_section(toys):
    """Its section is read, checked and documented like facesynth's own, by the commands that run
    members, in the members' settings."""
    config = Config.load(overrides=("toymean.scale=0.5",))
    assert config.settings("toymean") == ToySettings(scale=0.5)
    assert MethodSettings.of(config).toymean == ToySettings(scale=0.5)
    assert Config.load().settings("toymean").scale == 1.0  # its default, from its registration
    for command in ("synthesize", "batch", "stream", "evaluate", "fit-method"):
        assert "toymean" in READS[command], command
    assert "toymean" not in READS["render"]
    r = CliRunner().invoke(main, ["synthesize", "--set", "toymean.scale=3", "x.h5", "-o", "y.h5"])
    assert r.exit_code == 2 and "'toymean.scale' must be a number >= 0 and <= 2; got 3" in r.output
    r = CliRunner().invoke(main, ["render", "--set", "toymean.scale=1", "x.h5", "-o", "y.avi"])
    assert r.exit_code == 2 and "toymean" in r.output
    assert "## [toymean]" in reference_markdown() and "the share of the mean pose's displacement" in reference_markdown()


def test_a_toy_method_streams_through_its_live_hook(toys, tiny_db, tiny_corpus, held_out_take, tmp_path, config):
    """stream offers it and the live synthesizer runs its live form: every frame the held pose."""
    assert "toymean" in CliRunner().invoke(main, ["stream", "--help"]).output
    assert Config.load(overrides=("stream.method=toymean",)).settings("stream").method == "toymean"
    model_path = tmp_path / "toy.h5"
    assert CliRunner().invoke(main, ["fit-method", "toymean", str(tiny_db), "-o", str(model_path)]).exit_code == 0
    toy = ToyModel.read(model_path)
    settings = MethodSettings.of(Config.load(overrides=("toymean.scale=0.5",)))
    live = LiveModel(toy, settings, replace(config.settings("stream"), method="toymean", lookahead_phones=1,
                                                         pause_wait_s=3600.0),
                     config.settings("solve"))
    stream = LiveSynthesizer(live)
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    frames = []
    for p, a, b in zip(utt.phones, utt.starts, utt.ends):
        stream.add_phone(p, a, b)
        frames += stream.step(b)
    frames += stream.finish(utt.ends[-1])
    assert [f.index for f in frames] == list(range(len(frames))) and len(frames) > 10
    np.testing.assert_allclose(np.stack([f.markers for f in frames]),
                               np.repeat(held_pose(toy, 0.5)[None], len(frames), 0), atol=1e-5)
    r = CliRunner().invoke(main, ["stream", str(model_path), "--method", "dp", "--audio", "x.wav"])
    assert r.exit_code == 1 and "a toymean model streams with the toymean method; add --method toymean" in r.output
    r = CliRunner().invoke(main, ["stream", str(model_path), "--method", "coarticulation", "--audio", "x.wav"])
    assert r.exit_code == 2 and "'dp', 'greedy', 'trajectory', 'toymean'" in r.output  # the members with a live form


def test_a_toy_method_is_scored_by_evaluate_under_its_name(toys, tiny_db, tiny_artifacts, tmp_path):
    r = CliRunner().invoke(main, ["evaluate", str(tiny_db), "--heldout", str(tiny_artifacts["corpus"]),
                                  "--set", "evaluate.bootstrap_resamples=100", "--set", "evaluate.methods=['toymean']",
                                  "--set", "toymean.scale=0", "-o", str(tmp_path / "rep")])
    assert r.exit_code == 0, r.output
    m = json.loads((tmp_path / "rep" / "metrics.json").read_text())
    assert set(m) - {"figures_meta", "meta"} == {"dp", "toymean", "toymean_still", "capture"}
    # scale 0 holds the reference pose: the toy and its variant score the same
    assert m["toymean"]["overall"]["rms_mm"] == pytest.approx(m["toymean_still"]["overall"]["rms_mm"], rel=1e-5)
    assert "| toymean |" in (tmp_path / "rep" / "table.md").read_text()
    assert "\ntoymean: RMS" in r.output and "<i>toymean</i>, a toy" in (tmp_path / "rep" / "index.html").read_text()


def test_toy_members_are_in_the_docs_tables(toys):
    assert "| `toymean` | `toymean` | `toymean` | yes | a toy: the database's mean pose, held still |" in \
        registry.markdown("methods")
    assert "`toy-txt`" in registry.markdown("export-formats")
    assert "`*.toym`" in registry.markdown("capture-formats")
    assert "`toymean`" in registry.markdown("artifact-kinds")


def test_toy_members_work_like_the_built_in_ones(toys, tiny_db, tiny_corpus, held_out_take, held_out_synthesized,
                                                 tmp_path):
    """Fitted by fit-method, checked by check, synthesized by synthesize, exported by export, read
    as a capture."""
    runner = CliRunner()
    model = tmp_path / "toy.h5"
    r = runner.invoke(main, ["fit-method", "toymean", str(tiny_db), "-o", str(model)])
    assert r.exit_code == 0, r.output
    r = runner.invoke(main, ["check", str(model)])
    assert r.exit_code == 0 and "toymean" in r.output, r.output
    with h5py.File(model, "r+") as f:  # a broken toy artifact is refused like any other
        f.attrs["fps"] = -1.0
    r = runner.invoke(main, ["check", str(model)])
    assert r.exit_code == 1 and "fps" in r.output
    runner.invoke(main, ["fit-method", "toymean", str(tiny_db), "-o", str(model), "--overwrite"])
    motion = tmp_path / "m.h5"
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    r = runner.invoke(main, ["synthesize", "--method", "toymean", str(model), "--phonemes", str(tg), "-o", str(motion),
                             "--set", "toymean.scale=0.5"])
    assert r.exit_code == 0, r.output
    toy = ToyModel.read(model)
    with h5py.File(motion, "r") as f:  # its settings section reached it
        np.testing.assert_allclose(f["markers_capture"][0], held_pose(toy, 0.5), atol=1e-4)
        assert f.attrs["source"] == "synthesis" and f["path"].attrs["method"] == "toymean"
        assert "coefficients" not in f and "keyshape_weights" not in f  # it makes markers directly
    r = runner.invoke(main, ["check", str(motion)])  # a motion without PCA frames is a whole motion
    assert r.exit_code == 0 and "motion" in r.output, r.output
    curves = tmp_path / "c.h5"
    assert runner.invoke(main, ["solve", str(motion), "-o", str(curves)]).exit_code == 0
    with h5py.File(curves, "r") as f:  # what is made from it names the member too
        assert f["provenance"].attrs["origin"] == "synthesis" and f["provenance"].attrs["method"] == "toymean"
    out = tmp_path / "w.toy.txt"
    r = runner.invoke(main, ["export", str(held_out_synthesized["curves"]), "--format", "toy-txt", "-o", str(out)])
    assert r.exit_code == 0, r.output
    weights = np.loadtxt(out)
    assert weights.ndim == 2 and weights.shape[1] == 55
    capture = tmp_path / "take.toym"
    capture.write_text("60\nA B\n0 0 0 1 1 1\n0 0 1 1 1 2\n")
    take = read_capture(capture)
    assert take.names == ["A", "B"] and take.fps == 60 and take.positions.shape == (2, 2, 3)


def test_an_unknown_member_is_refused_naming_the_members():
    r = CliRunner().invoke(main, ["export", "motion.h5", "--format", "fbx", "-o", "x.fbx"])
    assert r.exit_code == 2 and "arkit-csv" in r.output


@pytest.mark.parametrize("page", ["methods.md", "exports.md", "inputs.md", "file-format.md"])
def test_the_docs_tables_are_the_registries(page):
    text = (DOCS / page).read_text(encoding="utf-8")
    assert "<!-- registry: " in text
    assert registry.document(text) == text, f"run `make docs` (python -m facesynth.base.registry docs/{page})"
