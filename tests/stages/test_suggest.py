import h5py
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.speech.utterance import read_utterance
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import suggest, synthesize


def test_suggested_costs_are_what_the_constrained_search_finds(tiny_db, tiny_corpus, held_out_take, config, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    utt = read_utterance(tg)
    db = MotionDatabase.read(tiny_db)
    c = next(k for k, p in enumerate(utt.phones) if p != "pau" and db.nodes.phone.count(p) >= 3)
    at = 0.5 * (utt.starts[c] + utt.ends[c])
    info = suggest.suggest(tiny_db, tg, at, config.settings("synthesize"), config.settings("ingest")).suggestions
    rows = info.rows
    assert info.index == c and info.relative_time == pytest.approx(0.5)
    assert {r.node for r in rows} == {j for j, p in enumerate(db.nodes.phone) if p == utt.phones[c]}
    assert rows[0].extra == pytest.approx(0.0, abs=1e-3) and rows[0].cost == pytest.approx(info.optimum, rel=1e-6)
    assert [r.cost for r in rows] == sorted(r.cost for r in rows)
    for r in rows[1:3]:  # constrain to a suggestion: the search's cost is the suggested cost
        (tmp_path / "c.txt").write_text(f"{c} {r.node}\n")
        synthesize.run(tiny_db, tmp_path / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                       config.settings("align"), phones_path=tg, constraints_path=tmp_path / "c.txt", overwrite=True)
        with h5py.File(tmp_path / "m.h5") as f:
            assert f["path"].attrs["total_cost"] == pytest.approx(r.cost, rel=1e-5)
    for r in rows:  # the time-correct frame: an integer frame of the node's take, inside the node
        take = db.nodes.take[r.node]
        assert isinstance(r.time_correct_frame, int) and db.takes.name[take] == r.take
        in_db = int(db.takes.frame_start[take]) + r.time_correct_frame
        node_frames = (db.nodes.frame_start[r.node], db.nodes.frame_start[r.node] + db.nodes.frame_count[r.node] - 1)
        assert node_frames[0] <= in_db <= node_frames[1]
        expected = node_frames[0] + round(0.5 * (db.nodes.frame_count[r.node] - 1))
        assert abs(in_db - expected) <= 1
        assert r.context_correct == (r.context == info.context)


def test_suggest_in_a_pause_is_refused(tiny_db, tiny_corpus, held_out_take, config):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    with pytest.raises(InputError, match="falls in a pause"):
        suggest.suggest(tiny_db, tg, 0.01, config.settings("synthesize"), config.settings("ingest"))


def test_a_shared_triphone_gives_context_correct_suggestions(tiny_db, spliced_sentence, config):
    tg, segs = spliced_sentence
    db = MotionDatabase.read(tiny_db)
    c = 3  # pau, s3, s4, [s5], ...: an inner phone, its neighbours as in the training sentence
    at = 0.5 * (segs[c].start + segs[c].end)
    info = suggest.suggest(tiny_db, tg, at, config.settings("synthesize"), config.settings("ingest")).suggestions
    rows = info.rows
    context = (segs[c - 1].label, segs[c].label, segs[c + 1].label)
    assert info.context == "{}-{}+{}".format(*context)
    same = {j for j in range(len(db.nodes)) if (db.nodes.prev_phone[j], db.nodes.phone[j], db.nodes.next_phone[j]) == context}
    assert same and {r.node for r in rows if r.context_correct} == same
    assert [s.index for s in info.context_correct_at] == [2, 3, 4, 5]  # not the edges, whose context is a pause

    r = CliRunner().invoke(main, ["suggest", str(tiny_db), "--phonemes", str(tg), "--at", f"{at}", "--context-only"])
    assert r.exit_code == 0, r.output
    lines = r.stdout.splitlines()
    assert lines[0].split("\t")[6] == "time_correct_take_frame"
    assert {int(line.split("\t")[1]) for line in lines[1:]} == same
    best = lines[1].split("\t")[1]
    assert "best: rank 1" in r.stderr and f'echo "{at:g}s {best}" > constraints.txt' in r.stderr
    assert "--constraints constraints.txt" in r.stderr


def test_a_filter_that_leaves_nothing_is_an_error(tiny_db, tiny_corpus, held_out_take, config):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    utt = read_utterance(tg)
    c = next(k for k, p in enumerate(utt.phones) if p != "pau")
    at = 0.5 * (utt.starts[c] + utt.ends[c])
    info = suggest.suggest(tiny_db, tg, at, config.settings("synthesize"), config.settings("ingest")).suggestions
    rows = info.rows
    if any(r.context_correct for r in rows):
        pytest.skip("this phone of the held-out sentence has context-correct nodes")
    plain = CliRunner().invoke(main, ["suggest", str(tiny_db), "--phonemes", str(tg), "--at", f"{at}"])
    assert plain.exit_code == 0 and "warning: no node of" in plain.stderr
    only = CliRunner().invoke(main, ["suggest", str(tiny_db), "--phonemes", str(tg), "--at", f"{at}", "--context-only"])
    assert only.exit_code == 1 and only.stdout == ""
    assert only.stderr.startswith("error: no node of") and len(only.stderr.strip().splitlines()) == 1
    assert "drop --context-only" in only.stderr
