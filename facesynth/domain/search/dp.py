"""The dynamic program of paper Algorithm 1, as a NumPy reference and on OpenCL.

Both compute ``phi_t(j) = min_i(phi_{t-1}(i) + TC(i, j)) + obs_t(j)`` in float32 with the
same additions, so they give bit-identical costs; the path is recovered afterwards by
recomputing each step's argmin along the optimal path only (lowest index on ties), which
is why the OpenCL kernel keeps no backpointers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from facesynth.base.opencl import aligned_empty, context, host_aligned, kernel, max_alloc_bytes, queue

#: Columns per panel of the panel-major TC matrix (a multiple of 8: the kernel reads float8s).
#: The one source of this size: ``kernels/dp_min_plus.cl`` is built with ``-DPANEL=<this>``.
PANEL = 96


@dataclass
class DpResult:
    """What the DP returns: COST* (Algorithm 1 line 10), the path ((T,) node per step) and the
    accumulated costs phi ((T, N) float32).
    """

    cost: float            # COST* of Algorithm 1 line 10
    path: np.ndarray       # (T,) node per step
    phi: np.ndarray        # (T, N) float32 accumulated costs


def backtrack(phi: np.ndarray, tc_column) -> np.ndarray:
    """Algorithm 1 lines 11-14 with chi recomputed: ``tc_column(j)`` returns TC[:, j]."""
    t_count = len(phi)
    path = np.empty(t_count, np.int64)
    path[-1] = int(np.argmin(phi[-1]))
    for t in range(t_count - 1, 0, -1):
        path[t - 1] = int(np.argmin(phi[t - 1] + tc_column(path[t])))
    return path


def dp_numpy(tc: np.ndarray, obs: np.ndarray, column_block: int = 512) -> DpResult:
    """Reference DP. tc : (N, N) float32; obs : (T, N) float32 (OC + EMP + B per step)."""
    tc = np.asarray(tc, np.float32)
    obs = np.asarray(obs, np.float32)
    t_count, n = obs.shape
    phi = np.empty((t_count, n), np.float32)
    phi[0] = obs[0]
    for t in range(1, t_count):
        prev = phi[t - 1][:, None]
        for a in range(0, n, column_block):
            phi[t, a : a + column_block] = (prev + tc[:, a : a + column_block]).min(axis=0)
        phi[t] += obs[t]
    path = backtrack(phi, lambda j: tc[:, j])
    return DpResult(float(phi[-1, path[-1]]), path, phi)


class PanelMatrix:
    """An (N, N) float32 cost matrix stored panel-major: ``panels[p, i, c]`` is
    ``TC[i, p * PANEL + c]``; columns past N are +inf. Rows can be filled block by block."""

    def __init__(self, n: int, panel: int = PANEL):

        self.n, self.panel = n, panel
        # page-aligned: the OpenCL DP reads it in place (USE_HOST_PTR) as float8s
        self.panels = aligned_empty((-(-n // panel), n, panel), np.float32)
        self.panels[-1, :, n - (len(self.panels) - 1) * panel :] = np.inf

    @classmethod
    def from_matrix(cls, tc: np.ndarray, panel: int = PANEL) -> "PanelMatrix":
        """The panel-major copy of a dense (N, N) matrix."""
        out = cls(tc.shape[0], panel)
        for a in range(0, out.n, 2048):
            out.set_rows(slice(a, min(out.n, a + 2048)), tc[a : a + 2048])
        return out

    def set_rows(self, rows: slice, values: np.ndarray) -> None:
        """Write rows ``rows`` (values (r, N))."""
        n, panel = self.n, self.panel
        full = n // panel
        if full:
            self.panels[:full, rows] = values[:, : full * panel].reshape(len(values), full, panel).transpose(1, 0, 2)
        if full < len(self.panels):
            self.panels[full, rows, : n - full * panel] = values[:, full * panel :]

    def column(self, j: int) -> np.ndarray:
        """TC[:, j], (N,) float32."""
        return self.panels[j // self.panel, :, j % self.panel]

    def __getitem__(self, ij: tuple[int, int]) -> np.float32:
        i, j = ij
        return self.panels[j // self.panel, i, j % self.panel]


def dp_bounded(tc: np.ndarray, obs: np.ndarray, upper: float) -> tuple[DpResult, np.ndarray]:
    """The reference DP pruned by an upper bound on the optimal cost (e.g. greedy's path
    cost under Eq. 4): a state whose accumulated cost plus the least possible remaining cost
    (the sum of each later step's smallest observation cost; TC >= 0) exceeds ``upper`` can
    lie on no optimal path, so its row of TC is not read. Exact: same cost and path as
    :func:`dp_numpy` whenever ``upper`` >= the optimum. Returns the result and the fraction
    of states kept active at each step."""
    tc = np.asarray(tc, np.float32)
    obs = np.asarray(obs, np.float32)
    t_count, n = obs.shape
    remaining = np.concatenate([np.cumsum(obs.min(axis=1)[::-1], dtype=np.float64)[::-1][1:], [0.0]])
    phi = np.full((t_count, n), np.inf, np.float32)
    phi[0] = obs[0]
    active_fraction = np.ones(t_count)
    for t in range(1, t_count):
        active = np.nonzero(phi[t - 1].astype(np.float64) + remaining[t - 1] <= upper)[0]
        active_fraction[t - 1] = len(active) / n
        phi[t] = (phi[t - 1][active][:, None] + tc[active]).min(axis=0) + obs[t]
    path = backtrack(phi, lambda j: tc[:, j])
    return DpResult(float(phi[-1, path[-1]]), path, phi), active_fraction


def to_panels(tc: np.ndarray, panel: int = PANEL) -> np.ndarray:
    """Panel-major copy of TC: (n_panels, N, panel), columns padded with +inf."""
    return PanelMatrix.from_matrix(tc, panel).panels


class OpenCLDp:
    """The DP on the OpenCL device chosen by ``PYOPENCL_CTX``.

    The panel-major cost matrix is uploaded once (split into buffers below the device's
    ``max_mem_alloc_size``); each step launches one work-item per column panel per buffer.
    """

    def __init__(self, tc: "np.ndarray | PanelMatrix"):
        import pyopencl as cl

        self.ctx, self.queue = context(), queue()
        self.kernel = kernel("dp_min_plus", "min_plus_panels", PANEL=PANEL)
        self.tc = tc if isinstance(tc, PanelMatrix) else PanelMatrix.from_matrix(tc)
        self.n = self.tc.n
        panels = self.tc.panels
        self.n_panels = panels.shape[0]
        per_panel = panels[0].nbytes
        per_buffer = max(1, min(self.n_panels, (min(max_alloc_bytes(), 1 << 30) // per_panel)))
        mf = cl.mem_flags
        self.groups = []
        for first in range(0, self.n_panels, per_buffer):
            count = min(per_buffer, self.n_panels - first)
            # USE_HOST_PTR: a CPU device reads the host array in place, no second copy. The kernel
            # reads float8s, so the host memory must be aligned: a PanelMatrix is; any other
            # array (a view at an odd offset) is copied into aligned memory first.
            host = host_aligned(panels[first : first + count])
            buf = cl.Buffer(self.ctx, mf.READ_ONLY | mf.USE_HOST_PTR, hostbuf=host)
            self.groups.append((first, count, buf, host))
        self.cols = self.n_panels * PANEL

    def run(self, obs: np.ndarray, while_running: Callable[[], None] | None = None) -> DpResult:
        """The DP for observation costs ``obs`` ((T, N) float32) on the device. ``while_running``,
        if given, is called on this thread once every step is queued and before waiting for the
        device: host work that overlaps the search (a CPU device runs the kernels on its own threads)."""
        import pyopencl as cl

        t_count, n = obs.shape
        mf = cl.mem_flags
        obs_padded = np.zeros((t_count, self.cols), np.float32)
        obs_padded[:, :n] = obs
        obs_buf = cl.Buffer(self.ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=obs_padded)
        # Every step's phi stays on the device and is read back once at the end: a read after
        # each step would make the host wait for that step, so nothing could overlap the search.
        phi_buf = cl.Buffer(self.ctx, mf.READ_WRITE, obs_padded.nbytes)
        cl.enqueue_copy(self.queue, phi_buf, obs_padded[0])  # phi_0 = obs_0
        for t in range(1, t_count):
            src, obs_row, dst = self._row(phi_buf, t - 1), self._row(obs_buf, t), self._row(phi_buf, t)
            for first, count, buf, _ in self.groups:
                self.kernel(self.queue, (count,), None, buf, src, obs_row, dst,
                            np.int32(self.n), np.int32(first), np.int32(count))
        self.queue.flush()
        if while_running is not None:
            while_running()
        phi = np.empty((t_count, self.cols), np.float32)
        cl.enqueue_copy(self.queue, phi, phi_buf)  # blocking: waits for the last step
        phi = phi[:, :n]
        path = backtrack(phi, self.tc.column)
        return DpResult(float(phi[-1, path[-1]]), path, phi)

    def _row(self, buffer, t):
        """Row t of a (T, cols) float32 buffer, as a sub-buffer."""
        return buffer.get_sub_region(4 * t * self.cols, 4 * self.cols)


def dp_opencl(tc: "np.ndarray | PanelMatrix", obs: np.ndarray, while_running: Callable[[], None] | None = None) -> DpResult:
    """Algorithm 1 on OpenCL for ``tc`` ((N, N) float32 or a PanelMatrix) and ``obs`` ((T, N) float32);
    bit-identical to :func:`dp_numpy`. ``while_running`` as for :meth:`OpenCLDp.run`.
    """
    return OpenCLDp(tc).run(obs, while_running)
