"""Labels of the global kinds: no actor, what they read or change as an operator."""

from __future__ import annotations

import scemlmodel as scm
from sceml.render.labels import Scope, action_lines


def test_global_nodes_read_as_what_they_do() -> None:
    raise_it = scm.SetVariable(variable="Counter", value="2", modify=scm.ModifyRule.add)
    high = scm.ParameterCondition(
        parameter="Counter", value="4", rule=scm.ComparisonRule.greaterThan
    )
    carla = scm.ParameterCondition(parameter="", value="", rule=scm.ComparisonRule.lessThan)
    assert action_lines(raise_it, Scope()) == ["global", "variable Counter += 2"]
    assert action_lines(high, Scope()) == ["global", "parameter Counter > 4"]
    assert action_lines(carla, Scope()) == ["global", "parameter (unnamed) <"]


def test_traffic_signal_nodes_read_as_the_state() -> None:
    green = scm.TrafficSignalState(signalId="1", state="off;off;on")
    red = scm.TrafficSignalCondition(signalId="1", state="on;off;off")
    assert action_lines(green, Scope()) == ["global", "signal 1 = off;off;on"]
    assert action_lines(red, Scope()) == ["global", "signal 1 == on;off;off"]
