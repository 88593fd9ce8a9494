"""OpenSCENARIO 1.0-1.3 export of concrete SceML scenarios (SPEC §7).

Entry points:

- `export(scenario, *, version="1.3", profile="generic", date=None, source_path=None,
  map_path=None, output_path=None, parameters=None, town=None, check_model=True)` returns the
  validated lxml tree;
- `export_to_file(scenario, path, **same)` writes it atomically and returns the path;
- `build_xosc(scenario, **same)` is the batch fast path: it returns `XoscDocument(data, tree,
  events_of)`, rendering with the precompiled templates, parsing once and validating the tree
  with the schema loaded once. Pass `check_model=False` when the caller has already validated.

Scenarios with module uses are flattened first. Functional and logical scenarios, invalid models
and nodes a version/profile cannot express raise `ExportError` with diagnostics; an output that
fails the XSD raises `InvalidOutputError` and nothing is written.

Parameterised export (issue 6): `parameters` maps `(model path, feature)` to a
`ParameterDeclarationSpec(name, value, type="double")`. The model path is `io.model_path` of the
object owning the value in the FLATTENED scenario (e.g. `Root/ego` with feature `initialSpeed`,
or `Accelerate_1` with `targetSpeed`, or a position such as `TurnRight_1/destination` with `x`).
Each value so keyed is written as `$name`, and a `<ParameterDeclaration name=... parameterType=...
value=...>` is added to the top-level ParameterDeclarations. Values the exporter derives
(bounding-box centre, the CARLA speed-change duration, the overtake arrival tolerance) stay
literal; DriveDistance's duration of parameters is the expression `${$distance / $speed}` (1.1+).

`sceml.xosc.support.unsupported_reason(kind, version, profile)` says why a node kind cannot be exported.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..xosc.support import supported_kinds, unsupported_reason
    from .values import ParameterDeclarationSpec
    from .writer import (
        ExportError,
        InvalidOutputError,
        XoscDocument,
        build_xosc,
        export,
        export_to_file,
    )

#: Where each public name lives. Imported on first use, so that importing a light submodule
#: (`sceml.export.versions`) does not load Jinja2 and the templates.
_HOMES = {
    "supported_kinds": "..xosc.support",
    "unsupported_reason": "..xosc.support",
    "ParameterDeclarationSpec": ".values",
    "ExportError": ".writer",
    "InvalidOutputError": ".writer",
    "XoscDocument": ".writer",
    "build_xosc": ".writer",
    "export": ".writer",
    "export_to_file": ".writer",
}


def __getattr__(name: str) -> Any:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(home, __name__), name)


__all__ = [
    "ExportError",
    "InvalidOutputError",
    "ParameterDeclarationSpec",
    "XoscDocument",
    "build_xosc",
    "export",
    "export_to_file",
    "supported_kinds",
    "unsupported_reason",
]
