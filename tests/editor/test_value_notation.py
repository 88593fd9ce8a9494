"""The server's display text of values, and the page's edit text, against one case table.

web/src/lib/__tests__/value-notation.json is read here and by the page's vitest: the server
shows each value as `shown`, and its notation without the unit is the page's `edit` text
wherever no number needs more than six digits.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

import scemlmodel as scm
from sceml.editor.values import value_from_json, value_text
from sceml.model import params

CASES = Path(__file__).resolve().parents[2] / "web/src/lib/__tests__/value-notation.json"


def cases() -> list[dict[str, Any]]:
    loaded: list[dict[str, Any]] = json.loads(CASES.read_text(encoding="utf-8"))["cases"]
    return loaded


def made(case: dict[str, Any]) -> scm.ParameterValue:
    """The model value of a case; a reference names a module parameter with no default."""
    value = value_from_json(case["value"], lambda name: scm.ModuleParameter(name=name))
    assert value is not None
    return value


@pytest.mark.parametrize("case", cases(), ids=lambda case: case["shown"])
def test_the_server_shows_each_value_as_the_table_says(case: dict[str, Any]) -> None:
    assert value_text(made(case), case["unit"]) == case["shown"]


@pytest.mark.parametrize("case", cases(), ids=lambda case: case["edit"])
def test_the_page_edits_in_the_servers_notation(case: dict[str, Any]) -> None:
    written = params.describe(made(case))
    if case.get("rounded"):
        # Six digits on show; the input keeps them all.
        assert written != case["edit"]
        assert written in case["shown"]
    else:
        assert written == case["edit"]


def test_the_table_covers_every_kind_of_value() -> None:
    from sceml.editor.values import VALUE_TYPES

    assert {case["value"]["type"] for case in cases()} == set(VALUE_TYPES)
