"""One editor op over HTTP on a kept-alive connection, beside the server's own work (issue 31).

    python benchmarks/editor_http.py [--runs 40] [--model examples/uis1-concrete.xmi]

Starts the real server (`sceml edit COPY --no-browser`, a copy of the model in a temporary
folder, so nothing of yours changes), then, on one kept-alive `http.client` connection as a
page holds one, posts the same kind of op again and again: a move of the first node one pixel
to and fro (`POST /api/ops`, with a tab and the revision the last answer gave, so the server
answers with a patch as it does to the page). The anchor, measured in turns with it, is the
server's own work for the same op on a second session of the same file, in this process: the
op applied (with its validation and view) and the view encoded as JSON, without the network.
The difference between the two is what the transport, Starlette, the thread pool and the view
patch cost (the issue found 44 ms of 48 ms there: Nagle against the client's delayed ACK, before
the server's sockets got TCP_NODELAY).
Prints the medians and the difference; the goal is under 10 ms over HTTP.
"""

from __future__ import annotations

import argparse
import http.client
import json
import re
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from sceml.editor import EditorSession, SessionOptions

ROOT = Path(__file__).resolve().parent.parent
TAB = "bench"


def start_server(model: Path) -> tuple[subprocess.Popen[str], str, int]:
    """`sceml edit` on `model`; its process, host and port once it prints its URL."""
    sceml = Path(sys.executable).with_name("sceml")
    process = subprocess.Popen(
        [str(sceml), "edit", str(model), "--no-browser"],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    assert process.stdout is not None
    deadline = time.monotonic() + 60
    for line in process.stdout:
        found = re.search(r"http://(127\.0\.0\.1):(\d+)", line)
        if found:
            host, port = found.group(1), int(found.group(2))
            _wait_until_listening(host, port, deadline)
            return process, host, port
        if time.monotonic() > deadline:
            break
    process.kill()
    raise SystemExit("the editor server did not print its URL")


def _wait_until_listening(host: str, port: int, deadline: float) -> None:
    """The URL is printed before the socket accepts: try until it does."""
    while True:
        try:
            socket.create_connection((host, port), timeout=1).close()
            return
        except OSError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


def move(view: dict[str, Any], dx: int) -> dict[str, Any]:
    """A move op of the view's first node to x = 100 + `dx` (the runs alternate 1 and -1, so
    every op changes the place; a node without a saved place has none in the view)."""
    node = view["nodes"][0]
    return {"ops": [{"op": "move", "positions": {node["id"]: {"x": 100 + dx, "y": 100}}}]}


class OverHttp:
    """The page's side: one kept-alive connection, the revision it holds."""

    def __init__(self, host: str, port: int) -> None:
        self.connection = http.client.HTTPConnection(host, port)
        self.origin = f"http://{host}:{port}"
        self.view = self.request("GET", "/api/view", None)
        self.revision = self.view["revision"]

    def request(self, method: str, path: str, body: dict[str, Any] | None) -> dict[str, Any]:
        headers = {"X-SceML-Tab": TAB, "Origin": self.origin}
        data = None
        if body is not None:
            data = json.dumps(body).encode()
            headers["Content-Type"] = "application/json"
        if getattr(self, "revision", None) is not None:
            headers["X-SceML-Revision"] = str(self.revision)
        self.connection.request(method, path, body=data, headers=headers)
        response = self.connection.getresponse()
        answer: dict[str, Any] = json.loads(response.read())
        if response.status != 200:
            raise SystemExit(f"{method} {path}: {response.status} {answer}")
        return answer

    def op(self, dx: int) -> float:
        started = time.perf_counter()
        answer = self.request("POST", "/api/ops", move(self.view, dx))
        elapsed = time.perf_counter() - started
        self.revision = answer["revision"]
        if "patch" not in answer:
            self.view = answer
        return elapsed


class InProcess:
    """The server's own work for the same op: the session applies it and the answer is encoded
    (the whole view: the page's patch is made from it, so this is the upper bound)."""

    def __init__(self, model: Path) -> None:
        self.session = EditorSession(SessionOptions())
        self.session.open(model)
        self.view = self.session.view(tab=TAB)

    def op(self, dx: int) -> float:
        started = time.perf_counter()
        answer = self.session.apply(move(self.view, dx)["ops"], None, TAB)
        json.dumps(answer)
        return time.perf_counter() - started


def measure(model: Path, runs: int) -> tuple[list[float], list[float]]:
    """Seconds of each op over HTTP and of the same op in-process, `runs` of each in turns, on
    copies of `model` (and the maps folder beside its folder) in a temporary folder."""
    with tempfile.TemporaryDirectory() as folder:
        # The model's map is named relative to it: copy the examples' folder layout.
        source = model.resolve()
        work = Path(folder) / "examples"
        shutil.copytree(source.parent, work)
        if (source.parent.parent / "maps").is_dir():
            shutil.copytree(source.parent.parent / "maps", Path(folder) / "maps")
        over_http_model = work / source.name
        in_process_model = work / f"in-process-{source.name}"
        shutil.copy(over_http_model, in_process_model)
        server, host, port = start_server(over_http_model)
        try:
            page = OverHttp(host, port)
            local = InProcess(in_process_model)
            for warm in (1, -1):  # the first requests pay for imports and caches
                page.op(warm)
                local.op(warm)
            http_times, local_times = [], []
            for run in range(runs):
                dx = 1 if run % 2 == 0 else -1
                http_times.append(page.op(dx))
                local_times.append(local.op(dx))
        finally:
            server.terminate()
            server.wait(timeout=30)
    return http_times, local_times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=40)
    parser.add_argument("--model", type=Path, default=ROOT / "examples" / "uis1-concrete.xmi")
    args = parser.parse_args()
    http_times, local_times = measure(args.model, args.runs)
    over_http = statistics.median(http_times) * 1000
    in_process = statistics.median(local_times) * 1000
    print(f"{args.model.name}: a move op, {args.runs} runs in turns, medians")
    print(f"  over HTTP, kept-alive connection: {over_http:.1f} ms (goal < 10 ms)")
    print(f"  the server's own work in-process, the anchor: {in_process:.1f} ms")
    print(
        f"  difference (HTTP, Starlette, the thread pool, the patch): {over_http - in_process:.1f} ms"
    )


if __name__ == "__main__":
    main()
