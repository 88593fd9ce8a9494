"""EditorSession: one open model, its undo stack, validation after every change, save and export."""

from __future__ import annotations

import json
import secrets
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
from .changelog import LOGGED_ROUTES, ChangeLog, Entry, log_path
from .changes import Recorder
from .clipboard import copy_nodes
from .commands import ANY_TAB, CommandStack, Step
from .comparing import SavedComparison
from .context import Clipboard, EditContext
from .errors import ConflictError, EditorError, ExportRefused, OperationError, ReadOnlyError
from .ids import Ids
from .paths import inside_allowed, path_text
from .recovery import NOTE_PREFIX, Offer, checkpoint_path, file_digest, find_offer


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
        #: Unsaved changes an earlier run left, offered until the user restores or drops them.
        self.recovery_offer: Offer | None = None
        #: What the last restore replayed, and where it stopped (for the page).
        self.replay_report: dict[str, Any] | None = None
        # The journal (docs/editor.md, "Nothing is lost"): the change log since the base (the
        # file as opened or saved, or the last checkpoint), the sequence number of the last
        # change logged, and the steps and clipboard a replay from the base would also have.
        self._log: ChangeLog | None = None
        self.journal_id: str | None = None
        self.seq = 0
        self._since_base: set[Step] = set()
        self._copied_since_base = False
        self._moved: Step | None = None
        # The log could not be written (a full disk): no log until the next checkpoint, since
        # a log started on the file now would miss the change that was not logged.
        self._log_failed = False
        #: The SHA-256 of the file as opened or last saved (None: not written yet).
        self.base_digest: str | None = None
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
        self.base_digest = file_digest(path)
        self.recovery_offer = self._earlier_recovery()
        return self.view()

    def _adopt(self, document: Document, module: str | None) -> None:
        """Edit `document` (one module of it, for a library) from a fresh history."""
        graph: scm.Graph = document.root
        if isinstance(document.root, scm.Library):
            graph = self._definition(document.root, module)
            module = str(graph.name)
        self.document, self.graph, self.module = document, graph, module
        self._end_journal()
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

        steps = len(self.stack.done)
        self._moved = None
        try:
            self.stack.run(label or operations.label_of(ops), edit, tab)
            if len(self.stack.done) > steps:
                self._moved = self.stack.done[-1]
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
        step = self._moved = move(tab)
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
        self.base_digest = file_digest(target)
        self._end_journal()
        if self.recovery_offer is None:
            self._drop_journal_files()  # the file holds everything: nothing to replay
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
        """Where unsaved changes are checkpointed: `.NAME.recovered.xmi` beside the file."""
        return checkpoint_path(self.path)

    @property
    def journal_path(self) -> Path:
        """Where the changes since the checkpoint are logged: `.NAME.journal` beside the file."""
        return log_path(self.path)

    def record(self, route: str, body: dict[str, Any], tab: str, before: int) -> bool:
        """Log a change request that succeeded (`before`: the version it started from).

        Called under the server's lock right after the request, before its answer, so the log
        holds every change in the order applied. Answers True when the request cannot be
        replayed from the base (it wrote another file, undid a step the base already holds, or
        pasted what was copied before it): a checkpoint is then due at once.
        """
        if route not in LOGGED_ROUTES or self.document is None or self.options.read_only:
            return False
        if route in ("/api/undo", "/api/redo") and self.version == before:
            return False  # nothing to undo or redo: nothing changed
        if route == "/api/copy" and self._log is None and not self._log_failed:
            return False  # copied while an offer waits: a later paste has the checkpoint due
        refused = self._why_not_replayable(route, body)
        self.seq += 1
        if self._log is None or not self._log.started:
            return True  # the log could not be started: the checkpoint is the only copy
        try:
            self._log.append(Entry(self.seq, route, body, tab, refused))
        except OSError:
            # A full disk: the change is made all the same; the checkpoint tries at once.
            self._log.close()
            self._log, self._log_failed = None, True
            return True
        return refused is not None

    def will_change(self, route: str) -> None:
        """Before a change request: start the log if none is, on the model as it still is (the
        log's header names the objects' ids by their places in the file)."""
        idle = self._log is None and self.document is not None and not self.options.read_only
        if self.recovery_offer is not None and route != "/api/ops":
            return  # only an edit replaces an earlier run's offer (a Copy changes nothing)
        if route in LOGGED_ROUTES and idle and not self._log_failed:
            try:
                self._start_journal()
            except (SceMLError, OSError):
                # A folder that cannot be written: the edit goes on; the checkpoint tries next.
                self._log, self._log_failed = None, True

    def _why_not_replayable(self, route: str, body: dict[str, Any]) -> str | None:
        step = self._moved
        if route == "/api/copy":
            self._copied_since_base = True
            return None
        if route == "/api/ops":
            ops = body.get("ops") or []
            names = {op.get("op") for op in ops if isinstance(op, dict)}
            if step is not None:
                self._since_base.add(step)
            if names & operations.OUTSIDE:
                return "it wrote another file (a library)"
            if "paste" in names and not self._copied_since_base:
                return "it pasted what was copied before the recovery copy was written"
            return None
        if step is not None and step not in self._since_base:
            return "it undid or redid a change the recovery copy already holds"
        if step is not None and step.recorder.reaches_outside:
            return "it changed another file (a library)"
        return None

    def _start_journal(self) -> None:
        """Start the log on the file as opened or saved: an earlier run's offer is replaced."""
        assert self.document is not None
        self.recovery_offer = None  # the user went on editing: the old copy is replaced
        self.journal_id = secrets.token_hex(8)
        self._log = ChangeLog(self.journal_path)
        self._log.start(
            {
                "id": self.journal_id,
                "base": "file",
                "digest": self.base_digest,
                "module": self.module,
                "ids": self.ids.in_resource(self.document.resource),
                "counter": self.ids.counter,
            }
        )
        self.recovery_path.unlink(missing_ok=True)

    def _end_journal(self) -> None:
        """Forget the log's state (the files stay): a new base begins."""
        if self._log is not None:
            self._log.close()
        self._log, self.journal_id, self.seq = None, None, 0
        self._log_failed = False
        self._since_base, self._copied_since_base = set(), False

    def _drop_journal_files(self) -> None:
        self.journal_path.unlink(missing_ok=True)
        self.recovery_path.unlink(missing_ok=True)

    def recover(self) -> Path | None:
        """Write the checkpoint: the unsaved model, or none when all is saved; then the log
        starts again after it.

        Answers the checkpoint's path when it holds unsaved changes. Called when the edits
        pause (the journal thread), at once after a change a replay could not apply, and when
        the server stops. Unsaved changes an earlier run left stay untouched until the user
        restores or drops them, or edits on.
        """
        if self.document is None or self.options.read_only:
            return None
        if not self.stack.dirty:
            if self.recovery_offer is None:
                self._end_journal()
                self._drop_journal_files()
            return None
        if self.recovery_offer is not None:
            return None  # nothing changed since the offer (a change would have replaced it)
        if self.journal_id is None:
            self.journal_id = secrets.token_hex(8)
        note = {
            "id": self.journal_id,
            "seq": self.seq,
            "module": self.module,
            "ids": self.ids.in_resource(self.document.resource),
            "counter": self.ids.counter,
        }
        target = self.recovery_path
        io_save(
            self.document.root,
            target,
            origin=self.path,
            note=NOTE_PREFIX + json.dumps(note, separators=(",", ":")),
        )
        # A crash here leaves the old log beside the new checkpoint: its entries up to `seq`
        # are skipped on replay, as the checkpoint names the same journal.
        if self._log is None:
            self._log = ChangeLog(self.journal_path)
        self._log.start({"id": self.journal_id, "base": "checkpoint", "module": self.module})
        self._log_failed = False
        self._since_base, self._copied_since_base = set(), False
        return target

    def _earlier_recovery(self) -> Offer | None:
        if self.options.read_only:
            return None
        return find_offer(self.path, self.module)

    def _recovery_info(self) -> dict[str, Any] | None:
        offer = self.recovery_offer
        if offer is None:
            return None
        stamps = [p.stat().st_mtime for p in (offer.checkpoint, offer.log) if p and p.is_file()]
        written = datetime.fromtimestamp(max(stamps, default=0.0))
        return {
            "path": str(offer.shown),
            "written": written.isoformat(timespec="seconds"),
            "changes": len(offer.entries),
        }

    def resolve_recovery(self, restore: object) -> dict[str, Any]:
        """Restore the offered unsaved changes (`restore` true) or delete them (false).

        Restoring loads the base (the checkpoint, or the file) and replays the logged changes
        through the methods that made them, with their tabs, so each tab can undo its own. A
        change that cannot be replayed stops the replay: it is named in `replay_report`, and it
        and the changes after it are kept in `.NAME.unreplayed.journal` for the user.
        """
        self._writable()
        if not isinstance(restore, bool):
            raise OperationError("'restore' must be true or false")
        offer = self.recovery_offer
        if offer is None:
            raise OperationError("there is no recovery copy to restore or drop")
        self.recovery_offer = None
        if not restore:
            self._drop_journal_files()
            self.version += 1
            return self.view()
        assert self.document is not None
        original, module = self.path, self.module
        base = offer.checkpoint or original
        # A log on a new file replays on the new scenario the first run started from.
        exists = base.exists()
        document = load(base, allowed_roots=self.roots) if exists else self._new_scenario(base)
        # The copy lies beside the file, so its relative references mean the same there.
        document.path = original
        document.resource.uri = URI(str(original))
        self._adopt(document, module)
        self.ids.restore(offer.ids, document.resource, offer.counter)
        if offer.checkpoint is not None:
            self.stack.mark_unsaved()
        self.replay_report = self._replay(offer)
        self.version += 1
        return {**self.view(), "replay": self.replay_report}

    def _replay(self, offer: Offer) -> dict[str, Any]:
        applied = 0
        stopped: str | None = None
        for index, entry in enumerate(offer.entries):
            try:
                self._replay_one(entry)
            except (EditorError, SceMLError) as error:
                stopped = f"{entry.describe()} could not be replayed: {error}"
                rest = offer.entries[index:]
                kept = self.path.with_name(f".{self.path.stem}.unreplayed.journal")
                ChangeLog(kept).start({"id": offer.journal, "base": "unreplayed"}, rest)
                # The model now holds the base and the changes before `entry`: checkpoint it
                # under a new journal, so the next crash does not replay the refused change.
                self._end_journal()
                self.recover()
                return {"replayed": applied, "stopped": stopped, "kept": str(kept)}
            applied += 1
        # The model is the base plus the whole log: go on with the same journal.
        self.journal_id = offer.journal
        self.seq = offer.entries[-1].seq if offer.entries else offer.seq
        self._log = ChangeLog(self.journal_path)
        header: dict[str, Any] = {"id": offer.journal, "module": self.module}
        if offer.checkpoint is not None:
            header["base"] = "checkpoint"
        else:
            header.update(
                base="file", digest=self.base_digest, ids=offer.ids, counter=offer.counter
            )
        if offer.journal is None:
            self._end_journal()
            self.recover()  # an old copy without a journal: checkpoint it under a new one
        else:
            # Rewritten whole: a torn last line would otherwise sit before the next entry.
            self._log.start(header, offer.entries)
            self._since_base = set(self.stack.done) | {
                step for steps in self.stack.undone.values() for step in steps
            }
        return {"replayed": applied, "stopped": None, "kept": None}

    def _replay_one(self, entry: Entry) -> None:
        if entry.refused is not None:
            raise OperationError(entry.refused)
        before = self.version
        if entry.route == "/api/ops":
            self.apply(entry.body.get("ops"), entry.body.get("label"), entry.tab)
        elif entry.route in ("/api/undo", "/api/redo"):
            move = self.undo if entry.route == "/api/undo" else self.redo
            move(entry.tab)
            if self.version == before:
                raise OperationError("there was nothing to undo or redo in its tab")
        elif entry.route == "/api/copy":
            self.copy(entry.body.get("nodes"), entry.tab)
            self._copied_since_base = True
        else:
            raise OperationError(f"the request {entry.route} is not one a replay knows")


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
