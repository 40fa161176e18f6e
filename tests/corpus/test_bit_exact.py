"""The corpus's fast paths give the same bits as the plain loops they stand for, so a corpus's
bytes do not depend on them (the numba kernels, the rotations of all frames at once, the truth's
number text)."""

import numpy as np
from scipy.signal import lfilter

from facesynth.domain.corpus.actress_mouth import critically_damped
from facesynth.domain.corpus.recurrences_numba import section_cascade
from facesynth.domain.corpus.speech import _euler
from facesynth.domain.corpus.truth import _number_rows


def _same_bits(a, b):
    return a.shape == b.shape and a.dtype == b.dtype and np.array_equal(a.view(np.uint8), b.view(np.uint8))


def test_the_damped_articulators_step_as_the_numpy_loop():
    rng = np.random.default_rng(0)
    inputs = np.repeat(rng.uniform(0, 1, (40, 5)), 7, axis=0)      # piecewise constant, (280, 5)
    omega = 2 * np.pi * rng.uniform(3, 8, (280, 5))
    dt = 1.0 / (120.0 * 4)
    x, v, expected = inputs[0].copy(), np.zeros(5), np.empty_like(inputs)
    for t in range(len(inputs)):
        u, w = inputs[t], omega[t]
        for _ in range(4):
            v += dt * (w * w * (u - x) - 2.0 * w * v)
            x += dt * v
        expected[t] = x
    assert _same_bits(critically_damped(inputs, omega, 120.0), expected)
    assert _same_bits(critically_damped(inputs, omega[0], 120.0)[:, :1],
                      critically_damped(inputs[:, :1], omega[0, :1], 120.0))


def test_the_resonator_cascade_filters_as_lfilter_block_by_block():
    rng = np.random.default_rng(1)
    signal = rng.normal(size=1000)
    signal[100:140] = 0.0
    block, n_blocks = 80, 13                                          # the last block is 40 samples
    r = np.exp(-np.pi * rng.uniform(60, 140, (n_blocks, 3)) / 16000)
    a = np.stack([np.ones_like(r), -2 * r * np.cos(rng.uniform(0.05, 2.0, (n_blocks, 3))), r * r], axis=2)
    b = np.zeros_like(a)
    b[..., 0] = a.sum(axis=2)
    expected = np.empty_like(signal)
    states = [np.zeros(2) for _ in range(3)]
    for j, s in enumerate(range(0, len(signal), block)):
        y = signal[s:s + block]
        for k in range(3):
            y, states[k] = lfilter(b[j, k, :1], a[j, k], y, zi=states[k])
        expected[s:s + block] = y
    out = np.zeros_like(signal)
    section_cascade(signal, block, b, a, out)
    assert _same_bits(out, expected)


def test_the_rotations_are_those_of_one_frame_at_a_time():
    rng = np.random.default_rng(2)
    nod, yaw, roll = rng.normal(0, 0.05, (3, 300))

    def one(x, y, z):
        rx = np.array([[1, 0, 0], [0, np.cos(x), -np.sin(x)], [0, np.sin(x), np.cos(x)]])
        ry = np.array([[np.cos(y), 0, np.sin(y)], [0, 1, 0], [-np.sin(y), 0, np.cos(y)]])
        rz = np.array([[np.cos(z), -np.sin(z), 0], [np.sin(z), np.cos(z), 0], [0, 0, 1]])
        return rz @ ry @ rx

    assert _same_bits(_euler(nod, yaw, roll), np.stack([one(x, y, z) for x, y, z in zip(nod, yaw, roll)]))


def test_the_truth_numbers_are_four_decimals_without_trailing_zeros():
    def number(v):
        text = f"{v:.4f}".rstrip("0").rstrip(".")
        return "0" if text in ("", "-0") else text

    rng = np.random.default_rng(3)
    values = np.concatenate([
        rng.uniform(-1e-4, 1e-4, 2000), rng.uniform(0, 1, 2000), np.round(rng.uniform(0, 1, 2000), 2),
        np.arange(2000) * 1e-4 + 0.5e-4,                              # halfway, as far as the binary value is
        [0.0, -0.0, 1.0, -1.0, 10.0, 100.5, -0.00005, 0.00005, 0.03125, 0.99995, 12345.6789, np.nan, np.inf]])
    rng.shuffle(values)
    values = values[: len(values) // 7 * 7].reshape(-1, 7)
    assert _number_rows(values) == [",".join(number(v) for v in row) for row in values]
