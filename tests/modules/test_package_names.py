"""sceml.modules imports extraction, the library listing and the store on first use; every name
it offers is still there, and `extract` stays the function whatever was imported first."""

from __future__ import annotations

import subprocess
import sys
import types

import sceml.modules

CHECK = """
import sys, types
{first}
import sceml.modules
from sceml.modules import extract
assert isinstance(extract, types.FunctionType), extract
assert isinstance(sceml.modules.extract, types.FunctionType), sceml.modules.extract
print("ok")
"""


def _fresh(first: str) -> str:
    ran = subprocess.run(
        [sys.executable, "-c", CHECK.format(first=first)], capture_output=True, text=True
    )
    return ran.stdout.strip() or ran.stderr


def test_every_listed_name_is_offered() -> None:
    for name in sceml.modules.__all__:
        assert getattr(sceml.modules, name) is not None, name


def test_extract_is_the_function_when_its_module_was_imported_first() -> None:
    # The editor imports sceml.modules.extract directly, which binds the module in the package.
    assert _fresh("from sceml.modules.extract import plan_extraction") == "ok"
    assert _fresh("import sceml.modules.extract") == "ok"
    assert _fresh("") == "ok"


def test_flatten_is_the_function() -> None:
    assert isinstance(sceml.modules.flatten, types.FunctionType)
