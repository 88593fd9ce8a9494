"""Modules and libraries: list, show, instantiate, flatten and extract reusable sub-scenarios.

A module definition lives in a library file; scenarios (and other modules) use it through a
ModuleUse that binds its roles to actors and may override its parameters. See docs/modules.md.
"""

import importlib
import sys
import types
from typing import TYPE_CHECKING, Any

from .errors import ExtractError, FlattenError, UnknownModuleError
from .flatten import Flattened, Origin, expand, flatten
from .resolve import resolved_definition

if TYPE_CHECKING:
    from .extract import Region, RoleSpec, extract, find_region, parse_role
    from .library import (
        DefinitionDetail,
        DefinitionSummary,
        definition_named,
        depth,
        instantiate,
        list_definitions,
        show,
    )
    from .store import ExtractReport, FlattenReport, extract_file, flatten_file, save_together

#: Names whose submodule is imported when one of them is first asked for. `sceml validate`
#: imports this package for the expansion alone; extracting, the library listing (with the
#: scenario builder) and the store were about 10 ms of its start.
_LAZY = {
    **dict.fromkeys(("Region", "RoleSpec", "extract", "find_region", "parse_role"), "extract"),
    **dict.fromkeys(
        (
            "DefinitionDetail",
            "DefinitionSummary",
            "definition_named",
            "depth",
            "instantiate",
            "list_definitions",
            "show",
        ),
        "library",
    ),
    **dict.fromkeys(
        ("ExtractReport", "FlattenReport", "extract_file", "flatten_file", "save_together"),
        "store",
    ),
}


def __getattr__(name: str) -> Any:
    submodule = _LAZY.get(name)
    if submodule is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{submodule}"), name)
    globals()[name] = value
    return value


class _Package(types.ModuleType):
    """This package, keeping `extract` the function.

    Importing a submodule binds it in its package under its own name: once
    `sceml.modules.extract` is imported (the editor imports it directly), the package's
    `extract` would be that module. When every name was imported here at once, the function
    was bound after the module and stayed.
    """

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "extract" and isinstance(value, types.ModuleType):
            value = value.extract
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package

__all__ = [
    "DefinitionDetail",
    "DefinitionSummary",
    "ExtractError",
    "ExtractReport",
    "FlattenError",
    "FlattenReport",
    "Flattened",
    "Origin",
    "Region",
    "RoleSpec",
    "UnknownModuleError",
    "definition_named",
    "depth",
    "expand",
    "extract",
    "extract_file",
    "find_region",
    "flatten",
    "flatten_file",
    "instantiate",
    "list_definitions",
    "parse_role",
    "resolved_definition",
    "save_together",
    "show",
]
