"""User-facing errors.

Every error a user can cause (bad input file, bad configuration, impossible request)
is a :class:`FacesynthError` whose message is one sentence naming the file, the place
and what to do. The command line prints it and exits with status 1 (bad input or data),
or 2 for a :class:`UsageError` (bad usage: a missing or contradictory option, a bad
``--set``), as click does for its own usage errors; anything else that escapes is a bug
and keeps its traceback.
"""


class FacesynthError(Exception):
    """Base class of every error caused by the user's input; the message is shown as is."""


class InputError(FacesynthError):
    """An input file is missing, unreadable or inconsistent."""


class ArtifactError(FacesynthError):
    """An HDF5 artifact has the wrong kind or schema, or lacks a dataset."""


class ConfigError(FacesynthError):
    """A configuration file or ``--set`` override is invalid."""


class SearchError(FacesynthError):
    """The synthesis request cannot be satisfied (bad constraint, unknown phone, ...)."""


class OutputExistsError(FacesynthError):
    """The output path exists and ``--overwrite`` was not given."""


class UsageError(FacesynthError):
    """The command was called wrongly: an option is missing or contradicts another (exit status 2)."""


class OverrideError(ConfigError, UsageError):
    """A ``--set`` override is malformed, names an unknown setting or one of a section the
    command does not read, or holds a value the setting does not allow (exit status 2)."""
