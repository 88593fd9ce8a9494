"""A ParameterValueDistribution makes the import logical: SceML's own distributions come back as
the logical scenario they were exported from, hand-written ones map what SceML can hold, and
everything else is reported and keeps its declared value."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

import scemlmodel as scm
from sceml.cli import cli
from sceml.diagnostics import Severity
from sceml.importer import XoscImportError, import_file
from sceml.model.loading import load, load_scenario
from sceml.model.params import value
from sceml.model.saving import save
from sceml.modules import flatten
from sceml.validation import validate

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
FILES = Path(__file__).resolve().parent / "files"

#: A small scenario: Speed and Rate fill one value each, Speed also an expression; Unused is not
#: used anywhere.
SCENARIO = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="d" author="t"/>
  <ParameterDeclarations>
    <ParameterDeclaration name="Speed" parameterType="double" value="10"/>
    <ParameterDeclaration name="Rate" parameterType="double" value="2"/>
    <ParameterDeclaration name="Unused" parameterType="double" value="1"/>
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
                <SpeedActionDynamics dynamicsShape="linear" value="$Rate" dynamicsDimension="rate"/>
                <SpeedActionTarget><AbsoluteTargetSpeed value="$Speed"/></SpeedActionTarget>
              </SpeedAction></LongitudinalAction></PrivateAction></Action>
              <StartTrigger><ConditionGroup>
                <Condition name="GoWhen" delay="0" conditionEdge="none"><ByValueCondition>
                  <SimulationTimeCondition value="0" rule="greaterThan"/>
                </ByValueCondition></Condition>
              </ConditionGroup></StartTrigger>
            </Event>
            <Event name="Stop" priority="override">
              <Action name="StopAction"><PrivateAction><LongitudinalAction><SpeedAction>
                <SpeedActionDynamics dynamicsShape="linear" value="${$Speed / 2.5}" dynamicsDimension="rate"/>
                <SpeedActionTarget><AbsoluteTargetSpeed value="0"/></SpeedActionTarget>
              </SpeedAction></LongitudinalAction></PrivateAction></Action>
              <StartTrigger><ConditionGroup>
                <Condition name="StopWhen" delay="0" conditionEdge="none"><ByValueCondition>
                  <StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="Go" state="completeState"/>
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


def _pvd(body: str, scenario: str = "scenario.xosc", minor: int = 2) -> str:
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="{minor}" date="2024-01-01T00:00:00" description="d" author="t"/>
  <ParameterValueDistribution>
    <ScenarioFile filepath="{scenario}"/>
{body}
  </ParameterValueDistribution>
</OpenSCENARIO>
"""


def _write(folder: Path, body: str, scenario: str = "scenario.xosc") -> Path:
    (folder / "scenario.xosc").write_text(SCENARIO)
    pvd = folder / "scenario.pvd.xosc"
    pvd.write_text(_pvd(body, scenario))
    return pvd


def _nodes(scenario: scm.Scenario) -> dict[str, scm.GraphElement]:
    return {str(n.name): n for n in scenario.nodes}


def _messages(imported, section: str) -> list[str]:  # type: ignore[no-untyped-def]
    return [
        f"{Path(e.file).name if e.file else ''}:{e.line}: {e.message}"
        for e in imported.report.section(section)
    ]


def _export_distribution(logical: Path, out: Path, *more: str) -> Path:
    result = CliRunner().invoke(cli, ["export-distribution", str(logical), "-o", str(out), *more])
    assert result.exit_code == 0, result.output
    return next(out.glob("*.pvd.xosc"))


# Round trips: SceML's own distributions -------------------------------------------------------


@pytest.mark.parametrize("name", ["uis1", "uis2"])
def test_the_exported_distribution_imports_as_the_logical_scenario(
    name: str, tmp_path: Path, same
) -> None:
    logical = EXAMPLES / f"{name}-logical.xmi"
    pvd = _export_distribution(logical, tmp_path / "out")
    imported = import_file(pvd, allow=[REPO / "maps"])
    assert imported.scenario.nodes[0].level is scm.AbstractionLevel.logical
    same(flatten(load(logical).root), imported.scenario)
    # A SceML export maps completely; only the run count and seed have no place in the model.
    assert imported.report.counts()["opaque"] == 0
    assert imported.report.counts()["guessed"] == 0
    expected = [
        "numberOfTestRuns=100 and randomSeed=0.0 are not kept: `sceml sample` takes --n and --seed"
    ]
    if name == "uis2":
        # DriveDistance finishes ${$distance / $speed} after it starts (issue 25); the node's
        # speed comes from its SpeedAction, the delay is read at the declared value.
        expected.append(
            "$DriveDistance_1_speed at <Condition delay> keeps its declared value 8.0 "
            "(it is used in an expression)"
        )
    assert [e.message for e in imported.report.section("not represented")] == expected
    assert "ego.initialSpeed" in imported.report.logical


def test_the_comparison_sees_a_changed_distribution(tmp_path: Path, canonical) -> None:
    logical = EXAMPLES / "uis1-logical.xmi"
    pvd = _export_distribution(logical, tmp_path / "out")
    original = canonical(flatten(load(logical).root))
    for change in ("mean", "weight", "kind"):
        imported = import_file(pvd).scenario
        nodes = _nodes(imported)
        if change == "mean":
            nodes["Accelerate_1"].targetSpeed.mean += 0.5
        elif change == "weight":
            nodes["InVehicleRadius_1"].radius.options[0].weight = 2.0
        else:
            nodes["Accelerate_2"].targetSpeed = scm.Range(min=3.0, max=6.0, step=1.0)
        assert canonical(imported) != original, change


def test_the_import_validates_and_samples(tmp_path: Path) -> None:
    pvd = _export_distribution(EXAMPLES / "uis2-logical.xmi", tmp_path / "out")
    output = tmp_path / "uis2.xmi"
    # The export names the repository's map, outside tmp_path: allowed, it is read.
    maps = str(EXAMPLES.parent / "maps")
    result = CliRunner().invoke(
        cli, ["import", str(pvd), "-o", str(output), "--report", "--allow", maps]
    )
    assert result.exit_code == 0, result.output
    assert "6 places logical" in result.output
    assert (
        "CrossingManeuver_1_Accelerate_1.targetSpeed = $CrossingManeuver_1_crossingSpeed: U(1, 2)"
        in (result.output)
    )
    document = load_scenario(output, allow=[EXAMPLES.parent / "maps"])
    errors = [d for d in validate(document.root, document=document) if d.severity is Severity.ERROR]
    assert errors == []
    samples = tmp_path / "samples"
    sampled = CliRunner().invoke(
        cli,
        [
            "sample",
            str(output),
            "--strategy",
            "random",
            "--n",
            "4",
            "--seed",
            "1",
            "--executor",
            "local",
            "--allow",
            str(EXAMPLES.parent / "maps"),
            "-o",
            str(samples),
        ],
    )
    assert sampled.exit_code == 0, sampled.output
    assert len(list(samples.glob("*.xosc"))) == 4
    manifest = json.loads((samples / "manifest.json").read_text())
    assert "Accelerate_1.targetSpeed" in json.dumps(manifest)


def test_a_deterministic_distribution_comes_back_as_ranges_with_steps(tmp_path: Path, same) -> None:
    # UIS1 with its two distributions fixed leaves two ranges with steps: a deterministic sweep.
    logical = load_scenario(EXAMPLES / "uis1-logical.xmi")
    nodes = _nodes(logical.root)
    nodes["Accelerate_1"].targetSpeed = value(8)
    nodes["Accelerate_2"].targetSpeed = value(4)
    grid_only = tmp_path / "uis1-logical.xmi"
    root = logical.root.nodes[0]
    root.map = str((EXAMPLES / root.map).resolve())
    save(logical.root, grid_only)
    pvd = _export_distribution(grid_only, tmp_path / "out", "--mode", "deterministic")
    imported = import_file(pvd)
    same(flatten(load(grid_only).root), imported.scenario)
    radius = _nodes(imported.scenario)["InVehicleRadius_1"].radius
    assert isinstance(radius, scm.Range)
    assert (radius.min, radius.max, radius.step) == (8.0, 16.0, 4.0)
    assert imported.report.section("not represented") == []


# Hand-written distributions ------------------------------------------------------------------


def test_ranges_and_sets_map_and_what_does_not_fit_is_reported(tmp_path: Path) -> None:
    pvd = _write(
        tmp_path,
        """    <Deterministic>
      <DeterministicSingleParameterDistribution parameterName="Speed">
        <DistributionRange stepWidth="2"><Range lowerLimit="8" upperLimit="12"/></DistributionRange>
      </DeterministicSingleParameterDistribution>
      <DeterministicSingleParameterDistribution parameterName="Rate">
        <DistributionSet><Element value="1"/><Element value="2"/><Element value="3"/></DistributionSet>
      </DeterministicSingleParameterDistribution>
      <DeterministicSingleParameterDistribution parameterName="Unused">
        <DistributionSet><Element value="1"/><Element value="2"/></DistributionSet>
      </DeterministicSingleParameterDistribution>
      <DeterministicSingleParameterDistribution parameterName="Ghost">
        <DistributionSet><Element value="1"/></DistributionSet>
      </DeterministicSingleParameterDistribution>
    </Deterministic>""",
    )
    imported = import_file(pvd)
    go = _nodes(imported.scenario)["Go"]
    assert isinstance(go.targetSpeed, scm.Range)
    assert (go.targetSpeed.min, go.targetSpeed.max, go.targetSpeed.step) == (8.0, 12.0, 2.0)
    assert [o.value for o in go.rate.options] == [1.0, 2.0, 3.0]
    assert [o.weight for o in go.rate.options] == [None, None, None]
    # `${$Speed / 2.5}` is affine in Speed: its range is carried through, [8, 12] step 2 / 2.5.
    stop_rate = _nodes(imported.scenario)["Stop"].rate
    assert isinstance(stop_rate, scm.Range)
    assert (stop_rate.min, stop_rate.max, stop_rate.step) == pytest.approx((3.2, 4.8, 0.8))
    assert imported.scenario.nodes[0].level is scm.AbstractionLevel.logical
    assert imported.report.logical == {
        "Go.targetSpeed": "$Speed: [8, 12] step 2",
        "Go.rate": "$Rate: {1, 2, 3}",
        "Stop.rate": "$Speed * 0.4: [3.2, 4.8] step 0.8",
    }
    assert _messages(imported, "not represented") == [
        "scenario.pvd.xosc:7: Speed fills 2 places: SceML samples each on its own, OpenSCENARIO "
        "draws one value for all",
        "scenario.pvd.xosc:13: Unused is distributed but the scenario never uses it",
        "scenario.pvd.xosc:16: Ghost is distributed but the scenario does not declare it",
    ]


def test_a_value_set_gives_each_parameter_its_values_and_says_the_joint_set_is_lost(
    tmp_path: Path,
) -> None:
    pvd = _write(
        tmp_path,
        """    <Deterministic>
      <DeterministicMultiParameterDistribution><ValueSetDistribution>
        <ParameterValueSet>
          <ParameterAssignment parameterRef="Speed" value="10"/><ParameterAssignment parameterRef="Rate" value="2"/>
        </ParameterValueSet>
        <ParameterValueSet>
          <ParameterAssignment parameterRef="Speed" value="12"/><ParameterAssignment parameterRef="Rate" value="2"/>
        </ParameterValueSet>
        <ParameterValueSet>
          <ParameterAssignment parameterRef="Speed" value="14"/><ParameterAssignment parameterRef="Rate" value="3"/>
        </ParameterValueSet>
      </ValueSetDistribution></DeterministicMultiParameterDistribution>
    </Deterministic>""",
    )
    imported = import_file(pvd)
    go = _nodes(imported.scenario)["Go"]
    assert [(o.value, o.weight) for o in go.targetSpeed.options] == [
        (10.0, None),
        (12.0, None),
        (14.0, None),
    ]
    # Rate is 2 in two of the three sets: its marginal weights say so.
    assert [(o.value, o.weight) for o in go.rate.options] == [(2.0, 2.0), (3.0, 1.0)]
    assert (
        "scenario.pvd.xosc:7: ValueSetDistribution of Speed, Rate: each parameter becomes the "
        "discrete set of its values; the 3 joint combinations are not kept (SceML samples each "
        "parameter on its own)"
    ) in _messages(imported, "not represented")


def test_stochastic_distributions_map_with_their_weights_and_bounds(tmp_path: Path) -> None:
    pvd = _write(
        tmp_path,
        """    <Stochastic numberOfTestRuns="5" randomSeed="2">
      <StochasticDistribution parameterName="Speed">
        <NormalDistribution expectedValue="10" variance="4"><Range lowerLimit="6" upperLimit="14"/></NormalDistribution>
      </StochasticDistribution>
      <StochasticDistribution parameterName="Rate">
        <ProbabilityDistributionSet>
          <Element value="1" weight="0.25"/><Element value="2" weight="0.75"/>
        </ProbabilityDistributionSet>
      </StochasticDistribution>
    </Stochastic>""",
    )
    go = _nodes(import_file(pvd).scenario)["Go"]
    normal = go.targetSpeed
    assert isinstance(normal, scm.NormalDistribution)
    assert (normal.mean, normal.standardDeviation, normal.lowerBound, normal.upperBound) == (
        10.0,
        2.0,
        6.0,
        14.0,
    )
    assert [(o.value, o.weight) for o in go.rate.options] == [(1.0, 0.25), (2.0, 0.75)]


@pytest.mark.parametrize(
    ("element", "said"),
    [
        ('<PoissonDistribution expectedValue="11"/>', "a Poisson distribution"),
        (
            '<Histogram><Bin weight="1"><Range lowerLimit="8" upperLimit="12"/></Bin></Histogram>',
            "a histogram",
        ),
        (
            '<UserDefinedDistribution type="lookup">table.csv</UserDefinedDistribution>',
            "a UserDefinedDistribution of type 'lookup'",
        ),
    ],
)
def test_a_distribution_sceml_cannot_hold_is_reported_and_keeps_the_declared_value(
    element: str, said: str, tmp_path: Path
) -> None:
    pvd = _write(
        tmp_path,
        f"""    <Stochastic numberOfTestRuns="5">
      <StochasticDistribution parameterName="Speed">
        {element}
      </StochasticDistribution>
    </Stochastic>""",
    )
    imported = import_file(pvd)
    go = _nodes(imported.scenario)["Go"]
    assert isinstance(go.targetSpeed, scm.Value) and go.targetSpeed.value == 10.0
    # Nothing became logical, so the scenario stays concrete.
    assert imported.scenario.nodes[0].level is scm.AbstractionLevel.concrete
    assert imported.report.logical == {}
    assert (
        f"scenario.pvd.xosc:8: Speed: {said} has no SceML parameter value; it keeps its "
        "declared value 10"
    ) in _messages(imported, "not represented")


def test_a_parameter_passed_into_a_catalog_entry_is_followed_there(tmp_path: Path) -> None:
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    text = (FILES / "follow-and-brake.xosc").read_text()
    text = text.replace(
        '<ParameterDeclaration name="Gap" parameterType="double" value="25"/>',
        '<ParameterDeclaration name="Gap" parameterType="double" value="25"/>\n'
        '    <ParameterDeclaration name="Brake" parameterType="double" value="7"/>',
    ).replace('parameterRef="Deceleration" value="7"', 'parameterRef="Deceleration" value="$Brake"')
    (tmp_path / "scenario.xosc").write_text(text)
    pvd = tmp_path / "brake.pvd.xosc"
    pvd.write_text(
        _pvd(
            """    <Stochastic numberOfTestRuns="5">
      <StochasticDistribution parameterName="Brake">
        <UniformDistribution><Range lowerLimit="5" upperLimit="9"/></UniformDistribution>
      </StochasticDistribution>
      <StochasticDistribution parameterName="Speed">
        <UniformDistribution><Range lowerLimit="15" upperLimit="25"/></UniformDistribution>
      </StochasticDistribution>
      <StochasticDistribution parameterName="Gap">
        <UniformDistribution><Range lowerLimit="20" upperLimit="30"/></UniformDistribution>
      </StochasticDistribution>
    </Stochastic>"""
        )
    )
    imported = import_file(pvd)
    logical = imported.report.logical
    # The catalog maneuver's rate is `$Deceleration`, assigned `$Brake`.
    assert [what for what in logical.values() if what.startswith("$Brake")] == ["$Brake: U(5, 9)"]
    assert sum(what.startswith("$Speed") for what in logical.values()) == 2
    braked = [e for e in imported.report.section("mapped") if "$Brake" in e.message]
    assert Path(str(braked[0].file)).name == "ManeuverCatalog.xosc"
    lost = _messages(imported, "not represented")
    assert any("Speed fills 2 places: SceML samples each on its own" in m for m in lost)
    # The lead starts at `${100 + $Gap + 10}`: the gap's distribution, shifted by 110.
    assert logical["Lead.startPosition.s"] == "$Gap + 110: U(130, 140)"


# The command line and unusable input ---------------------------------------------------------


def test_the_distribution_option_applies_a_distribution_to_the_scenario(tmp_path: Path) -> None:
    pvd = _write(
        tmp_path,
        """    <Stochastic numberOfTestRuns="5">
      <StochasticDistribution parameterName="Speed">
        <UniformDistribution><Range lowerLimit="8" upperLimit="12"/></UniformDistribution>
      </StochasticDistribution>
    </Stochastic>""",
        scenario="elsewhere.xosc",
    )
    output = tmp_path / "out.xmi"
    result = CliRunner().invoke(
        cli,
        [
            "import",
            str(tmp_path / "scenario.xosc"),
            "--distribution",
            str(pvd),
            "-o",
            str(output),
            "--report",
        ],
    )
    assert result.exit_code == 0, result.output
    assert "2 places logical" in result.output
    assert "Go.targetSpeed = $Speed: U(8, 12)" in result.output
    assert "Stop.rate = $Speed * 0.4: U(3.2, 4.8)" in result.output
    # The distribution names another file: applied as asked, and said so.
    assert "elsewhere.xosc; applied to" in result.output
    assert 'level="logical"' in output.read_text()


def test_a_distribution_naming_a_missing_scenario_is_refused_with_file_and_line(
    tmp_path: Path,
) -> None:
    pvd = _write(
        tmp_path,
        """    <Deterministic/>""",
        scenario="missing.xosc",
    )
    output = tmp_path / "out.xmi"
    result = CliRunner().invoke(cli, ["import", str(pvd), "-o", str(output)])
    assert result.exit_code == 2, result.output
    assert f"{pvd}:5:" in result.output
    assert "'missing.xosc' does not exist" in result.output
    assert not output.exists()
    assert sorted(tmp_path.iterdir()) == sorted([pvd, tmp_path / "scenario.xosc"])


@pytest.mark.parametrize("case", ["scenario as distribution", "two distributions", "version 1.0"])
def test_distribution_options_that_cannot_be_used_are_refused(case: str, tmp_path: Path) -> None:
    pvd = _write(tmp_path, "    <Deterministic/>")
    scenario = tmp_path / "scenario.xosc"
    if case == "scenario as distribution":
        arguments = [str(scenario), "--distribution", str(scenario)]
        said = "no ParameterValueDistribution"
    elif case == "two distributions":
        arguments = [str(pvd), "--distribution", str(pvd)]
        said = "itself a ParameterValueDistribution"
    else:
        pvd.write_text(_pvd("    <Deterministic/>", minor=0))
        arguments = [str(pvd)]
        said = "OpenSCENARIO 1.0 has no ParameterValueDistribution"
    output = tmp_path / "out.xmi"
    result = CliRunner().invoke(cli, ["import", *arguments, "-o", str(output)])
    assert result.exit_code == 2, result.output
    assert said in result.output
    assert not output.exists()
    with pytest.raises(XoscImportError):
        import_file(arguments[0], distribution=arguments[2] if len(arguments) > 1 else None)


# Expressions of a distributed parameter (issue 24: logical imports keep their logic) -----------

_SPEED_SET = """    <Deterministic>
      <DeterministicSingleParameterDistribution parameterName="Speed">
        <DistributionSet><Element value="10"/><Element value="20"/></DistributionSet>
      </DeterministicSingleParameterDistribution>
    </Deterministic>"""


@pytest.mark.parametrize(
    ("expression", "carried"),
    [
        # A line in Speed, also with a negative slope: carried through.
        ("${$Speed / 2 + 1}", [6.0, 11.0]),
        ("${30 - $Speed}", [10.0, 20.0]),  # 30 - {10, 20}: the order of the options turns round
        # Not a line in Speed: computed from the declared 10 and reported.
        ("${$Speed * $Speed / 100}", None),
        ("${floor($Speed / 3)}", None),
        ("${max($Speed, 15)}", None),
    ],
)
def test_an_affine_expression_carries_the_distribution(
    tmp_path: Path, expression: str, carried: list[float] | None
) -> None:
    pvd = _write(tmp_path, _SPEED_SET)
    scenario = tmp_path / "scenario.xosc"
    scenario.write_text(scenario.read_text().replace("${$Speed / 2.5}", expression))
    imported = import_file(pvd)
    rate = _nodes(imported.scenario)["Stop"].rate
    if carried is None:
        assert isinstance(rate, scm.Value)
        assert any(
            "(it is used in an expression)" in m for m in _messages(imported, "not represented")
        )
    else:
        assert isinstance(rate, scm.DiscreteDistribution)
        assert sorted(option.value for option in rate.options) == carried


def test_applied_maps_every_kind_of_value_through_the_line() -> None:
    from sceml.importer.logical import applied

    normal = applied(
        scm.NormalDistribution(mean=10.0, standardDeviation=2.0, lowerBound=6.0, upperBound=14.0),
        -0.5,
        1.0,
    )
    # -0.5 * 10 + 1 = -4; sd 0.5 * 2 = 1; the bounds swap: -0.5 * 14 + 1 = -6, -0.5 * 6 + 1 = -2.
    assert (normal.mean, normal.standardDeviation, normal.lowerBound, normal.upperBound) == (
        -4.0,
        1.0,
        -6.0,
        -2.0,
    )
    ranged = applied(scm.Range(min=8.0, max=12.0, step=2.0), 0.5, 0.0)
    assert (ranged.min, ranged.max, ranged.step) == (4.0, 6.0, 1.0)
    uniform = applied(scm.UniformDistribution(min=1.0, max=3.0), -1.0, 0.0)
    assert (uniform.min, uniform.max) == (-3.0, -1.0)
    options = scm.DiscreteDistribution()
    options.options.extend([scm.WeightedValue(value=1.0, weight=3.0), scm.WeightedValue(value=2.0)])
    mapped = applied(options, 2.0, 1.0)
    assert [(o.value, o.weight) for o in mapped.options] == [(3.0, 3.0), (5.0, None)]


def test_a_declaration_that_is_a_line_in_the_parameter_carries_it_on(tmp_path: Path) -> None:
    pvd = _write(tmp_path, _SPEED_SET)
    scenario = tmp_path / "scenario.xosc"
    text = scenario.read_text().replace(
        '<Maneuver name="M">',
        '<Maneuver name="M"><ParameterDeclarations><ParameterDeclaration name="Half" '
        'parameterType="double" value="${$Speed / 2}"/></ParameterDeclarations>',
    )
    scenario.write_text(text.replace("${$Speed / 2.5}", "${$Half + 1}"))
    imported = import_file(pvd)
    rate = _nodes(imported.scenario)["Stop"].rate
    # Speed {10, 20} / 2 + 1: {6, 11}.
    assert sorted(option.value for option in rate.options) == [6.0, 11.0]
    assert imported.report.logical["Stop.rate"] == "$Speed * 0.5 + 1: {6, 11}"
