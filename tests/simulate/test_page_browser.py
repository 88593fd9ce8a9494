"""The preview page in headless Chromium: the time slider moves the actors and the timeline."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from browser import CHROMIUM, CHROMIUM_ARGS
from conftest import EXAMPLES

from sceml.model.loading import load_scenario
from sceml.simulate import simulate
from sceml.simulate.page import preview_page


# CI installs Chromium (scripts/setup.sh), so there a missing browser is a failure, not a skip.
@pytest.mark.skipif(
    not CHROMIUM.exists() and not os.environ.get("CI"),
    reason="Debian's chromium (/usr/bin/chromium) is not installed",
)
def test_the_slider_moves_the_actors_and_marks_the_running_nodes(tmp_path: Path) -> None:
    sync_api = pytest.importorskip("playwright.sync_api")
    source = EXAMPLES / "uis1-concrete.xmi"
    scenario = load_scenario(source).root
    run = simulate(scenario, source)
    page_file = tmp_path / "uis1.html"
    page_file.write_text(preview_page(run, scenario, source), encoding="utf-8")
    profile = tmp_path / "profile"
    with sync_api.sync_playwright() as playwright:
        context = playwright.chromium.launch_persistent_context(
            str(profile), executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True
        )
        try:
            page = context.new_page()
            page.goto(page_file.as_uri())
            ego = page.locator("#actor-ego")
            # At the start the ego stands at (1.75, -39) facing north (90 degrees).
            assert ego.get_attribute("transform") == "translate(1.75 -39) rotate(90)"
            slider = page.get_by_role("slider", name="Time")
            k = int(round(5.0 / run.step))  # 5 s: the ego is turning, the bike crossing
            slider.fill(str(k))
            x, y = run.states[0, k, :2]
            moved = ego.get_attribute("transform") or ""
            assert moved.startswith(f"translate({round(x, 3):g} {round(y, 3):g})")
            assert page.locator("#clock").inner_text() == "5.00 s"
            running = page.locator(".timeline-row.running")
            names = {running.nth(i).get_attribute("data-node") for i in range(running.count())}
            assert names == {"TurnRight_1", "Cross_1"}
            page.get_by_role("button", name="Play").click()
            page.wait_for_function("document.getElementById('clock').textContent !== '5.00 s'")
            assert page.get_by_role("button", name="Pause").is_visible()
        finally:
            context.close()
    shutil.rmtree(profile, ignore_errors=True)
