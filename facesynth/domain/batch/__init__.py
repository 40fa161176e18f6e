"""The Dask batch runner of ``facesynth batch``: a script of dialogue lines (audio, text or
alignment, emotion) -> per-line motion, mesh animation and video, plus a summary.

- :mod:`.script` reads and checks the script (a malformed one is refused before any work);
- :mod:`.job` checks the whole request before any work and makes the job every line carries;
- :mod:`.line` does one line in a worker process (database cached per worker, resumable,
  atomic outputs, failures turned into reasons);
- :mod:`.runner` creates the Dask client in one place (a ``LocalCluster`` of processes by
  default, or an existing scheduler) and gathers the results with a progress bar;
- :mod:`.report` writes the summary (CSV and HTML).
"""
