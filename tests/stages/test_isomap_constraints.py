"""``facesynth isomap page``: the paper's constraint GUI (VI-A, Fig. 9) as a person uses it.
Opened in headless Chromium (where the Debian package is installed) and driven over the
DevTools protocol: for a picked time or phone the highlighted nodes are the ones ``facesynth
suggest`` lists as time-correct and context-correct, the synthesized path's node is marked,
and a click on a node writes the constraint line that makes ``synthesize`` use that node."""

import json
import re

import numpy as np
import pytest
from chromium_page import CHROMIUM, ChromiumPage
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.exports.isomap_page import mid_time
from facesynth.domain.search.constraint_choice import time_correct_offset
from facesynth.domain.search.constraints import read_constraints
from facesynth.domain.speech.utterance import read_utterance
from facesynth.formats.labels import Segment, read_phone_segments, write_textgrid
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import suggest

needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")


def _cli(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.fixture(scope="module")
def made(tiny_db, spliced_sentence, tmp_path_factory):
    """The isomap, a spliced sentence, its synthesized motion and its constraint page."""
    d = tmp_path_factory.mktemp("isoconstraints")
    tg, _ = spliced_sentence
    for args in (["isomap", "build", tiny_db, "-o", d / "iso.h5"],
                 ["synthesize", tiny_db, "--phonemes", tg, "-o", d / "motion.h5"],
                 ["isomap", "page", d / "iso.h5", tiny_db, "--phonemes", tg, "--motion", d / "motion.h5", "-o", d / "page.html"]):
        r = _cli(*args)
        assert r.exit_code == 0, r.output
    return {"dir": d, "db": tiny_db, "tg": tg, "iso": d / "iso.h5", "motion": d / "motion.h5", "page": d / "page.html"}


class Browser(ChromiumPage):
    """The page in headless Chromium, with the constraint GUI's clicks and state."""

    def __init__(self, url: str, profile):
        super().__init__(url, profile, 1300, 1000)

    def js(self, expression: str):
        return self.evaluate(expression)

    def click(self, x: float, y: float) -> None:
        """A real mouse click at page coordinates (CSS pixels)."""
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left", clickCount=1)

    def state(self) -> dict:
        return self.js("Object.assign({}, document.getElementById('mapbox').dataset, "
                       "{errors: document.body.dataset.errors, box: document.getElementById('constraints').value})")


@pytest.fixture
def browser(made, tmp_path):
    pytest.importorskip("websockets", reason="the DevTools protocol client needs the websockets package")
    if CHROMIUM is None:
        pytest.skip("headless Chromium (Debian package 'chromium') is not installed")
    b = Browser(made["page"].as_uri(), tmp_path / "profile")
    yield b
    b.close()


def _expected(tiny_db, tg, text: str):
    """What ``facesynth suggest`` says at the time written as ``text``: the step, the
    context-correct nodes and every node's time-correct frame in its take."""
    from facesynth.base.config import Config

    config = Config.load()
    found = suggest.suggest(tiny_db, tg, float(text), config.settings("synthesize"), config.settings("ingest")).suggestions
    return (found.index, " ".join(str(n) for n in sorted(r.node for r in found.rows if r.context_correct)),
            {r.node: r.time_correct_frame for r in found.rows})


def _time_correct(state: dict) -> dict[int, int]:
    return {int(a): int(b) for a, b in (item.split(":") for item in state["timeCorrect"].split())}


def test_time_correct_frames_span_the_node():
    counts = np.array([1, 2, 5, 12])
    assert time_correct_offset(0.0, counts).tolist() == [0, 0, 0, 0]
    assert time_correct_offset(1.0, counts).tolist() == [0, 1, 4, 11]
    assert time_correct_offset(0.5, counts).tolist() == [0, 1, 2, 6]  # 5.5 rounds up, as floor(x + 0.5) does
    assert time_correct_offset(0.24, 5).item() == 1 and time_correct_offset(0.26, 5).item() == 1


@needs_chromium
def test_page_highlights_what_suggest_lists(made, browser, tiny_db):
    utt = read_utterance(made["tg"])
    search, _ = Motion.read_search(made["motion"])
    spoken = [c for c, p in enumerate(utt.phones) if p != "pau"]
    checked_context = 0
    for c in spoken:
        s, e = float(utt.starts[c]), float(utt.ends[c])
        for frac in (0.5, 0.13, 0.87):  # the mid time and times off it: the time-correct frames move
            text = f"{s + frac * (e - s):.3f}"
            browser.js(f"facesynthSelect({text!r})")
            state = browser.state()
            step, context, frames = _expected(tiny_db, made["tg"], text)
            assert int(state["step"]) == step == c and state["phone"] == utt.phones[c] and state["time"] == text
            assert state["contextCorrect"] == context
            assert _time_correct(state) == frames
            # the path's node is marked, on its own time-correct frame
            assert int(state["chosenNode"]) == int(search.node[c])
            marked = browser.js("Array.from(document.querySelectorAll('#marks circle.chosen')).map(e => e.dataset.node)")
            assert marked == [str(int(search.node[c]))]
            highlighted = browser.js("Array.from(document.querySelectorAll('#marks circle.cc')).map(e => +e.dataset.node)")
            assert sorted(highlighted) == [int(n) for n in context.split()]
            checked_context += bool(context)
    assert checked_context >= 3  # the spliced sentence's inner phones share their training triphones
    assert browser.state()["errors"] == "0"


@needs_chromium
def test_a_phone_picked_from_the_list_or_the_timeline(made, browser):
    utt = read_utterance(made["tg"])
    c = [k for k, p in enumerate(utt.phones) if p != "pau"][2]
    browser.js(f"var l=document.getElementById('phones'); l.value='{c}'; l.dispatchEvent(new Event('change'))")
    state = browser.state()
    assert int(state["step"]) == c and float(state["time"]) == pytest.approx(0.5 * (utt.starts[c] + utt.ends[c]), abs=6e-4)
    # a click on the timeline at a quarter of the next phone picks that phone at that time
    d = c + 1
    x, y, w = browser.js(f"(function(){{var r=document.querySelector('#timeline .seg[data-step=\"{d}\"]').getBoundingClientRect();"
                         "return [r.left, r.top + r.height / 2, r.width];})()")
    browser.click(x + 0.25 * w, y)
    state = browser.state()
    assert int(state["step"]) == d and state["phone"] == utt.phones[d]
    assert float(state["time"]) == pytest.approx(utt.starts[d] + 0.25 * (utt.ends[d] - utt.starts[d]), abs=0.002)
    assert float(state["relativeTime"]) == pytest.approx(0.25, abs=0.05)


def _marker_positions(browser) -> list[tuple[int, str, float, float]]:
    """Every node marker of the shown map: node, class, page x, page y."""
    return browser.js("(function(){var r=document.getElementById('marks').getBoundingClientRect();"
                      "return Array.from(document.querySelectorAll('#marks circle.tc, #marks circle.cc')).map(e => "
                      "[+e.dataset.node, e.getAttribute('class'), r.left + +e.getAttribute('cx'), r.top + +e.getAttribute('cy')]);})()")


def _clear_node(markers, want: str, avoid: int):
    """A node of class ``want`` (not ``avoid``) whose marker lies at least 3 pixels from every other."""
    for node, cls, x, y in markers:
        if cls == want and node != avoid and all(np.hypot(x - a, y - b) >= 3 for n, _, a, b in markers if n != node):
            return node, x, y
    return None


@needs_chromium
def test_a_click_on_a_node_writes_the_constraint_synthesize_follows(made, browser, tiny_db, tmp_path):
    utt = read_utterance(made["tg"])
    search, _ = Motion.read_search(made["motion"])
    db = MotionDatabase.read(tiny_db)
    for c in (k for k, p in enumerate(utt.phones) if p != "pau"):
        text = f"{utt.starts[c] + 0.4 * (utt.ends[c] - utt.starts[c]):.3f}"
        browser.js(f"facesynthSelect({text!r})")
        pick = _clear_node(_marker_positions(browser), "cc", int(search.node[c]))
        if pick is not None:
            break
    else:
        pytest.fail("no context-correct node other than the path's, clear of the others, on any phone")
    node, x, y = pick
    browser.click(x, y)
    state = browser.state()
    assert state["box"] == f"{text}s {node}\n" and int(state["constrainedNode"]) == node
    # the constrained node is ringed; a second click on another node of the phone replaces the line
    assert browser.js("Array.from(document.querySelectorAll('#marks circle.constrained')).map(e => +e.dataset.node)") == [node]
    other = _clear_node(_marker_positions(browser), "tc", node) or _clear_node(_marker_positions(browser), "cc", node)
    if other is not None:
        browser.click(other[1], other[2])
        assert browser.state()["box"] == f"{text}s {other[0]}\n"
        browser.click(x, y)
        assert browser.state()["box"] == f"{text}s {node}\n"
    # synthesize's parser reads the line as this phone and node, and the search then uses it
    line = tmp_path / "constraints.txt"
    line.write_text(state["box"])
    assert read_constraints(line, utt, db.nodes.phone) == {c: node}
    r = _cli("synthesize", tiny_db, "--phonemes", made["tg"], "--constraints", line, "-o", tmp_path / "m.h5")
    assert r.exit_code == 0, r.output
    constrained, _ = Motion.read_search(tmp_path / "m.h5")
    assert int(constrained.node[c]) == node != int(search.node[c])
    # the page made with those constraints starts with them in its box and rings the node
    r = _cli("isomap", "page", made["iso"], tiny_db, "--phonemes", made["tg"], "--constraints", line,
             "--motion", tmp_path / "m.h5", "-o", tmp_path / "again.html")
    assert r.exit_code == 0, r.output
    again = Browser((tmp_path / "again.html").as_uri() + f"#t={text}", tmp_path / "profile2")
    try:
        state = again.state()
        assert state["box"] == f"{mid_time(utt, c):.3f}s {node}\n"  # the constraints given, as TIMEs NODE lines
        assert int(state["step"]) == c and int(state["constrainedNode"]) == node == int(state["chosenNode"])
    finally:
        again.close()


def test_page_is_self_contained(made):
    text = made["page"].read_text()
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", text)
    assert "data:image/png;base64," in text and 'id="pagedata"' in text
    again = made["dir"] / "again.html"  # deterministic: the same inputs give the same page
    r = _cli("isomap", "page", made["iso"], made["db"], "--phonemes", made["tg"], "--motion", made["motion"], "-o", again)
    assert r.exit_code == 0 and again.read_bytes() == made["page"].read_bytes()


def _one_sentence(r) -> str:
    assert r.exit_code == 1, r.output
    lines = r.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and "Traceback" not in r.output, r.output
    return lines[0]


def test_phones_the_database_lacks(made, tiny_db, tmp_path):
    db = MotionDatabase.read(tiny_db)
    absent = [p for p in ("zh", "oy", "uh", "ch", "jh", "th") if p not in db.nodes.phone][:2]
    assert absent, "the tiny database holds every phone tried"
    tg = tmp_path / "absent.TextGrid"
    write_textgrid(tg, {"phones": [Segment(0.0, 0.1, "pau"), Segment(0.1, 0.25, absent[0]),
                                   Segment(0.25, 0.4, absent[-1]), Segment(0.4, 0.5, "pau")]})
    out = tmp_path / "p.html"
    line = _one_sentence(_cli("isomap", "page", made["iso"], tiny_db, "--phonemes", tg, "-o", out))
    assert str(tg) in line and f"/{absent[0]}/" in line and "no node of any of its phones" in line
    assert not out.exists()
    # one present phone is enough: the others are shown as unconstrainable, with a warning
    present = next(p for p in db.nodes.phone if p != "pau")
    write_textgrid(tg, {"phones": [Segment(0.0, 0.1, "pau"), Segment(0.1, 0.25, absent[0]),
                                   Segment(0.25, 0.4, present), Segment(0.4, 0.5, "pau")]})
    r = _cli("isomap", "page", made["iso"], tiny_db, "--phonemes", tg, "-o", out)
    assert r.exit_code == 0 and f"warning: the database has no node of /{absent[0]}/" in r.output and out.exists()


def test_a_motion_or_isomap_of_another_database(made, tiny_db, tmp_path):
    other = tmp_path / "other.h5"
    r = _cli("prune", tiny_db, "--remove", "0-2", "-o", other)
    assert r.exit_code == 0, r.output
    r = _cli("synthesize", other, "--phonemes", made["tg"], "-o", tmp_path / "m.h5")
    assert r.exit_code == 0, r.output
    out = tmp_path / "p.html"
    line = _one_sentence(_cli("isomap", "page", made["iso"], tiny_db, "--phonemes", made["tg"],
                              "--motion", tmp_path / "m.h5", "-o", out))
    assert f"{tmp_path / 'm.h5'}: was synthesized from another database" in line and str(other) in line
    line = _one_sentence(_cli("isomap", "page", made["iso"], other, "--phonemes", made["tg"], "-o", out))
    assert f"{made['iso']}: was built from another database" in line and "isomap build" in line
    # a motion of another utterance (the same phones but the last) of the same database
    held = tmp_path / "held.TextGrid"
    segs = read_phone_segments(made["tg"])
    write_textgrid(held, {"phones": segs[:-2] + [Segment(segs[-2].start, segs[-1].end, "pau")]})
    line = _one_sentence(_cli("isomap", "page", made["iso"], tiny_db, "--phonemes", held,
                              "--motion", made["motion"], "-o", out))
    assert "was synthesized for another utterance" in line
    assert not out.exists()


def test_emotions_travel_to_the_page_and_a_differing_motion_is_warned_about(made, tiny_db, tmp_path):
    spans = tmp_path / "emotions.txt"
    spans.write_text("0 1000 happy\n")
    out = tmp_path / "p.html"
    r = _cli("isomap", "page", made["iso"], tiny_db, "--phonemes", made["tg"], "--emotions", spans,
             "--motion", made["motion"], "-o", out)
    assert r.exit_code == 0, r.output
    assert f"warning: {made['motion']} was synthesized with other emotions than the page's" in r.output
    data = json.loads(re.search(r'id="pagedata">(.*?)</script>', out.read_text(), re.S).group(1))
    assert {s["emotion"] for s in data["steps"]} == {"happy"}
    assert data["command"].endswith(f"--emotions {spans} --constraints constraints.txt -o constrained.h5")
