"""``benchmarks/real_speech_lipsync.py``: its scoring functions on made-up curves with known
answers (the benchmark itself needs the FACEGOOD recordings and runs the pipeline; it is not
part of the test suite)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from facesynth.formats.labels import Segment

SPEC = importlib.util.spec_from_file_location(
    "real_speech_lipsync", Path(__file__).resolve().parents[1] / "benchmarks" / "real_speech_lipsync.py")
bench = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(bench)


def test_pearson_known_values_and_undefined():
    t = np.arange(100.0)
    x = np.sin(t / 5)
    assert bench.pearson(x, 3 * x + 2) == pytest.approx(1.0)
    assert bench.pearson(x, -x) == pytest.approx(-1.0)
    # cos and sin over whole periods are uncorrelated
    u = np.linspace(0, 4 * np.pi, 400, endpoint=False)
    assert bench.pearson(np.sin(u), np.cos(u)) == pytest.approx(0.0, abs=1e-12)
    assert np.isnan(bench.pearson(x, np.ones(100)))
    assert np.isnan(bench.pearson(x[:2], x[:2]))


def test_windows_tile_the_take_in_equal_parts():
    spans = bench.windows(650, 30.0, 10.0)  # 21.7 s -> two windows of 325 frames
    assert spans == [(0, 325), (325, 650)]
    assert bench.windows(100, 30.0, 10.0) == [(0, 100)]  # shorter than a window: one window
    spans = bench.windows(3295, 30.0, 10.0)
    assert spans[0][0] == 0 and spans[-1][1] == 3295 and len(spans) == 11
    assert all(b == c for (_, b), (c, _) in zip(spans[:-1], spans[1:]))


def test_window_r_scores_each_window_alone():
    rng = np.random.default_rng(0)
    real = rng.normal(size=200)
    method = real.copy()
    method[100:] = -real[100:]  # right in the first window, inverted in the second
    r = bench.window_r(method, real, [(0, 100), (100, 200)])
    assert r == pytest.approx([1.0, -1.0])


def test_mean_r_and_ratio_statistics():
    values = np.array([0.2, np.nan, 0.6])
    assert bench.mean_r_statistic(values)(np.array([0, 1, 2])) == pytest.approx(0.4)
    assert np.isnan(bench.mean_r_statistic(values)(np.array([1, 1])))
    hits, totals = np.array([1, 2, 0]), np.array([2, 2, 0])
    assert bench.ratio_statistic(hits, totals)(np.array([0, 1])) == pytest.approx(0.75)
    assert np.isnan(bench.ratio_statistic(hits, totals)(np.array([2, 2])))


def test_closure_events_find_the_deep_minima_only():
    n = 300
    opening = np.ones(n)
    for f in (50, 150, 250):  # three closures to 0 ...
        opening[f - 5:f + 6] = np.abs(np.arange(-5, 6)) / 5.0
    opening[100 - 5:100 + 6] = 0.8 + 0.2 * np.abs(np.arange(-5, 6)) / 5.0  # ... and one shallow dip
    events = bench.closure_events(opening, depth=0.25, prominence=0.25)
    assert list(events) == [50, 150, 250]
    assert len(bench.closure_events(np.ones(50), 0.25, 0.25)) == 0


def test_match_closures_counts_both_ways_within_tolerance():
    real = np.array([10, 50, 90])
    method = np.array([12, 57, 91, 200])
    # 10~12 and 90~91 within 3 frames; 50 vs 57 is 7 frames away; 200 is nowhere near
    assert bench.match_closures(real, method, 3) == (2, 2)
    assert bench.match_closures(real, method, 7) == (3, 3)
    assert bench.match_closures(real, np.zeros(0, int), 3) == (0, 0)


def test_summarize_intervals_and_paired_difference():
    rng = np.random.default_rng(1)
    good = 0.6 + 0.05 * rng.normal(size=40)
    bad = good - 0.3  # worse in every window by exactly 0.3
    closures = np.array([[2, 1, 2, 2]] * 40)  # half the real closures found, every found one right
    groups = np.repeat(np.arange(4), 10)  # four takes of ten windows
    s = bench.summarize({"opening": {"facesynth": good, "openfacefx": bad}}, {"facesynth": closures}, groups, 500, 0)
    r = s["r"]["opening"]["facesynth"]
    assert r["value"] == pytest.approx(good.mean())
    assert r["low"] < r["value"] < r["high"]
    d = s["paired"]["opening"]["facesynth - openfacefx"]
    assert d["value"] == pytest.approx(0.3) and d["low"] == pytest.approx(0.3) and d["high"] == pytest.approx(0.3)
    assert s["closures"]["facesynth"]["recall"]["value"] == pytest.approx(0.5)
    assert s["closures"]["facesynth"]["precision"]["value"] == pytest.approx(1.0)
    assert s["windows"] == 40 and s["takes"] == 4
    assert s["r_takes"]["opening"]["facesynth"]["value"] == pytest.approx(good.mean())
    assert s["paired_takes"]["opening"]["facesynth - openfacefx"]["low"] == pytest.approx(0.3)


def test_by_take_resamples_whole_takes():
    values = np.array([0.1, 0.1, 0.5, 0.5, 0.5, 0.9])  # take 0: two windows, take 1: three, take 2: one
    groups = np.array([0, 0, 1, 1, 1, 2])
    stat = bench.by_take(bench.mean_r_statistic(values), groups)
    assert stat(np.array([0, 1, 2])) == pytest.approx(values.mean())
    assert stat(np.array([2, 2])) == pytest.approx(0.9)
    assert stat(np.array([0, 2])) == pytest.approx((0.1 + 0.1 + 0.9) / 3)  # windows, not takes, are averaged


def test_real_curves_follow_facegood_table():
    table = bench.read_table()
    assert table["jawOpen"] == ["mouth_stretch_c"]
    assert table["mouthPucker"] == ["mouth_pucker_l", "mouth_pucker_r"]
    assert "eyeBlinkLeft" not in table  # marked invalid by FACEGOOD
    names = ["mouth_stretch_c", "mouth_oh_c", "mouth_chew_c", "mouth_pucker_l", "mouth_pucker_r", "mouth_press_l",
             "mouth_press_r", "mouth_funnel_dl", "mouth_funnel_dr", "mouth_funnel_ul", "mouth_funnel_ur"]
    values = np.zeros((2, len(names)))
    values[0, :5] = [0.5, 0.25, 0.0, 0.2, 0.7]
    values[1, 5:7] = [0.4, 0.2]
    real = bench.real_curves(values, names, table)
    assert real["opening"] == pytest.approx([0.75, 0.0])
    assert real["mouthPucker"] == pytest.approx([0.7, 0.0])
    assert real["mouthPress"] == pytest.approx([0.0, 0.3])


def test_phone_means_fit_and_interpolate():
    segs = [Segment(0.0, 1.0, "aa"), Segment(1.0, 2.0, "m")]
    n = 60
    real = {c: np.where(np.arange(n) < 30, 1.0, 0.0) for c in bench.CHANNELS}
    means = bench.phone_means([{"segs": segs, "real": real, "n": n}])
    assert means["opening"]["aa"] == pytest.approx(1.0) and means["opening"]["m"] == pytest.approx(0.0)
    pred = bench.phone_mean_method(means, [Segment(0.0, 1.0, "m"), Segment(1.0, 2.0, "aa"), Segment(2.0, 3.0, "zh")], 90)
    # held at the first centre, ramping to the next, the unseen phone gets the overall mean (0.5)
    assert pred["opening"][0] == 0.0 and pred["opening"][45] == pytest.approx(1.0) and pred["opening"][89] == pytest.approx(0.5)


def test_phones_from_audio_prefers_facesynths_own_audio_only_alignment(tmp_path, monkeypatch):
    import click

    import facesynth.cli
    from facesynth.base.config import Config
    from facesynth.formats.audio import write_wav
    from facesynth.formats.labels import write_textgrid

    @click.group()
    def fake_main():
        pass

    @fake_main.command()
    @click.argument("audio")
    @click.option("-o", "output")
    @click.option("--overwrite", is_flag=True)
    @click.option("-q", is_flag=True)
    def align(audio, output, overwrite, q):
        write_textgrid(Path(output), {"phones": [Segment(0.0, 0.4, "pau"), Segment(0.4, 1.0, "aa")]}, xmax=1.0)

    monkeypatch.setattr(facesynth.cli, "main", fake_main)
    wav = tmp_path / "x.wav"
    write_wav(wav, np.zeros(16000, np.float32), 16000)
    segs, source = bench.phones_from_audio(wav, tmp_path / "x.TextGrid", Config.load().settings("align"))
    assert source == "facesynth align (audio only)"
    assert [s.label for s in segs] == ["pau", "aa"]


def test_phones_from_audio_tiles_the_audio(tmp_path):
    pytest.importorskip("pocketsphinx", reason="pocketsphinx is needed for phone recognition")
    from facesynth.base.config import Config
    from facesynth.formats.audio import write_wav

    rate = 16000
    t = np.arange(rate * 2) / rate
    voiced = (t > 0.5) & (t < 1.5)
    samples = (0.3 * np.sin(2 * np.pi * 150 * t) * (1 + 0.5 * np.sin(2 * np.pi * 4 * t)) * voiced).astype(np.float32)
    wav = tmp_path / "x.wav"
    write_wav(wav, samples, rate)
    segs, source = bench.phones_from_audio(wav, tmp_path / "x.TextGrid", Config.load().settings("align"))
    assert source in ("facesynth align (audio only)", "pocketsphinx phone loop (en-us phone language model)")
    assert segs[0].start == 0.0 and segs[-1].end == pytest.approx(2.0, abs=0.02)
    assert all(a.end == pytest.approx(b.start) for a, b in zip(segs[:-1], segs[1:]))
    assert (tmp_path / "x.TextGrid").exists()
