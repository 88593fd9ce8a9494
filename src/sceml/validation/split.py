"""Validating a large scenario in two processes, with the same diagnostics in the same order.

A scenario's checks fall into two shares of about equal cost at scale: the rules of the scenario
object itself (the simultaneity check C001, the graph rules, module expansion) followed by the
through-modules pass, and the rules of every other object (nodes, actors, values, positions), each
of which reads only its own corner of the model. After the model is loaded, the process forks:
the child runs the second share on its copy of the model (the same objects at the same
addresses, shared until written) and sends back what it found, while the parent runs the first.
The parent then puts them in the order one process would have produced them (scenario,
objects, through-modules) and drops repeats, as `iter_diagnostics` does.

It is worth it only for a large scenario (`SPLIT_FROM` nodes): a fork and a pipe cost a few
milliseconds, and for a small scenario so does the whole validation. The child's copies of the
pages it writes (reference counts, mostly) cost memory: 37-46 % of the parent's at 50k and 208k
nodes, so a scenario is split only where the memory the system has free (and, in a memory
control group, its room) could hold the parent's size again. Where there is no `fork`
(Windows) or only one processor, or the child fails for any reason (killed, out of memory), the
parent runs the second share itself: the result is always that of one process.
"""

from __future__ import annotations

import contextlib
import os
import signal
from collections.abc import Iterable
from pathlib import Path

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model.documents import Document
from ..processors import processors
from .context import Context
from .engine import Key, each_object, objects, through_modules, unique
from .limits import Limits
from .registry import REGISTRY, Registry

#: The number of scenario nodes from which validation is split in two.
SPLIT_FROM = 2000

#: A diagnostic as the child sends it: its fields, and the address of its element (the same
#: object in both processes, since the child is a fork of the parent).
_Sent = tuple[Severity, str, str, str | None, str | None, str | None, int | None, int | None]


def worth_splitting(model: EObject) -> bool:
    """Whether `validate_split` would run `model` in two processes."""
    return (
        hasattr(os, "fork")
        and processors() > 1
        and isinstance(model, scm.Scenario)
        and len(model.nodes) >= SPLIT_FROM
        and room_for_a_child()
    )


def room_for_a_child() -> bool:
    """Whether the memory free to this process could hold its own size again (the most a child
    copies); True where that cannot be read (not Linux)."""
    try:
        size = _kilobytes(Path("/proc/self/status"), "VmRSS")
        free = _kilobytes(Path("/proc/meminfo"), "MemAvailable")
    except (OSError, ValueError):
        return True
    for limit, used in _memory_groups():
        free = min(free, limit - used)
    return size < free


def _kilobytes(path: Path, field: str) -> int:
    """A `field: N kB` line of a /proc file, in kB."""
    for line in path.read_text().splitlines():
        if line.startswith(field + ":"):
            return int(line.split()[1])
    raise ValueError(f"no {field} in {path}")


def _memory_groups() -> list[tuple[int, int]]:
    """(limit, use) in kB of the memory control groups this process is in that have a limit."""
    found = []
    for group in ("/sys/fs/cgroup", "/sys/fs/cgroup/memory"):  # cgroup v2, v1 (as mounted here)
        for limit_name, used_name in (
            ("memory.max", "memory.current"),
            ("memory.limit_in_bytes", "memory.usage_in_bytes"),
        ):
            try:
                limit = (Path(group) / limit_name).read_text().strip()
                used = (Path(group) / used_name).read_text().strip()
            except OSError:
                continue
            if limit.isdigit() and used.isdigit():
                found.append((int(limit) // 1024, int(used) // 1024))
    return found


def validate_split(
    model: EObject,
    *,
    document: Document | None = None,
    limits: Limits | None = None,
    osc_version: str | None = None,
    osc_profile: str | None = None,
    registry: Registry = REGISTRY,
) -> list[Diagnostic]:
    """Every diagnostic of `model`, as `iter_diagnostics` gives them, the objects' own rules run
    in a forked child (see the module's docstring)."""
    context = Context(model, document, limits or Limits(), osc_version, osc_profile)
    try:
        everything = list(objects(model, context))
        first, rest = everything[:1], everything[1:]
        theirs = _in_child(rest, context, document, registry, everything)
        try:
            mine = list(each_object(first, context, document, registry))
            through = list(through_modules(context, document, registry))
            found = theirs.result() if theirs is not None else None
        except BaseException:  # Ctrl-C, say: the child must not outlive the run
            if theirs is not None:
                theirs.stop()
            raise
        if found is None:  # no child, or it failed: its share is done here
            found = list(each_object(rest, context, document, registry))
        seen: set[Key] = set()
        return list(unique([*mine, *found, *through], seen))
    finally:
        context.release()


class _Child:
    """A forked child's pipe and process id: `result` reads what it found and reaps it."""

    def __init__(self, pid: int, reader: int, everything: list[EObject]) -> None:
        self.pid = pid
        self.reader = reader
        self.everything = everything

    def result(self) -> list[Diagnostic] | None:
        """The child's diagnostics, or None if it failed."""
        try:
            with os.fdopen(self.reader, "rb") as stream:
                data = stream.read()
        finally:
            _, status = os.waitpid(self.pid, 0)
        if status != 0 or not data:
            return None
        import pickle  # already imported by _in_child, before the fork

        sent: list[_Sent] = pickle.loads(data)
        if not sent:
            return []  # a valid scenario: no table of a million objects' addresses to build
        by_address = {id(obj): obj for obj in self.everything}
        return [
            Diagnostic(
                severity,
                code,
                message,
                fragment,
                path,
                file,
                line,
                by_address.get(element) if element is not None else None,
            )
            for severity, code, message, fragment, path, file, line, element in sent
        ]

    def stop(self) -> None:
        """End the child early (the parent's own share failed or was interrupted)."""
        with contextlib.suppress(OSError):
            os.kill(self.pid, signal.SIGKILL)
        with contextlib.suppress(OSError):
            os.close(self.reader)
        with contextlib.suppress(OSError):
            os.waitpid(self.pid, 0)


def _in_child(
    rest: Iterable[EObject],
    context: Context,
    document: Document | None,
    registry: Registry,
    everything: list[EObject],
) -> _Child | None:
    """Fork a child that runs `rest`'s rules and writes what it found into a pipe; None where
    that cannot be done (the caller then runs them itself)."""
    # Imported here, before the fork, for both processes: every `sceml validate` imports this
    # module, and only a split run (2,000 nodes or more) needs pickle (about 1 ms to import).
    import pickle

    try:
        reader, writer = os.pipe()
    except OSError:
        return None
    try:
        pid = os.fork()
    except OSError:
        os.close(reader)
        os.close(writer)
        return None
    if pid == 0:  # the child: never returns
        os.close(reader)
        status = 1
        try:
            sent: list[_Sent] = [
                (
                    d.severity,
                    d.code,
                    d.message,
                    d.fragment,
                    d.path,
                    d.file,
                    d.line,
                    id(d.element) if d.element is not None else None,
                )
                for d in each_object(rest, context, document, registry)
            ]
            data = pickle.dumps(sent, protocol=pickle.HIGHEST_PROTOCOL)
            with os.fdopen(writer, "wb") as stream:
                stream.write(data)
            status = 0
        finally:
            # Ends the child here, whatever happened: no exit handlers, no buffers of the
            # parent's written twice, nothing freed.
            os._exit(status)
    os.close(writer)
    return _Child(pid, reader, everything)
