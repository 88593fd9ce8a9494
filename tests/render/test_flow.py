"""The flow view: node counts, colours, labels and module frames on the reference examples."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml import io
from sceml.build import LibraryBuilder, ScenarioBuilder
from sceml.render import ModuleChoiceError, diagram, flow_diagram, to_bytes

from .svgtools import fills, groups, parse, text_of

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def svg_of(name: str, **options: object):
    root = io.load(EXAMPLES / name).root
    return parse(to_bytes(diagram(root, **options), "svg"))  # type: ignore[arg-type]


def test_uis1_has_the_nodes_of_fig_1d_by_category() -> None:
    svg = svg_of("uis1-functional.xmi")
    counts = {
        name: len(groups(svg, f"sceml-{name}"))
        for name in ("root", "longitudinal", "lateral", "composite", "condition", "end")
    }
    assert counts == {
        "root": 1,
        "longitudinal": 2,
        "lateral": 2,
        "composite": 0,
        "condition": 3,
        "end": 1,
    }
    assert len(groups(svg, "sceml-flow")) == 9


def test_fill_colours_follow_the_category() -> None:
    svg = svg_of("uis1-logical.xmi")
    expected = {"longitudinal": "#ffe066", "lateral": "#f28b82", "condition": "#8ab4f8"}
    for category, colour in expected.items():
        for group in groups(svg, f"sceml-{category}"):
            assert fills(group) == {colour}


def test_labels_name_kind_actors_and_parameters_by_level() -> None:
    svg = svg_of("uis1-logical.xmi")
    ego_branch = [text_of(g) for g in groups(svg, "sceml-actor-ego")]
    assert sorted(t.split()[0] for t in ego_branch) == [
        "Accelerate",
        "InLocationRadius",
        "TurnRight",
    ]
    waiting = next(
        text_of(g) for g in groups(svg, "sceml-condition") if "InVehicleRadius" in text_of(g)
    )
    # Sync 2: the bike waits until the ego is near; the radius is a range at the logical level.
    assert "bike, target ego" in waiting and "[8, 16] step 4 m" in waiting
    accelerate = next(
        text_of(g) for g in groups(svg, "sceml-actor-bike") if "Accelerate" in text_of(g)
    )
    assert "U(3, 6) m/s = 10.8–21.6 km/h" in accelerate
    root = text_of(groups(svg, "sceml-root")[0])
    for part in ("UIS1", "level: logical", "intersection.xodr", "ego: Car, ego", "bike: Bicycle"):
        assert part in root


def test_functional_labels_show_no_parameters() -> None:
    svg = svg_of("uis1-functional.xmi")
    turn = next(text_of(g) for g in groups(svg, "sceml-lateral") if "TurnRight" in text_of(g))
    assert turn == "TurnRight TurnRight_1 ego"  # kind, name, actor (issue 14: both are shown)


def test_uis1_flows_follow_the_paper() -> None:
    document = io.load(EXAMPLES / "uis1-concrete.xmi")
    svg = parse(to_bytes(flow_diagram(document.root).graph, "svg"))
    titles = {
        g.get("id"): g.findtext("{http://www.w3.org/2000/svg}title")
        for g in groups(svg, "sceml-node")
    }
    names = {f"nodes.{i}": str(n.name) for i, n in enumerate(document.root.nodes)}
    edges = set()
    for group in groups(svg, "sceml-flow"):
        source, target = group.findtext("{http://www.w3.org/2000/svg}title").split("->")
        edges.add((names[source], names[target]))
    assert titles  # node ids are the fragments used above
    assert {
        ("Root", "Accelerate_1"),
        ("Accelerate_1", "TurnRight_1"),
        ("TurnRight_1", "InLocationRadius_1"),
        ("InLocationRadius_1", "End"),
        ("Root", "InVehicleRadius_1"),
        ("InVehicleRadius_1", "Accelerate_2"),
        ("Accelerate_2", "Cross_1"),
        ("Cross_1", "InLocationRadius_2"),
        ("InLocationRadius_2", "End"),
    } == edges


def test_collapsed_module_is_one_box_without_a_frame() -> None:
    svg = svg_of("uis2-logical.xmi")
    uses = groups(svg, "sceml-module-use")
    assert len(uses) == 1
    assert "CrossingManeuver" in text_of(uses[0])
    assert "crosser = pedestrian" in text_of(uses[0]) and "trigger = car" in text_of(uses[0])
    assert groups(svg, "sceml-module") == [] and groups(svg, "sceml-in-port") == []


def test_expanded_module_is_a_frame_with_ports_and_bound_actors() -> None:
    svg = svg_of("uis2-logical.xmi", modules="expanded")
    frames = groups(svg, "sceml-module")
    assert len(frames) == 1 and "CrossingManeuver_1: CrossingManeuver" in text_of(frames[0])
    assert len(groups(svg, "sceml-in-port")) == 1 and len(groups(svg, "sceml-out-port")) == 1
    inner = groups(svg, "sceml-actor-pedestrian")
    assert len(inner) == 4
    assert all(g.get("id").startswith(frames[0].get("id") + "/modules.0/") for g in inner)
    sync3 = next(text_of(g) for g in inner if "InVehicleRadius" in text_of(g))
    assert "pedestrian (crosser), target car (trigger)" in sync3
    assert "[10, 20] step 5 m ($triggerRadius)" in sync3
    assert groups(svg, "sceml-module-use") == []


def test_library_module_alone_and_the_choice_of_module() -> None:
    library = io.load(EXAMPLES / "library" / "sceml-library.xmi").root
    svg = parse(to_bytes(diagram(library, module="CrossingManeuver"), "svg"))
    assert len(groups(svg, "sceml-module")) == 1
    assert len(groups(svg, "sceml-condition")) == 2 and len(groups(svg, "sceml-lateral")) == 1
    frame = text_of(groups(svg, "sceml-module")[0])
    assert "role crosser: TwoWheeler | Pedestrian" in frame
    with pytest.raises(ModuleChoiceError, match="CrossingManeuver"):
        diagram(library)
    with pytest.raises(ModuleChoiceError, match="holds: CrossingManeuver"):
        diagram(library, module="Nope")


def _joins_scenario() -> scm.Scenario:
    b = ScenarioBuilder("Joins", map="Town03", level="functional")
    ego = b.actor("Car", "ego", ego=True)
    car = b.actor("Car", "car")
    a, c = b.add("Accelerate", ego), b.add("Overtake", ego, target=car)
    d, e = b.add("KeepVelocity", car), b.add("TimeElapsed", car)
    b.chain(b.root, a)
    b.chain(b.root, c)
    both = b.join_all(a, c)
    b.chain(both, d)
    b.chain(both, e)
    first = b.join_one(d, e)
    b.chain(first, b.end)
    return b.scenario


def test_joins_and_end_have_their_own_symbols() -> None:
    svg = parse(to_bytes(diagram(_joins_scenario(), legend=False), "svg"))
    assert (
        len(groups(svg, "sceml-join-all")) == 1 and text_of(groups(svg, "sceml-join-all")[0]) == "⇉"
    )
    assert (
        len(groups(svg, "sceml-join-one")) == 1 and text_of(groups(svg, "sceml-join-one")[0]) == "?"
    )
    assert text_of(groups(svg, "sceml-end")[0]) == "End"
    assert fills(groups(svg, "sceml-composite")[0]) == {"#81c995"}
    assert "ego, target car" in text_of(groups(svg, "sceml-composite")[0])


def test_legend_is_added_on_request() -> None:
    scenario = _joins_scenario()
    assert groups(parse(to_bytes(diagram(scenario), "svg")), "sceml-legend") == []
    svg = parse(to_bytes(diagram(scenario, legend=True), "svg"))
    assert len(groups(svg, "sceml-legend")) == 1
    assert len(groups(svg, "sceml-legend-sample")) == 13


def test_a_module_that_uses_itself_is_drawn_collapsed() -> None:
    library = LibraryBuilder("Loop")
    module = library.module("Again")
    role = module.role("who", "Car")
    module.chain(module.in_port, module.add("Stop", role), module.out_port)
    inner = module.use(library.library.modules[0], {"who": role})
    module.flow(module.in_port, inner)
    module.flow(inner, module.out_port)
    svg = parse(to_bytes(diagram(library.library, module="Again"), "svg"))
    broken = groups(svg, "sceml-broken")
    assert len(broken) == 1 and "recursive use" in text_of(broken[0])


def test_unresolved_module_is_drawn_as_a_broken_box(examples_copy: Path) -> None:
    (examples_copy / "library" / "sceml-library.xmi").unlink()
    root = io.load(examples_copy / "uis2-logical.xmi").root
    svg = parse(to_bytes(diagram(root, modules="expanded"), "svg"))
    broken = groups(svg, "sceml-broken")
    assert len(broken) == 1 and "definition not found" in text_of(broken[0])
