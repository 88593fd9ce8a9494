"""A diff as a report: text for a terminal, JSON for tools, Markdown and JUnit XML for a pull request."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass

from lxml import etree

from .changes import PARTS, Change
from .snapshot import Leaf
from .words import describe

#: Version of the JSON shape (docs/diff.md); bumped when a field changes meaning or disappears.
JSON_SCHEMA_VERSION = 1

#: Headings of each part in the text and Markdown reports.
HEADINGS = {
    "root": "Root settings",
    "actors": "Actors",
    "nodes": "Nodes",
    "modules": "Module uses",
    "flows": "Flows",
    "layout": "Layout (diagram positions only)",
}


@dataclass
class DiffReport:
    """What a report shows: the two files, the changes, and those that touch a guarded part."""

    old: str
    new: str
    changes: list[Change]
    guarded: tuple[str, ...] = ()

    @property
    def blocked(self) -> list[Change]:
        """The changes that touch a part (or element) named with --exit-code."""
        return [c for c in self.changes if any(c.touches(name) for name in self.guarded)]


def _grouped(changes: Sequence[Change]) -> list[tuple[str, list[Change]]]:
    return [
        (p, [c for c in changes if c.part == p]) for p in PARTS if any(c.part == p for c in changes)
    ]


def summary(report: DiffReport) -> str:
    """`3 changes (1 layout)` or `no changes`."""
    count = len(report.changes)
    if not count:
        return "no changes"
    layout = sum(1 for c in report.changes if c.part == "layout")
    text = f"{count} change{'s' if count != 1 else ''}"
    return text + (f" ({layout} layout only)" if layout else "")


def format_text(report: DiffReport) -> str:
    """A heading per part and one line per change."""
    lines = [f"{report.old} -> {report.new}: {summary(report)}"]
    for part, changes in _grouped(report.changes):
        lines.append(HEADINGS[part])
        lines += [f"  {describe(change)}" for change in changes]
    lines += [f"guarded: {describe(c)}" for c in report.blocked]
    return "\n".join(lines) + "\n"


def format_markdown(report: DiffReport) -> str:
    """A pull-request comment: a title, a section per part, guarded changes called out first."""
    lines = [f"### Scenario changes: `{report.old}` → `{report.new}`", "", f"{summary(report)}."]
    if report.blocked:
        guarded = ", ".join(f"`{name}`" for name in report.guarded)
        lines += ["", f"**{len(report.blocked)} change(s) touch a guarded part ({guarded}):**", ""]
        lines += [f"- `{describe(c)}`" for c in report.blocked]
    for part, changes in _grouped(report.changes):
        lines += ["", f"#### {HEADINGS[part]}", ""]
        lines += [f"- `{describe(change)}`" for change in changes]
    return "\n".join(lines) + "\n"


def leaf_json(leaf: Leaf) -> object:
    """A leaf as JSON: parameter values in the editor protocol's ParamValue shape."""
    if not isinstance(leaf, tuple):
        return leaf
    word, *rest = leaf
    shapes: dict[str, tuple[str, ...]] = {
        "value": ("value",),
        "range": ("min", "max", "step"),
        "uniform": ("min", "max"),
        "normal": ("mean", "sd", "min", "max"),
        "ref": ("parameter",),
        "actor": ("name",),
        "module": ("library", "module"),
        "object": ("kind",),
    }
    if word == "discrete":
        values = [v for v, _ in rest[0]]
        weights = [w for _, w in rest[0]]
        return {
            "type": "discrete",
            "values": values,
            "weights": None if None in weights else weights,
        }
    if word in shapes:
        return {"type": word, **dict(zip(shapes[word], rest, strict=True))}
    return {"x": leaf[0], "y": leaf[1]} if len(leaf) == 2 else list(leaf)


def change_json(change: Change) -> dict[str, object]:
    """One change as JSON, with its line of text."""
    return {
        "part": change.part,
        "action": change.action,
        "element": change.element,
        "was": change.was,
        "kind": change.kind,
        "path": change.path,
        "old": leaf_json(change.old),
        "new": leaf_json(change.new),
        "unit": change.unit or None,
        "text": describe(change),
    }


def format_json(report: DiffReport) -> str:
    """The whole report as one JSON object (docs/diff.md)."""
    data = {
        "schemaVersion": JSON_SCHEMA_VERSION,
        "old": report.old,
        "new": report.new,
        "summary": {part: sum(1 for c in report.changes if c.part == part) for part in PARTS},
        "changes": [change_json(change) for change in report.changes],
        "guarded": list(report.guarded),
        "blocked": [change_json(change) for change in report.blocked],
    }
    return json.dumps(data, indent=2) + "\n"


def format_junit(report: DiffReport) -> str:
    """JUnit XML: one test case per change, failing when it touches a guarded part."""
    blocked = {id(c) for c in report.blocked}
    suite = etree.Element(
        "testsuite",
        name="sceml diff",
        tests=str(max(len(report.changes), 1)),
        failures=str(len(blocked)),
        errors="0",
    )
    if not report.changes:
        etree.SubElement(suite, "testcase", classname=report.new, name="no changes")
    for change in report.changes:
        case = etree.SubElement(
            suite, "testcase", classname=f"{report.new}.{change.part}", name=describe(change)
        )
        if id(change) in blocked:
            failure = etree.SubElement(case, "failure", message="change to a guarded part")
            failure.text = describe(change)
    root = etree.Element("testsuites")
    root.append(suite)
    data: bytes = etree.tostring(root, pretty_print=True, xml_declaration=True, encoding="UTF-8")
    return data.decode("utf-8")


FORMATS = {
    "text": format_text,
    "json": format_json,
    "markdown": format_markdown,
    "junit": format_junit,
}
