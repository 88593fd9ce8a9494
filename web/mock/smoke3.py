"""Extract a module and open its definition, against a running `sceml edit` on a copy of UIS1.

python web/mock/smoke3.py http://127.0.0.1:8781/
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
    diagram.locator('.react-flow__node[aria-label="Accelerate_2"]').click()
    diagram.locator('.react-flow__node[aria-label="Cross_1"]').click(modifiers=["Shift"])
    print("selected:", diagram.locator(".react-flow__node.selected").count())
    page.get_by_role("button", name="Extract module").click()
    dialog = page.get_by_role("dialog", name="Extract module")
    dialog.get_by_label("Module name").fill("BikeCross")
    dialog.get_by_label("Library").fill("library/test-lib.xmi")
    dialog.get_by_role("button", name="Extract module").click()
    page.wait_for_timeout(1500)
    v = view()
    print(
        "uses:",
        [
            (n["name"], n["title"])
            for n in v["nodes"]
            if n["kind"] == "ModuleUse" and n["parent"] is None
        ],
    )
    alert = page.get_by_role("alert")
    print("alert:", alert.inner_text() if alert.count() else None)
    use = diagram.locator(".react-flow__node.selected")
    print("selected after extract:", use.count() and use.first.get_attribute("aria-label"))
    # typing Backspace in a field must not delete the node
    props = page.get_by_role("region", name="Properties")
    name = props.get_by_label("Name", exact=True)
    if name.count():
        name.click()
        name.press("Backspace")
        page.wait_for_timeout(300)
        print("nodes after Backspace in a field:", len(view()["nodes"]) == len(v["nodes"]))
        name.press("Escape")
    page.on("dialog", lambda d: d.accept())
    button = props.get_by_role("button", name="Open definition")
    if button.count():
        page.keyboard.press("Escape")
        button.click()
        page.wait_for_timeout(1200)
        print("document:", view()["document"], "| title:", page.title())
        alert = page.get_by_role("alert")
        print("alert:", alert.inner_text() if alert.count() else None)
        page.screenshot(path="/tmp/smoke3.png")
    print("page errors:", errors)
    browser.close()
