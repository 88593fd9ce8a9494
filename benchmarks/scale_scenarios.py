"""Valid concrete scenarios of any size on the real map, for the scale benchmarks.

    python benchmarks/scale_scenarios.py 10000 out-folder   # writes out-folder/scale-10000.xmi

Every node kind of the notation but OpaqueAction (an imported player's XML, which no rule reads),
on maps/intersection.xodr, so the map rules run: groups of six road users, each group on its own
stretch of the arms (cars and a truck on the driving lanes of roads 1, 2 and 3, a bicycle and a pedestrian on
the sidewalks of roads 2 and 4), each running a chain of maneuvers and conditions with turns,
crossings, a lane change, an overtaking, following and approaching, forks joined by
JoinAllFinished, and a use of the library's CrossingManeuver; the chains end in one
JoinOneFinished. `write` checks the file has no errors before it hands it over.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.model.build import ScenarioBuilder, lane, world
from sceml.model.loading import load, load_library
from sceml.model.saving import save
from sceml.validation import validate

REPO = Path(__file__).resolve().parents[1]
MAP = REPO / "maps" / "intersection.xodr"
LIBRARY = REPO / "examples" / "library" / "sceml-library.xmi"
SEGMENT_NODES = 21  # a group's five chains of four nodes and a join (module internals not counted)
SEGMENTS = 5  # segments per group: about 105 nodes for six actors


def build(nodes: int, crossing: scm.ModuleDefinition) -> scm.Scenario:
    """A concrete scenario of about `nodes` nodes (root, end and joins included)."""
    b = ScenarioBuilder("Scale", map="maps/intersection.xodr", level="concrete")
    b.environment()
    groups = max(1, round((nodes - 3) / (SEGMENT_NODES * SEGMENTS)))
    segments = max(1, round((nodes - 3) / (groups * SEGMENT_NODES)))
    ends: list[scm.GraphElement] = []
    for g in range(groups):
        s = 20.0 + 60.0 * g / groups  # each group on its own stretch of the arms
        ego = b.actor("Car", f"ego{g}", ego=g == 0, start=lane(3, 1, s), speed=5.0)
        car = b.actor("Car", f"car{g}", start=lane(1, 1, s), speed=8.0)
        slow = b.actor("Truck", f"truck{g}", start=lane(2, -1, s + 12.0), speed=4.0)
        bike = b.actor("Bicycle", f"bike{g}", start=lane(2, 2, s), speed=4.0)
        walker = b.actor("Pedestrian", f"walker{g}", start=lane(4, 2, 1.0 + s / 10), speed=1.0)
        behind = b.actor("Car", f"overtaker{g}", start=lane(2, -1, s), speed=6.0)
        last = [b.root] * 5
        for k in range(segments):
            first = k == 0  # a turn is driven once: after it the actor is on road 4
            side = 1 if k % 2 == 0 else -1  # the pedestrian crosses to and fro
            chains = [
                [
                    b.add("Accelerate", ego, targetSpeed=12.0, rate=2.0),
                    b.add("TurnLeft", ego, destination=lane(4, -1, 20.0))
                    if first
                    else b.add("KeepVelocity", ego, duration=1.0),
                    b.add("LaneChange", ego, direction="left" if k % 2 == 0 else "right"),
                    b.add("Decelerate", ego, targetSpeed=4.0 + k % 5, rate=3.0),
                ],
                [
                    b.add("SpeedCondition", car, speed=7.0, rule="greaterThan"),
                    b.add("TurnRight", car, destination=lane(4, -1, 30.0))
                    if first
                    else b.add("Accelerate", car, targetSpeed=9.0, rate=2.0),
                    b.add("Follow", car, target=ego, distance=10.0),
                    b.add("Stop", car, rate=4.0),
                ],
                [
                    b.add("TimeElapsed", bike, duration=1.0 + k % 3),
                    b.add("Accelerate", bike, targetSpeed=5.0, rate=1.0),
                    b.add("InVehicleRadius", bike, target=car, radius=10.0),
                    b.add("FollowTrajectory", bike, waypoints=[world(40.0, 3.5), world(60.0, 3.5)]),
                ],
                [
                    b.use(
                        crossing,
                        {"crosser": walker, "trigger": car},
                        {"crossingSpeed": 1.5, "destinationX": -10.0, "destinationY": 4.5 * side},
                    ),
                    b.add("InLocationRadius", walker, position=world(0.0, 0.0), radius=3.0),
                    b.add("Cross", walker, destination=lane(4, -2 * side, 1.0)),
                    b.add("KeepVelocity", walker, duration=2.0),
                ],
                [
                    b.add("TimeToCollision", behind, target=slow, time=4.0, rule="lessThan"),
                    b.add("Overtake", behind, target=slow, side="left", speed=10.0, gap=8.0),
                    b.add("DriveDistance", behind, distance=30.0, speed=8.0),
                    b.add("Approach", behind, target=slow, distance=15.0),
                ],
            ]
            for i, chain in enumerate(chains):
                b.chain(last[i], *chain)
                last[i] = chain[-1]
            join = b.join_all(last[0], last[1])
            last[0] = last[1] = join
        ends.extend(last[1:])  # last[0] is last[1], their join
    b.chain(b.join_one(*ends), b.end)
    return b.scenario


def write(nodes: int, folder: Path) -> Path:
    """Write the scenario of about `nodes` nodes under `folder` (with the map and library it
    names) and check it has no errors; the path of the file."""
    # The map and the library inside the scenario's folder, which validation reads by default.
    (folder / "maps").mkdir(parents=True, exist_ok=True)
    (folder / "library").mkdir(exist_ok=True)
    shutil.copy(MAP, folder / "maps" / MAP.name)
    shutil.copy(LIBRARY, folder / "library" / LIBRARY.name)
    crossing = load_library(folder / "library" / LIBRARY.name).root.modules[0]
    path = save(build(nodes, crossing), folder / f"scale-{nodes}.xmi")
    document = load(path)
    errors = [d for d in validate(document.root, document=document) if d.severity is Severity.ERROR]
    if errors:
        shown = "\n".join(str(d) for d in errors[:8])
        raise SystemExit(f"{path}: the generated scenario has {len(errors)} errors:\n{shown}")
    return path


if __name__ == "__main__":
    print(write(int(sys.argv[1]), Path(sys.argv[2])))
