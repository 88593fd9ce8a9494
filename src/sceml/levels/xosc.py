"""One sample to one XSD-checked .xosc file, through the export's fast path, written atomically.

The export's `build_xosc` renders the document from precompiled templates, parses it once, and
checks the tree against the XSD that `sceml.schema` loads once per process; the bytes it returns
are written as they are, so nothing is parsed again here.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lxml import etree

import scemlmodel as scm

from .. import schema
from ..errors import SceMLError
from ..io import model_path, write_atomically
from ..safexml import hardened_parser
from .apply import FlatTemplate

if TYPE_CHECKING:
    from ..export.writer import XoscDocument


class XoscWriter:
    """Builds, checks and writes the .xosc of concrete (flattened) scenarios of one source file."""

    def __init__(self, source: Path, version: str) -> None:
        from ..export import build_xosc  # the export package imports Jinja2; only load it here

        self._build = build_xosc
        self.source = source
        self.version = version

    def document(
        self, scenario: scm.Scenario, target: Path, parameters: Mapping[Any, Any] | None = None
    ) -> XoscDocument:
        """The export's document (bytes and tree) for a scenario that will be written to `target`."""
        return self._build(
            scenario,
            version=self.version,
            source_path=self.source,
            output_path=target,
            parameters=parameters,
            check_model=False,
        )

    def write(self, scenario: scm.Scenario, target: Path) -> str | None:
        """Write the scenario's .xosc to `target`; a reason instead when it cannot be exported."""
        try:
            document = self.document(scenario, target)
        except SceMLError as error:  # ExportError, or InvalidOutputError for an XSD failure
            return f"export: {error.message}"
        write_atomically(target, document.data)
        return None


_PLACEHOLDER = "SceMLsample"
_TOKEN = re.compile(rb"\$" + _PLACEHOLDER.encode() + rb"(\d+)")
_TEXT_TOKEN = re.compile(r"\$" + _PLACEHOLDER + r"(\d+)")


class SampleXosc:
    """The export of one flattened template, rendered once, with each sampled number a slot.

    The export is run once with every sampled value written as a placeholder `$SceMLsample<k>`
    (the export's parameter hook); per sample the placeholders are replaced by the numbers as
    the export writes them, and the top-level ParameterDeclarations are those of a concrete
    export. Only the sampled numbers change between samples, so when the exporter derives no
    other value from them the bytes equal a full export. That is checked, not assumed:
    `matches` compares the result with a full export, and the batch uses this path only while
    those comparisons hold.

    The XSD check works the same way. The placeholders sit in attribute values, so the template
    is parsed once and each sample's numbers are set into those attributes of that one tree,
    which is then validated: a sample costs no parse. A number as the export writes it (Python's
    repr of a float: digits, `.`, `-`, `e`, `inf`, `nan`) holds nothing that XML would escape
    or normalise, so the tree is the one parsing the sample's bytes would give; `matches`
    checks that too. Should a placeholder sit anywhere but in an attribute, every sample is
    parsed instead.
    """

    def __init__(self, writer: XoscWriter, template: FlatTemplate, target: Path) -> None:
        from ..export import ParameterDeclarationSpec
        from ..export.values import number

        self.writer = writer
        self.template = template
        self.target = target
        self._number = number
        row = [t[0].value if t else 0.0 for t in template.targets]
        hook = {}
        for k, targets in enumerate(template.targets):
            spec = ParameterDeclarationSpec(f"{_PLACEHOLDER}{k}", number(row[k]))
            for value in targets:
                hook[(model_path(value.eContainer()), value.eContainmentFeature().name)] = spec
        concrete = writer.document(template.scenario, target).data
        marked = writer.document(template.scenario, target, parameters=hook).data
        marked = _with_declarations_of(marked, concrete)
        self.segments: list[bytes] = _TOKEN.split(marked)
        self.usable = self.render(row) == concrete
        self._tree = _SlottedTree.of(marked, (len(self.segments) - 1) // 2)
        if self._tree is not None and not self._tree.agrees(self.texts(row), concrete):
            self._tree = None

    def texts(self, row: Sequence[float]) -> list[str]:
        """Each sampled number as the export writes it."""
        return [self._number(value) for value in row]

    def render(self, row: Sequence[float], texts: Sequence[str] | None = None) -> bytes:
        """The document bytes of one sample (`texts`: its `texts(row)`, if already made)."""
        texts = self.texts(row) if texts is None else texts
        parts = list(self.segments)
        for position in range(1, len(parts), 2):
            parts[position] = texts[int(parts[position])].encode()
        return b"".join(parts)

    def schema_problem(self, row: Sequence[float], texts: Sequence[str] | None = None) -> str:
        """Why the sample's document fails the XSD (`xsd: reason`), or "" when it is valid."""
        texts = self.texts(row) if texts is None else texts
        if self._tree is None:
            tree = etree.fromstring(self.render(row, texts), _parser())
        else:
            tree = self._tree.filled(texts)
        if schema.is_valid_tree(tree, self.writer.version):
            return ""
        return f"xsd: {schema.validate_tree(tree, self.writer.version)[0].reason}"

    def matches(self, scenario: scm.Scenario, row: Sequence[float]) -> bool:
        """Whether this path gives the same bytes as a full export of the filled template, and
        the tree it checks is the one those bytes parse into."""
        texts = self.texts(row)
        data = self.render(row, texts)
        if data != self.writer.document(scenario, self.target).data:
            return False
        if self._tree is not None and not self._tree.agrees(texts, data):
            self._tree = None  # the bytes are right; check them by parsing from now on
        return True

    def write(self, row: Sequence[float], target: Path) -> str | None:
        """Check the sample's document against the XSD and write it; a reason if it fails."""
        texts = self.texts(row)
        problem = self.schema_problem(row, texts)
        if problem:
            return problem
        write_atomically(target, self.render(row, texts))
        return None


class _SlottedTree:
    """The parsed template with, for each attribute value holding placeholders, its parts."""

    def __init__(
        self, root: etree._Element, slots: list[tuple[etree._Element, str, list[str]]]
    ) -> None:
        self.root = root
        self.slots = slots

    @classmethod
    def of(cls, marked: bytes, count: int) -> _SlottedTree | None:
        """The tree of `marked`, or None unless all of its `count` placeholders are found in
        attribute values."""
        root = etree.fromstring(marked, _parser())
        slots = []
        found = 0
        for element in root.iter():
            for name, value in element.attrib.items():
                parts = _TEXT_TOKEN.split(value)
                if len(parts) > 1:
                    slots.append((element, name, parts))
                    found += len(parts) // 2
        return cls(root, slots) if found == count else None

    def filled(self, texts: Sequence[str]) -> etree._Element:
        """The tree with the sample's numbers in place (the same tree, changed in place)."""
        for element, name, parts in self.slots:
            if len(parts) == 3 and not parts[0] and not parts[2]:  # the whole value: the usual case
                element.set(name, texts[int(parts[1])])
            else:
                filled = list(parts)
                for position in range(1, len(filled), 2):
                    filled[position] = texts[int(filled[position])]
                element.set(name, "".join(filled))
        return self.root

    def agrees(self, texts: Sequence[str], data: bytes) -> bool:
        """Whether the tree filled with `texts` equals the tree that `data` parses into."""
        parsed = etree.fromstring(data, _parser())
        return bool(etree.tostring(self.filled(texts)) == etree.tostring(parsed))


def _with_declarations_of(marked: bytes, concrete: bytes) -> bytes:
    """`marked` with its top-level ParameterDeclarations replaced by those of `concrete`."""
    start, end = _declarations(marked)
    c_start, c_end = _declarations(concrete)
    return marked[:start] + concrete[c_start:c_end] + marked[end:]


def _declarations(data: bytes) -> tuple[int, int]:
    start = data.index(b"<ParameterDeclarations")
    closing = b"</ParameterDeclarations>"
    empty = data.find(b"/>", start)
    opened_end = data.find(b">", start)
    if empty != -1 and empty + 1 == opened_end:  # an empty element: <ParameterDeclarations/>
        return start, empty + 2
    return start, data.index(closing, start) + len(closing)


def _parser() -> etree.XMLParser:
    return hardened_parser()
