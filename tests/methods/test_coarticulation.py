"""The fitted Cohen-Massaro model recovers a dominance blend it could have made."""

import numpy as np

from facesynth.domain.methods.coarticulation import DominanceModel, fit_dominance, token_weights


def _sentences(model, rng, n=12, fps=120.0):
    out = []
    for _ in range(n):
        phones = ["pau"] + [str(p) for p in rng.choice(["a", "b", "c", "d"], 10)] + ["pau"]
        durations = rng.uniform(0.05, 0.15, len(phones))
        ends = np.cumsum(durations)
        starts = ends - durations
        n_frames = int(ends[-1] * fps)
        poses = model.predict(phones, starts, ends, n_frames, fps)
        out.append((phones, starts, ends, poses, np.ones(n_frames, bool)))
    return out


def test_weights_are_a_partition_of_unity():
    w = token_weights(np.array([0.0, 0.1, 0.2]), np.array([0.1, 0.2, 0.3]), np.array([1.0, 5.0, 1.0]),
                      np.array([20.0, 20.0, 200.0]), 40, 120.0)
    assert w.shape == (40, 3) and np.allclose(w.sum(axis=1), 1.0)
    assert w[18].argmax() == 1  # the strong middle phone rules its own centre


def test_fit_recovers_the_generating_model():
    rng = np.random.default_rng(0)
    truth = DominanceModel(("a", "b", "c", "d", "pau"), rng.normal(0, 5, (5, 3)), np.array([1.0, 4.0, 0.5, 1.0, 2.0]),
                           np.array([15.0, 40.0, 10.0, 25.0, 8.0]))
    train, test = _sentences(truth, rng), _sentences(truth, rng, n=4)
    fitted = fit_dominance(train, 120.0, max_iterations=200)
    for phones, starts, ends, poses, _ in test:
        predicted = fitted.predict(phones, starts, ends, len(poses), 120.0)
        assert np.sqrt(np.mean((predicted - poses) ** 2)) < 0.05 * np.sqrt(np.mean(poses**2))
    # and does better than its starting point, equal dominances
    start = fit_dominance(train, 120.0, max_iterations=1)
    phones, starts, ends, poses, _ = test[0]
    assert np.mean((fitted.predict(phones, starts, ends, len(poses), 120.0) - poses) ** 2) < \
        np.mean((start.predict(phones, starts, ends, len(poses), 120.0) - poses) ** 2)


def test_masked_frames_do_not_count_and_unseen_phones_get_the_mean():
    rng = np.random.default_rng(1)
    truth = DominanceModel(("a", "b", "pau"), rng.normal(0, 5, (3, 2)), np.ones(3), np.full(3, 20.0))
    train = _sentences(DominanceModel(("a", "b", "c", "d", "pau"), np.vstack([truth.targets[:2], np.zeros((2, 2)), truth.targets[2:]]),
                                      np.ones(5), np.full(5, 20.0)), rng)
    spoiled = []
    for phones, starts, ends, poses, mask in train:
        poses = poses.copy()
        poses[::7] += 1000.0  # contaminated frames, masked out
        mask = mask.copy()
        mask[::7] = False
        spoiled.append((phones, starts, ends, poses, mask))
    fitted = fit_dominance(spoiled, 120.0, max_iterations=100)
    assert np.abs(fitted.targets).max() < 50.0
    out = fitted.predict(["pau", "q", "pau"], np.array([0.0, 0.1, 0.2]), np.array([0.1, 0.2, 0.3]), 36, 120.0)
    assert out.shape == (36, 2) and np.isfinite(out).all()


def test_the_objective_gradient_matches_finite_differences(monkeypatch):
    from facesynth.domain.methods import coarticulation

    objectives = []
    minimize = coarticulation.minimize

    def recording(fun, x0, **options):
        objectives.append(fun)
        return minimize(fun, x0, **options)

    monkeypatch.setattr(coarticulation, "minimize", recording)
    rng = np.random.default_rng(3)
    truth = DominanceModel(("a", "b", "c", "d", "pau"), rng.normal(0, 5, (5, 3)), np.array([1.0, 4.0, 0.5, 1.0, 2.0]),
                           np.array([15.0, 40.0, 10.0, 25.0, 8.0]))
    fit_dominance(_sentences(truth, rng, n=4), 120.0, max_iterations=1)
    x = np.concatenate([rng.normal(0, 0.5, 5), np.log(rng.uniform(5, 50, 5))])
    _, gradient = objectives[0](x)
    step = 1e-6
    central = np.array([(objectives[0](x + e)[0] - objectives[0](x - e)[0]) / (2 * step) for e in np.eye(len(x)) * step])
    assert np.allclose(gradient, central, rtol=1e-4, atol=1e-9 * np.abs(gradient).max())
