"""Render the rules table (docs/validation-rules.md) from the registry, so the two cannot drift.

python -m sceml.validation.docs > docs/validation-rules.md
"""

from __future__ import annotations

import sys

from . import REGISTRY
from .engine import INTERNAL_ERROR, OLDER_RELEASE
from .limits import DEFAULT_LIMITS, LIMIT_KEYS
from .registry import Registry

INTRO = """\
# Validation rules

`sceml validate FILE...` checks scenarios and module libraries against the rules below (SPEC §6,
the paper's rules 1-5, and what a scenario engineer would expect). Every diagnostic carries its
rule code, severity, message, file, line and model path. Codes are stable: S structure, A actors,
P parameters and levels, C simultaneity, L plausibility, M modules, E export readiness, R the
map, Y what real players can honour (`sceml.xosc.meaning`, docs/openscenario-mapping.md).

This file is generated from the rule registry: `python -m sceml.validation.docs >
docs/validation-rules.md`. A test fails when it is stale.

## Decisions

- **Module internals.** Validating a scenario also checks every module definition it uses, once,
  reported in the library's file. Simultaneity, level and plausibility rules (marked *through
  modules* below) also run on the scenario with its module uses expanded (`sceml flatten`),
  because only there do module parameters have the values a use gives them; such findings are
  reported at the module use, naming the expanded node (`CrossingManeuver_1.Accelerate_1`).
- **Simultaneity and JoinOneFinished.** Maneuver b is ordered after maneuver a when b can only
  start once a has finished. A path through a JoinOneFinished does not by itself order: the join
  finishes with its first incoming branch while the others keep running, so it (and what follows
  it) is ordered after a only when *every* incoming branch is. The EndNode has no successors, so
  its policy does not matter here. The check uses one pass over a topological order with bitsets,
  without listing pairs.
- **Plausibility is an error.** A speed or rate beyond the actor kind's limit is an error (paper
  rule 5: the scenario is not valid). The limits are plausible maxima; a project that needs more
  raises them with `--limits FILE`. A value is judged by the largest size (absolute number) it
  allows: a range or uniform distribution by its larger end, a normal distribution by its bounds
  (and its mean where a side is unbounded), a discrete one by its largest option. A negative
  speed is driving backwards (release 1.4), judged by its size. Unset parameters (language
  defaults) are not judged.
- **Levels.** A functional scenario may leave anything unset. Logical and concrete ones need every
  value without a language default (SCEML-P002, SCEML-M006); concrete ones hold single values only
  (SCEML-P001).
- **The map.** The R rules read the OpenDRIVE file the root node names (relative to the scenario
  file; a model built in Python without a file is checked only against an absolute map path) with `sceml.maps` (docs/map-reader.md). A simulator town name is not read (SCEML-R002,
  info). A world position is on a lane when it lies within the lane's edges or at most 0.5 m
  outside them; vehicles need driving lanes, bicycles may also use bike lanes and sidewalks,
  pedestrians sidewalks and the roadway. A logical position is judged at the ends and the middle
  of each range or distribution. A turn starts from the actor's start lane, or from the
  destination of its latest earlier routed maneuver; after a lane change or overtake, any lane of
  the road in the same direction. Turns: more than 30 degrees of heading change through the
  junction's connecting road is a left or right turn, more than 150 degrees a U-turn.
- **Export.** `sceml export` refuses a model with any error, then runs the rules marked
  *checked* in the Export column again on the scenario with its module uses expanded, with the
  chosen OpenSCENARIO version and profile: what the mapping needs beyond a valid graph.
- **Imported scenarios.** Some rules judge a value as the scenario states it against the world
  (the actor kind's limits, the map): {stated}. A file `sceml import` reads states the same
  value, so their findings are the original's too: the import lists them apart and does not
  fail on them unless `--strict` (docs/import.md). Every other error of an imported scenario is
  one the import caused.
- **Internal errors.** A rule that fails unexpectedly on a malformed model does not stop the run:
  it becomes a diagnostic with code `{internal}` naming the rule, and all other rules still run.
- **Older metamodel releases.** A file saved with an earlier release of the metamodel (its nsURI
  names the release) is migrated in memory as it is read (docs/metamodel.md). `validate` says so
  with a warning, `{older}`, on line 1 of each such file (libraries it loaded included), listing
  the migration's changes; `--strict` makes it an error. `sceml migrate` rewrites the file.
"""


def rules_table(registry: Registry = REGISTRY) -> str:
    """The Markdown table of every rule: code, severity, applies to, what it checks, whether an
    export checks it on the flattened scenario, source."""
    lines = [
        "| Code | Severity | Applies to | What it checks | Export | Source |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for rule in registry.rules():
        applies = ", ".join(rule.metaclasses)
        if rule.through_modules:
            applies += " (through modules)"
        description = rule.description[0].upper() + rule.description[1:]
        export = "checked" if rule.export else ""
        lines.append(
            f"| `{rule.code}` | {rule.severity} | {applies} | {description}. | {export} "
            f"| {rule.source} |"
        )
    return "\n".join(lines) + "\n"


def _stated(registry: Registry) -> str:
    """The codes of the rules that judge stated values, as the Decisions list them."""
    return ", ".join(f"`{r.code}`" for r in registry.rules() if r.judges_stated_values)


def limits_table() -> str:
    """The built-in plausibility limits as a Markdown table (SI units and km/h)."""
    keys = list(LIMIT_KEYS)
    header = " | ".join(f"{key} ({LIMIT_KEYS[key].split('(')[1]}" for key in keys)
    lines = [f"| Actor kind | {header} |", "| --- |" + " --- |" * len(keys)]
    for kind, values in DEFAULT_LIMITS.items():
        cells = []
        for key in keys:
            value = values[key]
            cells.append(
                f"{value:g} ({value * 3.6:g} km/h)" if key == "max_speed" else f"{value:g}"
            )
        lines.append(f"| {kind} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def render(registry: Registry = REGISTRY) -> str:
    """The whole of docs/validation-rules.md."""
    limits_intro = (
        "## Plausibility limits\n\nBuilt-in limits per actor kind. A limits file (YAML or TOML, "
        "same keys, SI units) is laid over them key by key; a limit is looked up on the actor's "
        "kind, then on its superclasses (TwoWheeler, FourWheeler, Actor).\n\n"
        "```yaml\nPedestrian:\n  max_speed: 3.0\nFourWheeler:\n  max_deceleration: 9.0\n```\n\n"
    )
    return (
        INTRO.format(internal=INTERNAL_ERROR, older=OLDER_RELEASE, stated=_stated(registry))
        + "\n## Rules\n\n"
        + rules_table(registry)
        + "\n"
        + limits_intro
        + limits_table()
    )


if __name__ == "__main__":
    sys.stdout.write(render())
