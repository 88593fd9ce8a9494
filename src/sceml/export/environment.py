"""The Init EnvironmentAction: time of day, clouds, precipitation and fog, per version."""

from __future__ import annotations

from typing import Any

import scemlmodel as scm

from ..validation.readiness import is_time_of_day
from .context import Context
from .values import number

#: 1.2 replaced cloudState by fractionalCloudCover (oktas).
OKTAS = {
    "free": "zeroOktas",
    "cloudy": "fourOktas",
    "overcast": "eightOktas",
    "rainy": "eightOktas",
}
#: Sun illuminance (lux) and the older `intensity`, by cloud state.
SUN = {"free": 100000.0, "cloudy": 50000.0, "overcast": 20000.0, "rainy": 10000.0}


class EnvironmentValueError(ValueError):
    """The environment holds a value OpenSCENARIO cannot take (e.g. a malformed time of day)."""


def environment(ctx: Context, root: scm.RootNode, date: str) -> dict[str, Any]:
    """The Environment element's content; `date` (YYYY-MM-DD...) gives the day of TimeOfDay."""
    given = root.environment
    owner = given if given is not None else scm.Environment()
    time_of_day = owner.timeOfDay or "12:00:00"
    if not is_time_of_day(time_of_day):
        raise EnvironmentValueError(f"time of day {time_of_day!r} is not HH:MM:SS")
    cloud = owner.cloudState.name
    return {
        "name": "Environment",
        "date_time": f"{date[:10]}T{time_of_day}",
        "cloud_state": cloud,
        "cloud_cover": OKTAS[cloud],
        "sun": number(SUN[cloud]),
        "fog": ctx.values.text(owner, "fogVisualRange"),
        "precipitation": owner.precipitation.name,
        "intensity": ctx.values.text(owner, "precipitationIntensity"),
    }
