"""The export profiles: generic OpenSCENARIO, or what CARLA's scenario_runner can play.

Kept apart from `support` so that the command line can offer the choices with nothing more than
the list of versions loaded.
"""

from __future__ import annotations

from .schema import SUPPORTED_VERSIONS

PROFILES = ("generic", "carla")
#: The one OpenSCENARIO version scenario_runner reads.
CARLA_VERSION = "1.0"
#: The version written when none is asked for (and not the carla profile): the newest.
DEFAULT_VERSION = SUPPORTED_VERSIONS[-1]


def default_version(profile: str = "generic") -> str:
    """The version written when none is asked for: CARLA's for carla, else the newest."""
    return CARLA_VERSION if profile == "carla" else DEFAULT_VERSION
