"""More of the page against a running `sceml edit` (on a copy!): drop a module, move, arrange, export.

python web/mock/smoke2.py http://127.0.0.1:8781/
"""

import json
import sys
import urllib.request

from playwright.sync_api import sync_playwright
from screenshot import ARGS

URL = sys.argv[1]


def view():
    with urllib.request.urlopen(URL + "api/view") as answer:
        return json.load(answer)


with sync_playwright() as p:
    browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=ARGS)
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(URL)
    diagram = page.get_by_role("application", name="Diagram")
    diagram.locator(".react-flow__node").first.wait_for()
    page.wait_for_timeout(500)

    # drag a module from the palette onto the canvas
    item = page.get_by_role("region", name="Palette").get_by_role(
        "button", name="CrossingManeuver", exact=True
    )
    item.drag_to(diagram, target_position={"x": 150, "y": 200})
    dialog = page.get_by_role("dialog", name="Use CrossingManeuver")
    print("dialog:", dialog.count())
    if dialog.count():
        for select in dialog.get_by_role("combobox").all():
            print(" role select:", select.get_attribute("id"))
        dialog.get_by_role("button", name="Add", exact=True).click()
        page.wait_for_timeout(800)
    uses = [n for n in view()["nodes"] if n["kind"] == "ModuleUse" and n["parent"] is None]
    print("module uses:", [(n["name"], n["position"]) for n in uses])
    props = page.get_by_role("region", name="Properties")
    crosser = props.get_by_label("crosser", exact=True)
    if crosser.count():
        crosser.select_option("bike")
        page.wait_for_timeout(500)
        use = next(n for n in view()["nodes"] if n["id"] == uses[0]["id"])
        print("bindings:", use["module"]["bindings"])

    # drag an action node palette item
    page.get_by_role("region", name="Palette").get_by_role(
        "button", name="Stop", exact=True
    ).drag_to(diagram, target_position={"x": 700, "y": 100})
    page.wait_for_timeout(700)
    stop = next((n for n in view()["nodes"] if n["kind"] == "Stop"), None)
    print("stop at:", stop and stop["position"])

    # move a node by dragging it
    node = diagram.locator('.react-flow__node[aria-label="Stop_1"]')
    before = node.bounding_box()
    page.mouse.move(before["x"] + 20, before["y"] + 10)
    page.mouse.down()
    page.mouse.move(before["x"] + 80, before["y"] + 70, steps=8)
    page.mouse.up()
    page.wait_for_timeout(600)
    stop = next(n for n in view()["nodes"] if n["kind"] == "Stop")
    print("stop moved to:", stop["position"], "undo label:", view()["undo"])

    # arrange, then left to right
    page.get_by_role("button", name="Arrange").click()
    page.wait_for_timeout(800)
    print("after arrange undo:", view()["undo"])
    page.get_by_label("Layout direction").select_option(label="Left to right")
    page.wait_for_timeout(1000)
    print(
        "handles:",
        diagram.locator(".react-flow__handle-left").count(),
        diagram.locator(".react-flow__handle-right").count(),
    )
    page.get_by_role("button", name="Fit view").click()
    page.wait_for_timeout(500)
    page.screenshot(path="/tmp/smoke2-lr.png")
    page.get_by_label("Layout direction").select_option(label="Top down")
    page.wait_for_timeout(800)

    # select all, escape
    diagram.click(position={"x": 5, "y": 5})
    page.keyboard.press("Control+a")
    print("selected after ctrl+a:", diagram.locator(".react-flow__node.selected").count())
    page.keyboard.press("Escape")
    print("selected after escape:", diagram.locator(".react-flow__node.selected").count())

    # export dialog
    page.get_by_role("button", name="Export", exact=True).click()
    export = page.get_by_role("dialog", name="Export")
    export.get_by_label("Version").select_option("1.2")
    export.get_by_label("Path").fill("/tmp/ex/out-test.xosc")
    export.get_by_role("button", name="Export", exact=True).click()
    page.wait_for_timeout(2500)
    print("export:", export.inner_text().replace("\n", " | ")[:600])
    page.screenshot(path="/tmp/smoke2-export.png")
    export.get_by_role("button", name="Cancel").click()

    # extract module dialog exists
    page.get_by_role("button", name="Open", exact=True).click()
    print(
        "open dialog:", page.get_by_role("dialog", name="Open").get_by_label("Path").input_value()
    )
    page.keyboard.press("Escape")
    print("page errors:", errors)
    browser.close()
