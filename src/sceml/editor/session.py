"""EditorSession: one open model, its undo stack, validation after every change, save and export."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pyecore.resources import URI

import scemlmodel as scm

from .. import io
from ..build import ScenarioBuilder
from ..diagnostics import Diagnostic
from ..errors import LoadError, SceMLError
from ..export.writer import ExportError, InvalidOutputError, export_to_file
from ..graph import root_node
from ..modules.library import definition_named
from ..render.labels import loaded_definition
from ..render.style import style_data
from ..validation.incremental import IncrementalValidator
from . import operations, palette, view
from .changes import Recorder
from .clipboard import copy_nodes
from .commands import CommandStack, Step
from .context import Clipboard, EditContext
from .errors import ConflictError, ExportRefused, OperationError, ReadOnlyError
from .ids import Ids


@dataclass
class SessionOptions:
    """How a session was started: read-only, the level of a new scenario, extra libraries."""

    read_only: bool = False
    level: str = "functional"
    libraries: list[Path] = field(default_factory=list)


class EditorSession:
    """Owns the model being edited; every public method answers with the protocol's view."""

    def __init__(self, options: SessionOptions | None = None) -> None:
        self.options = options or SessionOptions()
        self.version = 0
        self.document: io.Document | None = None
        self.graph: scm.Graph = scm.Scenario()
        self.module: str | None = None
        self.stack = CommandStack()
        self.ids = Ids()
        self.clipboard = Clipboard()
        self._listing = view.Listing()
        self.validator: IncrementalValidator | None = None

    # Opening -------------------------------------------------------------------------------

    @property
    def path(self) -> Path:
        """The file being edited (the library file when a module definition is edited)."""
        assert self.document is not None, "no file is open"
        return self.document.path

    def open(
        self, path: str | Path, *, module: str | None = None, discard: bool = True
    ) -> dict[str, Any]:
        """Open a scenario (a missing file: a new one) or one module of a library."""
        if self.document is not None and self.stack.dirty and not discard:
            raise ConflictError("there are unsaved changes; save them or open with discard")
        path = Path(path).resolve()
        document = io.load(path) if path.exists() else self._new_scenario(path)
        graph: scm.Graph = document.root
        if isinstance(document.root, scm.Library):
            graph = self._definition(document.root, module)
            module = str(graph.name)
        self.document, self.graph, self.module = document, graph, module
        self.stack, self.ids, self._listing = CommandStack(), Ids(), view.Listing()
        self.validator = IncrementalValidator(document.root, document=document)
        self.version += 1
        return self.view()

    def _definition(self, library: scm.Library, module: str | None) -> scm.ModuleDefinition:
        if module is None:
            if not library.modules:
                raise OperationError("the library has no module to edit")
            return library.modules[0]
        try:
            return definition_named(library, module)
        except SceMLError as error:
            raise OperationError(error.message) from None

    def _new_scenario(self, path: Path) -> io.Document:
        builder = ScenarioBuilder(path.stem, level=self.options.level)
        # The environment the panel shows is the one the file gets: noon, clear, dry.
        builder.environment()
        # Root above End with room between: the first picture of a new scenario, instead of
        # two unconnected nodes that automatic layout would pack side by side.
        builder.root.diagramPosition = scm.DiagramPosition(x=0.0, y=0.0)
        builder.end.diagramPosition = scm.DiagramPosition(x=70.0, y=480.0)
        resource_set = io.new_resource_set(io.reading_roots(path))
        resource = resource_set.create_resource(URI(str(path)))
        resource.append(builder.scenario)
        return io.Document(path, builder.scenario, resource, resource_set)

    def open_definition(self, node_id: object, *, discard: bool = False) -> dict[str, Any]:
        """Edit the module definition a use of the current graph refers to, in its library."""
        use = self._context().node(node_id)
        definition = loaded_definition(use) if isinstance(use, scm.ModuleUse) else None
        if definition is None or definition.eResource is None:
            raise OperationError(f"{use.name} is not a module use whose library can be opened")
        library = Path(definition.eResource.uri.normalize())
        return self.open(library, module=str(definition.name), discard=discard)

    def _context(self) -> EditContext:
        """What an operation works on: the edited graph, its ids, libraries and clipboard."""
        return EditContext(self.graph, self.ids, self.find_library, self.clipboard)

    # Libraries -----------------------------------------------------------------------------

    def find_library(self, text: str, create: bool = False) -> tuple[scm.Library, Path]:
        """A library file named relative to the edited file; with `create`, a new one if missing."""
        assert self.document is not None
        path = (self.path.parent / text).resolve()
        if path.exists():
            try:
                loaded = io.load_library(path, resource_set=self.document.resource_set)
            except LoadError as error:
                raise OperationError(str(error)) from None
            return loaded.root, path
        if not create:
            raise OperationError(f"no library file {text!r}")
        resource = self.document.resource_set.create_resource(URI(str(path)))
        library = scm.Library(name=path.stem)
        resource.append(library)
        return library, path

    def library_paths(self) -> list[Path]:
        """Libraries the model can use: its uses' files, `library/*.xmi` beside it, --library."""
        found: list[Path] = []
        for node in self.graph.nodes:
            definition = loaded_definition(node) if isinstance(node, scm.ModuleUse) else None
            if definition is not None and definition.eResource is not None:
                found.append(Path(definition.eResource.uri.normalize()))
        if self.module is not None:
            found.append(self.path)
        found += sorted((self.path.parent / "library").glob("*.xmi"))
        found += list(self.options.libraries)
        return list(dict.fromkeys(p.resolve() for p in found))

    def _palette(self) -> list[dict[str, Any]]:
        groups = list(palette.node_groups())
        for path in self.library_paths():
            try:
                library, _ = self.find_library(str(path))
            except OperationError:
                continue  # an unreadable library is left out of the palette, not fatal
            groups.append(palette.library_group(library, view.relative(path, self.path.parent)))
        return groups

    # The view ------------------------------------------------------------------------------

    @property
    def level(self) -> str:
        """The scenario's abstraction level (a module shows its values as logical ones)."""
        root = root_node(self.graph) if isinstance(self.graph, scm.Scenario) else None
        if root is not None and root.level is not None:
            return str(root.level.name)
        return "logical" if self.module is not None else self.options.level

    def diagnostics(self) -> list[Diagnostic]:
        """Every diagnostic of the model as the real validator gives it.

        Validation is incremental (sceml.validation.incremental): after an edit, undo or redo
        only the rules whose inputs the edit changed run again; the list equals a full run's.
        """
        assert self.validator is not None, "no file is open"
        found = self.validator.validate()
        if self.module is None:
            return found
        return [d for d in found if _inside(d.element, self.graph)]

    def view(self, created: list[str] | None = None) -> dict[str, Any]:
        """The whole view of the protocol, re-validated."""
        assert self.document is not None, "no file is open"
        listing = view.Lister(self.ids, self.path.parent).graph(self.graph)
        self._listing = listing
        found = view.problems(self.diagnostics(), listing, self.ids)
        answer: dict[str, Any] = {
            "version": self.version,
            "document": self._document_info(),
            "readOnly": self.options.read_only,
            "dirty": self.stack.dirty,
            "undo": self.stack.undo_label,
            "redo": self.stack.redo_label,
            "level": self.level,
            "valueTypes": palette.value_types(self.level, self.module is not None),
            "nodes": listing.nodes,
            "edges": listing.edges,
            "actors": view.actors(self.graph, self.ids),
            "diagnostics": found,
            "summary": view.summary(found),
            "palette": self._palette(),
            "style": style_data(),
            "choices": palette.choices(),
        }
        if created is not None:
            answer["created"] = created
        return answer

    def _document_info(self) -> dict[str, Any]:
        info = {
            "kind": "module" if self.module is not None else "scenario",
            "path": str(self.path),
            "name": self.path.name,
        }
        if self.module is not None:
            info["module"] = self.module
        return info

    # Changes -------------------------------------------------------------------------------

    def _writable(self) -> None:
        if self.options.read_only:
            raise ReadOnlyError("the editor is read-only: changes are not allowed")

    def apply(self, ops: object, label: str | None = None) -> dict[str, Any]:
        """Apply operations as one undo step (none stays applied if one fails)."""
        self._writable()
        if not isinstance(ops, list):
            raise OperationError("'ops' must be a list of operations")
        ctx = self._context()
        recorders: list[Recorder] = []

        def edit(recorder: Recorder) -> None:
            recorders.append(recorder)
            ctx.rec = recorder
            for op in ops:
                operations.apply(ctx, op)

        try:
            self.stack.run(label or operations.label_of(ops), edit)
        finally:
            # A refused request was rolled back: what it touched is noted all the same.
            self._changed(recorders, ops)
        self.version += 1
        return self.view(created=ctx.created)

    def _changed(self, recorders: list[Recorder], ops: list[Any]) -> None:
        """Tell the validator what a request changed (all of it, if an op reached outside)."""
        assert self.validator is not None
        for recorder in recorders:
            self.validator.note(recorder.changes())
        if any(isinstance(op, dict) and op.get("op") in operations.OUTSIDE for op in ops):
            self.validator.forget()

    def undo(self) -> dict[str, Any]:
        """Revert the last step."""
        return self._history(self.stack.undo)

    def redo(self) -> dict[str, Any]:
        """Apply the last undone step again."""
        return self._history(self.stack.redo)

    def _history(self, move: Callable[[], Step | None]) -> dict[str, Any]:
        self._writable()
        step = move()
        if step is not None:
            assert self.validator is not None
            self.validator.note(step.recorder.changes())
            self.version += 1
        return self.view()

    def copy(self, node_ids: object) -> int:
        """Keep deep copies of these nodes and the flows among them for `paste`."""
        if not isinstance(node_ids, list):
            raise OperationError("'nodes' must be a list of node ids")
        ctx = self._context()
        self.clipboard = copy_nodes(self.graph, [ctx.node(i) for i in node_ids])
        return len(self.clipboard.nodes)

    # Files ---------------------------------------------------------------------------------

    def save(self, path: str | Path | None = None) -> dict[str, Any]:
        """Save atomically, in place or to `path` (a scenario elsewhere is then edited there)."""
        self._writable()
        assert self.document is not None
        target = Path(path).resolve() if path else self.path
        io.save(self.document.root, target)
        # Saving may rewrite references and the file's path: validate the whole model again.
        assert self.validator is not None
        self.validator.forget()
        if target != self.path:
            if target.parent != self.path.parent:
                # Relative references (map, libraries) were rewritten for the new folder: read
                # the file back so the model in memory says what the file says.
                return self.open(target, module=self.module)
            self.document.resource.uri = URI(str(target))
            self.document.path = target
        self.stack.mark_saved()
        self.version += 1
        return self.view()

    def export(
        self, version: str = "1.3", profile: str = "generic", path: str | Path | None = None
    ) -> Path:
        """Export the scenario to OpenSCENARIO; a refusal is an ExportRefused with diagnostics."""
        if not isinstance(self.graph, scm.Scenario):
            raise OperationError("only a scenario can be exported, not a module")
        target = Path(path).resolve() if path else self.path.with_suffix(".xosc")
        try:
            return export_to_file(
                self.graph, target, version=version, profile=profile, source_path=self.path
            )
        except ExportError as error:
            found = view.problems(error.diagnostics, self._listing, self.ids)
            raise ExportRefused(error.message, found) from None
        except InvalidOutputError as error:
            raise ExportRefused(error.message, []) from None

    def recover(self) -> Path | None:
        """If there are unsaved changes, write them beside the file; the copy's path, else None."""
        if self.document is None or not self.stack.dirty:
            return None
        target = self.path.with_name(f".{self.path.stem}.recovered{self.path.suffix or '.xmi'}")
        io.save(self.document.root, target)
        return target


def _inside(element: object, container: object) -> bool:
    current = element
    while current is not None:
        if current is container:
            return True
        current = current.eContainer()  # type: ignore[attr-defined]
    return False
