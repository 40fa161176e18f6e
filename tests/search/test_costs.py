import numpy as np
import pytest

from facesynth.config import Config
from facesynth.search.costs import step_costs, transition_matrix


@pytest.fixture()
def s():
    return Config.load(None, ("synthesize.pnt=10", "synthesize.alpha1=2", "synthesize.alpha2=0.5", "synthesize.alpha3=3",
                              "synthesize.alpha4=0.5", "synthesize.alpha5=4", "synthesize.alpha6=6")).settings("synthesize")


def test_transition_rules_of_table_i(s):
    # nodes: 0 /p/, 1 /b/ (captured predecessor 0), 2 /aa/ (predecessor 1), 3 /m/ (no predecessor)
    vis = np.array([12, 12, 3, 12])
    pre = np.array([-1, 0, 1, -1])
    dsc = np.full((4, 4), 2.0, np.float32)
    pgap = np.full((4, 4), 1.0, np.float32)
    vgap = np.full((4, 4), 0.25, np.float32)
    tc = transition_matrix(dsc, pgap, vgap, vis, pre, s)
    assert tc[0, 1] == 0.0 and tc[1, 2] == 0.0                         # rule 1: captured
    assert tc[3, 1] == pytest.approx(0.5 * 2 + 3 * 1 + 0.25)           # rule 2: same viseme as pre(o_1) = /p/
    assert tc[2, 1] == pytest.approx(0.5 * 2 + 3 * 1 + 0.25 + 10)      # rule 3: /aa/ vs /p/ adds PNT
    assert tc[:, 3].tolist() == [20.0] * 4 and tc[:, 0].tolist() == [20.0] * 4  # rule 4: alpha1 * PNT


def test_observation_emotion_and_blocking(s):
    c = step_costs(["p", "pau", "aa"], ["happy", "sad", "happy"], ["p", "b", "aa", "sh"], ["happy", "sad", "sad", "happy"],
                   {2: 2}, s)
    assert c.oc[0].tolist() == [0.0, 0.5 * 4 * 10, 4 * 10, 4 * 10]      # Table II rules 1, 2, 3
    assert c.oc[1].tolist() == [0.0] * 4                                  # /pau/ costs nothing
    assert c.emp[0].tolist() == [0.0, 60.0, 60.0, 0.0]                    # Eq. 5
    assert c.block[2].tolist() == [s.huge_penalty, s.huge_penalty, 0.0, s.huge_penalty]  # Eq. 10
    assert c.block[:2].max() == 0.0
