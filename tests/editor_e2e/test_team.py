"""The editor for a team, in real Chromium against real `sceml edit` processes (issue 27): nothing
lost on any stop, no framing, every tab live with its own undo, invalid numbers explained."""

from __future__ import annotations

import http.server
import os
import re
import signal
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from browser import CHROMIUM
from editor.servers import Server, start
from editor_e2e.test_editor import commit, node, open_editor, ops_answer
from playwright.sync_api import Browser, Page, expect

from sceml.model.loading import load, load_library

pytestmark = pytest.mark.skipif(
    not CHROMIUM.exists() and not os.environ.get("CI"),
    reason="Debian's chromium (/usr/bin/chromium) is not installed",
)

#: How long a page may take to show another page's edit (ms).
LIVE = 15_000


def names_in(path: Path) -> set[str]:
    return {str(n.name) for n in load(path).root.nodes}


def status(page: Page):  # noqa: ANN201 - a Playwright Locator
    return page.get_by_role("toolbar", name="Editor").get_by_role("status")


def fitted_count(page: Page, name: str, want: int) -> None:
    """Wait until `page` draws `want` nodes named `name` with the whole diagram in view.

    The canvas draws only the nodes in view (React Flow's onlyRenderVisibleElements), and a
    node another tab adds is placed in that tab's view: this page's view may not show it. So
    each look fits the view first, as a user would, and a count of 0 means gone, not off-screen.
    """
    deadline = time.monotonic() + LIVE / 1000
    while True:
        page.get_by_role("toolbar", name="Editor").get_by_role("button", name="Fit view").click()
        page.wait_for_timeout(300)  # the fit's 200 ms animation, then the nodes it brings in
        count = node(page, name).count()
        if count == want:
            return
        if time.monotonic() > deadline:
            raise AssertionError(f"{count} nodes named {name!r} in view, expected {want}")


def add_from_palette(page: Page, label: str) -> None:
    palette = page.get_by_role("region", name="Palette")
    with ops_answer(page):
        palette.get_by_role("button", name=label, exact=True).click()


def test_kill_term_with_unsaved_edits_then_reopen(
    page: Page, servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    server = start(servers, target)
    open_editor(page, server.url)
    add_from_palette(page, "Stop")
    expect(status(page)).to_contain_text("Unsaved changes")
    assert server.stop(signal.SIGTERM) == 0
    recovered = examples_copy / ".uis1-concrete.recovered.xmi"
    assert "Stop_1" in names_in(recovered) and "Stop_1" not in names_in(target)

    # Reopen: the recovered copy opens as a scenario of its own, with the edit in it.
    again = start(servers, recovered)
    open_editor(page, again.url)
    expect(node(page, "Stop_1")).to_be_visible()


def test_a_kill_9_loses_nothing_the_page_showed_and_the_next_run_offers_it(
    page: Page, servers: list[Server], examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    server = start(servers, target)
    open_editor(page, server.url)
    add_from_palette(page, "Stop")
    add_from_palette(page, "Decelerate")
    # Decelerate, which UIS1 has none of: its Accelerate_1 would be found before the edit.
    recovered = examples_copy / ".uis1-concrete.recovered.xmi"
    deadline = time.monotonic() + 10
    while not (recovered.exists() and "Decelerate_1" in names_in(recovered)):
        assert time.monotonic() < deadline, "the journal did not keep the last edit"
        time.sleep(0.05)
    server.stop(signal.SIGKILL)

    again = start(servers, target)
    open_editor(page, again.url)
    dialog = page.get_by_role("dialog", name="Restore unsaved changes")
    expect(dialog).to_contain_text(str(recovered))
    dialog.get_by_role("button", name="Restore").click()
    expect(node(page, "Decelerate_1")).to_be_visible()
    expect(node(page, "Stop_1")).to_be_visible()
    expect(status(page)).to_contain_text("Unsaved changes")


def test_text_typed_without_enter_survives_a_reload(
    page: Page, editor: object, examples_copy: Path
) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    url = editor(target)  # type: ignore[operator]
    open_editor(page, url)
    node(page, "TurnRight_1").click()
    name = page.get_by_role("region", name="Properties").get_by_label("Name", exact=True)
    name.fill("TurnAtTheCorner")
    page.once("dialog", lambda dialog: dialog.accept())  # "leave with unsaved changes?"
    page.reload()
    expect(node(page, "TurnAtTheCorner")).to_be_visible()
    expect(node(page, "TurnRight_1")).to_have_count(0)


def test_a_framed_page_cannot_act(page: Page, editor: object, examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    url = editor(target)  # type: ignore[operator]
    before = names_in(target)
    refusals: list[str] = []
    page.on("console", lambda message: refusals.append(message.text))
    with attacker_site(url) as attacker:
        page.goto(attacker)
        frame = page.frame_locator("#victim")
        # The browser refused to draw the editor inside the frame, and said why.
        for _ in range(50):
            if any("frame-ancestors" in text for text in refusals):
                break
            page.wait_for_timeout(100)
        assert any("frame-ancestors 'none'" in text for text in refusals), refusals
        expect(frame.get_by_role("region", name="Palette")).to_have_count(0)
        page.mouse.click(60, 200)
        page.mouse.click(300, 300)
    open_editor(page, url)
    assert page.evaluate("fetch('/api/view').then(r => r.json()).then(v => v.dirty)") is False
    assert names_in(target) == before


class _Attacker(http.server.BaseHTTPRequestHandler):
    page = b""

    def do_GET(self) -> None:  # noqa: N802 - http.server's name
        self.send_response(200)
        self.send_header("Content-Type", "text/html")
        self.end_headers()
        self.wfile.write(self.page)

    def log_message(self, format: str, *args: object) -> None:  # noqa: A002
        pass


class attacker_site:  # noqa: N801 - used as a context manager, like open()
    """Another local site whose page frames the editor full size."""

    def __init__(self, victim: str) -> None:
        handler = type("Handler", (_Attacker,), {})
        handler.page = (
            '<!doctype html><body style="margin:0">'
            f'<iframe id="victim" src="{victim}" style="border:0;width:1900px;height:1100px">'
            "</iframe></body>"
        ).encode()
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    def __enter__(self) -> str:
        self.thread.start()
        return f"http://localhost:{self.server.server_address[1]}/"

    def __exit__(self, *exc: object) -> None:
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture
def two_pages(browser: Browser) -> Iterator[tuple[Page, Page]]:
    context = browser.new_context(viewport={"width": 1600, "height": 1000})
    pages = (context.new_page(), context.new_page())
    errors: list[str] = []
    for each in pages:
        each.set_default_timeout(10_000)
        each.on("pageerror", lambda error: errors.append(str(error)))
    yield pages
    context.close()
    assert errors == []


def test_two_pages_see_each_others_edits_live_and_undo_their_own(
    two_pages: tuple[Page, Page], editor: object, examples_copy: Path
) -> None:
    a, b = two_pages
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(a, url)
    open_editor(b, url)
    # The other page hears of an edit over its event stream: on a loaded machine that can take
    # longer than an edit of its own, hence the longer wait.
    add_from_palette(a, "Stop")
    fitted_count(b, "Stop_1", 1)
    add_from_palette(b, "Decelerate")
    fitted_count(a, "Decelerate_1", 1)
    expect(status(b)).to_contain_text("Unsaved changes")

    # A's Ctrl+Z undoes A's edit, not B's later one; both pages show it.
    a.get_by_role("application", name="Diagram").click(position={"x": 5, "y": 5})
    with a.expect_response(lambda r: r.url.endswith("/api/undo")):
        a.keyboard.press("Control+z")
    for each in (a, b):
        fitted_count(each, "Stop_1", 0)
        fitted_count(each, "Decelerate_1", 1)
    # B's Undo button undoes B's edit; A sees it go.
    b.get_by_role("toolbar", name="Editor").get_by_role("button", name="Undo").click()
    fitted_count(a, "Decelerate_1", 0)
    expect(status(a)).to_contain_text("Saved")

    # Saving in one page makes every page say so.
    add_from_palette(a, "Stop")
    a.keyboard.press("Control+s")
    for each in (a, b):
        expect(status(each)).to_contain_text("Saved")


def test_a_conflict_between_tabs_is_explained_with_names(
    two_pages: tuple[Page, Page], editor: object, examples_copy: Path
) -> None:
    a, b = two_pages
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(a, url)
    open_editor(b, url)
    add_from_palette(a, "Stop")
    # B renames the Stop A added; A's Undo of the add would throw B's rename away.
    fitted_count(b, "Stop_1", 1)
    node(b, "Stop_1").focus()
    b.keyboard.press("Enter")
    name = b.get_by_role("region", name="Properties").get_by_label("Name", exact=True)
    commit(b, name, "Halt")
    fitted_count(a, "Halt", 1)
    with a.expect_response(lambda r: r.url.endswith("/api/undo")):
        a.get_by_role("toolbar", name="Editor").get_by_role("button", name="Undo").click()
    expect(a.get_by_role("alert")).to_contain_text(
        "'Add Stop' cannot be undone here: another tab changed the same things since ('Set')"
    )
    for each in (a, b):
        fitted_count(each, "Halt", 1)


def test_invalid_number_text_is_marked_with_the_reason(
    page: Page, editor: object, examples_copy: Path
) -> None:
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    node(page, "Accelerate_1").click()
    props = page.get_by_role("region", name="Properties")
    speed = props.get_by_label("Target speed", exact=True)
    before = speed.input_value()
    for text, reason in [
        ("fast", "“fast” is not a number"),
        ("1e400", "1e400 is too large: numbers go up to about 1.8e308"),
    ]:
        speed.fill(text)
        speed.press("Enter")
        expect(speed).to_have_attribute("aria-invalid", "true")
        expect(speed).to_have_accessible_description(reason)
    # Nothing was sent: the canvas still shows the old value.
    expect(node(page, "Accelerate_1")).to_contain_text(f"targetSpeed: {before} m/s")
    speed.fill("9")
    with ops_answer(page):
        speed.press("Enter")
    expect(speed).not_to_have_attribute("aria-invalid", "true")
    expect(node(page, "Accelerate_1")).to_contain_text("targetSpeed: 9 m/s")


def edges_between(page: Page) -> set[tuple[str, str]]:
    view = page.evaluate("fetch('/api/view').then(r => r.json())")
    names = {n["id"]: n["name"] for n in view["nodes"]}
    return {(names[e["source"]], names[e["target"]]) for e in view["edges"]}


def test_connect_by_keyboard_and_search_the_palette(
    page: Page, editor: object, examples_copy: Path
) -> None:
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    # Palette search by typing: "/" focuses it, Enter adds the first match.
    page.get_by_role("application", name="Diagram").click(position={"x": 5, "y": 5})
    page.keyboard.press("/")
    search = page.get_by_role("searchbox", name="Search the palette")
    expect(search).to_be_focused()
    page.keyboard.type("decel")
    palette = page.get_by_role("region", name="Palette")
    expect(palette.get_by_role("button")).to_have_count(1)
    with ops_answer(page):
        page.keyboard.press("Enter")
    expect(node(page, "Decelerate_1")).to_be_visible()
    assert ("Accelerate_1", "Decelerate_1") not in edges_between(page)

    # Select the source, C, select the target, C.
    node(page, "Accelerate_1").focus()
    page.keyboard.press("Enter")
    page.keyboard.press("c")
    expect(page.get_by_text("Connecting from Accelerate_1")).to_be_visible()
    node(page, "Decelerate_1").focus()
    page.keyboard.press("Enter")
    with ops_answer(page):
        page.keyboard.press("c")
    expect(page.get_by_text("Connecting from")).to_have_count(0)
    assert ("Accelerate_1", "Decelerate_1") in edges_between(page)

    # The handles are keyboard controls too: Enter on an out-handle, Enter on an in-handle.
    diagram = page.get_by_role("application", name="Diagram")
    out = diagram.get_by_role("button", name="Connect from Decelerate_1")
    out.focus()
    page.keyboard.press("Enter")
    into = diagram.get_by_role("button", name="Connect Decelerate_1 to End")
    into.focus()
    with ops_answer(page):
        page.keyboard.press("Enter")
    assert ("Decelerate_1", "End") in edges_between(page)


def overlaps(a: dict[str, float], b: dict[str, float]) -> bool:
    return not (
        a["x"] + a["width"] <= b["x"]
        or b["x"] + b["width"] <= a["x"]
        or a["y"] + a["height"] <= b["y"]
        or b["y"] + b["height"] <= a["y"]
    )


def test_modules_expand_with_room_unique_labels_fitting_roles_and_a_way_back(
    page: Page, editor: object, examples_copy: Path
) -> None:
    url = editor(examples_copy / "uis2-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    use = node(page, "CrossingManeuver_1")
    toolbar = page.get_by_role("toolbar", name="Editor")
    with ops_answer(page):  # every position saved, as after any move: the hard case
        toolbar.get_by_role("button", name="Arrange").click()
    with ops_answer(page):
        use.get_by_role("button", name="Expand").click()
    expect(toolbar.get_by_role("button", name="Undo")).to_have_attribute(
        "title", re.compile("Arrange")
    )
    # The internals are labelled by their use: no two boxes share a name.
    expect(node(page, "CrossingManeuver_1.Accelerate_1")).to_be_visible()
    labels = page.locator(".react-flow__node").evaluate_all("els => els.map(e => e.ariaLabel)")
    assert len(labels) == len(set(labels)), labels
    # The frame made room: it covers no other top-level box.
    page.wait_for_timeout(500)
    frame = use.bounding_box()
    for name in ("Accelerate_1", "End", "Root"):
        assert not overlaps(frame, node(page, name).bounding_box()), name

    # Dropping the module again: only fitting actors, a single fitting one chosen already.
    page.get_by_role("region", name="Palette").get_by_role(
        "button", name="CrossingManeuver", exact=True
    ).click()
    dialog = page.get_by_role("dialog", name="Use CrossingManeuver")
    crosser = dialog.get_by_label("crosser", exact=True)
    expect(crosser).to_have_value("pedestrian")
    expect(crosser.locator("option")).to_have_text(["(none)", "pedestrian (Pedestrian)"])
    expect(dialog.get_by_label("trigger", exact=True).locator("option")).to_have_text(
        ["(none)", "ego (Car)", "car (Car)"]
    )
    dialog.get_by_role("button", name="Cancel").click()

    # Open definition, then back to the scenario.
    use.focus()
    page.keyboard.press("Enter")
    props = page.get_by_role("region", name="Properties")
    page.once("dialog", lambda dialog: dialog.accept())  # "Save the changes and open ...?"
    props.get_by_role("button", name="Open definition").click()
    expect(toolbar).to_contain_text("sceml-library.xmi")
    # A module is not offered inside its own definition (the other modules still are).
    palette = page.get_by_role("region", name="Palette")
    expect(palette.get_by_role("button", name="CrossingManeuver", exact=True)).to_have_count(0)
    expect(palette.get_by_role("button", name="Stop", exact=True)).to_be_visible()
    toolbar.get_by_role("button", name="Back to scenario").click()
    expect(toolbar).to_contain_text("uis2-concrete.xmi")
    expect(toolbar.get_by_role("button", name="Back to scenario")).to_have_count(0)


def test_expanding_a_use_fits_the_whole_diagram_in_view(
    page: Page, editor: object, examples_copy: Path
) -> None:
    # UIS2 has no saved places: ELK lays it out again, and the page must fit what it drew (it
    # used to keep the old view, the frame spilling past the canvas's edge).
    url = editor(examples_copy / "uis2-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    node(page, "CrossingManeuver_1").get_by_role("button", name="Expand").click()
    expect(node(page, "CrossingManeuver_1.Cross_1")).to_be_visible()
    page.wait_for_timeout(1500)  # the fit glides for 200 ms
    pane = page.locator(".react-flow").bounding_box()
    assert pane is not None
    for box in page.locator(".react-flow__node").evaluate_all(
        "els => els.map(e => { const r = e.getBoundingClientRect();"
        " return {x: r.x, y: r.y, width: r.width, height: r.height}; })"
    ):
        assert (
            pane["x"] - 1 <= box["x"] and box["x"] + box["width"] <= pane["x"] + pane["width"] + 1
        )
        assert (
            pane["y"] - 1 <= box["y"] and box["y"] + box["height"] <= pane["y"] + pane["height"] + 1
        )


#: Each edge's path, sampled in screen coordinates, against the frame header's box: the ids of
#: the edges that pass through it, and how many edges there were.
EDGES_THROUGH_HEADER = """() => {
  const header = document.querySelector('.sceml-frame .frame-header').getBoundingClientRect();
  const paths = [...document.querySelectorAll('.react-flow__edge-path')];
  const through = paths.filter((path) => {
    const total = path.getTotalLength();
    const screen = path.getScreenCTM();
    for (let i = 0; i <= 200; i++) {
      const p = path.getPointAtLength((total * i) / 200).matrixTransform(screen);
      if (p.x > header.left && p.x < header.right && p.y > header.top && p.y < header.bottom) return true;
    }
    return false;
  });
  return { through: through.map((p) => p.closest('.react-flow__edge').dataset.testid),
           edges: paths.length, header: header.width * header.height };
}"""


@pytest.mark.parametrize("direction", ["Top down", "Left to right"])
def test_edges_keep_clear_of_an_expanded_frames_header(
    page: Page, editor: object, examples_copy: Path, direction: str
) -> None:
    # The edge into the use ended at its in-port, under the header, and crossed its text.
    url = editor(examples_copy / "uis2-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    page.get_by_label("Layout direction").select_option(label=direction)
    node(page, "CrossingManeuver_1").get_by_role("button", name="Expand").click()
    expect(node(page, "CrossingManeuver_1.Cross_1")).to_be_visible()
    page.wait_for_timeout(1500)  # the layout, then the fit's glide
    found = page.evaluate(EDGES_THROUGH_HEADER)
    assert found["header"] > 0 and found["edges"] >= 12, found
    assert found["through"] == [], found


def test_extract_asks_for_the_library_and_undo_takes_its_write_back(
    page: Page, editor: object, examples_copy: Path
) -> None:
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    node(page, "Accelerate_1").click()
    node(page, "TurnRight_1").click(modifiers=["Shift"])
    toolbar = page.get_by_role("toolbar", name="Editor")
    toolbar.get_by_role("button", name="Extract module").click()
    dialog = page.get_by_role("dialog", name="Extract module")
    dialog.get_by_label("Module name").fill("Turning")
    dialog.get_by_label("Module name").press("Enter")
    # Enter without a library writes nowhere: the dialog asks for one.
    expect(dialog.get_by_role("alert")).to_have_text(
        "Choose the library file the module is written into."
    )
    library = examples_copy / "library" / "turning.xmi"
    assert not library.exists()
    dialog.get_by_label("Library").fill("library/turning.xmi")
    with ops_answer(page):
        dialog.get_by_label("Library").press("Enter")
    expect(node(page, "Accelerate_1")).to_have_count(0)
    assert [str(m.name) for m in load_library(library).root.modules] == ["Turning"]
    with page.expect_response(lambda r: r.url.endswith("/api/undo")):
        toolbar.get_by_role("button", name="Undo").click()
    expect(node(page, "Accelerate_1")).to_be_visible()
    assert not library.exists()  # Extract made the file; Undo removes it


def test_an_edit_is_answered_with_a_patch_of_that_node(
    page: Page, editor: object, examples_copy: Path
) -> None:
    url = editor(examples_copy / "uis1-concrete.xmi")  # type: ignore[operator]
    open_editor(page, url)
    node(page, "Accelerate_1").focus()
    page.keyboard.press("Enter")
    speed = page.get_by_role("region", name="Properties").get_by_label("Target speed", exact=True)
    speed.fill("9")
    with ops_answer(page) as answered:
        speed.press("Enter")
    request = answered.value.request
    answer = answered.value.json()
    # The page names the revision it holds, so the server sends only the edited node.
    assert request.headers["x-sceml-revision"].isdigit()
    assert "nodes" not in answer
    assert [n["name"] for n in answer["patch"]["nodes"]["changed"]] == ["Accelerate_1"]
    expect(node(page, "Accelerate_1")).to_contain_text("targetSpeed: 9 m/s")
    expect(node(page, "Accelerate_2")).to_contain_text("targetSpeed: 4 m/s")
