"""Validates OpenSCENARIO 1.0-1.3 documents against the official ASAM XSDs.

The XSDs are the ones shipped inside the ``asam-qc-openscenarioxml`` package (module
``qc_openscenario``), located with :mod:`importlib.resources` so that this works from any
install layout (wheel, editable, zip).

Two validators are used on purpose:

* lxml/libxml2 decides validity. It validates an in-memory tree directly (no serialise and
  reparse) and is fast: validating a ~20 KB OpenSCENARIO 1.3 tree takes about 0.1 ms
  (``timeit``, 2000 runs, lxml 5.4 / libxml2 2.13, dev container); serialising and reparsing
  it would cost another ~0.17 ms. The first call per process pays ~2 ms to compile the XSD; the
  file is found without importing ``qc_openscenario`` (which imports pydantic).
* xmlschema is only consulted once lxml has said "invalid", because its messages name the
  expected element or the missing attribute. Building its schema costs 0.2-0.3 s per version
  (plus ~0.1 s to import xmlschema), so it is built lazily, once per process; after that an
  invalid document costs ~2 ms.

Files are read with a hardened lxml parser; documents with a DOCTYPE are refused before
parsing (OpenSCENARIO never needs one, and a DTD is the carrier of billion-laughs and XXE).
Library code here never prints or logs.
"""

from __future__ import annotations

import functools
import importlib.util
import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Final, TypeAlias

from lxml import etree

from sceml.diagnostics import Diagnostic, Severity
from sceml.errors import LoadError, SceMLError
from sceml.files.safefiles import read_input
from sceml.files.safexml import doctype_line, hardened_parser, has_dtd

if TYPE_CHECKING:
    import xmlschema

__all__ = [
    "DISTRIBUTION_VERSIONS",
    "SUPPORTED_VERSIONS",
    "SchemaError",
    "SchemaIssue",
    "UnsafeXMLError",
    "UnsupportedVersionError",
    "XMLParseError",
    "XSD_CODE",
    "declared_version",
    "is_valid_tree",
    "parse_file",
    "validate_file",
    "validate_tree",
]

#: The code of every schema violation reported as a Diagnostic.
XSD_CODE: Final = "XOSC-XSD"

#: The OpenSCENARIO versions SceML checks and writes: the one list every module and option reads.
SUPPORTED_VERSIONS: Final[tuple[str, ...]] = ("1.0", "1.1", "1.2", "1.3")
#: The versions that have ParameterValueDistribution (it came with 1.1).
DISTRIBUTION_VERSIONS: Final[tuple[str, ...]] = tuple(v for v in SUPPORTED_VERSIONS if v != "1.0")

# Folder names under qc_openscenario/schema/. For 1.1 the package ships 1.1.0 and the 1.1.1
# errata. The only non-comment difference is the `expression` pattern: 1.1.1 adds ',' to the
# allowed characters so that two-argument functions such as ${max($a, $b)} (defined by the
# 1.1 expression grammar) validate; 1.2 and 1.3 use the same pattern as 1.1.1. 1.1.1 is thus
# a strict superset of 1.1.0 and matches the spec text, so we use it. Note that ASAM's own QC
# bundle validates 1.1 files against 1.1.0, so it can flag such expressions where we do not.
_XSD_FOLDERS: Final[dict[str, str]] = {
    "1.0": "1.0.0",
    "1.1": "1.1.1",
    "1.2": "1.2.0",
    "1.3": "1.3.0",
}
_XSD_PACKAGE: Final = "qc_openscenario.schema"
_XSD_NAME: Final = "OpenSCENARIO.xsd"

TreeOrElement: TypeAlias = "etree._ElementTree | etree._Element"


class SchemaError(SceMLError):
    """Base class for everything this module raises (``file``/``line`` say where)."""

    exit_code = 2  # the input cannot be used at all, like errors.LoadError


class UnsupportedVersionError(SchemaError, ValueError):
    """The FileHeader version is missing, malformed or not one of SUPPORTED_VERSIONS."""


class UnsafeXMLError(SchemaError):
    """The document carries a DOCTYPE/DTD (entity expansion, external entities) and is refused."""


class XMLParseError(SchemaError):
    """The document is not well-formed XML; ``reason`` is libxml2's explanation."""

    def __init__(
        self, message: str, *, file: str | None = None, line: int | None = None, reason: str = ""
    ) -> None:
        super().__init__(message, file=file, line=line)
        self.reason = reason


@dataclass(frozen=True, slots=True)
class SchemaIssue:
    """One schema violation, ready to show to a user.

    ``message`` is a one-line summary (line, location and reason); ``line`` is the source line
    when the tree was parsed from text (None for trees built in memory); ``path`` is an lxml
    XPath such as ``/OpenSCENARIO/Entities/ScenarioObject[2]/Vehicle``; ``reason`` is the bare
    validator explanation.
    """

    message: str
    line: int | None
    path: str | None
    reason: str

    def __str__(self) -> str:
        return self.message

    def diagnostic(self, version: str, file: str | None = None) -> Diagnostic:
        """The violation as an error Diagnostic (code XOSC-XSD) of `file`, if given."""
        return Diagnostic(
            Severity.ERROR,
            XSD_CODE,
            f"OpenSCENARIO {version} XSD: {self.reason}",
            path=self.path,
            file=file,
            line=self.line,
        )


def xsd_bytes(version: str) -> bytes:
    """The official XSD of an OpenSCENARIO version, as the asam-qc-openscenarioxml package holds it."""
    if version not in _XSD_FOLDERS:
        raise UnsupportedVersionError(
            f"OpenSCENARIO version {version!r} is not supported; "
            f"expected one of {', '.join(SUPPORTED_VERSIONS)}"
        )
    # Found without importing the package: its __init__ imports pydantic (about 0.2 s), which
    # every worker of a batch export would pay just to read a file.
    spec = importlib.util.find_spec(_XSD_PACKAGE.partition(".")[0])
    folders = list(spec.submodule_search_locations or ()) if spec is not None else []
    for folder in folders:
        path = Path(folder) / "schema" / _XSD_FOLDERS[version] / _XSD_NAME
        if path.is_file():
            return path.read_bytes()
    # An install layout without plain folders (a zip): ask the package itself. (Imported here:
    # importlib.resources costs every command's start about 8 ms.)
    from importlib import resources

    resource = resources.files(_XSD_PACKAGE) / _XSD_FOLDERS[version] / _XSD_NAME
    return resource.read_bytes()


def compiled_schema(version: str) -> etree.XMLSchema:
    """The XSD of an OpenSCENARIO version, compiled once per process (lxml)."""
    return _lxml_schema(version)


@functools.cache
def _lxml_schema(version: str) -> etree.XMLSchema:
    return etree.XMLSchema(etree.fromstring(xsd_bytes(version), hardened_parser()))


@functools.cache
def _xmlschema_schema(version: str) -> xmlschema.XMLSchema10:
    import xmlschema  # deferred: ~0.1 s import, only needed for invalid documents

    # XSD 1.0 semantics, like libxml2, so both validators judge by the same rules.
    return xmlschema.XMLSchema10(
        xsd_bytes(version).decode("utf-8-sig"), defuse="always", allow="none"
    )


def _root_of(tree_or_root: TreeOrElement) -> etree._Element:
    if isinstance(tree_or_root, etree._ElementTree):
        return tree_or_root.getroot()
    return tree_or_root


def declared_version(tree_or_root: TreeOrElement) -> str:
    """Return the ``"major.minor"`` version declared by the document's FileHeader.

    Raises UnsupportedVersionError when FileHeader, revMajor or revMinor is missing, is not a
    literal integer, or names a version outside SUPPORTED_VERSIONS.
    """
    root = _root_of(tree_or_root)
    header = root.find("FileHeader")
    if header is None:
        raise UnsupportedVersionError(
            f"<{root.tag}> has no FileHeader child, so its OpenSCENARIO version is unknown"
        )
    major, minor = header.get("revMajor"), header.get("revMinor")
    if major is None or minor is None:
        raise UnsupportedVersionError("FileHeader lacks revMajor and/or revMinor")
    try:
        version = f"{int(major)}.{int(minor)}"
    except ValueError:
        raise UnsupportedVersionError(
            f"FileHeader revMajor={major!r} revMinor={minor!r} are not literal integers"
        ) from None
    if version not in SUPPORTED_VERSIONS:
        raise UnsupportedVersionError(
            f"OpenSCENARIO version {version} is not supported; "
            f"expected one of {', '.join(SUPPORTED_VERSIONS)}"
        )
    return version


def is_valid_tree(tree: TreeOrElement, version: str | None = None) -> bool:
    """Fast yes/no check with lxml only; ``version`` defaults to the declared one."""
    return bool(_lxml_schema(version or declared_version(tree)).validate(tree))


def validate_tree(tree: TreeOrElement, version: str | None = None) -> list[SchemaIssue]:
    """Validate an lxml tree (or root element) and return its issues; ``[]`` means valid.

    ``version`` overrides the FileHeader, e.g. to check a 1.2 document against 1.3.
    The tree is validated in place; nothing is serialised.
    """
    version = version or declared_version(tree)
    lxml_schema = _lxml_schema(version)
    if lxml_schema.validate(tree):
        return []
    # lxml keeps only the latest run's log on the shared (cached) schema object, so copy it
    # now; under threads it may be another run's log, which is why it is only the fallback.
    lxml_errors = list(lxml_schema.error_log)
    issues = _xmlschema_issues(tree, version)
    # lxml is authoritative; should xmlschema disagree, fall back to libxml2's own messages.
    return issues or [_issue(e.message, e.line or None, e.path or None) for e in lxml_errors]


def _xmlschema_issues(tree: TreeOrElement, version: str) -> list[SchemaIssue]:
    root = _root_of(tree)
    roottree = root.getroottree()
    issues = []
    for error in _xmlschema_schema(version).iter_errors(tree):
        elem: Any = error.elem
        # For "unexpected child" errors xmlschema reports the parent; the child at `index`
        # is what the author has to fix, so point there.
        index = getattr(error, "index", None)
        if isinstance(elem, etree._Element) and isinstance(index, int) and 0 <= index < len(elem):
            elem = elem[index]
        if isinstance(elem, etree._Element):
            line, path = elem.sourceline, roottree.getpath(elem)
        else:
            line, path = error.sourceline, error.path
        issues.append(_issue(error.reason or error.message, line, path))
    return issues


def _issue(reason: str, line: int | None, path: str | None) -> SchemaIssue:
    reason = " ".join(reason.split())
    where = ", ".join(p for p in (f"line {line}" if line else None, path) if p)
    return SchemaIssue(
        message=f"{where}: {reason}" if where else reason, line=line, path=path, reason=reason
    )


def parse_file(path: str | os.PathLike[str]) -> etree._ElementTree:
    """Parse an OpenSCENARIO file safely.

    Raises UnsafeXMLError for documents with a DOCTYPE (checked before parsing, so entity
    bombs are never expanded and external entities never fetched) and XMLParseError for
    malformed XML; both carry ``file`` and ``line`` and print gcc-style as ``file:line: ...``.
    Files above ``sceml.files.safexml.max_bytes_limit()`` (64 MiB, or $SCEML_MAX_BYTES), and anything
    but a regular file (a FIFO, a device), raise SchemaError unread. OSError propagates for
    missing or unreadable files.
    """
    name = os.fspath(path)
    # The one reading rule: a regular file, refused by size before reading and counted while
    # reading, like models (the file is parsed in memory).
    try:
        data = read_input(name, what="OpenSCENARIO file")
    except LoadError as error:
        raise SchemaError(error.message, file=name) from None
    line = doctype_line(data)
    if line is not None:
        raise UnsafeXMLError(
            "DOCTYPE declarations are not allowed in OpenSCENARIO files "
            "(refused unparsed: entity expansion / external entities)",
            file=name,
            line=line,
        )
    try:
        tree = etree.ElementTree(etree.fromstring(data, hardened_parser(), base_url=name))
    except etree.XMLSyntaxError as exc:
        raise XMLParseError(
            f"not well-formed XML: {exc.msg}", file=name, line=exc.lineno or None, reason=exc.msg
        ) from None
    # Backstop for encodings the prolog scan cannot read (e.g. UTF-32): parsing above was
    # already entity-safe, but the document is still refused.
    if has_dtd(tree):
        raise UnsafeXMLError(
            "DOCTYPE declarations are not allowed in OpenSCENARIO files", file=name
        )
    return tree


def validate_file(path: str | os.PathLike[str], version: str | None = None) -> list[SchemaIssue]:
    """Safely parse and validate an OpenSCENARIO file; ``[]`` means valid.

    Malformed XML is reported as a single SchemaIssue (with its line). A DOCTYPE raises
    UnsafeXMLError; a missing or unsupported FileHeader version raises
    UnsupportedVersionError (with ``file`` set).
    """
    try:
        tree = parse_file(path)
    except XMLParseError as exc:
        return [SchemaIssue(message=str(exc), line=exc.line, path=None, reason=exc.reason)]
    try:
        return validate_tree(tree, version)
    except UnsupportedVersionError as exc:
        raise UnsupportedVersionError(exc.message, file=os.fspath(path)) from None
