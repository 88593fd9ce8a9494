"""The stages import downwards only, and never in a loop: docs/architecture.md's layer list.

Read from the source with `ast` (nothing is imported). A unit is a subpackage or a module
directly under src/sceml; imports inside functions count too (a late import is still a
dependency). The layers are read from the one list in docs/architecture.md.
"""

from __future__ import annotations

import ast
import re
import sys
from collections.abc import Iterator
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "sceml"
DOC = ROOT / "docs" / "architecture.md"


def layers() -> list[list[str]]:
    """The layers, bottom first, from the ```layers block of docs/architecture.md."""
    found = re.search(r"```layers\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)
    assert found, "docs/architecture.md has no ```layers block"
    rows = [line.split("#")[0].split(":")[-1].split() for line in found.group(1).splitlines()]
    return [row for row in reversed(rows) if row]  # the block lists the top first


def module_name(path: Path) -> tuple[str, bool]:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        return ".".join(parts[:-1]), True
    return ".".join(parts), False


def imported(path: Path) -> Iterator[tuple[int, str]]:
    """(line, absolute module) of every sceml import in a file, late ones included."""
    name, is_package = module_name(path)
    package = name.split(".") if is_package else name.split(".")[:-1]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target == "sceml":  # `from sceml import x` / `from .. import x`: x is the unit
                for alias in node.names:
                    yield node.lineno, f"sceml.{alias.name}"
            elif target.startswith("sceml."):
                yield node.lineno, target
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("sceml."):
                    yield node.lineno, alias.name


def unit(dotted: str) -> str:
    return dotted.split(".")[1]


def sources() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py") if "generated" not in p.parts)


@cache
def edges() -> dict[tuple[str, str], str]:
    """(importing unit, imported unit) -> where the first such import is, `file:line`."""
    found: dict[tuple[str, str], str] = {}
    for path in sources():
        here = unit(module_name(path)[0]) if path.parent != PACKAGE else path.stem
        for line, target in imported(path):
            there = unit(target)
            if there != here and there != "__version__":
                found.setdefault((here, there), f"{path.relative_to(ROOT)}:{line}")
    return found


def test_every_unit_has_a_layer() -> None:
    placed = {name for layer in layers() for name in layer}
    units = {p.stem for p in PACKAGE.glob("*.py") if p.stem != "__init__"} | {
        p.parent.name for p in PACKAGE.glob("*/__init__.py")
    }
    assert units - placed == set(), "add them to the ```layers block of docs/architecture.md"
    assert placed - units == set(), "docs/architecture.md names units that do not exist"


def test_no_unit_imports_one_above_it() -> None:
    level = {name: i for i, layer in enumerate(layers()) for name in layer}
    upwards = [
        f"{where}: {here} (layer {level[here]}) imports {there} (layer {level[there]})"
        for (here, there), where in sorted(edges().items())
        if here in level and there in level and level[there] > level[here]
    ]
    assert upwards == []


def test_no_import_loop_between_units() -> None:
    graph: dict[str, set[str]] = {}
    for here, there in edges():
        graph.setdefault(here, set()).add(there)
    loops = []
    for start in sorted(graph):
        # a path back to `start` through units after it (each loop is reported once)
        stack = [(start, [start])]
        seen: set[str] = set()
        while stack:
            node, path = stack.pop()
            for following in sorted(graph.get(node, ())):
                if following == start:
                    loops.append(" -> ".join([*path, start]))
                elif following > start and following not in seen:
                    seen.add(following)
                    stack.append((following, [*path, following]))
    assert loops == []


def test_the_edges_are_read() -> None:
    # Known dependencies, so that an empty graph (a reader that sees nothing) cannot pass.
    found = edges()
    assert ("cli", "model") in found and ("export", "validation") in found
    assert ("validation", "export") not in found  # the loop issue 28 broke


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("from .. import model\n", {"sceml.a"}),
        ("from ..files.safexml import hardened_parser\n", {"sceml.a.files.safexml"}),
        ("def f():\n    from ... import xosc, model\n", {"sceml.xosc", "sceml.model"}),
        ("import sceml.model.loading\nimport os\n", {"sceml.model.loading"}),
    ],
)
def test_imports_are_read_relative_to_their_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, source: str, expected: set[str]
) -> None:
    # A file at sceml/a/b/c.py: `..` is the package sceml.a, `...` is sceml.
    folder = tmp_path / "sceml" / "a" / "b"
    folder.mkdir(parents=True)
    file = folder / "c.py"
    file.write_text(source)
    monkeypatch.setattr(sys.modules[__name__], "PACKAGE", tmp_path / "sceml")
    assert {target for _, target in imported(file)} == expected


def test_only_the_cli_talks() -> None:
    # Library code never prints: the workflows return results and the commands show them.
    talking = []
    for path in sources():
        if "cli" in path.relative_to(PACKAGE).parts:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "print":
                talking.append(f"{path.relative_to(ROOT)}:{node.lineno}: print()")
            names = (
                [alias.name for alias in node.names]
                if isinstance(node, ast.Import)
                else [node.module or ""]
                if isinstance(node, ast.ImportFrom)
                else []
            )
            if any(name.split(".")[0] == "click" for name in names):
                talking.append(f"{path.relative_to(ROOT)}:{node.lineno}: imports click")
    assert talking == []
