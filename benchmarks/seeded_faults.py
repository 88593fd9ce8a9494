"""scale_scenarios.py's scenario with faults seeded throughout: a file with findings of many
kinds, for checking that a change to validation leaves every diagnostic the same.

    python benchmarks/seeded_faults.py 10000 out-folder   # writes out-folder/faults-10000.xmi

The valid scenarios of the scale benchmarks have no findings, so comparing their reports before
and after a change proves little. Here, deterministically (by position in the file), nodes run
0 or 3 times, lose a parameter or their reference actor, take a value out of bounds (negative,
huge, above the actor's limits), repeat a neighbour's name or point a destination off the
map; module uses override a parameter out of bounds; flows lose an end. Compare the reports
with `sceml validate --format json` from the trees before and after.
"""

from __future__ import annotations

import sys
from pathlib import Path

from pyecore.ecore import EObject
from scale_scenarios import write

import scemlmodel as scm
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.model.traversal import all_contents


def _values(node: EObject) -> list[scm.Value]:
    return [obj for obj in all_contents(node) if isinstance(obj, scm.Value)]


def _seed_node(i: int, node: scm.ActionNode, previous: scm.ActionNode) -> None:
    values = _values(node)
    if i % 97 == 0:
        node.maxRuns = 0
    elif i % 89 == 1:
        node.maxRuns = 3
    elif i % 83 == 2 and values:
        holder = values[0]
        holder.eContainer().eSet(holder.eContainmentFeature(), None)
    elif i % 79 == 3 and values:
        values[-1].value = -1.0
    elif i % 73 == 4 and values:
        values[0].value = 1e9
    elif i % 71 == 5 and values:
        values[0].value = 120.0  # above every kind's speed and acceleration limit
    elif i % 67 == 6:
        node.referenceActor = None
    elif i % 61 == 7:
        node.name = previous.name
    elif i % 59 == 8 and isinstance(node, scm.RoutedManeuver):
        for position in [node.destination, *all_contents(node.destination)]:
            if isinstance(position, scm.WorldPosition) and position.x is not None:
                position.x.value = 5000.0  # off the map


def seed(scenario: scm.Scenario) -> None:
    """Seed the faults into `scenario` in place."""
    actions = [n for n in scenario.nodes if isinstance(n, scm.ActionNode)]
    for i, node in enumerate(actions[1:], start=1):
        _seed_node(i, node, actions[i - 1])
    uses = [n for n in scenario.nodes if isinstance(n, scm.ModuleUse)]
    for i, use in enumerate(uses):
        for override in use.overrides if i % 5 == 0 else ():
            if isinstance(override.value, scm.Value):
                override.value.value = 40.0 if i % 10 == 0 else -3.0
    for i, flow in enumerate(list(scenario.flows)):
        if i % 211 == 7:
            flow.target = None


def write_faulty(nodes: int, folder: Path) -> Path:
    """Write scale_scenarios' scenario of about `nodes` nodes with faults seeded; its path."""
    valid = write(nodes, folder)
    document = load(valid)
    seed(document.root)
    return save(document.root, folder / f"faults-{nodes}.xmi")


if __name__ == "__main__":
    print(write_faulty(int(sys.argv[1]), Path(sys.argv[2])))
