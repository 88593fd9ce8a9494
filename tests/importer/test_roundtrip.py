"""Export then import gives the scenario back: every reference example at every version, and
sampled concrete UIS1/UIS2 scenarios; exporting the import writes the same bytes again."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.levels.apply import FlatTemplate
from sceml.levels.sampling import plan_for, values_at
from sceml.levels.space import parameter_space
from sceml.model.loading import load, load_scenario
from sceml.modules import flatten

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((REPO / "examples").glob("*-concrete.xmi"))
VERSIONS = ("1.0", "1.1", "1.2", "1.3")
SAMPLES_PER_EXAMPLE = 12


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_survives_export_then_import(
    example: Path, version: str, tmp_path: Path, same
) -> None:
    scenario = load(example).root
    exported = tmp_path / f"{example.stem}.xosc"
    export_to_file(scenario, exported, version=version, source_path=example)
    # The map stays in the repository, outside the export's folder: allowed, so it is read.
    imported = import_file(exported, allow=[REPO / "maps"])
    same(flatten(scenario), imported.scenario)
    # An export of our own maps completely: nothing opaque, nothing guessed.
    assert imported.report.counts()["opaque"] == 0
    assert imported.report.counts()["guessed"] == 0


@pytest.mark.parametrize("version", ("1.0", "1.3"))
@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_the_import_exports_to_the_same_bytes(example: Path, version: str, tmp_path: Path) -> None:
    first = tmp_path / "first.xosc"
    export_to_file(load(example).root, first, version=version, source_path=example)
    model = tmp_path / "imported.xmi"
    import_to_file(first, model)
    second = tmp_path / "second.xosc"
    export_to_file(load(model).root, second, version=version, source_path=model)
    assert second.read_bytes() == first.read_bytes()


def _samples() -> list[tuple[str, int]]:
    return [(name, index) for name in ("uis1", "uis2") for index in range(SAMPLES_PER_EXAMPLE)]


@pytest.fixture(scope="module")
def sampled() -> dict[str, list]:
    """Concrete scenarios sampled (random, seed 7) from the logical UIS1 and UIS2."""
    found = {}
    for name in ("uis1", "uis2"):
        logical = load_scenario(REPO / "examples" / f"{name}-logical.xmi").root
        space = parameter_space(logical)
        rows = values_at(
            space, plan_for(space, "random", SAMPLES_PER_EXAMPLE, 7), np.arange(SAMPLES_PER_EXAMPLE)
        )
        template = FlatTemplate(logical, space.paths)
        found[name] = [template.fill(row) for row in rows]
    return found


@pytest.mark.parametrize(("name", "index"), _samples())
def test_sampled_scenarios_survive_export_then_import(
    name: str, index: int, sampled, tmp_path: Path, same
) -> None:
    scenario = sampled[name][index]
    version = VERSIONS[index % len(VERSIONS)]
    exported = tmp_path / "sample.xosc"
    export_to_file(
        scenario, exported, version=version, source_path=REPO / "examples" / f"{name}-logical.xmi"
    )
    same(scenario, import_file(exported).scenario)


def test_the_comparison_sees_a_changed_value_actor_and_flow(tmp_path: Path, canonical) -> None:
    path = REPO / "examples" / "uis2-concrete.xmi"
    original = flatten(load(path).root)
    exported = tmp_path / "uis2.xosc"
    export_to_file(load(path).root, exported, version="1.3", source_path=path)
    for change in ("value", "actor", "flow"):
        imported = import_file(exported).scenario
        drive = next(n for n in imported.nodes if n.eClass.name == "DriveDistance")
        if change == "value":
            drive.distance.value += 1
        elif change == "actor":
            drive.referenceActor = next(
                a for a in drive.referenceActor.eContainer().actors if a is not drive.referenceActor
            )
        else:
            drive.incoming[0].source = next(
                n for n in imported.nodes if n.eClass.name == "RootNode"
            )
        assert canonical(imported) != canonical(original), change
