"""``facesynth evaluate``: synthesized motion against captured ground truth (paper VI-D, VIII),
written as ``metrics.json``, plots, an HTML report and a Markdown table ``table.md`` (the
metrics, baselines and intervals: :mod:`facesynth.domain.evaluation.held_out`; the report:
:mod:`facesynth.domain.evaluation.report`)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import EvaluateSettings, NormalizeSettings, SynthesizeSettings
from facesynth.base.errors import OutputExistsError
from facesynth.domain.evaluation.held_out import evaluate
from facesynth.domain.evaluation.report import plot, write_report
from facesynth.domain.evaluation.sources import given_models
from facesynth.domain.methods import MethodSettings
from facesynth.model.artifacts import atomic_folder, check_output_folder


def check_report_folder(out_dir: Path, overwrite: bool) -> None:
    """Refuse a report folder that is a file, or that already holds files unless ``overwrite``
    (an empty folder is fine). The report is written into a temporary folder beside it and renamed
    into place; with ``overwrite`` the old folder is replaced as a whole."""
    check_output_folder(out_dir, "the report")
    if out_dir.is_dir() and any(out_dir.iterdir()) and not overwrite:
        what = "already holds a report" if (out_dir / "metrics.json").exists() else "is not empty"
        raise OutputExistsError(f"{out_dir}: {what}; pass --overwrite to write the report into it or choose another folder.")


@dataclass(frozen=True)
class EvaluateResult:
    """What ``facesynth evaluate`` measured.

    methods: per row (a member of the method family, its per-phone variants, openfacefx, the
        references), its overall metrics as metrics.json holds them (``rms_mm`` and
        ``velocity_rms_mm_s`` in mm and mm/s, ...), with ``figures`` (each a value and its
        bootstrap interval) where computed.
    recommendation: the report's last sentence, recommending a method for this database from
        the paired bootstrap intervals ('' when there is nothing to compare).
    """

    methods: dict[str, dict]
    recommendation: str = ""


def run(db_path: Path, corpus: Path, out_dir: Path, settings: EvaluateSettings,
        synth: SynthesizeSettings | MethodSettings, normalize_settings: NormalizeSettings, overwrite: bool = False,
        truth: Path | None = None, models: Sequence[Path] = ()) -> EvaluateResult:
    """Evaluate the database on the corpus's held-out takes and write the report to ``out_dir``.
    ``synth``: the members' settings (:class:`MethodSettings`, or ``[synthesize]`` alone);
    ``truth``: the corpus folder with clean ground truth (``groundtruth/``, ``markers.csv``);
    ``models``: models fitted on ``db_path`` (``facesynth fit-method``), each scored by its member.
    """
    check_report_folder(out_dir, overwrite)
    given = given_models(models, db_path)
    metrics, records = evaluate(db_path, corpus, settings, synth, normalize_settings, truth=truth, models=given)
    with atomic_folder(out_dir, "the report", overwrite) as tmp:
        images = plot(records, tmp, settings.plot_marker)
        meta = {"db": str(db_path), "heldout": str(corpus), "split": settings.split, "sentences": len(records),
                "models": [str(m) for m in models],
                "plot_marker": settings.plot_marker, "closure_mm": settings.closure_mm, "truth": None if truth is None else str(truth),
                "bootstrap_resamples": settings.bootstrap_resamples}
        write_report(tmp, metrics, images, meta)
    return EvaluateResult({m: {**v["overall"], **({"figures": v["figures"]} if "figures" in v else {})}
                           for m, v in metrics.items() if not m.startswith("_")},
                          metrics.get("_figures", {}).get("recommendation", {}).get("sentence", ""))
