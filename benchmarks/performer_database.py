"""The performer as the database: the method family on FACEGOOD when the motion database is the
real speaker's own capture, with the scored takes left out of it.
Prints JSON (and writes a markdown table with ``--out``).

Data: FACEGOOD's seven takes (``--data`` laid out as for ``benchmarks/real_speech_lipsync.py``,
whose docstring defines the real curves, the scores and the baselines). Split, fixed before
looking: the performer's database is built from the train takes 1114_2_01, 1114_2_02, 1114_2_03
and 1114_3_16 only; it is scored on 1114_2_04, 1114_2_05 and 1114_3_15, the three takes used for
no choice in docs/real-speech.md.

The performer's database (in ``WORK/performer/``, each file built once and reused while it exists):
``facesynth sample-corpus corpus --preset facegood`` (the takes as facesynth ships them:
float16 curves, Opus audio), its ``manifest.csv`` copied to ``manifest_train.csv`` without the
scored takes' rows, then ``ingest`` (phones recognised from each take's audio; the slow step,
about two minutes), ``normalize``, ``pca``, ``build-db``, all with the default settings;
``fit-method coarticulation`` on it, and ``keyshapes`` then ``fit-method trajectory
--keyshapes``, defaults again.

Methods (rows), each at 30 frames/s over the whole scored take, no lag, solved onto the built-in
rig as in real_speech_lipsync (mouth opening = the inner-lip marker gap of the motion, channels =
the solve's curves):

- ``performer_dp``, ``performer_greedy``, ``performer_mean``, ``performer_coarticulation``,
  ``performer_trajectory``: ``synthesize --method M --phonemes PHONES`` from the performer's
  database (or its fitted model), the phones alone; PHONES are the phones real_speech_lipsync
  recognises (its ``phones_from_audio``, run again as it does, into
  ``WORK/takes/<take>/phones.TextGrid``).
- ``performer_dp_audio``: ``synthesize --audio TAKE.wav`` alone from the performer's database
  (the phones recognised inside, the voice's articulation fused in): the shipped audio-only path.
- ``actress_dp_audio``, ``actress_dp``: real_speech_lipsync's ``facesynth`` (audio alone) and
  ``facesynth_phones`` rows, the built-in actress's database (``WORK/db.h5``, built there if
  missing), same calls, same cache.
- ``openfacefx``, ``energy``: as in real_speech_lipsync.
- ``phone_mean``: the speaker's own mean of every real channel per recognised phone, fitted on the
  four train takes (their phones recognised the same way) and scored on the scored takes.

Scores: real_speech_lipsync's (Pearson r per ~10 s window, mean over windows with 95% bootstrap
intervals over windows and over takes from its ``summarize``; closures from ``closure_events`` and
``match_closures``), plus paired differences of ``performer_dp`` and ``performer_dp_audio`` minus
every other row on the same resamples. No RMS: the methods' mouth openings are in mm on the
built-in rig, the real one in FACEGOOD's weights, and no rescaling is fair to all rows at once.
``diagnostics``: the database's size, how far the train takes' phones recognised by ``ingest``
(shipped Opus audio) agree frame by frame with the ones recognised from the original wav (the
recognition's stability, since no true phones exist), and how much of the real opening's
variance the recognised phone explains.

    python benchmarks/performer_database.py --data FACEGOOD_DIR --work WORK [--out table.md] \\
        > benchmarks/performer_database.json

``WORK`` may be real_speech_lipsync's own ``--work`` folder: the actress's database and her motion
are reused. With that cache and the performer's files built, about three minutes on two cores
(recognising the phones of the seven takes again is most of it); building the performer's
database adds about three more (ingest the longest step), the actress's database and her motion
more where they are missing.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.phonemes import PAU
from facesynth.domain.evaluation.baselines import openfacefx_missing
from facesynth.domain.evaluation.bootstrap import paired_difference, resamples
from facesynth.domain.speech.loudness import envelope
from facesynth.formats.audio import read_audio

sys.path.insert(0, str(Path(__file__).resolve().parent))

import real_speech_lipsync as bench  # noqa: E402  (its methods and scoring functions)

FPS = bench.FPS
TRAIN = ("1114_2_01", "1114_2_02", "1114_2_03", "1114_3_16")
SCORED = ("1114_2_04", "1114_2_05", "1114_3_15")
PERFORMER_METHODS = ("dp", "greedy", "mean", "coarticulation", "trajectory")
METHODS = tuple(f"performer_{m}" for m in PERFORMER_METHODS) + (
    "performer_dp_audio", "actress_dp_audio", "actress_dp", "openfacefx", "energy", "phone_mean")
LEADS = ("performer_dp", "performer_dp_audio")
CHANNELS = ("opening", "jawOpen", "mouthFunnel", "mouthPucker", "mouthPress")


# ---------------------------------------------------------------- the performer's database

def build_performer(root: Path) -> dict[str, Path]:
    """The performer's database and fitted models in ``root``, each built once (see the docstring)."""
    corpus = root / "corpus"
    if not (corpus / "manifest.csv").exists():
        bench.facesynth_cli("sample-corpus", str(corpus), "--preset", "facegood")
    train = corpus / "manifest_train.csv"
    if not train.exists():
        with (corpus / "manifest.csv").open(newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        kept = [rows[0]] + [r for r in rows[1:] if r and r[0] in TRAIN]
        if sorted(r[0] for r in kept[1:]) != sorted(TRAIN):
            raise SystemExit(f"{corpus / 'manifest.csv'}: expected the takes {', '.join(TRAIN)}")
        with train.open("w", newline="", encoding="utf-8") as f:
            csv.writer(f, lineterminator="\n").writerows(kept)
    steps = [("ingest", train, "corpus.h5"), ("normalize", root / "corpus.h5", "normalized.h5"),
             ("pca", root / "normalized.h5", "pca.h5"), ("build-db", root / "pca.h5", "db.h5")]
    for command, src, dst in steps:
        if not (root / dst).exists():
            bench.facesynth_cli(command, str(src), "-o", str(root / dst))
    db = root / "db.h5"
    out = {"dp": db, "greedy": db, "mean": db, "coarticulation": root / "coarticulation.h5",
           "trajectory": root / "trajectory.h5", "keyshapes": root / "keyshapes.h5"}
    if not out["coarticulation"].exists():
        bench.facesynth_cli("fit-method", "coarticulation", str(db), "-o", str(out["coarticulation"]))
    if not out["keyshapes"].exists():
        bench.facesynth_cli("keyshapes", str(db), "-o", str(out["keyshapes"]))
    if not out["trajectory"].exists():
        bench.facesynth_cli("fit-method", "trajectory", str(db), "--keyshapes", str(out["keyshapes"]),
                            "-o", str(out["trajectory"]))
    return out


def database_size(db) -> dict:
    """How much of the performer the database (a ``MotionDatabase``) holds."""
    speech = [p for p in db.phones.phone if p != PAU]
    return {"takes": list(db.takes.name), "seconds": round(float(db.takes.frame_count.sum()) / db.fps, 1),
            "phones": len(speech), "distinct_phones": len(set(speech)), "nodes": len(db.nodes),
            "nodes_pruned": 0 if db.pruned is None else len(db.pruned.removed_id)}


def database_phones(db, take: str) -> list:
    """The phones ``ingest`` recognised for ``take`` (as segments), read from the database."""
    from facesynth.formats.labels import Segment

    rows = np.flatnonzero(db.phones.take == db.takes.index(take))
    return [Segment(float(db.phones.start[k]), float(db.phones.end[k]), db.phones.phone[k]) for k in rows]


# ---------------------------------------------------------------- takes and scores

def load_take(data: Path, work: Path, take: str, names: list[str], table: dict, settings,
              window_s: float) -> dict:
    """A take's real curves (n frames), audio and recognised phones (real_speech_lipsync's)."""
    wav, curves_file = data / "wav" / f"{take}.wav", data / "bs_value_npy" / f"bs_value_{take}.npy"
    if not wav.exists() or not curves_file.exists():
        raise SystemExit(f"{data}: take {take!r} needs wav/{take}.wav and bs_value_npy/bs_value_{take}.npy")
    values = bench.load_npy(curves_file)
    samples, rate = read_audio(wav)
    n = min(len(values), int(np.floor(len(samples) / rate * FPS)))
    real = {k: v[:n] for k, v in bench.real_curves(np.asarray(values, np.float64), names, table).items()}
    folder = work / "takes" / take
    folder.mkdir(parents=True, exist_ok=True)
    phones = folder / "phones.TextGrid"
    segs, source = bench.phones_from_audio(wav, phones, settings)
    return {"take": take, "wav": wav, "samples": samples, "rate": rate, "n": n, "real": real, "segs": segs,
            "phones": phones, "folder": folder, "source": source, "spans": bench.windows(n, FPS, window_s)}


def closure_rows(real_opening: np.ndarray, opening: np.ndarray, spans, depth: float, prominence: float,
                 tolerance: int) -> np.ndarray:
    """(W, 4) per window: real closures, matched real, method closures, matched method (as in
    real_speech_lipsync's main)."""
    real = bench.closure_events(real_opening, depth, prominence)
    events = bench.closure_events(opening, depth, prominence)
    rows = []
    for a, b in spans:
        rc, mc = real[(real >= a) & (real < b)], events[(events >= a) & (events < b)]
        rows.append((len(rc), bench.match_closures(rc, events, tolerance)[0], len(mc),
                     bench.match_closures(real, mc, tolerance)[1]))
    return np.array(rows, int).reshape(-1, 4)


def paired(r: dict, groups: np.ndarray, resample_count: int, seed: int) -> dict:
    """Paired differences, each lead of :data:`LEADS` minus every other method, per channel, on
    the resamples of real_speech_lipsync's ``summarize`` (over windows, and over takes)."""
    n, k = len(groups), int(groups.max()) + 1
    out = {}
    for suffix, wrap, count, idx in (("", lambda f: f, n, resamples(n, resample_count, seed)),
                                     ("_takes", lambda f: bench.by_take(f, groups), k,
                                      resamples(k, resample_count, seed))):
        out["paired" + suffix] = {
            channel: {f"{lead} - {m}": paired_difference(wrap(bench.mean_r_statistic(per[lead])),
                                                         wrap(bench.mean_r_statistic(v)), count, idx)
                      for lead in LEADS if lead in per for m, v in per.items() if m != lead}
            for channel, per in r.items()}
    return out


def frame_labels(takes: list[dict]) -> np.ndarray:
    return np.concatenate([bench.frame_phones(t["segs"], t["n"]) for t in takes])


def explained(takes: list[dict], means: dict) -> float:
    """R² of the real opening by its phone's mean opening (frame by frame, no interpolation)."""
    y = np.concatenate([t["real"]["opening"] for t in takes])
    m = means["opening"]
    pred = np.array([m.get(p, m[""]) for p in frame_labels(takes)])
    return float(1 - ((y - pred) ** 2).sum() / ((y - y.mean()) ** 2).sum())


def diagnostics(train: list[dict], scored: list[dict], means: dict, db_path: Path) -> dict:
    """Database size, the stability of the phone recognition, and what the phones say of the opening."""
    from facesynth.model.motiondb import MotionDatabase

    db = MotionDatabase.read(db_path)
    agree = []
    for t in train:
        ingest = database_phones(db, t["take"])
        a = np.array(bench.frame_phones(ingest, t["n"]))
        b = np.array(bench.frame_phones(t["segs"], t["n"]))
        speech = (a != PAU) | (b != PAU)
        agree.append((int((a == b)[speech].sum()), int(speech.sum())))
    durations = np.array([s.end - s.start for t in scored for s in t["segs"] if s.label != PAU])
    train_labels, scored_labels = frame_labels(train), frame_labels(scored)
    seen = set(train_labels)
    return {
        "database": database_size(db),
        "phones_agree_ingest_vs_wav": round(sum(a for a, _ in agree) / sum(b for _, b in agree), 3),
        "phones_agree_note": "train takes, speech frames: ingest's phones (shipped Opus audio) against "
                             "phones_from_audio on the original wav",
        "scored_phone_ms_median": round(float(np.median(durations)) * 1000, 1),
        "scored_phones_under_60ms": round(float((durations < 0.06).mean()), 3),
        "scored_phones_per_s": round(len(durations) / (sum(t["n"] for t in scored) / FPS), 2),
        "scored_frames_phone_unseen_in_train": round(float(np.mean([p not in seen for p in scored_labels])), 4),
        "opening_r2_by_phone_train": round(explained(train, means), 3),
        "opening_r2_by_phone_scored": round(explained(scored, means), 3),
    }


# ---------------------------------------------------------------- the run

def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", type=Path, required=True, help="the FACEGOOD folder (see real_speech_lipsync.py)")
    ap.add_argument("--work", type=Path, required=True,
                    help="cache: phones, databases, motion and curves (empty it after changing facesynth)")
    bench.add_scoring_options(ap)
    args = ap.parse_args(argv)

    missing = openfacefx_missing()
    if missing:
        raise SystemExit(missing)
    names = bench.channel_names(args.data)
    config = Config.load()
    align_settings, lip_markers = config.settings("align"), config.settings("evaluate").lip_markers
    table = bench.read_table()
    started = time.perf_counter()
    args.work.mkdir(parents=True, exist_ok=True)
    root = args.work / "performer"
    root.mkdir(exist_ok=True)
    models = build_performer(root)
    actress = bench.build_database(args.work)

    from facesynth.domain.rig.face import load_face_rig
    from facesynth.formats.mesh import read_binding

    rig = load_face_rig()
    binding = read_binding(args.work / "corpus" / "markers.csv")  # the actress's markers, the performer's too
    lip_vertices = np.array([binding[m] for m in lip_markers])

    train = [load_take(args.data, args.work, t, names, table, align_settings, args.window_s) for t in TRAIN]
    scored = [load_take(args.data, args.work, t, names, table, align_settings, args.window_s)
              for t in SCORED]
    means = bench.phone_means(train)
    for t in scored:
        n, phones, wav = t["n"], t["phones"], t["wav"]
        mine = root / "takes" / t["take"]
        mine.mkdir(parents=True, exist_ok=True)
        methods = {f"performer_{m}": bench.facesynth_method(models[m], phones, mine, n, lip_markers, m)
                   for m in PERFORMER_METHODS}
        methods["performer_dp_audio"] = bench.facesynth_method(models["dp"], None, mine, n, lip_markers, audio=wav)
        methods["actress_dp_audio"] = bench.facesynth_method(actress, None, t["folder"], n, lip_markers, audio=wav)
        methods["actress_dp"] = bench.facesynth_method(actress, phones, t["folder"], n, lip_markers)
        methods["openfacefx"] = bench.openfacefx_method(t["segs"], n, rig, lip_vertices)
        env = envelope(t["samples"], t["rate"], n, FPS, args.energy_smooth_s)
        methods["energy"] = {"opening": env, "jawOpen": env}
        methods["phone_mean"] = bench.phone_mean_method(means, t["segs"], n)
        t["methods"] = methods

    r = {c: {} for c in CHANNELS}
    closures, per_take = {}, {}
    for t in scored:
        per_take[t["take"]] = {"seconds": round(t["n"] / FPS, 2), "windows": len(t["spans"]),
                               "phones": sum(s.label != PAU for s in t["segs"]), "opening_r": {}}
        for method, curves in t["methods"].items():
            for channel in CHANNELS:
                if channel in curves:
                    values = bench.window_r(curves[channel], t["real"][channel], t["spans"])
                    r[channel].setdefault(method, []).append(values)
            values = r["opening"][method][-1]
            per_take[t["take"]]["opening_r"][method] = (float(np.nanmean(values)) if np.isfinite(values).any()
                                                        else None)
            closures.setdefault(method, []).append(closure_rows(
                t["real"]["opening"], curves["opening"], t["spans"], args.closure_depth, args.closure_prominence,
                args.closure_tolerance_frames))
    r = {c: {m: np.concatenate(v) for m, v in per.items()} for c, per in r.items()}
    closures = {m: np.concatenate(v) for m, v in closures.items()}
    groups = np.concatenate([np.full(len(t["spans"]), i) for i, t in enumerate(scored)])
    summary = bench.summarize(r, closures, groups, args.resamples, args.seed)
    summary.pop("paired"), summary.pop("paired_takes")  # its leads are the actress's; ours are below
    summary.update(paired(r, groups, args.resamples, args.seed))
    seconds = sum(t["n"] for t in scored) / FPS
    result = {
        "data": {"source": "FACEGOOD Audio2Face training takes (MIT)", "train_takes": list(TRAIN),
                 "scored_takes": list(SCORED), "scored_seconds": round(seconds, 1),
                 "real_opening": " + ".join(bench.REAL_OPENING)},
        "phones_from": sorted({t["source"] for t in train + scored}),
        "settings": {"fps": FPS, "window_s": args.window_s, "lag_frames": 0, "energy_smooth_s": args.energy_smooth_s,
                     "closure_depth": args.closure_depth, "closure_prominence": args.closure_prominence,
                     "closure_tolerance_frames": args.closure_tolerance_frames, "resamples": args.resamples,
                     "seed": args.seed, "performer_database": "default settings, train takes only",
                     "phone_mean_fit": "the four train takes", "rms": "not reported (mm against weights)"},
        **summary,
        "diagnostics": diagnostics(train, scored, means, models["dp"]),
        "per_take": per_take,
        "seconds": round(time.perf_counter() - started, 1),
    }
    if args.out:
        args.out.write_text(markdown(result), encoding="utf-8")
    return result


def markdown(result: dict) -> str:
    """The result as markdown tables: r per channel and method, paired differences, closures."""
    fmt = bench._fmt
    methods = [m for m in METHODS if any(m in per for per in result["r"].values())]
    lines = ["| channel | " + " | ".join(methods) + " |", "|---|" + "---|" * len(methods)]
    for channel, per in result["r"].items():
        lines.append(f"| {channel} | " + " | ".join(fmt(per.get(m)) for m in methods) + " |")
    lines += ["", "| paired difference | over windows [95%] | over takes [95%] |", "|---|---|---|"]
    for channel, per in result["paired"].items():
        for name, s in per.items():
            lines.append(f"| {channel}: {name} | {fmt(s)} | {fmt(result['paired_takes'][channel][name])} |")
    lines += ["", "| method | closure recall | precision | closures |", "|---|---|---|---|"]
    for m, c in result["closures"].items():
        lines.append(f"| {m} | {fmt(c['recall'])} | {fmt(c['precision'])} | {c['closures']} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
