"""One sample to one XSD-checked .xosc file, through the export's fast path, written atomically.

The export's `build_xosc` renders the document from precompiled templates, parses it once, and
checks the tree against the XSD that `sceml.xosc.schema` loads once per process; the bytes it returns
are written as they are, so nothing is parsed again here.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lxml import etree

import scemlmodel as scm

from ..errors import SceMLError
from ..files.safexml import hardened_parser
from ..files.writing import write_atomically
from ..model.locating import model_path
from ..xosc import schema
from ..xosc.attribute_types import ValueCheck, attribute_types
from ..xosc.meaning import drive_distance_duration
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


def prepare_export(version: str) -> None:
    """Import the exporter and compile its template and the XSD of `version` in this process.

    Called before worker processes are forked from it, they start with all three; each worker
    used to import and compile them itself while setting up (50-200 ms each, two workers at
    once on two cores), before its first file.
    """
    from ..export import render, writer  # noqa: F401  # what XoscWriter imports, with Jinja2
    from ..templating import template

    template(render.TEMPLATE)
    schema.compiled_schema(version)


_PLACEHOLDER = "SceMLsample"
_TOKEN = re.compile(rb"\$" + _PLACEHOLDER.encode() + rb"(\d+)")
_TEXT_TOKEN = re.compile(r"\$" + _PLACEHOLDER + r"(\d+)")
# A value the exporter derives from sampled ones: DriveDistance's condition delay, which it
# writes as `${$distance / $speed}` where either is a parameter and as the quotient otherwise.
_OPERAND = rb"(\$" + _PLACEHOLDER.encode() + rb"\d+|[-+0-9.eE]+)"
_QUOTIENT = re.compile(rb"\$\{" + _OPERAND + rb" / " + _OPERAND + rb"\}")

#: An operand of a derived value: the index of a sampled number, or a number written as is.
Operand = int | float


class SampleXosc:
    """The export of one flattened template, rendered once, with each sampled number a slot.

    The export is run once with every sampled value written as a placeholder `$SceMLsample<k>`
    (the export's parameter hook); per sample the placeholders are replaced by the numbers as
    the export writes them, and the top-level ParameterDeclarations are those of a concrete
    export. The one value the exporter derives from sampled numbers, a DriveDistance's delay
    (distance / speed, written `${$distance / $speed}` under the hook), becomes a slot of its
    own that is computed per sample as the exporter computes it. Should the exporter derive
    anything else, the bytes would differ from a full export. That is checked, not assumed:
    `matches` compares the result with a full export, and the batch uses this path only while
    those comparisons hold.

    The XSD check works the same way. The placeholders sit in attribute values, so the template
    is parsed once, and a sample's document differs from the probe's (which the export found
    valid) only in those attributes' values: it is valid exactly when each of them is valid for
    its attribute's XSD type, which `sceml.xosc.attribute_types` checks in one small element
    (4 us against 0.1 ms for the whole document). A sample that fails it is checked whole, in
    that one tree with the sample's numbers set in, for libxml2's reason: a sample costs no
    parse. A number as the export writes it (Python's repr of a float: digits, `.`, `-`, `e`,
    `inf`, `nan`) holds nothing that XML would escape or normalise, so the tree is the one
    parsing the sample's bytes would give; `matches` checks that too. Should a placeholder sit
    anywhere but in an attribute, every sample is parsed and checked whole instead.
    """

    def __init__(
        self,
        writer: XoscWriter,
        template: FlatTemplate,
        target: Path,
        row: Sequence[float] | None = None,
    ) -> None:
        """Render the template at `row` (a sample's numbers; by default those it holds now).

        The export must accept that row: the values it derives (a DriveDistance's time from
        its speed) are computed from it, so a speed of 0 there would refuse the whole path."""
        from ..export import ParameterDeclarationSpec
        from ..export.values import number

        self.writer = writer
        self.template = template
        self.target = target
        self._number = number
        if row is None:
            row = [t[0].value if t else 0.0 for t in template.targets]
        else:
            template.fill(row)
        hook = {}
        for k, targets in enumerate(template.targets):
            spec = ParameterDeclarationSpec(f"{_PLACEHOLDER}{k}", number(row[k]))
            for value in targets:
                hook[(model_path(value.eContainer()), value.eContainmentFeature().name)] = spec
        concrete = writer.document(template.scenario, target).data
        marked = writer.document(template.scenario, target, parameters=hook).data
        marked = _with_declarations_of(marked, concrete)
        marked, self.derived = _derived_slots(marked, len(template.targets))
        self.segments: list[bytes] = _TOKEN.split(marked)
        self.usable = self.render(row) == concrete
        self._tree = _SlottedTree.of(marked, (len(self.segments) - 1) // 2)
        if self._tree is not None and not self._tree.agrees(self.texts(row), concrete):
            self._tree = None
        # `concrete` passed the XSD as a whole (the export checks it), so from here a sample's
        # document is valid exactly when its slotted values are (`sceml.xosc.attribute_types`).
        self._values = (
            None if self._tree is None else self._tree.value_check(writer.version, self.texts(row))
        )

    def texts(self, row: Sequence[float]) -> list[str]:
        """Each sampled number as the export writes it, then each value derived from them."""
        texts = [self._number(value) for value in row]
        for distance, speed in self.derived:
            duration = drive_distance_duration(_operand(distance, row), _operand(speed, row))
            texts.append(self._number(duration))
        return texts

    def covers(self, row: Sequence[float]) -> bool:
        """Whether this path gives the sample's document: every derived value is finite.

        A DriveDistance at 0 m/s never finishes; the full export refuses it with its reason."""
        return all(_operand(speed, row) > 0 for _, speed in self.derived)

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
        slotted, values = self._tree, self._values
        if slotted is not None and values is not None and values.valid(slotted.values(texts)):
            return ""
        # Invalid (or not checkable by its values): the whole document, for libxml2's reason.
        if slotted is None:
            tree = etree.fromstring(self.render(row, texts), _parser())
        else:
            tree = slotted.filled(texts)
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

    def values(self, texts: Sequence[str]) -> list[str]:
        """Each slotted attribute's value with the sample's numbers in place, in slot order."""
        values = []
        for _, _, parts in self.slots:
            if len(parts) == 3 and not parts[0] and not parts[2]:  # the whole value: the usual case
                values.append(texts[int(parts[1])])
            else:
                filled = list(parts)
                for position in range(1, len(filled), 2):
                    filled[position] = texts[int(filled[position])]
                values.append("".join(filled))
        return values

    def filled(self, texts: Sequence[str]) -> etree._Element:
        """The tree with the sample's numbers in place (the same tree, changed in place)."""
        for (element, name, _), value in zip(self.slots, self.values(texts), strict=True):
            element.set(name, value)
        return self.root

    def value_check(self, version: str, texts: Sequence[str]) -> ValueCheck | None:
        """A check of the slotted values alone against their XSD types, which `texts` (those
        of a document found valid as a whole) pass; None if any slot's type is not found."""
        types = attribute_types(version)
        names = []
        for element, name, _ in self.slots:
            path = [ancestor.tag for ancestor in element.iterancestors()][::-1] + [element.tag]
            type_name = types.of(path, name)
            if type_name is None:
                return None
            names.append(type_name)
        check = ValueCheck.of(types, names)
        return check if check is not None and check.valid(self.values(texts)) else None

    def agrees(self, texts: Sequence[str], data: bytes) -> bool:
        """Whether the tree filled with `texts` equals the tree that `data` parses into."""
        parsed = etree.fromstring(data, _parser())
        return bool(etree.tostring(self.filled(texts)) == etree.tostring(parsed))


def _derived_slots(marked: bytes, sampled: int) -> tuple[bytes, list[tuple[Operand, Operand]]]:
    """`marked` with each derived quotient made a placeholder of its own, numbered after the
    `sampled` ones, and the operands of each (distance, speed)."""
    derived: list[tuple[Operand, Operand]] = []

    def slot(match: re.Match[bytes]) -> bytes:
        derived.append((_operand_of(match.group(1)), _operand_of(match.group(2))))
        return f"${_PLACEHOLDER}{sampled + len(derived) - 1}".encode()

    return _QUOTIENT.sub(slot, marked), derived


def _operand_of(text: bytes) -> Operand:
    token = _TOKEN.fullmatch(text)
    return int(token.group(1)) if token else float(text)


def _operand(operand: Operand, row: Sequence[float]) -> float:
    # The export computes from the numbers as it writes them; repr reads back as the same float.
    return float(row[operand]) if isinstance(operand, int) else operand


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
