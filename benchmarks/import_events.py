"""How `sceml import` time grows with the number of events (issue 26: it must be n log n or better).

    python benchmarks/import_events.py [--sizes 125 250 500 1000]

Each synthetic scenario has four cars on a straight road and n events of speed changes,
spread over the cars: event i starts when event i-1 (of any car) has completed, and every
tenth also waits for a simulation time, so triggers, joins and the one-maneuver-at-a-time rule
all run. Prints, per size, seconds for the import and microseconds per event, beside an
anchor measured in the same run (parsing the same file with lxml), and the growth exponent
between successive sizes (1.0 is linear).
"""

from __future__ import annotations

import argparse
import math
import tempfile
import time
from pathlib import Path

from lxml import etree

from sceml.importer import import_file

#: Cars the events are spread over (--cars).
CARS = 4

HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="events"
    author="benchmark"/>
  <ParameterDeclarations/>
  <CatalogLocations/>
  <RoadNetwork><LogicFile filepath="none.xodr"/></RoadNetwork>
  <Entities>{entities}</Entities>
  <Storyboard>
    <Init><Actions>{init}</Actions></Init>
    <Story name="story"><Act name="act">{groups}
      <StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none">
        <ByValueCondition><SimulationTimeCondition value="0" rule="greaterThan"/>
        </ByValueCondition></Condition></ConditionGroup></StartTrigger>
    </Act></Story>
    <StopTrigger/>
  </Storyboard>
</OpenSCENARIO>
"""
ENTITY = """<ScenarioObject name="car{i}"><Vehicle name="car{i}" vehicleCategory="car">
  <BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="1.8" length="4.5" height="1.5"/>
  </BoundingBox><Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="3.1"
  positionZ="0.3"/><RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0"
  positionZ="0.3"/></Axles><Properties/></Vehicle></ScenarioObject>"""
INIT = """<Private entityRef="car{i}"><PrivateAction><TeleportAction><Position>
  <WorldPosition x="{x}" y="{y}" z="0" h="0"/></Position></TeleportAction></PrivateAction>
  <PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step"
  value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/>
  </SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"""
EVENT = """<Event name="e{i}" priority="overwrite"><Action name="a{i}"><PrivateAction>
  <LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="linear" value="2"
  dynamicsDimension="rate"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/>
  </SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Action>
  <StartTrigger><ConditionGroup>{conditions}</ConditionGroup></StartTrigger></Event>"""
AFTER = """<Condition name="c{i}" delay="0" conditionEdge="none"><ByValueCondition>
  <StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="e{j}"
  state="completeState"/></ByValueCondition></Condition>"""
CLOCK = """<Condition name="t{i}" delay="0" conditionEdge="none"><ByValueCondition>
  <SimulationTimeCondition value="{t}" rule="greaterThan"/></ByValueCondition></Condition>"""


def scenario(events: int, cars: int = CARS, same_trigger: bool = False) -> str:
    """A scenario of `events` chained speed events over `cars` cars."""
    per_car: list[list[str]] = [[] for _ in range(cars)]
    for i in range(events):
        conditions = AFTER.format(i=i, j=i - 1) if i and not same_trigger else ""
        if i % 10 == 0 or same_trigger:
            conditions += CLOCK.format(i=i, t=0 if same_trigger else i * 0.5)
        speed = 10 + (i % 5)
        per_car[i % cars].append(EVENT.format(i=i, speed=speed, conditions=conditions))
    groups = "".join(
        f'<ManeuverGroup name="g{c}" maximumExecutionCount="1"><Actors '
        f'selectTriggeringEntities="false"><EntityRef entityRef="car{c}"/></Actors>'
        f'<Maneuver name="m{c}">{"".join(evs)}</Maneuver></ManeuverGroup>'
        for c, evs in enumerate(per_car)
        if evs
    )
    return HEAD.format(
        entities="".join(ENTITY.format(i=c) for c in range(cars)),
        init="".join(INIT.format(i=c, x=20 * c, y=0) for c in range(cars)),
        groups=groups,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[125, 250, 500, 1000])
    parser.add_argument("--cars", type=int, default=CARS)
    parser.add_argument(
        "--same-trigger", action="store_true", help="every event starts with the act instead"
    )
    options = parser.parse_args()
    sizes = options.sizes
    print(f"{'events':>7} {'import s':>9} {'us/event':>9} {'lxml parse s':>13} {'exponent':>9}")
    previous: tuple[int, float] | None = None
    with tempfile.TemporaryDirectory() as folder:
        for size in sizes:
            path = Path(folder) / f"events{size}.xosc"
            path.write_text(scenario(size, options.cars, options.same_trigger))
            start = time.perf_counter()
            etree.parse(str(path))
            anchor = time.perf_counter() - start
            start = time.perf_counter()
            import_file(path)
            seconds = time.perf_counter() - start
            exponent = (
                ""
                if previous is None
                else f"{math.log(seconds / previous[1]) / math.log(size / previous[0]):.2f}"
            )
            print(
                f"{size:>7} {seconds:>9.2f} {1e6 * seconds / size:>9.0f} {anchor:>13.4f} "
                f"{exponent:>9}"
            )
            previous = (size, seconds)


if __name__ == "__main__":
    main()
