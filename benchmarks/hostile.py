"""Run the hostile-input cases of ``tests/hostile/cases.py`` and print, per input kind and
mutation, how many cases were tried and how many met the contract, as JSON (``--markdown``:
a table).

    python benchmarks/hostile.py --seeds 3 --work out/hostile [--markdown]

The tiny sample corpus and its artifacts are built under ``--work`` first (seed 0).
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import time
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

import cases  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--work", type=Path, default=Path("out/hostile"))
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--kinds", nargs="*", default=None)
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--failures", action="store_true", help="list each case that failed, with why")
    a = parser.parse_args()
    from facesynth.domain.corpus.generate import generate

    a.work.mkdir(parents=True, exist_ok=True)
    corpus = a.work / "corpus"
    if not (corpus / "manifest.csv").exists():
        generate(corpus, "tiny", seed=0)
    bases = cases.build_bases(a.work / "bases", corpus)
    broken = cases.check_bases(bases, a.work / "cases")
    if broken:  # every case of such a kind would be refused for the base's sake, proving nothing
        print("bases that do not run: " + "; ".join(f"{k}: {why}" for k, why in broken.items()), file=sys.stderr)
    todo = [c for c in cases.all_cases(a.seeds) if a.kinds is None or c[0] in a.kinds]
    started = time.perf_counter()

    def one(c):
        folder = a.work / "cases" / f"{c[0]}-{c[1]}-{c[2]}"
        shutil.rmtree(folder, ignore_errors=True)
        _, outcome, why = cases.run_case(bases, *c, folder)
        shutil.rmtree(folder, ignore_errors=True)
        return c, why

    with ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(one, todo))
    seconds = time.perf_counter() - started
    table: dict = defaultdict(lambda: [0, 0])
    failures = []
    for (kind, mutation, seed), why in results:
        table[(kind, mutation)][0] += 1
        table[(kind, mutation)][1] += why is None
        if why is not None:
            failures.append(f"{kind} {mutation} {seed}: {why}")
    rows = [{"kind": k, "mutation": m, "tried": t, "handled": h} for (k, m), (t, h) in table.items()]
    for r in rows:
        r["base_runs"] = r["kind"] not in broken
    summary = {"tried": sum(r["tried"] for r in rows), "handled": sum(r["handled"] for r in rows), "seconds": seconds,
               "bases_that_do_not_run": broken}
    if a.markdown:
        print("| input | mutation | tried | handled |\n|---|---|---|---|")
        for r in rows:
            print(f"| {r['kind']} | {r['mutation']} | {r['tried']} | {r['handled']} |")
        print(f"\n{summary['handled']} of {summary['tried']} handled in {seconds:.1f} s")
    else:
        print(json.dumps({"summary": summary, "rows": rows}, indent=1))
    if a.failures:
        print("\n".join(failures), file=sys.stderr)


if __name__ == "__main__":
    main()
