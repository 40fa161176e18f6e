"""facesynth: expressive speech animation synthesis from a facial motion-capture database.

The method follows Deng & Neumann (2008), "Expressive Speech Animation Synthesis with
Phoneme-Level Controls". Each pipeline stage lives in :mod:`facesynth.stages` and reads and
writes one stamped HDF5 artifact (see ``docs/file-format.md``).

The public Python API (``docs/api.md``) is :mod:`facesynth.api`, whose names this package
offers too (``facesynth.synthesize``, ...). They are looked up by name on first use, as the
registries name their members (:mod:`facesynth.base.registry`), so that ``import facesynth`` (which
the command line does) stays cheap and this package, the bottom layer, imports nothing above it.
``__init__.pyi`` gives type checkers the same names with their types.
"""

import importlib

__version__ = "0.1.0"

#: The names of :mod:`facesynth.api`, offered here (``facesynth.api.__all__`` is the same list).
_API = (
    "Config", "load_config",
    "read_database", "read_model", "read_motion", "read_curves", "read_rig",
    "Utterance", "utterance_from_phones", "utterance_from_audio",
    "methods", "synthesize", "solve", "export_formats", "export",
    "MotionDatabase", "TrajectoryModel", "CoarticulationModel", "Motion", "RigCurves", "MeshAnimation", "Rig",
    "HeadMotion", "Alignment",
    "FacesynthError", "InputError", "UsageError", "ArtifactError", "ConfigError", "SearchError", "OutputExistsError",
)

__all__ = ["__version__", *_API]


def __getattr__(name: str):
    """A name of the API, from :mod:`facesynth.api` (imported on the first such use)."""
    if name in _API:
        value = getattr(importlib.import_module("facesynth.api"), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'facesynth' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API))
