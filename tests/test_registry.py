"""The extension points are registries (docs/architecture.md, "Extending facesynth"): a toy member
of each family, its own code plus one registration line, is offered by the command line (its
choices and ``--help``), read and checked like the built-in members (``facesynth check``,
``--set`` validation, the pipeline's producers) and listed in the docs' tables; and the docs'
tables are the registries as they stand."""

from dataclasses import dataclass
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base import registry
from facesynth.base.config import Config
from facesynth.base.pipeline import producers
from facesynth.base.registry import ARTIFACT_KINDS, CAPTURE_READERS, EXPORT_FORMATS, METHODS
from facesynth.cli import main
from facesynth.domain.capture.readers import read_capture
from facesynth.domain.exports.animation import Exportable
from facesynth.domain.exports.format import ExportFormat, ExportOptions
from facesynth.domain.methods import FitSummary, Method, MethodSettings, Synthesis, SynthesisSummary
from facesynth.domain.methods.steps import frame_motion
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
        markers = np.repeat(source.mean[None], frames, axis=0)
        motion = frame_motion(self.name, utt, markers, None, source.fps, settings.synthesize.output_fps,
                              source.marker_names, source.reference, list(utt.phones), list(utt.emotions), "cpu")
        return Synthesis(motion, SynthesisSummary(phones=len(utt), frames=len(motion.markers)))


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
                     source_kind="toymean")
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


def test_toy_members_are_in_the_docs_tables(toys):
    assert "| `toymean` | `toymean` |  | a toy: the database's mean pose, held still |" in registry.markdown("methods")
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
    r = runner.invoke(main, ["synthesize", "--method", "toymean", str(model), "--phonemes", str(tg), "-o", str(motion)])
    assert r.exit_code == 0, r.output
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
