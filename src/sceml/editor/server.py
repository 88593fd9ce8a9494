"""Run the editor: a free port on 127.0.0.1, uvicorn, the browser, and a recovery copy at exit."""

from __future__ import annotations

import contextlib
import errno
import signal
import socket
import threading
import webbrowser
from collections.abc import Callable, Generator
from dataclasses import dataclass
from pathlib import Path
from types import FrameType

import uvicorn

from ..errors import ArgumentError
from .app import create_app
from .live import Broadcaster
from .session import EditorSession

HOST = "127.0.0.1"


def listening_socket(port: int | None) -> socket.socket:
    """A socket bound to 127.0.0.1 (`port`, or a free one), before any URL is announced.

    Binding here, not in uvicorn, means a busy port is a clear error and a free port cannot be
    taken by someone else between choosing it and serving on it.
    """
    # IPPROTO_TCP, not 0: asyncio turns Nagle off (TCP_NODELAY) only on sockets whose proto says
    # TCP, and accepted connections inherit it. With Nagle on, each answer's body waited ~40 ms
    # for the browser's delayed ACK of its headers (issue 31: 48 ms per edit, 3 ms of work).
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM, socket.IPPROTO_TCP)
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


#: The signals that stop the editor cleanly, each writing the recovery copy: Ctrl-C, a service
#: manager's or `kill`'s SIGTERM, and the SIGHUP of a closed terminal.
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


@dataclass
class ServeResult:
    """How a run ended: the URL it served, the recovery copy written, and the stopping signal."""

    url: str
    recovered: Path | None
    signal: int | None = None


class EditorServer(uvicorn.Server):
    """uvicorn's server, stopped cleanly by STOP_SIGNALS and ending the pages' event streams.

    uvicorn re-raises a SIGTERM after its graceful shutdown, which would end the process before
    the recovery copy is written; here every stop signal just ends `run`, and `serve` writes it.
    """

    def __init__(self, config: uvicorn.Config, live: Broadcaster) -> None:
        super().__init__(config)
        self.live = live
        self.stopped_by: int | None = None

    @contextlib.contextmanager
    def capture_signals(self) -> Generator[None, None, None]:
        if threading.current_thread() is not threading.main_thread():
            yield
            return
        previous = {sig: signal.signal(sig, self.handle_exit) for sig in STOP_SIGNALS}
        try:
            yield
        finally:
            for sig, handler in previous.items():
                signal.signal(sig, handler)

    def handle_exit(self, sig: int, frame: FrameType | None) -> None:
        self.stopped_by = self.stopped_by or sig
        super().handle_exit(sig, frame)

    async def shutdown(self, sockets: list[socket.socket] | None = None) -> None:
        # Open event streams never end by themselves; uvicorn would wait for them.
        self.live.close()
        await super().shutdown(sockets)


def serve(
    session: EditorSession,
    *,
    port: int | None = None,
    open_browser: bool = True,
    announce: Callable[[str], None] = lambda url: None,
) -> ServeResult:
    """Serve `session` until a stop signal; unsaved changes are then in the recovery copy."""
    sock = listening_socket(port)
    url = f"http://{HOST}:{sock.getsockname()[1]}/"
    app = create_app(session)
    api = app.state.api
    config = uvicorn.Config(app, log_level="warning", timeout_graceful_shutdown=5)
    server = EditorServer(config, api.live)
    announce(url)
    if open_browser:
        webbrowser.open(url)
    try:
        # A second Ctrl-C forces uvicorn out; it may land here.
        with contextlib.suppress(KeyboardInterrupt), sock:
            server.run(sockets=[sock])
    finally:
        api.journal.stop()
    with api.lock:
        recovered = session.recover()
    return ServeResult(url, recovered, server.stopped_by)
