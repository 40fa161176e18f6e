"""Numba kernels of the sample corpus's recurrences: the same float64 operations in the same order
as the plain NumPy loop and ``scipy.signal.lfilter`` calls they stand for, bit for bit, so a
corpus's bytes do not depend on which computes them.

* :func:`damped_response`: the critically damped articulators of
  :func:`facesynth.domain.corpus.actress_mouth.critically_damped` (semi-implicit Euler substeps);
* :func:`section_cascade`: ``scipy.signal.lfilter`` through a cascade of second-order sections
  run block by block, each section's state carried from one block to the next (``zi``/``zf``),
  with coefficients that change per block (the formant resonators of
  :func:`facesynth.domain.corpus.speech.synthesize_audio`).

Why identical: every value is a float64 ``+ - *`` grouped as in those loops (``a * b * c`` is
``(a * b) * c``), and numba compiles without ``fastmath``, so LLVM neither fuses
multiply-adds nor reorders. lfilter's double loop (transposed direct form II, coefficients
divided by ``a[0]`` once, the numerator padded with zeros to the denominator's length) computes,
per sample ``x``, ``y = z0 + b0 * x``, ``z0 = (z1 + x * b1) - y * a1``, ``z1 = x * b2 - y * a2``;
the kernel takes the coefficients already divided by ``a[0]`` (exactly, where ``a[0]`` is 1) and
keeps the zero numerator terms, which are not free to drop (``x * 0.0`` is -0.0 for a negative
``x``, and ``-0.0 + 0.0`` is +0.0). tests/corpus/test_bit_exact.py compares both kernels with
those loops.

Serial on purpose: each is one recurrence in time, over a few channels.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.jit import jit


@jit()
def damped_response(inputs, omega, dt, substeps, out):
    """Critically damped second-order systems ``x'' = w^2 (u - x) - 2 w x'`` at rest at the first
    input, ``substeps`` semi-implicit Euler steps of ``dt`` seconds per frame.

    inputs : (T, C) float64 piecewise-constant inputs u per frame; omega : (T, C) float64
    natural frequencies (rad/s); out : (T, C) float64, filled with x at the end of each frame.
    """
    n_frames, n_channels = inputs.shape
    for c in range(n_channels):
        x = inputs[0, c]
        v = 0.0
        for t in range(n_frames):
            u = inputs[t, c]
            w = omega[t, c]
            for _ in range(substeps):
                v = v + dt * (w * w * (u - x) - 2.0 * w * v)
                x = x + dt * v
            out[t, c] = x


@jit()
def section_cascade(signal, block, numerators, denominators, out):
    """``signal`` through S second-order sections in series, block by block: block j (samples
    ``j * block`` to ``(j + 1) * block``, the last one shorter) through the coefficients of row j,
    every section starting at rest and keeping its state across blocks.

    signal : (n,) float64; block : samples per block; numerators, denominators : (n_blocks, S, 3)
    float64, each section's ``b`` and ``a`` divided by its ``a[0]``; out : (n,) float64, the last
    section's output.
    """
    n_sections = numerators.shape[1]
    state = np.zeros((n_sections, 2))
    for i in range(signal.shape[0]):
        j = i // block
        y = signal[i]
        for s in range(n_sections):
            x = y
            b = numerators[j, s]
            a = denominators[j, s]
            y = state[s, 0] + b[0] * x
            state[s, 0] = state[s, 1] + x * b[1] - y * a[1]
            state[s, 1] = x * b[2] - y * a[2]
        out[i] = y
