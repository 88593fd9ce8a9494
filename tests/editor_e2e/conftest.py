"""Fixtures of the editor's browser tests: the real `sceml edit` server and Debian's Chromium."""

from __future__ import annotations

import re
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from browser import CHROMIUM, CHROMIUM_ARGS
from editor.servers import Server, kill_all

SCEML = Path(sys.executable).parent / "sceml"
URL = re.compile(r"http://127\.0\.0\.1:\d+/")


def _stop(process: subprocess.Popen[bytes]) -> None:
    if process.poll() is None:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(timeout=10)


@pytest.fixture
def editor(tmp_path: Path) -> Iterator[Callable[..., str]]:
    """Start `sceml edit PATH --no-browser [extra]`; answer its URL once /api/view answers."""
    started: list[subprocess.Popen[bytes]] = []

    def start(path: Path, *extra: str) -> str:
        # The server picks its own free port and prints the URL once it is bound: a port chosen
        # here could be taken meanwhile, or answered by another run's server.
        log_path = tmp_path / f"server-{len(started)}.log"
        with log_path.open("wb") as log:
            process = subprocess.Popen(
                [str(SCEML), "edit", str(path), "--no-browser", *extra],
                stdout=log,
                stderr=subprocess.STDOUT,
            )
        started.append(process)
        deadline = time.monotonic() + 20
        while True:
            announced = URL.search(log_path.read_text(errors="replace"))
            if announced:
                try:
                    with urllib.request.urlopen(announced[0] + "api/view", timeout=2) as answer:
                        if answer.status == 200:
                            return announced[0]
                except (urllib.error.URLError, ConnectionError, TimeoutError):
                    pass
            if process.poll() is not None or time.monotonic() > deadline:
                _stop(process)
                output = log_path.read_text(errors="replace")
                pytest.fail(f"sceml edit did not start:\n{output}")
            time.sleep(0.1)

    yield start
    for process in started:
        _stop(process)


@pytest.fixture(scope="module")
def browser() -> Iterator[object]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(
            executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True
        )
        yield chromium
        chromium.close()


@pytest.fixture
def page(browser: object) -> Iterator[object]:
    context = browser.new_context(viewport={"width": 1920, "height": 1200})
    page = context.new_page()
    page.set_default_timeout(10_000)
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    # The page must work under its own Content-Security-Policy (a refusal is logged, not thrown);
    # a refused frame is what test_a_framed_page_cannot_act wants.
    page.on(
        "console",
        lambda message: (
            "Content Security Policy" in message.text
            and not message.text.startswith("Framing ")
            and errors.append(message.text)
        ),
    )
    yield page
    context.close()
    assert errors == [], f"errors in the page: {errors}"


@pytest.fixture
def servers() -> Iterator[list[Server]]:
    """Real `sceml edit` processes a test starts with `start(servers, path)`; killed after it."""
    started: list[Server] = []
    yield started
    kill_all(started)
