"""EditorSession: one open model, its undo stack, validation after every change, save and export."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path
from typing import Any

from pyecore.resources import URI

import scemlmodel as scm

from ..diagnostics import Diagnostic
from ..errors import LoadError, SceMLError
from ..export.writer import ExportError, InvalidOutputError, export_to_file
from ..files.safefiles import reading_roots
from ..model.build import ScenarioBuilder
from ..model.documents import Document, new_resource_set
from ..model.graph import DEFAULT_LEVEL, scenario_level
from ..model.loading import load, load_library
from ..model.saving import save as io_save
from ..modules.library import definition_named
from ..render.labels import loaded_definition
from ..render.style import style_data
from ..validation.incremental import IncrementalValidator
from ..xosc.profiles import default_version
from . import operations, palette, view
from .changes import Recorder
from .clipboard import copy_nodes
from .commands import ANY_TAB, CommandStack, Step
from .comparing import SavedComparison
from .context import Clipboard, EditContext
from .errors import ConflictError, ExportRefused, OperationError, ReadOnlyError
from .ids import Ids
from .paths import inside_allowed, path_text


@dataclass
class SessionOptions:
    """How a session was started: read-only, the level of a new scenario, extra libraries."""

    read_only: bool = False
    level: str = DEFAULT_LEVEL
    libraries: list[Path] = field(default_factory=list)
    #: Folders the editor may also read and write (`--allow`), beyond `reading_roots`.
    allow: list[Path] = field(default_factory=list)


class EditorSession:
    """Owns the model being edited; every public method answers with the protocol's view."""

    def __init__(self, options: SessionOptions | None = None) -> None:
        self.options = options or SessionOptions()
        self.version = 0
        self.document: Document | None = None
        self.graph: scm.Graph = scm.Scenario()
        self.module: str | None = None
        self.stack = CommandStack()
        self.ids = Ids()
        self.clipboard = Clipboard()
        self._listing = view.Listing()
        self._cache = view.NodeCache()
        self.validator: IncrementalValidator | None = None
        #: The folders files may be opened from and written to, fixed by the first file opened
        #: (the one named when the server started), so no request can widen them.
        self.roots: list[Path] | None = None
        #: A recovery copy left by an earlier run, offered until the user restores or drops it.
        self.recovery_offer: Path | None = None
        #: While the user compares with the saved file: marks and changes in every view.
        self.comparison: SavedComparison | None = None

    # Opening -------------------------------------------------------------------------------

    @property
    def path(self) -> Path:
        """The file being edited (the library file when a module definition is edited)."""
        assert self.document is not None, "no file is open"
        return self.document.path

    def open(
        self, named: str | Path | object, *, module: str | None = None, discard: bool = True
    ) -> dict[str, Any]:
        """Open a scenario (a missing file: a new one) or one module of a library.

        The first file opened (the one named on the command line) fixes the allowed folders;
        any later one must lie in them.
        """
        if self.roots is None:
            path = Path(path_text(named, "the file")).resolve()
            self.roots = self._allowed_folders(path)
        else:
            path = self.allowed(named, "'path'")
        if self.document is not None and self.stack.dirty and not discard:
            raise ConflictError("there are unsaved changes; save them or open with discard")
        document = (
            load(path, allowed_roots=self.roots) if path.exists() else self._new_scenario(path)
        )
        self._adopt(document, module)
        self.recovery_offer = self._earlier_recovery()
        return self.view()

    def _adopt(self, document: Document, module: str | None) -> None:
        """Edit `document` (one module of it, for a library) from a fresh history."""
        graph: scm.Graph = document.root
        if isinstance(document.root, scm.Library):
            graph = self._definition(document.root, module)
            module = str(graph.name)
        self.document, self.graph, self.module = document, graph, module
        self.comparison = None
        self.stack, self.ids, self._listing = CommandStack(), Ids(), view.Listing()
        self._cache = view.NodeCache()
        self.validator = IncrementalValidator(document.root, document=document)
        self.version += 1

    def _allowed_folders(self, path: Path) -> list[Path]:
        # A library named with --library is the user's explicit choice, like --allow.
        extra = [*self.options.allow, *(Path(p).resolve().parent for p in self.options.libraries)]
        return reading_roots(path, extra)

    def allowed(self, path: object, what: str) -> Path:
        """The absolute path a request names, if it lies in the allowed folders."""
        assert self.roots is not None and self.document is not None, "no file is open"
        return inside_allowed(path, what, self.path.parent, self.roots)

    def _definition(self, library: scm.Library, module: str | None) -> scm.ModuleDefinition:
        if module is None:
            if not library.modules:
                raise OperationError("the library has no module to edit")
            return library.modules[0]
        try:
            return definition_named(library, module)
        except SceMLError as error:
            raise OperationError(error.message) from None

    def _new_scenario(self, path: Path) -> Document:
        builder = ScenarioBuilder(path.stem, level=self.options.level)
        # The environment the panel shows is the one the file gets: noon, clear, dry.
        builder.environment()
        # Root above End with room between: the first picture of a new scenario, instead of
        # two unconnected nodes that automatic layout would pack side by side.
        builder.root.diagramPosition = scm.DiagramPosition(x=0.0, y=0.0)
        builder.end.diagramPosition = scm.DiagramPosition(x=70.0, y=480.0)
        resource_set = new_resource_set(self.roots)
        resource = resource_set.create_resource(URI(str(path)))
        resource.append(builder.scenario)
        return Document(path, builder.scenario, resource, resource_set)

    def open_definition(self, node_id: object, *, discard: bool = False) -> dict[str, Any]:
        """Edit the module definition a use of the current graph refers to, in its library."""
        use = self._context().node(node_id)
        definition = loaded_definition(use) if isinstance(use, scm.ModuleUse) else None
        if definition is None or definition.eResource is None:
            raise OperationError(f"{use.name} is not a module use whose library can be opened")
        library = Path(definition.eResource.uri.normalize())
        return self.open(library, module=str(definition.name), discard=discard)

    def _context(self, tab: str = ANY_TAB) -> EditContext:
        """What an operation works on: the edited graph, its ids, libraries and clipboard."""
        return EditContext(
            self.graph,
            self.ids,
            self.find_library,
            self.clipboard,
            why_gone=lambda obj: self._why_gone(obj, tab),
        )

    def _why_gone(self, obj: object, tab: str) -> str | None:
        """How `obj` left the model, in the words of the tab that asks about it."""
        step = self.stack.removal_of(obj)
        if step is not None:
            if step.tab != tab:
                return "was deleted in another tab"
            return f"was deleted by '{step.label}'"
        return None

    # Libraries -----------------------------------------------------------------------------

    def find_library(self, text: str, create: bool = False) -> tuple[scm.Library, Path]:
        """A library file named relative to the edited file; with `create`, a new one if missing."""
        assert self.document is not None
        path = self.allowed(text, "'library'")
        if path.exists():
            try:
                loaded = load_library(path, resource_set=self.document.resource_set)
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
        # Each distinct path resolved once: a large scenario's many uses name one library, and
        # resolving asks the file system every time (a tenth of a drop's answer at 500 nodes).
        return list(dict.fromkeys(p.resolve() for p in dict.fromkeys(found)))

    def _palette(self) -> list[dict[str, Any]]:
        groups = list(palette.node_groups())
        for path in self.library_paths():
            try:
                library, _ = self.find_library(str(path))
            except OperationError:
                continue  # an unreadable library is left out of the palette, not fatal
            shown = view.relative(path, self.path.parent)
            participants = self._context().participants()
            editing = self.graph if isinstance(self.graph, scm.ModuleDefinition) else None
            groups.append(palette.library_group(library, shown, participants, editing))
        return groups

    # The view ------------------------------------------------------------------------------

    @property
    def level(self) -> str:
        """The scenario's abstraction level (a module shows its values as logical ones)."""
        level = scenario_level(self.graph) if isinstance(self.graph, scm.Scenario) else None
        if level is not None:
            return level
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

    def view(self, created: list[str] | None = None, tab: str = ANY_TAB) -> dict[str, Any]:
        """The whole view of the protocol, re-validated."""
        assert self.document is not None, "no file is open"
        listing = view.Lister(self.ids, self.path.parent, self._cache).graph(self.graph)
        self._listing = listing
        found = view.problems(self.diagnostics(), listing, self.ids)
        compared = self._compared(listing.nodes)
        answer: dict[str, Any] = {
            "version": self.version,
            "document": self._document_info(),
            "readOnly": self.options.read_only,
            "dirty": self.stack.dirty,
            "undo": self.stack.undo_label_for(tab),
            "redo": self.stack.redo_label_for(tab),
            "recovery": self._recovery_info(),
            "level": self.level,
            "valueTypes": palette.value_types(self.level, self.module is not None),
            "nodes": listing.nodes,
            "edges": listing.edges,
            "actors": self._cache.actors(self.graph, self.ids),
            "diagnostics": found,
            "summary": view.summary(found),
            "palette": self._palette(),
            "style": style_data(),
            "choices": palette.choices(),
        }
        if compared is not None:
            answer["comparison"] = compared
        if created is not None:
            answer["created"] = created
        return answer

    def compare(self, on: bool, tab: str = ANY_TAB) -> dict[str, Any]:
        """Start or stop comparing the scenario with its saved file (`sceml diff`'s terms)."""
        if on and self.module is not None:
            raise OperationError("comparing with the saved file works on scenarios, not modules")
        self.comparison = SavedComparison(self.path, self.roots) if on else None
        return self.view(tab=tab)

    def _compared(self, nodes: list[dict[str, Any]]) -> dict[str, Any] | None:
        if self.comparison is None:
            return None
        assert self.document is not None
        marks, report = self.comparison.compare(self.document.root, self.ids)
        for entry in nodes:  # entries are this view's own copies
            mark = marks.get(entry["id"])
            if mark is not None:
                entry["mark"] = mark
        return report

    def _document_info(self) -> dict[str, Any]:
        info: dict[str, Any] = {
            "kind": "module" if self.module is not None else "scenario",
            "path": str(self.path),
            "name": self.path.name,
        }
        if self.module is not None:
            info["module"] = self.module
        migration = self.document.migration if self.document is not None else None
        if migration is not None:
            # Read through a migration and not saved since: the page offers to save it in
            # the current release (docs/metamodel.md, "Reading an older file").
            info["olderRelease"] = {
                "saved": migration.from_release,
                "current": migration.to_release,
            }
        return info

    # Changes -------------------------------------------------------------------------------

    def _writable(self) -> None:
        if self.options.read_only:
            raise ReadOnlyError("the editor is read-only: changes are not allowed")

    def apply(self, ops: object, label: object = None, tab: str = ANY_TAB) -> dict[str, Any]:
        """Apply operations as one undo step (none stays applied if one fails)."""
        self._writable()
        if not isinstance(ops, list):
            raise OperationError("'ops' must be a list of operations")
        if label is not None and (not isinstance(label, str) or len(label) > 200):
            raise OperationError("'label' must be a text of at most 200 characters")
        ctx = self._context(tab)
        recorders: list[Recorder] = []

        def edit(recorder: Recorder) -> None:
            recorders.append(recorder)
            ctx.rec = recorder
            for op in ops:
                operations.apply(ctx, op)

        try:
            self.stack.run(label or operations.label_of(ops), edit, tab)
        finally:
            # A refused request was rolled back: what it touched is noted all the same.
            self._changed(recorders, ops)
        self.version += 1
        return self.view(created=ctx.created, tab=tab)

    def _changed(self, recorders: list[Recorder], ops: list[Any]) -> None:
        """Tell the validator what a request changed (all of it, if an op reached outside)."""
        assert self.validator is not None
        for recorder in recorders:
            self.validator.note(recorder.changes())
            self._cache.forget(recorder.changes(), self.graph)
        if any(isinstance(op, dict) and op.get("op") in operations.OUTSIDE for op in ops):
            self.validator.forget()
            self._cache.forget_all()

    def undo(self, tab: str = ANY_TAB) -> dict[str, Any]:
        """Revert `tab`'s last step (the last step of all, without a tab)."""
        return self._history(self.stack.undo, tab)

    def redo(self, tab: str = ANY_TAB) -> dict[str, Any]:
        """Apply `tab`'s last undone step again."""
        return self._history(self.stack.redo, tab)

    def _history(self, move: Callable[[str], Step | None], tab: str) -> dict[str, Any]:
        self._writable()
        step = move(tab)
        if step is not None:
            assert self.validator is not None
            self.validator.note(step.recorder.changes())
            self._cache.forget(step.recorder.changes(), self.graph)
            if step.recorder.reaches_outside:
                self.validator.forget()
            self.version += 1
        return self.view(tab=tab)

    def copy(self, node_ids: object, tab: str = ANY_TAB) -> int:
        """Keep deep copies of these nodes and the flows among them for `paste`."""
        if not isinstance(node_ids, list):
            raise OperationError("'nodes' must be a list of node ids")
        ctx = self._context(tab)
        self.clipboard = copy_nodes(self.graph, [ctx.node(i) for i in node_ids])
        return len(self.clipboard.nodes)

    # Files ---------------------------------------------------------------------------------

    def save(self, path: str | Path | None = None, tab: str = ANY_TAB) -> dict[str, Any]:
        """Save atomically, in place or to `path` (a scenario elsewhere is then edited there);
        the view has `tab`'s undo and redo."""
        self._writable()
        assert self.document is not None
        target = self.path if path is None else self.allowed(path, "'path'")
        io_save(self.document.root, target)
        self.document.resource.sceml_migration = None  # the file is of the current release now
        # Saving may rewrite references and the file's path: validate the whole model again.
        assert self.validator is not None
        self.validator.forget()
        self._cache.forget_all()
        if target != self.path:
            if target.parent != self.path.parent:
                # Relative references (map, libraries) were rewritten for the new folder: read
                # the file back so the model in memory says what the file says.
                return self.open(target, module=self.module)
            self.document.resource.uri = URI(str(target))
            self.document.path = target
        self.stack.mark_saved()
        if self.comparison is not None:  # compare with the file just written
            self.comparison = SavedComparison(self.path, self.roots)
        self.version += 1
        return self.view(tab=tab)

    def export(
        self, version: str | None = None, profile: str = "generic", path: str | Path | None = None
    ) -> Path:
        """Export the scenario to OpenSCENARIO; a refusal is an ExportRefused with diagnostics."""
        if not isinstance(self.graph, scm.Scenario):
            raise OperationError("only a scenario can be exported, not a module")
        _check_choice(profile, "'profile'")
        version = default_version(profile) if version is None else version
        _check_choice(version, "'version'")
        target = self.path.with_suffix(".xosc") if path is None else self.allowed(path, "'path'")
        try:
            return export_to_file(
                self.graph, target, version=version, profile=profile, source_path=self.path
            )
        except ExportError as error:
            found = view.problems(error.diagnostics, self._listing, self.ids)
            raise ExportRefused(error.message, found) from None
        except InvalidOutputError as error:
            raise ExportRefused(error.message, []) from None

    # Recovery ------------------------------------------------------------------------------

    @property
    def recovery_path(self) -> Path:
        """Where unsaved changes are kept: `.NAME.recovered.xmi` beside the file."""
        return self.path.with_name(f".{self.path.stem}.recovered{self.path.suffix or '.xmi'}")

    def recover(self) -> Path | None:
        """Bring the recovery copy up to date: the unsaved model, or none when all is saved.

        Answers the copy's path when it holds unsaved changes. Called after every change (the
        journal, so a crash loses at most the change being written) and when the server stops.
        A copy from an earlier run stays untouched until the user restores or drops it.
        """
        if self.document is None or self.options.read_only:
            return None
        if not self.stack.dirty:
            if self.recovery_offer is None:
                self.recovery_path.unlink(missing_ok=True)
            return None
        target = self.recovery_path
        io_save(self.document.root, target)
        if self.recovery_offer == target:
            self.recovery_offer = None  # the user went on editing: the old copy is replaced
        return target

    def _earlier_recovery(self) -> Path | None:
        copy = self.recovery_path
        if self.options.read_only or not copy.is_file():
            return None
        if self.path.is_file() and copy.stat().st_mtime < self.path.stat().st_mtime:
            return None  # the file was saved after the copy was written: the copy is stale
        return copy

    def _recovery_info(self) -> dict[str, Any] | None:
        if self.recovery_offer is None:
            return None
        written = datetime.fromtimestamp(self.recovery_offer.stat().st_mtime)
        return {"path": str(self.recovery_offer), "written": written.isoformat(timespec="seconds")}

    def resolve_recovery(self, restore: object) -> dict[str, Any]:
        """Restore the offered recovery copy (`restore` true) or delete it (false)."""
        self._writable()
        if not isinstance(restore, bool):
            raise OperationError("'restore' must be true or false")
        offer = self.recovery_offer
        if offer is None:
            raise OperationError("there is no recovery copy to restore or drop")
        self.recovery_offer = None
        if not restore:
            offer.unlink(missing_ok=True)
            self.version += 1
            return self.view()
        assert self.document is not None
        original, module = self.path, self.module
        document = load(offer, allowed_roots=self.roots)
        # The copy lies beside the file, so its relative references mean the same there.
        document.path = original
        document.resource.uri = URI(str(original))
        self._adopt(document, module)
        self.stack.mark_unsaved()
        return self.view()


def _check_choice(value: object, what: str) -> None:
    # The exporter names the versions and profiles it knows; a non-text value is refused here.
    if not isinstance(value, str) or len(value) > 40:
        raise OperationError(f"{what} must be a short text, not {value!r:.40}")


def _inside(element: object, container: object) -> bool:
    current = element
    while current is not None:
        if current is container:
            return True
        current = current.eContainer()  # type: ignore[attr-defined]
    return False
