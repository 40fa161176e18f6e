"""Seeded random per-node transition features for the search tests."""

import numpy as np

from facesynth.model.motiondb import TransitionFeatures


def random_features(n: int, seed: int, markers: int = 7, dims: int = 12, duplicates: int = 0) -> TransitionFeatures:
    """Seeded random features of ``n`` nodes in captured runs of 1-5, with ``duplicates`` nodes
    copied from others (so that pair costs tie exactly)."""
    rng = np.random.default_rng(seed)
    pre = -np.ones(n, np.int64)
    k = 0
    while k < n:
        run = int(rng.integers(1, 6))
        pre[k + 1 : k + run] = np.arange(k, min(n, k + run) - 1)
        k += run
    arrays = [rng.normal(0, s, (n, 3 * markers)).astype(np.float32) for s in (5, 5, 1, 1)]
    x = rng.normal(0, 1, (n, dims)).astype(np.float32)
    y = rng.normal(0, 1, (n, dims)).astype(np.float32)
    scale = rng.uniform(0.1, 3, n).astype(np.float32)
    viseme = rng.integers(0, 4, n)
    for _ in range(duplicates):
        src, dst = int(rng.integers(n)), int(rng.integers(n))
        for a in arrays + [x]:
            a[dst] = a[src]
        viseme[dst] = viseme[src]
    y[pre < 0] = 0.0
    scale[pre < 0] = 0.0
    return TransitionFeatures(*arrays, x, y, scale, viseme, pre)


def tiny_utterance_steps(db, s, textgrid, with_emotions: bool, with_constraints: bool):
    """The step costs of the utterance ``textgrid`` over the database ``db`` (a MotionDatabase)
    for settings ``s``: per-phone emotions cycling through angry, sad and happy when
    ``with_emotions``, and with ``with_constraints`` up to three phones constrained to a node
    of their own phone. Returns (StepCosts, constraints {step: node})."""
    from facesynth.domain.search.costs import step_costs
    from facesynth.domain.speech.utterance import read_utterance

    utt = read_utterance(textgrid)
    if with_emotions:
        utt.emotions = [("angry", "sad", "happy")[k % 3] for k in range(len(utt))]
    constraints = {}
    if with_constraints:
        for t, p in enumerate(utt.phones):
            nodes = [j for j, q in enumerate(db.nodes.phone) if q == p]
            if nodes and len(constraints) < 3:
                constraints[t] = nodes[len(nodes) // 2]
        assert constraints
    return step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, constraints, s), constraints
