"""The editor in real Chromium against the real `sceml edit` server: mouse and keyboard only."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from browser import CHROMIUM
from playwright.sync_api import Locator, Page, Response, Route, expect

from sceml.diagnostics import Severity
from sceml.model.loading import load
from sceml.validation import validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# CI installs Chromium (scripts/setup.sh), so there a missing browser is a failure, not a skip.
pytestmark = pytest.mark.skipif(
    not CHROMIUM.exists() and not os.environ.get("CI"),
    reason="Debian's chromium (/usr/bin/chromium) is not installed",
)

SKIPPED = {"incoming", "outgoing", "diagramPosition"}


# --- canonical form of a scenario: what must be equal, whatever the order and layout ------------


def canonical(obj: object) -> object:
    """Attributes, contained objects (recursively) and references (by the target's name)."""
    if obj is None or isinstance(obj, (str, int, float, bool)):
        return obj
    if obj.eClass.name == "EEnumLiteral":
        return obj.name
    result: dict[str, object] = {"class": obj.eClass.name}
    for feature in obj.eClass.eAllStructuralFeatures():
        if feature.name in SKIPPED or feature.derived or feature.transient:
            continue
        value = obj.eGet(feature)
        items = list(value) if feature.many else [value]
        if feature.eClass.name == "EReference" and not feature.containment:
            items = [getattr(item, "name", None) for item in items]
        else:
            items = [canonical(item) for item in items]
        result[feature.name] = items if feature.many else items[0]
    return result


def scenario_form(path: Path) -> dict[str, object]:
    root = load(path).root
    return {
        "nodes": {node.name: canonical(node) for node in root.nodes},
        "flows": sorted((flow.source.name, flow.target.name) for flow in root.flows),
    }


# --- the page ------------------------------------------------------------------------------------


def open_editor(page: Page, url: str) -> Locator:
    page.goto(url)
    diagram = page.get_by_role("application", name="Diagram")
    expect(node(page, "Root")).to_be_visible()
    return diagram


def node(page: Page, name: str) -> Locator:
    return page.get_by_role("application", name="Diagram").locator(
        f'.react-flow__node[aria-label="{name}"]'
    )


def answered_ops(response: Response) -> bool:
    return response.url.endswith("/api/ops") and response.ok


def ops_answer(page: Page):  # noqa: ANN201 - Playwright's EventContextManager
    return page.expect_response(answered_ops)


def commit(page: Page, field: Locator, text: str, *, sends: bool = True) -> None:
    """Type `text` into a field and press Enter; wait for the op when the value changes the model.

    One try: a field must take what is typed even while the answer to the previous edit is
    still being drawn (it once was re-created under the cursor and dropped the typing).
    """
    if field.input_value() == text:
        return
    field.fill(text)
    if not sends:
        field.press("Enter")
        return
    with page.expect_response(answered_ops, timeout=3_000):
        field.press("Enter")


def choose(page: Page, select: Locator, value: str) -> None:
    if select.input_value() == value:
        return
    with ops_answer(page):
        select.select_option(value)


def set_position(page: Page, where: Locator, label: str, kind: str, values: dict[str, str]) -> None:
    """Fill a position: the optional coordinates first, the required ones last (one op)."""
    where.get_by_label(f"{label} type", exact=True).select_option(kind)
    items = list(values.items())
    for index, (name, text) in enumerate(items):
        field = where.get_by_label(f"{label} {name}", exact=True)
        commit(page, field, text, sends=index == len(items) - 1)


def connect(page: Page, source: str, target: str) -> None:
    out = node(page, source).locator(".react-flow__handle.source")
    into = node(page, target).locator(".react-flow__handle.target")
    with ops_answer(page):
        out.drag_to(into)


def drop(page: Page, label: str, x: float, y: float) -> None:
    item = page.get_by_role("region", name="Palette").get_by_role("button", name=label, exact=True)
    with ops_answer(page):
        item.drag_to(
            page.get_by_role("application", name="Diagram"), target_position={"x": x, "y": y}
        )


def save(page: Page) -> None:
    page.keyboard.press("Control+s")
    status = page.get_by_role("toolbar", name="Editor").get_by_role("status")
    expect(status).to_contain_text(re.compile(r"^Saved"))


# --- the tests -----------------------------------------------------------------------------------

WORLD = ("z", "heading", "x", "y")

# name (the auto name, in drop order), palette label, where to drop it, actor, parameters
UIS1_NODES = [
    ("Accelerate_1", "Accelerate", (230, 456), "ego", {"Target speed": "8", "Rate": "2"}),
    ("TurnRight_1", "TurnRight", (230, 606), "ego", {"Tolerance": "3"}),
    ("InLocationRadius_1", "InLocationRadius", (230, 756), "ego", {"Radius": "3"}),
    ("InVehicleRadius_1", "InVehicleRadius", (1030, 396), "bike", {"Radius": "12"}),
    ("Accelerate_2", "Accelerate", (1030, 526), "bike", {"Target speed": "4", "Rate": "1.5"}),
    ("Cross_1", "Cross", (1030, 656), "bike", {"Tolerance": "2"}),
    ("InLocationRadius_2", "InLocationRadius", (1030, 786), "bike", {"Radius": "2"}),
]
UIS1_POSITIONS = {
    "TurnRight_1": ("Destination", ["0", "0", "34", "-1.75"]),
    "InLocationRadius_1": ("Position", ["0", "0", "34", "-1.75"]),
    "Cross_1": ("Destination", ["0", "1.570796", "10", "4.5"]),
    "InLocationRadius_2": ("Position", ["0", "1.570796", "10", "4.5"]),
}
UIS1_FLOWS = [
    ("Root", "Accelerate_1"),
    ("Accelerate_1", "TurnRight_1"),
    ("TurnRight_1", "InLocationRadius_1"),
    ("InLocationRadius_1", "End"),
    ("Root", "InVehicleRadius_1"),
    ("InVehicleRadius_1", "Accelerate_2"),
    ("Accelerate_2", "Cross_1"),
    ("Cross_1", "InLocationRadius_2"),
    ("InLocationRadius_2", "End"),
]


def add_actor(page: Page, name: str, fields: dict[str, str], lane: list[str]) -> None:
    props = page.get_by_role("region", name="Properties")
    with ops_answer(page):
        props.get_by_role("button", name="Add actor").click()
    new = props.get_by_role("group", name=re.compile(r"^Actor car_\d+$"))
    commit(page, new.get_by_label("Name", exact=True), name)
    actor = props.get_by_role("group", name=f"Actor {name}")
    choose(page, actor.get_by_label("Kind", exact=True), fields["Kind"])
    if fields.get("Ego"):
        # A controlled checkbox: it shows the server's value, so click and wait for the view.
        with ops_answer(page):
            actor.get_by_label("Ego", exact=True).click()
        expect(actor.get_by_label("Ego", exact=True)).to_be_checked()
    commit(page, actor.get_by_label("Model", exact=True), fields["Model"])
    set_position(
        page,
        actor,
        "Start position",
        "lane",
        dict(zip(("offset", "road", "lane", "s"), lane, strict=True)),
    )
    commit(page, actor.get_by_label("Initial speed", exact=True), fields["Initial speed"])


def test_build_uis1_with_mouse_and_keyboard(
    page: Page, editor: object, examples_copy: Path
) -> None:
    target = examples_copy / "uis1-built.xmi"
    open_editor(page, editor(target))
    props = page.get_by_role("region", name="Properties")

    node(page, "Root").click()
    commit(page, props.get_by_label("Scenario name", exact=True), "UIS1")
    commit(
        page,
        props.get_by_label("Description", exact=True),
        "Urban intersection: the ego turns right while a bike crosses the street.",
    )
    commit(page, props.get_by_label("Date", exact=True), "2026-01-01T00:00:00")
    commit(page, props.get_by_label("Map", exact=True), "../maps/intersection.xodr")
    choose(page, props.get_by_label("Level", exact=True), "concrete")
    commit(page, props.get_by_label("Max duration", exact=True), "60")
    # A new scenario starts with the default environment written out, as the example has it.
    expect(props.get_by_label("Time of day", exact=True)).to_have_value("12:00:00")
    choose(page, props.get_by_label("Cloud state", exact=True), "free")
    choose(page, props.get_by_label("Precipitation", exact=True), "dry")
    add_actor(
        page,
        "ego",
        {"Kind": "Car", "Ego": "yes", "Model": "vehicle.tesla.model3", "Initial speed": "5"},
        ["0", "3", "1", "30"],
    )
    add_actor(
        page,
        "bike",
        {"Kind": "Bicycle", "Model": "vehicle.diamondback.century", "Initial speed": "0"},
        ["0", "3", "2", "15"],
    )

    for name, label, (x, y), actor, parameters in UIS1_NODES:
        drop(page, label, x, y)
        expect(node(page, name)).to_be_visible()
        expect(props.get_by_label("Name", exact=True)).to_have_value(name)
        choose(page, props.get_by_label("Reference actor", exact=True), actor)
        if name == "InVehicleRadius_1":
            choose(page, props.get_by_label("Target actor", exact=True), "ego")
        for label_, text in parameters.items():
            commit(page, props.get_by_label(label_, exact=True), text)
        if name in UIS1_POSITIONS:
            label_, values = UIS1_POSITIONS[name]
            set_position(page, props, label_, "world", dict(zip(WORLD, values, strict=True)))

    for source, target_name in UIS1_FLOWS:
        connect(page, source, target_name)
    save(page)

    document = load(target)
    errors = [d for d in validate(document.root) if d.severity is Severity.ERROR]
    assert errors == []
    assert scenario_form(target) == scenario_form(EXAMPLES / "uis1-concrete.xmi")


def test_place_crossing_maneuver_for_uis2(page: Page, editor: object, examples_copy: Path) -> None:
    target = examples_copy / "uis2-concrete.xmi"
    diagram = open_editor(page, editor(target))
    props = page.get_by_role("region", name="Properties")
    old = node(page, "CrossingManeuver_1")
    box, frame = old.bounding_box(), diagram.bounding_box()
    spot = {"x": box["x"] - frame["x"] + 20, "y": box["y"] - frame["y"] + 20}
    old.click()
    with ops_answer(page):
        page.keyboard.press("Delete")
    expect(old).to_have_count(0)

    item = page.get_by_role("region", name="Palette").get_by_role(
        "button", name="CrossingManeuver", exact=True
    )
    item.drag_to(diagram, target_position=spot)
    dialog = page.get_by_role("dialog", name="Use CrossingManeuver")
    dialog.get_by_label("crosser", exact=True).select_option("pedestrian")
    dialog.get_by_label("trigger", exact=True).select_option("car")
    with ops_answer(page):
        dialog.get_by_role("button", name="Add", exact=True).click()
    expect(dialog).to_have_count(0)
    expect(node(page, "CrossingManeuver_1")).to_be_visible()
    expect(props.get_by_label("Name", exact=True)).to_have_value("CrossingManeuver_1")
    expect(props.get_by_label("crosser", exact=True)).to_have_value("pedestrian")
    expect(props.get_by_label("trigger", exact=True)).to_have_value("car")
    overrides = {
        "triggerRadius": "15",
        "crossingSpeed": "1.5",
        "destinationX": "-10",
        "destinationY": "4.5",
        "destinationHeading": "1.570796",
    }
    for name, text in overrides.items():
        commit(page, props.get_by_label(name, exact=True), text)
    connect(page, "Root", "CrossingManeuver_1")
    connect(page, "CrossingManeuver_1", "End")
    save(page)

    use = next(n for n in load(target).root.nodes if n.name == "CrossingManeuver_1")
    assert {b.role: b.actor.name for b in use.bindings} == {
        "crosser": "pedestrian",
        "trigger": "car",
    }
    assert {o.parameter: o.value.value for o in use.overrides} == {
        name: float(text) for name, text in overrides.items()
    }
    errors = [d for d in validate(load(target).root) if d.severity is Severity.ERROR]
    assert errors == []
    assert scenario_form(target) == scenario_form(EXAMPLES / "uis2-concrete.xmi")


def test_live_validation_after_deleting_a_flow(
    page: Page, editor: object, examples_copy: Path
) -> None:
    diagram = open_editor(page, editor(examples_copy / "uis1-concrete.xmi"))
    turn = node(page, "TurnRight_1")
    expect(turn).not_to_have_attribute("data-severity", re.compile(".*"))
    source = node(page, "Accelerate_1").get_attribute("data-id")
    edge = diagram.locator(
        f'.react-flow__edge[aria-label="Edge from {source} to {turn.get_attribute("data-id")}"]'
    )
    edge.click()
    page.keyboard.press("Delete")
    expect(turn).to_have_attribute("data-severity", "error", timeout=1000)
    problems = page.get_by_role("region", name="Problems")
    problem = problems.get_by_role("button", name=re.compile(r"^SCEML-\S+ .*'TurnRight_1'"))
    expect(problem.first).to_be_visible(timeout=1000)
    problem.first.click()
    expect(turn).to_have_class(re.compile(r"\bselected\b"))
    page.keyboard.press("Control+z")
    expect(turn).not_to_have_attribute("data-severity", re.compile(".*"))
    expect(problem).to_have_count(0)
    expect(edge).to_have_count(1)


def test_read_only_mode(page: Page, editor: object, examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    before = target.read_bytes()
    open_editor(page, editor(target, "--read-only"))
    expect(page.get_by_role("region", name="Palette")).to_have_count(0)
    accelerate = node(page, "Accelerate_1")
    accelerate.click()
    props = page.get_by_role("region", name="Properties")
    expect(props.get_by_label("Name", exact=True)).to_be_disabled()
    expect(props.get_by_label("Target speed", exact=True)).to_be_disabled()
    expect(props.get_by_label("Reference actor", exact=True)).to_be_disabled()
    expect(page.get_by_role("button", name="Delete", exact=True)).to_be_disabled()
    expect(page.get_by_role("button", name="Save", exact=True)).to_be_disabled()
    page.keyboard.press("Delete")
    page.keyboard.press("Control+s")
    expect(accelerate).to_be_visible()
    expect(page.get_by_role("toolbar", name="Editor").get_by_role("status")).to_contain_text(
        re.compile(r"^Saved")
    )
    assert target.read_bytes() == before


LEAVING_IS_HELD = """() => {
    const event = new Event("beforeunload", { cancelable: true });
    window.dispatchEvent(event);
    return event.defaultPrevented;
}"""


def test_unsaved_work_is_never_lost_silently(
    page: Page, editor: object, examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    url = editor(target)
    open_editor(page, url)
    assert page.evaluate(LEAVING_IS_HELD) is False  # nothing to lose yet
    node(page, "Stop_1").wait_for(state="detached")
    with ops_answer(page):
        page.get_by_role("region", name="Palette").get_by_role("button", name="Stop").click()
    expect(node(page, "Stop_1")).to_be_visible()
    # Closing or leaving the tab now asks first (the browser shows its leave-page dialog).
    assert page.evaluate(LEAVING_IS_HELD) is True
    # A crashed or reloaded tab loses nothing: the model lives in the server.
    page.reload()
    open_editor(page, url)
    expect(node(page, "Stop_1")).to_be_visible()
    expect(page.get_by_role("toolbar", name="Editor").get_by_role("status")).to_contain_text(
        re.compile(r"^Unsaved changes")
    )
    save(page)
    assert page.evaluate(LEAVING_IS_HELD) is False
    assert b'name="Stop_1"' in target.read_bytes()


def test_a_dropped_node_shows_at_once_and_a_refused_one_goes(
    page: Page, editor: object, examples_copy: Path
) -> None:
    diagram = open_editor(page, editor(examples_copy / "uis2-concrete.xmi"))
    boxes = diagram.locator(".react-flow__node")
    before = boxes.count()
    pending = diagram.locator(".react-flow__node.pending")
    # The server's answer is held back: the box is drawn before it, greyed, named by its kind.
    held: list[Route] = []

    def hold(route: Route) -> None:
        held.append(route)

    page.route("**/api/ops", hold)
    item = page.get_by_role("region", name="Palette").get_by_role("button", name="Stop", exact=True)
    item.drag_to(diagram, target_position={"x": 300, "y": 120})
    expect(pending).to_have_count(1)
    expect(pending).to_have_attribute("aria-label", "Stop (adding)")
    expect(boxes).to_have_count(before + 1)
    with ops_answer(page):
        held[0].continue_()
    page.unroute("**/api/ops")
    # The answer brings the node itself in the box's place.
    expect(pending).to_have_count(0)
    expect(node(page, "Stop_1")).to_be_visible()
    expect(boxes).to_have_count(before + 1)

    # Refused: the box goes, and nothing else was added.
    page.route(
        "**/api/ops",
        lambda route: route.fulfill(
            status=400, content_type="application/json", body='{"error": "refused for the test"}'
        ),
    )
    item.drag_to(diagram, target_position={"x": 420, "y": 120})
    expect(page.get_by_role("alert")).to_contain_text("refused for the test")
    expect(pending).to_have_count(0)
    expect(boxes).to_have_count(before + 1)


def test_a_value_reads_as_the_server_writes_it(
    page: Page, editor: object, examples_copy: Path
) -> None:
    open_editor(page, editor(examples_copy / "uis1-logical.xmi"))
    node(page, "Accelerate_1").click()
    props = page.get_by_role("region", name="Properties")
    speed = props.get_by_role("group", name="Target speed")
    expect(speed).to_contain_text("N(8, 1) in [6, 10] m/s = mean 28.8 km/h")
    commit(page, speed.get_by_label("Target speed mean", exact=True), "9")
    # The text is the server's answer to the edit, km/h and all.
    expect(speed).to_contain_text("N(9, 1) in [6, 10] m/s = mean 32.4 km/h")
    expect(speed).not_to_contain_text("28.8 km/h")
