"""The export profiles: generic OpenSCENARIO, or what CARLA's scenario_runner can play.

Kept apart from `support` (which imports every action mapping) so that the command line can
offer the choices without loading the exporter.
"""

from __future__ import annotations

PROFILES = ("generic", "carla")
#: The one OpenSCENARIO version scenario_runner reads.
CARLA_VERSION = "1.0"
