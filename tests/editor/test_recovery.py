"""Nothing lost on any stop: SIGINT, SIGTERM and SIGHUP write the recovery copy; after a SIGKILL
the copy the journal kept holds every edit but the one being written, and the next run offers it."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest
from editor.servers import Server, start

from sceml.editor import EditorSession, SessionOptions
from sceml.editor.journal import Journal
from sceml.model.loading import load


def node_names(path: Path) -> set[str]:
    return {str(node.name) for node in load(path).root.nodes}


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_every_stop_signal_writes_the_recovery_copy(
    servers: list[Server], examples_copy: Path, sig: int
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    before = target.read_bytes()
    server = start(servers, target)
    server.post("/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]})
    assert server.stop(sig) == 0, server.output()
    recovered = examples_copy / ".uis1-concrete.recovered.xmi"
    assert f"unsaved changes were written to {recovered}" in server.output()
    assert "Stop_1" in node_names(recovered)
    assert target.read_bytes() == before


def test_after_a_kill_the_next_run_offers_the_journal(
    servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    recovered = examples_copy / ".uis1-concrete.recovered.xmi"
    server = start(servers, target)
    server.post("/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]})
    server.post("/api/ops", {"ops": [{"op": "add_node", "kind": "Decelerate"}]})
    deadline = time.monotonic() + 20
    while not (recovered.exists() and "Decelerate_1" in node_names(recovered)):
        assert time.monotonic() < deadline, "the journal did not write the second edit"
        time.sleep(0.05)
    assert server.stop(signal.SIGKILL) == -signal.SIGKILL

    again = start(servers, target)
    assert f"unsaved changes of an earlier run are in {recovered}" in again.output()
    offer = again.view()["recovery"]
    assert isinstance(offer, dict) and offer["path"] == str(recovered)
    assert "Stop_1" not in {n["name"] for n in again.view()["nodes"]}  # type: ignore[union-attr]
    restored = again.post("/api/recovery", {"restore": True})
    assert {"Stop_1", "Decelerate_1"} <= {n["name"] for n in restored["nodes"]}  # type: ignore[union-attr]
    assert restored["dirty"] is True and restored["recovery"] is None
    assert restored["document"]["path"] == str(target)  # type: ignore[index]
    again.post("/api/save", {})
    assert {"Stop_1", "Decelerate_1"} <= node_names(target)
    assert again.stop(signal.SIGTERM) == 0
    assert not recovered.exists(), "everything was saved: no copy is left"


def test_dropping_the_offer_deletes_the_copy(examples_copy: Path) -> None:
    first = EditorSession(SessionOptions())
    first.open(examples_copy / "uis1-concrete.xmi")
    first.apply([{"op": "add_node", "kind": "Stop"}])
    copy = first.recover()
    assert copy is not None and copy.exists()
    second = EditorSession(SessionOptions())
    view = second.open(examples_copy / "uis1-concrete.xmi")
    assert view["recovery"]["path"] == str(copy)
    assert view["recovery"]["changes"] == 0, "the copy holds the change: nothing to replay"
    assert second.recover() is None and copy.exists(), "an offered copy is kept until answered"
    assert second.resolve_recovery(False)["recovery"] is None
    assert not copy.exists()


def test_a_copy_older_than_the_file_is_not_offered(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    copy = examples_copy / ".uis1-concrete.recovered.xmi"
    copy.write_bytes(target.read_bytes())
    later = copy.stat().st_mtime + 10
    os.utime(target, (later, later))
    session = EditorSession(SessionOptions())
    assert session.open(target)["recovery"] is None


def test_the_journal_writes_after_each_change_and_folds_a_burst() -> None:
    writes: list[int] = []
    changes = 0

    def write() -> None:
        writes.append(changes)
        time.sleep(0.05)  # a slow disk: changes arriving meanwhile wait for the next write

    journal = Journal(write)
    for _ in range(20):
        changes += 1
        journal.changed()
    assert journal.flush(timeout=10)
    assert writes[-1] == 20, "the last write covers the last change"
    assert len(writes) < 20, "changes that arrived during a write were folded into one"
    journal.stop()


def test_the_journal_waits_for_the_changes_to_pause_and_a_stop_writes_at_once() -> None:
    writes: list[float] = []
    journal = Journal(lambda: writes.append(time.monotonic()), quiet=30.0, patience=60.0)
    journal.changed()
    journal.changed()
    assert not journal.flush(timeout=0.3), "written before the changes paused"
    assert writes == []
    journal.stop()
    assert len(writes) == 1, "the stop wrote both changes at once, in one write"


def test_the_journal_writes_within_its_patience_while_changes_keep_coming() -> None:
    writes: list[float] = []
    journal = Journal(lambda: writes.append(time.monotonic()), quiet=30.0, patience=0.2)
    deadline = time.monotonic() + 20
    while not writes:
        assert time.monotonic() < deadline, "a steady stream of changes was never written"
        journal.changed()  # never a pause of 30 s: only the patience can start the write
        time.sleep(0.02)
    journal.stop()
