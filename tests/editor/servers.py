"""A real `sceml edit` process for tests that signal or kill it, and the requests they send."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

SCEML = Path(sys.executable).parent / "sceml"
URL = re.compile(r"http://127\.0\.0\.1:\d+/")


class Server:
    """A real `sceml edit FILE --no-browser` process and its URL."""

    def __init__(self, path: Path, log: Path) -> None:
        self.log = log
        with log.open("wb") as out:
            self.process = subprocess.Popen(
                [str(SCEML), "edit", str(path), "--no-browser"], stdout=out, stderr=out
            )
        deadline = time.monotonic() + 20
        while not URL.search(self.output()):
            assert self.process.poll() is None, self.output()
            assert time.monotonic() < deadline, "the server did not start"
            time.sleep(0.05)
        self.url = URL.findall(self.output())[0]
        # The URL is printed once the port is bound, a moment before uvicorn listens on it.
        while True:
            try:
                self.view()
                break
            except OSError:
                assert time.monotonic() < deadline, "the server did not answer"
                time.sleep(0.05)

    def output(self) -> str:
        return self.log.read_text(errors="replace")

    def post(self, route: str, body: dict[str, object]) -> dict[str, object]:
        request = urllib.request.Request(
            self.url + route.lstrip("/"),
            data=json.dumps(body).encode(),
            headers={"Content-Type": "application/json"},
        )
        with urllib.request.urlopen(request, timeout=20) as answer:
            return json.loads(answer.read())  # type: ignore[no-any-return]

    def view(self) -> dict[str, object]:
        with urllib.request.urlopen(self.url + "api/view", timeout=20) as answer:
            return json.loads(answer.read())  # type: ignore[no-any-return]

    def stop(self, sig: int) -> int:
        self.process.send_signal(sig)
        return self.process.wait(timeout=20)


def kill_all(servers: list[Server]) -> None:
    """End every server a test started and left running."""
    for server in servers:
        if server.process.poll() is None:
            server.process.kill()
            server.process.wait(timeout=10)


def start(servers: list[Server], path: Path) -> Server:
    server = Server(path, path.with_name(f"server-{len(servers)}.log"))
    servers.append(server)
    return server
