"""A 500-node scenario in the browser: it fits, zoomed out its boxes are drawn light (no text)
with every edge, and zoomed in the edges end on the handles the page draws."""

from __future__ import annotations

import json
import math
import sys
import urllib.request
from pathlib import Path

from editor_e2e.test_editor import node
from playwright.sync_api import Page, expect

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "benchmarks"))
from scale_scenarios import write  # noqa: E402

SCALE = (
    "Number(/scale\\(([0-9.]+)\\)/.exec("
    "document.querySelector('.react-flow__viewport').style.transform)[1])"
)

#: Every drawn node's box against the canvas's: the names of those outside it.
OUTSIDE = """() => {
  const pane = document.querySelector('.react-flow').getBoundingClientRect();
  return [...document.querySelectorAll('.react-flow__node')].filter((node) => {
    const r = node.getBoundingClientRect();
    return r.left < pane.left - 1 || r.right > pane.right + 1
      || r.top < pane.top - 1 || r.bottom > pane.bottom + 1;
  }).map((node) => node.getAttribute('aria-label'));
}"""

#: For each drawn edge whose target box is drawn: how far (screen px) its end lies from the top
#: centre of the target's in-handle (the layout runs top down).
EDGE_ENDS = """() => {
  const misses = [];
  for (const edge of document.querySelectorAll('.react-flow__edge')) {
    const [, target] = /to (\\S+)$/.exec(edge.getAttribute('aria-label')) ?? [];
    const handle = document.querySelector(
      `.react-flow__node[data-id="${target}"] .react-flow__handle.target`);
    if (!handle) continue;
    const path = edge.querySelector('.react-flow__edge-path');
    const end = path.getPointAtLength(path.getTotalLength()).matrixTransform(path.getScreenCTM());
    // How far the end lies from the middle of the handle's top edge, where React Flow ends an
    // edge into a top handle: 3 px in every run (the handle's border), 4 where rounding at a
    // zoom near 1 moves it by a pixel; a node drawn without handles ends its edges far off.
    const r = handle.getBoundingClientRect();
    misses.push(Math.hypot(end.x - (r.left + r.width / 2), end.y - r.top));
  }
  return misses;
}"""


def test_a_large_scenario_fits_light_when_far_and_its_edges_meet_the_handles(
    page: Page, editor: object, tmp_path: Path
) -> None:
    url = editor(write(500, tmp_path / "big"))  # type: ignore[operator]
    view = json.loads(urllib.request.urlopen(url + "api/view", timeout=30).read())
    top = [n for n in view["nodes"] if n["parent"] is None]
    page.goto(url)
    # Fitted: every top-level node is drawn, inside the canvas (React Flow fits the nodes it
    # knows the size of; the page tells it every node's size, drawn or not).
    page.wait_for_function(
        f"() => document.querySelectorAll('.react-flow__node').length >= {len(top)}",
        timeout=60_000,
    )
    page.wait_for_timeout(500)  # the fit once React Flow knows the pane's size
    assert page.evaluate(OUTSIDE) == []
    far = float(page.evaluate(SCALE))
    assert far < 0.3, far
    # Light boxes: no text, and every flow between top-level nodes drawn (a node drawn without
    # its handles in the page, tried once, lost its edges: React Flow measures them).
    assert page.locator(".react-flow__node .node-title").count() == 0
    ids = {n["id"] for n in top}
    flows = [e for e in view["edges"] if e["source"] in ids and e["target"] in ids]
    assert page.locator(".react-flow__edge").count() == len(flows) > 500
    paths = page.locator(".react-flow__edge-path").evaluate_all(
        "ps => ps.map(p => p.getAttribute('d'))"
    )
    assert all(path and "NaN" not in path for path in paths)

    # Zoomed in over a box: text and handles again, and the edges end on the handles drawn.
    target = next(n["name"] for n in top if n["kind"] == "Accelerate")
    box = node(page, target).bounding_box()
    assert box is not None
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, -math.log2(1 / far) / 0.002)  # d3-zoom: 2 ** (-deltaY * 0.002)
    page.wait_for_function(f"() => {SCALE} > 0.9")
    expect(node(page, target).locator(".node-title")).to_have_text("Accelerate")
    expect(node(page, target).locator(".react-flow__handle")).to_have_count(2)
    misses = page.evaluate(EDGE_ENDS)
    assert len(misses) >= 3, misses
    assert max(misses) < 5, misses  # every end on its handle (a pixel of rounding allowed)
