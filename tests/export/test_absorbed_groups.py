"""A trigger leaves out a ConditionGroup that tests all another group tests and more: the OR of
the groups means the same without it (A or (A and B) is A)."""

from __future__ import annotations

from sceml.export.triggers import Condition, activation


def names(groups: list[list[Condition]]) -> list[list[str]]:
    return [[c.name for c in group] for group in groups]


def test_a_group_testing_more_than_another_is_left_out() -> None:
    stop = [[Condition("Far", "entity", {"value": "30"})]]
    rest = [[Condition("Far", "entity", {"value": "30"}), Condition("Done", "state", ref="Go")]]
    # Either the stop, or the other branches joined with it: the second implies the first.
    assert names(activation([stop, rest], True, "End")) == [["Far"]]


def test_groups_that_test_different_things_stay() -> None:
    near = [[Condition("Near", "entity", {"value": "10"})]]
    far = [[Condition("Far", "entity", {"value": "30"}), Condition("Late", "time", delay="2")]]
    assert names(activation([near, far], True, "End")) == [["Near"], ["Far", "Late"]]


def test_what_a_condition_tests_is_its_kind_values_delay_and_reference_not_its_name() -> None:
    waited = [[Condition("A", "entity", {"value": "30"}, delay="1.0")]]
    sooner = [[Condition("B", "entity", {"value": "30"}), Condition("C", "state", ref="Go")]]
    # The same test after a delay is another test: nothing is left out.
    assert len(activation([waited, sooner], True, "End")) == 2
    renamed = [[Condition("B", "entity", {"value": "30"}, delay="1.0")]]
    both = [
        [Condition("A", "entity", {"value": "30"}, delay="1.0"), Condition("D", "state", ref="Go")]
    ]
    assert names(activation([renamed, both], True, "End")) == [["B"]]
