"""OpenSCENARIO's LongitudinalDistanceAction to Follow (continuous) or Approach, with its measure.

The gap (a `distance`, or a `timeGap` at the target's speed), `freespace`, 1.1's
`displacement` and the DynamicConstraints (maxAcceleration, maxDeceleration, maxSpeed and 1.2's
jerks) are kept as the file says them (release 1.5): players drive the gap by them, so a
re-export without them plays otherwise (`distance_test`'s Dummy drove 8 m off).
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from .actions import Motion, Request, add_node, maps
from .context import Build
from .positions import number

#: DynamicConstraints attribute -> the DistanceKeeping feature of the same meaning.
CONSTRAINTS = (
    "maxAcceleration",
    "maxDeceleration",
    "maxSpeed",
    "maxAccelerationRate",
    "maxDecelerationRate",
)

#: OpenSCENARIO's LongitudinalDisplacement values -> LongitudinalDisplacement literals.
DISPLACEMENTS = {
    "trailingReferencedEntity": "trailing",
    "leadingReferencedEntity": "leading",
    "any": "any",
}


@maps("PrivateAction/LongitudinalAction/LongitudinalDistanceAction")
def _distance_keeping(
    build: Build, request: Request, keep: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    gap_key = "distance" if keep.get("distance") is not None else "timeGap"
    if keep.get(gap_key) is None:
        return "a distance keeping with neither distance nor timeGap has no SceML form"
    gap = number(keep, gap_key)
    displacement = _displacement(build, keep, gap)
    if gap < 0:
        gap = -gap  # the side is the displacement's (1.0: the sign's, read above)
    _report_frame(build, request, keep)
    kind = "Follow" if keep.get("continuous") == "true" else "Approach"
    constraints = keep.find("DynamicConstraints")
    limits = {key: _optional(constraints, key) for key in CONSTRAINTS}
    node = add_node(
        build,
        request,
        kind,
        # Unset where they are the defaults, so that the model says only what the file does.
        freespace=True if keep.get("freespace") in ("true", "1") else None,
        displacement=None if displacement == "trailing" else displacement,
        **{gap_key: gap},
        **limits,
    )
    node.targetActor = build.actor(keep.get("entityRef"), keep)
    return node


def _displacement(build: Build, keep: etree._Element, gap: float) -> str:
    """The side the gap is kept on: 1.1's `displacement` (absent: behind, as players take it);
    in 1.0, which has none, a negative distance keeps the actor ahead."""
    written = keep.get("displacement")
    if written is not None:
        return DISPLACEMENTS.get(written, "trailing")
    if build.source.version == "1.0" and gap < 0:
        return "leading"
    return "trailing"


def _report_frame(build: Build, request: Request, keep: etree._Element) -> None:
    """1.1's coordinateSystem other than the actor's own frame is not kept (reported)."""
    frame = keep.get("coordinateSystem")
    if frame not in (None, "entity") and keep.get("freespace") not in ("true", "1"):
        build.report.add(
            "not represented",
            f"{request.name}: the gap measured in the {frame} frame is measured along the "
            "actor's heading",
            build.where(keep),
        )


def _optional(element: etree._Element | None, key: str) -> float | None:
    """The attribute's number; None when absent (the actor's own limit, as players take it)."""
    if element is None or element.get(key) is None:
        return None
    return number(element, key)
