"""A stand-in for `sceml edit` while developing the page: serves the built bundle and view.json.

Moves are kept and every op marks the view dirty; nothing else is modelled (the real server
owns the model). Run: python web/mock/serve.py [port]
"""

import json
import sys
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

HERE = Path(__file__).parent
STATIC = HERE.parent.parent / "src" / "sceml" / "editor" / "static"
VIEW = json.loads((HERE / "view.json").read_text())


class Handler(SimpleHTTPRequestHandler):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, directory=str(STATIC), **kwargs)

    def log_message(self, *args):
        pass

    def answer(self, data, status=200):
        body = json.dumps(data).encode()
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self):
        if self.path == "/api/view":
            return self.answer(VIEW)
        return super().do_GET()

    def do_POST(self):
        length = int(self.headers.get("Content-Length") or 0)
        body = json.loads(self.rfile.read(length) or b"{}")
        if self.path == "/api/ops":
            for op in body["ops"]:
                if op["op"] == "move":
                    for node in VIEW["nodes"]:
                        if node["id"] in op["positions"]:
                            node["position"] = op["positions"][node["id"]]
                elif op["op"] == "connect" and op["source"] == op["target"]:
                    return self.answer({"error": "A node cannot flow into itself."}, 400)
            VIEW["dirty"] = True
            VIEW["undo"] = body.get("label") or body["ops"][-1]["op"]
        elif self.path == "/api/save":
            VIEW["dirty"] = False
        elif self.path == "/api/copy":
            return self.answer({"copied": len(body.get("nodes", []))})
        elif self.path == "/api/export":
            return self.answer(
                {
                    "error": "Export refused: the scenario has errors.",
                    "diagnostics": VIEW["diagnostics"],
                },
                422,
            )
        VIEW["version"] += 1
        return self.answer(VIEW)


if __name__ == "__main__":
    port = int(sys.argv[1]) if len(sys.argv) > 1 else 8766
    ThreadingHTTPServer(("127.0.0.1", port), Handler).serve_forever()
