"""The artifact kinds: each kind's schema, the commands that make it and the version of the
group encodings. The data every layer above the formats reads (:mod:`facesynth.model.artifacts`,
:mod:`facesynth.model.check`, :mod:`facesynth.model.spec`); it imports only the stage declarations
(:mod:`facesynth.base.pipeline`, standard library only), whose outputs name the commands that make each kind.
"""

from facesynth.base.pipeline import producers

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
    "coarticulation": 1,
}

#: The commands that write each kind, for messages that say what to do ("pass the output of
#: `facesynth synthesize`, ... or `facesynth capture`"), from the declarations in facesynth.base.pipeline.
PRODUCERS: dict[str, str] = {kind: producers(kind) for kind in SCHEMAS}

#: Version of each group encoding (the ``encoding-type`` attribute names the group's layout,
#: ``encoding-version`` this number); bumped when a group's layout changes incompatibly.
ENCODING_VERSION = "1"
