import h5py
import numpy as np
import pytest
from click.testing import CliRunner
from coded_audio import COMPRESSED, coded, correlation, same_motion

from facesynth.base.errors import InputError, SearchError
from facesynth.cli import main
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import synthesize


def _run(db, tg, out, config, **kw):
    return synthesize.run(db, out, config.settings("synthesize"), config.settings("ingest"),
                          config.settings("align"), phones_path=tg, **kw)


def test_motion_artifact_holds_both_rates_path_costs_and_provenance(tiny_db, tiny_corpus, held_out_take, config, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    out = tmp_path / "m.h5"
    s = _run(tiny_db, tg, out, config)
    with h5py.File(out) as f:
        m30, m120 = f["markers"], f["markers_capture"]
        assert m30.attrs["fps"] == 30 and m120.attrs["fps"] == 120 and m30.attrs["units"] == "mm"
        assert len(m120) == pytest.approx(4 * (len(m30) - 1) + 1, abs=3)
        path = f["path/node"][()]
        assert len(path) == s.summary.phones
        total = sum(f[f"path/cost_{k}"][()].astype(np.float64).sum() for k in ("tc", "oc", "emp", "block"))
        assert total == pytest.approx(f["path"].attrs["total_cost"], rel=1e-5)
        assert f["path"].attrs["non_captured_joins"] == s.summary.joins
        node, take, src = f["provenance/node"][()], f["provenance/take"][()], f["provenance/source_frame"][()]
        assert len(node) == len(m120)
        assert ((node == -1) == (src == -1)).all() and ((node == -1) == (take == -1)).all()
        spoken = node >= 0
        assert set(np.unique(node[spoken])) <= set(path.tolist())


def test_constraints_are_met_and_emotions_steer_the_search(tiny_db, tiny_corpus, held_out_take, config, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    db = MotionDatabase.read(tiny_db)
    from facesynth.domain.speech.utterance import read_utterance

    utt = read_utterance(tg)
    t = next(k for k, p in enumerate(utt.phones) if p != "pau" and p in db.nodes.phone)
    node = [j for j, p in enumerate(db.nodes.phone) if p == utt.phones[t]][-1]
    (tmp_path / "c.txt").write_text(f"# pick a node\n{t} {node}\n")
    (tmp_path / "e.txt").write_text("0 100 angry\n")
    _run(tiny_db, tg, tmp_path / "m.h5", config, constraints_path=tmp_path / "c.txt", emotions_path=tmp_path / "e.txt")
    with h5py.File(tmp_path / "m.h5") as f:
        assert f["path/node"][t] == node
        emotions = [e.decode() for e in f["path/node_emotion"][()]]
    spoken = [e for e, p in zip(emotions, utt.phones) if p != "pau"]
    assert spoken.count("angry") > 0.7 * len(spoken)


@pytest.mark.parametrize("line, message", [
    ("0 5", "is a pause"),
    ("999 5", "phone index 999 is out of range"),
    ("99.0s 5", "outside the utterance"),
    ("1 100000", "node 100000 does not exist"),
    ("1 x", "expected 'INDEX NODE' or 'TIMEs NODE' with numbers"),
])
def test_bad_constraints_are_named(tiny_db, tiny_corpus, held_out_take, config, tmp_path, line, message):
    (tmp_path / "c.txt").write_text(line + "\n")
    with pytest.raises((SearchError, InputError), match=message):
        _run(tiny_db, tiny_corpus / "labels" / f"{held_out_take}.TextGrid", tmp_path / "m.h5", config,
             constraints_path=tmp_path / "c.txt")
    assert not (tmp_path / "m.h5").exists()


def test_constraint_with_a_node_of_another_phone(tiny_db, tiny_corpus, held_out_take, config, tmp_path):
    from facesynth.domain.speech.utterance import read_utterance

    db = MotionDatabase.read(tiny_db)
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    node = next(j for j, p in enumerate(db.nodes.phone) if p != utt.phones[1])
    (tmp_path / "c.txt").write_text(f"1 {node}\n")
    with pytest.raises(SearchError, match=rf"node {node} is /{db.nodes.phone[node]}/ but phone 1 is /{utt.phones[1]}/"):
        _run(tiny_db, tiny_corpus / "labels" / f"{held_out_take}.TextGrid", tmp_path / "m.h5", config, constraints_path=tmp_path / "c.txt")


@pytest.mark.parametrize("text, message", [
    ("0 1 happy\n0.5 2 sad\n", "line 2: emotion span overlaps the one at line 1"),
    ("0 1 bored\n", "unknown emotion 'bored'"),
    ("0 x happy\n", "expected 'start_s end_s emotion'"),
])
def test_bad_emotion_files(tiny_db, tiny_corpus, held_out_take, config, tmp_path, text, message):
    (tmp_path / "e.txt").write_text(text)
    with pytest.raises(InputError, match=message):
        _run(tiny_db, tiny_corpus / "labels" / f"{held_out_take}.TextGrid", tmp_path / "m.h5", config, emotions_path=tmp_path / "e.txt")


def test_cli_warns_about_phones_without_nodes(tiny_db, tiny_corpus, tmp_path):
    from facesynth.formats.labels import Segment, write_textgrid

    tg = tmp_path / "u.TextGrid"
    write_textgrid(tg, {"phones": [Segment(0, 0.2, "pau"), Segment(0.2, 0.3, "zh"), Segment(0.3, 0.5, "oy"), Segment(0.5, 0.7, "pau")]})
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tg), "-o", str(tmp_path / "m.h5")])
    assert r.exit_code == 0, r.output
    db = MotionDatabase.read(tiny_db)
    for phone in ("zh", "oy"):
        if phone not in db.nodes.phone:
            assert f"no node of /{phone}/" in r.output


def test_cli_verbose_reports_every_phase(tiny_db, tiny_corpus, held_out_take, tmp_path):
    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes", str(tg), "-o", str(tmp_path / "m.h5"), "-v"])
    assert r.exit_code == 0, r.output
    line = next(ln for ln in r.output.splitlines() if ln.startswith("phases:"))
    for phase in ("read database", "transition costs", "step costs", "search", "post-processing", "input hashes", "write"):
        assert f"{phase} " in line
    assert ("OpenCL set-up " in line) == ("search on OpenCL" in line)  # no set-up on the NumPy fallback


def test_numpy_and_opencl_synthesis_write_the_same_motion(tiny_db, tiny_corpus, held_out_take, config, tmp_path, opencl_device):
    from facesynth.base.config import Config

    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    _run(tiny_db, tg, tmp_path / "a.h5", config)
    numpy_config = Config.load(None, ("synthesize.use_opencl=false",))
    _run(tiny_db, tg, tmp_path / "b.h5", numpy_config)
    with h5py.File(tmp_path / "a.h5") as a, h5py.File(tmp_path / "b.h5") as b:
        assert np.array_equal(a["path/node"][()], b["path/node"][()])
        assert np.array_equal(a["markers"][()], b["markers"][()])


@pytest.mark.parametrize("use_opencl", ["true", "false"])
def test_pruned_and_dense_searches_write_the_same_motion(tiny_db, tiny_corpus, held_out_take, tmp_path, use_opencl):
    from facesynth.base.config import Config

    tg = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    costs = [_run(tiny_db, tg, tmp_path / f"{dp}.h5", Config.load(None, (f"synthesize.dp={dp}", f"synthesize.use_opencl={use_opencl}"))).summary.cost
             for dp in ("pruned", "dense")]
    assert costs[0] == costs[1]
    with h5py.File(tmp_path / "pruned.h5") as a, h5py.File(tmp_path / "dense.h5") as b:
        assert np.array_equal(a["path/node"][()], b["path/node"][()])
        assert np.array_equal(a["markers"][()], b["markers"][()])


def test_audio_and_text_are_aligned_on_the_fly_and_emotion_tiers_read(tiny_db, tiny_corpus, config, tmp_path):
    import csv

    from facesynth.formats.labels import Segment, read_textgrid, write_textgrid

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    s = synthesize.run(tiny_db, tmp_path / "a.h5", config.settings("synthesize"), config.settings("ingest"),
                       config.settings("align"), audio=tiny_corpus / row["audio"], text=row["transcript"])
    assert s.summary.phones > len(row["transcript"].split())
    tiers = read_textgrid(tiny_corpus / row["alignment"])
    end = tiers["phones"][-1].end
    write_textgrid(tmp_path / "e.TextGrid", {"phones": tiers["phones"],
                                             "emotions": [Segment(0, end / 2, "sad"), Segment(end / 2, end, "happy")]})
    synthesize.run(tiny_db, tmp_path / "b.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tmp_path / "e.TextGrid", emotions_path=tmp_path / "e.TextGrid")
    with h5py.File(tmp_path / "b.h5") as f:
        asked = [e.decode() for e in f["path/emotion"][()]]
        mids = (f["path/start"][()] + f["path/end"][()]) / 2
    assert all(e == ("sad" if m < end / 2 else "happy") for e, m in zip(asked, mids))


def test_align_settings_reach_the_aligner_of_the_input_audio(tiny_db, tiny_corpus, held_out_take, tmp_path, monkeypatch):
    from facesynth.domain.speech import recognition
    from facesynth.domain.speech.alignment import Alignment
    from facesynth.formats.labels import read_phone_segments

    received = []

    def fake_align(samples, rate, text, *, settings=None, extra=None, where="audio"):
        received.append(settings)
        return Alignment(read_phone_segments(tiny_corpus / "labels" / f"{held_out_take}.TextGrid", ("phones",)), [],
                         "pocketsphinx")

    monkeypatch.setattr(recognition, "align_robust", fake_align)
    r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--audio", str(tiny_corpus / "audio" / f"{held_out_take}.wav"),
                                  "--text", "words", "-o", str(tmp_path / "m.h5"),
                                  "--set", "align.sample_rate=22050", "--set", "align.frame_rate=200"])
    assert r.exit_code == 0, r.output
    assert [(s.sample_rate, s.frame_rate) for s in received] == [(22050, 200)]


@pytest.mark.parametrize("name", COMPRESSED)
def test_coded_speech_synthesizes_as_the_wav(tiny_db, tiny_corpus, held_out_take, coded_speech, tmp_path, name):
    """``synthesize --audio`` with the held-out sentence as M4A, MP3, Opus, Ogg or an MP4's sound
    (aligned to its text): the WAV's phones, boundaries within 50 ms, and markers that follow the
    WAV's (``coded_audio.same_motion``: r 0.993 for MP3, Opus and Ogg, 0.930 for AAC, one boundary
    30 ms later and a different node there). The tolerance is the aligner's, not the decoder's: the
    WAV resampled to 44.1 kHz gives 0.9996, the WAV with one least-significant bit of noise added
    (eight seeds) 0.975-0.980 (with the loudness step), while AAC's samples follow the WAV's at r
    1.0000."""
    import csv

    text = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == held_out_take)["transcript"]
    got = {}
    for kind, path in (("wav", coded_speech["wav"]), (name, coded(coded_speech, name))):
        out = tmp_path / f"{kind}.h5"
        r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--audio", str(path), "--text", text, "-o", str(out)])
        assert r.exit_code == 0, r.output
        with h5py.File(out) as f:
            got[kind] = ([p.decode() for p in f["path/phone"][()]], f["path/start"][()], f["markers"][()])
    (phones, starts, markers), (phones_c, starts_c, markers_c) = got["wav"], got[name]
    assert phones_c == phones and np.abs(starts_c - starts).max() <= 0.05
    assert abs(len(markers_c) - len(markers)) <= 1
    assert correlation(markers, markers_c) > same_motion(name)
