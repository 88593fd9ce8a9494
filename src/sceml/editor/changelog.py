"""The change log beside the file: every change request since the last checkpoint, one line each.

`.NAME.journal` holds a header line (the journal's id, its base: the file as saved, or the
recovery copy written at a sequence number) and then one JSON line per change request that
succeeded: its sequence number, route, body and tab. A line is appended with one `write` before
the answer is sent, so a SIGKILL of the server cannot lose it (the operating system holds it);
a crash while writing can tear only the last line, which reading ignores.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import LoadError
from ..files.writing import write_atomically

#: The requests the log keeps: they change the model, or the clipboard a later paste reads.
LOGGED_ROUTES = frozenset({"/api/ops", "/api/undo", "/api/redo", "/api/copy"})
#: The log format, in the header, so that a later format is refused rather than misread.
FORMAT = 1


def log_path(path: Path) -> Path:
    """Where the change log of `path` lives: `.NAME.journal` beside it."""
    return path.with_name(f".{path.stem}.journal")


def _line(record: dict[str, Any]) -> bytes:
    return (json.dumps(record, ensure_ascii=False, separators=(",", ":")) + "\n").encode()


@dataclass(frozen=True)
class Entry:
    """One logged change request."""

    seq: int
    route: str
    body: dict[str, Any]
    tab: str
    #: Why a replay must not apply it (it writes another file, or undoes what the base holds).
    refused: str | None = None

    def record(self) -> dict[str, Any]:
        found: dict[str, Any] = {"seq": self.seq, "route": self.route, "body": self.body}
        found["tab"] = self.tab
        if self.refused is not None:
            found["refused"] = self.refused
        return found

    def describe(self) -> str:
        """The change in the user's words: its undo label, or what it did."""
        label = self.body.get("label") if self.route == "/api/ops" else None
        if isinstance(label, str) and label:
            what = f"'{label}'"
        elif self.route == "/api/ops":
            ops = self.body.get("ops")
            names = [str(op.get("op")) for op in ops if isinstance(op, dict)] if ops else []
            what = "the edit " + (", ".join(names) or "(empty)")
        else:
            what = {"/api/undo": "an Undo", "/api/redo": "a Redo"}.get(self.route, "a Copy")
        return f"{what} (change {self.seq}{f', tab {self.tab}' if self.tab else ''})"


@dataclass
class Log:
    """A log as read: its header and its complete entries."""

    header: dict[str, Any]
    entries: list[Entry] = field(default_factory=list)


class ChangeLog:
    """The open log of a session: started with a header, then appended to."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._fd: int | None = None

    def start(self, header: dict[str, Any], entries: list[Entry] | None = None) -> None:
        """Replace the log by `header` (and `entries`) atomically, then append after them."""
        self.close()
        lines = [_line({"journal": FORMAT, **header})]
        lines += [_line(entry.record()) for entry in entries or []]
        write_atomically(self.path, b"".join(lines))
        self._fd = os.open(self.path, os.O_WRONLY | os.O_APPEND)

    @property
    def started(self) -> bool:
        return self._fd is not None

    def append(self, entry: Entry) -> None:
        """Append one entry with a single write (whole, or torn only by a crash inside it)."""
        assert self._fd is not None, "the log is not started"
        data = _line(entry.record())
        while data:  # a regular file takes it whole but on a full disk; then the rest, or OSError
            data = data[os.write(self._fd, data) :]

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None

    def remove(self) -> None:
        """Close and delete the log (everything is saved, or the user dropped it)."""
        self.close()
        self.path.unlink(missing_ok=True)


def read_log(path: Path) -> Log | None:
    """The log at `path` (None if there is none); a torn last line is left out.

    A damaged line before the last is a LoadError naming the file and line: the entries after
    it cannot be trusted to follow the ones before.
    """
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return None
    lines = data.split(b"\n")
    # A complete log ends with a newline: the last piece is empty, or the torn tail of a write.
    complete, torn = lines[:-1], lines[-1]
    del torn  # a crash cut it short: the request it logged never got its answer
    records: list[dict[str, Any]] = []
    for number, raw in enumerate(complete, start=1):
        try:
            record = json.loads(raw)
        except ValueError:
            record = None
        if not isinstance(record, dict):
            raise LoadError("a damaged line in the change log", file=path, line=number)
        records.append(record)
    if not records:
        return None  # the header itself was torn: nothing was logged after it
    header = records[0]
    if header.get("journal") != FORMAT:
        raise LoadError(f"not a change log of format {FORMAT}", file=path, line=1)
    log = Log(header)
    for number, record in enumerate(records[1:], start=2):
        try:
            entry = Entry(
                int(record["seq"]),
                str(record["route"]),
                dict(record["body"]),
                str(record["tab"]),
                record.get("refused"),
            )
        except (KeyError, TypeError, ValueError):
            raise LoadError(
                "a change log entry without seq, route, body or tab", file=path, line=number
            ) from None
        log.entries.append(entry)
    return log
