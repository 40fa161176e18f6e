"""What a line of text in another language costs against an English one.

    .venv/bin/python benchmarks/language_cost.py [--repeats 5]

Aligns one recording (four seconds of FACEGOOD's Mandarin take, shipped with the package) to a
line of twenty-odd phones in English, German, French, Spanish and Mandarin, and prints JSON:

* ``import_s``: the first non-English line's one-time cost per backend (importing gruut or
  pypinyin and loading the language's lexicon), measured on its first line in this process;
* ``lines``: per language, the line's phones and the median wall time (s) of ``repeats``
  alignments after that first one, and its ratio to English's. Every line is aligned by the
  ``duration`` method alone (``align.methods``), so that each does the same work (the words
  looked up, the decoder made with them, the phones timed): the texts are not what the
  recording says, and the acoustic methods would fail or succeed on each by chance;
* ``lookup_s``: per language, the median time of the words-to-phones step alone: the CMU
  dictionary's lookup for English, the G2P and the mapping to English phones for the others;
* ``step_costs_s``: per language, the median time of the search's observation costs
  (:func:`facesynth.domain.search.costs.step_costs`, ``synthesize.phone_match`` as configured)
  of the aligned line against ``--nodes`` motion nodes of English phones (seeded): Table II for
  English, the IPA phones' feature distances for the others; the fastest of ``--cost-repeats``
  (a few tens of milliseconds each, so the fastest is the least disturbed by other work on the
  machine), per phone, and its ratio to English's; ``features_against_table_ii``: per language,
  the same line's step costs with its IPA phones (features) against its English phones alone
  (Table II), both timed in turn: what matching by features adds.

The languages need the ``languages`` extra (``pip install 'facesynth[languages]'``); one that is
not installed is reported as skipped.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import json
import statistics
import sys
import time
from importlib import resources

import numpy as np
import soundfile

from facesynth.base.config import Config
from facesynth.base.ipa import FESTIVAL_IPA
from facesynth.base.phonemes import _cmudict_lines, _parse
from facesynth.domain.search.costs import step_costs
from facesynth.domain.speech.alignment import align_robust, normalize_text
from facesynth.domain.speech.languages import words_of
from facesynth.domain.speech.utterance import utterance

LINES = {
    "en": "my mother bought a ripe apple today",
    "de": "Meine Mutter kaufte heute einen Apfel",
    "fr": "Ma mère a acheté une pomme aujourd'hui",
    "es": "Mi madre compró una manzana hoy",
    "cmn": "我妈妈今天买了一个苹果",
}
MODULE = {"de": "gruut_lang_de", "fr": "gruut_lang_fr", "es": "gruut_lang_es", "cmn": "pypinyin"}


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--nodes", type=int, default=20000, help="motion nodes of the step-cost timing")
    parser.add_argument("--cost-repeats", type=int, default=25, help="timings of the step costs (the fastest is kept)")
    args = parser.parse_args(argv)
    config = Config.load()
    align, synth = config.settings("align"), config.settings("synthesize")
    rng = np.random.default_rng(0)
    node_phone = [str(p) for p in rng.choice(sorted(FESTIVAL_IPA), args.nodes)]
    node_emotion = ["neutral"] * args.nodes
    data, rate = soundfile.read(str(resources.files("facesynth").joinpath("data/facegood_audio.ogg")), dtype="float32")
    samples = (data if data.ndim == 1 else data.mean(axis=1))[: 4 * rate]
    out: dict[str, object] = {"audio_s": len(samples) / rate, "repeats": args.repeats, "import_s": {}, "lines": {},
                              "lookup_s": {}, "step_costs_s": {}, "features_against_table_ii": {},
                              "nodes": args.nodes, "skipped": []}
    for language, text in LINES.items():
        module = MODULE.get(language)
        if module is not None and importlib.util.find_spec(module) is None:
            out["skipped"].append(language)  # type: ignore[union-attr]
            continue
        settings = dataclasses.replace(align, language=language, methods=("duration",))
        t0 = time.perf_counter()
        result = align_robust(samples, rate, text, settings=settings)
        first = time.perf_counter() - t0
        times, g2p = [], []
        for _ in range(args.repeats):
            t0 = time.perf_counter()
            result = align_robust(samples, rate, text, settings=settings)
            times.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            if language == "en":
                _parse(_cmudict_lines(), set(normalize_text(text)))
            else:
                words_of(text, language)
            g2p.append(time.perf_counter() - t0)
        median = statistics.median(times)
        utt = utterance([x.label for x in result.phones], [x.start for x in result.phones],
                        [x.end for x in result.phones], ipa=result.ipa)
        costs, english_rule = [], []
        for _ in range(args.cost_repeats):
            t0 = time.perf_counter()
            step_costs(utt.phones, utt.emotions, node_phone, node_emotion, {}, synth, utt.ipa)
            costs.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            step_costs(utt.phones, utt.emotions, node_phone, node_emotion, {}, synth)
            english_rule.append(time.perf_counter() - t0)
        out["step_costs_s"][language] = round(min(costs), 4)  # type: ignore[index]
        if language != "en":
            out["features_against_table_ii"][language] = round(min(costs) / min(english_rule), 2)  # type: ignore[index]
        if language != "en":
            out["import_s"][language] = round(first - median, 3)  # type: ignore[index]
        out["lookup_s"][language] = round(statistics.median(g2p), 4)  # type: ignore[index]
        out["lines"][language] = {  # type: ignore[index]
            "text": text, "phones": sum(s.label != "pau" for s in result.phones), "method": result.method,
            "median_s": round(median, 3)}
    english = out["lines"]["en"]["median_s"]  # type: ignore[index]
    for row in out["lines"].values():  # type: ignore[union-attr]
        row["ratio_to_english"] = round(row["median_s"] / english, 2)
    per_phone = {k: v / out["lines"][k]["phones"] for k, v in out["step_costs_s"].items()}  # type: ignore[union-attr, index]
    out["step_costs_per_phone_ms"] = {k: round(1000 * v, 3) for k, v in per_phone.items()}
    out["step_costs_per_phone_ratio_to_english"] = {k: round(v / per_phone["en"], 2) for k, v in per_phone.items()}
    json.dump(out, sys.stdout, indent=1, ensure_ascii=False)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
