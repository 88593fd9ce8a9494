"""The HTTP side of the editor: docs/editor-protocol.md's routes over one EditorSession."""

from __future__ import annotations

import re
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
from starlette.responses import (
    FileResponse,
    HTMLResponse,
    JSONResponse,
    Response,
    StreamingResponse,
)
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from ..errors import SceMLError
from ..xosc.profiles import default_version
from .bodies import BadBody, parse_object, read_limited
from .commands import ANY_TAB
from .errors import EditorError, ExportRefused, OperationError
from .headers import SecurityHeaders
from .journal import Journal
from .live import Broadcaster
from .patches import ViewHistory
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


#: The header a page names itself with, so each tab undoes its own edits.
TAB_HEADER = "x-sceml-tab"
_TAB = re.compile(r"[A-Za-z0-9_-]{1,64}")
#: The header a page names the view revision it holds with, to be answered with a patch.
REVISION_HEADER = "x-sceml-revision"
#: The routes that answer with a view (the others answer with their own small results).
VIEW_ROUTES = frozenset(
    {
        "/api/view",
        "/api/ops",
        "/api/undo",
        "/api/redo",
        "/api/save",
        "/api/open",
        "/api/open-definition",
        "/api/recovery",
        "/api/compare",
    }
)


def _tab(request: Request) -> str:
    tab = request.headers.get(TAB_HEADER, ANY_TAB)
    if tab != ANY_TAB and not _TAB.fullmatch(tab):
        raise BadBody(f"the {TAB_HEADER} header must be 1 to 64 letters, digits, - or _")
    return tab


def _revision(request: Request) -> int | None:
    text = request.headers.get(REVISION_HEADER)
    if text is None:
        return None
    if not text.isascii() or not text.isdigit() or len(text) > 18:
        raise BadBody(f"the {REVISION_HEADER} header must be a view revision (a number)")
    return int(text)


Action = Callable[[dict[str, Any], str], Any]


class Api:
    """The protocol's endpoints; the lock keeps one request at a time on the session."""

    def __init__(self, session: EditorSession) -> None:
        self.session = session
        self.lock = threading.Lock()
        self.live = Broadcaster()
        self.history = ViewHistory()
        self.journal = Journal(lambda: self._locked(lambda body, tab: session.recover(), {}, "")[0])

    async def call(self, request: Request, action: Action) -> Response:
        """Read the JSON body, run `action` under the lock, answer JSON or a protocol error."""
        if request.method == "POST" and not _same_origin(request):
            # Any web page the user visits could post to 127.0.0.1; only this page may edit.
            return _error("a request from another site was refused", 403)
        try:
            tab = _tab(request)
            known = _revision(request)
            body: dict[str, Any] = {}
            if request.method == "POST":
                raw = await read_limited(request.stream(), request.headers.get("content-length"))
                body = parse_object(raw)
            if request.url.path in VIEW_ROUTES:
                action = self._patched(action, known)
            result, event = await run_in_threadpool(
                self._locked, action, body, tab, request.url.path
            )
        except ExportRefused as error:
            return _error(error.message, error.status, diagnostics=error.diagnostics)
        except EditorError as error:
            return _error(error.message, error.status)
        except SceMLError as error:
            # A file that cannot be read or written: the user's input, not a server fault.
            return _error(str(error), 400)
        except OSError as error:
            # A path the system refuses (too long, a device that cannot be read, no rights).
            return _error(f"the file cannot be used: {error.strerror or error}", 400)
        if request.method == "POST":
            self.journal.changed()
            self.live.publish(event)
        return JSONResponse(result)

    def _patched(self, action: Action, known: int | None) -> Action:
        """`action`, its view answered as a patch when the page holds a revision one applies to."""

        def patched(body: dict[str, Any], tab: str) -> Any:
            return self.history.answer(action(body, tab), known)

        return patched

    def _locked(
        self, action: Action, body: dict[str, Any], tab: str, route: str = ""
    ) -> tuple[Any, dict[str, Any]]:
        """`action`'s result and the change event other pages get if it changed something
        (made under the lock, so that it is this request's revision).

        A change is logged (`EditorSession.record`) under the same lock, before the answer: the
        log holds the changes in the order they were applied, and a SIGKILL after the answer
        cannot lose it. One a replay could not apply has the checkpoint written at once.
        """
        with self.lock:
            before = self.session.version
            self.session.will_change(route)
            result = action(body, tab)
            if self.session.record(route, body, tab, before):
                self.journal.now()
            return result, {**self.history.event(tab), "version": self.session.version}

    async def events(self, request: Request) -> Response:
        """The stream of change events every open page listens to."""
        first = {"version": self.session.version}
        return StreamingResponse(
            self.live.stream(first),
            media_type="text/event-stream",
            headers={"Cache-Control": "no-store"},
        )

    def routes(self) -> list[Route]:
        """The /api routes."""
        s = self.session

        def export(body: dict[str, Any], tab: str) -> dict[str, Any]:
            profile = body.get("profile") or "generic"
            version = body.get("version") or default_version(profile)
            path = s.export(version, profile, body.get("path"))
            return {"path": str(path), "version": version}

        def open_file(body: dict[str, Any], tab: str) -> dict[str, Any]:
            return s.open(body.get("path"), module=_module(body), discard=_flag(body, "discard"))

        table: dict[str, tuple[str, Action]] = {
            "/api/view": ("GET", lambda body, tab: s.view(tab=tab)),
            "/api/ops": (
                "POST",
                lambda body, tab: s.apply(body.get("ops"), body.get("label"), tab),
            ),
            "/api/undo": ("POST", lambda body, tab: s.undo(tab)),
            "/api/redo": ("POST", lambda body, tab: s.redo(tab)),
            "/api/copy": ("POST", lambda body, tab: {"copied": s.copy(body.get("nodes"), tab)}),
            "/api/save": ("POST", lambda body, tab: s.save(body.get("path"), tab)),
            "/api/export": ("POST", export),
            "/api/open": ("POST", open_file),
            "/api/open-definition": (
                "POST",
                lambda body, tab: s.open_definition(
                    body.get("node"), discard=_flag(body, "discard")
                ),
            ),
            "/api/recovery": ("POST", lambda body, tab: s.resolve_recovery(body.get("restore"))),
            "/api/compare": ("POST", lambda body, tab: s.compare(_flag(body, "on"), tab)),
        }
        routes = [self._route(path, method, action) for path, (method, action) in table.items()]
        return [*routes, Route("/api/events", self.events)]

    def _route(self, path: str, method: str, action: Action) -> Route:
        async def endpoint(request: Request) -> Response:
            return await self.call(request, action)

        return Route(path, endpoint, methods=[method])


def _flag(body: dict[str, Any], key: str) -> bool:
    value = body.get(key, False)
    if not isinstance(value, bool):
        raise OperationError(f"'{key}' must be true or false")
    return value


def _module(body: dict[str, Any]) -> str | None:
    module = body.get("module")
    if module is not None and not isinstance(module, str):
        raise OperationError("'module' must be the name of a module")
    return module


async def index(request: Request) -> Response:
    """The built page, or a page that says how to build it."""
    page = static_folder() / "index.html"
    if page.is_file():
        return FileResponse(page)
    return HTMLResponse(MISSING_BUNDLE)


def create_app(session: EditorSession) -> Starlette:
    """The editor's web application over an opened session.

    `app.state.api` is the Api: its `journal` and `live` are stopped by the server at exit.
    """
    assets = StaticFiles(directory=static_folder() / "assets", check_dir=False)
    api = Api(session)
    routes = [
        Route("/", index),
        *api.routes(),
        Mount("/assets", app=assets, name="assets"),
    ]
    # Only names of this machine: a DNS-rebinding page gets its own host name refused.
    local = Middleware(TrustedHostMiddleware, allowed_hosts=LOCAL_HOSTS)
    app = Starlette(routes=routes, middleware=[Middleware(SecurityHeaders), local])
    app.state.api = api
    return app
