"""How the voice's predicted opening becomes lip gaps (``synthesize.voice_opening_map``): by rank
onto the method's own gaps, or affinely by percentiles. Prints JSON.

With audio alone (``synthesize --audio``: phones recognised, the voice's articulation fused in),
the articulation model's opening varies less within speech than between speech and silence, so
mapped by its 5th..95th percentiles it holds the mouth half open through speech: the "frozen
grimace", lips apart, of a database driven by a voice. By rank the mouth is as often closed,
half and wide open as the method's, in the voice's order. This measures both on FACEGOOD's three
takes used for no choice (1114_2_04, 1114_2_05, 1114_3_15; ``--data`` laid out as for
``benchmarks/real_speech_lipsync.py``), the first ``--seconds`` of each, synthesized from the
database ``--db`` (real_speech_lipsync's ``WORK/db.h5``: the actress's ``small`` corpus):

- ``r``: Pearson r of the motion's inner-lip gap (``ULI_C``-``LLI_C``) with the real opening
  (``mouth_stretch_c + mouth_oh_c``) per 10 s window, mean over windows with a 95% bootstrap
  interval over windows, and the paired difference rank - percentiles;
- ``closed_in_speech``: the share of speech frames (the real speaker's opening above 0.05 within
  0.5 s) where the mouth is nearly closed (below 0.15 of its 5th..95th percentile range), the
  synthesized mouth's and the real one's;
- ``spread_in_speech``: the standard deviation of the opening over speech frames, in the same
  range units.

    python benchmarks/voice_opening_map.py --data FACEGOOD_DIR --db WORK/db.h5 --work out/opening_map

About 3 minutes on two cores (six syntheses of a minute of speech each).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
from pathlib import Path

import numpy as np
import soundfile as sf

from facesynth.base.config import Config
from facesynth.domain.evaluation.bootstrap import interval, resamples
from facesynth.domain.speech.loudness import lip_gaps
from facesynth.model.motion import Motion
from facesynth.stages import synthesize

TAKES = ("1114_2_04", "1114_2_05", "1114_3_15")
WINDOW = 300  # frames: 10 s at 30 frames/s
MODES = ("percentiles", "rank")


def _real_opening(data: Path, take: str) -> np.ndarray:
    names = [str(n) for n in np.load(data / "shirley_1015_bs_name.npy", allow_pickle=False)]
    curves = np.load(data / "bs_value_npy" / f"bs_value_{take}.npy", allow_pickle=False)
    return curves[:, names.index("mouth_stretch_c")] + curves[:, names.index("mouth_oh_c")]


def _unit(x: np.ndarray) -> np.ndarray:
    """x in units of its 5th..95th percentile range, 0 at the 5th."""
    lo, hi = np.percentile(x, [5, 95])
    return (x - lo) / max(hi - lo, 1e-9)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", type=Path, required=True, help="FACEGOOD's folder (wav/, bs_value_npy/, names)")
    parser.add_argument("--db", type=Path, required=True, help="the motion database to synthesize from")
    parser.add_argument("--work", type=Path, required=True, help="folder for the clips and motions (reused)")
    parser.add_argument("--seconds", type=float, default=60.0, help="the first seconds of each take")
    args = parser.parse_args(argv)
    args.work.mkdir(parents=True, exist_ok=True)
    from scipy.ndimage import maximum_filter1d

    config = Config.load()
    r: dict[str, list[float]] = {m: [] for m in MODES}
    closed: dict[str, list[np.ndarray]] = {m: [] for m in (*MODES, "real")}
    spread: dict[str, list[np.ndarray]] = {m: [] for m in (*MODES, "real")}
    for take in TAKES:
        samples, rate = sf.read(args.data / "wav" / f"{take}.wav", dtype="float32")
        clip = args.work / f"{take}.wav"
        sf.write(clip, samples[: int(args.seconds * rate)], rate)
        real = _real_opening(args.data, take)
        for mode in MODES:
            out = args.work / f"{take}_{mode}.h5"
            if not out.exists():
                settings = dataclasses.replace(config.settings("synthesize"), voice_opening_map=mode)
                synthesize.run(args.db, out, settings, config.settings("ingest"), config.settings("align"), audio=clip)
            motion = Motion.read(out)
            gap = lip_gaps(motion.markers.astype(np.float64), list(motion.marker_names), ("ULI_C", "LLI_C"))
            n = min(len(gap), len(real))
            g, o = np.asarray(gap[:n], np.float64), real[:n]
            r[mode] += [float(np.corrcoef(g[a:a + WINDOW], o[a:a + WINDOW])[0, 1]) for a in range(0, n - WINDOW + 1, WINDOW)]
            talk = maximum_filter1d((o > 0.05).astype(np.int64), 31) > 0
            closed[mode].append(_unit(g)[talk] < 0.15)
            spread[mode].append(_unit(g)[talk])
            if mode == MODES[0]:
                closed["real"].append(_unit(o)[talk] < 0.15)
                spread["real"].append(_unit(o)[talk])

    def cell(values) -> dict:  # the mean over windows, 95% bootstrap interval over windows
        v = np.asarray(values, np.float64)
        summary = interval(lambda idx: float(v[idx].mean()), len(v), resamples(len(v), 2000, 0))
        return {k: round(float(summary[k]), 3) for k in ("value", "low", "high")}

    report = {
        "takes": list(TAKES), "seconds_each": args.seconds, "db": args.db.name, "windows": len(r["rank"]),
        "r": {m: cell(r[m]) for m in MODES},
        "r_paired_rank_minus_percentiles": cell(np.subtract(r["rank"], r["percentiles"])),
        "closed_in_speech": {m: round(float(np.concatenate(closed[m]).mean()), 3) for m in closed},
        "spread_in_speech": {m: round(float(np.concatenate(spread[m]).std()), 3) for m in spread},
    }
    print(json.dumps(report, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
