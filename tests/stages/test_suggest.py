import h5py
import pytest

from facesynth.errors import InputError
from facesynth.search.inputs import read_utterance
from facesynth.stages import suggest, synthesize


def test_suggested_costs_are_what_the_constrained_search_finds(tiny_db, tiny_corpus, held_out_take, config, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    utt = read_utterance(tg)
    db = synthesize.MotionDatabase.read(tiny_db)
    c = next(k for k, p in enumerate(utt.phones) if p != "pau" and db.nodes.phone.count(p) >= 3)
    at = 0.5 * (utt.starts[c] + utt.ends[c])
    info, rows = suggest.suggest(tiny_db, tg, at, config.settings("synthesize"), config.settings("ingest"))
    assert info["index"] == c and info["relative_time"] == pytest.approx(0.5)
    assert {r.node for r in rows} == {j for j, p in enumerate(db.nodes.phone) if p == utt.phones[c]}
    assert rows[0].extra == pytest.approx(0.0, abs=1e-3) and rows[0].cost == pytest.approx(info["optimum"], rel=1e-6)
    assert [r.cost for r in rows] == sorted(r.cost for r in rows)
    for r in rows[1:3]:  # constrain to a suggestion: the search's cost is the suggested cost
        (tmp_path / "c.txt").write_text(f"{c} {r.node}\n")
        synthesize.run(tiny_db, tmp_path / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                       config.settings("align"), phones_path=tg, constraints_path=tmp_path / "c.txt", overwrite=True)
        with h5py.File(tmp_path / "m.h5") as f:
            assert f["path"].attrs["total_cost"] == pytest.approx(r.cost, rel=1e-5)
    for r in rows:
        node_frames = (db.nodes.frame_start[r.node], db.nodes.frame_start[r.node] + db.nodes.frame_count[r.node] - 1)
        assert node_frames[0] <= r.time_correct_frame <= node_frames[1]
        assert r.context_correct == (r.context == info["context"])


def test_suggest_in_a_pause_is_refused(tiny_db, tiny_corpus, held_out_take, config):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    with pytest.raises(InputError, match="falls in a pause"):
        suggest.suggest(tiny_db, tg, 0.01, config.settings("synthesize"), config.settings("ingest"))
