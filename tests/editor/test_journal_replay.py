"""The change log beside the file: a SIGKILL loses at most the last edit; a replay is exact, stops
at what it cannot apply and keeps the rest; a save empties the log."""

from __future__ import annotations

import errno
import signal
from pathlib import Path
from typing import Any

import pytest
from editor.helpers import node_id
from editor.servers import Server, start

from sceml.editor import EditorSession, SessionOptions
from sceml.editor.changelog import ChangeLog, log_path, read_log


def names(view: dict[str, Any]) -> list[str]:
    return sorted(n["name"] for n in view["nodes"])


def request(session: EditorSession, route: str, body: dict[str, Any], tab: str = "A") -> None:
    """What the server does for one change request: apply it, then log it."""
    before = session.version
    session.will_change(route)
    if route == "/api/ops":
        session.apply(body["ops"], body.get("label"), tab)
    elif route == "/api/undo":
        session.undo(tab)
    else:
        session.redo(tab)
    session.record(route, body, tab, before)


def add(kind: str) -> dict[str, Any]:
    return {"ops": [{"op": "add_node", "kind": kind}]}


def reopen(path: Path) -> EditorSession:
    session = EditorSession(SessionOptions())
    session.open(path)
    return session


def test_a_burst_then_sigkill_loses_nothing_answered(
    servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    server = start(servers, target)
    kinds = ["Stop", "Accelerate", "Decelerate", "TurnLeft", "TurnRight", "Stop"] * 2
    for kind in kinds:  # back to back: no pause lets a checkpoint be written
        server.post("/api/ops", add(kind))
    first = node_id(server.view(), "Stop_1")  # type: ignore[arg-type]
    server.post(
        "/api/ops", {"ops": [{"op": "set", "node": first, "field": "name", "value": "Halt"}]}
    )
    expected = names(server.view())  # type: ignore[arg-type]
    assert server.stop(signal.SIGKILL) == -signal.SIGKILL

    again = start(servers, target)
    offer = again.view()["recovery"]
    assert isinstance(offer, dict) and offer["changes"] >= 1
    restored = again.post("/api/recovery", {"restore": True})
    assert names(restored) == expected
    assert "Halt" in expected and "Stop_2" in expected
    assert restored["replay"] == {"replayed": offer["changes"], "stopped": None, "kept": None}


def test_a_torn_last_line_is_ignored(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    request(first, "/api/ops", add("Stop"))
    request(first, "/api/ops", add("Decelerate"))
    log = log_path(target)
    with log.open("ab") as stream:
        stream.write(b'{"seq":3,"route":"/api/ops","body":{"ops":[{"op":"add_no')  # cut by a crash
    found = read_log(log)
    assert found is not None and [e.seq for e in found.entries] == [1, 2]
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert {"Stop_1", "Decelerate_1"} <= set(names(restored))
    assert restored["replay"]["stopped"] is None
    # The log was rewritten without the torn line, and goes on after the replayed changes.
    request(second, "/api/ops", add("TurnLeft"))
    again = read_log(log)
    assert again is not None and [e.seq for e in again.entries] == [1, 2, 3]


def test_a_replay_stops_at_what_it_cannot_apply_and_keeps_the_rest(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    request(first, "/api/ops", add("Stop"))
    assert first.recover() is not None  # a checkpoint: Stop_1 is in the copy, the log is empty
    request(first, "/api/ops", add("Decelerate"), tab="B")
    request(first, "/api/undo", {}, tab="A")  # undoes Stop_1, which only the copy holds
    request(first, "/api/ops", add("TurnLeft"), tab="B")
    second = reopen(target)
    assert second.recovery_offer is not None and len(second.recovery_offer.entries) == 3
    restored = second.resolve_recovery(True)
    report = restored["replay"]
    assert report["replayed"] == 1
    assert report["stopped"].startswith("an Undo (change 3, tab A) could not be replayed")
    assert {"Stop_1", "Decelerate_1"} <= set(names(restored))
    assert "TurnLeft_1" not in names(restored)
    kept = read_log(Path(report["kept"]))
    assert kept is not None and [e.route for e in kept.entries] == ["/api/undo", "/api/ops"]
    assert kept.entries[1].body == add("TurnLeft")


def test_undo_and_redo_per_tab_across_the_replay(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    request(first, "/api/ops", add("Stop"), tab="A")
    request(first, "/api/ops", add("Decelerate"), tab="B")
    request(first, "/api/undo", {}, tab="A")  # tab A's own step, not B's later one
    request(first, "/api/redo", {}, tab="A")
    request(first, "/api/undo", {}, tab="A")
    stop = first.stack.undone["A"][-1].label
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert restored["replay"]["stopped"] is None
    assert "Stop_1" not in names(restored) and "Decelerate_1" in names(restored)
    # The same tab (its name survives a reload) redoes and undoes its own replayed steps.
    assert second.view(tab="A")["redo"] == stop
    assert "Stop_1" in names(second.redo("A"))
    assert "Decelerate_1" not in names(second.undo("B"))
    assert second.view(tab="B")["undo"] is None


def test_ids_of_the_earlier_run_mean_the_same_nodes_after_a_checkpoint(
    examples_copy: Path,
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    accelerate = node_id(first.view(), "Accelerate_1")
    request(first, "/api/ops", {"ops": [{"op": "delete", "nodes": [accelerate]}]})
    request(first, "/api/ops", add("Stop"))  # a new id, after every id of the file's objects
    assert first.recover() is not None
    stop = node_id(first.view(), "Stop_1")
    rename = {"ops": [{"op": "set", "node": stop, "field": "name", "value": "Halt"}]}
    request(first, "/api/ops", rename)
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert restored["replay"]["stopped"] is None
    assert "Halt" in names(restored) and "Stop_1" not in names(restored)
    assert node_id(restored, "Halt") == stop


def test_save_empties_the_log(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    session = reopen(target)
    request(session, "/api/ops", add("Stop"))
    assert log_path(target).exists()
    session.save()
    assert not log_path(target).exists()
    assert reopen(target).recovery_offer is None
    request(session, "/api/undo", {})  # a step the saved file holds: the checkpoint is due
    found = read_log(log_path(target))
    assert found is not None and found.header["base"] == "file"
    assert found.entries[0].refused is not None


def test_a_new_file_killed_before_its_first_save_replays_on_a_new_scenario(
    examples_copy: Path,
) -> None:
    target = examples_copy / "fresh.xmi"
    first = reopen(target)
    request(first, "/api/ops", add("Stop"))
    assert not target.exists()
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert "Stop_1" in names(restored) and restored["replay"]["stopped"] is None
    assert restored["dirty"] is True


def test_a_crash_between_the_checkpoint_and_emptying_the_log_replays_nothing_twice(
    examples_copy: Path,
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    request(first, "/api/ops", add("Stop"))
    request(first, "/api/ops", add("Decelerate"))
    before_checkpoint = log_path(target).read_bytes()
    assert first.recover() is not None
    log_path(target).write_bytes(before_checkpoint)  # the crash hit before the log was emptied
    with log_path(target).open("ab") as stream:  # and one more change was logged after it
        stream.write(b'{"seq":3,"route":"/api/ops","body":' + b'{"ops":[{"op":"add_node",')
        stream.write(b'"kind":"TurnLeft"}]},"tab":"A"}\n')
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert restored["replay"] == {"replayed": 1, "stopped": None, "kept": None}
    found = names(restored)
    assert found.count("Stop_1") == 1 and "Stop_2" not in found and "Decelerate_2" not in found
    assert "TurnLeft_1" in found


def test_an_extract_is_not_written_again_by_a_replay(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = reopen(target)
    chosen = [node_id(first.view(), n) for n in ("Accelerate_2", "Cross_1")]
    extract = {"ops": [{"op": "extract_module", "nodes": chosen, "name": "BikeGo",
                        "library": "library/mine.xmi"}]}  # fmt: skip
    first.will_change("/api/ops")
    first.apply(extract["ops"], None, "A")
    assert first.record("/api/ops", extract, "A", 0), "an extract has the checkpoint due at once"
    library = examples_copy / "library" / "mine.xmi"
    written = library.read_bytes()
    library.write_bytes(written + b"\n")  # edited since, by hand: a replay must leave it be
    # Killed before the checkpoint was written: the replay meets the extract and stops there.
    second = reopen(target)
    restored = second.resolve_recovery(True)
    assert restored["replay"]["replayed"] == 0
    assert restored["replay"]["stopped"].startswith("the edit extract_module (change 1, tab A)")
    assert "it wrote another file (a library)" in restored["replay"]["stopped"]
    assert library.read_bytes() == written + b"\n"
    assert {"Accelerate_2", "Cross_1"} <= set(names(restored))


def test_a_log_that_cannot_be_written_asks_for_the_checkpoint_and_starts_again_after_it(
    examples_copy: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    session = reopen(target)
    request(session, "/api/ops", add("Stop"))

    def full_disk(self: ChangeLog, entry: object) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    with monkeypatch.context() as patched:
        patched.setattr(ChangeLog, "append", full_disk)
        session.will_change("/api/ops")
        session.apply(add("Decelerate")["ops"], None, "A")
        assert session.record("/api/ops", add("Decelerate"), "A", 0), "the checkpoint is due"
    # Not a new log on the file, which would miss Decelerate_1: nothing until the checkpoint.
    request(session, "/api/ops", add("TurnLeft"))
    found = read_log(log_path(target))
    assert found is not None and [e.body for e in found.entries] == [add("Stop")]
    assert session.recover() is not None
    request(session, "/api/ops", add("TurnRight"))
    restored = reopen(target).resolve_recovery(True)
    assert {"Stop_1", "Decelerate_1", "TurnLeft_1"} <= set(names(restored))
    assert "TurnRight_2" in names(restored) and restored["replay"]["replayed"] == 1


def test_a_copy_while_an_offer_waits_keeps_the_offer(examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    request(reopen(target), "/api/ops", add("Stop"))
    second = reopen(target)
    assert second.recovery_offer is not None
    stop_log = log_path(target).read_bytes()
    chosen = [node_id(second.view(), "Cross_1")]
    second.will_change("/api/copy")
    second.copy(chosen, "A")
    assert not second.record("/api/copy", {"nodes": chosen}, "A", second.version)
    assert second.recovery_offer is not None and log_path(target).read_bytes() == stop_log
    # The paste after an edit replaced the offer: what was copied before is not in the log.
    request(second, "/api/ops", add("TurnLeft"))
    assert second.recovery_offer is None
    second.will_change("/api/ops")
    second.apply([{"op": "paste"}], None, "A")
    assert second.record("/api/ops", {"ops": [{"op": "paste"}]}, "A", 0)
