"""Each command's one-line summary for `sceml --help`, read from its source, so that listing them
imports none.

`sceml --help` used to import every command's module (the exporter, the simulator, the editor's
server ...) only to read the first paragraph of each docstring: 0.34 s against 0.1 s. The first
paragraph is read from the command function's docstring in the module's text instead (a regular
expression, not a parse: parsing all the modules would cost most of what importing them does);
tests/cli/test_help_summaries.py checks that it is what click shows for the imported command.
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path

_HERE = Path(__file__).resolve().parent


def summary(target: str) -> str | None:
    """The first paragraph of the docstring of "module:function" in this package, on one line.

    None when it cannot be read so (the caller then imports the commands).
    """
    module, function = target.split(":")
    try:
        text = (_HERE / f"{module}.py").read_text(encoding="utf-8")
    except OSError:
        return None
    found = re.search(
        rf'^def {re.escape(function)}\(.*?\)\s*(?:->\s*[^:\n]+)?:\s*\n\s*"""(.*?)"""',
        text,
        re.S | re.M,
    )
    if found is None or "\\" in found.group(1):
        return None
    first = inspect.cleandoc(found.group(1)).split("\f")[0].split("\n\n")[0]
    return " ".join(first.split())


def summaries(commands: dict[str, str]) -> dict[str, str]:
    """Command name -> summary, for each of `commands` (name -> "module:function") that has one."""
    return {name: text for name, target in commands.items() if (text := summary(target))}
