"""The headline figures of the README (and of docs/results.md) are those of the runs they cite:
the real-speech benchmark's JSON and the report's seed-0 evaluation. A rerun that changes a
figure fails here until the pages quote the new one."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
RESULTS = (ROOT / "docs" / "results.md").read_text(encoding="utf-8")


def quoted(cell: dict, decimals: int) -> str:
    """'value [low, high]' as the pages write it (a minus sign, not a hyphen)."""
    text = f"{cell['value']:.{decimals}f} [{cell['low']:.{decimals}f}, {cell['high']:.{decimals}f}]"
    return text.replace("-", "\u2212")


def signed(cell: dict, decimals: int) -> str:
    """'+value [+low, +high]' as the pages write a paired difference."""
    text = f"{cell['value']:+.{decimals}f} [{cell['low']:+.{decimals}f}, {cell['high']:+.{decimals}f}]"
    return text.replace("-", "−")


def _real_speech_figures(name: str) -> tuple[dict, list[str]]:
    run = json.loads((ROOT / "benchmarks" / name).read_text(encoding="utf-8"))
    return run, [quoted(run["r"]["opening"]["facesynth"], 2), quoted(run["r"]["opening"]["openfacefx"], 2),
                 signed(run["paired"]["opening"]["facesynth - openfacefx"], 2)]


def test_real_speech_figures_are_the_benchmarks():
    # the README leads with the fair test (the takes used for no choice), results.md has both runs
    fair, fair_figures = _real_speech_figures("real_speech_lipsync_scored_takes.json")
    _, all_figures = _real_speech_figures("real_speech_lipsync.json")
    for page, text, figures in (("README.md", README, fair_figures), ("docs/results.md", RESULTS, fair_figures),
                                ("docs/results.md", RESULTS, all_figures)):
        missing = [f for f in figures if f not in text]
        assert not missing, f"{page} does not quote {missing} of the real-speech benchmark's JSON"
    assert f"over {fair['windows']} windows" in README


@pytest.mark.parametrize("method", ["dp", "greedy", "baseline_emotion", "dominance_emotion", "openfacefx", "capture"])
def test_virtual_actress_table_is_the_reports_seed_0(method):
    report = json.loads((ROOT / "docs" / "results.json").read_text(encoding="utf-8"))
    [seed0] = [entry for entry in report["methods"] if entry["seed"] == 0]
    figures = seed0["figures"][method]
    cells = [quoted(figures["rms_clean_mm"], 2), quoted(figures["velocity_rms_clean_mm_s"], 1),
             quoted(figures["closure_delay_ms"], 1)]
    if method != "capture":
        cells.append(quoted(figures["emotion_accuracy"], 2))
    for page, text in (("README.md", README), ("docs/results.md", RESULTS)):
        rows = [line for line in text.splitlines() if line.startswith("|") and cells[0] in line]
        assert any(all(c in row for c in cells) for row in rows), f"{page}: no row with {cells} ({method}, seed 0)"
