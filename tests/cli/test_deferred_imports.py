"""The console script's start-up: `sceml --help` imports no model, and `urllib.request` (which
pyecore imports for http:// URIs) and RestrictedPython (for EOperation bodies) run only when
something uses them (issue 31).

Each case runs a fresh interpreter, as the `sceml` console script runs (`sceml.cli.main`).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

MAIN = """
import atexit, json, sys
watched = {watched!r}
def report():
    sys.stdout.flush()
    print(json.dumps(sorted(m for m in watched if m in sys.modules)), file=sys.stderr)
atexit.register(report)
sys.argv[0] = "sceml"
from sceml.cli import main
main()
"""


def _run_main(tmp_path: Path, *arguments: str, watched: tuple[str, ...]) -> tuple[str, list[str]]:
    """stdout of `sceml ARGUMENTS` through the console script's entry point, and which of the
    watched modules it had imported when it ended."""
    ran = subprocess.run(
        [sys.executable, "-c", MAIN.format(watched=watched), *arguments],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert ran.returncode == 0, ran.stderr
    imported: list[str] = json.loads(ran.stderr.splitlines()[-1])
    return ran.stdout, imported


def test_help_lists_every_command_without_importing_the_model(tmp_path: Path) -> None:
    watched = ("pyecore", "scemlmodel", "lxml", "sceml.model.documents", "sceml.diagnostics")
    shown, imported = _run_main(tmp_path, "--help", watched=watched)
    assert imported == []
    assert "validate" in shown and "simulate" in shown and "git-setup" in shown


def test_validate_does_not_run_urllib_request(tmp_path: Path) -> None:
    # pyecore.resources imports urllib.request; the module is there, its code (and http.client,
    # ssl, email) is not run.
    uis1 = ROOT / "examples" / "uis1-concrete.xmi"
    shown, imported = _run_main(
        tmp_path, "validate", str(uis1), watched=("pyecore.resources", "http.client", "ssl")
    )
    assert imported == ["pyecore.resources"]
    assert "0 error(s)" in shown


USE = """
import sys
from sceml.cli.deferred import defer_unused_imports
defer_unused_imports()
import pyecore.resources.resource as resource
import urllib.request
assert "http.client" not in sys.modules
assert resource.urllib.request is sys.modules["urllib.request"] is urllib.request
{use}
import http.client
assert urllib.request.Request("http://example.org/").host == "example.org"
assert urllib.request.urlopen.__module__ == "urllib.request"
assert type(urllib.request) is type(sys)
print("ok")
"""


def _uses(use: str) -> str:
    ran = subprocess.run(
        [sys.executable, "-c", USE.format(use=use)], capture_output=True, text=True
    )
    assert ran.returncode == 0, ran.stderr
    return ran.stdout.strip()


def test_a_deferred_module_runs_at_its_first_attribute() -> None:
    assert _uses("urllib.request.Request") == "ok"


def test_a_deferred_module_runs_at_a_from_import() -> None:
    assert _uses("from urllib.request import urlopen") == "ok"


def test_a_missing_dunder_name_does_not_run_it() -> None:
    use = "assert not hasattr(urllib.request, '__path__')\nassert 'http.client' not in sys.modules"
    assert _uses(use) == "ok"


def test_validate_does_not_run_restricted_python(tmp_path: Path) -> None:
    # pyecore.ecore takes compile_restricted and safe_builtins from it by name: stand-ins.
    uis1 = ROOT / "examples" / "uis1-concrete.xmi"
    watched = ("RestrictedPython", "RestrictedPython.compile", "RestrictedPython.Guards")
    shown, imported = _run_main(tmp_path, "validate", str(uis1), watched=watched)
    assert imported == ["RestrictedPython"]
    assert "0 error(s)" in shown


OPERATION = """
import sys
from sceml.cli.deferred import defer_unused_imports
defer_unused_imports()
import pyecore.ecore as ecore
assert "RestrictedPython.Guards" not in sys.modules
Shape = ecore.EClass("Shape")
Shape.eOperations.append(ecore.EOperation("area"))  # pyecore compiles a body for it
import RestrictedPython
assert "RestrictedPython.Guards" in sys.modules
assert ecore.compile_restricted is not RestrictedPython.compile_restricted
assert set(ecore.safe_builtins) - {"__builtins__"} == set(RestrictedPython.safe_builtins)
try:
    Shape().area()
except NotImplementedError as raised:
    print(raised)
"""


def test_an_operation_of_a_dynamic_class_still_gets_its_restricted_body() -> None:
    ran = subprocess.run(
        [sys.executable, "-c", OPERATION], capture_output=True, text=True, check=True
    )
    assert ran.stdout.strip() == "Method area(self) is not yet implemented"


def test_a_library_import_of_sceml_defers_nothing() -> None:
    code = "import sys, sceml.cli, pyecore.resources; print('http.client' in sys.modules)"
    ran = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert ran.stdout.strip() == "True"
