"""Numbers as OpenSCENARIO writes them, and the hook that turns chosen ones into `$parameter`s."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from pyecore.ecore import EObject

from ..model import params
from ..model.locating import model_path


@dataclass(frozen=True)
class ParameterDeclarationSpec:
    """A top-level ParameterDeclaration that replaces one numeric value of the model."""

    name: str
    value: str
    type: str = "double"


ParameterHook = Mapping[tuple[str, str], ParameterDeclarationSpec]


def number(value: float) -> str:
    """Shortest text that reads back as the same double (`5.0`, `1.570796`), so output is stable."""
    return repr(float(value))


class Values:
    """Reads the single values of a concrete (flattened) model, applying the parameter hook."""

    def __init__(self, parameters: ParameterHook | None = None) -> None:
        self._parameters = parameters or {}
        self.declarations: dict[str, ParameterDeclarationSpec] = {}

    def raw(self, owner: EObject, feature: str) -> float:
        """The concrete number, for values the exporter computes with."""
        return params.concrete(owner, feature)

    def text(self, owner: EObject, feature: str) -> str:
        """The number as written: `$name` where the hook names this value, else the literal."""
        if self._parameters:
            spec = self._parameters.get((model_path(owner), feature))
            if spec is not None:
                self.declarations[spec.name] = spec
                return f"${spec.name}"
        return number(params.concrete(owner, feature))
