"""The crash journal in real Chromium against real `sceml edit` processes (issue 27): a kill -9
right after a burst of edits loses none the page showed, and a restore that stops says why."""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest
from browser import CHROMIUM
from editor.servers import Server, start
from editor_e2e.test_editor import node, open_editor
from editor_e2e.test_team import add_from_palette, names_in, status
from playwright.sync_api import Page, expect

from sceml.editor import EditorSession, SessionOptions

pytestmark = pytest.mark.skipif(
    not CHROMIUM.exists() and not os.environ.get("CI"),
    reason="Debian's chromium (/usr/bin/chromium) is not installed",
)


def fit(page: Page) -> None:
    """Fit the diagram to the view: the canvas draws only the nodes in view."""
    page.get_by_role("toolbar", name="Editor").get_by_role("button", name="Fit view").click()
    page.wait_for_timeout(300)  # the fit's animation


def test_a_kill_9_right_after_a_burst_loses_no_edit_the_page_showed(
    page: Page, servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    server = start(servers, target)
    open_editor(page, server.url)
    for label in ["Stop", "Decelerate", "Stop"]:
        add_from_palette(page, label)  # each waits for its answer, none for a checkpoint
    # Killed at once: the checkpoint waits for a pause of half a second after the last edit.
    server.stop(signal.SIGKILL)
    assert "Stop_1" not in names_in(target)

    again = start(servers, target)
    open_editor(page, again.url)
    dialog = page.get_by_role("dialog", name="Restore unsaved changes")
    expect(dialog).to_contain_text("logged beside it")
    dialog.get_by_role("button", name="Restore").click()
    expect(dialog).to_have_count(0)
    fit(page)
    for name in ["Stop_1", "Decelerate_1", "Stop_2"]:
        expect(node(page, name)).to_be_visible()
    expect(status(page)).to_contain_text("Unsaved changes")


def test_a_restore_that_stops_names_the_change_it_could_not_replay(
    page: Page, servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    first = EditorSession(SessionOptions())
    first.open(target)
    add = {"ops": [{"op": "add_node", "kind": "Stop"}]}
    first.will_change("/api/ops")
    first.apply(add["ops"], None, "other")
    first.record("/api/ops", add, "other", 0)
    assert first.recover() is not None  # Stop_1 is in the checkpoint; the log starts again
    before = first.version
    first.undo("other")  # undoes a step only the checkpoint holds: not replayable
    first.record("/api/undo", {}, "other", before)

    server = start(servers, target)
    open_editor(page, server.url)
    page.get_by_role("dialog", name="Restore unsaved changes").get_by_role(
        "button", name="Restore"
    ).click()
    alert = page.get_by_role("alert", name="Restore stopped")
    expect(alert).to_contain_text("an Undo (change 2, tab other) could not be replayed")
    expect(alert).to_contain_text(".uis1-concrete.unreplayed.journal")
    fit(page)
    expect(node(page, "Stop_1")).to_be_visible()
