"""Regenerate the pictures in docs/diagrams/ from the reference examples.

    .venv/bin/python docs/diagrams/build_diagrams.py [--no-screenshot] [--only-maps]

Writes SVG and PNG of UIS1 and UIS2 (flow and behavior-tree views), the CrossingManeuver library
module on its own, the legend, the map views of UIS1 and UIS2 (concrete, and UIS2 logical as
PNG), and the HTML review report of UIS2 with a screenshot of it taken
in headless Chromium (/usr/bin/chromium through Playwright), skipped when that is not installed.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import graphviz

from sceml.files.writing import write_atomically
from sceml.model.loading import load
from sceml.render import diagram, legend_graph, to_bytes
from sceml.render.mapview import map_view
from sceml.review.figures import report_figures
from sceml.review.page import build_report
from sceml.validation import validate

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "examples"
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def write_both(graph: graphviz.Digraph, stem: str) -> list[Path]:
    """Write `stem.svg` and `stem.png` beside this script."""
    written = []
    for fmt in ("svg", "png"):
        path = HERE / f"{stem}.{fmt}"
        write_atomically(path, to_bytes(graph, fmt))
        written.append(path)
    return written


def build_pictures() -> list[Path]:
    """Every diagram of the documentation."""
    uis1 = load(EXAMPLES / "uis1-logical.xmi").root
    uis2 = load(EXAMPLES / "uis2-logical.xmi").root
    library = load(EXAMPLES / "library" / "sceml-library.xmi").root
    written = write_both(diagram(uis1), "uis1-flow")
    written += write_both(diagram(uis1, view="bt"), "uis1-bt")
    written += write_both(diagram(uis2), "uis2-flow")
    written += write_both(diagram(uis2, modules="expanded"), "uis2-flow-expanded")
    written += write_both(diagram(uis2, view="bt", modules="expanded"), "uis2-bt")
    written += write_both(diagram(library, module="CrossingManeuver"), "crossing-maneuver")
    legend = HERE / "legend.png"
    write_atomically(legend, to_bytes(legend_graph(), "png"))
    return [*written, legend]


def build_map_views() -> list[Path]:
    """The map views (`sceml render FILE --view map`) of UIS1 and UIS2."""
    written = []
    for example, stem, formats in (
        ("uis1-concrete.xmi", "uis1-map", ("svg", "png")),
        ("uis2-concrete.xmi", "uis2-map", ("svg", "png")),
        ("uis2-logical.xmi", "uis2-logical-map", ("png",)),
    ):
        document = load(EXAMPLES / example)
        for fmt in formats:
            path = HERE / f"{stem}.{fmt}"
            write_atomically(path, map_view(document.root, document.path, fmt).data)
            written.append(path)
    return written


def build_report_page() -> Path:
    """The UIS2 review report, validated, with its map view."""
    document = load(EXAMPLES / "uis2-logical.xmi")
    page = HERE / "uis2-report.html"
    diagnostics = validate(document.root, document=document)
    html = build_report(document, diagnostics, figures=report_figures(document))
    write_atomically(page, html.encode("utf-8"))
    return page


def screenshot(page: Path, target: Path) -> Path:
    """A full-page screenshot of the report with its first linked element highlighted."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright, tempfile.TemporaryDirectory() as profile:
        context = playwright.chromium.launch_persistent_context(
            profile,
            executable_path=str(CHROMIUM),
            args=CHROMIUM_ARGS,
            headless=True,
            viewport={"width": 1400, "height": 1000},
        )
        try:
            browser_page = context.new_page()
            browser_page.goto(page.as_uri())
            links = browser_page.locator("a[data-targets]")
            if links.count():
                links.first.click()
            browser_page.screenshot(path=str(target), full_page=True)
        finally:
            context.close()
    return target


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-screenshot", action="store_true", help="skip the browser step")
    parser.add_argument("--only-maps", action="store_true", help="draw the map views only")
    arguments = parser.parse_args(argv)
    if arguments.only_maps:
        for path in build_map_views():
            print(path.relative_to(HERE.parent.parent))
        return
    written = [*build_pictures(), *build_map_views(), build_report_page()]
    if not arguments.no_screenshot and CHROMIUM.exists():
        written.append(screenshot(written[-1], HERE / "uis2-report.png"))
    for path in written:
        print(path.relative_to(HERE.parent.parent))


if __name__ == "__main__":
    main()
