"""The HTTP side of the editor: docs/editor-protocol.md's routes over one EditorSession."""

from __future__ import annotations

import threading
from collections.abc import Callable
from importlib import resources
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request
from starlette.responses import FileResponse, HTMLResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from ..errors import SceMLError
from .errors import EditorError, ExportRefused
from .session import EditorSession

#: The host names the editor answers to; it listens on 127.0.0.1 only.
LOCAL_HOSTS = ["127.0.0.1", "localhost"]

MISSING_BUNDLE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>SceML editor: page not built</title></head>
<body>
<h1>The editor's page is not built</h1>
<p>The server is running, but the browser bundle (<code>src/sceml/editor/static/</code>) is
missing. Build it with <code>bash scripts/setup.sh</code> in the SceML checkout, then reload.</p>
<p>The server's API answers meanwhile: <a href="/api/view">/api/view</a>.</p>
</body></html>
"""


def static_folder() -> Path:
    """Where the built page lives: `static/` inside this package."""
    return Path(str(resources.files("sceml.editor"))) / "static"


def _same_origin(request: Request) -> bool:
    """Whether a request comes from the editor's own page (browsers name the page's origin)."""
    origin = request.headers.get("origin")
    return origin is None or origin == f"{request.url.scheme}://{request.headers.get('host')}"


def _error(message: str, status: int, **extra: Any) -> JSONResponse:
    return JSONResponse({"error": message, **extra}, status_code=status)


class Api:
    """The protocol's endpoints; the lock keeps one request at a time on the session."""

    def __init__(self, session: EditorSession) -> None:
        self.session = session
        self.lock = threading.Lock()

    async def call(self, request: Request, action: Callable[[dict[str, Any]], Any]) -> Response:
        """Read the JSON body, run `action` under the lock, answer JSON or a protocol error."""
        body: dict[str, Any] = {}
        if request.method == "POST" and not _same_origin(request):
            # Any web page the user visits could post to 127.0.0.1; only this page may edit.
            return _error("a request from another site was refused", 403)
        if request.method == "POST":
            raw = await request.body()
            try:
                body = (await request.json()) if raw.strip() else {}
            except ValueError:
                return _error("the request body is not JSON", 400)
            if not isinstance(body, dict):
                return _error("the request body must be a JSON object", 400)
        try:
            result = await run_in_threadpool(self._locked, action, body)
        except ExportRefused as error:
            return _error(error.message, error.status, diagnostics=error.diagnostics)
        except EditorError as error:
            return _error(error.message, error.status)
        except SceMLError as error:
            # A file that cannot be read or written: the user's input, not a server fault.
            return _error(str(error), 400)
        return JSONResponse(result)

    def _locked(self, action: Callable[[dict[str, Any]], Any], body: dict[str, Any]) -> Any:
        with self.lock:
            return action(body)

    def routes(self) -> list[Route]:
        """The /api routes."""
        s = self.session

        def export(body: dict[str, Any]) -> dict[str, Any]:
            version = str(body.get("version") or "1.3")
            path = s.export(version, str(body.get("profile") or "generic"), body.get("path"))
            return {"path": str(path), "version": version}

        def open_file(body: dict[str, Any]) -> dict[str, Any]:
            if not isinstance(body.get("path"), str) or not body["path"]:
                raise EditorError("'path' must name a file")
            return s.open(
                body["path"], module=body.get("module"), discard=bool(body.get("discard"))
            )

        table: dict[str, tuple[str, Callable[[dict[str, Any]], Any]]] = {
            "/api/view": ("GET", lambda body: s.view()),
            "/api/ops": ("POST", lambda body: s.apply(body.get("ops"), body.get("label"))),
            "/api/undo": ("POST", lambda body: s.undo()),
            "/api/redo": ("POST", lambda body: s.redo()),
            "/api/copy": ("POST", lambda body: {"copied": s.copy(body.get("nodes"))}),
            "/api/save": ("POST", lambda body: s.save(body.get("path"))),
            "/api/export": ("POST", export),
            "/api/open": ("POST", open_file),
            "/api/open-definition": (
                "POST",
                lambda body: s.open_definition(body.get("node"), discard=bool(body.get("discard"))),
            ),
        }
        return [self._route(path, method, action) for path, (method, action) in table.items()]

    def _route(self, path: str, method: str, action: Callable[[dict[str, Any]], Any]) -> Route:
        async def endpoint(request: Request) -> Response:
            return await self.call(request, action)

        return Route(path, endpoint, methods=[method])


async def index(request: Request) -> Response:
    """The built page, or a page that says how to build it."""
    page = static_folder() / "index.html"
    if page.is_file():
        return FileResponse(page)
    return HTMLResponse(MISSING_BUNDLE)


def create_app(session: EditorSession) -> Starlette:
    """The editor's web application over an opened session."""
    assets = StaticFiles(directory=static_folder() / "assets", check_dir=False)
    routes = [
        Route("/", index),
        *Api(session).routes(),
        Mount("/assets", app=assets, name="assets"),
    ]
    # Only names of this machine: a DNS-rebinding page gets its own host name refused.
    local = Middleware(TrustedHostMiddleware, allowed_hosts=LOCAL_HOSTS)
    return Starlette(routes=routes, middleware=[local])
