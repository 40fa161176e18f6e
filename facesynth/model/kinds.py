"""The artifact kinds: each kind's schema, the commands that make it and the version of the
group encodings. The data every layer above the formats reads (:mod:`facesynth.artifacts`,
:mod:`facesynth.check`, :mod:`facesynth.model.spec`); it imports nothing of facesynth.
"""

#: Current schema of each artifact kind; bumped on an incompatible change.
SCHEMAS: dict[str, int] = {
    "corpus": 1,
    "normalized": 1,
    "pca": 1,
    "motiondb": 2,  # 2: per-node transition features instead of (N, N) pair tables
    "isomap": 1,
    "motion": 1,
    "meshanim": 1,
    "expression": 1,
    "headmotion": 1,
    "curves": 1,
    "keyshapes": 1,
    "trajectory": 1,
}

#: Which stage makes each kind (used in messages that say what to do).
PRODUCERS: dict[str, str] = {
    "corpus": "facesynth ingest",
    "normalized": "facesynth normalize",
    "pca": "facesynth pca",
    "motiondb": "facesynth build-db",
    "isomap": "facesynth isomap",
    "motion": "facesynth synthesize",
    "meshanim": "facesynth deform",
    "expression": "facesynth expression fit",
    "headmotion": "facesynth head-motion",
    "curves": "facesynth solve",
    "keyshapes": "facesynth keyshapes",
    "trajectory": "facesynth train-trajectory",
}

#: Version of each group encoding (the ``encoding-type`` attribute names the group's layout,
#: ``encoding-version`` this number); bumped when a group's layout changes incompatibly.
ENCODING_VERSION = "1"
