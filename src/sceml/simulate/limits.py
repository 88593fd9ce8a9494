"""What the preview refuses before it runs: values it cannot use, or runs too large to hold.

The engine allocates by what it is given: a speed of 2^31 m/s asks numpy for a path hundreds
of GiB long, a long run at a fine step records millions of samples. So every parameter of the
flattened scenario is read once here, before any actor is set up, and refused with the file,
line and element it came from (a module's default is located in its library): not a single
value (a range, a distribution, unset without a default), not finite, or beyond what any road
user does. These are hard ceilings of the preview, far above the plausibility limits that
validation applies per actor kind (`sceml.validation.limits`), which a project may raise.
"""

from __future__ import annotations

import math
from pathlib import Path

from pyecore.ecore import EObject

from ..model import catalog
from ..model.graph import actors as scenario_actors
from ..model.graph import root_node
from ..model.loading import unresolved_references
from ..model.locating import model_path
from ..model.params import concrete
from ..model.traversal import all_contents
from ..modules.flatten import Flattened
from .world import SimulationError

#: The largest magnitude the preview accepts per SI unit: beyond any road user (540 km/h, 10 g),
#: and for lengths beyond any map's coordinates (UTM northings reach 10,000 km).
CEILINGS: dict[str, float] = {
    "m/s": 150.0,
    "m/s2": 100.0,
    "m": 1e7,
    "s": 86_400.0,
    "rad": 1e3,
    "mm/h": 1e3,
}

#: The most samples (steps times actors) a run may record: each costs about 150 bytes while the
#: run lasts and more in the metrics, so this keeps a run well under 1 GB.
MAX_SAMPLES = 2_000_000

_BYTES_PER_SAMPLE = 150


def refuse_unusable(flattened: Flattened, step: float) -> None:
    """Raise SimulationError for the first parameter the preview cannot use, or a run too long.

    `flattened` is the scenario to run with the origin of each element; `step` the time step.
    """
    flat = flattened.scenario
    for owner in [flat, *all_contents(flat)]:
        for spec in catalog.parameters(owner):
            _check(flattened, owner, spec, step)
    root = root_node(flat)
    if root is None:
        return
    samples = run_samples(flat, step)
    if samples > MAX_SAMPLES:
        raise _located(
            flattened,
            root,
            "maxDuration",
            f"a run of maxDuration {concrete(root, 'maxDuration'):g} s at a step of {step:g} s "
            f"would record {samples:,} samples (about {_megabytes(samples)} MB); the preview "
            f"records at most {MAX_SAMPLES:,}: shorten maxDuration or make --step larger",
        )


def refuse_unresolved(scenario: EObject) -> None:
    """Raise SimulationError, at its line, for a reference to another file that cannot be
    loaded (a module's definition, a hand-edited referenceActor): the run would meet it later
    as pyecore's TypeError."""
    for holder, _href, reason in unresolved_references(scenario, through_files=True):
        file, line = _where(holder)
        raise SimulationError(reason, file=file, line=line, element=model_path(holder))


def run_samples(scenario: EObject, step: float) -> int:
    """How many samples (steps times actors) a run of `scenario` records at most, at `step`.

    For a logical scenario, whose maxDuration may be a range or distribution, its highest
    value; the language default when it has none.
    """
    root = root_node(scenario)
    if root is None:
        return 0
    try:
        duration = concrete(root, "maxDuration")
    except ValueError:
        held = root.maxDuration
        highest = [getattr(held, name, None) for name in ("max", "upperBound")]
        duration = max([float(h) for h in highest if h is not None] or [60.0])
    if not math.isfinite(duration) or duration > CEILINGS["s"]:
        duration = CEILINGS["s"]
    actors = max(1, len(list(scenario_actors(scenario))))
    return (math.ceil(max(duration, 0.0) / step) + 1) * actors


#: An actor's own Performance (release 1.4): a cap, not a motion. One beyond the ceiling caps
#: nothing the preview simulates (esmini's scenarios give hero cars maxAcceleration 200 m/s²).
_CAPS = frozenset({"maxSpeed", "maxAcceleration", "maxDeceleration"})


def _check(flattened: Flattened, owner: EObject, spec: catalog.ParameterSpec, step: float) -> None:
    if spec.optional and owner.eGet(spec.name) is None:
        return  # unset has its own meaning (a road position's h: along its lane)
    try:
        value = concrete(owner, spec.name)
    except ValueError as error:
        raise _located(flattened, owner, spec.name, f"cannot be simulated: {error}") from None
    ceiling = CEILINGS.get(spec.unit)
    if not math.isfinite(value):
        problem = f"{spec.name} is {value}, not a finite number"
    elif ceiling is not None and abs(value) > ceiling and spec.name not in _CAPS:
        problem = (
            f"{spec.name}={value:g} {spec.unit} is beyond what the preview simulates "
            f"(at most {ceiling:g} {spec.unit} in magnitude)"
        )
    else:
        return
    raise _located(flattened, owner, spec.name, problem)


def _located(flattened: Flattened, owner: EObject, name: str, message: str) -> SimulationError:
    # The value itself when it was copied from a file (a module's default lives in its
    # library), else its owner, else what the input scenario shows for it (the module use).
    candidates: list[EObject | None] = [owner.eGet(name), owner]
    for candidate in list(candidates):
        origin = flattened.origin(candidate) if candidate is not None else None
        if origin is not None:
            candidates += [origin.element, origin.in_scenario]
    for candidate in candidates:
        file, line = _where(candidate)
        if file is not None and line is not None:
            return SimulationError(message, file=file, line=line, element=model_path(candidate))
    return SimulationError(message, element=model_path(owner))


def located_in(
    error: SimulationError, scenario: EObject, scenario_file: str | Path | None
) -> SimulationError:
    """`error` with the file and line it is about, where it has none: the element it names (a
    node or actor of `scenario`, or for an expanded node `use.node` the use), else the file."""
    if error.file is not None and error.line is not None:
        return error
    named = {
        str(obj.name): obj
        for obj in [scenario, *all_contents(scenario)]
        if getattr(obj, "name", None)
    }
    element = error.element or ""
    target = named.get(element) or named.get(element.split(".")[0])
    file, line = _where(target) if target is not None else (None, None)
    fallback = str(scenario_file) if scenario_file is not None else None
    error.file = error.file or (str(file) if file is not None else fallback)
    error.line = error.line or line
    return error


def _where(obj: EObject | None) -> tuple[Path | None, int | None]:
    resource = obj.eResource if obj is not None else None
    if resource is None:
        return None, None
    lines = getattr(resource, "sceml_lines", None) or {}
    return Path(resource.uri.normalize()), lines.get(obj)


def _megabytes(samples: int) -> str:
    return f"{samples * _BYTES_PER_SAMPLE / 1e6:,.0f}"
