"""Input that cannot be used: a clear error with file and line, exit 2, and nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.importer import XoscImportError, import_file

#: A small valid OpenSCENARIO 1.2 scenario; the tests break one thing each.
GOOD = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="small" author="tests"/>
  <ParameterDeclarations>
    <ParameterDeclaration name="Speed" parameterType="double" value="10"/>
  </ParameterDeclarations>
  <CatalogLocations/>
  <RoadNetwork><LogicFile filepath="town"/></RoadNetwork>
  <Entities>
    <ScenarioObject name="Ego">
      <Vehicle name="car" vehicleCategory="car">
        <BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="5" height="1.5"/></BoundingBox>
        <Performance maxSpeed="50" maxAcceleration="5" maxDeceleration="8"/>
        <Axles>
          <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/>
          <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/>
        </Axles>
        <Properties/>
      </Vehicle>
    </ScenarioObject>
  </Entities>
  <Storyboard>
    <Init><Actions>
      <Private entityRef="Ego">
        <PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0" h="0"/></Position></TeleportAction></PrivateAction>
      </Private>
    </Actions></Init>
    <Story name="S">
      <Act name="A">
        <ManeuverGroup name="G" maximumExecutionCount="1">
          <Actors selectTriggeringEntities="false"><EntityRef entityRef="Ego"/></Actors>
          <Maneuver name="M">
            <Event name="Go" priority="override">
              <Action name="GoAction"><PrivateAction><LongitudinalAction><SpeedAction>
                <SpeedActionDynamics dynamicsShape="linear" value="2" dynamicsDimension="rate"/>
                <SpeedActionTarget><AbsoluteTargetSpeed value="$Speed"/></SpeedActionTarget>
              </SpeedAction></LongitudinalAction></PrivateAction></Action>
              <StartTrigger><ConditionGroup>
                <Condition name="GoWhen" delay="0" conditionEdge="none"><ByValueCondition>
                  <StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="Stop" state="completeState"/>
                </ByValueCondition></Condition>
              </ConditionGroup></StartTrigger>
            </Event>
            <Event name="Stop" priority="override">
              <Action name="StopAction"><PrivateAction><LongitudinalAction><SpeedAction>
                <SpeedActionDynamics dynamicsShape="linear" value="4" dynamicsDimension="rate"/>
                <SpeedActionTarget><AbsoluteTargetSpeed value="0"/></SpeedActionTarget>
              </SpeedAction></LongitudinalAction></PrivateAction></Action>
              <StartTrigger><ConditionGroup>
                <Condition name="StopWhen" delay="0" conditionEdge="none"><ByValueCondition>
                  <SimulationTimeCondition value="0" rule="greaterThan"/>
                </ByValueCondition></Condition>
              </ConditionGroup></StartTrigger>
            </Event>
          </Maneuver>
        </ManeuverGroup>
        <StartTrigger><ConditionGroup><Condition name="Start" delay="0" conditionEdge="none">
          <ByValueCondition><SimulationTimeCondition value="0" rule="greaterThan"/></ByValueCondition>
        </Condition></ConditionGroup></StartTrigger>
      </Act>
    </Story>
    <StopTrigger/>
  </Storyboard>
</OpenSCENARIO>
"""

_VEHICLE = GOOD[GOOD.index('<Vehicle name="car"') : GOOD.index("</Vehicle>") + len("</Vehicle>")]
_LAST_TRIGGER = (
    '<SimulationTimeCondition value="0" rule="greaterThan"/>\n'
    "                </ByValueCondition></Condition>\n"
    "              </ConditionGroup></StartTrigger>\n"
    "            </Event>"
)
_LOOP = _LAST_TRIGGER.replace(
    '<SimulationTimeCondition value="0" rule="greaterThan"/>',
    '<StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="Go" '
    'state="completeState"/>',
)

#: What breaks the file (old -> new), what the error says, and text on the line it must name.
BROKEN = {
    "malformed XML": (("</Entities>", "</Entitie>"), "not well-formed", "</Entitie>"),
    "another version": (('revMinor="2"', 'revMinor="4"'), "1.4 is not supported", "<FileHeader"),
    "an XSD violation": (
        ('vehicleCategory="car"', 'vehicleCategory="spaceship"'),
        "not valid OpenSCENARIO 1.2",
        "spaceship",
    ),
    "a DOCTYPE": (
        ("<OpenSCENARIO>", "<!DOCTYPE x [<!ENTITY a 'b'>]>\n<OpenSCENARIO>"),
        "DOCTYPE",
        "<!DOCTYPE",
    ),
    "a missing catalog": (
        (_VEHICLE, '<CatalogReference catalogName="Cars" entryName="car"/>'),
        "catalog 'Cars' not found",
        'catalogName="Cars"',
    ),
    "a dangling entity reference": (
        ('<Private entityRef="Ego">', '<Private entityRef="Nobody">'),
        "unknown entity 'Nobody'",
        "Nobody",
    ),
    "a dangling storyboard reference": (
        ('storyboardElementRef="Stop"', 'storyboardElementRef="Later"'),
        "unknown event 'Later'",
        "Later",
    ),
    "a circular trigger": (
        (_LAST_TRIGGER, _LOOP),
        "circular trigger: Go -> Stop -> Go",
        "<StartTrigger><ConditionGroup>",
    ),
    "an undeclared parameter": (
        ('value="$Speed"', 'value="$Fast"'),
        "parameter $Fast is not declared",
        "$Fast",
    ),
}


def _write(tmp_path: Path, old: str, new: str) -> Path:
    assert old in GOOD
    path = tmp_path / "broken.xosc"
    path.write_text(GOOD.replace(old, new, 1))
    return path


def _line_of(path: Path, text: str) -> int:
    """The first line of the file that holds `text`."""
    return next(n for n, line in enumerate(path.read_text().splitlines(), 1) if text in line)


def test_the_good_file_imports(tmp_path: Path) -> None:
    path = tmp_path / "good.xosc"
    path.write_text(GOOD)
    imported = import_file(path)
    kinds = sorted(n.eClass.name for n in imported.scenario.nodes)
    # `SimulationTime > 0`: the TimeElapsed of the step after the start it first holds at.
    assert kinds == ["Accelerate", "EndNode", "RootNode", "Stop", "TimeElapsed"]


@pytest.mark.parametrize("what", sorted(BROKEN))
def test_unusable_input_is_refused_with_file_and_line(what: str, tmp_path: Path) -> None:
    (old, new), message, marker = BROKEN[what]
    path = _write(tmp_path, old, new)
    with pytest.raises(XoscImportError) as caught:
        import_file(path)
    assert message in caught.value.message
    assert (caught.value.file, caught.value.line) == (str(path), _line_of(path, marker))
    assert caught.value.exit_code == 2


@pytest.mark.parametrize("what", ["malformed XML", "a circular trigger", "a missing catalog"])
def test_the_command_exits_2_and_writes_nothing(what: str, tmp_path: Path) -> None:
    (old, new), message, marker = BROKEN[what]
    path = _write(tmp_path, old, new)
    fresh, kept = tmp_path / "new.xmi", tmp_path / "kept.xmi"
    kept.write_text("previous")
    for output in (fresh, kept):
        result = CliRunner().invoke(cli, ["import", str(path), "-o", str(output)])
        assert result.exit_code == 2
        assert f"{path}:{_line_of(path, marker)}: " in result.output
        assert message in result.output
    assert not fresh.exists()
    assert kept.read_text() == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["broken.xosc", "kept.xmi"]
