"""Parameter and variable actions and conditions (no actor performs them) import as the global
kinds, with the declarations they name, export back at every version that can say them (XSD-valid,
the same elements as the original) and import again to the same scenario; variables, which 1.0
and 1.1 lack, are refused there with the node named."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from sceml import graph, io, schema
from sceml.export import ExportError, export_to_file
from sceml.importer import import_file, import_to_file
from sceml.importer.markers import MARKER

FILES = Path(__file__).parent / "files"
PARAMETERS = FILES / "parameters.xosc"
VARIABLES = FILES / "variables.xosc"
GLOBAL_TAGS = (
    "ParameterAction",
    "ParameterCondition",
    "VariableAction",
    "VariableCondition",
)


def global_elements(path: Path) -> list[str]:
    """Each parameter or variable action and condition of a file, with what it does, sorted,
    the SceML marker's left out."""
    found = []
    for element in etree.parse(str(path)).iter(*GLOBAL_TAGS):
        if MARKER in element.attrib.values():
            continue  # the export's own bookkeeping (docs/openscenario-mapping.md)
        inner = [f"{e.tag}{sorted(e.attrib.items())}" for e in element.iter() if e is not element]
        found.append(f"{element.tag}{sorted(element.attrib.items())}{inner}")
    return sorted(found)


def declared(path: Path, names: set[str]) -> list[tuple[str, ...]]:
    """The file's top-level declarations of `names`: (tag, name, type, value)."""
    root = etree.parse(str(path)).getroot()
    found = []
    for tag in ("ParameterDeclaration", "VariableDeclaration"):
        for element in root.iterfind(f"{tag}s/{tag}"):
            if element.get("name") in names:
                kind = element.get("parameterType") or element.get("variableType")
                found.append((tag, str(element.get("name")), str(kind), str(element.get("value"))))
    return sorted(found)


def test_parameter_actions_and_conditions_import_as_global_nodes() -> None:
    imported = import_file(PARAMETERS)
    assert imported.report.counts()["opaque"] == 0
    nodes = {n.name: n for n in imported.scenario.nodes}
    kinds = {name: node.eClass.name for name, node in nodes.items()}
    assert kinds["SetCounter"] == kinds["RaiseCounter"] == kinds["Calm"] == "SetParameter"
    assert kinds["CounterHigh"] == kinds["StillCalm"] == "ParameterCondition"
    raise_it, high = nodes["RaiseCounter"], nodes["CounterHigh"]
    assert (raise_it.parameter, raise_it.value, raise_it.modify.name) == ("Counter", "2", "add")
    assert (high.parameter, high.value, high.rule.name) == ("Counter", "4", "greaterThan")
    assert all(
        nodes[name].referenceActor is None
        for name in ("SetCounter", "RaiseCounter", "Calm", "CounterHigh", "StillCalm")
    )
    root = imported.scenario.nodes[0]
    # Only what a global node names is declared; Ignored was resolved where it was used.
    assert [(d.name, d.type.name, d.value, d.variable) for d in root.declarations] == [
        ("Counter", "integer", "0", False),
        ("Mood", "string", "calm", False),
    ]


@pytest.mark.parametrize(
    ("source", "version"),
    [(PARAMETERS, v) for v in ("1.0", "1.1", "1.2", "1.3")]
    + [(VARIABLES, "1.2"), (VARIABLES, "1.3")],
    ids=lambda x: x.stem if isinstance(x, Path) else x,
)
def test_global_nodes_export_as_they_were_read(
    source: Path, version: str, tmp_path: Path, same
) -> None:
    model = tmp_path / "imported.xmi"
    import_to_file(source, model)
    exported = tmp_path / "exported.xosc"
    export_to_file(io.load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    assert global_elements(exported) == global_elements(source)
    names = {"Counter", "Mood"}
    assert declared(exported, names) == declared(source, names)
    again = import_file(exported)
    assert again.report.counts()["opaque"] == 0
    first = import_file(source)
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first.scenario, again.scenario):
        graph.root_node(scenario).environment = None
    same(first.scenario, again.scenario)


@pytest.mark.parametrize("version", ("1.0", "1.1"))
def test_variables_are_refused_before_1_2(version: str, tmp_path: Path) -> None:
    model = tmp_path / "variables.xmi"
    import_to_file(VARIABLES, model)
    target = tmp_path / "out.xosc"
    with pytest.raises(ExportError, match="SetVariable needs OpenSCENARIO 1.2 or later"):
        export_to_file(io.load(model).root, target, version=version, source_path=model)
    assert not target.exists()
