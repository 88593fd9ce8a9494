"""Find what a module use refers to, across files, and say where model elements are written."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from ..errors import LoadError
from ..model.documents import Document
from ..model.locating import model_path
from .errors import FlattenError


def unwrap(obj: EObject) -> EObject:
    """The object itself, or the object a resolved cross-file proxy stands for."""
    return obj._wrapped if isinstance(obj, EProxy) and obj.resolved else obj


def location(obj: EObject) -> dict[str, Any]:
    """File, line and model path of an element, as keyword arguments for a SceMLError."""
    resource = obj.eResource
    if resource is None or not resource.contents:
        return {"element": model_path(obj)}
    document = Document(
        path=Path(resource.uri.normalize()),
        root=resource.contents[0],
        resource=resource,
        resource_set=resource.resource_set,
    )
    return {"file": document.path, "line": document.line_of(obj), "element": model_path(obj)}


def resolved_definition(
    use: scm.ModuleUse, located: Callable[[EObject], dict[str, Any]] = location
) -> scm.ModuleDefinition:
    """The definition a use refers to, loaded if it lives in another file.

    FlattenError, located at the use, names the reference (file#name) that was tried.
    """
    definition = use.definition
    if definition is None:
        raise FlattenError(f"module use {use.name!r} refers to no definition", **located(use))
    if isinstance(definition, EProxy):
        href = str(definition._proxy_path)
        try:
            definition = definition.force_resolve()
        except Exception as error:  # pyecore wraps load failures and missing names in bare errors
            raise FlattenError(
                f"module definition {href!r} cannot be loaded: {_why_unresolved(definition, error)}",
                **located(use),
            ) from None
    if not isinstance(definition, scm.ModuleDefinition):
        raise FlattenError(
            f"module use {use.name!r} refers to a {definition.eClass.name}, not a module definition",
            **located(use),
        )
    return definition


def _why_unresolved(proxy: EProxy, error: Exception) -> str:
    file, _, name = str(proxy._proxy_path).partition("#")
    referrer = proxy._proxy_resource
    target = (Path(referrer.uri.normalize()).parent / file).resolve()
    for resource in referrer.resource_set.resources.values():
        if Path(resource.uri.normalize()).resolve() == target and resource.contents:
            names = ", ".join(str(m.name) for m in getattr(resource.contents[0], "modules", ()))
            return f"{target} has no module {name!r} (it has: {names or 'none'})"
    cause: BaseException | None = error
    while cause is not None:  # pyecore re-raises a failed load as a TypeError
        if isinstance(cause, LoadError):
            return str(cause)
        cause = cause.__cause__ or cause.__context__
    if not target.exists():
        return f"{target}: no such file"
    return f"{target}: {error}"


def definition_key(definition: scm.ModuleDefinition) -> tuple[str, str]:
    """What identifies a definition across proxies and files: its file and its name."""
    definition = unwrap(definition)
    resource = definition.eResource
    file = str(Path(resource.uri.normalize()).resolve()) if resource is not None else ""
    return file, str(definition.name)
