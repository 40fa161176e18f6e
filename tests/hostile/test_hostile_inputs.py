"""Every reader against broken and hostile files (see :mod:`tests.hostile.cases` for the
mutations and the contract): exit 1 with one sentence naming the file, no traceback, nothing
left behind, the input unchanged, within the time bound, or exit 0 with valid outputs.

``make test`` runs :func:`cases.quick_cases` (seed 0, under a minute); ``make test-hostile``
(``pytest -m hostile_long``) runs the other cases of every kind x mutation over five seeds."""

from __future__ import annotations

import pytest

from . import cases


@pytest.mark.hostile_long
def test_every_base_is_valid(hostile_bases, tmp_path):
    """Each kind's command succeeds on the unmutated input, so a refusal is the mutation's doing."""
    assert cases.check_bases(hostile_bases, tmp_path) == {}


@pytest.mark.parametrize("kind, mutation, seed", cases.quick_cases(), ids=lambda v: str(v))
def test_hostile_input(hostile_bases, tmp_path, kind, mutation, seed):
    case, outcome, why = cases.run_case(hostile_bases, kind, mutation, seed, tmp_path / "case")
    assert why is None, f"{' '.join(case.args)}\n{why}\n{outcome['output']}\n{outcome.get('escaped') or ''}"


def _long_cases():
    quick = set(cases.quick_cases())
    return [c for c in cases.all_cases(seeds=5) if c not in quick]


@pytest.mark.hostile_long
@pytest.mark.parametrize("kind, mutation, seed", _long_cases(), ids=lambda v: str(v))
def test_hostile_input_long(hostile_bases, tmp_path, kind, mutation, seed):
    case, outcome, why = cases.run_case(hostile_bases, kind, mutation, seed, tmp_path / "case")
    assert why is None, f"{' '.join(case.args)}\n{why}\n{outcome['output']}\n{outcome.get('escaped') or ''}"
