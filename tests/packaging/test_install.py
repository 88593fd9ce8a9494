"""Generated code, templates and the metamodel import from a built wheel, not only the checkout."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

PROBE = """
import sys
# Drop the editable install's finder so only the unpacked wheel can provide the packages.
sys.meta_path = [f for f in sys.meta_path if "editable" not in type(f).__module__.lower()]
sys.path_hooks = [h for h in sys.path_hooks if "editable" not in repr(h).lower()]
sys.path_importer_cache.clear()
sys.path.insert(0, sys.argv[1])
import importlib.resources as resources
import sceml, scemlmodel
from sceml.model import catalog
assert sceml.__file__.startswith(sys.argv[1]), sceml.__file__
assert scemlmodel.__file__.startswith(sys.argv[1]), scemlmodel.__file__
assert (resources.files("sceml.metamodel") / "scemlmodel.ecore").is_file()
assert resources.files("sceml.templates").is_dir()
assert (resources.files("sceml.templates") / "report.html.j2").is_file()
assert catalog.parameter("Accelerate", "rate").default == 2.0
print("ok")
"""


def test_wheel_contains_and_imports_everything(tmp_path: Path) -> None:
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--no-deps",
            "--no-build-isolation",
            "-q",
            "-w",
            str(tmp_path),
            str(REPO),
        ],
        check=True,
    )
    wheel = next(tmp_path.glob("sceml-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    assert "scemlmodel/scemlmodel.py" in names
    assert "sceml/metamodel/scemlmodel.ecore" in names
    assert "sceml/templates/openscenario.xosc.j2" in names
    assert "sceml/templates/report.html.j2" in names
    unpacked = tmp_path / "unpacked"
    zipfile.ZipFile(wheel).extractall(unpacked)
    probe = subprocess.run(
        [sys.executable, "-c", PROBE, str(unpacked)], capture_output=True, text=True, cwd=tmp_path
    )
    assert probe.stdout.strip() == "ok", probe.stderr


def test_editable_install_provides_the_same(tmp_path: Path) -> None:
    probe = subprocess.run(
        [
            sys.executable,
            "-c",
            "import importlib.resources as r, scemlmodel, sceml.model.catalog as c;"
            "print(scemlmodel.__file__);"
            "print((r.files('sceml.metamodel') / 'scemlmodel.ecore').is_file())",
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        check=True,
    )
    assert probe.stdout.split() == [str(REPO / "generated/scemlmodel/__init__.py"), "True"]
