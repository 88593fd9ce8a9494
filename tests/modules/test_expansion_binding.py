"""Module expansion binds parameters by writing pyecore's end state directly
(`model.fastobjects.replace_child`): the copies, the values they were given and the parameter
references they let go must be left exactly as pyecore's setter leaves them, on every file with
module uses of the examples and the validation corpus."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from core.model_state import difference, model_state
from pyecore.ecore import EObject

import scemlmodel as scm
from sceml.errors import LoadError
from sceml.model.loading import load
from sceml.modules import expansion as expansion_module
from sceml.modules.errors import FlattenError

REPO = Path(__file__).resolve().parents[2]
FILES = sorted(
    path
    for path in [*(REPO / "examples").rglob("*.xmi"), *(REPO / "tests").rglob("*.xmi")]
    if b"ModuleUse" in path.read_bytes() and b"<sceml:Library" not in path.read_bytes()[:400]
)


def _expanded_state(path: Path) -> Any:
    try:
        scenario = load(path).root
    except LoadError as error:
        return f"unreadable: {error}"
    if not isinstance(scenario, scm.Scenario):
        return "not a scenario"
    try:
        flat = expansion_module.expansion(scenario)
    except FlattenError as error:
        return f"refused: {error}"
    roots: dict[str, EObject] = {"scenario": scenario}
    # Every copy without a container (the expanded nodes, and the parameter references let go).
    for i, copy in enumerate(copy for copy in flat.origins if copy.eContainer() is None):
        roots[f"copy{i}"] = copy
    return model_state(roots)


def test_there_are_files_with_parameters_to_bind() -> None:
    assert len(FILES) >= 5
    assert any(b"overrides" in path.read_bytes() for path in FILES)


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(REPO)))
def test_binding_leaves_what_pyecores_setter_leaves(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    direct = _expanded_state(path)
    with monkeypatch.context() as patched:
        patched.setattr(expansion_module, "replace_child", lambda *arguments: False)
        through_setter = _expanded_state(path)
    assert difference(through_setter, direct) is None
