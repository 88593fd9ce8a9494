"""Drive the page against a running `sceml edit` (on a copy!) the way a person would; print what happened.

python web/mock/smoke.py http://127.0.0.1:8781/
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


def node_named(name):
    return next(n for n in view()["nodes"] if n["name"] == name)


with sync_playwright() as p:
    browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=ARGS)
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(URL)
    diagram = page.get_by_role("application", name="Diagram")
    diagram.locator(".react-flow__node").first.wait_for()
    page.wait_for_timeout(500)
    status = page.get_by_role("toolbar", name="Editor").get_by_role("status")
    print("status:", status.inner_text())

    # add from the palette (click = middle of the view)
    page.get_by_role("region", name="Palette").get_by_role(
        "button", name="Decelerate", exact=True
    ).click()
    page.wait_for_timeout(800)
    v = view()
    added = [n for n in v["nodes"] if n["kind"] == "Decelerate"]
    print(
        "added:",
        [n["name"] for n in added],
        "all positioned:",
        all(n["position"] for n in v["nodes"] if n["parent"] is None),
    )
    print("title:", page.title(), "| status:", status.inner_text())
    props = page.get_by_role("region", name="Properties")
    print("properties name:", props.get_by_label("Name", exact=True).input_value())

    # set a parameter
    speed = props.get_by_label("Target speed", exact=True)
    speed.fill("12.5")
    speed.press("Enter")
    page.wait_for_timeout(500)
    print(
        "targetSpeed:",
        [f["value"] for f in node_named("Decelerate_1")["fields"] if f["name"] == "targetSpeed"],
    )
    props.get_by_label("Reference actor", exact=True).select_option("bike")
    page.wait_for_timeout(500)
    print("lines:", node_named("Decelerate_1")["lines"])

    # connect: Accelerate_1 out -> Decelerate_1 in
    src = diagram.locator('.react-flow__node[aria-label="Cross_1"] .react-flow__handle.source')
    dst = diagram.locator('.react-flow__node[aria-label="Decelerate_1"] .react-flow__handle.target')
    src.drag_to(dst)
    page.wait_for_timeout(600)
    ids = {n["name"]: n["id"] for n in view()["nodes"]}
    print(
        "connected:",
        any(
            e["source"] == ids["Cross_1"] and e["target"] == ids["Decelerate_1"]
            for e in view()["edges"]
        ),
    )

    # undo, redo
    page.get_by_role("button", name="Undo").click()
    page.wait_for_timeout(400)
    print(
        "after undo edges from Cross_1:",
        [e["target"] for e in view()["edges"] if e["source"] == ids["Cross_1"]],
    )
    page.keyboard.press("Control+Shift+Z")
    page.wait_for_timeout(400)
    print("after redo:", [e["target"] for e in view()["edges"] if e["source"] == ids["Cross_1"]])

    # a refused op shows the server's message
    src = diagram.locator('.react-flow__node[aria-label="Decelerate_1"] .react-flow__handle.source')
    dst = diagram.locator('.react-flow__node[aria-label="Root"] .react-flow__handle.target')
    src.drag_to(dst)
    page.wait_for_timeout(500)
    alert = page.get_by_role("alert")
    print("alert:", alert.inner_text() if alert.count() else None)

    # root: actors
    diagram.locator('.react-flow__node[aria-label="Root"]').click()
    page.wait_for_timeout(300)
    props.get_by_role("button", name="Add actor").click()
    page.wait_for_timeout(500)
    print("actors:", [a["name"] for a in view()["actors"]])
    group = props.get_by_role("group", name="Actor car_1")
    print("actor group visible:", group.count())
    group.get_by_label("Initial speed", exact=True).fill("3")
    group.get_by_label("Initial speed", exact=True).press("Tab")
    page.wait_for_timeout(500)
    a = next(a for a in view()["actors"] if a["name"] == "car_1")
    print("initialSpeed:", [f["value"] for f in a["fields"] if f["name"] == "initialSpeed"])

    # delete by keyboard
    diagram.locator('.react-flow__node[aria-label="Decelerate_1"]').click()
    page.keyboard.press("Delete")
    page.wait_for_timeout(500)
    print("deleted:", not any(n["name"] == "Decelerate_1" for n in view()["nodes"]))

    # copy/paste
    diagram.locator('.react-flow__node[aria-label="TurnRight_1"]').click()
    page.keyboard.press("Control+c")
    page.wait_for_timeout(300)
    page.keyboard.press("Control+v")
    page.wait_for_timeout(600)
    print("pasted:", [n["name"] for n in view()["nodes"] if n["kind"] == "TurnRight"])

    # problems list
    problems = page.get_by_role("region", name="Problems").get_by_role("button")
    print("problems:", problems.count(), problems.first.inner_text() if problems.count() else "")
    if problems.count():
        problems.first.click()
        page.wait_for_timeout(400)
        print(
            "selected after problem click:",
            diagram.locator(".react-flow__node.selected").get_attribute("aria-label"),
        )
    badges = diagram.get_by_role("img", name="problems")
    print(
        "badges:",
        badges.count(),
        "data-severity nodes:",
        diagram.locator(".react-flow__node[data-severity]").count(),
    )

    # save
    page.keyboard.press("Control+s")
    page.wait_for_timeout(800)
    print("after save:", status.inner_text(), "| title:", page.title(), "| dirty:", view()["dirty"])
    page.screenshot(path="/tmp/smoke.png")
    print("page errors:", errors)
    browser.close()
