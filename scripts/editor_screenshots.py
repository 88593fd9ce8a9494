"""Take the editor screenshots in docs/editor/ (README and docs/editor.md show them).

    .venv/bin/python scripts/editor_screenshots.py [--out docs/editor]

Starts `sceml edit` on copies of the examples (so nothing in examples/ is touched), opens each
in headless Chromium (Debian's /usr/bin/chromium through Playwright) and saves the page. Look
at the pictures before committing them.
"""

from __future__ import annotations

import argparse
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import Page, sync_playwright

REPO = Path(__file__).resolve().parents[1]
SCEML = Path(sys.executable).with_name("sceml")


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def serve(file: Path) -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    server = subprocess.Popen(
        [str(SCEML), "edit", str(file), "--no-browser", "--port", str(port)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    url = f"http://127.0.0.1:{port}/"
    for _ in range(100):
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            return server, url
        except OSError:
            time.sleep(0.1)
    server.kill()
    raise SystemExit(f"sceml edit did not start on {file}")


def shoot(page: Page, url: str, target: Path, expand: str | None = None) -> None:
    page.goto(url)
    page.wait_for_selector(".react-flow__node", timeout=30_000)
    if expand is not None:
        page.locator(".react-flow__node", has_text=expand).get_by_role(
            "button", name="Expand"
        ).click()
        page.wait_for_timeout(3000)  # the layout and the page's own fit settle
    page.wait_for_timeout(2000)
    page.screenshot(path=str(target))
    print(target)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=REPO / "docs" / "editor")
    out = parser.parse_args().out
    with tempfile.TemporaryDirectory() as scratch:
        copy = Path(scratch)
        shutil.copytree(REPO / "examples", copy / "examples")
        shutil.copytree(REPO / "maps", copy / "maps")
        (copy / ".sceml-root").touch()
        shots = [
            ("uis1-concrete.xmi", out / "uis1.png", None),
            ("uis2-concrete.xmi", out / "uis2-collapsed.png", None),
            ("uis2-concrete.xmi", out / "uis2-expanded.png", "CrossingManeuver"),
        ]
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path="/usr/bin/chromium",
                args=["--no-sandbox", "--disable-gpu", "--disable-background-networking"],
            )
            for name, target, expand in shots:
                server, url = serve(copy / "examples" / name)
                try:
                    page = browser.new_page(viewport={"width": 1400, "height": 860})
                    shoot(page, url, target, expand)
                    page.close()
                finally:
                    server.terminate()
                    server.wait(timeout=10)
            browser.close()


if __name__ == "__main__":
    main()
