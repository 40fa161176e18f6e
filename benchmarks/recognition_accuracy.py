"""Phones from audio alone (``align.recognition``: ``words`` or ``phones``, see
:mod:`facesynth.domain.speech.recognition`) against the text-given alignment, on the recordings of
``benchmarks/alignment_accuracy.py`` (the sample corpus; praatio's and the Montreal Forced
Aligner's real speech). Prints JSON (and writes it with ``--out``).

Per source and mode:

- ``per``: phone error rate, the Levenshtein distance between the mode's phones and the
  reference phones (pauses left out, both in the Festival set) over the number of reference
  phones, pooled over the recordings; with its substitutions, deletions and insertions. The
  reference is the recording's phone tier where it has one (the sample corpus's exact timing,
  praatio's hand-made ``bobby``, the MFA corpora's aligner-made tiers), else the first CMU
  pronunciation of each word of its reference transcript.
- ``ver``: the same over visemes (Table VI classes): the error the mouth shows.
- boundary error (ms): absolute start and end differences of the phones that the PER's edit
  alignment pairs as equal (recordings with a phone tier only): count, mean, median, 95th
  percentile. (``alignment_accuracy.py`` pairs phones by :class:`difflib.SequenceMatcher`
  instead, which can pair a recognised phone with an equal one far away.)
- ``confusions``: the most frequent substitutions (reference > recognised), and the
  deletions, insertions and substitutions by phone class; ``failures``: recordings refused,
  with the reason; ``seconds``: the time the mode took.

The ``text`` mode is the forced alignment of the reference transcript (its PER is the
distance between the dictionary's pronunciations and the reference tier: the floor of the
other two).

    python benchmarks/recognition_accuracy.py [--sources sample,praatio,mfa] [--modes text,words,phones] [--out FILE]
"""

from __future__ import annotations

import dataclasses
import json
import sys
import time
from collections import Counter
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from alignment_accuracy import festival, load_sources, speech_arguments

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU, VOWELS, pronunciations, to_festival, viseme
from facesynth.domain.speech.alignment import AlignmentFailed, normalize_text
from facesynth.domain.speech.recognition import align_or_recognize
from facesynth.formats.audio import read_audio

#: Phone classes for the confusion summary (Festival phones).
CLASSES = {"vowel": VOWELS, "stop": {"p", "b", "t", "d", "k", "g"},
           "fricative": {"f", "v", "th", "dh", "s", "z", "sh", "zh", "hh"}, "affricate": {"ch", "jh"},
           "nasal": {"m", "n", "ng"}, "approximant": {"l", "r", "w", "y"}}


def phone_class(phone: str) -> str:
    return next((name for name, members in CLASSES.items() if phone in members), "other")


def edit_operations(ref: list, hyp: list) -> list[tuple[str, int | None, int | None]]:
    """A minimal Levenshtein alignment of ``hyp`` to ``ref``: ("=" | "sub" | "del" | "ins", index
    in ref, index in hyp) in order (ties: substitution, then deletion, then insertion)."""
    n, m = len(ref), len(hyp)
    cost = np.zeros((n + 1, m + 1), int)
    cost[:, 0], cost[0, :] = np.arange(n + 1), np.arange(m + 1)
    for i in range(1, n + 1):
        for j in range(1, m + 1):
            cost[i, j] = min(cost[i - 1, j - 1] + (ref[i - 1] != hyp[j - 1]), cost[i - 1, j] + 1, cost[i, j - 1] + 1)
    ops = []
    i, j = n, m
    while i or j:
        if i and j and cost[i, j] == cost[i - 1, j - 1] + (ref[i - 1] != hyp[j - 1]):
            ops.append(("=" if ref[i - 1] == hyp[j - 1] else "sub", i - 1, j - 1))
            i, j = i - 1, j - 1
        elif i and cost[i, j] == cost[i - 1, j] + 1:
            ops.append(("del", i - 1, None))
            i -= 1
        else:
            ops.append(("ins", None, j - 1))
            j -= 1
    return ops[::-1]


def reference_phones(item: dict) -> list[str] | None:
    """The recording's reference phones (no pauses): its phone tier, else the first CMU (or the
    item's extra) pronunciation of each word of its text; None when a word has none."""
    if "phones" in item:
        return [s.label for s in reference_segments(item)]
    words = normalize_text(item["text"])
    table = pronunciations(words)
    extra = item.get("extra") or {}
    out = []
    for w in words:
        prons = list(extra.get(w, [])) + list(table.get(w, ()))
        if not prons:
            return None
        out += [p for p in (to_festival(x) for x in prons[0]) if p and p != PAU]
    return out


def reference_segments(item: dict) -> list:
    """The non-pause segments of the recording's phone tier, in the Festival set."""
    return [s for s in festival(item["phones"]) if s.label != PAU]


def boundary_errors(ref: list, hyp: list, ops: list) -> list[float]:
    """Absolute start and end differences (ms) of the phones the edit alignment ``ops`` pairs
    as equal (``ref`` and ``hyp``: non-pause segments)."""
    out = []
    for op, i, j in ops:
        if op == "=":
            out += [abs(ref[i].start - hyp[j].start) * 1e3, abs(ref[i].end - hyp[j].end) * 1e3]
    return out


def run_mode(items: list[dict], mode: str, base_settings) -> dict:
    settings = base_settings if mode == "text" else dataclasses.replace(base_settings, recognition=mode)
    counts = Counter()
    vis = Counter()
    errors: list[float] = []
    subs, by_class = Counter(), Counter()
    failures, methods, per_recording = [], Counter(), {}
    started = time.perf_counter()
    for item in items:
        ref = reference_phones(item)
        samples, rate = read_audio(item["audio"])
        try:
            result = align_or_recognize(samples, rate, item["text"] if mode == "text" else None, settings=settings,
                                        extra=item.get("extra"), where=item["name"])
        except (AlignmentFailed, InputError) as exc:
            failures.append({"item": item["name"], "reason": str(exc)})
            if ref:  # nothing recognised: every reference phone is deleted
                counts.update(ref=len(ref), dele=len(ref))
                vis.update(ref=len(ref), dele=len(ref))
            continue
        methods[result.method] += 1
        hyp_segments = [s for s in result.phones if s.label != PAU]
        hyp = [s.label for s in hyp_segments]
        record = {"method": result.method}
        if mode != "text":
            record["recognized"] = result.recognized
        if ref:
            ops = edit_operations(ref, hyp)
            k = Counter(op for op, _, _ in ops)
            counts.update(ref=len(ref), sub=k["sub"], dele=k["del"], ins=k["ins"])
            for op, i, j in ops:
                r, h = ref[i] if i is not None else None, hyp[j] if j is not None else None
                if op == "sub":
                    subs[f"{r}>{h}"] += 1
                    by_class[f"sub {phone_class(r)}>{phone_class(h)}"] += 1
                elif op == "del":
                    by_class[f"del {phone_class(r)}"] += 1
                elif op == "ins":
                    by_class[f"ins {phone_class(h)}"] += 1
            record["per"] = round((k["sub"] + k["del"] + k["ins"]) / len(ref), 3)
            vops = Counter(op for op, _, _ in edit_operations([viseme(p) for p in ref], [viseme(p) for p in hyp]))
            vis.update(ref=len(ref), sub=vops["sub"], dele=vops["del"], ins=vops["ins"])
        if "phones" in item:
            e = boundary_errors(reference_segments(item), hyp_segments, ops)
            errors += e
            if e:
                record["median_ms"] = round(float(np.median(e)), 1)
        per_recording[item["name"]] = record
    e = np.array(errors)

    def rate(c: Counter):
        return round((c["sub"] + c["dele"] + c["ins"]) / c["ref"], 3) if c["ref"] else None

    return {"recordings": len(items), "failures": failures, "methods": dict(methods),
            "per": rate(counts), "ver": rate(vis), "reference_phones": counts["ref"],
            "substitutions": counts["sub"], "deletions": counts["dele"], "insertions": counts["ins"],
            "boundaries": len(e), "mean_ms": round(float(e.mean()), 1) if len(e) else None,
            "median_ms": round(float(np.median(e)), 1) if len(e) else None,
            "p95_ms": round(float(np.percentile(e, 95)), 1) if len(e) else None,
            "confusions": {"top_substitutions": dict(subs.most_common(12)), "by_class": dict(by_class.most_common())},
            "per_recording": per_recording, "seconds": round(time.perf_counter() - started, 2)}


def main() -> None:
    parser = speech_arguments(__doc__.splitlines()[0])
    parser.add_argument("--modes", default="text,words,phones")
    parser.add_argument("--only", default="", help="comma-separated recording names to keep (default: all)")
    args = parser.parse_args()
    settings = Config.load().settings("align")
    keep = set(filter(None, args.only.split(",")))
    result = {}
    for source, items in load_sources(args).items():
        if isinstance(items, str):
            result[source] = {"skipped": items}
            continue
        if keep:
            items = [i for i in items if i["name"] in keep]
        result[source] = {mode: run_mode(items, mode, settings) for mode in args.modes.split(",")}
    text = json.dumps(result, indent=2)
    print(text)
    if args.out:
        args.out.write_text(text + "\n")


if __name__ == "__main__":
    main()
