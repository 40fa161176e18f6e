"""Ranking the nodes a phone can be constrained to (facesynth.domain.search.constraint_choice.suggest,
paper VI-A) on the tiny database, called with an utterance made here."""

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.search.constraint_choice import suggest
from facesynth.domain.speech.utterance import Utterance
from facesynth.model.motiondb import MotionDatabase


def _utterance(db, phones):
    n = len(phones)
    return Utterance(phones, np.arange(n) * 0.1, np.arange(1, n + 1) * 0.1, ["neutral"] * n)


def _spoken(db, count):
    """``count`` spoken phones of the database that have at least 3 nodes each."""
    phones = [p for p in dict.fromkeys(db.nodes.phone) if p != "pau" and db.nodes.phone.count(p) >= 3]
    return phones[:count]


def test_the_best_suggestion_is_the_optimum_and_a_constraint_elsewhere_costs_more(tiny_db, config):
    db = MotionDatabase.read(tiny_db)
    utt = _utterance(db, ["pau"] + _spoken(db, 3) + ["pau"])
    settings = config.settings("synthesize")
    free = suggest(db, utt, 0.25, {}, settings, False, where="phones", db_where="db")
    assert free.index == 2 and free.phone == utt.phones[2] and free.relative_time == pytest.approx(0.5)
    assert free.rows[0].cost == pytest.approx(free.optimum, rel=1e-6) and free.rows[0].node == free.optimal_node
    assert [r.cost for r in free.rows] == sorted(r.cost for r in free.rows)
    # hold step 1 to its worst node: no path through step 2 gets cheaper, and the optimum rises
    worst = suggest(db, utt, 0.15, {}, settings, False, where="phones", db_where="db").rows[-1]
    assert worst.extra > 0
    held = suggest(db, utt, 0.25, {1: worst.node}, settings, False, where="phones", db_where="db")
    by_node = {r.node: r.cost for r in free.rows}
    assert all(r.cost >= by_node[r.node] - 1e-6 for r in held.rows)
    assert held.optimum == pytest.approx(free.optimum + worst.extra, rel=1e-6)


def test_a_phone_the_database_lacks_and_a_pause_are_named(tiny_db, config):
    db = MotionDatabase.read(tiny_db)
    missing = next(p for p in ("zh", "oy", "uh", "aw") if p not in db.nodes.phone)
    utt = _utterance(db, ["pau", missing, "pau"])
    with pytest.raises(InputError, match=f"^db: the database has no node of /{missing}/ to suggest"):
        suggest(db, utt, 0.15, {}, config.settings("synthesize"), False, where="phones", db_where="db")
    with pytest.raises(InputError, match="^phones: 0.050 s falls in a pause"):
        suggest(db, utt, 0.05, {}, config.settings("synthesize"), False, where="phones", db_where="db")
