"""Reading an OpenSCENARIO file: hardened parse, declared version, XSD of that version.

Catalogs and parameters are resolved afterwards (`catalogs.py`, `parameters.py`) on the parsed
tree, so every later stage sees plain literal values.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ..xosc import schema
from .errors import XoscImportError

#: Attribute set on elements copied from a catalog: the file they came from (namespaced, so it
#: can never clash with OpenSCENARIO's own attributes; removed before any XML is kept).
ORIGIN = "{urn:sceml:import}origin"
#: Attribute set on an entity copied from a catalog into a ScenarioObject: the entry's name, so
#: that the actor keeps which entry it was read from (`Actor.catalogEntry`, release 1.5).
CATALOG_ENTRY = "{urn:sceml:import}catalog-entry"


@dataclass
class Source:
    """The file being imported: its path, declared version and (resolved) tree."""

    path: Path
    version: str
    tree: etree._ElementTree

    @property
    def root(self) -> etree._Element:
        """The OpenSCENARIO element."""
        return self.tree.getroot()

    def where(self, element: etree._Element) -> tuple[str, int | None]:
        """The file and line an element was read from (a catalog's file for catalog entries)."""
        for ancestor in (element, *element.iterancestors()):
            origin = ancestor.get(ORIGIN)
            if origin is not None:
                return origin, element.sourceline
        return str(self.path), element.sourceline

    def error(self, message: str, element: etree._Element | None = None) -> XoscImportError:
        """An import error located at `element` (or the file)."""
        if element is None:
            return XoscImportError(message, file=self.path)
        file, line = self.where(element)
        return XoscImportError(message, file=file, line=line)


def read(path: str | Path) -> Source:
    """Parse and check an OpenSCENARIO 1.0-1.3 file; XoscImportError says why it cannot be used."""
    path = Path(path)
    return scenario_source(path, *load(path))


def load(path: Path) -> tuple[etree._ElementTree, str]:
    """The parsed OpenSCENARIO document and its declared version (not yet checked by the XSD)."""
    try:
        tree = schema.parse_file(path)
    except OSError as error:
        raise XoscImportError(
            f"cannot read the file: {error.strerror or error}", file=path
        ) from None
    except schema.SchemaError as error:
        raise XoscImportError(error.message, file=error.file or path, line=error.line) from None
    root = tree.getroot()
    try:
        version = schema.declared_version(tree)
    except schema.UnsupportedVersionError as error:
        header = root.find("FileHeader")
        line = header.sourceline if header is not None else root.sourceline
        raise XoscImportError(error.message, file=path, line=line) from None
    if root.tag != "OpenSCENARIO":
        raise XoscImportError(
            f"the document is a <{root.tag}>, not <OpenSCENARIO>", file=path, line=root.sourceline
        )
    return tree, version


def is_distribution(tree: etree._ElementTree) -> bool:
    """Whether a loaded document is a ParameterValueDistribution."""
    return tree.getroot().find("ParameterValueDistribution") is not None


def scenario_source(path: Path, tree: etree._ElementTree, version: str) -> Source:
    """A loaded document as the scenario to import, once it has a Storyboard and passes the XSD."""
    root = tree.getroot()
    if root.find("Storyboard") is None:
        raise XoscImportError(
            "the file has no Storyboard: it is a catalog or a parameter distribution, not a "
            "scenario",
            file=path,
            line=root.sourceline,
        )
    check(path, tree, version)
    return Source(path, version, tree)


def check(path: Path, tree: etree._ElementTree, version: str) -> None:
    """XoscImportError with the first XSD violation, if any."""
    issues = schema.validate_tree(tree, version)
    if issues:
        first = issues[0]
        more = f" (and {len(issues) - 1} more)" if len(issues) > 1 else ""
        raise XoscImportError(
            f"not valid OpenSCENARIO {version}: {first.reason}{more}", file=path, line=first.line
        )
