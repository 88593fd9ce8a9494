"""What an earlier run left for recovery, and from what base its changes are replayed.

Two files beside `NAME.xmi`: the checkpoint `.NAME.recovered.xmi` (the whole unsaved model,
written when the edits pause; an XML comment names the journal and the last change it holds),
and the change log `.NAME.journal` (changelog.py: the changes since). A crash may fall between
writing the checkpoint and emptying the log; the sequence numbers make that safe: entries the
checkpoint already holds are skipped.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import LoadError
from .changelog import Entry, log_path, read_log

#: The comment the checkpoint carries: `<!-- sceml-journal {"journal": ..., "seq": ...} -->`.
NOTE_PREFIX = "sceml-journal "
_NOTE = re.compile(rb"<!-- sceml-journal (\{.*?\}) -->")


def checkpoint_path(path: Path) -> Path:
    """Where the checkpoint of `path` lives: `.NAME.recovered.xmi` beside it."""
    return path.with_name(f".{path.stem}.recovered{path.suffix or '.xmi'}")


def file_digest(path: Path) -> str | None:
    """The SHA-256 of the file's bytes (None: no file yet), to tell whether it changed."""
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except FileNotFoundError:
        return None


def checkpoint_note(path: Path) -> dict[str, Any] | None:
    """The journal position a checkpoint holds (None: a copy without one, or unreadable)."""
    try:
        with path.open("rb") as stream:
            head = stream.read(1 << 20)
    except OSError:
        return None
    found = _NOTE.search(head)
    if found is None:
        return None
    try:
        note = json.loads(found.group(1))
    except ValueError:
        return None
    return note if isinstance(note, dict) else None


@dataclass
class Offer:
    """Unsaved changes of an earlier run: a base (the checkpoint, or the file) and the changes
    to replay on it."""

    #: The checkpoint to load, or None to replay on the file itself.
    checkpoint: Path | None
    #: The change log beside the file (it may not exist).
    log: Path
    entries: list[Entry] = field(default_factory=list)
    #: The journal the entries belong to, and the ids the base's objects had in that run.
    journal: str | None = None
    #: The last change the checkpoint holds (0: none, or no checkpoint).
    seq: int = 0
    ids: dict[str, str] = field(default_factory=dict)
    counter: int = 0
    #: A log that could not be used (damaged, or for a file changed since), for the report.
    problem: str | None = None

    @property
    def shown(self) -> Path:
        """The file the page names: the checkpoint, or the log when there is none."""
        return self.checkpoint if self.checkpoint is not None else self.log


def find_offer(path: Path, module: str | None) -> Offer | None:
    """The unsaved changes an earlier run left beside `path`, or None."""
    checkpoint = checkpoint_path(path)
    note = checkpoint_note(checkpoint) if checkpoint.is_file() else None
    problem = None
    try:
        log = read_log(log_path(path))
    except LoadError as error:
        log, problem = None, str(error)
    if log is not None and log.header.get("module") == module:
        journal = str(log.header.get("id"))
        if note is not None and note.get("id") == journal:
            seq = int(note.get("seq", 0))
            later = [e for e in log.entries if e.seq > seq]
            return _offer(checkpoint, later, note, log_path(path))
        if log.header.get("base") == "file" and log.entries:
            if log.header.get("digest") == file_digest(path):
                return _offer(None, log.entries, log.header, log_path(path))
            problem = "the change log is for the file as it was before it was changed elsewhere"
    if checkpoint.is_file() and not _older_than_file(checkpoint, path):
        found = _offer(checkpoint, [], note or {}, log_path(path))
        found.problem = problem
        return found
    return None


def _offer(checkpoint: Path | None, entries: list[Entry], note: dict[str, Any], log: Path) -> Offer:
    ids = note.get("ids")
    return Offer(
        checkpoint,
        log,
        entries,
        journal=str(note["id"]) if "id" in note else None,
        seq=int(note.get("seq", 0)) if checkpoint is not None else 0,
        ids=ids if isinstance(ids, dict) else {},
        counter=int(note.get("counter", 0)),
    )


def _older_than_file(copy: Path, path: Path) -> bool:
    # The file was saved after the copy was written: the copy is stale.
    return path.is_file() and copy.stat().st_mtime < path.stat().st_mtime
