"""Run the editor: a free port on 127.0.0.1, uvicorn, the browser, and a recovery copy at exit."""

from __future__ import annotations

import contextlib
import errno
import socket
import webbrowser
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import uvicorn

from ..errors import ArgumentError
from .app import create_app
from .session import EditorSession

HOST = "127.0.0.1"


def listening_socket(port: int | None) -> socket.socket:
    """A socket bound to 127.0.0.1 (`port`, or a free one), before any URL is announced.

    Binding here, not in uvicorn, means a busy port is a clear error and a free port cannot be
    taken by someone else between choosing it and serving on it.
    """
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    try:
        sock.bind((HOST, port or 0))
    except OSError as error:
        sock.close()
        reason = (
            "is in use" if error.errno == errno.EADDRINUSE else f"cannot be used ({error.strerror})"
        )
        raise ArgumentError(
            f"port {port} on {HOST} {reason}; choose another with --port, or leave --port out"
        ) from None
    return sock


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
    sock = listening_socket(port)
    url = f"http://{HOST}:{sock.getsockname()[1]}/"
    config = uvicorn.Config(create_app(session), log_level="warning")
    server = uvicorn.Server(config)
    announce(url)
    if open_browser:
        webbrowser.open(url)
    # uvicorn handles the first Ctrl-C itself; a second one would land here.
    with contextlib.suppress(KeyboardInterrupt), sock:
        server.run(sockets=[sock])
    return ServeResult(url, session.recover())
