"""Modules and libraries: list, show, instantiate, flatten and extract reusable sub-scenarios.

A module definition lives in a library file; scenarios (and other modules) use it through a
ModuleUse that binds its roles to actors and may override its parameters. See docs/modules.md.
"""

from .errors import ExtractError, FlattenError, UnknownModuleError
from .extract import Region, RoleSpec, extract, find_region, parse_role
from .flatten import Flattened, Origin, expand, flatten
from .library import (
    DefinitionDetail,
    DefinitionSummary,
    definition_named,
    depth,
    instantiate,
    list_definitions,
    show,
)
from .resolve import resolved_definition
from .store import ExtractReport, FlattenReport, extract_file, flatten_file, save_together

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
