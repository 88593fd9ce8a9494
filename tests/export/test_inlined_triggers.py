"""Which nodes the export writes into their successor's trigger (`xosc.flows.inlined`), and
what it writes there: worked out by hand from SPEC §3 on small graphs built here."""

from __future__ import annotations

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import ExportError, ParameterDeclarationSpec, build_xosc
from sceml.model.build import ScenarioBuilder, world
from sceml.xosc.flows import flow_steps, inlined

SIZE = {"length": 4.0, "width": 2.0}


def built() -> tuple[ScenarioBuilder, dict[str, scm.GraphElement]]:
    """root -> Fast -> SpeedUp -> Wait1 -> Wait2 -> Brake -> End;
    root -> Near -> Follow -> End; root -> Short, root -> Long, both -> AnyOf -> End."""
    b = ScenarioBuilder("inline", map="map.xodr", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
    n = {
        "Fast": b.add("SpeedCondition", ego, speed=9.0, rule="greaterThan"),
        "SpeedUp": b.add("Accelerate", ego, targetSpeed=14.0, rate=2.0),
        "Wait1": b.add("TimeElapsed", ego, duration=1.5),
        "Wait2": b.add("TimeElapsed", ego, duration=0.5),
        "Brake": b.add("Decelerate", ego, targetSpeed=6.0, rate=3.0),
        "Near": b.add("InVehicleRadius", lead, target=ego, radius=20.0),
        "Follow": b.add("Follow", lead, target=ego, distance=15.0),
        "Short": b.add("TimeElapsed", ego, duration=1.0),
        "Long": b.add("TimeElapsed", ego, duration=2.0),
    }
    for name, node in n.items():
        node.name = name
    b.chain(b.root, n["Fast"], n["SpeedUp"], n["Wait1"], n["Wait2"], n["Brake"], b.end)
    b.chain(b.root, n["Near"], n["Follow"], b.end)
    b.chain(b.root, n["Short"])
    b.chain(b.root, n["Long"])
    any_of = b.join_one(n["Short"], n["Long"])
    any_of.name = "AnyOf"
    n["AnyOf"] = any_of
    b.chain(any_of, b.end)
    return b, n


def test_only_what_keeps_its_meaning_is_inlined() -> None:
    b, n = built()
    found = {str(node.name) for node in inlined(b.scenario.nodes)}
    # Fast and Near: their successor waits for them alone and starts one event on them (Follow's
    # finish marker waits for Follow's event to have started, not for its activation again).
    # The waits and the join-one stay true once true.
    assert found == {"Fast", "Near", "Wait1", "Wait2", "Short", "Long", "AnyOf"}


def trigger(document: etree._Element, path: str) -> list[list[tuple[str, str, str]]]:
    """Each ConditionGroup as (kind of condition, what it refers to or its value, delay)."""
    groups = []
    for group in document.iterfind(f"{path}/ConditionGroup"):
        read = []
        for condition in group.iterfind("Condition"):
            inner = condition.find("ByValueCondition/*")
            if inner is None:
                inner = condition.find(".//EntityCondition/*")
            target = inner.get("storyboardElementRef") or inner.get("value")
            read.append((inner.tag, str(target), str(float(condition.get("delay")))))
        groups.append(sorted(read))
    return sorted(groups)


def test_the_triggers_hold_the_inlined_conditions() -> None:
    b, _ = built()
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    names = {str(e.get("name")) for e in document.iter("Event")}
    assert {"Fast", "Near", "Wait1", "Wait2", "Short", "Long", "AnyOf"}.isdisjoint(names)
    # SpeedUp: the start AND the speed condition, in the step it holds.
    assert trigger(document, ".//Event[@name='SpeedUp']/StartTrigger") == [
        [("SimulationTimeCondition", "0.0", "0.0"), ("SpeedCondition", "9.0", "0.0")]
    ]
    # Brake: SpeedUp completed, delayed by both waits: 1.5 + 0.5 s.
    assert trigger(document, ".//Event[@name='Brake']/StartTrigger") == [
        [("StoryboardElementStateCondition", "SpeedUp", "2.0")]
    ]
    # Follow: the start AND lead within 20 m of ego, in the step it holds.
    assert trigger(document, ".//Event[@name='Follow']/StartTrigger") == [
        [("RelativeDistanceCondition", "20.0", "0.0"), ("SimulationTimeCondition", "0.0", "0.0")]
    ]
    # Its gap: Follow's event running (or complete) AND the gap under 15 m + 10 % slack, the
    # radius not asked again.
    marker = ".//Event[@name='Follow__gap_reached']/StartTrigger"
    assert trigger(document, marker) == 2 * [
        [
            ("RelativeDistanceCondition", "16.5", "0.0"),
            ("StoryboardElementStateCondition", "Follow", "0.0"),
        ]
    ]
    states = [
        e.get("state") for e in document.iterfind(f"{marker}//StoryboardElementStateCondition")
    ]
    assert states == ["runningState", "completeState"]
    # The end: Brake and Follow's gap and (the join-one of the two waits, each a delay of the
    # start) in one group each of the join-one's alternatives, or the maximum duration.
    follow_done = "Follow__gap_reached"
    assert trigger(document, "Storyboard/StopTrigger") == [
        [
            ("SimulationTimeCondition", "0.0", "1.0"),
            ("StoryboardElementStateCondition", "Brake", "0.0"),
            ("StoryboardElementStateCondition", follow_done, "0.0"),
        ],
        [
            ("SimulationTimeCondition", "0.0", "2.0"),
            ("StoryboardElementStateCondition", "Brake", "0.0"),
            ("StoryboardElementStateCondition", follow_done, "0.0"),
        ],
        [("SimulationTimeCondition", "30.0", "0.0")],
    ]


def test_parameterised_waits_in_a_row_add_up_as_an_expression() -> None:
    # Wait1 and Wait2 (1.5 s, 0.5 s) as parameters: Brake's delay is their sum, which 1.1+
    # write as an expression and 1.0, which has none, refuses with the reason.
    b, _ = built()
    hook = {
        ("Wait1", "duration"): ParameterDeclarationSpec("First", "1.5"),
        ("Wait2", "duration"): ParameterDeclarationSpec("Second", "0.5"),
    }
    document = build_xosc(b.scenario, version="1.1", parameters=hook).tree.getroot()
    (condition,) = document.iterfind(".//Event[@name='Brake']/StartTrigger//Condition")
    assert condition.get("delay") == "${$First + $Second}"
    with pytest.raises(ExportError, match="1.0 has no expressions"):
        build_xosc(b.scenario, version="1.0", parameters=hook)


def test_a_condition_and_the_wait_after_it_go_into_the_trigger_as_its_delay() -> None:
    # root -> Slow (speed below 12) -> Pause (2 s) -> Brake: an original's condition with a
    # delay. A player counts the delay from each instant the condition held, as SceML counts
    # the wait from the condition's finish, so both go into Brake's trigger: no marker event,
    # and Brake starts 2 s after the speed first held, not a step later.
    b = ScenarioBuilder("delayed", map="map.xodr", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    slow = b.add("SpeedCondition", ego, speed=12.0, rule="lessThan")
    pause = b.add("TimeElapsed", ego, duration=2.0)
    brake = b.add("Decelerate", ego, targetSpeed=6.0, rate=3.0)
    slow.name, pause.name, brake.name = "Slow", "Pause", "Brake"
    b.chain(b.root, slow, pause, brake, b.end)
    assert {str(node.name) for node in inlined(b.scenario.nodes)} == {"Slow", "Pause"}
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert trigger(document, ".//Event[@name='Brake']/StartTrigger") == [
        [("SimulationTimeCondition", "0.0", "2.0"), ("SpeedCondition", "12.0", "2.0")]
    ]
    # A wait with two successors, one of them waiting for something else too: the condition
    # keeps its marker (a delayed condition ANDed with another would be "held 2 s ago").
    other = b.add("KeepVelocity", ego, duration=1.0)
    both = b.join_all(pause, other)
    b.chain(b.root, other)
    b.chain(both, b.end)
    assert "Slow" not in {str(node.name) for node in inlined(b.scenario.nodes)}


def test_a_traffic_signal_condition_goes_into_the_trigger_of_the_state_it_starts() -> None:
    # root -> Yellow (signal 1 is yellow) -> Red (set signal 2 red): the global condition is
    # written into the global action's trigger, as any condition is (it had a marker event of
    # its own, a step before the action: `traffic_lights`).
    b = ScenarioBuilder("signals", map="map.xodr", level="concrete", max_duration=30.0)
    b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    yellow = b.add("TrafficSignalCondition", None, signalId="1", state="yellow")
    red = b.add("TrafficSignalState", None, signalId="2", state="red")
    yellow.name, red.name = "Yellow", "Red"
    b.chain(b.root, yellow, red, b.end)
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert document.find(".//Event[@name='Yellow']") is None
    start = document.find(".//Event[@name='Red']/StartTrigger/ConditionGroup")
    assert start is not None
    signal = start.find("Condition/ByValueCondition/TrafficSignalCondition")
    assert signal is not None and (signal.get("name"), signal.get("state")) == ("1", "yellow")
    # Named after the condition node, so that an import gives the node its name back.
    assert signal.getparent().getparent().get("name") == "Yellow"


def ending_on_a_condition(policy: str) -> tuple[ScenarioBuilder, dict[str, scm.GraphElement]]:
    """root -> Near (the lead within 20 m of the ego) -> End; root -> Brake -> End; and Near
    and Brake -> Both (join-all) -> End: an imported StopTrigger's condition, which the
    import also joins with the branches it does not name (`importer.ending`)."""
    b = ScenarioBuilder(
        "stops", map="map.xodr", level="concrete", max_duration=30.0, end_policy=policy
    )
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
    n = {
        "Near": b.add("InVehicleRadius", lead, target=ego, radius=20.0),
        "Brake": b.add("Decelerate", ego, targetSpeed=6.0, rate=3.0),
    }
    for name, node in n.items():
        node.name = name
    b.chain(b.root, n["Near"], b.end)
    b.chain(b.root, n["Brake"])
    n["Both"] = b.join_all(n["Near"], n["Brake"], name="Both")
    b.chain(n["Both"], b.end)
    return b, n


def test_a_condition_that_ends_the_run_goes_into_the_stop_trigger() -> None:
    # The end waits for one of its predecessors: the StopTrigger stops the run in the step
    # Near holds, as the original's did (`pedestrian_traj_synch`: a marker event for Near
    # before it ended the run 0.1 s late). Both adds nothing: it waits for Near too, so the
    # run has stopped by the time it could finish, and its group is left out.
    b, n = ending_on_a_condition("joinOne")
    assert {str(node.name) for node in inlined(b.scenario.nodes)} == {"Near", "Both"}
    # What each flow costs in steps, worked out by hand: none out of Near (in the
    # StopTrigger) or Both (a join), and none out of the root; one out of Brake (its event's
    # completion is seen a step later).
    inline = inlined(b.scenario.nodes)
    assert [flow_steps(n[k], inline) for k in ("Near", "Both", "Brake")] == [0, 0, 1]
    assert flow_steps(b.root, inline) == 0
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert document.find(".//Event[@name='Near']") is None
    assert trigger(document, "Storyboard/StopTrigger") == [
        [("RelativeDistanceCondition", "20.0", "0.0"), ("SimulationTimeCondition", "0.0", "0.0")],
        [("SimulationTimeCondition", "30.0", "0.0")],
    ]


def test_a_condition_keeps_its_marker_before_an_end_that_waits_for_all() -> None:
    # The end waits for Near and Both: Near's "has held" must stay true until Brake is done.
    b, _ = ending_on_a_condition("joinAll")
    assert "Near" not in {str(node.name) for node in inlined(b.scenario.nodes)}
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert document.find(".//Event[@name='Near']") is not None


def test_a_condition_before_an_arrival_costs_no_step() -> None:
    # root -> Near (the ego within 20 m of the lead) -> Pause (0.5 s) -> Walk (a
    # FollowTrajectory of the lead) -> End. Walk's arrival marker waits for Walk's own event
    # to have started (running or complete), not for its activation again, so Near and the
    # pause go into Walk's trigger: Walk starts 0.5 s after Near first holds, no step later
    # (`traffic_lights`' walkers were two steps late on their marker). A DriveDistance's marker
    # still ANDs its activation with its time: the condition before it keeps its marker event,
    # and its successor one step.
    b = ScenarioBuilder("arrival", map="map.xodr", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
    near = b.add("InVehicleRadius", ego, target=lead, radius=20.0)
    pause = b.add("TimeElapsed", ego, duration=0.5)
    walk = b.add("FollowTrajectory", lead, waypoints=[world(60.0, 0.0), world(80.0, 0.0)])
    close = b.add("InVehicleRadius", lead, target=ego, radius=10.0)
    drive = b.add("DriveDistance", lead, speed=8.0, distance=40.0)
    for node, name in ((near, "Near"), (pause, "Pause"), (walk, "Walk"), (close, "Close")):
        node.name = name
    drive.name = "Drive"
    b.chain(b.root, near, pause, walk, b.end)
    b.chain(b.root, close, drive, b.end)
    inline = inlined(b.scenario.nodes)
    assert {str(node.name) for node in inline} == {"Near", "Pause"}
    assert (flow_steps(near, inline), flow_steps(pause, inline)) == (0, 0)
    assert flow_steps(close, inline) == 1
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert document.find(".//Event[@name='Near']") is None
    assert trigger(document, ".//Event[@name='Walk']/StartTrigger") == [
        [("RelativeDistanceCondition", "20.0", "0.5"), ("SimulationTimeCondition", "0.0", "0.5")]
    ]
    arrived = trigger(document, ".//Event[@name='Walk__arrived']/StartTrigger")
    assert [[kind for kind, _, _ in group] for group in arrived] == [
        ["DistanceCondition", "StoryboardElementStateCondition"]
    ] * 2
    states = {
        (c.get("storyboardElementRef"), c.get("state"))
        for c in document.iterfind(
            ".//Event[@name='Walk__arrived']//StoryboardElementStateCondition"
        )
    }
    assert states == {("Walk", "runningState"), ("Walk", "completeState")}
    # scenario_runner keeps a startTransition once seen and reads no runningState (and has no
    # TimeElapsed: its delays count from the act's start).
    b = ScenarioBuilder("arrival", map="Town01", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
    near = b.add("InVehicleRadius", ego, target=lead, radius=20.0)
    walk = b.add("FollowTrajectory", lead, waypoints=[world(60.0, 0.0), world(80.0, 0.0)])
    near.name, walk.name = "Near", "Walk"
    b.chain(b.root, near, walk, b.end)
    carla = build_xosc(b.scenario, version="1.0", profile="carla").tree.getroot()
    assert carla.find(".//Event[@name='Near']") is None
    states = {
        (c.get("storyboardElementRef"), c.get("state"))
        for c in carla.iterfind(".//Event[@name='Walk__arrived']//StoryboardElementStateCondition")
    }
    assert states == {("Walk", "startTransition")}


def test_conditions_of_a_join_one_go_into_the_trigger_as_groups() -> None:
    # root -> Fast (speed above 12) and root -> Near (the lead within 20 m), both -> AnyOf
    # (join-one) -> Brake -> End: an original's trigger of two ConditionGroups. Brake starts
    # at the first instant either holds, so each goes into Brake's trigger as a group of its
    # own, and neither costs a step (they were marker events, Brake a step after them). A
    # successor that runs twice would need the join-one's finish to repeat, which players do
    # not see in a trigger: there the conditions keep their markers.
    b = ScenarioBuilder("anyof", map="map.xodr", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
    fast = b.add("SpeedCondition", ego, speed=12.0, rule="greaterThan")
    near = b.add("InVehicleRadius", ego, target=lead, radius=20.0)
    brake = b.add("Decelerate", ego, targetSpeed=6.0, rate=3.0)
    fast.name, near.name, brake.name = "Fast", "Near", "Brake"
    b.chain(b.root, fast)
    b.chain(b.root, near)
    any_of = b.join_one(fast, near)
    any_of.name = "AnyOf"
    b.chain(any_of, brake, b.end)
    inline = inlined(b.scenario.nodes)
    assert {str(node.name) for node in inline} == {"Fast", "Near", "AnyOf"}
    assert (flow_steps(fast, inline), flow_steps(near, inline)) == (0, 0)
    document = build_xosc(b.scenario, version="1.3").tree.getroot()
    assert document.find(".//Event[@name='Fast']") is None
    assert trigger(document, ".//Event[@name='Brake']/StartTrigger") == [
        [("RelativeDistanceCondition", "20.0", "0.0"), ("SimulationTimeCondition", "0.0", "0.0")],
        [("SimulationTimeCondition", "0.0", "0.0"), ("SpeedCondition", "12.0", "0.0")],
    ]
    brake.maxRuns = 2
    assert {str(node.name) for node in inlined(b.scenario.nodes)} == {"AnyOf"}


def test_a_condition_before_a_follow_costs_no_step() -> None:
    # root -> Close (lead within 30 m of ego) -> Keep (lead follows ego at 15 m) -> End, as
    # `long_dist_action_with_jerk` has it: Close goes into Keep's trigger and costs no step;
    # the gap marker waits for Keep's event to have started (carla: its startTransition).
    for profile, version, started in (
        ("generic", "1.3", {"runningState", "completeState"}),
        ("carla", "1.0", {"startTransition"}),
    ):
        road = "Town01" if profile == "carla" else "map.xodr"
        b = ScenarioBuilder("follow", map=road, level="concrete", max_duration=30.0)
        ego = b.actor("Car", "ego", ego=True, start=world(40.0, 0.0, h=0.0), speed=8.0, **SIZE)
        lead = b.actor("Car", "lead", start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
        close = b.add("InVehicleRadius", lead, target=ego, radius=30.0)
        keep = b.add("Follow", lead, target=ego, distance=15.0)
        close.name, keep.name = "Close", "Keep"
        b.chain(b.root, close, keep, b.end)
        inline = inlined(b.scenario.nodes)
        assert {str(node.name) for node in inline} == {"Close"}
        assert flow_steps(close, inline) == 0
        document = build_xosc(b.scenario, version=version, profile=profile).tree.getroot()
        assert document.find(".//Event[@name='Close']") is None
        kinds = trigger(document, ".//Event[@name='Keep']/StartTrigger")
        assert [[kind for kind, _, _ in group] for group in kinds] == [
            ["RelativeDistanceCondition", "SimulationTimeCondition"]
        ]
        marker = ".//Event[@name='Keep__gap_reached']/StartTrigger"
        states = {
            (c.get("storyboardElementRef"), c.get("state"))
            for c in document.iterfind(f"{marker}//StoryboardElementStateCondition")
        }
        assert states == {("Keep", state) for state in started}
        values = {c.get("value") for c in document.iterfind(f"{marker}//RelativeDistanceCondition")}
        assert values == {"16.5"}  # the gap (15 m) and 1.5 m slack, not Close's 30 m again
