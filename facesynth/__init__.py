"""facesynth: expressive speech animation synthesis from a facial motion-capture database.

The method follows Deng & Neumann (2008), "Expressive Speech Animation Synthesis with
Phoneme-Level Controls". Each pipeline stage lives in :mod:`facesynth.stages` and reads and
writes one stamped HDF5 artifact (see ``docs/file-format.md``).
"""

__version__ = "0.1.0"
