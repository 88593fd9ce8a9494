"""Saving a model as XMI, atomically, with the paths it names rebased to where it is written."""

from __future__ import annotations

import io as _io
import math
import os
from pathlib import Path

from pyecore.ecore import EObject
from pyecore.resources import URI
from pyecore.resources.xmi import XMIOptions, XMIResource

import scemlmodel as scm

from ..errors import SaveError
from ..files.writing import write_atomically
from .documents import new_resource_set
from .loading import unresolved_references
from .locating import model_path
from .xmiresource import FLOAT_TYPES, INT_RANGE, INT_TYPES


def save(
    root: EObject, path: str | Path, *, origin: str | Path | None = None, note: str | None = None
) -> Path:
    """Write a model atomically: to a temporary file beside `path`, then renamed over it.

    Cross-file references are written relative to `path`, and so is a relative map path: it is
    read relative to `origin`, the file the model (or the model it was derived from, for a
    flattened or sampled copy) was loaded from; by default the model's own file. On any failure
    the previous file, if any, is left as it was. `note` is written as an XML comment after
    the declaration (the editor's recovery copy names the journal position it covers there).
    """
    path = Path(path)
    resource = root.eResource
    if resource is None:
        resource_set = new_resource_set()
        resource = resource_set.create_resource(URI(str(path)))
        resource.append(root)
    _resolve_before_moving(root, resource, path)
    _refuse_unreadable_values(root, path)
    buffer = _MemoryURI(str(path))
    original_uri = resource.uri
    source = Path(origin) if origin is not None else Path(original_uri.normalize())
    moved_maps = _rebase_map_paths(root, source.parent, path.parent)
    resource.uri = URI(str(path))
    try:
        # Defaults are written out: `kind="Pedestrian"` and `value="0.0"` read better than an
        # empty element, and no reader has to know the metamodel's defaults.
        resource.save(output=buffer, options={XMIOptions.SERIALIZE_DEFAULT_VALUES: True})
    except Exception as error:
        raise SaveError(f"cannot serialise the model: {error}", file=path) from None
    finally:
        resource.uri = original_uri
        for node, feature, original in moved_maps:
            node.eSet(feature, original)
    data = buffer.data.getvalue()
    if note is not None:
        declaration_end = data.index(b"?>") + 2
        comment = f"\n<!-- {note.replace('--', '- -')} -->".encode()
        data = data[:declaration_end] + comment + data[declaration_end:]
    write_atomically(path, data)
    return path


def _rebase_map_paths(
    root: EObject, old_folder: Path, new_folder: Path
) -> list[tuple[scm.RootNode, str, str]]:
    """Point relative map and vehicle catalog paths at the same place from the new folder, for
    this save.

    The model in memory keeps its own paths: (node, feature, old value) are returned to be
    restored. A map that is a simulator town name (no `.xodr`) or an absolute path is left as
    it is, and so is an absolute catalog folder.
    """
    if old_folder.resolve() == new_folder.resolve() or not isinstance(root, scm.Scenario):
        return []
    changed = []
    for node in root.nodes:
        if not isinstance(node, scm.RootNode):
            continue
        for feature in ("map", "vehicleCatalog"):
            text = node.eGet(feature)
            if not text or Path(text).is_absolute():
                continue
            if feature == "map" and not text.lower().endswith(".xodr"):
                continue
            target = (old_folder / text).resolve()
            moved = Path(os.path.relpath(target, new_folder.resolve())).as_posix()
            node.eSet(feature, moved)
            changed.append((node, feature, text))
    return changed


def _refuse_unreadable_values(root: EObject, path: Path) -> None:
    # pyecore would write these as "inf", "nan" or a 64-bit number, and EMF refuses to read the
    # file back; refusing here keeps a good file from being replaced by one EMF cannot open.
    for obj in [root, *root.eAllContents()]:
        for attribute in obj.eClass.eAllAttributes():
            name = attribute.eType.name
            if name not in FLOAT_TYPES and name not in INT_TYPES:
                continue
            value = obj.eGet(attribute)
            for item in list(value) if attribute.many else [value]:
                if item is None:
                    continue
                if name in FLOAT_TYPES and not math.isfinite(item):
                    problem = f"{attribute.name} is {item}, which EMF cannot read"
                elif name in INT_TYPES and not INT_RANGE[0] <= item <= INT_RANGE[1]:
                    problem = f"{attribute.name}={item} does not fit a 32-bit int"
                else:
                    continue
                raise SaveError(f"cannot save: {problem}", file=path, element=model_path(obj))


class _MemoryURI(URI):  # type: ignore[misc]  # pyecore is untyped
    """A URI pyecore can save into that keeps the bytes in memory, for the atomic write."""

    def __init__(self, uri: str) -> None:
        super().__init__(uri)
        self.data = _io.BytesIO()

    def create_outstream(self) -> _io.BytesIO:
        return self.data

    def close_stream(self) -> None:
        pass  # the bytes are read after pyecore is done


def _resolve_before_moving(root: EObject, resource: XMIResource, path: Path) -> None:
    # An unresolved proxy keeps its href text verbatim, which would be wrong relative to a new
    # folder; resolving it first lets pyecore write a correct relative href.
    same_folder = Path(resource.uri.normalize()).parent == path.resolve().parent
    if same_folder:
        return
    for holder, href, reason in unresolved_references(root):
        raise SaveError(
            f"cannot save into another folder: reference {href!r} does not resolve ({reason})",
            file=path,
            element=model_path(holder),
        )
