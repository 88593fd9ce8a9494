"""The HTML report: diagnostics mapped to diagram ids, tables, and a click test in real Chromium."""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

import pytest
from browser import CHROMIUM, CHROMIUM_ARGS

import scemlmodel as scm
from sceml.diagnostics import Diagnostic, Severity
from sceml.model.build import ScenarioBuilder
from sceml.model.documents import Document
from sceml.model.loading import load
from sceml.model.locating import uri_fragment
from sceml.model.params import span
from sceml.model.saving import save
from sceml.review.figure import Figure
from sceml.review.page import TEMPLATE, build_report

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def broken_document(tmp_path: Path) -> Document:
    """A scenario with a join that has only one input (paper rule 3), saved and loaded back."""
    b = ScenarioBuilder("Broken", map="Town03", level="logical")
    ego = b.actor("Car", "ego", ego=True)
    go = b.add("Accelerate", ego, targetSpeed=span(5, 10))
    b.chain(b.root, go)
    join = b.join_all(go)
    b.chain(join, b.end)
    path = save(b.scenario, tmp_path / "broken.xmi")
    return load(path)


def diagnostics_for(document: Document) -> list[Diagnostic]:
    join = next(n for n in document.root.nodes if isinstance(n, scm.JoinAllFinished))
    ego = document.root.nodes[0].actors[0]
    return [
        Diagnostic(
            Severity.ERROR,
            "SCEML-S004",
            "join has one input",
            fragment=uri_fragment(join),
            file=str(document.path),
            line=document.line_of(join),
        ),
        Diagnostic(Severity.WARNING, "SCEML-X001", "about the ego", element=ego),
        Diagnostic(Severity.INFO, "SCEML-X002", "about the model as a whole"),
    ]


def test_diagnostics_link_to_the_nodes_they_are_about(tmp_path: Path) -> None:
    document = broken_document(tmp_path)
    html = build_report(document, diagnostics_for(document))
    links = re.findall(r'<a data-targets="([^"]*)" href="#diagram">([^<]*)</a>', html)
    assert ("nodes.3", "join has one input") in links
    assert ("nodes.0", "about the ego") in links  # actors live in the root box
    assert "about the model as a whole <i>(not in the diagram)</i>" in html
    assert re.search(r'<g id="nodes.3" class="[^"]*sceml-has-error', html)
    assert "1 error, 1 warning, 1 info" in html


def test_tables_list_actors_and_parameters(tmp_path: Path) -> None:
    document = broken_document(tmp_path)
    html = build_report(document, [])
    assert "No problems found." in html
    assert "<td>ego</td><td>Car</td><td>yes</td>" in html
    assert "[5, 10] m/s = 18–36 km/h" in html  # a logical range, with km/h
    assert '<td class="status-default">default</td>' in html  # rate falls back to its default
    assert "Validation was not run" in build_report(document, None)


def test_the_page_comes_from_a_template_file_of_the_shared_environment() -> None:
    from importlib import resources

    from sceml.templating import environment

    assert (resources.files("sceml.templates") / TEMPLATE).is_file()
    assert TEMPLATE in environment().list_templates()


def test_extra_figures_follow_the_diagram_under_their_titles(tmp_path: Path) -> None:
    document = broken_document(tmp_path)
    figure = Figure("Map view", "map-view", '<svg xmlns="http://www.w3.org/2000/svg"><g/></svg>')
    html = build_report(document, [], figures=[figure])
    box = '<h2>Map view</h2>\n<div class="figure" id="map-view">\n<svg'
    assert box in html
    assert html.index('<div id="diagram">') < html.index(box) < html.index("<h2>Actors</h2>")
    assert 'class="figure"' not in build_report(document, [])


def test_module_internals_map_through_expanded_uses() -> None:
    document = load(EXAMPLES / "uis2-logical.xmi")
    use = next(n for n in document.root.nodes if isinstance(n, scm.ModuleUse))
    inner = use.definition.nodes[3]
    library = str(EXAMPLES / "library" / "sceml-library.xmi")
    diagnostic = Diagnostic(
        Severity.ERROR, "SCEML-M9", "inside", fragment=uri_fragment(inner), file=library
    )
    html = build_report(document, [diagnostic])
    use_id = f"nodes.{list(document.root.nodes).index(use)}"
    assert f'data-targets="{use_id}/modules.0/nodes.3"' in html
    collapsed = build_report(document, [diagnostic], modules="collapsed")
    assert f'data-targets="{use_id}"' in collapsed


# CI installs Chromium (scripts/setup.sh), so there a missing browser is a failure, not a skip.
@pytest.mark.skipif(
    not CHROMIUM.exists() and not os.environ.get("CI"),
    reason="Debian's chromium (/usr/bin/chromium) is not installed",
)
def test_clicking_a_diagnostic_highlights_its_node_in_chromium(tmp_path: Path) -> None:
    sync_api = pytest.importorskip("playwright.sync_api")
    document = broken_document(tmp_path)
    page_file = tmp_path / "report.html"
    page_file.write_text(build_report(document, diagnostics_for(document)), encoding="utf-8")
    profile = tmp_path / "profile"
    with sync_api.sync_playwright() as playwright:
        context = playwright.chromium.launch_persistent_context(
            str(profile), executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True
        )
        try:
            page = context.new_page()
            page.goto(page_file.as_uri())
            join = page.locator("[id='nodes.3']")
            assert page.locator("#diagram svg").is_visible() and join.is_visible()
            assert "sceml-highlight" not in join.get_attribute("class")
            page.click("text=join has one input")
            assert "sceml-highlight" in join.get_attribute("class")
            stroke = join.locator("ellipse").first.evaluate("e => getComputedStyle(e).stroke")
            assert stroke == "rgb(213, 0, 249)"
            page.click("text=about the ego")
            assert "sceml-highlight" not in join.get_attribute("class")
            assert "sceml-highlight" in page.locator("[id='nodes.0']").get_attribute("class")
            page.screenshot(path=str(tmp_path / "report.png"), full_page=True)
        finally:
            context.close()
    assert (tmp_path / "report.png").stat().st_size > 10_000
    shutil.rmtree(profile, ignore_errors=True)


def test_a_follows_unset_limits_read_unset_in_the_report(tmp_path: Path) -> None:
    # Optional parameters with no default (release 1.5's Follow limits) have no number to show.
    b = ScenarioBuilder("Gap", map="Town03", level="concrete")
    ego = b.actor("Car", "ego", ego=True, speed=10.0)
    lead = b.actor("Car", "lead", speed=8.0)
    b.chain(b.root, b.add("Follow", ego, target=lead, distance=12.0, maxSpeed=30.0), b.end)
    html = build_report(load(save(b.scenario, tmp_path / "gap.xmi")), [])
    assert html.count(">unset<") >= 5  # maxAcceleration, maxDeceleration, the jerks, timeGap
    assert ">30 m/s" in html
