"""The page's types.ts says what the server sends: each ParamValue and Position kind, with the
same fields as editor/values.py writes (a change on one side fails here until the other follows)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

import scemlmodel as scm
from sceml.editor.values import RELATIVE_TYPES, VALUE_TYPES, position_to_json, value_to_json

TYPES = Path(__file__).resolve().parents[2] / "web" / "src" / "types.ts"


def union(name: str) -> dict[str, set[str]]:
    """The members of `export type NAME = | { type: "x"; a: ...; b: ... } | ...` by their tag."""
    text = TYPES.read_text(encoding="utf-8")
    found = re.search(rf"export type {name} =(.*?);\n\n", text, re.S)
    assert found, f"types.ts has no union {name}"
    members = {}
    for body in re.findall(r"\{([^{}]*)\}", found.group(1)):
        fields = dict(re.findall(r"(\w+): ([^;]+)", body))
        tag = fields.pop("type").strip().strip('"')
        members[tag] = set(fields)
    return members


def keys(sent: dict[str, Any] | None) -> tuple[str, set[str]]:
    assert sent is not None
    return sent["type"], set(sent) - {"type"}


def test_the_value_kinds_are_the_servers() -> None:
    assert list(union("ParamValue")) == list(VALUE_TYPES)


@pytest.mark.parametrize(
    "value",
    [
        scm.Value(value=1.0),
        scm.Range(min=1.0, max=2.0),
        scm.UniformDistribution(min=1.0, max=2.0),
        scm.NormalDistribution(mean=1.0, standardDeviation=0.5),
        scm.DiscreteDistribution(),
        scm.ParameterRef(),
    ],
    ids=lambda value: value.eClass.name,
)
def test_each_value_kind_has_the_fields_the_server_sends(value: scm.ParameterValue) -> None:
    kind, sent = keys(value_to_json(value))
    assert union("ParamValue")[kind] == sent


@pytest.mark.parametrize(
    "name", ["WorldPosition", "LanePosition", "RoadPosition", "RoutePosition", *RELATIVE_TYPES]
)
def test_each_position_kind_has_the_fields_the_server_sends(name: str) -> None:
    kind, sent = keys(position_to_json(getattr(scm, name)()))
    assert union("Position")[kind] == sent
