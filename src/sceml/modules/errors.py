"""Errors of module operations: a use that cannot be expanded, an unknown name, a bad selection."""

from __future__ import annotations

from ..errors import SceMLError


class FlattenError(SceMLError):
    """A module use cannot be expanded: unresolved definition, unbound role, or recursion."""

    exit_code = 1


class UnknownModuleError(SceMLError):
    """A library has no module definition of the requested name."""

    exit_code = 2


class ExtractError(SceMLError):
    """A selection of nodes cannot become a module, or the module cannot be stored."""

    exit_code = 2
