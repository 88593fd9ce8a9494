"""Run the editor: a free port on 127.0.0.1, uvicorn, the browser, and a recovery copy at exit."""

from __future__ import annotations

import contextlib
import socket
import webbrowser
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import uvicorn

from .app import create_app
from .session import EditorSession

HOST = "127.0.0.1"


def free_port() -> int:
    """A TCP port on 127.0.0.1 that nobody listens on right now."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind((HOST, 0))
        return int(probe.getsockname()[1])


@dataclass
class ServeResult:
    """How a run ended: the URL it served and the recovery copy written, if any."""

    url: str
    recovered: Path | None


def serve(
    session: EditorSession,
    *,
    port: int | None = None,
    open_browser: bool = True,
    announce: Callable[[str], None] = lambda url: None,
) -> ServeResult:
    """Serve `session` until Ctrl-C; unsaved changes are then written to a recovery copy."""
    chosen = port or free_port()
    url = f"http://{HOST}:{chosen}/"
    config = uvicorn.Config(create_app(session), host=HOST, port=chosen, log_level="warning")
    server = uvicorn.Server(config)
    announce(url)
    if open_browser:
        webbrowser.open(url)
    # uvicorn handles the first Ctrl-C itself; a second one would land here.
    with contextlib.suppress(KeyboardInterrupt):
        server.run()
    return ServeResult(url, session.recover())
