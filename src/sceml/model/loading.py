"""Loading scenarios and module libraries, and finding the references that did not resolve."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from pathlib import Path

from pyecore.ecore import EClass, EObject, EProxy
from pyecore.resources import URI, ResourceSet
from pyecore.resources.xmi import XMIResource

import scemlmodel as scm

from ..errors import LoadError, SceMLError
from ..files.safefiles import reading_roots
from .documents import Document, new_resource_set
from .locating import model_path
from .traversal import all_contents, cross_references, stored


def load(
    path: str | Path,
    *,
    resource_set: ResourceSet | None = None,
    allowed_roots: Iterable[str | Path] | None = None,
    allow: Iterable[str | Path] = (),
    max_bytes: int | None = None,
    read_only: bool = False,
) -> Document:
    """Load a scenario or library XMI file; references to other files load on first use.

    Referenced files are read only from `allowed_roots`, by default `reading_roots(path, allow)`
    (the file's folder, its project root and `allow`), and only up to `max_bytes` each (default:
    $SCEML_MAX_BYTES, else DEFAULT_MAX_BYTES). `read_only` (with a new resource set) makes
    lighter objects that refuse any change: for a caller that only reads the model.
    """
    path = Path(path)
    if resource_set is None:
        roots = allowed_roots if allowed_roots is not None else reading_roots(path, allow)
        resource_set = new_resource_set(roots, max_bytes, read_only)
    # The file the user names is always read; allowed_roots govern what it refers to.
    named: set[Path] = getattr(resource_set, "sceml_named_files", set())
    named.add(path.resolve())
    resource_set.sceml_named_files = named
    resource = resource_set.get_resource(URI(str(path)))
    if not resource.contents:
        raise LoadError("the file holds no model", file=path)
    root = resource.contents[0]
    if not isinstance(root, scm.Scenario | scm.Library):
        raise LoadError(
            f"expected a Scenario or Library, found {root.eClass.name}",
            file=path,
            line=_root_line(resource),
        )
    return Document(path=path, root=root, resource=resource, resource_set=resource_set)


def _root_line(resource: XMIResource) -> int | None:
    lines = getattr(resource, "sceml_lines", None)
    return lines.get(resource.contents[0]) if lines and resource.contents else None


def load_scenario(path: str | Path, **kwargs: object) -> Document:
    """Load a file that must hold a Scenario."""
    document = load(path, **kwargs)  # type: ignore[arg-type]
    if not isinstance(document.root, scm.Scenario):
        raise LoadError(
            "expected a scenario, found a module library",
            file=path,
            line=_root_line(document.resource),
        )
    return document


def load_library(path: str | Path, **kwargs: object) -> Document:
    """Load a file that must hold a module Library."""
    document = load(path, **kwargs)  # type: ignore[arg-type]
    if not isinstance(document.root, scm.Library):
        raise LoadError(
            "expected a module library, found a scenario",
            file=path,
            line=_root_line(document.resource),
        )
    return document


def unresolved_references(
    root: EObject, *, through_files: bool = False
) -> Iterator[tuple[EObject, str, str]]:
    """Every cross-file reference below `root` that cannot be loaded: (holder, href, reason).

    Any reference may name another file (a ModuleUse's definition by design, a node's
    referenceActor by a hand-edited file); each is tried here, so that no tool meets a proxy
    that fails later with pyecore's TypeError. With `through_files`, the files reached are
    searched too, each once: a library's own broken reference is found before a tool expands
    its modules.
    """
    pending, seen = [root], {id(root)}
    while pending:
        top = pending.pop()
        for obj in [top, *all_contents(top)]:
            for holder, target, failure in _proxies_of(obj):
                if failure is not None:
                    yield holder, target._proxy_path, failure
                    continue
                reached = target.eRoot() if through_files else None
                if reached is not None and id(reached) not in seen:
                    seen.add(id(reached))
                    pending.append(reached)


def _proxies_of(obj: EObject) -> Iterator[tuple[EObject, EProxy, str | None]]:
    """`obj`'s references to other files, each tried: (obj, proxy, why it fails or None).

    Only a module use's definition may name another file (SceML writes no other); any other
    reference that does is a failure without reading what it names.
    """
    for reference in cross_references(obj.eClass):
        held = stored(obj, reference.name)
        for target in list(held) if reference.many and held is not None else [held]:
            if not isinstance(target, EProxy):
                continue
            if not (isinstance(obj, scm.ModuleUse) and reference.name == "definition"):
                yield (
                    obj,
                    target,
                    (
                        f"{reference.name} refers to another file ({target._proxy_path!r}); only a "
                        "module use's definition may"
                    ),
                )
                continue
            try:
                target.force_resolve()
            except Exception as error:  # pyecore wraps our LoadError, or raises its own
                yield obj, target, _resolution_failure(target._proxy_path, error)
                continue
            # `#//` names the file's own root: it loads, and is no module definition.
            kind = target.eClass
            # The generated package types a reference by its Python class, which holds the EClass.
            wanted = (
                reference.eType if isinstance(reference.eType, EClass) else reference.eType.eClass
            )
            fits = kind is wanted or wanted in kind.eAllSuperTypes()
            yield (
                obj,
                target,
                None
                if fits
                else (
                    f"cannot resolve {target._proxy_path!r}: it names a {kind.name}, not a "
                    f"{wanted.name}"
                ),
            )


def broken_references(document: Document) -> list[SceMLError]:
    """Every module use of a loaded file whose definition cannot be had, located in the file.

    The file itself was read, so these are errors of its content (exit 1), not unusable input.
    """
    return [
        SceMLError(
            reason,
            file=document.file_of(holder) or document.path,
            line=document.line_of(holder),
            element=model_path(holder),
        )
        for holder, _href, reason in unresolved_references(document.root, through_files=True)
    ]


def _resolution_failure(href: str, error: BaseException) -> str:
    cause: BaseException | None = error
    while cause is not None:
        if isinstance(cause, LoadError):
            return f"cannot resolve {href!r}: {cause}"
        cause = cause.__cause__ or cause.__context__
    # The file loaded, so what failed is the fragment after '#' (KeyError, IndexError, ...).
    file, _, fragment = href.partition("#")
    return f"cannot resolve {href!r}: {file or 'this file'} has no element {fragment!r}"
