"""Validating a large scenario in two processes, with the same diagnostics in the same order.

After the model is loaded, the process forks; the child works on its copy of the model (the
same objects at the same addresses, shared until written) and sends back what it found. The
parent runs the rules that read the expansion of the module uses (the simultaneity check C001,
E003, M017, which expand the uses) and then the through-modules pass (rules on the expanded
copies); the child runs the scenario's other rules (its graph rules). Then both take parts of
the other objects (nodes, actors, values, positions: each of their rules reads only its own
corner of the model) from one pipe until none is left (`Parts`), so they end together whatever
each share costs: at 10k nodes of `benchmarks/scale_scenarios.py` the parent takes about a
sixth of the parts, and the more, the fewer module uses there are. The parent then puts the
findings in the order one process would have produced them (the scenario's rules in the
registry's order, the objects, the through-modules pass) and drops repeats, as
`iter_diagnostics` does. Any rule could run on either side with the same findings; the shares
only decide where the time goes.

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
from dataclasses import dataclass
from pathlib import Path

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model.documents import Document
from ..processors import processors
from .context import Context
from .engine import Key, each_object, objects, run_rule, through_modules, unique
from .limits import Limits
from .reads import EXPANSION
from .registry import REGISTRY, Registry, Rule

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
        rules = registry.rules_for(model.eClass)
        mine = [rule for rule in rules if _reads_expansion(rule)]
        share = Share(model, [rule for rule in rules if not _reads_expansion(rule)])
        parts = Parts(everything[1:])
        try:
            theirs = (
                _in_child(share, parts, context, document, registry, everything)
                if parts.shared
                else None
            )
            try:
                own = {rule.code: run_rule(rule, model, context, document) for rule in mine}
                through = list(through_modules(context, document, registry))
                # Then the objects' rules the child has not come to yet.
                done = parts.take(context, document, registry)
                found = theirs.result() if theirs is not None else None
            except BaseException:  # Ctrl-C, say: the child must not outlive the run
                if theirs is not None:
                    theirs.stop()
                raise
        finally:
            parts.close()
        if found is None:  # no child, or it failed: its share is done here
            found = share.run(context, document), parts.rest_of(done, context, document, registry)
        on_model, their_parts = found
        own.update(on_model)
        in_order = [d for rule in rules for d in own[rule.code]]
        on_objects = [
            d for n in range(len(parts)) for d in (done[n] if n in done else their_parts[n])
        ]
        seen: set[Key] = set()
        return list(unique([*in_order, *on_objects, *through], seen))
    finally:
        context.release()


def _reads_expansion(rule: Rule) -> bool:
    """Whether a rule reads the expansion of the module uses (as declared; a rule that declares
    nothing is counted in): it goes with the through-modules pass, which reads it too."""
    return rule.reads is None or EXPANSION in rule.reads.aspects


#: Findings per part of the objects, by the part's number.
ByPart = dict[int, list[Diagnostic]]
#: A child's findings: per rule code on the scenario, and per part of the objects it took.
Found = tuple[dict[str, list[Diagnostic]], ByPart]


@dataclass(frozen=True)
class Share:
    """The scenario's rules the child runs (before it takes parts of the objects)."""

    model: EObject
    rules: list[Rule]

    def run(self, context: Context, document: Document | None) -> dict[str, list[Diagnostic]]:
        return {rule.code: run_rule(rule, self.model, context, document) for rule in self.rules}


class Parts:
    """The objects other than the scenario, in parts that either process takes, each once.

    The parts' numbers wait in a pipe that both processes read (four bytes a number: a read
    that small is never split between readers), so the child takes parts from the start while
    the parent runs its own share, and then the parent takes the rest: neither waits for the
    other, whatever the share of each costs in a given scenario. The findings are put back in
    the parts' order.
    """

    #: At most this many parts: their numbers must fit the pipe's buffer (64 KiB on Linux)
    #: before anyone reads them.
    MOST = 4096
    #: At least this many objects a part: a read of the pipe per part stays a small cost.
    FEWEST = 32

    def __init__(self, rest: list[EObject]) -> None:
        self.rest = rest
        self.size = max(self.FEWEST, -(-len(rest) // self.MOST))
        self.count = -(-len(rest) // self.size)
        #: The pipe the numbers wait in; None where none could be made: then no child shares
        #: the parts, and the parent takes them all.
        self.reader: int | None = None
        try:
            reader, writer = os.pipe()
        except OSError:
            return
        try:
            os.write(writer, b"".join(n.to_bytes(4, "little") for n in range(self.count)))
        finally:
            os.close(writer)  # then a read after the last number finds the end
        self.reader = reader

    @property
    def shared(self) -> bool:
        return self.reader is not None

    def __len__(self) -> int:
        return self.count

    def part(self, number: int) -> list[EObject]:
        return self.rest[number * self.size : (number + 1) * self.size]

    def take(self, context: Context, document: Document | None, registry: Registry) -> ByPart:
        """Take parts until none is left, and run their objects' rules."""
        if self.reader is None:
            return self.rest_of({}, context, document, registry)
        done: ByPart = {}
        while data := os.read(self.reader, 4):
            number = int.from_bytes(data, "little")
            done[number] = list(each_object(self.part(number), context, document, registry))
        return done

    def rest_of(
        self, done: ByPart, context: Context, document: Document | None, registry: Registry
    ) -> ByPart:
        """The parts not in `done` (those a failed child took), run here."""
        return {
            n: list(each_object(self.part(n), context, document, registry))
            for n in range(self.count)
            if n not in done
        }

    def close(self) -> None:
        if self.reader is not None:
            with contextlib.suppress(OSError):
                os.close(self.reader)
            self.reader = None


class _Child:
    """A forked child's pipe and process id: `result` reads what it found and reaps it."""

    def __init__(self, pid: int, reader: int, everything: list[EObject]) -> None:
        self.pid = pid
        self.reader = reader
        self.everything = everything

    def result(self) -> Found | None:
        """The child's findings, or None if it failed."""
        try:
            with os.fdopen(self.reader, "rb") as stream:
                data = stream.read()
        finally:
            _, status = os.waitpid(self.pid, 0)
        if status != 0 or not data:
            return None
        import pickle  # already imported by _in_child, before the fork

        on_model: dict[str, list[_Sent]]
        on_parts: dict[int, list[_Sent]]
        on_model, on_parts = pickle.loads(data)
        if not any(on_parts.values()) and not any(on_model.values()):
            # A valid scenario: no table of a million objects' addresses to build.
            return {code: [] for code in on_model}, {number: [] for number in on_parts}
        by_address = {id(obj): obj for obj in self.everything}
        return (
            {code: self._diagnostics(sent, by_address) for code, sent in on_model.items()},
            {number: self._diagnostics(sent, by_address) for number, sent in on_parts.items()},
        )

    @staticmethod
    def _diagnostics(sent: list[_Sent], by_address: dict[int, EObject]) -> list[Diagnostic]:
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
    share: Share,
    parts: Parts,
    context: Context,
    document: Document | None,
    registry: Registry,
    everything: list[EObject],
) -> _Child | None:
    """Fork a child that takes parts of the objects, then runs `share`, and writes what it found
    into a pipe; None where that cannot be done (the caller then runs it all itself)."""
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
            # Its rules on the scenario first, then parts until none is left: the two processes
            # then end within a part of each other, whatever each share costs.
            on_model = share.run(context, document)
            on_parts = parts.take(context, document, registry)
            sent = (
                {code: _sent(found) for code, found in on_model.items()},
                {number: _sent(found) for number, found in on_parts.items()},
            )
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


def _sent(diagnostics: list[Diagnostic]) -> list[_Sent]:
    """Diagnostics as the pipe carries them: the element they name by its address, which is the
    same object's in both processes."""
    return [
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
        for d in diagnostics
    ]
